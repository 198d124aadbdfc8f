// The intrinsic decomposition (decompose.h): Retinex on an image with a known reflectance, the
// primal-dual solver on known layers, and stiff input (black, clipped, Gamma ~ 0, constant,
// extreme weights, tiny and large photos): finite output, constraints held to 1e-6 and a clear
// report when the solver stops early.
#include "inlay/lighting/decompose.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

namespace inlay {
namespace {

// A checker reflectance (two colours) under smooth shading; Gamma a smooth fraction of it.
struct Layers {
  ImageF B, gamma, rhoTrue;
  std::vector<uint8_t> valid, clipped;
};

Layers makeLayers(int W, int H, int cell = 8) {
  Layers l{ImageF(W, H, 3), ImageF(W, H, 3), ImageF(W, H, 3),
           std::vector<uint8_t>(size_t(W) * H, 1), std::vector<uint8_t>(size_t(W) * H, 0)};
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const bool odd = ((x / cell) + (y / cell)) & 1;
      const Vec3 rho = odd ? Vec3(0.7, 0.6, 0.5) : Vec3(0.3, 0.35, 0.4);
      const double u = double(x) / W, v = double(y) / H;
      const double direct = 0.4 + 0.3 * std::exp(-4 * ((u - 0.4) * (u - 0.4) + (v - 0.3) * (v - 0.3)));
      const double gamma = 0.2 + 0.1 * u;
      l.rhoTrue.setRgb(x, y, rho);
      l.gamma.setRgb(x, y, Vec3::Constant(gamma));
      l.B.setRgb(x, y, rho * (direct + gamma));
    }
  return l;
}

// 0 <= rho <= 1; where B is not clipped rho * Gamma <= B and D = B - rho * Gamma >= 0.
void expectFeasible(const Layers& l, const Decomposition& d, double tol = 1e-6) {
  ASSERT_EQ(d.albedo.width, l.B.width);
  ASSERT_EQ(d.albedo.height, l.B.height);
  for (int y = 0; y < l.B.height; ++y)
    for (int x = 0; x < l.B.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double r = d.albedo.at(x, y, c), D = d.direct.at(x, y, c);
        ASSERT_TRUE(std::isfinite(r) && std::isfinite(D)) << x << "," << y;
        ASSERT_GE(r, -tol);
        ASSERT_LE(r, 1 + tol);
        ASSERT_GE(D, -tol);
        const double b = l.B.at(x, y, c), g = l.gamma.at(x, y, c);
        if (!l.clipped[size_t(y) * l.B.width + x] && std::isfinite(b) && std::isfinite(g)) {
          ASSERT_LE(r * std::max(g, 0.0), std::max(b, 0.0) + tol) << x << "," << y;
          ASSERT_NEAR(D, std::max(b, 0.0) - r * std::max(g, 0.0), 1e-5 * (1 + std::abs(b)));
        }
      }
}

ImageF anchoredRetinex(const Layers& l) {
  ImageF r = retinexReflectance(l.B, l.valid);
  // Scale per channel to the truth's mean (what the light fit provides in the pipeline).
  for (int c = 0; c < 3; ++c) {
    double st = 0, se = 0;
    for (int y = 0; y < r.height; ++y)
      for (int x = 0; x < r.width; ++x) st += l.rhoTrue.at(x, y, c), se += r.at(x, y, c);
    for (int y = 0; y < r.height; ++y)
      for (int x = 0; x < r.width; ++x)
        r.at(x, y, c) = std::clamp(float(r.at(x, y, c) * st / se), 0.f, 1.f);
  }
  return r;
}

double mae(const ImageF& a, const ImageF& b) {
  double s = 0;
  for (size_t i = 0; i < a.data.size(); ++i) s += std::abs(a.data[i] - b.data[i]);
  return s / double(a.data.size());
}

TEST(Retinex, RecoversCheckerUnderSmoothShading) {
  const Layers l = makeLayers(64, 48);
  const ImageF r = anchoredRetinex(l);
  EXPECT_LT(mae(r, l.rhoTrue), 0.02);
  // A flat grey would be far off: the test can fail.
  ImageF grey(64, 48, 3, 0.5f);
  EXPECT_GT(mae(grey, l.rhoTrue), 0.1);
}

TEST(Retinex, OddSizesAndInvalidPixelsStayFinite) {
  Layers l = makeLayers(17, 13, 3);
  for (int x = 0; x < 17; ++x) l.valid[size_t(6) * 17 + x] = 0, l.B.setRgb(x, 6, Vec3::Zero());
  const ImageF r = retinexReflectance(l.B, l.valid);
  for (float v : r.data) ASSERT_TRUE(std::isfinite(v) && v > 0);
}

TEST(Decompose, LowersTheObjectiveAndKeepsTheConstraints) {
  const Layers l = makeLayers(48, 40);
  ImageF rho0 = anchoredRetinex(l);
  DecomposeOptions o;
  o.maxIterations = 200;
  o.timeLimitSeconds = 0;
  auto d = decomposeIntrinsic(l.B, l.gamma, rho0, l.valid, l.clipped, o);
  ASSERT_TRUE(d) << d.error().message();
  expectFeasible(l, *d);
  ASSERT_GE(d->history.size(), 2u);
  EXPECT_LT(d->history.back().objective, d->history.front().objective + 1e-9);
  for (const auto& h : d->history) {
    EXPECT_TRUE(std::isfinite(h.objective));
    EXPECT_GE(h.seconds, 0);
  }
  EXPECT_FALSE(d->report.empty());
  // Still the checker: close to the truth.
  EXPECT_LT(mae(d->albedo, l.rhoTrue), 0.06);
}

TEST(Decompose, ConvergesOnASmallProblemAndSaysSo) {
  const Layers l = makeLayers(24, 20, 6);
  DecomposeOptions o;
  o.maxIterations = 20000;
  o.timeLimitSeconds = 0;
  o.tolerance = 1e-3;
  auto d = decomposeIntrinsic(l.B, l.gamma, anchoredRetinex(l), l.valid, l.clipped, o);
  ASSERT_TRUE(d);
  EXPECT_TRUE(d->converged) << d->report;
  EXPECT_NE(d->report.find("converged after"), std::string::npos);
  EXPECT_LT(d->history.back().primalResidual, 1e-3);
  EXPECT_LT(d->history.back().dualResidual, 1e-3);
  expectFeasible(l, *d);
}

TEST(Decompose, ReportsWhenStoppedBeforeConvergence) {
  const Layers l = makeLayers(32, 32);
  DecomposeOptions o;
  o.maxIterations = 3;
  o.tolerance = 1e-12;
  auto d = decomposeIntrinsic(l.B, l.gamma, ImageF(32, 32, 3, 0.5f), l.valid, l.clipped, o);
  ASSERT_TRUE(d);
  EXPECT_FALSE(d->converged);
  EXPECT_NE(d->report.find("not converged"), std::string::npos) << d->report;
  EXPECT_NE(d->report.find("iteration limit"), std::string::npos) << d->report;
  EXPECT_EQ(d->iterations, 3);
  expectFeasible(l, *d);
}

TEST(Decompose, BlackPixelsGetZeroAlbedoAndStayFinite) {
  Layers l = makeLayers(32, 24);
  for (int y = 5; y < 15; ++y)
    for (int x = 3; x < 20; ++x) l.B.setRgb(x, y, Vec3::Zero());
  auto d = decomposeIntrinsic(l.B, l.gamma, anchoredRetinex(l), l.valid, l.clipped, {});
  ASSERT_TRUE(d);
  expectFeasible(l, *d);
  EXPECT_NEAR(d->albedo.at(10, 10, 1), 0.0, 1e-6);  // B = 0 with Gamma > 0: rho Gamma <= 0
}

TEST(Decompose, SaturatedPixelsAreOnlyALowerBound) {
  Layers l = makeLayers(32, 24);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      l.B.setRgb(x, y, Vec3::Ones());
      l.gamma.setRgb(x, y, Vec3::Constant(3.0));  // more than B: the cap is lifted there
      l.clipped[size_t(y) * 32 + x] = 1;
      l.valid[size_t(y) * 32 + x] = 0;
    }
  auto d = decomposeIntrinsic(l.B, l.gamma, anchoredRetinex(l), l.valid, l.clipped, {});
  ASSERT_TRUE(d);
  expectFeasible(l, *d);
}

