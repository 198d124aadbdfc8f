// The sunlit patches as a light for next-event estimation (render/src/sun_patch.h and
// TracerOptions::sunPatchNee): the patch light's own sampling, and the path tracer with and
// without it on a room whose photo shows a bright patch next to an object.
#include "../render/src/sun_patch.h"
#include "render_test_scenes.h"

#include "inlay/render/path_tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace inlay {
namespace {

using detail::SunPatchLight;
using detail::texelFootprint;

SunPatchLight::Footprint square(size_t texel, const Vec3& corner, double side, double radiance) {
  SunPatchLight::Footprint f;
  f.texel = texel;
  f.corner = corner;
  f.edgeU = Vec3(side, 0, 0);
  f.edgeV = Vec3(0, 0, side);
  f.radiance = Vec3::Constant(radiance);
  return f;
}

// The estimator radiance / pdfArea of a sample integrates radiance over the patch: its mean is
// sum(radiance x area) whatever the texels' powers (here 1 to 1000 times apart).
TEST(SunPatchLight, SamplesIntegrateRadianceOverTheArea) {
  std::vector<SunPatchLight::Footprint> fs;
  double exact = 0;
  for (size_t i = 0; i < 10; ++i) {
    const double side = 0.01 * double(1 + i % 3), radiance = std::pow(10.0, double(i % 4));
    fs.push_back(square(i * 3, Vec3(double(i), 0, 0), side, radiance));
    exact += radiance * side * side;
  }
  const SunPatchLight light(fs, 40);
  ASSERT_EQ(light.size(), 10u);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  double sum = 0;
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    const auto s = light.sample(u(rng), u(rng), u(rng));
    ASSERT_GT(s.pdfArea, 0);
    EXPECT_EQ(s.pdfArea, light.pdfArea(size_t(std::floor(s.y.x())) * 3));  // footprint i sits at x = i
    sum += s.radiance.x() / s.pdfArea;
  }
  // Sampled by power, every sample gives the same value: the sum is exact up to round-off.
  EXPECT_NEAR(sum / n, exact, 1e-6 * exact);
  EXPECT_EQ(light.pdfArea(1), 0.0);    // not a patch texel
  EXPECT_EQ(light.pdfArea(999), 0.0);  // outside the grid
}

// Footprints with no area, no light, NaN or a texel outside the grid are left out; with none
// left the light is empty and samples nothing.
TEST(SunPatchLight, DegenerateFootprintsAreLeftOut) {
  std::vector<SunPatchLight::Footprint> fs = {square(0, Vec3::Zero(), 0.0, 5),    // no area
                                              square(1, Vec3::Zero(), 0.1, 0.0),  // black
                                              square(2, Vec3::Zero(), 0.1, 5),    // texel 2 >= 2
                                              square(0, Vec3::Zero(), 0.1, std::nan(""))};
  const SunPatchLight light(fs, 2);
  EXPECT_TRUE(light.empty());
  EXPECT_EQ(light.sample(0.5, 0.5, 0.5).pdfArea, 0.0);
  EXPECT_EQ(light.pdfArea(0), 0.0);
  EXPECT_TRUE(SunPatchLight().empty());
}

