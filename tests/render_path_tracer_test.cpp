// Path tracer and RoomTracer tests with known answers: a uniform-radiance enclosure (furnace;
// the room's own surfaces cannot emit, so the field comes from emitters lining every wall),
// diffuse planes and a sphere under rectangle and trapezoid lights (closed-form form factors),
// a mirror, a glass slab, suns and the photo's radiance, the exact zero difference of the
// differential render, determinism, and stiff inputs.
#include "render_test_scenes.h"
#include "test_support.h"

#include "inlay/render/composite.h"
#include "inlay/render/path_tracer.h"

#include <chrono>
#include <cstring>
#include <functional>

namespace inlay {
namespace {

using test::kPi;

// Uniform-radiance enclosure: every face of the room is lined with an inward light of radiance
// le (black-backed, so no room surface is ever seen or lit).
RenderScene furnaceScene(int w, int h, double le) {
  const RoomBox box;
  RenderScene s = test::roomScene(test::testCamera(w, h, 50), box, 0.5);
  for (const auto& f : test::boxFaces(box))
    s.lights.push_back(test::rectLight(f.c, f.u, f.v, Vec3::Constant(le)));
  return s;
}

struct RegionStats {
  Vec3 mean = Vec3::Zero();
  double maxAbsDeviation = 0;  // of the per-pixel mean, channel 0
  int pixels = 0;
};

// Mean of `image` over pixels whose mask equals `maskValue` exactly (fully inside or outside).
RegionStats regionStats(const ImageF& image, const ImageF& mask, float maskValue, double expected) {
  RegionStats r;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (mask.at(x, y) == maskValue) {
        r.mean += image.rgb(x, y);
        r.maxAbsDeviation = std::max(r.maxAbsDeviation, std::abs(image.at(x, y, 0) - expected));
        ++r.pixels;
      }
  if (r.pixels) r.mean /= r.pixels;
  return r;
}

struct FurnaceCase {
  const char* name;
  Material material;
  double expectedOverLe;  // radiance of the object / le
  double tolerance;       // relative, on the mean over the object
};

class Furnace : public ::testing::TestWithParam<FurnaceCase> {};

// A convex object in a uniform radiance field le (black-backed emitters, no room visible):
// diffuse albedo a shows a * le, a mirror r * le, clear glass le (Fresnel splits, nothing is
// lost), an albedo-1 diffuse sphere le. Background pixels see an emitter directly: exactly le.
TEST_P(Furnace, ObjectRadianceMatchesUniformField) {
  const FurnaceCase& fc = GetParam();
  const double le = 0.7;
  RenderScene s = furnaceScene(48, 36, le);
  InsertedObject o;
  o.meshObject = test::sphereMesh(0.5);
  o.worldFromObject = test::translation(Vec3(0, 1.3, -2.2));
  o.material = fc.material;
  s.objects.push_back(o);
  TracerOptions opt;
  opt.maxDepth = 32;
  PathTracer tracer(s, opt);
  DifferentialBuffers b(48, 36);
  ASSERT_TRUE(tracer.render(b, 0, 64, 7));
  const ImageF with = b.meanWith(), mask = b.meanMask();
  const RegionStats obj = regionStats(with, mask, 1.f, fc.expectedOverLe * le);
  const RegionStats bg = regionStats(with, mask, 0.f, le);
  ASSERT_GT(obj.pixels, 100);
  ASSERT_GT(bg.pixels, 100);
  const double rel = obj.mean.x() / (fc.expectedOverLe * le) - 1.0;
  std::printf(
      "[ furnace ] %-14s object mean %.5f expected %.5f (rel err %+.4f) over %d px, "
      "background max dev %.2g\n",
      fc.name, obj.mean.x(), fc.expectedOverLe * le, rel, obj.pixels, bg.maxAbsDeviation);
  EXPECT_LT(std::abs(rel), fc.tolerance);
  EXPECT_LT(bg.maxAbsDeviation, 1e-6);
  EXPECT_EQ(tracer.stats().nonFiniteSamples, 0u);
}

Material mat(Material::Kind kind, double albedo, double roughness = 0.3) {
  Material m;
  m.kind = kind;
  m.albedo = Vec3::Constant(albedo);
  m.roughness = roughness;
  return m;
}

INSTANTIATE_TEST_SUITE_P(
    Materials, Furnace,
    ::testing::Values(
        FurnaceCase{"diffuse_0.6", mat(Material::Kind::Diffuse, 0.6), 0.6, 0.02},
        FurnaceCase{"diffuse_1.0", mat(Material::Kind::Diffuse, 1.0), 1.0, 0.02},
        FurnaceCase{"mirror_0.9", mat(Material::Kind::Mirror, 0.9), 0.9, 1e-5},
        FurnaceCase{"glass", mat(Material::Kind::Glass, 1.0), 1.0, 0.02},
        FurnaceCase{"conductor_r0.3", mat(Material::Kind::Conductor, 1.0, 0.3), 1.0, 0.03},
        // GGX single-scattering loss (a few % per interface at alpha 0.09), compounded inside.
        FurnaceCase{"rough_glass_r0.3", mat(Material::Kind::RoughGlass, 1.0, 0.3), 0.955, 0.02}),
    [](const auto& p) {
      std::string n = p.param.name;
      for (char& c : n)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return n;
    });

// Glossy (Fresnel-weighted GGX over a white base) must not create energy, and with a white
// base it must lose little (only the GGX single-scattering loss).
TEST(Furnace, GlossyWhiteConservesEnergy) {
  const double le = 0.7;
  for (double roughness : {0.05, 0.3, 0.8}) {
    RenderScene s = furnaceScene(48, 36, le);
    InsertedObject o;
    o.meshObject = test::sphereMesh(0.5);
    o.worldFromObject = test::translation(Vec3(0, 1.3, -2.2));
    o.material = mat(Material::Kind::Glossy, 1.0, roughness);
    s.objects.push_back(o);
    PathTracer tracer(s);
    DifferentialBuffers b(48, 36);
    ASSERT_TRUE(tracer.render(b, 0, 64, 3));
    const RegionStats obj = regionStats(b.meanWith(), b.meanMask(), 1.f, le);
    std::printf("[ furnace ] glossy roughness %.2f: object/le = %.4f\n", roughness, obj.mean.x() / le);
    EXPECT_LT(obj.mean.x() / le, 1.01);
    EXPECT_GT(obj.mean.x() / le, 0.95);
  }
}

// A glass slab seen at near-normal incidence in front of an emitter, in a black room: the
// incoherent sum of the inter-reflections transmits (1 - R) / (1 + R) with R = ((n-1)/(n+1))^2.
void expectSlabTransmitsFresnelSeries(const TracerOptions& opt) {
  const int w = 32, h = 24;
  RenderScene s = test::roomScene(test::testCamera(w, h, 10), RoomBox{}, 0.0);
  const double le = 2.0;
  s.lights.push_back(
      test::rectLight(Vec3(0, 1.3, -3), Vec3(0.5, 0, 0), Vec3(0, 0.5, 0), Vec3::Constant(le)));
  ASSERT_GT(s.lights[0].normal().z(), 0.99);
  InsertedObject o;
  o.meshObject = test::boxMesh(RoomBox{-0.5, 0.5, -0.2, 0.2, 1.0});  // y in [0, 1]
  o.worldFromObject = test::translation(Vec3(0, 0.8, -2.0));
  o.material = mat(Material::Kind::Glass, 1.0);
  o.material.ior = 1.5;
  s.objects.push_back(o);
  PathTracer tracer(s, opt);
  DifferentialBuffers b(w, h);
  ASSERT_TRUE(tracer.render(b, 0, 64, 8));
  const double r = 0.04;
  const RegionStats g = regionStats(b.meanWith(), b.meanMask(), 1.f, le * (1 - r) / (1 + r));
  ASSERT_EQ(g.pixels, w * h);
  std::printf("[ glass ] slab transmission %.5f, expected %.5f\n", g.mean.x() / le, (1 - r) / (1 + r));
  EXPECT_NEAR(g.mean.x() / le, (1 - r) / (1 + r), 0.01);
}

TEST(Glass, SlabTransmitsFresnelSeries) {
  TracerOptions opt;
  opt.maxDepth = 16;
  expectSlabTransmitsFresnelSeries(opt);
}

// Smooth glass vertices count apart from maxDepth (TracerOptions::maxGlassDepth): with a single
// bounce allowed elsewhere, the slab still passes its light and its inner reflections (the path
// crosses two faces and up to ten more inside); counted in maxDepth the slab was black.
// Splitting at the camera's first glass vertex (the default) keeps the same expectation as the
// Fresnel choice: both give the slab's series.
TEST(Glass, SplitAtTheCameraKeepsTheSlabsTransmission) {
  TracerOptions opt;
  opt.maxDepth = 16;
  ASSERT_TRUE(opt.splitGlassAtCamera);
  expectSlabTransmitsFresnelSeries(opt);
  opt.splitGlassAtCamera = false;
  expectSlabTransmitsFresnelSeries(opt);
}

TEST(Glass, GlassVerticesCountApartFromTheBounces) {
  TracerOptions opt;
  opt.maxDepth = 1;
  ASSERT_GE(opt.maxGlassDepth, 12);
  expectSlabTransmitsFresnelSeries(opt);
}

// Form factor from a point to a parallel rectangle [x0,x1] x [z0,z1] at height c above it
// (irradiance / (pi * radiance)): the corner formula, signed, summed over four corners.
double cornerFormFactor(double x, double z, double c) {
  const double a = x / c, b = z / c;
  const double sa = std::sqrt(1 + a * a), sb = std::sqrt(1 + b * b);
  return (a / sa * std::atan(b / sa) + b / sb * std::atan(a / sb)) / (2 * kPi);
}
double rectFormFactor(double px, double pz, double x0, double x1, double z0, double z1, double c) {
  return cornerFormFactor(x1 - px, z1 - pz, c) - cornerFormFactor(x0 - px, z1 - pz, c) -
         cornerFormFactor(x1 - px, z0 - pz, c) + cornerFormFactor(x0 - px, z0 - pz, c);
}

// A 0.5 x 0.4 m light 1.2 m over the floor, facing down; the emitter sits 1 mm below the given
// corners (the tracers' offset), a 0.2% change that the tolerances cover.
struct PlaneSetup {
  double lightY = 1.2, x0 = -0.25, x1 = 0.25, z0 = -2.2, z1 = -1.8;
  double le = 3.0;
  AreaLight light() const {
    return test::rectLight(Vec3(0.5 * (x0 + x1), lightY, 0.5 * (z0 + z1)), Vec3(0.5 * (x1 - x0), 0, 0),
                           Vec3(0, 0, 0.5 * (z1 - z0)), Vec3::Constant(le));
  }
};

TEST(DiffusePlane, RoomTracerMatchesFormFactor) {
  const PlaneSetup p;
  const AreaLight light = p.light();
  ASSERT_LT(light.normal().y(), -0.99);
  const RoomTracer tracer(test::boxRoom());
  for (const Vec3& point : {Vec3(0, 0, -2), Vec3(0.3, 0, -1.5), Vec3(-1.0, 0, -3.0)}) {
    const double expected = rectFormFactor(point.x(), point.z(), p.x0, p.x1, p.z0, p.z1, p.lightY);
    const double got = tracer.unitLightIrradianceOverPi(light, point, Vec3(0, 1, 0), 1024, 5);
    std::printf("[ plane ] RoomTracer at (%.1f, %.1f): %.6f, closed form %.6f (rel %+.4f)\n", point.x(),
                point.z(), got, expected, got / expected - 1);
    EXPECT_NEAR(got / expected, 1.0, 0.01);
  }
  // Facing away, and behind the light: nothing.
  EXPECT_EQ(tracer.unitLightIrradianceOverPi(light, Vec3(0, 0, -2), Vec3(0, -1, 0), 64, 1), 0.0);
  EXPECT_EQ(tracer.unitLightIrradianceOverPi(light, Vec3(0, 2, -2), Vec3(0, -1, 0), 64, 1), 0.0);
  // Shadowed by a wall: the light seen from outside the room's back wall.
  EXPECT_EQ(tracer.unitLightIrradianceOverPi(light, Vec3(0, 0.5, -4.5), Vec3(0, 0, 1), 64, 1), 0.0);
  EXPECT_TRUE(tracer.visible(Vec3(0, 1, -1), Vec3(1, 2, -3)));
  EXPECT_FALSE(tracer.visible(Vec3(0, 1, -1), Vec3(0, 1, -5)));
  const auto hit = tracer.intersect(Ray{Vec3(0, 1, -1), Vec3(0, -1, 0)});
  ASSERT_TRUE(hit.has_value());
  EXPECT_EQ(hit->surfaceId, 0);
  EXPECT_NEAR(hit->t, 1.0, 1e-6);
  EXPECT_NEAR(hit->normalWorld.y(), 1.0, 1e-9);
}

// Next to a light touching a wall, 64 stratified samples already agree with 4096 (solid-angle
// stratification; area sampling needs far more this close).
TEST(DiffusePlane, RoomTracerNextToATouchingLight) {
  const RoomTracer tracer(test::boxRoom());
  const AreaLight light =
      test::rectLight(Vec3(0, 2.6, -3.7), Vec3(0.3, 0, 0), Vec3(0, 0, 0.3), Vec3::Ones());
  for (const double below : {0.003, 0.02, 0.2}) {
    const Vec3 p(0.1, 2.6 - below, -4.0 + 1e-4), n(0, 0, 1);
    const double few = tracer.unitLightIrradianceOverPi(light, p, n, 64, 3);
    const double many = tracer.unitLightIrradianceOverPi(light, p, n, 4096, 4);
    std::printf(
        "[ plane ] wall point %.3f m below a touching light: 64 samples %.5f, 4096 samples %.5f\n",
        below, few, many);
    EXPECT_GT(many, 0.0);
    EXPECT_NEAR(few / many, 1.0, 0.02);
  }
}

// The same through the path tracer with maxDepth 1 (direct light, NEE + MIS): every floor pixel
// shows albedo * le * F.
TEST(DiffusePlane, PathTracerDirectLightMatchesFormFactor) {
  const PlaneSetup p;
  const double albedo = 0.5;
  const int w = 48, h = 36;
  RenderScene s = test::roomScene(test::testCamera(w, h, 60, 0.6, -35), RoomBox{}, albedo);
  s.lights.push_back(p.light());
  TracerOptions opt;
  opt.maxDepth = 1;
  PathTracer tracer(s, opt);
  DifferentialBuffers b(w, h);
  ASSERT_TRUE(tracer.render(b, 0, 128, 11));
  const ImageF with = b.meanWith();
  test::RelativeError err;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      // Compare only pixels whose whole footprint lands on the floor: its four corners.
      bool floor = true;
      for (double dy : {0.0, 1.0})
        for (double dx : {0.0, 1.0}) {
          const Vec3 d = s.camera.directionThroughPixel(Vec2(x + dx, y + dy));
          const double t = d.y() < 0 ? -s.camera.heightM / d.y() : -1;
          const Vec3 q = s.camera.centreWorld() + t * d;
          floor = floor && t > 0 && q.x() > -2 && q.x() < 2 && q.z() > -4 && q.z() < 0.5;
        }
      if (!floor) continue;
      const Vec3 d = s.camera.directionThroughPixel(Vec2(x + 0.5, y + 0.5));
      const Vec3 q = s.camera.centreWorld() - s.camera.heightM / d.y() * d;
      const double expected = albedo * p.le *
                              rectFormFactor(q.x(), q.z(), p.x0, p.x1, p.z0, p.z1, p.lightY);
      if (expected < 0.005) continue;  // the far floor: relative noise too high to compare
      err.add(with.at(x, y, 0), expected);
    }
  ASSERT_GT(err.n, 200);
  const double bias = err.mean(), rms = err.rms();
  std::printf("[ plane ] path tracer, maxDepth 1, 128 spp: %d floor px, mean rel err %+.4f, rms %.4f\n",
              err.n, bias, rms);
  // Pixel-footprint averaging of a smooth function: the mean over pixels stays unbiased to 1%.
  EXPECT_LT(std::abs(bias), 0.01);
  EXPECT_LT(rms, 0.05);
}

// Form factor from a point (normal n) to an unoccluded polygon above its tangent plane:
// Lambert's contour integral, (1 / 2 pi) |sum_i theta_i n . (R_i x R_i+1) / |R_i x R_i+1||.
double polygonFormFactor(const Vec3& p, const Vec3& n, const std::array<Vec3, 4>& c) {
  double sum = 0;
  for (int i = 0; i < 4; ++i) {
    const Vec3 a = (c[i] - p).normalized(), b = (c[(i + 1) % 4] - p).normalized();
    const Vec3 x = a.cross(b);
    sum += std::acos(std::clamp(a.dot(b), -1.0, 1.0)) * n.dot(x.normalized());
  }
  return std::abs(sum) / (2 * kPi);
}

// Direct light only (maxDepth 1, NEE + MIS) from `light` on the floor of a box room, against
// albedo x le x Lambert's polygon formula at each pixel's centre from row firstRow down, the
// pixels split into two groups by region(floor point) (0 or 1); the far floor, where the light
// is too faint to compare, is left out.
std::array<test::RelativeError, 2> directLightErrors(const AreaLight& light, int spp, uint32_t seed,
                                                     int firstRow,
                                                     const std::function<int(const Vec3&)>& region) {
  const int w = 48, h = 36;
  const double albedo = 0.5;
  RenderScene s = test::roomScene(test::testCamera(w, h, 60, 0.6, -35), RoomBox{}, albedo);
  s.lights.push_back(light);
  TracerOptions opt;
  opt.maxDepth = 1;
  PathTracer tracer(s, opt);
  DifferentialBuffers b(w, h);
  EXPECT_TRUE(tracer.render(b, 0, spp, seed));
  const ImageF with = b.meanWith();
  std::array<test::RelativeError, 2> err;
  for (int y = firstRow; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Vec3 d = s.camera.directionThroughPixel(Vec2(x + 0.5, y + 0.5));
      if (d.y() >= 0) continue;
      const Vec3 q = s.camera.centreWorld() - s.camera.heightM / d.y() * d;
      if (!(q.x() > -1.9 && q.x() < 1.9 && q.z() > -3.9)) continue;
      const double expected = albedo * light.radiance.x() *
                              polygonFormFactor(q, Vec3(0, 1, 0), light.cornersWorld);
      if (expected < 0.005) continue;
      err[size_t(region(q) != 0)].add(with.at(x, y, 0), expected);
    }
  return err;
}

// A trapezoid light (not a rectangle: sampled by spherical triangles) over the floor: the
// RoomTracer and the path tracer (direct light) against Lambert's polygon formula.
TEST(DiffusePlane, TrapezoidLightMatchesPolygonFormula) {
  AreaLight light;
  light.cornersWorld = {Vec3(-0.3, 1.2, -2.2), Vec3(0.3, 1.2, -2.2), Vec3(0.1, 1.2, -1.8),
                        Vec3(-0.1, 1.2, -1.8)};
  light.radiance = Vec3::Constant(3.0);
  ASSERT_LT(light.normal().y(), -0.99);
  // The closed form agrees with the rectangle formula on a rectangle (checks the helper).
  const std::array<Vec3, 4> rect =
      test::rectCorners(Vec3(0, 1.2, -2), Vec3(0.25, 0, 0), Vec3(0, 0, 0.2));
  EXPECT_NEAR(polygonFormFactor(Vec3(0.3, 0, -1.5), Vec3(0, 1, 0), rect),
              rectFormFactor(0.3, -1.5, -0.25, 0.25, -2.2, -1.8, 1.2), 1e-9);
  const RoomTracer room(test::boxRoom());
  for (const Vec3& point :
       {Vec3(0, 0, -2), Vec3(0.5, 0, -1.5), Vec3(-1.0, 0, -3.0), Vec3(0, 1.19, -2.1)}) {
    const double expected = polygonFormFactor(point, Vec3(0, 1, 0), light.cornersWorld);
    const double got = room.unitLightIrradianceOverPi(light, point, Vec3(0, 1, 0), 256, 2);
    std::printf("[ plane ] trapezoid, RoomTracer at (%.1f, %.2f, %.1f): %.6f, closed form %.6f\n",
                point.x(), point.y(), point.z(), got, expected);
    EXPECT_NEAR(got / expected, 1.0, point.y() > 1 ? 0.02 : 0.01);  // 1 cm under it: the 1 mm offset
  }
  const test::RelativeError err =
      directLightErrors(light, 64, 5, 36 / 2, [](const Vec3&) { return 0; })[0];
  ASSERT_GT(err.n, 200);
  std::printf("[ plane ] trapezoid, path tracer 64 spp: %d px, mean rel err %+.4f, rms %.4f\n", err.n,
              err.mean(), err.rms());
  EXPECT_LT(std::abs(err.mean()), 0.01);
  EXPECT_LT(err.rms(), 0.05);
}

// NEE samples a light by area from points where its corners lie within an eighth of its
// centre's distance (PathTracer's kFarLightRatio) and by solid angle nearer: a trapezoid of 0.17 m
// radius 1.2 m above the floor is near for the floor under it and far beyond about 0.6 m. Both
// parts of the floor match Lambert's polygon formula (the area pdf with its d^2 / cos, and MIS
// with the same rule when a BSDF ray finds the light).
TEST(DiffusePlane, NearAndFarFromALightMatchPolygonFormula) {
  AreaLight light;
  light.cornersWorld = {Vec3(-0.14, 1.2, -2.1), Vec3(0.14, 1.2, -2.1), Vec3(0.05, 1.2, -1.9),
                        Vec3(-0.05, 1.2, -1.9)};
  light.radiance = Vec3::Constant(3.0);
  Vec3 centre = Vec3::Zero();
  for (const Vec3& c : light.cornersWorld) centre += 0.25 * c;
  double radius = 0;
  for (const Vec3& c : light.cornersWorld) radius = std::max(radius, (c - centre).norm());
  const auto region = [&](const Vec3& q) { return (q - centre).norm() > 8.0 * radius ? 1 : 0; };
  const std::array<test::RelativeError, 2> err = directLightErrors(light, 64, 7, 0, region);
  for (int k = 0; k < 2; ++k) {
    std::printf("[ plane ] trapezoid near and far, %s: %d px, mean rel err %+.4f, rms %.4f\n",
                k ? "far (by area)" : "near (by solid angle)", err[k].n, err[k].mean(), err[k].rms());
    ASSERT_GT(err[k].n, 80);
    EXPECT_LT(std::abs(err[k].mean()), 0.015);
    EXPECT_LT(err[k].rms(), 0.06);
  }
}

// A scaled diffuse sphere (instance with scale) on the floor under a ceiling light, direct
// light only: each sphere pixel shows albedo * le * (E / pi) at its surface point, computed by
// the RoomTracer (a convex object cannot shadow itself from above its tangent plane).
TEST(DiffuseSphere, DirectLightMatchesRoomTracerPerPixel) {
  const int w = 48, h = 36;
  RenderScene s = test::roomScene(test::testCamera(w, h, 30, 1.3, -20), RoomBox{}, 0.5);
  const double le = 4.0, albedo = 0.8, radius = 0.3;
  s.lights.push_back(
      test::rectLight(Vec3(0.3, 2.6, -2.4), Vec3(0.3, 0, 0), Vec3(0, 0, 0.3), Vec3::Constant(le)));
  const Vec3 centre(0, radius, -2.5);
  InsertedObject o;
  o.meshObject = test::sphereMesh(0.5, 48, 96);  // radius 0.5, scaled to 0.3 below
  Mat4 m = Mat4::Identity();
  m.topLeftCorner<3, 3>() *= radius / 0.5;
  m.topRightCorner<3, 1>() = centre;
  o.worldFromObject = m;
  o.material = mat(Material::Kind::Diffuse, albedo);
  s.objects.push_back(o);
  TracerOptions opt;
  opt.maxDepth = 1;
  PathTracer tracer(s, opt);
  DifferentialBuffers b(w, h);
  ASSERT_TRUE(tracer.render(b, 0, 64, 4));
  const ImageF with = b.meanWith(), mask = b.meanMask();
  const RoomTracer room(s.room);
  test::RelativeError err;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (mask.at(x, y) != 1.f) continue;
      const Ray r = s.camera.rayThroughPixel(Vec2(x + 0.5, y + 0.5));
      const Vec3 oc = r.origin - centre;
      const double bq = oc.dot(r.direction), disc = bq * bq - (oc.squaredNorm() - radius * radius);
      if (disc <= 0) continue;
      const Vec3 p = r.at(-bq - std::sqrt(disc)), nrm = (p - centre).normalized();
      const double expected = albedo * le *
                              room.unitLightIrradianceOverPi(s.lights[0], p + 1e-4 * nrm, nrm, 1024, 1);
      if (expected < 0.05) continue;  // the dim side: relative noise too high
      err.add(with.at(x, y, 0), expected);
    }
  ASSERT_GT(err.n, 30);
  std::printf("[ sphere ] direct light on a scaled sphere: %d px, mean rel err %+.4f, rms %.4f\n", err.n,
              err.mean(), err.rms());
  EXPECT_LT(std::abs(err.mean()), 0.02);
  EXPECT_LT(err.rms(), 0.08);
}

