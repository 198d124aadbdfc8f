#include "inlay/lighting/sun_ratio.h"

#include "inlay/modeling/parallel.h"
#include "inlay/render/path_tracer.h"

#include <opencv2/imgproc.hpp>
#include <tbb/blocked_range.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <utility>

namespace inlay {

namespace {

constexpr double kClipped = std::numeric_limits<double>::infinity();

// What one photo pixel shows: its surface, the sun's unit light there.
struct PixelView {
  int surface = -1;
  Vec3 point, normal;
  double sun = 0;
};

// What each photo pixel (W x H, the photo's frame) shows under `sun`.
std::vector<PixelView> pixelViews(const RoomTracer& tracer, const Camera& camera,
                                  const SceneGeometry& geometry, const SunLight& sun, int W, int H) {
  std::vector<PixelView> view(size_t(W) * H);
  parallelFor(tbb::blocked_range<int>(0, H), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < W; ++x) {
        const auto h = tracer.intersect(camera.rayThroughPixel(Vec2((x + 0.5) * camera.widthPx / W,
                                                                    (y + 0.5) * camera.heightPx / H)),
                                        1e-6);
        if (!h) continue;
        PixelView& v = view[size_t(y) * W + x];
        v.surface = h->surfaceId;
        v.point = h->pointWorld + 1e-5 * h->normalWorld;
        v.normal = h->normalWorld;
        v.sun = unitSunIrradianceOverPi(tracer, geometry, sun, v.point, v.normal);
      }
  });
  return view;
}

// The patch's surface: the one most of the fully lit pixels (over half the brightest) lie on;
// -1 when the beam lights no pixel.
int patchSurface(const std::vector<PixelView>& view) {
  double eMax = 0;
  for (const PixelView& v : view) eMax = std::max(eMax, v.sun);
  if (!(eMax > 0)) return -1;
  std::map<int, int> litCount;
  for (const PixelView& v : view)
    if (v.sun > 0.5 * eMax) ++litCount[v.surface];
  return std::max_element(litCount.begin(), litCount.end(),
                          [](auto& a, auto& b) { return a.second < b.second; })
      ->first;
}

// The light at pixel `i` (view `v`) besides the sun's direct light: the gathered light plus the
// area lights' direct light (`samples` points each).
Vec3 lightBesidesSun(const RoomTracer& tracer, const PixelView& v, const ImageF& gathered,
                     const std::vector<AreaLight>& lights, size_t i, int samples) {
  const int W = gathered.width;
  Vec3 g = gathered.rgb(int(i % size_t(W)), int(i / size_t(W))).cast<double>();
  for (size_t j = 0; j < lights.size(); ++j)
    g += lights[j].radiance * tracer.unitLightIrradianceOverPi(lights[j], v.point, v.normal, samples,
                                                               uint32_t(i) * 31u + uint32_t(j));
  return g;
}

// The q-quantile (q in [0, 1]) of v (reordered).
double quantile(std::vector<double>& v, double q) {
  const size_t k = std::min(v.size() - 1, size_t(q * double(v.size())));
  std::nth_element(v.begin(), v.begin() + long(k), v.end());
  return v[k];
}

// One lit pixel's data for one channel: B (kClipped when clipped), e, g.
struct LitSample {
  double b, e, g;
};

