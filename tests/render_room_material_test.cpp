// Room surfaces the user marks as a real mirror or a glossy floor (RenderScene::roomMaterials):
// an emissive sphere above a mirror floor shows in the composite's difference at its mirror
// image and nowhere the sphere cannot reach; a glossy floor blurs that reflection; with a marked
// surface and an object no path reaches, the with- and without-object sums stay bit-identical.
#include "render_test_scenes.h"

#include "inlay/render/composite.h"
#include "inlay/render/path_tracer.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

namespace inlay {
namespace {

constexpr int kW = 96, kH = 72;
const Vec3 kSphereCentre(1.0, 0.6, -2.5);
constexpr double kSphereRadius = 0.3;

Material marked(Material::Kind kind, double roughness = 0.2) {
  Material m;
  m.kind = kind;
  m.albedo = Vec3::Constant(0.9);
  m.roughness = roughness;
  return m;
}

// A box room without lights, seen by the photo (uniform radiance 0.5, usable everywhere), with
// a floor-to-ceiling partition at x = -0.2 over the back of the room (z in [-4, -1]) and an
// emissive sphere right of it. The floor (surface 0) gets `floor`.
RenderScene mirrorRoom(const std::optional<Material>& floor) {
  const RoomBox box;
  RenderScene s = test::roomScene(test::testCamera(kW, kH, 80, 1.3, -15), box, 0.5);
  Surface partition;
  partition.kind = SurfaceKind::ExtrusionSide;
  partition.name = "surface_0_side";
  partition.meshWorld =
      test::quadMesh(test::rectCorners(Vec3(-0.2, 1.3, -2.5), Vec3(0, 1.3, 0), Vec3(0, 0, 1.5)));
  s.room.surfaces.push_back(partition);
  s.roomAlbedo.surfaceMean.push_back(Vec3::Constant(0.5));
  s.roomAlbedo.photoRadiance = ImageF(kW, kH, 3);
  std::fill(s.roomAlbedo.photoRadiance.data.begin(), s.roomAlbedo.photoRadiance.data.end(), 0.5f);
  s.roomAlbedo.photoRadianceUsable.assign(size_t(kW) * kH, 1);
  s.roomAlbedo.computeFirstSurfaces(s.room);
  s.roomMaterials.assign(s.room.surfaces.size(), std::nullopt);
  s.roomMaterials[0] = floor;
  InsertedObject o;
  o.meshObject = test::sphereMesh(kSphereRadius);
  o.worldFromObject = test::translation(kSphereCentre);
  o.material.kind = Material::Kind::Emissive;
  o.material.emission = Vec3::Constant(3.0);
  s.objects.push_back(o);
  return s;
}

struct Difference {
  ImageF diff;  // mean with - mean without, channel 0
  ImageF mask;
};

// maxDepth 1: camera vertex plus one bounce, so a path from the left wall reaches the sphere
// only along a straight or floor-mirrored line (the partition blocks both); the photo closes
// every bounce on Lambertian room the camera sees.
Difference render(const RenderScene& s, int spp) {
  TracerOptions options;
  options.maxDepth = 1;
  PathTracer tracer(s, options);
  DifferentialBuffers b(kW, kH);
  EXPECT_TRUE(tracer.render(b, 0, spp, 7));
  const ImageF with = b.meanWith(), without = b.meanWithout();
  Difference d{ImageF(kW, kH, 1), b.meanMask()};
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) d.diff.at(x, y) = with.at(x, y, 0) - without.at(x, y, 0);
  return d;
}

// The pixel showing the reflection of the sphere's centre in the floor.
Vec2 mirrorImagePixel(const Camera& cam) {
  const auto px = cam.project(Vec3(kSphereCentre.x(), -kSphereCentre.y(), kSphereCentre.z()));
  EXPECT_TRUE(px.has_value());
  return px.value_or(Vec2(-1, -1));
}

// Pixels whose whole footprint (corners) sees the left wall at z in (-3.95, -2.6), y in
// (0.05, 2.55): from there every straight or floor-mirrored line to the sphere crosses the
// partition, so the object can change nothing.
std::vector<std::pair<int, int>> farPixels(const Camera& cam) {
  std::vector<std::pair<int, int>> out;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      bool inside = true;
      for (int c = 0; c < 4 && inside; ++c) {
        const Vec3 d = cam.directionThroughPixel(Vec2(x + (c & 1), y + (c >> 1)));
        if (!(d.x() < 0)) {
          inside = false;
          break;
        }
        const Vec3 p = cam.centreWorld() + (-2.0 - cam.centreWorld().x()) / d.x() * d;
        inside = p.z() > -3.95 && p.z() < -2.6 && p.y() > 0.05 && p.y() < 2.55;
      }
      if (inside) out.emplace_back(x, y);
    }
  return out;
}