// A mirror (an object quad facing the camera) reflecting a large light behind the camera:
// radiance = reflectance * le, exactly (the path is deterministic).
TEST(Mirror, ReflectsEmitterTimesReflectance) {
  const int w = 48, h = 36;
  RenderScene s = test::roomScene(test::testCamera(w, h, 40), RoomBox{}, 0.5);
  const double le = 2.5;
  s.lights.push_back(
      test::rectLight(Vec3(0, 1.3, 0.45), Vec3(0, 1.2, 0), Vec3(1.9, 0, 0), Vec3::Constant(le)));
  ASSERT_LT(s.lights[0].normal().z(), -0.99);
  InsertedObject o;
  o.meshObject = std::make_shared<TriangleMesh>(
      test::quadMesh(test::rectCorners(Vec3(0, 1.3, -2), Vec3(0.3, 0, 0), Vec3(0, 0.3, 0))));
  o.material = mat(Material::Kind::Mirror, 0.8);
  s.objects.push_back(o);
  PathTracer tracer(s);
  DifferentialBuffers b(w, h);
  ASSERT_TRUE(tracer.render(b, 0, 4, 1));
  const RegionStats m = regionStats(b.meanWith(), b.meanMask(), 1.f, 0.8 * le);
  ASSERT_GT(m.pixels, 20);
  std::printf("[ mirror ] %d px, mean %.6f, expected %.6f, max dev %.2g\n", m.pixels, m.mean.x(),
              0.8 * le, m.maxAbsDeviation);
  EXPECT_LT(m.maxAbsDeviation, 1e-5);
  // The camera never sees the light directly (it is behind), and the room is lit by it.
  const RegionStats room = regionStats(b.meanWithout(), b.meanMask(), 0.f, 0);
  EXPECT_GT(room.mean.x(), 0.0);
  EXPECT_LT(room.mean.x(), le);
}

