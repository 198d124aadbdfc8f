// Occluder cards in the path tracer: camera and shadow rays pass with probability 1 - alpha.
#include "render_test_scenes.h"

#include <gtest/gtest.h>

#include <optional>

namespace inlay {
namespace {

constexpr int kW = 40, kH = 30;

// A lit room, a sphere at (0, 0.4, -2.5) in the middle of the view and, when `alpha` is given,
// a card at z = -1.8 between it and the camera whose matte is `alpha` (photo pixels).
RenderScene sceneWithCard(const ImageF* alpha) {
  const Camera cam = test::testCamera(kW, kH, 70, 1.3, -10);
  RenderScene s = test::roomScene(cam, RoomBox{}, 0.6);
  s.lights.push_back(
      test::rectLight(Vec3(0, 2.6, -2), Vec3(0.4, 0, 0), Vec3(0, 0, 0.4), Vec3::Constant(5)));
  InsertedObject o;
  o.meshObject = test::sphereMesh(0.4);
  o.worldFromObject = test::translation(Vec3(0, 0.4, -2.5));
  Material m;
  m.kind = Material::Kind::Diffuse;
  m.albedo = Vec3::Constant(0.7);
  o.material = m;
  s.objects.push_back(o);
  if (alpha) {
    Surface card;
    card.kind = SurfaceKind::OccluderCard;
    card.name = "occluder_0_card";
    card.meshWorld =
        test::quadMesh(test::rectCorners(Vec3(0, 0.75, -1.8), Vec3(1.5, 0, 0), Vec3(0, 0.75, 0)));
    auto a = std::make_shared<CardAlpha>();
    a->camera = cam;
    a->alphaPx = *alpha;
    card.cardAlpha = a;
    s.room.surfaces.push_back(card);
    s.roomAlbedo.surfaceMean.push_back(Vec3::Constant(0.5));
  }
  return s;
}

// Object coverage of the left and right image halves (sum of the per-pixel mask).
std::pair<double, double> maskHalves(const RenderScene& scene, int spp) {
  PathTracer tracer(scene);
  DifferentialBuffers b(kW, kH);
  EXPECT_TRUE(tracer.render(b, 0, spp, 5));
  const ImageF m = b.meanMask();
  double left = 0, right = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) (x < kW / 2 ? left : right) += m.at(x, y);
  return {left, right};
}

TEST(OccluderCard, HidesTheObjectWhereTheMatteCoversIt) {
  const auto [left0, right0] = maskHalves(sceneWithCard(nullptr), 16);
  ASSERT_GT(left0, 5.0);  // the sphere shows in both halves without a card
  ASSERT_GT(right0, 5.0);
  ImageF half(kW, kH, 1, 0.f);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW / 2; ++x) half.at(x, y) = 1.f;
  const auto [left1, right1] = maskHalves(sceneWithCard(&half), 16);
  // Fully covered half: hidden (but for the pixel column whose footprint straddles the edge).
  EXPECT_LT(left1, 0.1 * left0);
  EXPECT_NEAR(right1, right0, 0.1 * right0);
  // A uniform 30% matte lets about 70% of the samples through.
  ImageF soft(kW, kH, 1, 0.3f);
  const auto [left2, right2] = maskHalves(sceneWithCard(&soft), 64);
  EXPECT_NEAR((left2 + right2) / (left0 + right0), 0.7, 0.05);
}

// A horizontal card between a small ceiling light and the floor, above the camera (out of its
// view); its matte is given in a second camera looking straight down, uniform `alpha` there.
// Returns the mean radiance of the floor the camera sees (all of it in the card's shadow).
double floorUnderCard(std::optional<float> alpha) {
  const Camera cam = test::testCamera(kW, kH, 40, 1.0, -70);
  RenderScene s = test::roomScene(cam, RoomBox{}, 0.3);
  s.lights.push_back(
      test::rectLight(Vec3(0, 2.5, -0.6), Vec3(0.05, 0, 0), Vec3(0, 0, 0.05), Vec3::Constant(200)));
  if (alpha) {
    Surface card;
    card.kind = SurfaceKind::OccluderCard;
    card.name = "occluder_0_card";
    card.meshWorld =
        test::quadMesh(test::rectCorners(Vec3(0, 1.6, -0.5), Vec3(0.4, 0, 0), Vec3(0, 0, 0.4)));
    auto a = std::make_shared<CardAlpha>();
    a->camera = test::testCamera(kW, kH, 120, 2.5, -90);
    a->alphaPx = ImageF(kW, kH, 1, *alpha);
    card.cardAlpha = a;
    s.room.surfaces.push_back(card);
    s.roomAlbedo.surfaceMean.push_back(Vec3::Constant(0.3));
  }
  PathTracer tracer(s);
  DifferentialBuffers b(kW, kH);
  EXPECT_TRUE(tracer.render(b, 0, 64, 3));
  const ImageF im = b.meanWithout();
  double sum = 0;
  for (float v : im.data) sum += v;
  return sum / double(im.data.size());
}

TEST(OccluderCard, SoftMatteCastsAShadowOfItsStrength) {
  const double open = floorUnderCard(std::nullopt), solid = floorUnderCard(1.f);
  ASSERT_GT(open, 2.0 * solid);  // the light reaches the floor only through the card
  // The shadow's strength (share of the direct light removed) follows the matte's alpha.
  for (float alpha : {0.25f, 0.5f, 0.75f}) {
    const double strength = (open - floorUnderCard(alpha)) / (open - solid);
    EXPECT_NEAR(strength, alpha, 0.06) << "alpha " << alpha;
  }
}

// The lighting stage's RoomTracer stops rays at a card only where its matte covers at least
// half, as SceneGeometry::intersect does (the floor seen between a table's legs is floor).
TEST(OccluderCard, RoomTracerFollowsTheMatte) {
  ImageF half(kW, kH, 1, 0.f);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW / 2; ++x) half.at(x, y) = 1.f;
  const RenderScene s = sceneWithCard(&half);
  const Camera& cam = s.camera;
  const int card = int(s.room.surfaces.size()) - 1;
  const RoomTracer tracer(s.room);
  const Ray left = cam.rayThroughPixel(Vec2(0.25 * kW, 0.5 * kH));
  const Ray right = cam.rayThroughPixel(Vec2(0.75 * kW, 0.5 * kH));
  const auto hitLeft = tracer.intersect(left), hitRight = tracer.intersect(right);
  ASSERT_TRUE(hitLeft && hitRight);
  EXPECT_EQ(hitLeft->surfaceId, card);
  EXPECT_NE(hitRight->surfaceId, card);
  // The same for the geometry's own intersect and for shadow (visibility) rays.
  EXPECT_EQ(s.room.intersect(right)->surfaceId, hitRight->surfaceId);
  EXPECT_FALSE(tracer.visible(left.origin, left.at(hitLeft->t + 0.5)));
  EXPECT_TRUE(tracer.visible(right.origin, right.at(hitLeft->t + 0.1)));
}

}  // namespace
}  // namespace inlay
