#include "lines.h"

#include "layout.h"

#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc/fast_line_detector.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace inlay::detail {

namespace {

float luminance(const ImageF& im, int x, int y) {
  const float* p = im.pixel(x, y);
  if (im.channels >= 3) return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
  return p[0];
}

// Area average by an integer factor k in each direction, luminance only: one pass over the
// photo, memory of the reduced image only.
cv::Mat binnedLuminance(const ImageF& im, int k) {
  const int w = std::max(1, im.width / k), h = std::max(1, im.height / k);
  cv::Mat out(h, w, CV_32F, cv::Scalar(0));
  const int usedW = std::min(im.width, w * k), usedH = std::min(im.height, h * k);
  for (int y = 0; y < usedH; ++y) {
    float* row = out.ptr<float>(y / k);
    for (int x = 0; x < usedW; ++x) {
      const float v = luminance(im, x, y);
      row[x / k] += std::isfinite(v) ? v : 0.f;
    }
  }
  out *= 1.0 / (double(k) * k);
  return out;
}

// Sub-pixel refinement of a detected segment (working pixels, centres at integers): along its
// normal, the peak of the gradient component across it (parabola through the best sample and
// its neighbours), one point per pixel of length; a line fitted to the peaks weighted by their
// strength, then one reweighting that drops points over half a pixel off. FastLineDetector fits
// its line to integer edge pixels, so short segments' angles are off by a fraction of a pixel
// over their length; the peaks are not (a synthetic edge: worst angle 0.12 -> 0.03 deg, offset
// 0.35 -> 0.13 px; York: focal error 2.13 -> 1.95 %, tests/bench/bench_camera.cpp).
class EdgeRefiner {
 public:
  explicit EdgeRefiner(const cv::Mat& grey8) {
    cv::Sobel(grey8, gx_, CV_32F, 1, 0, 3);
    cv::Sobel(grey8, gy_, CV_32F, 0, 1, 3);
  }

  // The refined segment, or the detector's when too few peaks support a line near it.
  cv::Vec4f operator()(const cv::Vec4f& r) const {
    const Vec2 a(r[0], r[1]), b(r[2], r[3]);
    const double len = (b - a).norm();
    if (!(len > 4)) return r;
    const Vec2 t = (b - a) / len, n(-t.y(), t.x());
    std::vector<Vec2> pts;
    std::vector<double> w;
    // The edge's polarity: the sign of the gradient across it, summed along it.
    double across = 0;
    for (double s = 1; s <= len - 1; s += 1) {
      const Vec2 p = a + s * t;
      across += sample(gx_, p) * n.x() + sample(gy_, p) * n.y();
    }
    const double polarity = across >= 0 ? 1 : -1;
    for (double s = 1; s <= len - 1; s += 1) {
      const Vec2 p = a + s * t;
      std::array<double, kSteps> prof;
      for (int j = 0; j < kSteps; ++j) {
        const Vec2 q = p + (j - kCentre) * kStep * n;
        prof[j] = sample(gx_, q) * n.x() + sample(gy_, q) * n.y();
      }
      int best = 1;
      for (int j = 2; j < kSteps - 1; ++j)
        if (polarity * prof[j] > polarity * prof[best]) best = j;
      const double y0 = polarity * prof[best - 1], y1 = polarity * prof[best],
                   y2 = polarity * prof[best + 1];
      const double curv = y0 - 2 * y1 + y2;
      if (!(y1 > kMinGradient) || !(curv < 0)) continue;
      const double off = (best - kCentre + 0.5 * (y0 - y2) / curv) * kStep;
      pts.push_back(p + off * n);
      w.push_back(y1);
    }
    if (pts.size() < 5) return r;
    Vec2 c, d;
    if (!fitLine(pts, w, c, d)) return r;
    for (size_t i = 0; i < pts.size(); ++i) {
      const double e = (pts[i] - c).dot(Vec2(-d.y(), d.x()));
      w[i] /= 1 + (e / 0.5) * (e / 0.5);
    }
    if (!fitLine(pts, w, c, d)) return r;
    if (d.dot(t) < 0) d = -d;
    // A peak line that leaves the detector's by more than a pixel is another edge.
    const Vec2 dn(-d.y(), d.x());
    if (std::abs((a - c).dot(dn)) > 1.0 || std::abs((b - c).dot(dn)) > 1.0) return r;
    const Vec2 a2 = c + (a - c).dot(d) * d, b2 = c + (b - c).dot(d) * d;
    return cv::Vec4f(float(a2.x()), float(a2.y()), float(b2.x()), float(b2.y()));
  }

 private:
  static constexpr int kSteps = 9;            // profile samples across the segment
  static constexpr int kCentre = kSteps / 2;  // the sample on the segment (kSteps is odd)
  static constexpr double kStep = 0.5;        // pixels between them: +-2 px
  static constexpr double kMinGradient = 8;   // one grey level per pixel (Sobel 3 x 3 gains 8)