// Sunlight (parallel, no mask) on the floor, direct light only: radiance albedo *
// irradianceOverPi * cos, exactly (no sampling involved), the box walls never block it, and a
// floating sphere's shadow shows only in the with-object render.
TEST(Sun, FloorRadianceAndObjectShadow) {
  const int w = 48, h = 36;
  const double albedo = 0.5;
  RenderScene s = test::roomScene(test::testCamera(w, h, 60, 0.6, -35), RoomBox{}, albedo);
  SunLight sun;
  sun.travelDirection = Vec3(1, -1, 0).normalized();
  sun.irradianceOverPi = Vec3(2, 1.5, 1);
  s.suns.push_back(sun);
  InsertedObject o;
  o.meshObject = test::sphereMesh(0.3);
  o.worldFromObject = test::translation(Vec3(0, 0.8, -2.5));
  s.objects.push_back(o);
  TracerOptions opt;
  opt.maxDepth = 1;
  PathTracer tracer(s, opt);
  DifferentialBuffers b(w, h);
  ASSERT_TRUE(tracer.render(b, 0, 4, 1));
  const ImageF with = b.meanWith(), without = b.meanWithout();
  const double cosSun = -sun.travelDirection.y();
  int floorPx = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      bool floor = true;
      for (double dy : {0.0, 1.0})
        for (double dx : {0.0, 1.0}) {
          const Vec3 d = s.camera.directionThroughPixel(Vec2(x + dx, y + dy));
          const Vec3 q = s.camera.centreWorld() - s.camera.heightM / d.y() * d;
          floor = floor && d.y() < 0 && q.x() > -2 && q.x() < 2 && q.z() > -4 && q.z() < 0.5;
        }
      if (!floor) continue;
      ++floorPx;
      EXPECT_NEAR(without.at(x, y, 0), albedo * 2 * cosSun, 1e-5);
      EXPECT_NEAR(without.at(x, y, 2), albedo * 1 * cosSun, 1e-5);
    }
  EXPECT_GT(floorPx, 300);
  // The shadow of the sphere's centre falls at (0.8, 0, -2.5).
  const auto px = s.camera.project(Vec3(0.8, 0, -2.5));
  ASSERT_TRUE(px.has_value());
  const int sx = int(px->x()), sy = int(px->y());
  EXPECT_EQ(b.meanMask().at(sx, sy), 0.f);
  EXPECT_NEAR(without.at(sx, sy, 0), albedo * 2 * cosSun, 1e-5);
  EXPECT_EQ(with.at(sx, sy, 0), 0.f);
}