// A texel's footprint on the floor: the area the pixel's solid angle covers there
// (distance^2 x solid angle / cos), and none for a plane the rays run along or behind the camera.
TEST(SunPatchLight, TexelFootprintOnAPlane) {
  const Camera cam = test::testCamera(64, 48, 60, 1.3, -40);
  const int x = 40, y = 30;
  const Vec3 d = cam.directionThroughPixel(Vec2(x + 0.5, y + 0.5));
  const auto f = texelFootprint(cam, 64, 48, x, y, Vec3::Zero(), Vec3(0, 1, 0));
  ASSERT_TRUE(f.has_value());
  const Vec3 centre = f->corner + 0.5 * (f->edgeU + f->edgeV);
  const double t = cam.heightM / -d.y();
  EXPECT_NEAR((centre - (cam.centreWorld() + t * d)).norm(), 0.0, 1e-3);
  const Vec3 toCentre = cam.centreWorld() + t * d - cam.centreWorld();
  const double cosAxis = d.dot(cam.worldFromCamera * Vec3(0, 0, -1));
  const double solidAngle = std::pow(cosAxis, 3) / (cam.focalPx * cam.focalPx);
  const double expected = toCentre.squaredNorm() * solidAngle / -d.y();
  EXPECT_NEAR(f->edgeU.cross(f->edgeV).norm() / expected, 1.0, 0.02);
  EXPECT_GT(f->normal.y(), 0.99);  // toward the camera
  // The same plane given with its normal down: still turned toward the camera.
  EXPECT_GT(texelFootprint(cam, 64, 48, x, y, Vec3::Zero(), Vec3(0, -1, 0))->normal.y(), 0.99);
  // A plane above the camera that these (downward) rays never reach, and one they run along.
  EXPECT_FALSE(texelFootprint(cam, 64, 48, x, y, Vec3(0, 5, 0), Vec3(0, 1, 0)).has_value());
  const Vec3 along = d.cross(Vec3(1, 0, 0)).normalized();
  const auto grazing = texelFootprint(cam, 64, 48, x, y, cam.centreWorld() + Vec3(0, 0, -3), along);
  if (grazing) {
    EXPECT_TRUE(grazing->edgeU.allFinite() && grazing->edgeV.allFinite());
  }
  EXPECT_FALSE(texelFootprint(cam, 0, 48, x, y, Vec3::Zero(), Vec3(0, 1, 0)).has_value());
}

// A room whose photo shows a sunlit floor patch `patchRadiance` bright (a clipped patch takes the
// model's radiance: many times white) and 0.2 elsewhere, lit by nothing else (bounces read the
// photo). A diffuse sphere stands beside the patch. travelDirection: the sun's.
RenderScene patchRoom(int w, int h, double patchRadiance, const Vec3& travelDirection) {
  RenderScene s = test::roomScene(test::testCamera(w, h, 60, 1.3, -35), RoomBox{}, 0.5);
  s.roomAlbedo.albedo = ImageF(w, h, 3, 0.5f);
  s.roomAlbedo.photoRadiance = ImageF(w, h, 3, 0.2f);
  s.roomAlbedo.photoRadianceUsable.assign(size_t(w) * h, 1);
  s.roomAlbedo.computeFirstSurfaces(s.room);
  SunLight sun;
  sun.travelDirection = travelDirection.normalized();
  sun.irradianceOverPi = Vec3::Constant(0.05);
  sun.receiverPlane = Vec4(0, 1, 0, 0);
  sun.camera = s.camera;
  sun.litMask = ImageF(w, h, 1, 0.f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Vec3 d = s.camera.directionThroughPixel(Vec2(x + 0.5, y + 0.5));
      if (d.y() >= 0) continue;
      const Vec3 q = s.camera.centreWorld() - s.camera.heightM / d.y() * d;
      if (q.x() > -0.9 && q.x() < 0.1 && q.z() > -3.0 && q.z() < -2.0) {
        sun.litMask.at(x, y) = 1.f;
        s.roomAlbedo.photoRadiance.setRgb(x, y, Vec3::Constant(patchRadiance));
      }
    }
  s.suns.push_back(sun);
  InsertedObject o;
  o.meshObject = test::sphereMesh(0.3);
  o.worldFromObject = test::translation(Vec3(0.5, 0.3, -2.5));
  o.material.kind = Material::Kind::Diffuse;
  o.material.albedo = Vec3::Constant(0.8);
  s.objects.push_back(o);
  return s;
}

struct Rendered {
  ImageF with, without, mask;
};

Rendered renderOf(const RenderScene& s, bool patchNee, int spp, uint32_t seed, double clamp = 0) {
  TracerOptions opt;
  opt.sunPatchNee = patchNee;
  opt.clampRadiance = clamp;
  PathTracer tracer(s, opt);
  DifferentialBuffers b(s.camera.widthPx, s.camera.heightPx);
  EXPECT_TRUE(tracer.render(b, 0, spp, seed));
  return {b.meanWith(), b.meanWithout(), b.meanMask()};
}