TEST(Decompose, GammaNearZeroAndNonFiniteInputs) {
  Layers l = makeLayers(32, 24);
  for (int y = 0; y < 24; ++y)
    for (int x = 16; x < 32; ++x) l.gamma.setRgb(x, y, Vec3::Constant(1e-14));
  l.B.at(3, 3, 0) = NAN;
  l.gamma.at(4, 4, 1) = INFINITY;
  l.clipped[size_t(3) * 32 + 3] = l.clipped[size_t(4) * 32 + 4] = 1;
  auto d = decomposeIntrinsic(l.B, l.gamma, anchoredRetinex(l), l.valid, l.clipped, {});
  ASSERT_TRUE(d);
  expectFeasible(l, *d);
  // All Gamma ~ 0: the normalisation must not blow up.
  Layers z = makeLayers(16, 16);
  z.gamma = ImageF(16, 16, 3, 1e-20f);
  auto dz = decomposeIntrinsic(z.B, z.gamma, ImageF(16, 16, 3, 0.5f), z.valid, z.clipped, {});
  ASSERT_TRUE(dz);
  expectFeasible(z, *dz);
}

TEST(Decompose, ConstantImageGivesAConstantAlbedo) {
  Layers l = makeLayers(20, 20);
  l.B = ImageF(20, 20, 3, 0.3f);
  l.gamma = ImageF(20, 20, 3, 0.2f);
  const ImageF rho0 = retinexReflectance(l.B, l.valid);
  for (float v : rho0.data) ASSERT_NEAR(v, 1.0, 1e-4);  // flat reflectance, geometric mean 1
  ImageF start(20, 20, 3, 0.6f);
  DecomposeOptions o;
  o.timeLimitSeconds = 0;
  auto d = decomposeIntrinsic(l.B, l.gamma, start, l.valid, l.clipped, o);
  ASSERT_TRUE(d);
  expectFeasible(l, *d);
  for (float v : d->albedo.data) EXPECT_NEAR(v, 0.6f, 1e-4);
}