// Bounces that land on room the camera sees take the photo's radiance; camera rays do not.
// A mirror tilted down reflects the floor in front of it: its pixels show reflectance x photo
// radiance where that floor is in the photo; the room the camera sees is rendered (no lights:
// only the photo's light gathered by its first bounce).
TEST(PhotoRadiance, BouncesSeeThePhotoCameraRaysDoNot) {
  const int w = 64, h = 48;
  RenderScene s = test::roomScene(test::testCamera(w, h, 70, 1.3, -10), RoomBox{}, 0.5);
  s.roomAlbedo.albedo = ImageF(w, h, 3, 0.5f);
  s.roomAlbedo.photoRadiance = ImageF(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) s.roomAlbedo.photoRadiance.setRgb(x, y, Vec3(0.3, 0.6, 0.9));
  s.roomAlbedo.photoRadianceUsable.assign(size_t(w) * h, 1);
  s.roomAlbedo.computeFirstSurfaces(s.room);
  const double tilt = 25 * kPi / 180;
  const Vec3 n(0, -std::sin(tilt), std::cos(tilt)), u(1, 0, 0);
  const Vec3 v = n.cross(u);
  InsertedObject o;
  o.meshObject = std::make_shared<TriangleMesh>(
      test::quadMesh(test::rectCorners(Vec3(0, 1.3, -3), 0.25 * u, 0.25 * v)));
  o.material = mat(Material::Kind::Mirror, 0.8);
  s.objects.push_back(o);
  PathTracer tracer(s);
  DifferentialBuffers b(w, h);
  ASSERT_TRUE(tracer.render(b, 0, 4, 1));
  const ImageF with = b.meanWith(), mask = b.meanMask();
  int photo = 0, mirror = 0, room = 0;
  double roomMean = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (mask.at(x, y) == 1.f) {
        ++mirror;
        if (std::abs(with.at(x, y, 1) - 0.8 * 0.6) < 1e-5) ++photo;
      } else if (mask.at(x, y) == 0.f) {
        // No lights: what the camera sees directly is rendered (albedo 0.5 x the photo's
        // radiance gathered by its bounces, below 0.15 in red), never the photo's 0.3 itself.
        ASSERT_NE(with.at(x, y, 0), 0.3f);
        roomMean += with.at(x, y, 0), ++room;
      }
    }
  std::printf("[ photo ] mirror pixels %d, showing reflectance x photo radiance %d\n", mirror, photo);
  EXPECT_GT(mirror, 20);
  EXPECT_GT(photo, mirror / 2);
  ASSERT_GT(room, 1000);
  EXPECT_GT(roomMean / room, 0.0);
  EXPECT_LT(roomMean / room, 0.15);
}