  static double sample(const cv::Mat& m, const Vec2& q) {
    const double x = std::clamp(q.x(), 0.0, m.cols - 1.001), y = std::clamp(q.y(), 0.0, m.rows - 1.001);
    const int x0 = int(x), y0 = int(y);
    const double fx = x - x0, fy = y - y0;
    const float* r0 = m.ptr<float>(y0);
    const float* r1 = m.ptr<float>(std::min(y0 + 1, m.rows - 1));
    const int x1 = std::min(x0 + 1, m.cols - 1);
    return (1 - fy) * ((1 - fx) * r0[x0] + fx * r0[x1]) + fy * ((1 - fx) * r1[x0] + fx * r1[x1]);
  }

  // Weighted total least squares: centroid c, unit direction d.
  static bool fitLine(const std::vector<Vec2>& p, const std::vector<double>& w, Vec2& c, Vec2& d) {
    double sw = 0;
    c = Vec2::Zero();
    for (size_t i = 0; i < p.size(); ++i) {
      c += w[i] * p[i];
      sw += w[i];
    }
    if (!(sw > 0)) return false;
    c /= sw;
    double sxx = 0, sxy = 0, syy = 0;
    for (size_t i = 0; i < p.size(); ++i) {
      const Vec2 q = p[i] - c;
      sxx += w[i] * q.x() * q.x();
      sxy += w[i] * q.x() * q.y();
      syy += w[i] * q.y() * q.y();
    }
    const double ang = 0.5 * std::atan2(2 * sxy, sxx - syy);
    d = Vec2(std::cos(ang), std::sin(ang));
    return d.allFinite() && c.allFinite();
  }

  cv::Mat gx_, gy_;
};

}  // namespace

DetectedLines detectLineSegments(const ImageF& linearRgb, int maxWorkingSidePx, int maxSegments,
                                 const CancelToken* cancel) {
  DetectedLines out;
  const int longSide = std::max(linearRgb.width, linearRgb.height);
  const int target = std::max(16, std::min(maxWorkingSidePx, longSide));
  const int k = std::max(1, longSide / target);
  cv::Mat lum = binnedLuminance(linearRgb, k);
  if (cancel && cancel->shouldStop()) return out;
  const double afterBin = std::max(lum.cols, lum.rows);
  if (afterBin > target) {
    const double s = target / afterBin;
    cv::Mat r;
    cv::resize(lum, r,
               cv::Size(std::max(1, int(std::lround(lum.cols * s))),
                        std::max(1, int(std::lround(lum.rows * s)))),
               0, 0, cv::INTER_AREA);
    lum = r;
  }
  out.workingWidth = lum.cols;
  out.workingHeight = lum.rows;
  // Working pixel = photo pixel * (working / photo) per axis; binning trims at most k-1 pixels,
  // so use the width ratio (the error is below a working pixel).
  out.workingScale = double(lum.cols) / double(linearRgb.width);
  const double sy = double(lum.rows) / double(linearRgb.height);

  // Encode for edges the eye sees (and the detector's thresholds were made for).
  cv::Mat grey8(lum.rows, lum.cols, CV_8U);
  for (int y = 0; y < lum.rows; ++y) {
    const float* s = lum.ptr<float>(y);
    unsigned char* d = grey8.ptr<unsigned char>(y);
    for (int x = 0; x < lum.cols; ++x) d[x] = srgbCode8(s[x]);
  }
  if (lum.cols < 8 || lum.rows < 8) return out;
  // Rendered and high-ISO photos are noisy: a light blur keeps edges, drops noise segments.
  cv::GaussianBlur(grey8, grey8, cv::Size(0, 0), 1.0);
  out.edges = photoEdgesOf(grey8, linearRgb.width, linearRgb.height);
  const double diag = std::hypot(double(lum.cols), double(lum.rows));
  const int minLength = std::max(6, int(std::lround(0.025 * diag)));
  auto fld = cv::ximgproc::createFastLineDetector(minLength, 1.414f, 20.0, 40.0, 3, false);
  std::vector<cv::Vec4f> raw;
  fld->detect(grey8, raw);
  if (cancel && cancel->shouldStop()) return out;

  out.segments.reserve(raw.size());
  const EdgeRefiner refine(grey8);
  for (const auto& r0 : raw) {
    const cv::Vec4f r = refine(r0);
    LineSegment s;
    // OpenCV puts pixel centres at integers, the photo frame at +0.5: shift, then scale.
    s.aPx = Vec2((r[0] + 0.5) / out.workingScale, (r[1] + 0.5) / sy);
    s.bPx = Vec2((r[2] + 0.5) / out.workingScale, (r[3] + 0.5) / sy);
    if (!s.aPx.allFinite() || !s.bPx.allFinite() || s.lengthPx() <= 0) continue;
    out.segments.push_back(s);
  }
  std::sort(out.segments.begin(), out.segments.end(),
            [](const LineSegment& a, const LineSegment& b) { return a.lengthPx() > b.lengthPx(); });
  if (int(out.segments.size()) > maxSegments) out.segments.resize(std::max(0, maxSegments));
  return out;
}

}  // namespace inlay::detail
