#include "inlay/modeling/occluder.h"

#include "inlay/modeling/image_io.h"
#include "inlay/modeling/image_resample.h"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
// After core.hpp: alphamat.hpp uses CV_EXPORTS_W without including what defines it.
#include <opencv2/alphamat.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace inlay {

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// Rasterises strokes (pixel coordinates, centres at +0.5) into `mask` with value `v`.
void drawStrokes(cv::Mat& mask, const std::vector<std::vector<Vec2>>& strokes, int radius, uchar v) {
  auto toPt = [](const Vec2& p) { return cv::Point(int(std::floor(p.x())), int(std::floor(p.y()))); };
  for (const auto& s : strokes) {
    if (s.size() == 1) cv::circle(mask, toPt(s[0]), radius, cv::Scalar(v), cv::FILLED);
    for (size_t i = 1; i < s.size(); ++i)
      cv::line(mask, toPt(s[i - 1]), toPt(s[i]), cv::Scalar(v), 2 * radius + 1, cv::LINE_8);
  }
}

bool finiteStrokes(const std::vector<std::vector<Vec2>>& strokes) {
  for (const auto& s : strokes)
    for (const Vec2& p : s)
      if (!p.allFinite() || std::abs(p.x()) > 1e7 || std::abs(p.y()) > 1e7) return false;
  return true;
}

using Strokes = std::vector<std::vector<Vec2>>;

// The keys that one occluder's messages name.
struct MatteKeys {
  std::string occluder, fg, bg;
};

// The strokes rasterised at the photo's size, and where the two kinds overlap.
struct StrokeMasks {
  cv::Mat fg, bg, both;  // CV_8U, 255 under a stroke
};

// What the cut works on: a region around the strokes, its colours and GrabCut's labels.
struct CutRegion {
  cv::Rect roi;  // the strokes' box grown by the margin, within the photo
  cv::Mat img;   // CV_8UC3, 8-bit sRGB BGR (what grabCut's colour models and alphamat expect)
  cv::Mat gc;    // CV_8U, GrabCut's labels (cv::GC_*)
};

// Strokes with at least one point, every point finite and within reach.
Status checkStrokes(const Strokes& fg, const Strokes& bg, const MatteKeys& keys) {
  auto hasPoints = [](const Strokes& s) {
    for (const auto& stroke : s)
      if (!stroke.empty()) return true;
    return false;
  };
  if (!hasPoints(fg))
    return Error{"", keys.fg, "is empty: scribble at least one stroke inside the object"};
  if (!hasPoints(bg))
    return Error{"", keys.bg, "is empty: scribble at least one stroke around the object"};
  if (!finiteStrokes(fg)) return Error{"", keys.fg, "holds a point that is not a finite number"};
  if (!finiteStrokes(bg)) return Error{"", keys.bg, "holds a point that is not a finite number"};
  return Status::Ok();
}

// Both kinds of strokes rasterised. Each must leave pixels inside the photo that the other kind
// does not cover, and neither may cover the whole photo.
Expected<StrokeMasks> rasteriseStrokes(const Strokes& fg, const Strokes& bg, int W, int H, int radius,
                                       const MatteKeys& keys) {
  StrokeMasks m;
  m.fg = cv::Mat(H, W, CV_8U, cv::Scalar(0));
  m.bg = cv::Mat(H, W, CV_8U, cv::Scalar(0));
  drawStrokes(m.fg, fg, radius, 255);
  drawStrokes(m.bg, bg, radius, 255);
  const int fgCount = cv::countNonZero(m.fg), bgCount = cv::countNonZero(m.bg);
  const int total = W * H;
  if (fgCount == 0) return Error{"", keys.fg, "no stroke falls inside the photo"};
  if (bgCount == 0) return Error{"", keys.bg, "no stroke falls inside the photo"};
  cv::bitwise_and(m.fg, m.bg, m.both);
  const int overlap = cv::countNonZero(m.both);
  if (fgCount >= total)
    return Error{"", keys.fg, "covers the whole photo: nothing is left for the background"};
  if (bgCount >= total)
    return Error{"", keys.bg, "covers the whole photo: nothing is left for the object"};
  if (fgCount - overlap == 0)
    return Error{"", keys.fg, "every foreground stroke is covered by background strokes"};
  if (bgCount - overlap == 0)
    return Error{"", keys.bg, "every background stroke is covered by foreground strokes"};
  return m;
}

