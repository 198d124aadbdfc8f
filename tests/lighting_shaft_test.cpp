// The threshold a sun shaft's lit patch is cut at: Otsu's (OpenCV's) between the two modes of
// the box's log luminances, and the mean of each side.
#include "inlay/lighting/shaft.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace inlay {
namespace {

// `n` values, a fraction `lit` of them around `high`, the rest around `low` (normal, sd
// `spread`); `isLit` says which mode each was drawn from.
std::vector<double> twoModes(int n, double lit, double low, double high, double spread, unsigned seed,
                             std::vector<bool>& isLit) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> a(low, spread), b(high, spread);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> v(size_t(n), 0.0);
  isLit.assign(size_t(n), false);
  for (size_t i = 0; i < v.size(); ++i) {
    isLit[i] = u(rng) < lit;
    v[i] = isLit[i] ? b(rng) : a(rng);
  }
  return v;
}

TEST(ShaftThreshold, SplitsTwoModesBetweenThemWithTheirMeans) {
  for (double lit : {0.1, 0.3, 0.5, 0.8}) {
    std::vector<bool> isLit;
    const auto v = twoModes(4000, lit, -2.0, 0.5, 0.15, 3, isLit);
    double lo = 0, hi = 0;
    const double t = detail::otsuThreshold(v, &lo, &hi);
    // In the gap between the modes (Otsu's criterion is flat across it: any point there).
    EXPECT_GT(t, -2.0 + 2 * 0.15) << lit;
    EXPECT_LT(t, 0.5 - 2 * 0.15) << lit;
    EXPECT_NEAR(lo, -2.0, 0.02) << lit;
    EXPECT_NEAR(hi, 0.5, 0.02) << lit;
    // Every value on its own mode's side, but for a far outlier of a tail (16 sd apart).
    size_t wrong = 0;
    for (size_t i = 0; i < v.size(); ++i) wrong += (v[i] > t) != isLit[i];
    EXPECT_LE(wrong, 2u) << lit;
  }
}

TEST(ShaftThreshold, OverlappingModesSplitNearTheirCrossing) {
  // Equal spreads and sizes: the split is halfway, and few values land on the wrong side.
  std::vector<bool> isLit;
  const auto v = twoModes(20000, 0.5, -1.0, 0.0, 0.2, 5, isLit);
  double lo = 0, hi = 0;
  const double t = detail::otsuThreshold(v, &lo, &hi);
  EXPECT_NEAR(t, -0.5, 0.05);
  size_t wrong = 0;
  for (size_t i = 0; i < v.size(); ++i) wrong += (v[i] > t) != isLit[i];
  EXPECT_LT(double(wrong) / double(v.size()), 0.02);  // 5 sd apart: 0.6 % for the ideal cut
  EXPECT_LT(lo, -0.9);
  EXPECT_GT(hi, -0.1);
}

TEST(ShaftThreshold, TwoValuesSplitBetweenThem) {
  std::vector<double> v(30, -3.0);
  v.resize(50, 1.0);
  double lo = 0, hi = 0;
  const double t = detail::otsuThreshold(v, &lo, &hi);
  EXPECT_GT(t, -3.0);
  EXPECT_LT(t, 1.0);
  EXPECT_DOUBLE_EQ(lo, -3.0);
  EXPECT_DOUBLE_EQ(hi, 1.0);
}

TEST(ShaftThreshold, ConstantValuesGiveThatValue) {
  const std::vector<double> v(20, 0.25);
  double lo = 0, hi = 0;
  EXPECT_DOUBLE_EQ(detail::otsuThreshold(v, &lo, &hi), 0.25);
  EXPECT_DOUBLE_EQ(lo, 0.25);
  EXPECT_DOUBLE_EQ(hi, 0.25);
}

}  // namespace
}  // namespace inlay