// A closed room lit by a ceiling light, with an object that no path can reach.
RenderScene closedRoomScene(int w, int h, bool objectInside) {
  RenderScene s = test::roomScene(test::testCamera(w, h, 70, 1.3, -10), RoomBox{}, 0.6);
  s.lights.push_back(
      test::rectLight(Vec3(0, 2.6, -2), Vec3(0.4, 0, 0), Vec3(0, 0, 0.4), Vec3::Constant(5)));
  InsertedObject o;
  o.meshObject = test::sphereMesh(0.4);
  o.worldFromObject = test::translation(objectInside ? Vec3(0.3, 0.4, -2.5) : Vec3(0, 1.3, -5.0));
  o.material = mat(Material::Kind::Diffuse, 0.7);
  s.objects.push_back(o);
  return s;
}

using test::sameBits;

ImageF randomPhoto(int w, int h) {
  ImageF photo(w, h, 3);
  uint32_t state = 12345;
  for (float& v : photo.data) {
    state = state * 1664525u + 1013904223u;
    v = float(state >> 8) / 16777216.f * 1.3f;
  }
  return photo;
}

TEST(Differential, UnreachableObjectLeavesWithEqualWithoutBitForBit) {
  const int w = 40, h = 30;
  PathTracer tracer(closedRoomScene(w, h, false));
  DifferentialBuffers b(w, h);
  ASSERT_TRUE(tracer.render(b, 0, 16, 9));
  EXPECT_TRUE(sameBits(b.sumWith, b.sumWithout));
  for (float v : b.sumDiffSq.data) ASSERT_EQ(v, 0.f);
  for (float v : b.sumMask.data) ASSERT_EQ(v, 0.f);
  double total = 0;
  for (float v : b.sumWith.data) total += v;
  EXPECT_GT(total, 0.0);  // the room is lit: not a vacuous comparison
  const ImageF photo = randomPhoto(w, h);
  EXPECT_TRUE(
      sameBits(differentialComposite(photo, b.meanWith(), b.meanWithout(), b.meanMask()), photo));
}

