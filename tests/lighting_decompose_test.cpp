// The intrinsic decomposition (decompose.h): Retinex on an image with a known reflectance, the
// primal-dual solver on known layers, and stiff input (black, clipped, Gamma ~ 0, constant,
// extreme weights, tiny and large photos): finite output, constraints held to 1e-6 and a clear
// report when the solver stops early.
#include "inlay/lighting/decompose.h"

#include "decompose_layers.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>
#include <utility>

namespace inlay {
namespace {

using test::Layers;
using test::makeLayers;

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

// Gaussian noise of standard deviation `sigma` added to B (deterministic).
void addNoise(Layers& l, double sigma, unsigned seed = 3) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> n(0.f, float(sigma));
  for (float& v : l.B.data) v += n(rng);
}

// Mean absolute difference between horizontal neighbours of the same checker cell: the noise
// left in an albedo that should be flat there.
double roughness(const ImageF& a, int cell) {
  double s = 0, n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x + 1 < a.width; ++x)
      if ((x + 1) % cell != 0)
        for (int c = 0; c < 3; ++c) s += std::abs(a.at(x + 1, y, c) - a.at(x, y, c)), n += 1;
  return s / n;
}

TEST(Decompose, PixelNoiseSigmaMeasuresTheNoiseNotTheEdges) {
  Layers l = makeLayers(96, 80, 8);
  // Noise-free: the checker's edges and the smooth shading are not noise.
  EXPECT_LT(pixelNoiseSigma(l.B, l.valid), 1e-3);
  addNoise(l, 0.02);
  EXPECT_NEAR(pixelNoiseSigma(l.B, l.valid), 0.02, 0.003);
  // Pixels outside `use` do not count; too few pixels give 0.
  std::vector<uint8_t> none(l.valid.size(), 0);
  EXPECT_EQ(pixelNoiseSigma(l.B, none), 0.0);
  EXPECT_EQ(pixelNoiseSigma(ImageF(2, 2, 3, 0.5f), std::vector<uint8_t>(4, 1)), 0.0);
}

// A grainy photo: counted in units of its own noise, the data terms no longer push the noise
// into rho (the smooth-D term wants rho Gamma to carry every gradient of B); in fixed 8-bit
// units they do, and more so the longer the solver runs.
TEST(Decompose, NoiseUnitsKeepAGrainyPhotosNoiseOutOfTheAlbedo) {
  Layers l = makeLayers(64, 48, 8);
  addNoise(l, 0.03);
  const ImageF rho0 = anchoredRetinex(l);
  DecomposeOptions fixed, noise;
  fixed.unitsFromNoise = false;
  fixed.maxIterations = noise.maxIterations = 200;
  auto a = decomposeIntrinsic(l.B, l.gamma, rho0, l.valid, l.clipped, fixed);
  auto b = decomposeIntrinsic(l.B, l.gamma, rho0, l.valid, l.clipped, noise);
  ASSERT_TRUE(a && b);
  expectFeasible(l, *a);
  expectFeasible(l, *b);
  EXPECT_LT(roughness(b->albedo, 8), 0.8 * roughness(a->albedo, 8));
  EXPECT_LT(mae(b->albedo, l.rhoTrue), mae(a->albedo, l.rhoTrue));
}

TEST(Decompose, ConvergesOnASmallProblemAndSaysSo) {
  const Layers l = makeLayers(24, 20, 6);
  DecomposeOptions o;
  o.maxIterations = 20000;
  o.tolerance = 1e-3;
  o.gapTolerance = 0;  // the residuals alone
  o.objectiveTolerance = 0;
  auto d = decomposeIntrinsic(l.B, l.gamma, anchoredRetinex(l), l.valid, l.clipped, o);
  ASSERT_TRUE(d);
  EXPECT_TRUE(d->converged) << d->report;
  EXPECT_EQ(d->report.rfind("converged (", 0), 0u) << d->report;
  EXPECT_LT(d->history.back().primalResidual, 1e-3);
  EXPECT_LT(d->history.back().dualResidual, 1e-3);
  expectFeasible(l, *d);
}

// The solver before issue #16 (the default until then): one scalar step, stopped at 30
// iterations unless its residuals or a flat objective stop it first, nothing held.
DecomposeOptions scalarSolver() {
  DecomposeOptions o;
  o.diagonalSteps = false;
  o.pyramidLevels = 0;
  o.holdInvalid = false;
  o.gapTolerance = 0;
  o.maxIterations = 30;
  return o;
}