TEST(RoomMaterial, MirrorFloorReflectsTheObjectAndNothingElseChanges) {
  const RenderScene s = mirrorRoom(marked(Material::Kind::Mirror));
  const Difference d = render(s, 8);
  // The sphere's mirror image: the reflection of its centre in the floor.
  const Vec2 image = mirrorImagePixel(s.camera);
  const int ix = int(image.x()), iy = int(image.y());
  ASSERT_TRUE(ix >= 0 && ix < kW && iy >= 0 && iy < kH);
  EXPECT_EQ(d.mask.at(ix, iy), 0.f);  // the camera sees floor there, not the sphere
  // Emission 3 x reflectance 0.9 against what the floor mirrors without the sphere: the
  // photo's 0.5 (a wall the camera sees) or nothing (a point it does not see, maxDepth 1).
  std::printf("[ mirror ] difference at the sphere's image (%d, %d): %.4f\n", ix, iy, d.diff.at(ix, iy));
  EXPECT_GE(d.diff.at(ix, iy), 0.9 * (3.0 - 0.5) - 1e-4);
  EXPECT_LE(d.diff.at(ix, iy), 0.9 * 3.0 + 1e-4);
  const auto far = farPixels(s.camera);
  ASSERT_GT(far.size(), 200u);
  for (const auto& [x, y] : far) ASSERT_EQ(d.diff.at(x, y), 0.f) << x << ", " << y;

  // The control: unmarked, the floor shows no reflection at that pixel (only the sphere's
  // light on a Lambertian floor, far weaker).
  const Difference plain = render(mirrorRoom(std::nullopt), 64);
  EXPECT_LT(std::abs(plain.diff.at(ix, iy)), 0.5);
}

TEST(RoomMaterial, GlossyFloorBlursTheReflection) {
  const RenderScene mirror = mirrorRoom(marked(Material::Kind::Mirror));
  const Difference sharp = render(mirror, 4);
  // A black base: the floor's only response to the sphere is its coat's (blurred) reflection.
  RenderScene coated = mirrorRoom(marked(Material::Kind::Glossy, 0.4));
  coated.roomAlbedo.surfaceMean[0] = Vec3::Zero();
  const Difference glossy = render(coated, 256);
  const Vec2 image = mirrorImagePixel(mirror.camera);
  const int ix = int(image.x()), iy = int(image.y());
  // Below the sharp reflection's footprint on the floor: the mirror shows nothing of the sphere
  // there, the glossy floor its blurred reflection.
  int below = iy;
  while (below < kH - 1 && sharp.diff.at(ix, below) != 0.f) ++below;
  below = std::min(kH - 1, below + 3);
  ASSERT_EQ(sharp.diff.at(ix, below), 0.f);
  std::printf("[ glossy ] at the image %.3f (mirror %.3f), %d px below it %.3f\n",
              glossy.diff.at(ix, iy), sharp.diff.at(ix, iy), below - iy, glossy.diff.at(ix, below));
  EXPECT_GT(glossy.diff.at(ix, below), 0.01);
  EXPECT_GT(glossy.diff.at(ix, iy), glossy.diff.at(ix, below));
  EXPECT_LT(glossy.diff.at(ix, iy), 0.8 * sharp.diff.at(ix, iy));
  for (const auto& [x, y] : farPixels(mirror.camera))
    ASSERT_EQ(glossy.diff.at(x, y), 0.f) << x << ", " << y;
}

using test::sameBits;

// A lit room with a mirror floor and a glossy back wall, and an object outside it: every sum
// with the object equals the one without it, bit for bit, and the composite is the photo.
TEST(RoomMaterial, UnreachableObjectLeavesMarkedRoomBitIdentical) {
  const int w = 40, h = 30;
  RenderScene s = test::roomScene(test::testCamera(w, h, 70, 1.3, -10), RoomBox{}, 0.6);
  s.lights.push_back(
      test::rectLight(Vec3(0, 2.6, -2), Vec3(0.4, 0, 0), Vec3(0, 0, 0.4), Vec3::Constant(5)));
  s.roomMaterials.assign(s.room.surfaces.size(), std::nullopt);
  s.roomMaterials[0] = marked(Material::Kind::Mirror);
  s.roomMaterials[4] = marked(Material::Kind::Glossy, 0.3);
  InsertedObject o;
  o.meshObject = test::sphereMesh(0.4);
  o.worldFromObject = test::translation(Vec3(0, 1.3, -5.0));  // behind the back wall
  s.objects.push_back(o);
  PathTracer tracer(s);
  DifferentialBuffers b(w, h);
  ASSERT_TRUE(tracer.render(b, 0, 16, 9));
  EXPECT_TRUE(sameBits(b.sumWith, b.sumWithout));
  double total = 0;
  for (float v : b.sumWith.data) total += v;
  EXPECT_GT(total, 0.0);
  ImageF photo(w, h, 3);
  for (size_t i = 0; i < photo.data.size(); ++i) photo.data[i] = float(i % 17) / 16.f;
  EXPECT_TRUE(
      sameBits(differentialComposite(photo, b.meanWith(), b.meanWithout(), b.meanMask()), photo));

  // The positive control: the same object inside the room changes the sums.
  s.objects[0].worldFromObject = test::translation(Vec3(0.3, 0.6, -2.5));
  PathTracer inside(s);
  DifferentialBuffers bi(w, h);
  ASSERT_TRUE(inside.render(bi, 0, 16, 9));
  EXPECT_FALSE(sameBits(bi.sumWith, bi.sumWithout));
}

}  // namespace
}  // namespace inlay