// The strokes' bounding box, grown by the margin on each side (at least 16 px).
cv::Rect workRegion(const StrokeMasks& m, double marginFraction) {
  cv::Mat any;
  cv::bitwise_or(m.fg, m.bg, any);
  const cv::Rect strokesBox = cv::boundingRect(any);
  const int mx = std::max(16, int(marginFraction * strokesBox.width));
  const int my = std::max(16, int(marginFraction * strokesBox.height));
  return cv::Rect(strokesBox.x - mx, strokesBox.y - my, strokesBox.width + 2 * mx,
                  strokesBox.height + 2 * my) &
         cv::Rect(0, 0, m.fg.cols, m.fg.rows);
}

// 8-bit sRGB BGR of the region.
cv::Mat srgb8Bgr(const ImageF& photo, const cv::Rect& roi) {
  cv::Mat img(roi.height, roi.width, CV_8UC3);
  for (int y = 0; y < roi.height; ++y)
    for (int x = 0; x < roi.width; ++x) {
      const float* p = photo.pixel(roi.x + x, roi.y + y);
      auto enc = [](float v) { return cv::saturate_cast<uchar>(std::lround(255.f * linearToSrgb(v))); };
      img.at<cv::Vec3b>(y, x) = cv::Vec3b(enc(p[2]), enc(p[1]), enc(p[0]));
    }
  return img;
}

// GrabCut's first labels: the strokes sure, contradicting strokes left to the cut. Undecided
// pixels: a background stroke that closes on itself is a loop around the object (GrabCut's
// rectangle): inside it "probably foreground", outside it sure background. Without a loop,
// "probably foreground" inside the foreground strokes' convex hull.
cv::Mat labelsFromStrokes(const StrokeMasks& m, const Strokes& bg, const cv::Rect& roi, int radius) {
  cv::Mat gc(roi.size(), CV_8U, cv::Scalar(cv::GC_PR_BGD));
  const cv::Mat fgR = m.fg(roi);
  gc.setTo(cv::GC_FGD, fgR);
  gc.setTo(cv::GC_BGD, m.bg(roi));
  gc.setTo(cv::GC_PR_BGD, m.both(roi));
  cv::Mat inside(roi.size(), CV_8U, cv::Scalar(0));
  bool loop = false;
  for (const auto& stroke : bg) {
    if (stroke.size() < 3) continue;
    const double closeGap = std::max(8.0, 4.0 * radius + 2.0);
    if ((stroke.front() - stroke.back()).norm() > closeGap) continue;
    std::vector<cv::Point> poly;
    poly.reserve(stroke.size());
    for (const Vec2& q : stroke)
      poly.emplace_back(int(std::floor(q.x())) - roi.x, int(std::floor(q.y())) - roi.y);
    cv::fillPoly(inside, std::vector<std::vector<cv::Point>>{poly}, cv::Scalar(255));
    loop = true;
  }
  if (!loop) {
    std::vector<cv::Point> pts;
    cv::findNonZero(fgR, pts);
    if (pts.size() >= 3) {
      std::vector<cv::Point> hull;
      cv::convexHull(pts, hull);
      cv::fillConvexPoly(inside, hull, cv::Scalar(255));
    }
  }
  cv::Mat undecided = gc == cv::GC_PR_BGD;
  gc.setTo(cv::GC_PR_FGD, undecided & inside);
  if (loop) gc.setTo(cv::GC_BGD, undecided & ~inside);
  return gc;
}

