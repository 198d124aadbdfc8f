// The photo-lit shortcut and the object's own shadow: a diffuse sphere resting on the floor of
// a box room under a ceiling light. The "photo" is a path-traced render of the EMPTY room. A
// bounce from the sphere's lower half lands on floor the photo shows; its radiance there must be
// the floor's WITH the sphere (in the sphere's shadow), not the empty photo's. The sphere's lower
// half in the composite must match a full path-traced reference (no photo at all), while the
// photo's radiance alone would make it clearly too bright.
#include "render_test_scenes.h"

#include "inlay/render/path_tracer.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace inlay {
namespace {

constexpr int kW = 80, kH = 60;
constexpr double kRadius = 0.45;
const Vec3 kCentre(0.0, kRadius, -2.4);

RenderScene emptyRoom() {
  RenderScene s = test::roomScene(test::testCamera(kW, kH, 55, 1.0, -12), RoomBox{}, 0.6);
  s.roomAlbedo.albedo = ImageF(kW, kH, 3);
  std::fill(s.roomAlbedo.albedo.data.begin(), s.roomAlbedo.albedo.data.end(), 0.6f);
  s.roomAlbedo.computeFirstSurfaces(s.room);
  s.lights.push_back(test::rectLight(Vec3(0.3, RoomBox{}.ceilingM - 0.02, -2.2), Vec3(0.35, 0, 0),
                                     Vec3(0, 0, 0.35), Vec3::Constant(6.0)));
  return s;
}

RenderScene withSphere(RenderScene s) {
  InsertedObject o;
  o.meshObject = test::sphereMesh(kRadius, 32, 64);
  o.worldFromObject = test::translation(kCentre);
  o.material.kind = Material::Kind::Diffuse;
  o.material.albedo = Vec3::Constant(0.8);
  s.objects.push_back(o);
  return s;
}

// The pixels below the projection of the sphere's centre, around the sphere.
struct Rect {
  int x0, y0, x1, y1;
};
Rect lowerHalf(const Camera& cam) {
  const Vec2 c = *cam.project(kCentre), top = *cam.project(kCentre + Vec3(0, kRadius, 0));
  const double r = 1.2 * (c.y() - top.y());
  return {int(c.x() - r), int(c.y()) + 1, int(c.x() + r) + 1, int(c.y() + r) + 1};
}

DifferentialBuffers render(const RenderScene& s, int spp, const Rect& r = {0, 0, kW, kH}) {
  DifferentialBuffers b(kW, kH);
  EXPECT_TRUE(PathTracer(s).renderRect(b, r.x0, r.y0, r.x1, r.y1, 0, spp, 7));
  return b;
}

// Mean radiance (channel 0) over the pixels of `r` whose every camera sample hits the sphere.
double sphereMean(const DifferentialBuffers& b, const Rect& r) {
  const ImageF with = b.meanWith(), mask = b.meanMask();
  double sum = 0;
  int n = 0;
  for (int y = std::max(0, r.y0); y < std::min(kH, r.y1); ++y)
    for (int x = std::max(0, r.x0); x < std::min(kW, r.x1); ++x)
      if (mask.at(x, y) > 0.999f) sum += with.at(x, y, 0), ++n;
  EXPECT_GT(n, 50);
  return n > 0 ? sum / n : 0.0;
}

TEST(PhotoShadow, SphereLowerHalfMatchesFullPathTracing) {
  const RenderScene empty = emptyRoom();
  const Rect lower = lowerHalf(empty.camera);
  // Reference: no photo, every bounce path traced in the scene with the sphere.
  const double truth = sphereMean(render(withSphere(empty), 256, lower), lower);

  // The photo: the empty room, path traced (it holds the floor's light without the sphere;
  // its noise averages out over the bounces that read it).
  RenderScene photoScene = withSphere(empty);
  photoScene.roomAlbedo.photoRadiance = render(empty, 32).meanWithout();
  photoScene.roomAlbedo.photoRadianceUsable.assign(size_t(kW) * kH, 1);
  const double shortcut = sphereMean(render(photoScene, 256, lower), lower);

  ASSERT_GT(truth, 0.02);
  EXPECT_NEAR(shortcut / truth, 1.0, 0.04) << "reference " << truth << ", with the photo " << shortcut;
}

}  // namespace
}  // namespace inlay