// S with quantile_q of b / (S e + g) over `lit` equal to `target`; the quotient falls with S.
double solveStrength(const std::vector<LitSample>& lit, double q, double target) {
  std::vector<double> x(lit.size());
  auto f = [&](double S) {
    for (size_t i = 0; i < lit.size(); ++i) x[i] = lit[i].b / (S * lit[i].e + lit[i].g);
    return quantile(x, q);
  };
  if (!(f(0) > target)) return 0;
  double lo = 0, hi = 1;
  for (int k = 0; k < 80 && f(hi) > target; ++k) hi *= 2;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > target ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

Expected<SunRatioResult> sunStrengthFromShadowRatio(const ImageF& photo, const Camera& camera,
                                                    const SceneGeometry& geometry,
                                                    const ImageF& gathered,
                                                    const std::vector<AreaLight>& lights,
                                                    const SunLight& sun, const SunRatioOptions& opt) {
  const int W = photo.width, H = photo.height;
  if (W <= 0 || H <= 0 || photo.channels < 3) return Error{"", "suns", "the photo is empty"};
  if (gathered.width != W || gathered.height != H || gathered.channels < 3)
    return Error{"", "suns", "the gathered light does not match the photo"};
  const RoomTracer tracer(geometry);
  const std::vector<PixelView> view = pixelViews(tracer, camera, geometry, sun, W, H);
  const int surface = patchSurface(view);
  if (surface < 0) return Error{"", "suns", "the sun's beam lights no pixel of the photo"};
  double eMax = 0;
  for (const PixelView& v : view) eMax = std::max(eMax, v.sun);
  // Lit: well inside the beam, away from other surfaces; shadowed: well outside it.
  cv::Mat litM(H, W, CV_8U, cv::Scalar(0)), beamM(H, W, CV_8U, cv::Scalar(0));
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const PixelView& v = view[size_t(y) * W + x];
      if (v.surface == surface && v.sun > 0.9 * eMax) litM.at<uint8_t>(y, x) = 1;
      if (v.sun > 0) beamM.at<uint8_t>(y, x) = 1;
    }
  const auto square = [](int r) {
    return cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * r + 1, 2 * r + 1));
  };
  cv::erode(litM, litM, square(opt.erodePx));
  cv::dilate(beamM, beamM, square(opt.shadowGapPx));
  int y0 = H, y1 = -1;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      if (litM.at<uint8_t>(y, x)) y0 = std::min(y0, y), y1 = std::max(y1, y);
  std::vector<size_t> lit, shadow;
  for (int y = std::max(y0, 0); y <= y1; ++y)
    for (int x = 0; x < W; ++x) {
      const size_t i = size_t(y) * W + x;
      if (litM.at<uint8_t>(y, x)) lit.push_back(i);
      else if (view[i].surface == surface && !beamM.at<uint8_t>(y, x)) shadow.push_back(i);
    }
  SunRatioResult out;
  out.litPixels = int(lit.size());
  out.shadowPixels = int(shadow.size());
  if (out.litPixels < opt.minPixels || out.shadowPixels < opt.minPixels)
    return Error{"", "suns",
                 "too few lit (" + std::to_string(lit.size()) + ") or shadowed (" +
                     std::to_string(shadow.size()) + ") pixels on the patch's surface"};
  // g: the gathered light plus the area lights' direct light.
  auto otherLight = [&](size_t i) {
    return lightBesidesSun(tracer, view[i], gathered, lights, i, opt.lightSamples);
  };
  std::vector<Vec3> gLit(lit.size()), gShadow(shadow.size());
  for (size_t k = 0; k < lit.size(); ++k) gLit[k] = otherLight(lit[k]);
  for (size_t k = 0; k < shadow.size(); ++k) gShadow[k] = otherLight(shadow[k]);
  auto photoAt = [&](size_t i, int c) {
    const double b = photo.at(int(i % size_t(W)), int(i / size_t(W)), c);
    return b >= opt.saturatedAbove ? kClipped : b;
  };
  // Quantiles as shares of the usable range: its upper part, as the lowest ranks of the
  // shadow's noisier pixels fall below their material's (the noise widens them; the lit pixels,
  // far brighter, are hardly affected).
  static const double kShares[] = {0.4, 0.6, 0.8, 1.0};
  for (int c = 0; c < 3; ++c) {
    std::vector<LitSample> ls;
    int unclipped = 0;
    for (size_t k = 0; k < lit.size(); ++k) {
      const double b = photoAt(lit[k], c);
      if (!(gLit[k][c] > 0) || !std::isfinite(gLit[k][c])) continue;
      unclipped += std::isfinite(b);
      ls.push_back({b, view[lit[k]].sun, gLit[k][c]});
    }
    std::vector<double> rho;
    for (size_t k = 0; k < shadow.size(); ++k)
      if (gShadow[k][c] > 0 && std::isfinite(gShadow[k][c]))
        rho.push_back(photoAt(shadow[k], c) / gShadow[k][c]);
    if (ls.size() < size_t(opt.minPixels) || rho.size() < size_t(opt.minPixels))
      return Error{"", "suns", "too few pixels with gathered light beside the sun's patch"};
    const double usable = opt.clippedShareUse * double(unclipped) / double(ls.size());
    std::vector<double> votes;
    for (double share : kShares) {
      const double q = share * usable;
      if (q * double(ls.size()) < 10) continue;  // too few pixels below the quantile
      // A shadow quantile at 0 (black or noise-dominated pixels) tells nothing.
      const double target = quantile(rho, q);
      if (target > 0 && std::isfinite(target)) votes.push_back(solveStrength(ls, q, target));
    }
    if (votes.empty())
      return Error{"", "suns",
                   "the sun's patch is clipped in channel " + std::to_string(c) +
                       " (too few unclipped pixels to compare with its shadow)"};
    out.quantilesUsed[c] = double(votes.size());
    out.strength[c] = quantile(votes, 0.5);
  }
  if (!out.strength.allFinite())
    return Error{"", "suns", "the lit/shadow ratio gave a non-finite strength"};
  return out;
}

}  // namespace inlay