// Squared RGB distance from c to the nearest of `set` (at most about 2000 of them looked at).
int nearestDistance2(const cv::Vec3b& c, const std::vector<cv::Vec3b>& set) {
  const size_t stride = std::max<size_t>(1, set.size() / 2000);
  int best = 1 << 30;
  for (size_t k = 0; k < set.size(); k += stride) {
    const int d0 = c[0] - set[k][0], d1 = c[1] - set[k][1], d2 = c[2] - set[k][2];
    best = std::min(best, d0 * d0 + d1 * d1 + d2 * d2);
  }
  return best;
}

// One foreground stroke's sure pixels, judged by colour: one whose colour is nearer the
// background strokes' colours than its own stroke's end colours (by a margin) is a gap pixel, a
// background seed; one merely close to a background colour is left to the cut. A stroke that
// would keep no sure pixel (an object coloured like its surroundings) is the user's word
// against the colours: only its gap pixels go, the rest stays sure.
void relabelStrokeGaps(CutRegion& c, const std::vector<Vec2>& stroke, cv::Size photoSize, int radius,
                       const std::vector<cv::Vec3b>& bgColours, int maxDist2) {
  const cv::Rect& roi = c.roi;
  cv::Mat one(photoSize, CV_8U, cv::Scalar(0));
  drawStrokes(one, {stroke}, radius, 255);
  cv::Mat ends(photoSize, CV_8U, cv::Scalar(0));
  for (const Vec2& e : {stroke.front(), stroke.back()})
    cv::circle(ends, cv::Point(int(std::floor(e.x())), int(std::floor(e.y()))), radius + 2,
               cv::Scalar(255), cv::FILLED);
  ends &= one;
  std::vector<cv::Vec3b> endColours;
  for (int y = 0; y < roi.height; ++y)
    for (int x = 0; x < roi.width; ++x)
      if (ends.at<uchar>(roi.y + y, roi.x + x)) endColours.push_back(c.img.at<cv::Vec3b>(y, x));
  std::vector<std::pair<cv::Point, uchar>> relabel;
  int kept = 0;
  for (int y = 0; y < roi.height; ++y)
    for (int x = 0; x < roi.width; ++x) {
      if (!one.at<uchar>(roi.y + y, roi.x + x) || c.gc.at<uchar>(y, x) != cv::GC_FGD) continue;
      const cv::Vec3b colour = c.img.at<cv::Vec3b>(y, x);
      const int dBg = nearestDistance2(colour, bgColours);
      const int dEnd = endColours.empty() ? (1 << 30) : nearestDistance2(colour, endColours);
      if (4 * dBg + 4 * maxDist2 < dEnd) {  // |c - bg| well below |c - ends|
        relabel.push_back({cv::Point(x, y), uchar(cv::GC_BGD)});
      } else if (dBg <= maxDist2) {
        relabel.push_back({cv::Point(x, y), uchar(cv::GC_PR_FGD)});
      } else {
        ++kept;
      }
    }
  for (const auto& [pt, label] : relabel)
    if (kept > 0 || label == cv::GC_BGD) c.gc.at<uchar>(pt) = label;
}

// A foreground stroke drawn across a gap (between table legs) crosses background; strokes
// start and end on the object, so each stroke's pixels are judged against its own ends'
// colours and the background strokes' (relabelStrokeGaps).
void relabelGaps(CutRegion& c, const StrokeMasks& m, const Strokes& fg, int radius, int maxDist2) {
  const cv::Mat bgR = m.bg(c.roi), bothR = m.both(c.roi);
  std::vector<cv::Vec3b> bgColours;
  for (int y = 0; y < c.roi.height; ++y)
    for (int x = 0; x < c.roi.width; ++x)
      if (bgR.at<uchar>(y, x) && !bothR.at<uchar>(y, x)) bgColours.push_back(c.img.at<cv::Vec3b>(y, x));
  for (const auto& stroke : fg)
    if (stroke.size() >= 2) relabelStrokeGaps(c, stroke, m.fg.size(), radius, bgColours, maxDist2);
}

