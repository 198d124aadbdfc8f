#include "inlay/lighting/sun_ratio.h"

#include "inlay/modeling/parallel.h"
#include "inlay/render/path_tracer.h"

#include <opencv2/imgproc.hpp>
#include <tbb/blocked_range.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace inlay {

namespace {

constexpr double kClipped = std::numeric_limits<double>::infinity();

// What one photo pixel shows: its surface, the sun's unit light there.
struct PixelView {
  int surface = -1;
  Vec3 point, normal;
  double sun = 0;
};

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
  // The patch's surface: the one most fully lit pixels lie on.
  double eMax = 0;
  for (const PixelView& v : view) eMax = std::max(eMax, v.sun);
  if (!(eMax > 0)) return Error{"", "suns", "the sun's beam lights no pixel of the photo"};
  std::map<int, int> litCount;
  for (const PixelView& v : view)
    if (v.sun > 0.5 * eMax) ++litCount[v.surface];
  const int surface = std::max_element(litCount.begin(), litCount.end(), [](auto& a, auto& b) {
                        return a.second < b.second;
                      })->first;
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
    const int x = int(i % size_t(W)), y = int(i / size_t(W));
    Vec3 g = gathered.rgb(x, y).cast<double>();
    for (size_t j = 0; j < lights.size(); ++j)
      g += lights[j].radiance * tracer.unitLightIrradianceOverPi(lights[j], view[i].point,
                                                                 view[i].normal, opt.lightSamples,
                                                                 uint32_t(i) * 31u + uint32_t(j));
    return g;
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
