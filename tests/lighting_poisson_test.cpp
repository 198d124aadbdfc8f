// The multigrid Poisson solve against the DCT (exact on even sizes), its residual on odd and
// awkward sizes, and the time it takes on a side with a large prime factor.
#include "inlay/lighting/poisson.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace inlay {
namespace {

// A divergence field: the Laplacian of a smooth field plus sharp steps (log reflectance edges),
// random noise, summing to zero.
std::vector<float> someDivergence(int W, int H, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> noise(0.f, 0.05f);
  std::vector<float> g(size_t(W) * H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      g[size_t(y) * W + x] = 0.3f * std::sin(0.05f * x) * std::cos(0.07f * y) +
                             (((x / 9) + (y / 7)) % 3 == 0 ? 0.4f : 0.f) + noise(rng);
  std::vector<float> div(g.size(), 0.f);  // L g: sums to zero by construction
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const size_t i = size_t(y) * W + x;
      if (x > 0) div[i] += g[i - 1] - g[i];
      if (x + 1 < W) div[i] += g[i + 1] - g[i];
      if (y > 0) div[i] += g[i - size_t(W)] - g[i];
      if (y + 1 < H) div[i] += g[i + size_t(W)] - g[i];
    }
  return div;
}

double rmsResidual(const std::vector<float>& u, const std::vector<float>& f, int W, int H) {
  double s = 0, n = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const size_t i = size_t(y) * W + x;
      double lu = 0;
      if (x > 0) lu += u[i - 1] - u[i];
      if (x + 1 < W) lu += u[i + 1] - u[i];
      if (y > 0) lu += u[i - size_t(W)] - u[i];
      if (y + 1 < H) lu += u[i + size_t(W)] - u[i];
      s += (lu - f[i]) * (lu - f[i]), n += 1;
    }
  return std::sqrt(s / n);
}

double rms(const std::vector<float>& f) {
  double s = 0;
  for (float v : f) s += double(v) * v;
  return std::sqrt(s / double(f.size()));
}

TEST(Poisson, MultigridMatchesTheDctOnEvenSizes) {
  for (auto [W, H] : {std::pair{64, 48}, {320, 240}, {200, 38}}) {
    const auto f = someDivergence(W, H, 7);
    PoissonReport rep;
    const auto mg = poissonNeumannMultigrid(f, W, H, 1e-5, 30, &rep);
    const auto dct = poissonNeumannDct(f, W, H);
    double mean = 0;
    for (float v : dct) mean += v;
    mean /= double(dct.size());
    double maxDiff = 0, range = 0;
    for (size_t i = 0; i < mg.size(); ++i) {
      maxDiff = std::max(maxDiff, std::abs(double(mg[i]) - (dct[i] - mean)));
      range = std::max(range, std::abs(dct[i] - mean));
    }
    EXPECT_GT(range, 0.1) << W << "x" << H;  // a solution with something in it
    EXPECT_LT(maxDiff, 2e-3) << W << "x" << H << " after " << rep.cycles << " cycles";
    EXPECT_LE(rep.relativeResidual, 1e-5);
    EXPECT_LT(rep.cycles, 20);
  }
}

TEST(Poisson, OddAndThinSizesReachTheTolerance) {
  for (auto [W, H] : {std::pair{17, 13}, {1, 1}, {1, 40}, {433, 3}, {301, 199}, {2, 2}}) {
    const auto f = someDivergence(W, H, 3);
    PoissonReport rep;
    const auto u = poissonNeumannMultigrid(f, W, H, 1e-5, 60, &rep);
    ASSERT_EQ(u.size(), f.size());
    for (float v : u) ASSERT_TRUE(std::isfinite(v));
    if (rms(f) > 0) {
      EXPECT_LE(rmsResidual(u, f, W, H), 2e-5 * rms(f)) << W << "x" << H;
    }
  }
}

TEST(Poisson, ZeroDivergenceGivesZero) {
  const std::vector<float> f(size_t(40) * 30, 0.f);
  PoissonReport rep;
  const auto u = poissonNeumannMultigrid(f, 40, 30, 1e-5, 30, &rep);
  for (float v : u) EXPECT_EQ(v, 0.f);
  EXPECT_EQ(rep.cycles, 0);
}

}  // namespace
}  // namespace inlay