TEST(Differential, NoObjectsGivesThePhotoBack) {
  const int w = 40, h = 30;
  RenderScene s = closedRoomScene(w, h, false);
  s.objects.clear();
  PathTracer tracer(s);
  DifferentialBuffers b(w, h);
  ASSERT_TRUE(tracer.render(b, 0, 8, 2));
  const ImageF photo = randomPhoto(w, h);
  EXPECT_TRUE(
      sameBits(differentialComposite(photo, b.meanWith(), b.meanWithout(), b.meanMask()), photo));
}

// The positive control: an object in the room changes the render (so the tests above can fail).
TEST(Differential, ObjectInsideChangesTheRender) {
  const int w = 40, h = 30;
  PathTracer tracer(closedRoomScene(w, h, true));
  DifferentialBuffers b(w, h);
  ASSERT_TRUE(tracer.render(b, 0, 16, 9));
  EXPECT_FALSE(sameBits(b.sumWith, b.sumWithout));
  double mask = 0, diffSq = 0;
  for (float v : b.sumMask.data) mask += v;
  for (float v : b.sumDiffSq.data) diffSq += v;
  EXPECT_GT(mask, 0);
  EXPECT_GT(diffSq, 0);
}

// The without-object render of a scene with an object is the render of the room alone, bit
// for bit: shared prefixes, the shadow retest and the split path all replay the same numbers.
TEST(Differential, WithoutImageEqualsRenderingTheEmptyRoom) {
  const int w = 40, h = 30;
  const RenderScene withObject = closedRoomScene(w, h, true);
  RenderScene empty = withObject;
  empty.objects.clear();
  PathTracer a(withObject), b(empty);
  DifferentialBuffers ba(w, h), bb(w, h);
  ASSERT_TRUE(a.render(ba, 0, 8, 13));
  ASSERT_TRUE(b.render(bb, 0, 8, 13));
  EXPECT_TRUE(sameBits(ba.sumWithout, bb.sumWith));
  EXPECT_TRUE(sameBits(bb.sumWith, bb.sumWithout));
  EXPECT_FALSE(sameBits(ba.sumWith, ba.sumWithout));
}

// An emissive object shows its emission to the camera exactly, and lights the room.
TEST(Emissive, SeenDirectlyAndLightsTheRoom) {
  const int w = 40, h = 30;
  RenderScene s = closedRoomScene(w, h, true);
  s.objects[0].material.kind = Material::Kind::Emissive;
  s.objects[0].material.emission = Vec3(3, 2, 1);
  PathTracer tracer(s);
  DifferentialBuffers b(w, h);
  ASSERT_TRUE(tracer.render(b, 0, 16, 3));
  const ImageF with = b.meanWith(), without = b.meanWithout(), mask = b.meanMask();
  int inside = 0;
  double gain = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (mask.at(x, y) == 1.f) {
        ++inside;
        EXPECT_NEAR(with.at(x, y, 0), 3.0, 1e-6);
        EXPECT_NEAR(with.at(x, y, 2), 1.0, 1e-6);
      } else if (mask.at(x, y) == 0.f) {
        gain += with.at(x, y, 0) - without.at(x, y, 0);
      }
    }
  EXPECT_GT(inside, 10);
  EXPECT_GT(gain, 0.0);
}