// GrabCut from the labels: the object's pixels (CV_8U, 255 on the object) of the region.
Expected<cv::Mat> cutObject(CutRegion& c, int iterations, const MatteKeys& keys) {
  cv::Mat bgdModel, fgdModel;
  if (cv::countNonZero((c.gc == cv::GC_FGD) | (c.gc == cv::GC_PR_FGD)) == 0)
    return Error{"", keys.fg, "no stroke pixel is left for the object"};
  if (cv::countNonZero((c.gc == cv::GC_BGD) | (c.gc == cv::GC_PR_BGD)) == 0)
    return Error{"", keys.bg, "no pixel is left for the background"};
  try {
    cv::grabCut(c.img, c.gc, cv::Rect(), bgdModel, fgdModel, std::max(1, iterations),
                cv::GC_INIT_WITH_MASK);
  } catch (const cv::Exception& e) {
    return Error{"", keys.occluder, std::string("the segmentation failed: ") + e.what()};
  }
  cv::Mat seg = (c.gc == cv::GC_FGD) | (c.gc == cv::GC_PR_FGD);
  return seg;
}

// Trimap: sure inside (eroded cut and strokes), sure outside (beyond the dilated cut and the
// background strokes), unknown (128) in the band between. Background strokes stay sure;
// foreground strokes only where the cut's core holds them (a stroke drawn across a gap, e.g.
// between table legs, is left to the matting there).
cv::Mat trimapOf(const cv::Mat& seg, const StrokeMasks& m, const cv::Rect& roi, const cv::Mat& kernel) {
  cv::Mat inner, outer;
  cv::erode(seg, inner, kernel);
  cv::dilate(seg, outer, kernel);
  cv::Mat trimap(roi.size(), CV_8U, cv::Scalar(128));
  trimap.setTo(0, outer == 0);
  trimap.setTo(255, inner);
  trimap.setTo(0, m.bg(roi) & ~m.both(roi));
  return trimap;
}

// Alpha (CV_8U) of the region by information-flow matting over the trimap's unknown band, or
// the cut itself when the trimap lacks one of its three parts. Matting costs with the pixels it
// sees: only the box around what is not sure background, plus a margin of background for its
// colour samples.
Expected<cv::Mat> alphaOf(const CutRegion& c, const cv::Mat& trimap, const cv::Mat& seg, int band,
                          const MatteKeys& keys) {
  if (!(cv::countNonZero(trimap == 128) > 0 && cv::countNonZero(trimap == 255) > 0 &&
        cv::countNonZero(trimap == 0) > 0))
    return seg.clone();
  const int m = 3 * band + 4;
  const cv::Rect r = cv::boundingRect(trimap != 0);
  const cv::Rect crop = cv::Rect(r.x - m, r.y - m, r.width + 2 * m, r.height + 2 * m) &
                        cv::Rect(0, 0, c.roi.width, c.roi.height);
  cv::Mat cropAlpha;
  try {
    cv::alphamat::infoFlow(c.img(crop).clone(), trimap(crop).clone(), cropAlpha);
  } catch (const cv::Exception& e) {
    return Error{"", keys.occluder, std::string("the matting failed: ") + e.what()};
  }
  cv::Mat alpha8(c.roi.size(), CV_8U, cv::Scalar(0));
  cropAlpha.copyTo(alpha8(crop));
  return alpha8;
}