namespace inlay {

namespace {

// The photo pixels the bounce fit reads, with what the model needs there (one channel's values
// at index c): the room outside the beam (B unclipped, `surface` >= 0), and the patch's clipped
// pixels (B per channel, clipped or not, with the sun's unit light `e`).
struct BounceSamples {
  std::vector<int> surface;
  std::vector<Vec3> b, other, bounce;  // photo; light besides the sun's; its bounce per unit S
  std::vector<double> e;               // the sun's unit light (patch pixels only)
  size_t size() const { return b.size(); }
};

// The bounce fit's pixels: the room outside the beam (dilated by opt.beamGapPx) that the photo
// shows unclipped and not black, and the patch surface's well-lit pixels (over half the beam's
// brightest) clipped in some channel.
std::pair<std::vector<size_t>, std::vector<size_t>> bounceAndPatchPixels(
    const std::vector<PixelView>& view, int surface, const ImageF& photo, const SunBounceOptions& opt) {
  const int W = photo.width, H = photo.height;
  double eMax = 0;
  for (const PixelView& v : view) eMax = std::max(eMax, v.sun);
  cv::Mat beam(H, W, CV_8U, cv::Scalar(0));
  for (size_t i = 0; i < view.size(); ++i)
    if (view[i].sun > 0) beam.at<uint8_t>(int(i / size_t(W)), int(i % size_t(W))) = 1;
  const int r = std::max(0, opt.beamGapPx);
  cv::dilate(beam, beam, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * r + 1, 2 * r + 1)));
  std::vector<size_t> room, patch;
  for (size_t i = 0; i < view.size(); ++i) {
    const int x = int(i % size_t(W)), y = int(i / size_t(W));
    const Vec3 b = photo.rgb(x, y).cast<double>();
    if (view[i].surface < 0 || !b.allFinite()) continue;
    const bool clipped = b.maxCoeff() >= opt.saturatedAbove;
    if (!beam.at<uint8_t>(y, x) && !clipped && b.minCoeff() > 0) room.push_back(i);
    if (view[i].surface == surface && view[i].sun > 0.5 * eMax && clipped) patch.push_back(i);
  }
  return {room, patch};
}

