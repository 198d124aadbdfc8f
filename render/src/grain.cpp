// The photo's noise level function and the matching deterministic grain (see grain.h).
#include "inlay/render/grain.h"

#include "inlay/modeling/parallel.h"

#include <Eigen/Dense>
#include <tbb/blocked_range.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <numeric>

namespace inlay {

namespace {

constexpr double kMaxGrainWidthPx = 3.0;
constexpr int kFields = 4;  // one shared by the channels, one per channel
// Noise below this fraction of the intensity is a noise-free photo's float round-off.
constexpr double kNoiseFreeRelative = 1e-5;

// ---- the grain field: hashed white noise, filtered ------------------------------------------

uint64_t mix64(uint64_t z) {  // splitmix64's finaliser
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// A standard normal deviate, a pure function of (x, y, field, seed) (Box-Muller on the hash).
double whiteNoise(int x, int y, int field, uint32_t seed) {
  const uint64_t key = uint64_t(uint32_t(x)) | (uint64_t(uint32_t(y)) << 32);
  const uint64_t h = mix64(key ^ mix64((uint64_t(seed) << 3) + uint64_t(field) + 0x9e3779b97f4a7c15ULL));
  const double u1 = (double(h >> 32) + 0.5) * 0x1p-32;    // (0, 1)
  const double u2 = double(h & 0xffffffffULL) * 0x1p-32;  // [0, 1)
  return std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2);
}

// The 1-D Gaussian of width `widthPx` (radius ceil(3 width)), scaled to unit sum of squares, so
// the 2-D separable filter keeps white noise's unit variance. Width 0: the identity.
std::vector<double> grainKernel(double widthPx) {
  if (!(widthPx > 1e-3)) return {1.0};
  const int r = int(std::ceil(3 * std::min(widthPx, kMaxGrainWidthPx)));
  std::vector<double> k(size_t(2 * r + 1));
  for (int i = -r; i <= r; ++i) k[size_t(i + r)] = std::exp(-0.5 * i * i / (widthPx * widthPx));
  const double norm = std::sqrt(std::inner_product(k.begin(), k.end(), k.begin(), 0.0));
  for (double& v : k) v /= norm;
  return k;
}

// Correlation of the filtered noise at lag d (1-D; the 2-D one is the product over axes).
double lagCorrelation(const std::vector<double>& k, int d) {
  d = std::abs(d);
  double s = 0;
  for (size_t i = 0; i + size_t(d) < k.size(); ++i) s += k[i] * k[i + size_t(d)];
  return s;
}

// ---- what a noise-only patch shows for a grain width --------------------------------------

// For grain of width w and unit variance, in a P x P patch with a fitted plane removed:
//   residualFactor: E[residual variance] (the plane takes some of the noise, more when coarse),
//   dof: the effective degrees of freedom of that variance (for its quantiles),
//   highFrequency: E[(Immerkaer response / 6)^2], 1 for white noise, less when coarse.
struct PatchResponse {
  double residualFactor = 1, dof = 1, highFrequency = 1;
};

PatchResponse patchResponse(double widthPx, int P) {
  const std::vector<double> k = grainKernel(widthPx);
  const int n = P * P;
  Eigen::MatrixXd C(n, n), X(n, 3);
  const double c0 = 0.5 * (P - 1);
  for (int i = 0; i < n; ++i) {
    const int column = i % P, row = i / P;  // of the patch's pixel i
    X(i, 0) = 1, X(i, 1) = column - c0, X(i, 2) = row - c0;
    for (int j = 0; j < n; ++j)
      C(i, j) = lagCorrelation(k, i % P - j % P) * lagCorrelation(k, i / P - j / P);
  }
  const Eigen::MatrixXd M = Eigen::MatrixXd::Identity(n, n) -
                            X * (X.transpose() * X).inverse() * X.transpose();
  const Eigen::MatrixXd MC = M * C;
  PatchResponse r;
  const double tr = MC.trace();
  r.residualFactor = tr / n;
  r.dof = std::max(1.0, tr * tr / std::max(1e-12, (MC * MC).trace()));
  // [1 -2 1] along one axis against the lag correlations; the 3 x 3 operator is its square.
  const double d1 = 6 * lagCorrelation(k, 0) - 8 * lagCorrelation(k, 1) + 2 * lagCorrelation(k, 2);
  r.highFrequency = (d1 / 6) * (d1 / 6);
  return r;
}

// The grain width whose high-frequency to residual variance ratio is `ratio` (bisection: the
// ratio falls as the width grows); 0 when the noise is at least as fine as white noise.
double widthForRatio(double ratio, int P) {
  const auto ratioOf = [&](double w) {
    const PatchResponse r = patchResponse(w, P);
    return r.highFrequency / r.residualFactor;
  };
  if (!(ratio < ratioOf(0))) return 0;
  if (ratio <= ratioOf(kMaxGrainWidthPx)) return kMaxGrainWidthPx;
  double lo = 0, hi = kMaxGrainWidthPx;
  for (int it = 0; it < 30; ++it) {
    const double mid = 0.5 * (lo + hi);
    (ratioOf(mid) > ratio ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The q-quantile of a chi-square with k degrees of freedom over k (Wilson-Hilferty).
double chiSquareQuantileOverDof(double q, double k) {
  double lo = -10, hi = 10;  // z with Phi(z) = q
  for (int it = 0; it < 80; ++it) {
    const double mid = 0.5 * (lo + hi);
    (0.5 * std::erfc(-mid / std::sqrt(2.0)) < q ? lo : hi) = mid;
  }
  const double z = 0.5 * (lo + hi), a = 2 / (9 * k);
  return std::max(1e-3, std::pow(std::max(0.0, 1 - a + z * std::sqrt(a)), 3));
}

// ---- patch statistics ------------------------------------------------------------------------

struct Patch {
  int x = 0, y = 0;
  std::array<double, 3> mean{}, residual{}, highFrequency{};  // per channel; variances
  std::array<bool, 3> valid{};
};

// The plane-fit residual of channel c of the patch at (x0, y0), row-major; false when a pixel
// is non-finite or clipped (at the channel's lowest or highest value).
bool patchResidual(const ImageF& img, int x0, int y0, int P, int c, double lo, double hi,
                   std::vector<double>& r, double& mean) {
  r.resize(size_t(P * P));
  double sum = 0, sx = 0, sy = 0, sxx = 0;
  const double c0 = 0.5 * (P - 1);
  for (int j = 0; j < P; ++j)
    for (int i = 0; i < P; ++i) {
      const double v = img.at(x0 + i, y0 + j, c);
      if (!std::isfinite(v) || v <= lo || v >= hi) return false;
      r[size_t(j * P + i)] = v;
      sum += v, sx += (i - c0) * v, sy += (j - c0) * v, sxx += (i - c0) * (i - c0);
    }
  const double n = double(P * P);
  mean = sum / n;
  const double bx = sx / sxx, by = sy / sxx;  // sxx = sum of (j - c0)^2 too
  for (int j = 0; j < P; ++j)
    for (int i = 0; i < P; ++i) r[size_t(j * P + i)] -= mean + bx * (i - c0) + by * (j - c0);
  return true;
}

// Mean of (Immerkaer response / 6)^2 over the patch's interior.
double highFrequencyOf(const std::vector<double>& r, int P) {
  double s = 0;
  for (int j = 1; j + 1 < P; ++j)
    for (int i = 1; i + 1 < P; ++i) {
      const auto v = [&](int dx, int dy) { return r[size_t((j + dy) * P + i + dx)]; };
      const double l = v(-1, -1) + v(1, -1) + v(-1, 1) + v(1, 1) -
                       2 * (v(0, -1) + v(-1, 0) + v(1, 0) + v(0, 1)) + 4 * v(0, 0);
      s += (l / 6) * (l / 6);
    }
  return s / double((P - 2) * (P - 2));
}

double sumOfSquares(const std::vector<double>& r) {
  return std::inner_product(r.begin(), r.end(), r.begin(), 0.0);
}

std::vector<Patch> measurePatches(const ImageF& img, const NoiseMeasureOptions& opt,
                                  const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
  const int P = opt.patchPx;
  const double area = double(img.width) * img.height;
  const int stride =
      std::max(P / 2, int(std::ceil(std::sqrt(area / double(std::max(1L, opt.maxPatches))))));
  std::vector<Patch> patches;
  std::vector<double> r;
  for (int y = 0; y + P <= img.height; y += stride)
    for (int x = 0; x + P <= img.width; x += stride) {
      Patch p;
      p.x = x, p.y = y;
      for (int c = 0; c < 3; ++c) {
        p.valid[size_t(c)] =
            patchResidual(img, x, y, P, c, lo[size_t(c)], hi[size_t(c)], r, p.mean[size_t(c)]);
        if (!p.valid[size_t(c)]) continue;
        p.residual[size_t(c)] = sumOfSquares(r) / double(P * P);
        p.highFrequency[size_t(c)] = highFrequencyOf(r, P);
        p.valid[size_t(c)] = std::isfinite(p.residual[size_t(c)]) &&
                             std::isfinite(p.highFrequency[size_t(c)]);
      }
      if (p.valid[0] || p.valid[1] || p.valid[2]) patches.push_back(p);
    }
  return patches;
}

// ---- the lower envelope per intensity bin ------------------------------------------------------

struct Bin {
  double intensity = 0;
  double residualQuantile = 0;  // the envelope quantile of the residual variances
  std::vector<size_t> flat;     // patches at or below it
  std::vector<size_t> members;  // every patch of the bin
};

// Patches whose residual variance is at most `factor` times what noise alone gives them
// (`expected`): nearly every noise-only patch (so the set is not biased toward quiet noise, as
// the envelope's lowest quarter is), few textured ones.
void keepNoiseOnly(const std::vector<Patch>& patches, int c, double expected, double factor, Bin& bin) {
  bin.flat.clear();
  for (size_t m : bin.members)
    if (patches[m].residual[size_t(c)] <= factor * expected) bin.flat.push_back(m);
}

std::vector<Bin> envelopeBins(const std::vector<Patch>& patches, int c, const NoiseMeasureOptions& opt) {
  std::vector<size_t> idx;
  for (size_t i = 0; i < patches.size(); ++i)
    if (patches[i].valid[size_t(c)]) idx.push_back(i);
  const int minPer = std::max(4, opt.minPatchesPerBin);
  const int nBins = std::min(std::max(1, opt.maxBins), int(idx.size()) / minPer);
  std::vector<Bin> bins;
  if (nBins < 1) return bins;
  std::sort(idx.begin(), idx.end(),
            [&](size_t a, size_t b) { return patches[a].mean[size_t(c)] < patches[b].mean[size_t(c)]; });
  for (int b = 0; b < nBins; ++b) {
    const size_t from = idx.size() * size_t(b) / size_t(nBins),
                 to = idx.size() * size_t(b + 1) / size_t(nBins);
    std::vector<size_t> members(idx.begin() + long(from), idx.begin() + long(to));
    Bin bin;
    bin.intensity = patches[members[members.size() / 2]].mean[size_t(c)];
    std::vector<double> v;
    v.reserve(members.size());
    for (size_t m : members) v.push_back(patches[m].residual[size_t(c)]);
    const size_t q = std::min(v.size() - 1, size_t(opt.envelopeQuantile * double(v.size())));
    std::nth_element(v.begin(), v.begin() + long(q), v.end());
    bin.residualQuantile = v[q];
    for (size_t m : members)
      if (patches[m].residual[size_t(c)] <= bin.residualQuantile) bin.flat.push_back(m);
    bin.members = std::move(members);
    bins.push_back(std::move(bin));
  }
  return bins;
}

// High-frequency against residual variance over the flat patches of every bin and channel, each
// bin's patches weighted by its envelope (so bright bins do not dominate).
double flatHighFrequencyRatio(const std::vector<Patch>& patches,
                              const std::array<std::vector<Bin>, 3>& bins) {
  double hf = 0, res = 0;
  for (int c = 0; c < 3; ++c)
    for (const Bin& b : bins[size_t(c)]) {
      if (!(b.residualQuantile > 0)) continue;
      for (size_t m : b.flat) {
        hf += patches[m].highFrequency[size_t(c)] / b.residualQuantile;
        res += patches[m].residual[size_t(c)] / b.residualQuantile;
      }
    }
  return res > 0 ? hf / res : 1.0;
}

// Mean correlation between the channels' residuals over patches flat in all three channels.
double channelCorrelationOf(const ImageF& img, const std::vector<Patch>& patches,
                            const std::array<std::vector<Bin>, 3>& bins, int P,
                            const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
  std::vector<int> flatIn(patches.size(), 0);
  for (int c = 0; c < 3; ++c)
    for (const Bin& b : bins[size_t(c)])
      for (size_t m : b.flat) ++flatIn[m];
  double sum = 0;
  int n = 0;
  std::array<std::vector<double>, 3> r;
  for (size_t i = 0; i < patches.size(); ++i) {
    if (flatIn[i] < 3) continue;
    double mean = 0;
    std::array<double, 3> norm{};
    bool ok = true;
    for (int c = 0; c < 3 && ok; ++c) {
      ok = patchResidual(img, patches[i].x, patches[i].y, P, c, lo[size_t(c)], hi[size_t(c)],
                         r[size_t(c)], mean);
      norm[size_t(c)] = std::sqrt(sumOfSquares(r[size_t(c)]));
      ok = ok && norm[size_t(c)] > 0 && std::isfinite(norm[size_t(c)]);
    }
    if (!ok) continue;
    for (int a = 0; a < 3; ++a)
      for (int b = a + 1; b < 3; ++b)
        sum += std::inner_product(r[size_t(a)].begin(), r[size_t(a)].end(), r[size_t(b)].begin(), 0.0) /
               (norm[size_t(a)] * norm[size_t(b)]);
    n += 3;
  }
  if (n < 3 * 16) return 0;
  return std::clamp(sum / n, 0.0, 0.95);
}

}  // namespace

// ---- PhotoNoise --------------------------------------------------------------------------------

bool PhotoNoise::empty() const {
  for (const auto& l : levels)
    for (const Knot& k : l)
      if (k.sigma > 0) return false;
  return true;
}

double PhotoNoise::sigma(int channel, double intensity) const {
  if (channel < 0 || channel > 2) return 0;
  const auto& l = levels[size_t(channel)];
  if (l.empty()) return 0;
  if (!(intensity > l.front().intensity)) return l.front().sigma;  // NaN included
  if (intensity >= l.back().intensity) return l.back().sigma;
  const auto hi = std::upper_bound(l.begin(), l.end(), intensity,
                                   [](double v, const Knot& k) { return v < k.intensity; });
  const auto lo = hi - 1;
  const double span = hi->intensity - lo->intensity;
  const double t = span > 0 ? (intensity - lo->intensity) / span : 0;
  return lo->sigma + t * (hi->sigma - lo->sigma);
}

PhotoNoise measurePhotoNoise(const ImageF& img, const NoiseMeasureOptions& opt) {
  PhotoNoise out;
  const int P = std::max(4, opt.patchPx);
  NoiseMeasureOptions o = opt;
  o.patchPx = P;
  if (img.channels < 3 || img.width < P || img.height < P) {
    out.notes.push_back("the photo is smaller than one " + std::to_string(P) + " x " +
                        std::to_string(P) + " patch");
    return out;
  }
  // Clip levels: each channel's lowest and highest finite value.
  std::array<double, 3> lo, hi;
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < img.pixelCount(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double v = img.data[i * size_t(img.channels) + size_t(c)];
      if (std::isfinite(v))
        lo[size_t(c)] = std::min(lo[size_t(c)], v), hi[size_t(c)] = std::max(hi[size_t(c)], v);
    }
  const std::vector<Patch> patches = measurePatches(img, o, lo, hi);
  std::array<std::vector<Bin>, 3> bins;
  for (int c = 0; c < 3; ++c) bins[size_t(c)] = envelopeBins(patches, c, o);
  if (bins[0].empty() && bins[1].empty() && bins[2].empty()) {
    out.notes.push_back("too few unclipped patches to measure the noise");
    return out;
  }
  // Twice: the grain's width from the flat patches' high-frequency share, then each bin's noise
  // variance from its envelope quantile (corrected by the chi-square quantile of a noise-only
  // patch of that grain); the second time the flat patches are every patch within a factor of
  // the first estimate's noise (the envelope's lowest quarter favours quiet noise).
  for (int pass = 0; pass < 2; ++pass) {
    out.grainWidthPx = widthForRatio(flatHighFrequencyRatio(patches, bins), P);
    const PatchResponse response = patchResponse(out.grainWidthPx, P);
    const double quantileFactor = chiSquareQuantileOverDof(o.envelopeQuantile, response.dof);
    const double noiseOnlyFactor = 1 + 4 * std::sqrt(2 / response.dof);  // 4 sd above the mean
    for (int c = 0; c < 3; ++c) {
      out.levels[size_t(c)].clear();
      out.patchesUsed[size_t(c)] = 0;
      for (Bin& b : bins[size_t(c)]) {
        // First pass: the envelope quantile; second: the mean over the noise-only patches (far
        // less spread, and they hold nearly every noise-only patch).
        double var = b.residualQuantile / (response.residualFactor * quantileFactor);
        if (pass == 1 && !b.flat.empty()) {
          double sum = 0;
          for (size_t m : b.flat) sum += patches[m].residual[size_t(c)];
          var = sum / double(b.flat.size()) / response.residualFactor;
        }
        if (!std::isfinite(var) ||
            var <= kNoiseFreeRelative * kNoiseFreeRelative * b.intensity * b.intensity)
          var = 0;  // float round-off of a noise-free photo
        out.levels[size_t(c)].push_back({b.intensity, std::sqrt(std::max(0.0, var))});
        keepNoiseOnly(patches, c, var * response.residualFactor, noiseOnlyFactor, b);
        out.patchesUsed[size_t(c)] += int(b.flat.size());
      }
    }
  }
  out.channelCorrelation = channelCorrelationOf(img, patches, bins, P, lo, hi);
  if (out.empty()) {
    out.notes.push_back("the photo shows no noise");
    out.grainWidthPx = 0, out.channelCorrelation = 0;
  }
  return out;
}

std::string describeNoise(const PhotoNoise& noise) {
  if (noise.empty())
    return "no grain: " +
           (noise.notes.empty() ? std::string("the photo shows no noise") : noise.notes.back());
  const auto& g = noise.levels[1].empty() ? noise.levels[0] : noise.levels[1];
  const double mid = g.empty() ? 0 : g[g.size() / 2].intensity;
  char buf[200];
  std::snprintf(
      buf, sizeof buf,
      "photo noise %.3g (R) %.3g (G) %.3g (B) at %.3g; grain %.2f px wide, %.0f%% shared by the channels",
      noise.sigma(0, mid), noise.sigma(1, mid), noise.sigma(2, mid), mid, noise.grainWidthPx,
      100 * noise.channelCorrelation);
  return buf;
}

// ---- the grain ---------------------------------------------------------------------------------

float grainAt(const PhotoNoise& noise, int x, int y, int c, uint32_t seed) {
  const std::vector<double> k = grainKernel(noise.grainWidthPx);
  const int r = int(k.size() / 2);
  const auto field = [&](int f) {
    double s = 0;
    for (int j = -r; j <= r; ++j)
      for (int i = -r; i <= r; ++i)
        s += k[size_t(i + r)] * k[size_t(j + r)] * whiteNoise(x + i, y + j, f, seed);
    return s;
  };
  const double rho =
      std::isfinite(noise.channelCorrelation) ? std::clamp(noise.channelCorrelation, 0.0, 1.0) : 0.0;
  return float(std::sqrt(rho) * field(0) + std::sqrt(1 - rho) * field(1 + std::clamp(c, 0, 2)));
}

namespace {

// The changed channels' bounding box [x0, x1) x [y0, y1); empty when nothing changed.
struct Box {
  int x0, y0, x1, y1;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
};

bool changedAt(const ImageF& with, const ImageF& without, const ImageF& mask, int x, int y, int c) {
  const float m = mask.empty() ? 0.f : mask.at(x, y, 0);
  return !(m == 0.f && with.at(x, y, c) == without.at(x, y, c));
}

Box changedBox(const ImageF& with, const ImageF& without, const ImageF& mask) {
  Box b{with.width, with.height, 0, 0};
  for (int y = 0; y < with.height; ++y)
    for (int x = 0; x < with.width; ++x)
      for (int c = 0; c < 3; ++c)
        if (changedAt(with, without, mask, x, y, c)) {
          b.x0 = std::min(b.x0, x), b.y0 = std::min(b.y0, y);
          b.x1 = std::max(b.x1, x + 1), b.y1 = std::max(b.y1, y + 1);
          break;
        }
  return b;
}

// The unit-variance grain of every channel over `box`: (box.w x box.h x 3), the shared field
// and each channel's own filtered separably from hashed white noise at absolute pixel positions
// (so a pixel's grain does not depend on the box).
ImageF grainFields(const PhotoNoise& noise, const Box& box, uint32_t seed) {
  const std::vector<double> k = grainKernel(noise.grainWidthPx);
  const int r = int(k.size() / 2), w = box.x1 - box.x0, h = box.y1 - box.y0;
  const int hw = h + 2 * r;  // rows of the horizontal pass
  const double rho =
      std::isfinite(noise.channelCorrelation) ? std::clamp(noise.channelCorrelation, 0.0, 1.0) : 0.0;
  const double a = std::sqrt(rho), b = std::sqrt(1 - rho);
  ImageF out(w, h, 3, 0.f);
  std::vector<double> horiz(size_t(hw) * size_t(w));
  for (int f = 0; f < kFields; ++f) {
    parallelFor(tbb::blocked_range<int>(0, hw), [&](const tbb::blocked_range<int>& rows) {
      std::vector<double> line(size_t(w + 2 * r));
      for (int j = rows.begin(); j < rows.end(); ++j) {
        const int y = box.y0 - r + j;
        for (int i = 0; i < w + 2 * r; ++i) line[size_t(i)] = whiteNoise(box.x0 - r + i, y, f, seed);
        for (int i = 0; i < w; ++i) {
          double s = 0;
          for (size_t t = 0; t < k.size(); ++t) s += k[t] * line[size_t(i) + t];
          horiz[size_t(j) * size_t(w) + size_t(i)] = s;
        }
      }
    });
    const double weight = f == 0 ? a : b;
    parallelFor(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
      for (int j = rows.begin(); j < rows.end(); ++j)
        for (int i = 0; i < w; ++i) {
          double s = 0;
          for (size_t t = 0; t < k.size(); ++t)
            s += k[t] * horiz[(size_t(j) + t) * size_t(w) + size_t(i)];
          for (int c = 0; c < 3; ++c)
            if (f == 0 || f == c + 1) out.at(i, j, c) += float(weight * s);
        }
    });
  }
  return out;
}

// The render's own standard error at (x, y) in linear units: RenderFrame::noise is in sRGB,
// mapped by the slope of the sRGB encoding at the pixel's mean with-object value (session.cpp's
// pixelError); the same slope takes it back. 0 where non-finite.
double renderSigmaLinear(const RenderFrame& frame, int x, int y) {
  double meanWith = 0;
  for (int c = 0; c < 3; ++c) meanWith += frame.withObjects.at(x, y, c) / 3.0;
  double slope = 12.92;
  if (meanWith > 0.0031308) slope = 1.055 / 2.4 * std::pow(std::min(meanWith, 1.0), 1.0 / 2.4 - 1.0);
  const double s = frame.noise.at(x, y, 0) / slope;
  return std::isfinite(s) && s > 0 ? s : 0.0;
}

}  // namespace

ImageF grainField(const PhotoNoise& noise, int width, int height, uint32_t seed) {
  if (noise.empty() || width <= 0 || height <= 0) return {};
  // Each pixel's sums run over the same hashed noise in the same order whatever the box, so
  // the whole frame's fields hold every box's bits.
  return grainFields(noise, Box{0, 0, width, height}, seed);
}

void addGrain(ImageF& composite, const ImageF& photoLinear, const RenderFrame& frame,
              const PhotoNoise& noise, uint32_t seed, const ImageF* field) {
  const ImageF &with = frame.withObjects, &without = frame.withoutObjects, &mask = frame.mask;
  const int W = composite.width, H = composite.height;
  INLAY_CHECK(photoLinear.width == W && photoLinear.height == H && photoLinear.channels >= 3);
  INLAY_CHECK(with.width == W && with.height == H && with.channels == 3);
  INLAY_CHECK(without.width == W && without.height == H && without.channels == 3);
  INLAY_CHECK(mask.empty() || (mask.width == W && mask.height == H && mask.channels >= 1));
  const bool renderNoise = frame.noise.width == W && frame.noise.height == H &&
                           frame.noise.channels >= 1;
  if (noise.empty() || composite.channels < 3) return;
  const Box box = changedBox(with, without, mask);
  if (box.empty()) return;
  const bool whole = field && field->width == W && field->height == H && field->channels == 3;
  const ImageF drawn = whole ? ImageF() : grainFields(noise, box, seed);
  const ImageF& grain = whole ? *field : drawn;
  const int gx = whole ? 0 : box.x0, gy = whole ? 0 : box.y0;  // the grain image's origin
  parallelFor(tbb::blocked_range<int>(box.y0, box.y1), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = box.x0; x < box.x1; ++x) {
        const double sRender = renderNoise ? renderSigmaLinear(frame, x, y) : 0.0;
        for (int c = 0; c < 3; ++c) {
          if (!changedAt(with, without, mask, x, y, c)) continue;
          const float m = mask.empty() ? 0.f : mask.at(x, y, 0);
          const double mm = std::isfinite(m) ? std::clamp(double(m), 0.0, 1.0) : 0.0;
          float& v = composite.at(x, y, c);
          const double sOut = noise.sigma(c, v), sPhoto = noise.sigma(c, photoLinear.at(x, y, c));
          const double missing = sOut * sOut - (1 - mm) * (1 - mm) * sPhoto * sPhoto - sRender * sRender;
          if (!(missing > 0) || !std::isfinite(missing)) continue;
          const double g = double(v) + std::sqrt(missing) * grain.at(x - gx, y - gy, c);
          if (std::isfinite(g)) v = float(std::max(0.0, g));
        }
      }
  });
}

}  // namespace inlay