// The matte at the photo's size (the trimap's sure parts exactly 0 and 1) and its box.
Status storeMatte(OccluderMatte& out, const cv::Mat& alpha8, const cv::Mat& trimap, const cv::Rect& roi,
                  int W, int H, const MatteKeys& keys) {
  out.alphaPx = ImageF(W, H, 1, 0.f);
  int x0 = W, y0 = H, x1 = -1, y1 = -1;
  for (int y = 0; y < roi.height; ++y)
    for (int x = 0; x < roi.width; ++x) {
      float a = alpha8.at<uchar>(y, x) / 255.f;
      const uchar t = trimap.at<uchar>(y, x);
      if (t == 0) a = 0.f;
      if (t == 255) a = 1.f;
      out.alphaPx.at(roi.x + x, roi.y + y) = a;
      if (a > 0.02f) {
        x0 = std::min(x0, roi.x + x), x1 = std::max(x1, roi.x + x);
        y0 = std::min(y0, roi.y + y), y1 = std::max(y1, roi.y + y);
      }
    }
  if (x1 < 0) return Error{"", keys.fg, "the matte keeps nothing of the object"};
  out.boxPx = {x0, y0, x1 + 1, y1 + 1};
  return Status::Ok();
}

// Lowest point: the lowest row with coverage >= 0.5, its middle such pixel; the edge crosses
// that pixel about `alpha` below its top (a horizontal edge covering it that much).
Status findLowestPoint(OccluderMatte& out, const MatteKeys& keys) {
  const auto& [x0, y0, x1, y1] = out.boxPx;
  for (int y = y1 - 1; y >= y0; --y) {
    std::vector<int> xs;
    for (int x = x0; x < x1; ++x)
      if (out.alphaPx.at(x, y) >= 0.5f) xs.push_back(x);
    if (xs.empty()) continue;
    const int x = xs[xs.size() / 2];
    out.lowestPx = Vec2(x + 0.5, y + double(out.alphaPx.at(x, y)));
    return Status::Ok();
  }
  return Error{"", keys.fg, "the matte has no pixel at least half covered"};
}

// Check and rasterise the strokes, cut the object from its surroundings in a region around them
// (GrabCut seeded by the strokes, gap pixels of foreground strokes relabelled by colour), then
// matte the cut's border band (information flow) and find where the matte stands on the floor.
// Every pixel size of `opt` is taken in the photo's own pixels.
Expected<OccluderMatte> matteAtOwnScale(const ImageF& photo, const Strokes& fg, const Strokes& bg,
                                        const std::string& key, const MatteOptions& opt) {
  const MatteKeys keys{key, key + ".foreground_scribbles_px", key + ".background_scribbles_px"};
  INLAY_CHECK(photo.channels >= 3 && photo.width > 0 && photo.height > 0);
  if (Status s = checkStrokes(fg, bg, keys); !s) return s.error();
  const int W = photo.width, H = photo.height;
  const int radius = std::max(0, opt.strokeRadiusPx);
  auto masks = rasteriseStrokes(fg, bg, W, H, radius, keys);
  if (!masks) return masks.error();
  CutRegion cut;
  cut.roi = workRegion(*masks, opt.marginFraction);
  cut.img = srgb8Bgr(photo, cut.roi);

  const auto t0 = Clock::now();
  cut.gc = labelsFromStrokes(*masks, bg, cut.roi, radius);
  relabelGaps(cut, *masks, fg, radius, opt.ambiguousColourDistance * opt.ambiguousColourDistance);
  auto seg = cutObject(cut, opt.grabCutIterations, keys);
  if (!seg) return seg.error();
  OccluderMatte out;
  out.segmentSeconds = secondsSince(t0);
  if (cv::countNonZero(*seg) == 0)
    return Error{"", keys.fg, "the segmentation keeps nothing of the object"};

  const auto t1 = Clock::now();
  const int band = std::max(1, opt.bandPx);
  const cv::Mat kernel =
      cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * band + 1, 2 * band + 1));
  const cv::Mat trimap = trimapOf(*seg, *masks, cut.roi, kernel);
  auto alpha8 = alphaOf(cut, trimap, *seg, band, keys);
  if (!alpha8) return alpha8.error();
  out.matteSeconds = secondsSince(t1);

  if (Status s = storeMatte(out, *alpha8, trimap, cut.roi, W, H, keys); !s) return s.error();
  if (Status s = findLowestPoint(out, keys); !s) return s.error();
  return out;
}

