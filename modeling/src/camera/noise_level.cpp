// The photo's noise level against its codes (see noise_level.h).
#include "noise_level.h"

#include "inlay/modeling/parallel.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace inlay::detail {

namespace {

constexpr int kBlock = 8;
constexpr int kMaxBins = 12;
constexpr int kMinBlocksPerBin = 20;
constexpr int kMinBins = 6;
constexpr double kQuantisation = 1.0 / 12;  // variance of rounding to whole codes

struct BlockPoint {
  double code, sigma;
};

// One block row's flat blocks of channel c, left to right: 3 x 3 mean codes within the block
// spread by less than max(8, 10 % of the mean), none near clipping. The 3 x 3 sums are whole
// numbers (a row of 3-sums, then three of those), so every value is what the direct sums give.
// `sums` is scratch.
void flatBlocksInRow(const unsigned char* codes, int W, int c, int by, std::vector<BlockPoint>& out,
                     std::vector<int>& sums) {
  auto at = [&](int x, int y) {
    return int(codes[(size_t(y) * size_t(W) + size_t(x)) * 3 + size_t(c)]);
  };
  constexpr int kRows = kBlock + 2;  // rows by - 1 .. by + kBlock
  sums.assign(size_t(kRows) * size_t(W), 0);
  for (int k = 0; k < kRows; ++k)
    for (int x = 1; x + 1 < W; ++x)
      sums[size_t(k) * size_t(W) + size_t(x)] = at(x - 1, by - 1 + k) + at(x, by - 1 + k) +
                                                at(x + 1, by - 1 + k);
  auto box = [&](int x, int k) {  // the 3 x 3 sum around (x, by - 1 + k)
    const size_t i = size_t(k) * size_t(W) + size_t(x);
    return sums[i - size_t(W)] + sums[i] + sums[i + size_t(W)];
  };
  for (int bx = 1; bx + kBlock < W; bx += kBlock) {
    double lo = 1e9, hi = -1e9, sum = 0, sum2 = 0;
    // A mean at or beyond the clipping codes, or a spread above 25.5 (10 % of the largest mean),
    // rejects the block whatever its other pixels.
    bool rejected = false;
    for (int y = by; y < by + kBlock && !rejected; ++y) {
      for (int x = bx; x < bx + kBlock; ++x) {
        const double mean = double(box(x, y - by + 1)) / 9;
        lo = std::min(lo, mean), hi = std::max(hi, mean);
        const int four = at(x - 1, y) + at(x + 1, y) + at(x, y - 1) + at(x, y + 1);
        const double r = at(x, y) - 0.25 * four;
        sum += mean, sum2 += r * r;
      }
      rejected = lo <= 3 || hi >= 250 || hi - lo > 25.5;
    }
    if (rejected) continue;
    const double n = kBlock * kBlock, m = sum / n;
    if (hi - lo >= std::max(8.0, 0.1 * m)) continue;
    // The residual of white noise against its four neighbours' mean has 1.25 x its variance.
    out.push_back({m, std::sqrt(sum2 / n / 1.25)});
  }
}

// Every channel's flat blocks (flatBlocksInRow), channel by channel, each top to bottom: block
// rows in parallel, joined in that order (the points' order does not depend on the threads).
std::vector<BlockPoint> flatBlocksOf(const std::vector<unsigned char>& codes, int W, int H) {
  std::vector<int> rowStarts;
  for (int by = 1; by + kBlock < H; by += kBlock) rowStarts.push_back(by);
  const int rows = int(rowStarts.size());
  std::vector<std::vector<BlockPoint>> perRow(size_t(3 * rows));
  parallelFor(tbb::blocked_range<int>(0, 3 * rows), [&](const tbb::blocked_range<int>& r) {
    std::vector<int> sums;
    for (int i = r.begin(); i < r.end(); ++i)
      flatBlocksInRow(codes.data(), W, i / rows, rowStarts[size_t(i % rows)], perRow[size_t(i)], sums);
  });
  std::vector<BlockPoint> out;
  for (const auto& row : perRow) out.insert(out.end(), row.begin(), row.end());
  return out;
}

// The q-quantile (nearest rank) of a non-empty list; q = 0.5 is the median.
double quantileOf(std::vector<double> v, double q) {
  const size_t k = std::min(v.size() - 1, size_t(q * double(v.size())));
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
  return v[k];
}

double medianOf(std::vector<double> v) { return quantileOf(std::move(v), 0.5); }

// g at a fractional code, by linear interpolation.
double at(const std::array<double, 256>& g, double code) {
  const double c = std::clamp(code, 0.0, 255.0);
  const int k = std::min(254, int(c));
  return g[size_t(k)] + (c - k) * (g[size_t(k + 1)] - g[size_t(k)]);
}

}  // namespace