// Up to `count` of `pixels` (shuffled with `seed`), as BounceSamples.
BounceSamples sampleOf(std::vector<size_t> pixels, int count, uint32_t seed, const RoomTracer& tracer,
                       const std::vector<PixelView>& view, const ImageF& photo, const ImageF& gathered,
                       const SunBounceImages& images, const std::vector<AreaLight>& lights,
                       const SunLight& sun, int lightSamples) {
  const bool unseen = images.unseen.width == photo.width && images.unseen.height == photo.height &&
                      images.unseen.channels >= 3;
  std::mt19937 rng(seed);
  std::shuffle(pixels.begin(), pixels.end(), rng);
  if (pixels.size() > size_t(std::max(count, 0))) pixels.resize(size_t(std::max(count, 0)));
  BounceSamples s;
  for (size_t i : pixels) {
    const int x = int(i % size_t(photo.width)), y = int(i / size_t(photo.width));
    const Vec3 direct = images.direct.rgb(x, y).cast<double>();
    const Vec3 viaUnseen = unseen ? Vec3(images.unseen.rgb(x, y).cast<double>()) : Vec3(Vec3::Zero());
    const Vec3 bounce = direct + viaUnseen;
    // The gathered light holds the bounce at the given strengths: the rest does not scale with S.
    const Vec3 other = (lightBesidesSun(tracer, view[i], gathered, lights, i, lightSamples) -
                        sun.irradianceOverPi.cwiseProduct(direct) -
                        images.unseenAt.cwiseProduct(viaUnseen))
                           .cwiseMax(0.0);
    if (!other.allFinite() || !bounce.allFinite()) continue;
    s.surface.push_back(view[i].surface);
    s.b.push_back(photo.rgb(x, y).cast<double>());
    s.other.push_back(other);
    s.bounce.push_back(bounce.cwiseMax(0.0));
    s.e.push_back(view[i].sun);
  }
  return s;
}

// The model of one channel at strength S: per bounce pixel its log albedo, the patch surface's
// albedo, the cost (the mean |log albedo - its surface's median|) and whether S is allowed.
class BounceChannel {
 public:
  BounceChannel(const BounceSamples& room, const BounceSamples& patch, int patchSurface, int c,
                double givenStrength, const SunBounceOptions& opt)
      : room_(room), patch_(patch), patchSurface_(patchSurface), c_(c), opt_(opt) {
    rhoGiven_ = patchAlbedo(givenStrength);
  }

  // The patch surface's median albedo outside the beam at S (its own bounce unscaled: a flat
  // patch sends its surface almost nothing); NaN when it has no usable pixel.
  double patchAlbedo(double S) const {
    std::vector<double> r;
    for (size_t i = 0; i < room_.size(); ++i) {
      const double shading = room_.other[i][c_] + S * room_.bounce[i][c_];
      if (room_.surface[i] == patchSurface_ && shading > 0 && room_.b[i][c_] > 0)
        r.push_back(room_.b[i][c_] / shading);
    }
    return r.empty() ? std::numeric_limits<double>::quiet_NaN() : quantile(r, 0.5);
  }

  // The least S that leaves the patch's clipped pixels at or above the clip level with the patch
  // albedo rho (a quantile of the pixels' bounds); 0 when none is clipped in this channel.
  double lowerBound(double rho) const {
    std::vector<double> bounds;
    for (size_t i = 0; i < patch_.size(); ++i)
      if (patch_.b[i][c_] >= opt_.saturatedAbove && patch_.e[i] > 0)
        bounds.push_back(std::max(0.0, (opt_.saturatedAbove / rho - patch_.other[i][c_]) / patch_.e[i]));
    return bounds.empty() ? 0.0 : quantile(bounds, std::clamp(opt_.lowerBoundQuantile, 0.0, 1.0));
  }

  struct At {
    double cost = std::numeric_limits<double>::infinity(), share = 0, lower = 0;
    bool allowed = false;
  };

