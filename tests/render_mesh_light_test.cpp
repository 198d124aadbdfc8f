// Emissive objects as lights: next-event estimation on their triangles (with MIS against BSDF
// hits) must give the same light as the equivalent area light, converge as fast, follow the
// object when it moves, and stay finite when extreme.
#include "render_test_scenes.h"
#include "test_support.h"

#include "inlay/render/path_tracer.h"

namespace inlay {
namespace {

// The floor under a 0.6 x 0.6 m ceiling lamp, seen from above; direct light only (maxDepth 1),
// so the lamp's back side (emissive objects glow on both sides) lights nothing the camera sees.
constexpr int kW = 40, kH = 30;
const Vec3 kLampCentre(0, 2.2, -2.0), kLampU(0.3, 0, 0), kLampV(0, 0, 0.3);

RenderScene floorScene() {
  return test::roomScene(test::testCamera(kW, kH, 60, 1.3, -40), RoomBox{}, 0.6);
}

RenderScene areaLightScene(double radiance) {
  RenderScene s = floorScene();
  s.lights.push_back(test::rectLight(kLampCentre, kLampU, kLampV, Vec3::Constant(radiance)));
  return s;
}

// The same emitter as an emissive quad object, 1 mm below (where the area light's emitter sits).
RenderScene lampObjectScene(double radiance, const Mat4& worldFromObject = Mat4::Identity()) {
  RenderScene s = floorScene();
  InsertedObject lamp;
  const Vec3 c = kLampCentre - Vec3(0, 1e-3, 0);
  lamp.meshObject = std::make_shared<TriangleMesh>(test::quadMesh(test::rectCorners(c, kLampU, kLampV)));
  lamp.worldFromObject = worldFromObject;
  lamp.material.kind = Material::Kind::Emissive;
  lamp.material.emission = Vec3::Constant(radiance);
  s.objects.push_back(lamp);
  return s;
}

ImageF render(const RenderScene& s, int firstSample, int spp, int maxDepth = 1) {
  TracerOptions opt;
  opt.maxDepth = maxDepth;
  PathTracer tracer(s, opt);
  DifferentialBuffers b(kW, kH);
  EXPECT_TRUE(tracer.render(b, firstSample, spp, 11));
  EXPECT_EQ(tracer.stats().nonFiniteSamples, 0u);
  return b.meanWith();
}

// Pixels that see lit room (not the lamp itself) in a reference image.
std::vector<size_t> litRoomPixels(const ImageF& reference) {
  std::vector<size_t> px;
  for (size_t i = 0; i < reference.pixelCount(); ++i)
    if (reference.data[i * 3] > 0.05 && reference.data[i * 3] < 2.0) px.push_back(i);
  return px;
}

double rmsRelative(const ImageF& a, const ImageF& ref, const std::vector<size_t>& px) {
  double s = 0;
  for (size_t i : px) {
    const double r = a.data[i * 3] / ref.data[i * 3] - 1.0;
    s += r * r;
  }
  return std::sqrt(s / px.size());
}

TEST(MeshLight, QuadGivesTheAreaLightsIrradiance) {
  const double le = 5.0;
  const ImageF area = render(areaLightScene(le), 0, 256);
  const ImageF mesh = render(lampObjectScene(le), 0, 256);
  const std::vector<size_t> px = litRoomPixels(area);
  ASSERT_GT(px.size(), 300u);
  double sumArea = 0, sumMesh = 0;
  for (size_t i : px) sumArea += area.data[i * 3], sumMesh += mesh.data[i * 3];
  const double rel = sumMesh / sumArea - 1.0;
  const double rms = rmsRelative(mesh, area, px);
  std::printf(
      "[ mesh light ] emissive quad vs area light, 256 spp, %zu px: mean rel %+.4f, rms rel %.4f\n",
      px.size(), rel, rms);
  EXPECT_LT(std::abs(rel), 0.01);
  EXPECT_LT(rms, 0.05);
}

// NEE makes it converge: at 16 spp the lamp's floor is within a few percent of a 512-spp
// reference (BSDF hits alone would leave most pixels black or spiking: the lamp subtends
// about 1% of the hemisphere).
TEST(MeshLight, ConvergesLikeAnAreaLight) {
  const RenderScene s = lampObjectScene(5.0);
  const ImageF ref = render(s, 1000, 512);
  const std::vector<size_t> px = litRoomPixels(ref);
  const double meshErr = rmsRelative(render(s, 0, 16), ref, px);
  const ImageF areaRef = render(areaLightScene(5.0), 1000, 512);
  const double areaErr = rmsRelative(render(areaLightScene(5.0), 0, 16), areaRef, px);
  std::printf("[ mesh light ] 16 spp rms rel error: emissive quad %.4f, area light (solid angle) %.4f\n",
              meshErr, areaErr);
  EXPECT_LT(meshErr, 0.05);
  EXPECT_LT(meshErr, 3.0 * areaErr + 0.01);
}

// Full transport with a closed lamp (a glowing sphere) in the room: the room gets brighter,
// with- and without-sums differ only by the lamp's light, and moving the lamp moves its light
// (the same buffers as building it there).
TEST(MeshLight, GlowingSphereLightsTheRoomAndFollowsItsMoves) {
  RenderScene s = floorScene();
  InsertedObject ball;
  ball.meshObject = test::sphereMesh(0.15, 12, 24);
  ball.worldFromObject = test::translation(Vec3(0.5, 0.3, -2.2));
  ball.material.kind = Material::Kind::Emissive;
  ball.material.emission = Vec3(8, 6, 4);
  s.objects.push_back(ball);
  PathTracer moved(s);
  const Mat4 there = test::translation(Vec3(-0.5, 0.3, -2.0));
  moved.setObjectTransform(0, there);
  s.objects[0].worldFromObject = there;
  PathTracer built(s);
  DifferentialBuffers a(kW, kH), b(kW, kH);
  ASSERT_TRUE(moved.render(a, 0, 8, 3));
  ASSERT_TRUE(built.render(b, 0, 8, 3));
  EXPECT_EQ(a.sumWith.data, b.sumWith.data);
  const ImageF with = a.meanWith(), without = a.meanWithout(), mask = a.meanMask();
  double left = 0, right = 0, withoutTotal = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      if (mask.at(x, y) != 0.f) continue;
      (x < kW / 2 ? left : right) += with.at(x, y, 0) - without.at(x, y, 0);
      withoutTotal += without.at(x, y, 0);
    }
  std::printf("[ mesh light ] glowing sphere on the left: added light left %.2f, right %.2f\n", left,
              right);
  EXPECT_EQ(withoutTotal, 0.0);  // no other light: the room without the lamp is black
  EXPECT_GT(left, 2.0 * right);
  EXPECT_GT(right, 0.0);
}

// A 1e6-radiance emissive mesh touching the floor: finite everywhere, no samples dropped, and
// the floor next to it is bright (no clamping by default).
TEST(MeshLight, ExtremeEmitterTouchingTheFloorStaysFinite) {
  RenderScene s = floorScene();
  InsertedObject lamp;
  lamp.meshObject = test::sphereMesh(0.05, 8, 16);
  lamp.worldFromObject = test::translation(Vec3(0, 0.05, -2.2));
  lamp.material.kind = Material::Kind::Emissive;
  lamp.material.emission = Vec3::Constant(1e6);
  s.objects.push_back(lamp);
  PathTracer tracer(s);
  DifferentialBuffers b(kW, kH);
  ASSERT_TRUE(tracer.render(b, 0, 8, 5));
  EXPECT_EQ(tracer.stats().nonFiniteSamples, 0u);
  EXPECT_TRUE(test::allFinite(b.sumWith));
  EXPECT_TRUE(test::allFinite(b.sumDiffSq));
  const ImageF with = b.meanWith(), mask = b.meanMask();
  double brightest = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      if (mask.at(x, y) == 0.f) brightest = std::max(brightest, double(with.at(x, y, 0)));
  EXPECT_GT(brightest, 100.0);
}

}  // namespace
}  // namespace inlay