// A photo the size of the bundled example's (512 x 384) with a band the data terms do not apply
// to (a lamp, an unexplained patch) and Gamma over a range of 16 across the photo.
Layers exampleSizedLayers() {
  Layers l = makeLayers(512, 384, 24);
  for (int y = 100; y < 160; ++y)
    for (int x = 200; x < 330; ++x) l.valid[size_t(y) * 512 + x] = 0;
  for (int y = 0; y < 384; ++y)
    for (int x = 0; x < 512; ++x) l.gamma.setRgb(x, y, l.gamma.rgb(x, y) * (0.2 + 3.0 * x / 512));
  return l;
}

// The diagonal steps with the coarse start (coarse levels converged) converge well within 200
// iterations without the held pixels; the scalar step, set by the brightest pixel, does not
// (docs/benchmarks.md, "The decomposition's steps and coarse-to-fine start").
TEST(Decompose, AnExampleSizedPhotoConvergesWithinTheCap) {
  const Layers l = exampleSizedLayers();
  DecomposeOptions o;
  o.maxIterations = 200;
  o.holdInvalid = false;
  o.gapTolerance = 0;
  o.coarseIterations = 200;  // coarse levels to convergence (30 leave it at 1e-3 here)
  auto d = decomposeIntrinsic(l.B, l.gamma, anchoredRetinex(l), l.valid, l.clipped, o);
  ASSERT_TRUE(d);
  EXPECT_TRUE(d->converged) << d->report;
  EXPECT_LT(d->iterations, 200) << d->report;
  expectFeasible(l, *d);
  DecomposeOptions scalar = scalarSolver();
  scalar.maxIterations = 200;
  auto s = decomposeIntrinsic(l.B, l.gamma, anchoredRetinex(l), l.valid, l.clipped, scalar);
  ASSERT_TRUE(s);
  EXPECT_FALSE(s->converged) << s->report;
}

// The product's solver (DecomposeOptions' defaults) on the example-sized photo: converged well
// within its cap, and its objective within gapTolerance per pixel and channel of the minimum (a
// run 10 times as long with only the residuals and a flat objective to stop it). The solver
// before issue #16 (scalarSolver, the default until then) stops at its cap 2 % above the minimum.
TEST(Decompose, TheDefaultSolverConvergesWithinItsGapOnAnExampleSizedPhoto) {
  const Layers l = exampleSizedLayers();
  const ImageF start = anchoredRetinex(l);
  const DecomposeOptions o;
  auto d = decomposeIntrinsic(l.B, l.gamma, start, l.valid, l.clipped, o);
  ASSERT_TRUE(d);
  EXPECT_TRUE(d->converged) << d->report;
  EXPECT_EQ(d->report.rfind("converged (", 0), 0u) << d->report;
  EXPECT_LE(d->iterations, o.maxIterations / 2) << d->report;
  expectFeasible(l, *d);
  DecomposeOptions longRun = o;
  longRun.gapTolerance = 0;
  longRun.objectiveTolerance = 1e-8;
  longRun.maxIterations = 10 * std::max(d->iterations, 30);
  auto ref = decomposeIntrinsic(l.B, l.gamma, start, l.valid, l.clipped, longRun);
  ASSERT_TRUE(ref);
  const double values = 3.0 * 512 * 384, fMin = ref->history.back().objective;
  EXPECT_LE((d->history.back().objective - fMin) / values, o.gapTolerance) << ref->report;
  auto old = decomposeIntrinsic(l.B, l.gamma, start, l.valid, l.clipped, scalarSolver());
  ASSERT_TRUE(old);
  EXPECT_FALSE(old->converged) << old->report;
}

// Finite, feasible, and a report that says "converged" or why not.
void checkExtreme(const Layers& l, const DecomposeOptions& o) {
  const ImageF start(l.B.width, l.B.height, 3, 0.5f);
  auto d = decomposeIntrinsic(l.B, l.gamma, start, l.valid, l.clipped, o);
  ASSERT_TRUE(d);
  expectFeasible(l, *d);
  for (const auto& h : d->history)
    ASSERT_TRUE(std::isfinite(h.objective) && std::isfinite(h.primalResidual) &&
                std::isfinite(h.dualResidual));
  EXPECT_TRUE(d->report.rfind("converged (", 0) == 0 ||
              d->report.rfind("not converged: stopped by ", 0) == 0)
      << d->report;
  EXPECT_EQ(d->converged, d->report.rfind("converged (", 0) == 0) << d->report;
}