// Over the object's pixels (mask 1): the mean of channel 0 and the RMS difference to a reference.
struct ObjectStats {
  double mean = 0, rmsToReference = 0;
};
ObjectStats objectStats(const Rendered& r, const Rendered& reference) {
  ObjectStats st;
  int n = 0;
  for (int y = 0; y < r.with.height; ++y)
    for (int x = 0; x < r.with.width; ++x) {
      if (reference.mask.at(x, y) < 1.f) continue;
      const double v = r.with.at(x, y, 0), e = v - reference.with.at(x, y, 0);
      st.mean += v, st.rmsToReference += e * e, ++n;
    }
  EXPECT_GT(n, 40);
  st.mean /= std::max(n, 1), st.rmsToReference = std::sqrt(st.rmsToReference / std::max(n, 1));
  return st;
}

// The patch 50 times the rest (clipped everywhere, the model's radiance): with NEE toward it the
// object's light converges to what BSDF sampling alone converges to (no bias), and at 8 samples
// it is much less noisy.
void expectSameLightLessNoise(const RenderScene& s, const char* label, double clamp = 0) {
  const Rendered reference = renderOf(s, true, 256, 99, clamp);
  const Rendered referenceOff = renderOf(s, false, 256, 98, clamp);
  const ObjectStats on = objectStats(renderOf(s, true, 8, 1, clamp), reference);
  const ObjectStats off = objectStats(renderOf(s, false, 8, 1, clamp), reference);
  const double refOn = objectStats(reference, reference).mean,
               refOff = objectStats(referenceOff, reference).mean;
  std::printf(
      "[ %s ] object mean 256 spp: NEE %.4f, BSDF only %.4f; RMS at 8 spp: NEE %.4f, BSDF only %.4f\n",
      label, refOn, refOff, on.rmsToReference, off.rmsToReference);
  EXPECT_NEAR(refOn / refOff, 1.0, 0.03);
  EXPECT_LT(on.rmsToReference, 0.5 * off.rmsToReference);
  EXPECT_TRUE(test::allFinite(reference.with) && test::allFinite(reference.without));
}

TEST(SunPatchNee, ABrightPatchLightsTheObjectWithoutFireflies) {
  expectSameLightLessNoise(patchRoom(48, 36, 10.0, Vec3(1, -1, 0.3)), "patch");
}

// The sun at 2 degrees above the horizon: the floor patch is still lit (the sun's cosine on it
// 0.035) and is still a patch light; the object's light is the patch's, as above.
TEST(SunPatchNee, GrazingSunStaysFiniteAndUnbiased) {
  expectSameLightLessNoise(patchRoom(48, 36, 10.0, Vec3(1, -std::tan(2 * test::kPi / 180), 0)),
                           "grazing");
}

// With the clamp of indirect light on (the product's default, 1), NEE toward the patch is made at
// the camera's first hit only (deeper landings are clamped): both still converge to one value.
TEST(SunPatchNee, WithTheClampOnlyTheFirstHitSamplesThePatch) {
  expectSameLightLessNoise(patchRoom(48, 36, 10.0, Vec3(1, -1, 0.3)), "clamp 1", 1.0);
}

// No sun, or a patch the photo shows black (no light in it): the tracer builds no patch light
// and renders as without the option, bit for bit.
TEST(SunPatchNee, NoSunOrABlackPatchRendersAsBefore) {
  RenderScene noSunScene = patchRoom(32, 24, 10.0, Vec3(1, -1, 0));
  noSunScene.suns.clear();
  const RenderScene& noSun = noSunScene;
  const RenderScene black = patchRoom(32, 24, 0.0, Vec3(1, -1, 0));
  for (const RenderScene* s : {&noSun, &black}) {
    const Rendered on = renderOf(*s, true, 4, 3), off = renderOf(*s, false, 4, 3);
    EXPECT_TRUE(test::sameBits(on.with, off.with));
    EXPECT_TRUE(test::sameBits(on.without, off.without));
  }
}

// Where the objects play no part, with and without stay equal bit for bit (the differential
// composite then gives the photo back): the shared paths' NEE toward the patch adds the same
// value to both.
TEST(SunPatchNee, UntouchedPixelsStayEqual) {
  RenderScene s = patchRoom(40, 30, 10.0, Vec3(1, -1, 0.3));
  s.objects[0].worldFromObject = test::translation(Vec3(0, 1.3, 5.0));  // behind the rear wall
  const Rendered r = renderOf(s, true, 8, 5);
  EXPECT_TRUE(test::sameBits(r.with, r.without));
  double total = 0;
  for (float v : r.with.data) total += v;
  EXPECT_GT(total, 0.0);
}

}  // namespace
}  // namespace inlay