TEST(Decompose, WeightsSweptOverTwelveDecades) {
  const Layers l = makeLayers(24, 24, 6);
  const ImageF rho0 = anchoredRetinex(l);
  for (int which = 0; which < 3; ++which)
    for (double w : {1e-6, 1e-3, 1.0, 1e3, 1e6}) {
      DecomposeOptions o;
      (which == 0 ? o.g1 : which == 1 ? o.g2 : o.g3) = w;
      o.maxIterations = 300;
      o.timeLimitSeconds = 0;
      auto d = decomposeIntrinsic(l.B, l.gamma, rho0, l.valid, l.clipped, o);
      ASSERT_TRUE(d) << which << " " << w;
      SCOPED_TRACE(::testing::Message() << "weight " << which << " = " << w << ": " << d->report);
      expectFeasible(l, *d);
      EXPECT_EQ(d->converged, d->report.rfind("converged", 0) == 0);
      for (const auto& h : d->history) ASSERT_TRUE(std::isfinite(h.objective));
    }
  DecomposeOptions bad;
  bad.g2 = -1;
  EXPECT_FALSE(decomposeIntrinsic(l.B, l.gamma, rho0, l.valid, l.clipped, bad));
  bad.g2 = NAN;
  EXPECT_FALSE(decomposeIntrinsic(l.B, l.gamma, rho0, l.valid, l.clipped, bad));
}

TEST(Decompose, TinyPhotoAndBadSizes) {
  const Layers l = makeLayers(16, 16, 4);
  auto d = decomposeIntrinsic(l.B, l.gamma, anchoredRetinex(l), l.valid, l.clipped, {});
  ASSERT_TRUE(d);
  expectFeasible(l, *d);
  EXPECT_FALSE(decomposeIntrinsic(l.B, ImageF(15, 16, 3), l.B, l.valid, l.clipped, {}));
  EXPECT_FALSE(decomposeIntrinsic(l.B, l.gamma, l.B, std::vector<uint8_t>(3, 1), l.clipped, {}));
  EXPECT_FALSE(decomposeIntrinsic(ImageF(), ImageF(), ImageF(), {}, {}, {}));
  const Layers one = makeLayers(1, 1, 1);
  auto d1 = decomposeIntrinsic(one.B, one.gamma, one.rhoTrue, one.valid, one.clipped, {});
  ASSERT_TRUE(d1);
  expectFeasible(one, *d1);
}

TEST(Decompose, LargePhotoStaysFiniteAndStopsOnTime) {
  const Layers l = makeLayers(4000, 3000, 40);
  const ImageF rho0 = retinexReflectance(l.B, l.valid);
  ImageF start = rho0;
  for (float& v : start.data) v = std::clamp(v * 0.45f, 0.f, 1.f);
  DecomposeOptions o;
  o.maxIterations = 1000;
  o.timeLimitSeconds = 2.0;
  // Only the solve is timed: building the 12-megapixel layers is not under the time limit
  // (and takes a minute in a sanitizer build).
  const auto t0 = std::chrono::steady_clock::now();
  auto d = decomposeIntrinsic(l.B, l.gamma, start, l.valid, l.clipped, o);
  ASSERT_TRUE(d);
  EXPECT_FALSE(d->converged);
  EXPECT_NE(d->report.find("time limit"), std::string::npos) << d->report;
  expectFeasible(l, *d);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 20);
}

}  // namespace
}  // namespace inlay