// Stiff and extreme photos: all black, one flat colour, saturated, a huge dynamic range of B and
// Gamma, a tiny Gamma, a single pixel. Nothing non-finite escapes, and the report says
// "converged" or why not.
TEST(Decompose, ExtremePhotosStayFiniteAndSayWhetherTheyConverged) {
  auto check = [](const Layers& l, const char* what) {
    DecomposeOptions diagonal;  // without the held pixels and the gap test
    diagonal.holdInvalid = false;
    diagonal.gapTolerance = 0;
    const std::pair<const char*, DecomposeOptions> solvers[] = {
        {", the default solver", DecomposeOptions{}},
        {", scalar step", scalarSolver()},
        {", diagonal steps", diagonal}};
    for (const auto& [name, o] : solvers) {
      SCOPED_TRACE(::testing::Message() << what << name);
      checkExtreme(l, o);
    }
  };
  Layers black = makeLayers(64, 48);
  black.B = ImageF(64, 48, 3, 0.f);
  check(black, "black photo");
  Layers flat = makeLayers(64, 48);
  flat.B = ImageF(64, 48, 3, 0.37f);
  check(flat, "one flat colour");
  Layers saturated = makeLayers(64, 48);
  saturated.B = ImageF(64, 48, 3, 1.f);
  std::fill(saturated.clipped.begin(), saturated.clipped.end(), uint8_t(1));
  check(saturated, "saturated");
  Layers range = makeLayers(64, 48);
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) {
      const double s = std::pow(10.0, -6 + 12.0 * x / 63);  // 1e-6 .. 1e6 across the photo
      range.B.setRgb(x, y, range.B.rgb(x, y) * s);
      range.gamma.setRgb(x, y, range.gamma.rgb(x, y) * s);
    }
  check(range, "twelve decades of dynamic range");
  Layers tiny = makeLayers(64, 48);
  tiny.gamma = ImageF(64, 48, 3, 1e-30f);
  check(tiny, "tiny Gamma");
  check(makeLayers(1, 1, 1), "a single pixel");
}

// holdInvalid: a pixel outside the data terms keeps its start (to rounding); without it the solver
// moves it (the test could fail).
TEST(Decompose, HeldPixelsOutsideTheDataTermsKeepTheirStart) {
  Layers l = makeLayers(48, 40, 8);
  for (int y = 10; y < 30; ++y)
    for (int x = 12; x < 36; ++x) l.valid[size_t(y) * 48 + x] = 0;
  ImageF start = anchoredRetinex(l);
  for (int y = 10; y < 30; ++y)
    for (int x = 12; x < 36; ++x) start.setRgb(x, y, Vec3(0.9, 0.1, 0.5));  // far from the truth
  for (bool hold : {true, false}) {
    DecomposeOptions o;
    o.diagonalSteps = true;
    o.pyramidLevels = 1;
    o.holdInvalid = hold;
    o.maxIterations = 300;
    auto d = decomposeIntrinsic(l.B, l.gamma, start, l.valid, l.clipped, o);
    ASSERT_TRUE(d);
    expectFeasible(l, *d);
    double moved = 0;
    for (int y = 10; y < 30; ++y)
      for (int x = 12; x < 36; ++x)
        for (int c = 0; c < 3; ++c) {
          const float cap = std::min(1.f, l.B.at(x, y, c) / l.gamma.at(x, y, c));
          moved = std::max(
              moved, double(std::abs(d->albedo.at(x, y, c) - std::clamp(start.at(x, y, c), 0.f, cap))));
        }
    if (hold) EXPECT_LT(moved, 1e-6) << d->report;  // the cap B / Gamma: rounding
    else EXPECT_GT(moved, 0.05) << d->report;
  }
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
  EXPECT_NE(d->report.find("iteration cap"), std::string::npos) << d->report;
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

// The solver stops on convergence or its iteration cap, never on the clock: the same input gives
// the same albedo bit for bit, whatever the machine's load.
TEST(Decompose, RepeatRunsAreBitIdentical) {
  const Layers l = makeLayers(64, 48);
  const ImageF rho0 = anchoredRetinex(l);
  DecomposeOptions o;
  o.maxIterations = 60;
  o.tolerance = 0;
  o.objectiveTolerance = 0;
  o.gapTolerance = 0;
  auto a = decomposeIntrinsic(l.B, l.gamma, rho0, l.valid, l.clipped, o);
  auto b = decomposeIntrinsic(l.B, l.gamma, rho0, l.valid, l.clipped, o);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->iterations, 60);
  EXPECT_EQ(b->iterations, 60);
  EXPECT_EQ(a->albedo.data, b->albedo.data);
  EXPECT_EQ(a->direct.data, b->direct.data);
  ASSERT_EQ(a->history.size(), b->history.size());
  for (size_t i = 0; i < a->history.size(); ++i)
    EXPECT_EQ(a->history[i].objective, b->history[i].objective);
  // The solver did move (the test could fail): the albedo differs from its start.
  EXPECT_GT(mae(a->albedo, rho0), 1e-5);
}