TEST(Determinism, SameSeedSameBuffersAnyThreadCount) {
  const int w = 40, h = 30;
  PathTracer tracer(closedRoomScene(w, h, true));
  DifferentialBuffers a(w, h), b(w, h), c(w, h);
  ASSERT_TRUE(tracer.render(a, 0, 4, 21, 1));
  ASSERT_TRUE(tracer.render(b, 0, 4, 21, 2));
  ASSERT_TRUE(tracer.render(c, 0, 4, 22, 2));
  EXPECT_TRUE(sameBits(a.sumWith, b.sumWith));
  EXPECT_TRUE(sameBits(a.sumWithout, b.sumWithout));
  EXPECT_TRUE(sameBits(a.sumMask, b.sumMask));
  EXPECT_FALSE(sameBits(a.sumWith, c.sumWith));
  // Two waves of 2 equal one wave of 4 up to float summation order: same samples.
  DifferentialBuffers d(w, h);
  ASSERT_TRUE(tracer.render(d, 0, 2, 21));
  ASSERT_TRUE(tracer.render(d, 2, 2, 21));
  EXPECT_EQ(d.samples, a.samples);
  for (size_t i = 0; i < d.sumWith.data.size(); ++i)
    ASSERT_NEAR(d.sumWith.data[i], a.sumWith.data[i], 1e-4 * (1 + std::abs(a.sumWith.data[i])));
}

TEST(Determinism, MovingAnObjectEqualsBuildingItThere) {
  const int w = 40, h = 30;
  RenderScene s = closedRoomScene(w, h, true);
  const Mat4 there = test::translation(Vec3(-0.4, 0.5, -2.0));
  PathTracer moved(s);
  moved.setObjectTransform(0, there);
  EXPECT_TRUE(moved.scene().objects[0].worldFromObject.isApprox(there));
  s.objects[0].worldFromObject = there;
  PathTracer built(s);
  DifferentialBuffers a(w, h), b(w, h);
  ASSERT_TRUE(moved.render(a, 0, 4, 5));
  ASSERT_TRUE(built.render(b, 0, 4, 5));
  EXPECT_TRUE(sameBits(a.sumWith, b.sumWith));
  EXPECT_TRUE(sameBits(a.sumWithout, b.sumWithout));
  EXPECT_TRUE(sameBits(a.sumMask, b.sumMask));
  // And moving it changes the picture.
  PathTracer original(closedRoomScene(w, h, true));
  DifferentialBuffers c(w, h);
  ASSERT_TRUE(original.render(c, 0, 4, 5));
  EXPECT_FALSE(sameBits(a.sumWith, c.sumWith));
}

TEST(Cancel, StoppedRenderReportsFalseAndKeepsWholeSamples) {
  const int w = 64, h = 48;
  PathTracer tracer(closedRoomScene(w, h, true));
  DifferentialBuffers b(w, h);
  CancelToken token;
  token.cancel();
  EXPECT_FALSE(tracer.render(b, 0, 4, 1, 0, &token));
  for (int n : b.samples) EXPECT_TRUE(n == 0 || n == 4);
}

// A ceiling light touching the back wall: the wall just below it gets light from a large solid
// angle at tiny distances. Solid-angle sampling keeps the estimator bounded there: 4 samples
// already come within 8% rms of a 256-sample render (area sampling: 24%).
TEST(Stiff, LightTouchingAWallConvergesFast) {
  const int w = 32, h = 32;
  RenderScene s = test::roomScene(test::testCamera(w, h, 16, 2.3), RoomBox{}, 0.7);
  s.lights.push_back(
      test::rectLight(Vec3(0, 2.6, -3.7), Vec3(0.3, 0, 0), Vec3(0, 0, 0.3), Vec3::Constant(10)));
  TracerOptions opt;
  opt.maxDepth = 1;
  opt.pixelFilterWidth = 0;  // the light's sampling alone: each pixel's 4 samples inside it
  PathTracer tracer(s, opt);
  DifferentialBuffers few(w, h), many(w, h);
  ASSERT_TRUE(tracer.render(few, 0, 4, 6));
  ASSERT_TRUE(tracer.render(many, 4, 256, 6));
  const ImageF a = few.meanWith(), b = many.meanWith();
  double sum2 = 0, worst = 0;
  int n = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (b.at(x, y, 0) < 0.2) continue;  // the lit wall under the light, not the dark ceiling
      const double rel = a.at(x, y, 0) / b.at(x, y, 0) - 1;
      sum2 += rel * rel, worst = std::max(worst, std::abs(rel)), ++n;
    }
  ASSERT_GT(n, 100);
  std::printf("[ stiff ] wall under a touching light, 4 vs 256 spp: %d px, rms rel %.4f, worst %.4f\n",
              n, std::sqrt(sum2 / n), worst);
  EXPECT_LT(std::sqrt(sum2 / n), 0.12);  // area sampling: 0.24 here
}

// Stiff inputs: a light lying on the floor, a light touching the floor edge-on, a 1e6-radiance
// light, a needle-thin triangle, a degenerate light and a NaN radiance. All finite.
TEST(Stiff, ExtremeInputsStayFinite) {
  const int w = 40, h = 30;
  RenderScene s = test::roomScene(test::testCamera(w, h, 70, 1.3, -15), RoomBox{}, 0.7);
  s.lights.push_back(
      test::rectLight(Vec3(0.5, 0.0, -2), Vec3(0, 0, 0.3), Vec3(0.3, 0, 0), Vec3::Constant(2)));
  s.lights.push_back(
      test::rectLight(Vec3(-0.5, 0.3, -2.5), Vec3(0, 0.3, 0), Vec3(0, 0, 0.3), Vec3::Constant(2)));
  s.lights.push_back(
      test::rectLight(Vec3(0, 2.6, -1.5), Vec3(0.05, 0, 0), Vec3(0, 0, 0.05), Vec3::Constant(1e6)));
  s.lights.push_back(test::rectLight(Vec3(0, 1, -1), Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3::Constant(1)));
  s.lights.push_back(test::rectLight(Vec3(1, 1, -1), Vec3(0.1, 0, 0), Vec3(0, 0.1, 0),
                                     Vec3::Constant(std::numeric_limits<double>::quiet_NaN())));
  auto needle = std::make_shared<TriangleMesh>();
  needle->positions = {Vec3f(0, 0, 0), Vec3f(1e-7f, 0, 0), Vec3f(0, 2, 0),
                       Vec3f(std::numeric_limits<float>::quiet_NaN(), 0, 0)};
  needle->triangles = {{0, 1, 2}, {0, 3, 2}, {0, 1, 7}};  // the last two unusable: ignored
  for (auto kind : {Material::Kind::Diffuse, Material::Kind::Glass, Material::Kind::Glossy}) {
    InsertedObject o;
    o.meshObject = needle;
    o.worldFromObject = test::translation(Vec3(0.2 * int(kind), 0.0, -2.0));
    o.material = mat(kind, 0.9, 0.01);
    s.objects.push_back(o);
  }
  InsertedObject glossy;
  glossy.meshObject = test::sphereMesh(0.3, 8, 16);
  glossy.worldFromObject = test::translation(Vec3(0.5, 0.3, -2.0));  // resting on the floor light
  glossy.material = mat(Material::Kind::Glossy, 0.5, 0.0);
  s.objects.push_back(glossy);
  PathTracer tracer(s);
  DifferentialBuffers b(w, h);
  ASSERT_TRUE(tracer.render(b, 0, 16, 4));
  EXPECT_TRUE(test::allFinite(b.sumWith));
  EXPECT_TRUE(test::allFinite(b.sumWithout));
  EXPECT_TRUE(test::allFinite(b.sumDiffSq));
  EXPECT_TRUE(test::allFinite(b.meanWith()));
  std::printf("[ stiff ] non-finite samples dropped: %llu of %d\n",
              (unsigned long long)tracer.stats().nonFiniteSamples, w * h * 16);
  EXPECT_EQ(tracer.stats().nonFiniteSamples, 0u);
  double total = 0;
  for (float v : b.sumWith.data) total += v;
  EXPECT_GT(total, 0.0);
}

