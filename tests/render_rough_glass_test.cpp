// Next-event estimation at rough glass (render/src/bsdf.h roughGlassEval, combined with BSDF
// sampling by MIS): with NEE on and off the renders of a frosted ball under a small ceiling
// light agree within their noise (NEE adds no bias), and NEE's per-pixel variance is lower
// (the light's highlight and the light seen through the ball are reached directly). The light
// is large enough for BSDF sampling alone to find it in every run, so both variances are seen.
#include "render_test_scenes.h"
#include "test_support.h"

#include "inlay/render/path_tracer.h"

#include <cstdio>

namespace inlay {
namespace {

constexpr int kW = 32, kH = 24, kRuns = 16, kSpp = 16;

RenderScene frostedBallScene(double roughness) {
  RenderScene s = test::roomScene(test::testCamera(kW, kH, 30, 1.3, -15), RoomBox{}, 0.6);
  s.lights.push_back(
      test::rectLight(Vec3(0, 2.55, -2.3), Vec3(0.4, 0, 0), Vec3(0, 0, 0.4), Vec3::Constant(15)));
  InsertedObject ball;
  ball.meshObject = test::sphereMesh(0.3, 32, 64);
  ball.worldFromObject = test::translation(Vec3(0, 0.8, -2.0));
  ball.material.kind = Material::Kind::RoughGlass;
  ball.material.roughness = roughness;
  s.objects.push_back(ball);
  return s;
}

struct Estimate {
  double mean = 0;           // over runs of the ball region's mean radiance (red)
  double standardError = 0;  // of that mean, from the spread of the runs
  double pixelVariance = 0;  // per-pixel variance across runs, averaged over the region
};

Estimate renderRuns(const RenderScene& s, bool nee, const std::vector<size_t>& region) {
  TracerOptions opt;
  opt.roughGlassNee = nee;
  PathTracer tracer(s, opt);
  std::vector<std::vector<double>> px(region.size());
  std::vector<double> regionMeans;
  for (int run = 0; run < kRuns; ++run) {
    DifferentialBuffers b(kW, kH);
    EXPECT_TRUE(tracer.render(b, 0, kSpp, uint32_t(100 + run)));
    const ImageF with = b.meanWith();
    double m = 0;
    for (size_t k = 0; k < region.size(); ++k) {
      px[k].push_back(with.data[region[k] * 3]);
      m += px[k].back() / region.size();
    }
    regionMeans.push_back(m);
  }
  EXPECT_EQ(tracer.stats().nonFiniteSamples, 0u);
  auto meanVar = [](const std::vector<double>& v, double* var) {
    double m = 0, q = 0;
    for (double x : v) m += x / v.size();
    for (double x : v) q += (x - m) * (x - m) / (v.size() - 1);
    *var = q;
    return m;
  };
  Estimate e;
  double var = 0;
  e.mean = meanVar(regionMeans, &var);
  e.standardError = std::sqrt(var / kRuns);
  for (const auto& p : px) {
    meanVar(p, &var);
    e.pixelVariance += var / px.size();
  }
  return e;
}

TEST(RoughGlassNee, AgreesWithBsdfSamplingAndLowersVariance) {
  for (double roughness : {0.3, 0.6}) {
    const RenderScene s = frostedBallScene(roughness);
    std::vector<size_t> region;  // pixels whose camera ray meets the ball
    {
      PathTracer probe(s);
      DifferentialBuffers b(kW, kH);
      probe.render(b, 0, 4, 1);
      const ImageF mask = b.meanMask();
      for (size_t i = 0; i < mask.pixelCount(); ++i)
        if (mask.data[i] == 1.f) region.push_back(i);
    }
    ASSERT_GE(region.size(), 20u);
    const Estimate on = renderRuns(s, true, region), off = renderRuns(s, false, region);
    const double tolerance = 4.0 * std::hypot(on.standardError, off.standardError);
    std::printf(
        "[ rough glass nee ] r%.1f, %zu px: NEE on %.4f +- %.4f (pixel var %.4f), off %.4f +- %.4f "
        "(pixel var %.4f)\n",
        roughness, region.size(), on.mean, on.standardError, on.pixelVariance, off.mean,
        off.standardError, off.pixelVariance);
    EXPECT_NEAR(on.mean, off.mean, tolerance) << "roughness " << roughness;
    EXPECT_LT(on.pixelVariance, 0.8 * off.pixelVariance) << "roughness " << roughness;
  }
}

}  // namespace
}  // namespace inlay
