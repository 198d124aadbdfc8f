// Stiff geometry for the path tracer: a 10 km object (its corners' float coordinates are only
// good to ~5e-4 m, more than the usual ray offset) must be lit like a small one, without shadow
// acne. (Embree's intersection relative to the ray origin keeps this case clean even without
// the round-off bound on the offset; the bound is a guard for larger coordinates.)
#include "render_test_scenes.h"
#include "test_support.h"

#include "inlay/render/path_tracer.h"

namespace inlay {
namespace {

constexpr int kW = 40, kH = 30;

// A horizontal plate at 0.5 m under a ceiling light; `halfSizeM` its half width.
RenderScene plateScene(double halfSizeM) {
  RenderScene s = test::roomScene(test::testCamera(kW, kH, 50, 1.3, -30), RoomBox{}, 0.6);
  s.lights.push_back(
      test::rectLight(Vec3(0, 2.5, -2.0), Vec3(0.3, 0, 0), Vec3(0, 0, 0.3), Vec3::Constant(6)));
  InsertedObject plate;
  // Corners C-U-V .. C-U+V with U x V = +y: the plate faces up.
  // Tilted off the axes (an axis-aligned plane would be intersected exactly in float).
  plate.meshObject = std::make_shared<TriangleMesh>(
      test::quadMesh(test::rectCorners(Vec3::Zero(), Vec3(0, 0, halfSizeM), Vec3(halfSizeM, 0, 0))));
  plate.worldFromObject = test::translation(Vec3(0, 0.5, -2.0));
  plate.worldFromObject.topLeftCorner<3, 3>() =
      Eigen::AngleAxisd(0.15, Vec3(1, 0.3, 0.8).normalized()).toRotationMatrix();
  plate.material.kind = Material::Kind::Diffuse;
  plate.material.albedo = Vec3::Constant(0.7);
  s.objects.push_back(plate);
  return s;
}

TEST(Stiff, TenKilometreObjectIsLitLikeASmallOne) {
  TracerOptions opt;
  opt.maxDepth = 1;  // direct light: the two plates must agree where the camera sees both
  PathTracer huge(plateScene(5000.0), opt), small(plateScene(1.9), opt);
  DifferentialBuffers a(kW, kH), b(kW, kH);
  ASSERT_TRUE(huge.render(a, 0, 64, 3));
  ASSERT_TRUE(small.render(b, 0, 64, 3));
  EXPECT_EQ(huge.stats().nonFiniteSamples, 0u);
  EXPECT_TRUE(test::allFinite(a.sumWith));
  const ImageF wa = a.meanWith(), wb = b.meanWith(), ma = a.meanMask(), mb = b.meanMask();
  double sa = 0, sb = 0, worst = 0;
  int n = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      if (ma.at(x, y) != 1.f || mb.at(x, y) != 1.f) continue;
      sa += wa.at(x, y, 0), sb += wb.at(x, y, 0), ++n;
      worst = std::max(worst, std::abs(wa.at(x, y, 0) / wb.at(x, y, 0) - 1.0));
    }
  ASSERT_GT(n, 300);
  std::printf("[ stiff ] 10 km plate vs 3.8 m plate, %d px: mean ratio %.4f, worst pixel %.4f\n", n,
              sa / sb, worst);
  EXPECT_NEAR(sa / sb, 1.0, 0.01);
  EXPECT_LT(worst, 0.05);  // acne would blacken whole pixels
}

}  // namespace
}  // namespace inlay