  At at(double S) const {
    At a;
    const double rho = patchAlbedo(S);
    if (!(rho > 0) || !std::isfinite(rho)) return a;
    const double scale = std::isfinite(rhoGiven_) && rhoGiven_ > 0 ? rho / rhoGiven_ : 1.0;
    std::map<int, std::vector<double>> logAlbedo;
    double bounceSum = 0, shadingSum = 0;
    for (size_t i = 0; i < room_.size(); ++i) {
      const double bounce = S * scale * room_.bounce[i][c_];
      const double shading = room_.other[i][c_] + bounce;
      if (!(shading > 0) || !(room_.b[i][c_] > 0)) continue;
      logAlbedo[room_.surface[i]].push_back(std::log(room_.b[i][c_] / shading));
      bounceSum += bounce, shadingSum += shading;
    }
    double sum = 0, n = 0, highest = -std::numeric_limits<double>::infinity();
    for (auto& [surface, v] : logAlbedo) {
      if (v.size() < size_t(std::max(1, opt_.minSurfacePixels))) continue;
      const double median = quantile(v, 0.5);
      highest = std::max(highest, median);
      for (double r : v) sum += std::abs(r - median), n += 1;
    }
    if (n == 0) return a;
    a.cost = sum / n;
    a.share = shadingSum > 0 ? bounceSum / shadingSum : 0.0;
    a.lower = lowerBound(rho);
    a.allowed = S >= a.lower && highest <= 0;
    return a;
  }

 private:
  const BounceSamples& room_;
  const BounceSamples& patch_;
  int patchSurface_, c_;
  const SunBounceOptions& opt_;
  double rhoGiven_ = 1;
};

// The fit of one factor t on the sun's given colour (S_c = t x given_c): the sum of the
// channels' costs, allowed where every channel is (BounceChannel::At). `why` is empty when the
// bounce determines t.
struct FactorFit {
  double factor = 1, lowerFactor = 0, share = 0, spread = 0;
  Vec3 lower = Vec3::Zero();
  std::string why;
};

// The channels' models at S = t x given, summed.
struct FactorAt {
  double cost = 0, share = 0;
  bool allowed = true;
};

FactorAt factorAt(const std::array<BounceChannel, 3>& models, const Vec3& given, double t) {
  FactorAt f;
  for (int c = 0; c < 3; ++c) {
    const BounceChannel::At a = models[size_t(c)].at(t * given[c]);
    f.cost += a.cost;
    f.share += a.share / 3;
    f.allowed = f.allowed && a.allowed;
  }
  return f;
}

FactorFit fitBounceFactor(const std::array<BounceChannel, 3>& models, const Vec3& given,
                          const SunBounceOptions& opt) {
  FactorFit r;
  for (int c = 0; c < 3; ++c) {
    const double rho = models[size_t(c)].patchAlbedo(given[c]);
    r.lower[c] = std::isfinite(rho) && rho > 0 ? models[size_t(c)].lowerBound(rho) : 0.0;
    r.lowerFactor = std::max(r.lowerFactor, r.lower[c] / given[c]);
  }
  const int steps = std::max(3, opt.steps);
  const double lo = (r.lowerFactor > 0 ? r.lowerFactor : 1.0) / 4;
  const double ratio = std::pow(std::max(1.0, opt.maxFactor) * 4, 1.0 / (steps - 1));
  int best = -1, first = -1, last = -1;
  std::vector<FactorAt> grid(static_cast<size_t>(steps));
  for (int k = 0; k < steps; ++k) {
    grid[size_t(k)] = factorAt(models, given, lo * std::pow(ratio, k));
    if (!grid[size_t(k)].allowed || !std::isfinite(grid[size_t(k)].cost)) continue;
    if (first < 0) first = k;
    last = k;
    if (best < 0 || grid[size_t(k)].cost < grid[size_t(best)].cost) best = k;
  }
  r.factor = std::max(1.0, r.lowerFactor);
  if (best < 0) {
    r.why = "no strength keeps the patch clipped with every surface's albedo at most 1";
    return r;
  }
  const FactorAt& b = grid[size_t(best)];
  r.share = b.share;
  // The factors whose cost is within opt.flatTolerance of the best's: how far the data leave it.
  int from = best, to = best;
  while (from > first && grid[size_t(from - 1)].allowed &&
         grid[size_t(from - 1)].cost <= (1 + opt.flatTolerance) * b.cost)
    --from;
  while (to < last && grid[size_t(to + 1)].allowed &&
         grid[size_t(to + 1)].cost <= (1 + opt.flatTolerance) * b.cost)
    ++to;
  r.spread = std::pow(ratio, to - from);
  char buf[200];
  if (b.share < opt.minBounceShare) {
    std::snprintf(buf, sizeof buf, "the bounce is %.0f%% of the light on the room outside the beam",
                  100 * b.share);
    r.why = buf;
  } else if (to == last || r.spread > opt.maxSpread) {
    std::snprintf(buf, sizeof buf,
                  "the room's albedo is as flat (within %.0f%%) from %.3g to %.3g times the estimate",
                  100 * opt.flatTolerance, lo * std::pow(ratio, from), lo * std::pow(ratio, to));
    r.why = buf;
  } else {
    r.factor = lo * std::pow(ratio, best);
  }
  return r;
}

}  // namespace