// The scribbles' region of a photo larger than the reference: their box grown by what
// workRegion grows it by at the reference's scale (and a pixel more), so the cut sees what it
// sees in the photo at that scale; within the photo; empty without a finite point or when the
// box misses the photo.
cv::Rect scribbleRegion(const Strokes& fg, const Strokes& bg, int W, int H, double reduce,
                        const MatteOptions& opt) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const Strokes* strokes : {&fg, &bg})
    for (const auto& stroke : *strokes)
      for (const Vec2& q : stroke)
        if (q.allFinite())
          x0 = std::min(x0, q.x()), y0 = std::min(y0, q.y()), x1 = std::max(x1, q.x()),
          y1 = std::max(y1, q.y());
  if (!(x1 >= x0 && y1 >= y0) || x1 < 0 || y1 < 0 || x0 > W || y0 > H) return {};
  const double stroke = (std::max(0, opt.strokeRadiusPx) + 2) / reduce;
  const double f = std::max(0.0, opt.marginFraction);
  const double mx = std::max(16.0 / reduce, f * (x1 - x0 + 2 * stroke)) + stroke + 1 / reduce;
  const double my = std::max(16.0 / reduce, f * (y1 - y0 + 2 * stroke)) + stroke + 1 / reduce;
  const int ix0 = std::clamp(int(std::floor(x0 - mx)), 0, W - 1);
  const int iy0 = std::clamp(int(std::floor(y0 - my)), 0, H - 1);
  const int ix1 = std::clamp(int(std::ceil(x1 + mx)), ix0 + 1, W);
  const int iy1 = std::clamp(int(std::ceil(y1 + my)), iy0 + 1, H);
  return cv::Rect(ix0, iy0, ix1 - ix0, iy1 - iy0);
}

// The matte of a photo larger than the reference, found on its scribbles' region reduced to the
// reference's scale and brought back (joint bilateral upsampling guided by the photo), pasted
// into a matte of the photo's size; box and lowest point in the photo's pixels.
Expected<OccluderMatte> matteAtReferenceScale(const ImageF& photo, const Strokes& fg, const Strokes& bg,
                                              const std::string& key, const MatteOptions& opt,
                                              double reduce) {
  const cv::Rect r = scribbleRegion(fg, bg, photo.width, photo.height, reduce, opt);
  if (r.empty()) return matteAtOwnScale(photo, fg, bg, key, opt);  // it says what is wrong
  ImageF crop(r.width, r.height, photo.channels);
  for (int y = 0; y < r.height; ++y)
    std::copy_n(photo.pixel(r.x, r.y + y), size_t(r.width) * photo.channels, crop.pixel(0, y));
  const int rw = std::max(1, int(std::lround(r.width * reduce)));
  const int rh = std::max(1, int(std::lround(r.height * reduce)));
  const ImageF region = resizeImage(crop, rw, rh);
  const double sx = double(rw) / r.width, sy = double(rh) / r.height;
  const auto inRegion = [&](Strokes strokes) {
    for (auto& stroke : strokes)
      for (Vec2& q : stroke) q = Vec2((q.x() - r.x) * sx, (q.y() - r.y) * sy);
    return strokes;
  };
  auto m = matteAtOwnScale(region, inRegion(fg), inRegion(bg), key, opt);
  if (!m) return m;
  const ImageF alpha = jointBilateralUpsample(m->alphaPx, region, crop);
  OccluderMatte out = *m;
  out.alphaPx = ImageF(photo.width, photo.height, 1, 0.f);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const float a = alpha.at(x, y);
      out.alphaPx.at(r.x + x, r.y + y) = a > 0 ? std::min(a, 1.f) : 0.f;  // NaN to 0
    }
  out.boxPx = {r.x + int(std::floor(m->boxPx[0] / sx)), r.y + int(std::floor(m->boxPx[1] / sy)),
               std::min(photo.width, r.x + int(std::ceil(m->boxPx[2] / sx))),
               std::min(photo.height, r.y + int(std::ceil(m->boxPx[3] / sy)))};
  out.lowestPx = Vec2(r.x + m->lowestPx.x() / sx, r.y + m->lowestPx.y() / sy);
  return out;
}

}  // namespace