// The projected albedo: visible points take their pixel, hidden or out-of-frame points the
// surface mean, unknown ids a neutral grey.
TEST(ProjectedAlbedo, LookupFollowsFirstSurfaces) {
  const int w = 32, h = 24;
  ProjectedAlbedo pa;
  pa.camera = test::testCamera(w, h, 60);
  pa.albedo = ImageF(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) pa.albedo.setRgb(x, y, Vec3(x / 64.0, y / 64.0, 0.25));
  const SceneGeometry room = test::boxRoom();
  pa.surfaceMean.assign(room.surfaces.size(), Vec3(0.1, 0.2, 0.3));
  pa.computeFirstSurfaces(room);
  ASSERT_EQ(pa.firstSurfacePerPixel.size(), size_t(w * h));
  // Centre pixel sees the back wall (id 4).
  EXPECT_EQ(pa.firstSurfacePerPixel[size_t(h / 2) * w + w / 2], 4);
  const Ray r = pa.camera.rayThroughPixel(Vec2(20.5, 10.5));
  const Vec3 onBack = r.at((-4.0 - r.origin.z()) / r.direction.z());
  EXPECT_TRUE(pa.lookup(4, onBack).isApprox(Vec3(20 / 64.0, 10 / 64.0, 0.25), 1e-6));
  // The same point claimed by the floor (id 0): that pixel's first surface is not the floor.
  EXPECT_TRUE(pa.lookup(0, onBack).isApprox(Vec3(0.1, 0.2, 0.3)));
  // Behind the camera: the mean; an unknown id: grey.
  EXPECT_TRUE(pa.lookup(5, Vec3(0, 1.3, 0.5)).isApprox(Vec3(0.1, 0.2, 0.3)));
  EXPECT_TRUE(pa.lookup(42, onBack).isApprox(Vec3(0.5, 0.5, 0.5)));
  EXPECT_TRUE(pa.lookup(-1, onBack).isApprox(Vec3(0.5, 0.5, 0.5)));
}

// The point of correlated rendering: at equal samples, the error of with - without is far
// below that of two independent renders (which are noisy everywhere, not only near the object).
TEST(Differential, CorrelatedBeatsIndependentRenders) {
  const int w = 32, h = 24, spp = 16;
  const RenderScene scene = closedRoomScene(w, h, true);
  RenderScene empty = scene;
  empty.objects.clear();
  PathTracer tracer(scene), emptyTracer(empty);
  DifferentialBuffers ref(w, h);
  ASSERT_TRUE(tracer.render(ref, 1000, 256, 99));  // reference: other samples, 16x as many
  auto diffOf = [](const ImageF& a, const ImageF& b) {
    ImageF d = a;
    for (size_t i = 0; i < d.data.size(); ++i) d.data[i] -= b.data[i];
    return d;
  };
  const ImageF refDiff = diffOf(ref.meanWith(), ref.meanWithout());
  auto rmse = [&](const ImageF& d) {
    double s = 0;
    for (size_t i = 0; i < d.data.size(); ++i)
      s += double(d.data[i] - refDiff.data[i]) * (d.data[i] - refDiff.data[i]);
    return std::sqrt(s / d.data.size());
  };
  DifferentialBuffers corr(w, h), withOnly(w, h), withoutOnly(w, h);
  const uint64_t r0 = tracer.stats().rays;
  ASSERT_TRUE(tracer.render(corr, 0, spp, 1));
  const uint64_t r1 = tracer.stats().rays;
  ASSERT_TRUE(tracer.render(withOnly, 0, spp, 2));
  const uint64_t r2 = tracer.stats().rays;
  ASSERT_TRUE(emptyTracer.render(withoutOnly, 0, spp, 3));
  const double raysCorr = double(r1 - r0), raysIndep = double(r2 - r1 + emptyTracer.stats().rays);
  const double eCorr = rmse(diffOf(corr.meanWith(), corr.meanWithout()));
  const double eIndep = rmse(diffOf(withOnly.meanWith(), withoutOnly.meanWith()));
  // At equal cost (rays as the cost), error goes as 1 / sqrt(cost).
  const double equalCost = eIndep / eCorr * std::sqrt(raysIndep / raysCorr);
  std::printf(
      "[ differential ] RMSE of with-without at %d spp: correlated %.4f, independent %.4f (%.1fx at "
      "equal samples, %.1fx at equal rays)\n",
      spp, eCorr, eIndep, eIndep / eCorr, equalCost);
  EXPECT_GT(equalCost, 3.0);
}

// Throughput figure (printed, not asserted): paths and rays per second on this machine.
TEST(Performance, PrintsPathRate) {
  const int w = 160, h = 120;
  PathTracer tracer(closedRoomScene(w, h, true));
  DifferentialBuffers b(w, h);
  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_TRUE(tracer.render(b, 0, 4, 1));
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double rays = double(tracer.stats().rays);
  std::printf(
      "[ perf ] %dx%d x 4 spp differential (sphere in a lit room, maxDepth 8, all cores): "
      "%.3f s, %.2f M samples/s, %.1f rays/sample, %.2f M rays/s\n",
      w, h, s, w * h * 4 / s * 1e-6, rays / (w * h * 4), rays / s * 1e-6);
  EXPECT_GT(rays, double(w * h * 4));
}

}  // namespace
}  // namespace inlay