Expected<SunBounceResult> sunStrengthFromBounce(const ImageF& photo, const Camera& camera,
                                                const SceneGeometry& geometry, const ImageF& gathered,
                                                const SunBounceImages& bounce,
                                                const std::vector<AreaLight>& lights,
                                                const SunLight& sun, const SunBounceOptions& opt) {
  const int W = photo.width, H = photo.height;
  if (W <= 0 || H <= 0 || photo.channels < 3) return Error{"", "suns", "the photo is empty"};
  for (const ImageF* m : {&gathered, &bounce.direct})
    if (m->width != W || m->height != H || m->channels < 3)
      return Error{"", "suns", "the gathered light or the sun's bounce does not match the photo"};
  if (!sun.irradianceOverPi.allFinite() || (sun.irradianceOverPi.array() < 0).any() ||
      !bounce.unseenAt.allFinite())
    return Error{"", "suns", "the sun's strength is not finite and non-negative"};
  const RoomTracer tracer(geometry);
  const std::vector<PixelView> view = pixelViews(tracer, camera, geometry, sun, W, H);
  const int surface = patchSurface(view);
  if (surface < 0) return Error{"", "suns", "the sun's beam lights no pixel of the photo"};
  const auto [room, patch] = bounceAndPatchPixels(view, surface, photo, opt);
  auto sample = [&](const std::vector<size_t>& pixels, uint32_t seed) {
    return sampleOf(pixels, opt.maxPixels, seed, tracer, view, photo, gathered, bounce, lights, sun,
                    opt.lightSamples);
  };
  const BounceSamples roomS = sample(room, opt.seed), patchS = sample(patch, opt.seed + 1);
  SunBounceResult out;
  out.bouncePixels = int(roomS.size());
  out.patchPixels = int(patchS.size());
  if (out.bouncePixels < opt.minPixels || out.patchPixels < opt.minPixels)
    return Error{"", "suns",
                 "too few unclipped pixels outside the beam (" + std::to_string(roomS.size()) +
                     ") or clipped pixels on the patch (" + std::to_string(patchS.size()) + ")"};
  // The factor keeps the estimate's colour; a black channel takes a thousandth of the brightest.
  if (!(sun.irradianceOverPi.maxCoeff() > 0))
    return Error{"", "suns", "the estimated sun is black: no colour to scale"};
  const Vec3 given = sun.irradianceOverPi.cwiseMax(1e-3 * sun.irradianceOverPi.maxCoeff());
  const std::array<BounceChannel, 3> models = {BounceChannel(roomS, patchS, surface, 0, given[0], opt),
                                               BounceChannel(roomS, patchS, surface, 1, given[1], opt),
                                               BounceChannel(roomS, patchS, surface, 2, given[2], opt)};
  const FactorFit f = fitBounceFactor(models, given, opt);
  out.strength = f.factor * given;
  out.lowerBound = f.lower;
  out.bounceShare = f.share;
  out.spread = f.spread;
  out.determined = f.why.empty();
  out.warning = f.why;
  if (!out.strength.allFinite()) return Error{"", "suns", "the bounce fit gave a non-finite strength"};
  return out;
}

}  // namespace inlay