TEST(Decompose, StopsWhenTheObjectiveIsFlat) {
  const Layers l = makeLayers(24, 20, 6);
  DecomposeOptions o;
  o.maxIterations = 20000;
  o.tolerance = 0;  // residuals alone never stop it
  o.gapTolerance = 0;
  o.objectiveTolerance = 1e-7;
  auto d = decomposeIntrinsic(l.B, l.gamma, anchoredRetinex(l), l.valid, l.clipped, o);
  ASSERT_TRUE(d);
  EXPECT_TRUE(d->converged) << d->report;
  EXPECT_NE(d->report.find("(objective)"), std::string::npos) << d->report;
  EXPECT_LT(d->iterations, 20000);
  const auto& h = d->history;
  ASSERT_GE(h.size(), 2u);
  EXPECT_LE(std::abs(h[h.size() - 2].objective - h.back().objective), 1e-7 * h.back().objective);
}

// 12 MP: solved on block means (maxSolvePixels), the change carried back; the constraints hold
// at full resolution and the albedo moves toward the truth from a start that is off.
TEST(Decompose, LargePhotoIsSolvedOnBlocksAndStaysFeasible) {
  const Layers l = makeLayers(4000, 3000, 40);
  ImageF start = l.rhoTrue;
  for (float& v : start.data) v = std::clamp(v * 1.3f, 0.f, 1.f);
  DecomposeOptions o;
  o.maxIterations = 40;
  auto d = decomposeIntrinsic(l.B, l.gamma, start, l.valid, l.clipped, o);
  ASSERT_TRUE(d);
  EXPECT_NE(d->report.find("blocks of the 4000x3000 photo"), std::string::npos) << d->report;
  EXPECT_EQ(d->converged, d->report.rfind("converged", 0) == 0);
  if (!d->converged) {
    EXPECT_NE(d->report.find("iteration cap"), std::string::npos) << d->report;
  }
  expectFeasible(l, *d);
  // The cap rho <= B / Gamma alone pulls the too-bright start toward the truth.
  EXPECT_LT(mae(d->albedo, l.rhoTrue), mae(start, l.rhoTrue));
}

// 50 MP with black, clipped and Gamma ~ 0 patches: finite, feasible, bounded work.
TEST(Decompose, FiftyMegapixelPhotoStaysFeasible) {
  const int W = 8660, H = 5780;  // 50.05 MP
  Layers l{ImageF(W, H, 3), ImageF(W, H, 3), ImageF(), std::vector<uint8_t>(size_t(W) * H, 1),
           std::vector<uint8_t>(size_t(W) * H, 0)};
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const float r = ((x / 200 + y / 200) & 1) ? 0.7f : 0.3f, g = 0.2f + 0.1f * x / W;
      for (int c = 0; c < 3; ++c) {
        l.gamma.at(x, y, c) = y < 100 ? 1e-12f : g;
        l.B.at(x, y, c) = x < 100 ? 0.f : r * (0.5f + g);
      }
      if (y > H - 100) {
        l.clipped[size_t(y) * W + x] = 1;
        l.B.setRgb(x, y, Vec3::Ones());
      }
    }
  DecomposeOptions o;
  o.maxIterations = 5;
  auto d = decomposeIntrinsic(l.B, l.gamma, ImageF(W, H, 3, 0.5f), l.valid, l.clipped, o);
  ASSERT_TRUE(d);
  EXPECT_FALSE(d->converged);
  EXPECT_NE(d->report.find("not converged"), std::string::npos) << d->report;
  EXPECT_EQ(d->iterations, 5);
  expectFeasible(l, *d);
}

}  // namespace
}  // namespace inlay
