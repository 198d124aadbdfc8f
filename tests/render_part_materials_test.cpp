// Multi-material objects (InsertedObject::partMaterials): each triangle renders in its part's
// material, and an emissive part is a light of its own (next-event estimation on its triangles
// alone), so a lamp whose shade glows lights the room as the shade alone would.
#include "render_test_scenes.h"
#include "test_support.h"

#include "inlay/render/path_tracer.h"

namespace inlay {
namespace {

// The floor under a 0.6 x 0.6 m glowing quad, seen from above; direct light only.
constexpr int kW = 40, kH = 30;
const Vec3 kLampCentre(0, 2.2, -2.0), kLampU(0.3, 0, 0), kLampV(0, 0, 0.3);

RenderScene floorScene() {
  return test::roomScene(test::testCamera(kW, kH, 60, 1.3, -40), RoomBox{}, 0.6);
}

Material emissive(double radiance) {
  Material m;
  m.kind = Material::Kind::Emissive;
  m.emission = Vec3::Constant(radiance);
  return m;
}

// The glowing quad alone, as an emissive object.
RenderScene shadeOnly(double radiance) {
  RenderScene s = floorScene();
  InsertedObject shade;
  shade.meshObject =
      std::make_shared<TriangleMesh>(test::quadMesh(test::rectCorners(kLampCentre, kLampU, kLampV)));
  shade.material = emissive(radiance);
  s.objects.push_back(shade);
  return s;
}

// One object of two parts: a 0.2 m "stand" quad high in a corner of the room (part 0) and the
// glowing quad (part 1).
RenderScene lamp(const std::vector<Material>& parts, const Material& whole) {
  RenderScene s = floorScene();
  TriangleMesh mesh =
      test::quadMesh(test::rectCorners(Vec3(1.8, 2.5, -3.8), Vec3(0.1, 0, 0), Vec3(0, 0, 0.1)));
  mesh.append(test::quadMesh(test::rectCorners(kLampCentre, kLampU, kLampV)));
  mesh.triangleMaterial = {0, 0, 1, 1};
  mesh.materials.resize(2);
  InsertedObject o;
  o.meshObject = std::make_shared<TriangleMesh>(mesh);
  o.material = whole;
  o.partMaterials = parts;
  s.objects.push_back(o);
  return s;
}

double floorLight(const RenderScene& s, int spp = 128) {
  TracerOptions opt;
  opt.maxDepth = 1;
  PathTracer tracer(s, opt);
  DifferentialBuffers b(kW, kH);
  EXPECT_TRUE(tracer.render(b, 0, spp, 5));
  EXPECT_EQ(tracer.stats().nonFiniteSamples, 0u);
  const ImageF with = b.meanWith();
  double sum = 0;
  for (size_t i = 0; i < with.pixelCount(); ++i)
    if (with.data[i * 3] < 2.0) sum += with.data[i * 3];  // the lit room, not the glowing quad seen
  return sum;
}

TEST(PartMaterials, AGlowingPartLightsTheRoomAsItWouldAlone) {
  Material dark;
  dark.albedo = Vec3::Constant(0.1);
  // At 16 samples only next-event estimation on the part's own triangles gets this close; BSDF
  // sampling alone (a part that is not a light) would be off by far more than 0.2%.
  const double alone = floorLight(shadeOnly(5.0), 16);
  const double asPart = floorLight(lamp({dark, emissive(5.0)}, dark), 16);
  ASSERT_GT(alone, 1.0);
  std::printf("[ part materials ] floor light: shade alone %.3f, shade as part 1 of 2 %.3f\n", alone,
              asPart);
  EXPECT_NEAR(asPart / alone, 1.0, 0.002);
}

TEST(PartMaterials, EachPartTakesItsOwnMaterial) {
  Material dark;
  dark.albedo = Vec3::Constant(0.1);
  // No part glows: the room stays dark though the object's own material is emissive.
  EXPECT_EQ(floorLight(lamp({dark, dark}, emissive(5.0)), 16), 0.0);
  // Without parts the object's material is everywhere: both quads glow, more light than one.
  const double one = floorLight(shadeOnly(5.0), 64);
  const double whole = floorLight(lamp({}, emissive(5.0)), 64);
  EXPECT_GT(whole, one * 1.02);
}

// A part list that does not match the mesh (the mesh has no per-triangle materials) is ignored:
// the object's material applies everywhere, and nothing reads past the lists.
TEST(PartMaterials, PartsWithoutPerTriangleMaterialsAreIgnored) {
  RenderScene s = shadeOnly(5.0);
  Material dark;
  s.objects[0].partMaterials = {dark, dark, dark};
  EXPECT_NEAR(floorLight(s, 32) / floorLight(shadeOnly(5.0), 32), 1.0, 1e-9);
}

}  // namespace
}  // namespace inlay