NoiseLevel measureNoiseLevel(const std::vector<unsigned char>& codes, int W, int H,
                             double sigmaQuantile) {
  NoiseLevel out;
  const double q = std::isnan(sigmaQuantile) ? 0.5 : std::clamp(sigmaQuantile, 0.0, 1.0);
  std::vector<BlockPoint> points;
  if (W > kBlock + 2 && H > kBlock + 2 && codes.size() >= size_t(W) * size_t(H) * 3)
    points = flatBlocksOf(codes, W, H);
  out.flatBlocks = int(points.size());
  std::sort(points.begin(), points.end(),
            [](const BlockPoint& a, const BlockPoint& b) { return a.code < b.code; });
  const int bins = std::min(kMaxBins, int(points.size()) / kMinBlocksPerBin);
  for (int b = 0; b < bins; ++b) {
    const size_t i0 = points.size() * size_t(b) / size_t(bins),
                 i1 = points.size() * size_t(b + 1) / size_t(bins);
    std::vector<double> code, sigma;
    for (size_t i = i0; i < i1; ++i) code.push_back(points[i].code), sigma.push_back(points[i].sigma);
    out.bins.push_back({medianOf(code), quantileOf(sigma, q), int(i1 - i0)});
  }
  if (int(out.bins.size()) < kMinBins) {
    out.undetermined = "too few flat regions to measure the noise (" + std::to_string(points.size()) +
                       " flat 8 x 8 blocks)";
  } else if (out.bins.back().code - out.bins.front().code < 32) {
    out.undetermined = "the flat regions cover too few codes to measure the noise against them";
  } else {
    // Noise that rounding to whole codes alone explains cannot show the curve.
    std::vector<double> sigmas;
    for (const NoiseBin& b : out.bins) sigmas.push_back(b.sigma);
    if (medianOf(sigmas) * medianOf(sigmas) < 2 * kQuantisation)
      out.undetermined = "the photo shows no measurable noise";
  }
  return out;
}

// The non-negative a, b, c of var = a + b x + c x^2 that best fit the points in relative
// terms (each row divided by its variance), by trying every subset of the three terms (an
// exact active-set search for three unknowns); returns the fitted variances' RMS log deviation.
double bestQuadraticFit(const std::vector<double>& x, const std::vector<double>& v) {
  const size_t n = x.size();
  double best = std::numeric_limits<double>::infinity();
  for (int subset = 1; subset < 8; ++subset) {
    std::vector<int> terms;
    for (int t = 0; t < 3; ++t)
      if (subset & (1 << t)) terms.push_back(t);
    const int m = int(terms.size());
    Eigen::MatrixXd A(n, m);
    for (size_t i = 0; i < n; ++i)
      for (int j = 0; j < m; ++j) A(Eigen::Index(i), j) = std::pow(x[i], terms[size_t(j)]) / v[i];
    const Eigen::VectorXd coef = A.colPivHouseholderQr().solve(Eigen::VectorXd::Ones(Eigen::Index(n)));
    if (!coef.allFinite() || coef.minCoeff() < 0) continue;
    const Eigen::VectorXd fit = A * coef;  // fitted variance over measured
    if (fit.minCoeff() <= 0) continue;
    double sum = 0;
    for (Eigen::Index i = 0; i < fit.size(); ++i) sum += std::log(fit[i]) * std::log(fit[i]);
    best = std::min(best, std::sqrt(sum / double(n)));
  }
  return best;
}

double noiseLevelResidual(const NoiseLevel& level, const std::array<double, 256>& g) {
  const size_t n = level.bins.size();
  if (n < 2) return 0;
  std::vector<double> x(n), v(n);
  for (size_t i = 0; i < n; ++i) {
    const NoiseBin& b = level.bins[i];
    const double s = std::sqrt(std::max(b.sigma * b.sigma - kQuantisation, 0.01));
    const double slope = std::max(0.5 * (at(g, b.code + 1) - at(g, b.code - 1)), 1e-12);
    x[i] = std::max(at(g, b.code), 1e-12);
    v[i] = slope * slope * s * s;
  }
  // Scale both to at most 1 (the fit is scale-free; this keeps the matrix well conditioned).
  const double xMax = *std::max_element(x.begin(), x.end()),
               vMax = *std::max_element(v.begin(), v.end());
  for (size_t i = 0; i < n; ++i) x[i] /= xMax, v[i] = std::max(v[i] / vMax, 1e-12);
  const double r = bestQuadraticFit(x, v);
  return std::isfinite(r) ? r : 10.0;  // no admissible fit: as bad as it gets
}

}  // namespace inlay::detail