Expected<OccluderMatte> matteFromScribbles(const ImageF& photo, const Strokes& fg, const Strokes& bg,
                                           const std::string& key, const MatteOptions& opt) {
  INLAY_CHECK(photo.channels >= 3 && photo.width > 0 && photo.height > 0);
  const int longSide = std::max(photo.width, photo.height);
  if (opt.referenceLongSidePx <= 0 || longSide <= opt.referenceLongSidePx)
    return matteAtOwnScale(photo, fg, bg, key, opt);
  return matteAtReferenceScale(photo, fg, bg, key, opt, double(opt.referenceLongSidePx) / longSide);
}

Expected<Surface> occluderCard(const Camera& camera, const OccluderMatte& matte, int groupIndex,
                               const std::string& key) {
  const Ray r = camera.rayThroughPixel(matte.lowestPx);
  if (!(r.direction.y() < -1e-9))
    return Error{"", key,
                 "the matte's lowest point is at or above the horizon: it cannot stand on the "
                 "floor (scribble the object down to where it meets the floor)"};
  const Vec3 foot = r.at(-r.origin.y() / r.direction.y());
  const Vec3 forward = camera.worldFromCamera * Vec3(0, 0, -1);
  Vec3 normal(-forward.x(), 0, -forward.z());
  if (!(normal.norm() > 1e-6))
    return Error{"", key, "the camera looks straight down: a vertical card cannot face it"};
  normal.normalize();
  const auto& b = matte.boxPx;
  const Vec2 corners[4] = {{double(b[0]), double(b[3])},
                           {double(b[2]), double(b[3])},
                           {double(b[2]), double(b[1])},
                           {double(b[0]), double(b[1])}};
  Surface s;
  s.kind = SurfaceKind::OccluderCard;
  s.name = "occluder_" + std::to_string(groupIndex) + "_card";
  s.supportsObjects = false;
  s.groupIndex = groupIndex;
  const uint32_t base = 0;
  for (const Vec2& c : corners) {
    const Ray rc = camera.rayThroughPixel(c);
    const double den = rc.direction.dot(normal);
    const double t = std::abs(den) > 1e-12 ? (foot - rc.origin).dot(normal) / den : -1.0;
    if (!(t > 0) || !std::isfinite(t))
      return Error{"", key, "a corner of the matte's box does not meet the card's plane"};
    s.meshWorld.positions.push_back(rc.at(t).cast<float>());
    s.meshWorld.normals.push_back(normal.cast<float>());
  }
  // Bottom-left, bottom-right, top-right, top-left as seen: counter-clockwise seen from the
  // camera side, so the winding's normal faces the camera.
  s.meshWorld.triangles.push_back({base, base + 1, base + 2});
  s.meshWorld.triangles.push_back({base, base + 2, base + 3});
  const Vec3 p0 = s.meshWorld.positions[0].cast<double>(), p1 = s.meshWorld.positions[1].cast<double>(),
             p2 = s.meshWorld.positions[2].cast<double>();
  if ((p1 - p0).cross(p2 - p0).dot(normal) < 0)
    for (auto& tri : s.meshWorld.triangles) std::swap(tri[1], tri[2]);
  auto alpha = std::make_shared<CardAlpha>();
  alpha->camera = camera;
  alpha->alphaPx = matte.alphaPx;
  s.cardAlpha = std::move(alpha);
  return s;
}

}  // namespace inlay
