// Next-event estimation's choice of a light (TracerOptions::lightSelection): the spatial rule
// (power over squared distance at every vertex) and the power table built once per scene
// against the analytic direct light of a room with one bright and many dim lights, their means
// against each other, the Auto switch, and the table kept current when an emissive object moves.
#include "render_test_scenes.h"
#include "test_support.h"

#include "inlay/render/path_tracer.h"

#include <cstdio>

namespace inlay {
namespace {

using test::kPi;
using Sel = TracerOptions::LightSelection;

// Form factor from a floor point (normal +y) to an unoccluded polygon above it (Lambert's
// contour integral).
double formFactorUp(const Vec3& p, const std::array<Vec3, 4>& c) {
  double sum = 0;
  for (int i = 0; i < 4; ++i) {
    const Vec3 a = (c[size_t(i)] - p).normalized(), b = (c[size_t(i + 1) % 4] - p).normalized();
    const Vec3 x = a.cross(b);
    sum += std::acos(std::clamp(a.dot(b), -1.0, 1.0)) * Vec3::UnitY().dot(x.normalized());
  }
  return std::abs(sum) / (2 * kPi);
}

struct FloorComparison {
  test::RelativeError err;       // against the form-factor sum
  std::vector<double> rendered;  // per compared pixel (channel 0)
};

// Direct light only (maxDepth 1) on the floor pixels of manyLightsScene, against
// albedo x sum_j le_j F_j at the pixel centre.
FloorComparison renderFloor(const RenderScene& s, Sel mode, int spp, uint32_t seed) {
  TracerOptions opt;
  opt.maxDepth = 1;
  opt.lightSelection = mode;
  PathTracer tracer(s, opt);
  DifferentialBuffers b(s.camera.widthPx, s.camera.heightPx);
  EXPECT_TRUE(tracer.render(b, 0, spp, seed));
  const ImageF with = b.meanWith();
  FloorComparison out;
  const RoomBox box;
  for (int y = 0; y < with.height; ++y)
    for (int x = 0; x < with.width; ++x) {
      const Vec3 d = s.camera.directionThroughPixel(Vec2(x + 0.5, y + 0.5));
      if (!(d.y() < 0)) continue;
      const Vec3 q = s.camera.centreWorld() - s.camera.heightM / d.y() * d;
      if (q.x() < box.xLeftM + 0.1 || q.x() > box.xRightM - 0.1 || q.z() < box.zBackM + 0.1 ||
          q.z() > box.zRearM - 0.1)
        continue;
      double expected = 0;
      for (const AreaLight& l : s.lights) expected += l.radiance.x() * formFactorUp(q, l.cornersWorld);
      expected *= 0.5;  // the room's albedo
      out.err.add(with.at(x, y, 0), expected);
      out.rendered.push_back(with.at(x, y, 0));
    }
  return out;
}

// One bright light among 23 dim ones: both rules converge to the form-factor sum (the table's
// pdf is the one MIS sees, so nothing is counted twice or lost).
TEST(LightSelection, BothRulesMatchTheFormFactorSum) {
  const RenderScene s = test::manyLightsScene(48, 36, 24, 40.0, 2.0);
  for (Sel mode : {Sel::Spatial, Sel::Power}) {
    const FloorComparison c = renderFloor(s, mode, 128, 3);
    ASSERT_GT(c.err.n, 300);
    std::printf("[ lights ] %s: %d floor px, mean rel err %+.4f, rms %.4f\n",
                mode == Sel::Spatial ? "spatial" : "power", c.err.n, c.err.mean(), c.err.rms());
    EXPECT_LT(std::abs(c.err.mean()), 0.01);
    EXPECT_LT(c.err.rms(), 0.08);
  }
}

// The RMS difference between two seeds' renders over sqrt 2: the noise of one render.
double noiseBetweenSeeds(const RenderScene& s, Sel mode, int spp) {
  const FloorComparison a = renderFloor(s, mode, spp, 1), b = renderFloor(s, mode, spp, 2);
  double d2 = 0, sum = 0;
  for (size_t i = 0; i < a.rendered.size(); ++i) {
    const double d = a.rendered[i] - b.rendered[i];
    d2 += d * d, sum += a.rendered[i];
  }
  return std::sqrt(d2 / double(a.rendered.size()) / 2) / (sum / double(a.rendered.size()));
}

// One light carrying most of the power among 47 dim ones: the two rules agree on the image's
// mean within their noise (measured between seeds). The table's noise at equal samples is
// printed, not bounded: the spatial rule weighs distance too and is the quieter per sample
// (0.035 against 0.059 here); the table is the cheaper per vertex (bench_light_selection).
TEST(LightSelection, OneBrightManyDimRulesAgreeOnTheMean) {
  const RenderScene s = test::manyLightsScene(48, 36, 48, 400.0, 1.0);
  const double spatialNoise = noiseBetweenSeeds(s, Sel::Spatial, 16),
               powerNoise = noiseBetweenSeeds(s, Sel::Power, 16);
  const FloorComparison a = renderFloor(s, Sel::Spatial, 64, 5), b = renderFloor(s, Sel::Power, 64, 6);
  double meanA = 0, meanB = 0;
  for (size_t i = 0; i < a.rendered.size(); ++i) meanA += a.rendered[i], meanB += b.rendered[i];
  meanA /= double(a.rendered.size()), meanB /= double(b.rendered.size());
  // The per-pixel noise at 64 spp is half that at 16; the mean over n pixels has 1/sqrt(n) of it.
  const double sigma = 0.5 * std::hypot(spatialNoise, powerNoise) / std::sqrt(double(a.rendered.size()));
  std::printf(
      "[ lights ] 1 bright + 47 dim, 16 spp: relative noise spatial %.4f, power %.4f; "
      "64 spp means %.5f / %.5f (rel diff %+.5f, sigma %.5f)\n",
      spatialNoise, powerNoise, meanA, meanB, meanB / meanA - 1, sigma);
  EXPECT_LT(std::abs(meanB / meanA - 1), 4 * sigma + 1e-3);
  EXPECT_LT(std::abs(a.err.mean()), 0.01);
  EXPECT_LT(std::abs(b.err.mean()), 0.01);
}

// Auto is the spatial rule up to spatialSelectionMax sources and the table above (bit for bit).
TEST(LightSelection, AutoSwitchesAtTheThreshold) {
  auto render = [](const RenderScene& s, Sel mode) {
    TracerOptions opt;
    opt.lightSelection = mode;
    opt.spatialSelectionMax = 8;
    PathTracer tracer(s, opt);
    DifferentialBuffers b(s.camera.widthPx, s.camera.heightPx);
    EXPECT_TRUE(tracer.render(b, 0, 4, 7));
    return b.sumWith;
  };
  const RenderScene few = test::manyLightsScene(24, 18, 8, 40.0, 2.0);
  const RenderScene many = test::manyLightsScene(24, 18, 9, 40.0, 2.0);
  EXPECT_TRUE(test::sameBits(render(few, Sel::Auto), render(few, Sel::Spatial)));
  EXPECT_FALSE(test::sameBits(render(few, Sel::Auto), render(few, Sel::Power)));
  EXPECT_TRUE(test::sameBits(render(many, Sel::Auto), render(many, Sel::Power)));
  EXPECT_FALSE(test::sameBits(render(many, Sel::Auto), render(many, Sel::Spatial)));
}

// An emissive object scaled by a move changes its power: the table follows, so moving it
// renders what building the tracer there renders.
TEST(LightSelection, TableFollowsAMovedEmissiveObject) {
  RenderScene s = test::manyLightsScene(32, 24, 4, 40.0, 2.0);
  InsertedObject o;
  o.meshObject = test::sphereMesh(0.2, 8, 16);
  o.worldFromObject = test::translation(Vec3(0.3, 0.4, -2.5));
  o.material.kind = Material::Kind::Emissive;
  o.material.emission = Vec3(20, 20, 20);
  s.objects.push_back(o);
  Mat4 there = test::translation(Vec3(-0.4, 0.6, -2.0));
  there.topLeftCorner<3, 3>() *= 3.0;  // nine times the area, so the power
  TracerOptions opt;
  opt.lightSelection = Sel::Power;
  PathTracer moved(s, opt);
  moved.setObjectTransform(0, there);
  s.objects[0].worldFromObject = there;
  PathTracer built(s, opt);
  DifferentialBuffers a(32, 24), b(32, 24);
  ASSERT_TRUE(moved.render(a, 0, 4, 5));
  ASSERT_TRUE(built.render(b, 0, 4, 5));
  EXPECT_TRUE(test::sameBits(a.sumWith, b.sumWith));
  EXPECT_TRUE(test::sameBits(a.sumWithout, b.sumWithout));
}

}  // namespace
}  // namespace inlay
