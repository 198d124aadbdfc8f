// The clamp of indirect light (TracerOptions::clampRadiance, the scene key
// render.clamp_indirect): off is the unclamped render bit for bit; a huge indirect sample comes
// out finite and bounded; light reaching the first surface the camera sees (an emitter seen,
// next-event estimation there, a light found by its bounce) is never clamped; the differential
// composite's untouched pixels stay the photo's bits with a clamp.
#include "render_test_scenes.h"
#include "test_support.h"

#include "inlay/render/composite.h"
#include "inlay/render/path_tracer.h"

#include <cmath>

namespace inlay {
namespace {

using test::sameBits;

// A closed room lit by a ceiling light of radiance `le`, with a diffuse sphere on the floor
// (inside) or out of every path's reach.
RenderScene litRoom(int w, int h, double le, bool objectInside) {
  RenderScene s = test::roomScene(test::testCamera(w, h, 70, 1.3, -10), RoomBox{}, 0.6);
  s.lights.push_back(
      test::rectLight(Vec3(0, 2.6, -2), Vec3(0.4, 0, 0), Vec3(0, 0, 0.4), Vec3::Constant(le)));
  InsertedObject o;
  o.meshObject = test::sphereMesh(0.4);
  o.worldFromObject = test::translation(objectInside ? Vec3(0.3, 0.4, -2.5) : Vec3(0, 1.3, -5.0));
  o.material.kind = Material::Kind::Diffuse;
  o.material.albedo = Vec3::Constant(0.7);
  s.objects.push_back(o);
  return s;
}

DifferentialBuffers renderWith(const RenderScene& s, const TracerOptions& options, int spp,
                               uint32_t seed = 5) {
  PathTracer tracer(s, options);
  DifferentialBuffers b(s.camera.widthPx, s.camera.heightPx);
  EXPECT_TRUE(tracer.render(b, 0, spp, seed));
  return b;
}

TracerOptions clampAt(double c) {
  TracerOptions o;
  o.clampRadiance = c;
  return o;
}

double maxValue(const ImageF& im) {
  double m = 0;
  for (float v : im.data) m = std::max(m, double(v));
  return m;
}

// Off (0, the default) is the render without the clamp; a clamp above every sample changes
// nothing either; a clamp below the room's indirect light does change it (so the first two
// comparisons can fail).
TEST(ClampIndirect, OffAndUnreachedClampAreBitIdentical) {
  const RenderScene s = litRoom(40, 30, 5, true);
  const DifferentialBuffers plain = renderWith(s, TracerOptions{}, 8);
  const DifferentialBuffers off = renderWith(s, clampAt(0), 8);
  EXPECT_TRUE(sameBits(plain.sumWith, off.sumWith));
  EXPECT_TRUE(sameBits(plain.sumWithout, off.sumWithout));
  const DifferentialBuffers huge = renderWith(s, clampAt(1e30), 8);
  EXPECT_TRUE(sameBits(plain.sumWith, huge.sumWith));
  EXPECT_TRUE(sameBits(plain.sumWithout, huge.sumWithout));
  const DifferentialBuffers low = renderWith(s, clampAt(0.01), 8);
  EXPECT_FALSE(sameBits(plain.sumWith, low.sumWith));
  EXPECT_FALSE(sameBits(plain.sumWithout, low.sumWithout));
}

// A light of radiance 1e30 facing the ceiling: the camera, looking down, sees only surfaces it
// lights through another surface. Unclamped the room is ~1e29; clamped at 2, every sample's
// contributions are each at most 2 (a path has at most maxDepth + 1 vertices, each adding
// next-event light and what its bounce finds), so every pixel is finite and below that bound.
TEST(ClampIndirect, HugeIndirectSampleComesOutFiniteAndBounded) {
  const int w = 32, h = 24;
  RenderScene s = test::roomScene(test::testCamera(w, h, 40, 1.3, -45), RoomBox{}, 0.8);
  // u x v points up: the light shines at the ceiling only.
  s.lights.push_back(
      test::rectLight(Vec3(0, 2.55, -2), Vec3(0, 0, 0.3), Vec3(0.3, 0, 0), Vec3::Constant(1e30)));
  ASSERT_GT(s.lights[0].normal().y(), 0.99);
  const DifferentialBuffers raw = renderWith(s, TracerOptions{}, 4);
  EXPECT_GT(maxValue(raw.meanWith()), 1e20);  // the control: the light does reach the camera
  const TracerOptions o = clampAt(2);
  const DifferentialBuffers clamped = renderWith(s, o, 4);
  const ImageF with = clamped.meanWith();
  EXPECT_TRUE(test::allFinite(with));
  EXPECT_TRUE(test::allFinite(clamped.meanWithout()));
  EXPECT_GT(maxValue(with), 0.0);
  EXPECT_LE(maxValue(with), 2.0 * 2 * (o.maxDepth + 1));
}

// Light reaching the first surface is direct: with one bounce (maxDepth 1) a path holds only
// that (the emitter seen, next-event estimation at the first hit, a light its bounce finds),
// and a clamp far below it leaves the render bit for bit.
TEST(ClampIndirect, NeverTouchesDirectLight) {
  const RenderScene s = litRoom(40, 30, 50, true);
  TracerOptions direct;
  direct.maxDepth = 1;
  TracerOptions clamped = direct;
  clamped.clampRadiance = 1e-4;
  const DifferentialBuffers a = renderWith(s, direct, 8), b = renderWith(s, clamped, 8);
  EXPECT_GT(maxValue(a.meanWith()), 1.0);  // bright enough that a clamp would show
  EXPECT_TRUE(sameBits(a.sumWith, b.sumWith));
  EXPECT_TRUE(sameBits(a.sumWithout, b.sumWithout));
  // An emitter the camera sees keeps its radiance under any clamp (full depth).
  RenderScene e = litRoom(40, 30, 50, true);
  e.objects[0].material.kind = Material::Kind::Emissive;
  e.objects[0].material.emission = Vec3(30, 20, 10);
  const DifferentialBuffers eb = renderWith(e, clampAt(1e-3), 8);
  const ImageF with = eb.meanWith(), mask = eb.meanMask();
  int seen = 0;
  for (int y = 0; y < with.height; ++y)
    for (int x = 0; x < with.width; ++x)
      if (mask.at(x, y) == 1.f) {
        ++seen;
        EXPECT_NEAR(with.at(x, y, 0), 30.0, 1e-5);
      }
  EXPECT_GT(seen, 10);
}

// Both renders of the differential composite are clamped alike (the same paths, the same
// clamp): an object no path reaches leaves with == without bit for bit, so the composite is the
// photo's bits; an object inside changes it (the control).
TEST(ClampIndirect, UntouchedPixelsStayThePhoto) {
  const int w = 40, h = 30;
  const DifferentialBuffers far = renderWith(litRoom(w, h, 5, false), clampAt(0.05), 16, 9);
  EXPECT_TRUE(sameBits(far.sumWith, far.sumWithout));
  ImageF photo(w, h, 3);
  uint32_t state = 777;
  for (float& v : photo.data) v = float((state = state * 1664525u + 1013904223u) >> 8) / 16777216.f;
  EXPECT_TRUE(
      sameBits(differentialComposite(photo, far.meanWith(), far.meanWithout(), far.meanMask()), photo));
  const DifferentialBuffers near = renderWith(litRoom(w, h, 5, true), clampAt(0.05), 16, 9);
  EXPECT_FALSE(sameBits(near.sumWith, near.sumWithout));
}

}  // namespace
}  // namespace inlay
