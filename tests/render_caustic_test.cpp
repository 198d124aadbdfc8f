// Caustics through glass from an area light must converge, not vanish: a glass ball over a
// diffuse floor focuses the ceiling light into a bright spot, which path tracing reaches by
// BSDF-sampled paths (floor -> glass -> glass -> light). Low-sample renders agree with a
// high-sample reference of other samples in the spot, and the error falls with samples.
#include "render_test_scenes.h"
#include "test_support.h"

#include "inlay/render/path_tracer.h"

namespace inlay {
namespace {

constexpr int kW = 32, kH = 24;  // a narrow view of the floor around the spot

RenderScene ballScene(Material::Kind kind, double roughness) {
  RenderScene s = test::roomScene(test::testCamera(kW, kH, 14, 1.3, -33), RoomBox{}, 0.7);
  s.lights.push_back(
      test::rectLight(Vec3(0, 2.55, -2.0), Vec3(0.15, 0, 0), Vec3(0, 0, 0.15), Vec3::Constant(40)));
  InsertedObject ball;
  ball.meshObject = test::sphereMesh(0.3, 48, 96);
  // A ball lens focuses at n R / (2 (n - 1)) = 0.45 m from its centre for n = 1.5.
  ball.worldFromObject = test::translation(Vec3(0, 0.45, -2.0));
  ball.material.kind = kind;
  ball.material.roughness = roughness;
  ball.material.albedo = Vec3::Constant(0.8);
  s.objects.push_back(ball);
  return s;
}

struct Rendered {
  ImageF with, without, mask;
};
Rendered render(const RenderScene& s, int firstSample, int spp) {
  TracerOptions opt;
  opt.maxDepth = 12;
  PathTracer tracer(s, opt);
  DifferentialBuffers b(kW, kH);
  EXPECT_TRUE(tracer.render(b, firstSample, spp, 17));
  EXPECT_EQ(tracer.stats().nonFiniteSamples, 0u);
  return {b.meanWith(), b.meanWithout(), b.meanMask()};
}

void expectCausticConverges(Material::Kind kind, double roughness, const char* name) {
  const RenderScene s = ballScene(kind, roughness);
  const Rendered ref = render(s, 100000, 512);
  // The spot: floor pixels (never the ball) at least twice as bright with the ball as without.
  std::vector<size_t> spot;
  for (size_t i = 0; i < ref.with.pixelCount(); ++i)
    if (ref.mask.data[i] == 0.f && ref.with.data[i * 3] > 2.0 * ref.without.data[i * 3])
      spot.push_back(i);
  ASSERT_GE(spot.size(), 20u) << name << ": no caustic";
  double refMean = 0;
  for (size_t i : spot) refMean += ref.with.data[i * 3];
  refMean /= spot.size();
  double previous = 1e300;
  for (int spp : {16, 64, 256}) {
    const Rendered r = render(s, 0, spp);
    double mean = 0, sq = 0;
    for (size_t i : spot) {
      mean += r.with.data[i * 3];
      const double e = r.with.data[i * 3] / ref.with.data[i * 3] - 1.0;
      sq += e * e;
    }
    mean /= spot.size();
    const double rms = std::sqrt(sq / spot.size());
    std::printf(
        "[ caustic ] %s: %zu spot px, %4d spp: mean %.3f (reference %.3f, rel %+.3f), rms rel %.3f\n",
        name, spot.size(), spp, mean, refMean, mean / refMean - 1, rms);
    // At 64 spp a few long caustic paths still weigh on the mean: rough glass gave +0.129 by
    // BSDF sampling alone and +0.157 with NEE through the glass (the same sample sequence; both
    // +0.03 at 256 spp), so 64 spp is held to 0.2 and 256 spp to 0.05.
    if (spp >= 64) {
      EXPECT_NEAR(mean / refMean, 1.0, spp >= 256 ? 0.05 : 0.2) << name << " at " << spp;
    }
    EXPECT_LT(rms, previous) << name << " at " << spp;
    previous = rms;
  }
}

TEST(Caustic, SmoothGlassBallFocusesTheLightAndConverges) {
  expectCausticConverges(Material::Kind::Glass, 0.0, "smooth glass");
}

TEST(Caustic, RoughGlassBallConverges) {
  expectCausticConverges(Material::Kind::RoughGlass, 0.15, "rough glass");
}

}  // namespace
}  // namespace inlay
