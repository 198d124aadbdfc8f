// The lighting stage on rooms with known answers: an empty room rendered by our own path tracer
// from known albedos and a known light must give them back; stiff photos (black, saturated,
// non-finite) give finite output or a clear error.
#include "inlay/lighting/estimate.h"
#include "inlay/lighting/refine.h"
#include "inlay/lighting/shaft.h"
#include "inlay/lighting/sun_ratio.h"
#include "inlay/modeling/response.h"
#include "inlay/render/path_tracer.h"
#include "test_support.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <cstdio>
#include <random>
#include <regex>

namespace inlay {
namespace {

struct SyntheticRoom {
  Camera camera;
  SceneGeometry geometry;
  std::vector<Vec3> albedo;  // per surface
  AreaLight light;
  std::vector<Vec2> lightOutlinePx;
  ImageF photo;
};

// A 5 x 6 m room, 2.7 m high, camera 1.5 m up looking slightly down; a 0.8 x 0.8 m ceiling
// panel of radiance `radiance`; rendered with `spp` samples (no objects).
// The room, camera and albedos (no light, no photo).
// `width`: the photo's width in pixels (4:3; the field of view of a 160-pixel one).
SyntheticRoom emptyRoom(int width = 160) {
  SyntheticRoom r;
  r.camera = levelCamera(width, width * 3 / 4, 130.0 * width / 160, 1.5);
  r.camera.worldFromCamera = Eigen::AngleAxisd(-8 * M_PI / 180, Vec3::UnitX()).toRotationMatrix();
  RoomBox box;
  box.xLeftM = -2.5, box.xRightM = 2.5, box.zBackM = -5.5, box.zRearM = 0.5, box.ceilingM = 2.7;
  r.geometry = buildSceneGeometry(box, {});
  r.albedo = {Vec3(0.35, 0.3, 0.25), Vec3(0.8, 0.8, 0.8),  Vec3(0.6, 0.55, 0.5),
              Vec3(0.5, 0.6, 0.55),  Vec3(0.7, 0.65, 0.6), Vec3(0.6, 0.6, 0.6)};
  return r;
}

// The room's render with `lights` and `suns` (no objects, uniform albedo per surface).
ImageF renderRoom(const SyntheticRoom& r, const std::vector<AreaLight>& lights,
                  const std::vector<SunLight>& suns, int spp) {
  RenderScene scene;
  scene.camera = r.camera;
  scene.room = r.geometry;
  scene.roomAlbedo.camera = r.camera;
  scene.roomAlbedo.surfaceMean = r.albedo;  // no albedo image: every surface is uniform
  scene.lights = lights;
  scene.suns = suns;
  PathTracer tracer(scene);
  DifferentialBuffers buf(r.camera.widthPx, r.camera.heightPx);
  EXPECT_TRUE(tracer.render(buf, 0, spp, 3));
  return buf.meanWithout();
}

// A 0.8 x 0.8 m ceiling panel of radiance `radiance` facing down, 1 mm under emptyRoom's ceiling.
AreaLight ceilingPanel(const Vec3& radiance) {
  AreaLight l;
  const double y = 2.699;
  l.cornersWorld = {Vec3(-0.4, y, -3.4), Vec3(-0.4, y, -2.6), Vec3(0.4, y, -2.6), Vec3(0.4, y, -3.4)};
  if (l.normal().y() > 0) std::swap(l.cornersWorld[1], l.cornersWorld[3]);
  l.radiance = radiance;
  return l;
}

SyntheticRoom makeRoom(const Vec3& radiance, int spp, int width = 160) {
  SyntheticRoom r = emptyRoom(width);
  r.light = ceilingPanel(radiance);
  for (const Vec3& c : r.light.cornersWorld) r.lightOutlinePx.push_back(*r.camera.project(c));
  r.photo = renderRoom(r, {r.light}, {}, spp);
  return r;
}

// The light's outline's bounding box grown by `growPx` pixels (negative: shrunk).
ImageF lightMaskOf(const SyntheticRoom& r, int growPx = 2) {
  ImageF m(r.photo.width, r.photo.height, 1, 0.f);
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
  for (const Vec2& p : r.lightOutlinePx)
    x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()),
    y1 = std::max(y1, p.y());
  for (int y = std::max(0, int(y0) - growPx); y <= std::min(r.photo.height - 1, int(y1) + growPx); ++y)
    for (int x = std::max(0, int(x0) - growPx); x <= std::min(r.photo.width - 1, int(x1) + growPx); ++x)
      m.at(x, y) = 1;
  return m;
}

// The exposure that clips a tenth of the room at 1 (the green channel's 90th percentile outside
// the light's mask brought to 1).
float exposureClippingATenth(const SyntheticRoom& r, const ImageF& mask) {
  std::vector<float> room;
  for (int y = 0; y < r.photo.height; ++y)
    for (int x = 0; x < r.photo.width; ++x)
      if (mask.at(x, y) < 0.5f) room.push_back(r.photo.at(x, y, 1));
  std::nth_element(room.begin(), room.begin() + long(room.size() * 9 / 10), room.end());
  return 1.f / room[room.size() * 9 / 10];
}

TEST(Lighting, RecoversLightAndAlbedoOfARenderedRoom) {
  const Vec3 trueRadiance(6.0, 5.0, 4.0);
  const SyntheticRoom r = makeRoom(trueRadiance, 64);
  auto light = lightFromOutline(r.camera, r.geometry, r.lightOutlinePx, "lights[0].points");
  ASSERT_TRUE(light.ok()) << light.error().message();
  EXPECT_LT((light->centre() - r.light.centre()).norm(), 0.02);
  EXPECT_NEAR(light->area(), r.light.area(), 0.02 * r.light.area());
  EXPECT_GT(light->normal().dot(Vec3(0, -1, 0)), 0.999);
  LightingOptions opt;
  opt.gatherSamples = 64;
  opt.gatherStride = 2;
  const auto est =
      estimateLighting(r.photo, r.camera, r.geometry, {*light}, {true}, lightMaskOf(r), {}, opt);
  ASSERT_TRUE(est.ok()) << est.error().message();
  // The per-surface fit is ill-conditioned along (albedo / k, light * k) where E and Gamma have
  // nearly the same shape (about 10% here); the decomposition and light refinement tighten it.
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(est->lights[0].radiance[c] / trueRadiance[c], 1.0, 0.2) << "channel " << c;
  }
  // Albedo per visible surface.
  for (size_t s = 0; s < r.albedo.size(); ++s) {
    std::printf("%-12s albedo %.3f %.3f %.3f  true %.3f %.3f %.3f\n",
                r.geometry.surfaces[s].name.c_str(), est->surfaceMeanAlbedo[s][0],
                est->surfaceMeanAlbedo[s][1], est->surfaceMeanAlbedo[s][2], r.albedo[s][0],
                r.albedo[s][1], r.albedo[s][2]);
    if (r.geometry.surfaces[s].kind == SurfaceKind::WallRear) continue;  // not seen
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(est->surfaceMeanAlbedo[s][c], r.albedo[s][c], 0.08)
          << r.geometry.surfaces[s].name << " channel " << c;
  }
  // Gathering is consistent with the photo: with the TRUE light and albedo, the model
  // rho * (L E + Gamma) reproduces each surface's mean brightness within 3%.
  {
    RoomTracer rt(r.geometry);
    for (int sid : {0, 4, 1}) {
      double sumB = 0, sumE = 0, sumG = 0;
      int n = 0;
      for (int y = 0; y < 120; y += 3)
        for (int x = 0; x < 160; x += 3) {
          const auto h = r.geometry.intersect(r.camera.rayThroughPixel(Vec2(x + 0.5, y + 0.5)));
          if (!h || h->surfaceId != sid) continue;
          sumB += r.photo.at(x, y, 1) / r.albedo[sid][1];
          sumE += trueRadiance[1] * rt.unitLightIrradianceOverPi(r.light,
                                                                 h->pointWorld + 1e-5 * h->normalWorld,
                                                                 h->normalWorld, 64, 1);
          sumG += est->gathered.at(x, y, 1);
          ++n;
        }
      std::printf("surface %d: B/rho %.4f  L*E %.4f  Gamma %.4f  (L*E+Gamma)/(B/rho) %.4f\n", sid,
                  sumB / n, sumE / n, sumG / n, (sumE + sumG) / sumB);
      EXPECT_NEAR((sumE + sumG) / sumB, 1.0, 0.03) << "surface " << sid;
    }
  }
  for (float v : est->albedo.data) ASSERT_TRUE(std::isfinite(v) && v >= 0 && v <= 1);
  for (float v : est->direct.data) ASSERT_TRUE(std::isfinite(v) && v >= 0);
  std::printf("fitted radiance %.3f %.3f %.3f (true 6 5 4), fit rms(log) %.4f, %.2f s\n",
              est->lights[0].radiance[0], est->lights[0].radiance[1], est->lights[0].radiance[2],
              est->fitRmsLog, est->seconds);
}

// No light outlined and no sun (a photo opened before any light is marked, as in the studio): the
// unseen patches' gather reads each ray's lights' share from an empty list. The estimate is
// finite, and the empty list is never indexed (UBSan: reference binding to a null pointer).
TEST(Lighting, NoLightsAndNoSunsGatherTheUnseenPatchesSafely) {
  const SyntheticRoom r = makeRoom(Vec3(6.0, 5.0, 4.0), 16);
  LightingOptions opt;
  opt.gatherSamples = 16;
  opt.gatherStride = 4;
  const ImageF noMask(r.photo.width, r.photo.height, 1, 0.f);
  const auto est = estimateLighting(r.photo, r.camera, r.geometry, {}, {}, noMask, {}, opt);
  ASSERT_TRUE(est.ok()) << est.error().message();
  EXPECT_TRUE(est->lights.empty());
  for (float v : est->albedo.data) ASSERT_TRUE(std::isfinite(v) && v >= 0 && v <= 1);
  for (float v : est->gathered.data) ASSERT_TRUE(std::isfinite(v) && v >= 0);
}

// Over-exposed: a tenth of the room clips at 1 (a bright wall by the lamp). The clipped pixels
// are only a lower bound of their radiance, so the light they send gets a fitted extra gain
// (never below 1 overall, bounded by what was clipped) and the albedo stays right.
TEST(Lighting, ClippedPixelsSendMoreLightThanTheyShow) {
  const SyntheticRoom r = makeRoom(Vec3(6.0, 5.0, 4.0), 64);
  const ImageF mask = lightMaskOf(r);
  const float exposure = exposureClippingATenth(r, mask);
  ImageF photo = r.photo;
  double excess = 0, clipped = 0;  // the clipped pixels' true radiance over what they show
  for (float& v : photo.data) {
    if (v * exposure >= 1.f) excess += v * exposure, clipped += 1;
    v = std::min(1.f, v * exposure);
  }
  excess = excess / std::max(1.0, clipped) - 1;
  auto light = lightFromOutline(r.camera, r.geometry, r.lightOutlinePx, "lights[0].points");
  ASSERT_TRUE(light.ok());
  LightingOptions opt;
  opt.gatherSamples = 64;
  opt.gatherStride = 2;
  const auto est = estimateLighting(photo, r.camera, r.geometry, {*light}, {true}, mask, {}, opt);
  ASSERT_TRUE(est.ok()) << est.error().message();
  std::printf("clipped gain %.3f %.3f %.3f, true mean excess %.3f\n", est->clippedGain[0],
              est->clippedGain[1], est->clippedGain[2], excess);
  // The total factor 1 + gain is at least 1 and not beyond the largest plausible excess.
  for (int c = 0; c < 3; ++c) {
    EXPECT_GE(est->clippedGain[c], -1e-9);
    EXPECT_LT(est->clippedGain[c], 4 * excess + 0.1);
  }
  for (size_t s = 0; s < r.albedo.size(); ++s) {
    if (r.geometry.surfaces[s].kind == SurfaceKind::WallRear) continue;  // not seen
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(est->surfaceMeanAlbedo[s][c], r.albedo[s][c], 0.08)
          << r.geometry.surfaces[s].name << " channel " << c;
  }
  for (float v : est->albedo.data) ASSERT_TRUE(std::isfinite(v) && v >= 0 && v <= 1);
}

// A sun room: a window in the back wall whose sky (radiance 2.5-3.5) clips at 1, and the sun
// through it on the floor, a patch that clips too (about 1.1-1.4) with a soft edge that does
// not. Neither is given as a light: the window's light comes from its clipped pixels times the
// fitted gain, which must be the sky's (radiance - 1), not one shared with the sunlit patch's
// far smaller excess; then the floor's gathered light, and so its albedo, come out right.
// A window in the back wall (x -0.8..0.8, y 1.0..2.2), or in the left wall (z -3.6..-2.0, the
// same heights: t04's and t10's side), and the sun through it onto the floor.
struct SunWindow {
  AreaLight window;
  SunLight sun;
};

// `revealDepth` > 0: the window is a hole through a wall that thick (its reveal), and the beam is
// what passes both its inner and its outer opening (t04's and t10's windows, 0.2 m); the sky
// light stays the inner opening.
SunWindow sunThroughWindow(const SyntheticRoom& r, const Vec3& sunStrength, bool leftWall = false,
                           double revealDepth = 0) {
  // The window spans u0..u1 along the wall (x on the back wall, z on the left) and y0..y1.
  const double u0 = leftWall ? -3.6 : -0.8, u1 = leftWall ? -2.0 : 0.8, y0 = 1.0, y1 = 2.2;
  const int axis = leftWall ? 0 : 2, along = leftWall ? 2 : 0;  // the wall's normal, along it
  const double wall = leftWall ? r.geometry.box.xLeftM + 1e-3 : r.geometry.box.zBackM + 1e-3;
  auto at = [&](double u, double y) {
    Vec3 p;
    p[axis] = wall, p[along] = u, p.y() = y;
    return p;
  };
  SunWindow out;
  AreaLight& window = out.window;
  window.cornersWorld = {at(u0, y0), at(u1, y0), at(u1, y1), at(u0, y1)};
  if (window.normal()[axis] < 0) std::swap(window.cornersWorld[1], window.cornersWorld[3]);
  window.radiance = Vec3(2.5, 3.0, 3.5);
  SunLight& sun = out.sun;
  sun.travelDirection = (leftWall ? Vec3(1.2, -1.0, 0.2) : Vec3(0.2, -1.0, 1.2)).normalized();
  sun.irradianceOverPi = sunStrength;
  sun.receiverPlane = Vec4(0, 1, 0, 0);
  sun.camera = r.camera;
  // The beam is the window's shape carried along the light onto the floor, 0.1 m soft at its
  // edge (the lit mask lives on the photo's pixels, read where the beam meets the floor).
  sun.litMask = ImageF(r.camera.widthPx, r.camera.heightPx, 1, 0.f);
  for (int y = 0; y < r.camera.heightPx; ++y)
    for (int x = 0; x < r.camera.widthPx; ++x) {
      const Ray ray = r.camera.rayThroughPixel(Vec2(x + 0.5, y + 0.5));
      if (!(ray.direction.y() < 0)) continue;
      const Vec3 q = ray.origin - ray.origin.y() / ray.direction.y() * ray.direction;
      auto insideAt = [&](double plane) {
        const Vec3 w = q - (q[axis] - plane) / sun.travelDirection[axis] * sun.travelDirection;
        return std::min({w[along] - u0, u1 - w[along], w.y() - y0, y1 - w.y()});
      };
      const double inside = std::min(insideAt(wall), insideAt(wall - revealDepth));
      sun.litMask.at(x, y) = float(std::clamp(inside / 0.1 + 0.5, 0.0, 1.0));
    }
  return out;
}

// The lighting estimate of a room lit by `sun` alone (through its window): `samples` gather
// rays a pixel on every second pixel, two threads.
Expected<LightingEstimate> estimateSunRoom(const ImageF& photo, const SyntheticRoom& r,
                                           const SunLight& sun, int samples) {
  LightingOptions opt;
  opt.gatherSunBounceUnseen = true;  // the bounce fit's term (computed only for it)
  opt.gatherSamples = samples;
  opt.gatherStride = 2;
  opt.threads = 2;
  return estimateLighting(photo, r.camera, r.geometry, {}, {}, ImageF(), {sun}, opt);
}

TEST(Lighting, ClippedSunPatchDoesNotShareTheWindowsGain) {
  SyntheticRoom r = emptyRoom();
  const SunWindow sw = sunThroughWindow(r, Vec3(6, 6, 6));
  const AreaLight& window = sw.window;
  const SunLight& sun = sw.sun;
  r.photo = renderRoom(r, {window}, {sun}, 32);
  ImageF photo = r.photo;
  for (float& v : photo.data) v = std::min(v, 1.f);

  const int floor = 0;
  ASSERT_EQ(r.geometry.surfaces[floor].kind, SurfaceKind::Floor);
  // The window is small seen from the floor: with 64 rays its gathered light is too noisy for
  // the robust fit to tell its gain (about 0.4 of the truth, with or without the fix).
  const auto est = estimateSunRoom(photo, r, sun, 256);
  ASSERT_TRUE(est.ok()) << est.error().message();
  // The floor's light-fit albedo away from the patch (no sun there, nothing clipped).
  std::vector<float> floorAlbedo[3];
  int patchClipped = 0;
  for (int y = 0; y < photo.height; ++y)
    for (int x = 0; x < photo.width; ++x) {
      const size_t idx = size_t(y) * photo.width + x;
      if (est->firstSurfacePerPixel[idx] != floor) continue;
      if (sun.litMask.at(x, y) > 0.f) {
        patchClipped += photo.rgb(x, y).maxCoeff() >= 1.f;
        continue;
      }
      for (int c = 0; c < 3; ++c) floorAlbedo[c].push_back(est->physicalAlbedo.at(x, y, c));
    }
  ASSERT_GT(patchClipped, 200) << "the sunlit patch must clip";
  const Vec3 trueGain = window.radiance - Vec3(1, 1, 1);
  for (int c = 0; c < 3; ++c) {
    auto& v = floorAlbedo[c];
    ASSERT_GT(v.size(), 500u);
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    const double median = v[v.size() / 2];
    std::printf(
        "channel %d: clipped gain %.3f (true %.3f), floor albedo %.3f / surface %.3f "
        "(true %.3f), sun %.3f (true %.3f)\n",
        c, est->clippedGain[c], trueGain[c], median, est->surfaceMeanAlbedo[floor][c],
        r.albedo[floor][c], est->suns[0].irradianceOverPi[c], sun.irradianceOverPi[c]);
    // With the fix the gain is 0.73-0.84 of the truth (the gather still undershoots the small
    // window); one gain shared with the patch was 0.50-0.58 of it.
    EXPECT_GT(est->clippedGain[c] / trueGain[c], 0.65) << "channel " << c;
    EXPECT_LT(est->clippedGain[c] / trueGain[c], 1.25) << "channel " << c;
    // The floor away from the patch: the patch's predicted radiance must not overshoot there.
    EXPECT_NEAR(median / r.albedo[floor][c], 1.0, 0.12) << "channel " << c;
    EXPECT_NEAR(est->surfaceMeanAlbedo[floor][c] / r.albedo[floor][c], 1.0, 0.12) << "channel " << c;
  }
  std::printf("%d clipped patch pixels, %.2f s\n", patchClipped, est->seconds);
}

// d4's case: the sun is the room's only light and its floor patch clips far above the clip
// level (up to 2.3 times), so the patch says only "at least this bright"; the walls and ceiling,
// lit by the light the patch bounces, must set the sun's strength (the patch's radiance is the
// floor's albedo times the sun's irradiance: the fit gathers it per unit sun and albedo).
// Measured: 5.94 / 4.94 / 3.73 against the truth's 5 / 4.6 / 4 (mean error 11%); before the
// bounce was tied to the sun (the patch's clipped value, then the first pass's prediction, in
// the gathered light) 6.92 / 5.34 / 4.03 (+38% in red, mean 18%).
TEST(Lighting, AClippedSunPatchsBounceTellsTheSunsStrength) {
  SyntheticRoom r = emptyRoom();
  r.albedo[0] = Vec3(0.6, 0.55, 0.5);  // a bright floor
  const Vec3 truth(5, 4.6, 4);
  const SunLight sun = sunThroughWindow(r, truth).sun;
  r.photo = renderRoom(r, {}, {sun}, 32);
  ImageF photo = r.photo;
  int farClipped = 0;
  for (int y = 0; y < photo.height; ++y)
    for (int x = 0; x < photo.width; ++x) farClipped += photo.rgb(x, y).maxCoeff() >= 1.5f;
  for (float& v : photo.data) v = std::min(v, 1.f);
  ASSERT_GT(farClipped, 200) << "the sunlit patch must reach 1.5 times the clip level";
  const auto est = estimateSunRoom(photo, r, sun, 128);
  ASSERT_TRUE(est.ok()) << est.error().message();
  // The patch's bounce at the fitted strength is part of the gathered light, and given apart.
  ASSERT_EQ(est->sunBounce.size(), 1u);
  double meanError = 0;
  for (int c = 0; c < 3; ++c) {
    const double fitted = est->suns[0].irradianceOverPi[c];
    std::printf("channel %d: sun fitted %.3f (true %.3f)\n", c, fitted, truth[c]);
    EXPECT_NEAR(fitted / truth[c], 1.0, 0.25) << "channel " << c;
    meanError += std::abs(fitted / truth[c] - 1) / 3;
  }
  EXPECT_LT(meanError, 0.14);
  // For the render's bounces the clipped patch takes the model's radiance: nearer the unclipped
  // truth than the clip level; every other pixel is the photo's.
  const ImageF bounce = radianceForBounces(photo, r.camera, r.geometry, *est);
  double errPhoto = 0, errModel = 0;
  int patch = 0, changedElsewhere = 0;
  for (int y = 0; y < photo.height; ++y)
    for (int x = 0; x < photo.width; ++x) {
      const bool clipped = photo.rgb(x, y).maxCoeff() >= 0.98f;
      if (!clipped || !(sun.litMask.at(x, y) > 0.f))
        changedElsewhere += bounce.rgb(x, y) != photo.rgb(x, y);
      if (!clipped || !(sun.litMask.at(x, y) > 0.5f)) continue;
      ++patch;
      errPhoto += (photo.rgb(x, y) - r.photo.rgb(x, y)).norm();
      errModel += (bounce.rgb(x, y) - r.photo.rgb(x, y)).norm();
    }
  std::printf("clipped patch: mean error of its radiance %.3f as clipped, %.3f modelled\n",
              errPhoto / patch, errModel / patch);
  EXPECT_LT(errModel, 0.4 * errPhoto);
  EXPECT_EQ(changedElsewhere, 0);
  // The refinement keeps the strength by default; asked to solve it (against D, with the bounce
  // put back) it stays finite and near (here 6.07 / 5.72 / 5.03: the decomposition's albedo is
  // low in this room).
  LightRefineOptions ro;
  ro.sunBounce = est->sunBounce;
  const auto kept = refineLights(r.camera, r.geometry, est->albedo, est->direct, est->decomposeValid, {},
                                 {}, est->suns, ro);
  ASSERT_TRUE(kept.ok()) << kept.error().message();
  EXPECT_EQ(kept->suns[0].irradianceOverPi, est->suns[0].irradianceOverPi);
  ro.refineSuns = true;
  const auto solved = refineLights(r.camera, r.geometry, est->albedo, est->direct, est->decomposeValid,
                                   {}, {}, est->suns, ro);
  ASSERT_TRUE(solved.ok()) << solved.error().message();
  ASSERT_TRUE(solved->suns[0].irradianceOverPi.allFinite());
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(solved->suns[0].irradianceOverPi[c] / truth[c], 1.0, 0.4) << c;
  // A bounce image of the wrong size is named.
  ro.sunBounce = {ImageF(3, 3, 3, 0.f)};
  const auto bad = refineLights(r.camera, r.geometry, est->albedo, est->direct, est->decomposeValid, {},
                                {}, est->suns, ro);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message().find("suns[0]"), std::string::npos);
}

// The opening a sun's beam came through, carried back from its lit patch (shaft.h): the window
// of sunThroughWindow, on the back wall, to within its mask's soft edge. Looking down so far
// that the back wall's window is out of view, the camera sees none of the opening; at the room's
// own camera it sees most of it (the photo then shows the window).
TEST(Lighting, TheBeamCarriedBackFindsItsWindow) {
  SyntheticRoom r = emptyRoom();
  r.camera.worldFromCamera = Eigen::AngleAxisd(-40 * M_PI / 180, Vec3::UnitX()).toRotationMatrix();
  const SunWindow sw = sunThroughWindow(r, Vec3(5, 4.6, 4));
  const auto opening = openingOfBeam(sw.sun, r.camera, r.geometry);
  ASSERT_TRUE(opening.has_value());
  EXPECT_EQ(r.geometry.surfaces[size_t(opening->surface)].kind, SurfaceKind::WallBack);
  Vec3 lo = Vec3::Constant(1e9), hi = Vec3::Constant(-1e9), wlo = lo, whi = hi;
  for (int k = 0; k < 4; ++k) {
    lo = lo.cwiseMin(opening->light.cornersWorld[size_t(k)]);
    hi = hi.cwiseMax(opening->light.cornersWorld[size_t(k)]);
    wlo = wlo.cwiseMin(sw.window.cornersWorld[size_t(k)]);
    whi = whi.cwiseMax(sw.window.cornersWorld[size_t(k)]);
  }
  std::printf(
      "opening x %.3f..%.3f y %.3f..%.3f z %.3f (window x %.3f..%.3f y %.3f..%.3f z %.3f), "
      "%d pixels, seen %.2f\n",
      lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), wlo.x(), whi.x(), wlo.y(), whi.y(), wlo.z(),
      opening->pixels, opening->visibleShare);
  for (int a : {0, 1}) {
    EXPECT_NEAR(lo[a], wlo[a], 0.08) << "axis " << a;
    EXPECT_NEAR(hi[a], whi[a], 0.08) << "axis " << a;
  }
  EXPECT_NEAR(lo.z(), wlo.z(), 0.01);
  EXPECT_GT(opening->light.normal().z(), 0.99) << "it faces into the room";
  EXPECT_NEAR(opening->widthM, hi.x() - lo.x(), 1e-9);
  EXPECT_LT(opening->visibleShare, 0.1);
  // The room's camera sees the back wall's window.
  SyntheticRoom seen = emptyRoom();
  const auto inView =
      openingOfBeam(sunThroughWindow(seen, Vec3(5, 4.6, 4)).sun, seen.camera, seen.geometry);
  ASSERT_TRUE(inView.has_value());
  EXPECT_GT(inView->visibleShare, 0.5);
  // No lit pixel: no opening.
  SunLight dark = sw.sun;
  for (float& v : dark.litMask.data) v = 0.f;
  EXPECT_FALSE(openingOfBeam(dark, r.camera, r.geometry).has_value());
}

// The bounds of a rectangle's corners.
std::pair<Vec3, Vec3> boundsOf(const AreaLight& l) {
  Vec3 lo = Vec3::Constant(1e9), hi = Vec3::Constant(-1e9);
  for (const Vec3& c : l.cornersWorld) lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
  return {lo, hi};
}

// A window through a wall 0.2 m thick (t04's, t10's and d4's): the beam is what passes both its
// inner and outer opening, so carried back it is the window less its top 0.17 m (and 0.03 m on
// one side), the part whose light the reveal takes. openingOfBeam with the reveal's depth widens
// it back to the window (within the mask's soft edge, 0.08 m), on either wall; without it the
// top is short. Stiff depths stay finite and inside the room: NaN or negative is no reveal, a
// depth of 1e6 (a beam grazing the wall) grows each side by at most the section's extent.
TEST(Lighting, TheOpeningOfABeamThroughAThickWallIsTheWholeWindow) {
  SyntheticRoom r = emptyRoom();
  r.camera.worldFromCamera = Eigen::AngleAxisd(-40 * M_PI / 180, Vec3::UnitX()).toRotationMatrix();
  for (const bool leftWall : {false, true}) {
    SCOPED_TRACE(leftWall ? "left wall" : "back wall");
    const SunWindow sw = sunThroughWindow(r, Vec3(5, 4.6, 4), leftWall, 0.2);
    const auto beam = openingOfBeam(sw.sun, r.camera, r.geometry);
    const auto widened = openingOfBeam(sw.sun, r.camera, r.geometry, 50, 0.2);
    ASSERT_TRUE(beam.has_value() && widened.has_value());
    const auto [wlo, whi] = boundsOf(sw.window);
    const auto [blo, bhi] = boundsOf(beam->light);
    const auto [lo, hi] = boundsOf(widened->light);
    std::printf("%s wall: window y %.3f..%.3f, beam %.3f..%.3f, widened %.3f..%.3f (%.2f x %.2f m)\n",
                leftWall ? "left" : "back", wlo.y(), whi.y(), blo.y(), bhi.y(), lo.y(), hi.y(),
                widened->widthM, widened->heightM);
    EXPECT_LT(bhi.y(), whi.y() - 0.1);  // the beam alone: the window's top is missing
    for (int a : {0, 1, 2}) {
      EXPECT_NEAR(lo[a], wlo[a], 0.08) << "axis " << a;
      EXPECT_NEAR(hi[a], whi[a], 0.08) << "axis " << a;
    }
    EXPECT_EQ(widened->surface, beam->surface);
    EXPECT_GT(widened->light.normal().dot(beam->light.normal()), 0.99);  // still into the room
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const double noReveal : {nan, -1.0, 0.0}) {
      const auto same = openingOfBeam(sw.sun, r.camera, r.geometry, 50, noReveal);
      ASSERT_TRUE(same.has_value());
      EXPECT_EQ(same->light.cornersWorld, beam->light.cornersWorld) << noReveal;
    }
    const auto deep = openingOfBeam(sw.sun, r.camera, r.geometry, 50, 1e6);
    ASSERT_TRUE(deep.has_value());
    const RoomBox& box = r.geometry.box;
    for (const Vec3& c : deep->light.cornersWorld) {
      EXPECT_TRUE(c.allFinite());
      EXPECT_GE(c.y(), -1e-9);
      EXPECT_LE(c.y(), box.ceilingM + 1e-9);
      EXPECT_GE(c.x(), std::min(box.xLeftM, box.xRightM) - 1e-9);
      EXPECT_LE(c.x(), std::max(box.xLeftM, box.xRightM) + 1e-9);
    }
    EXPECT_LE(deep->heightM, 2 * beam->heightM + 1e-9);
    EXPECT_LE(deep->widthM, 2 * beam->widthM + 1e-9);
  }
}

// t04's and t10's case: the sun comes through a window the photo does not show, and that
// window lets the sky in too, a large share of the light on everything the camera sees. No light
// marks it: the fit lit the room with the gathered light and the sun alone and made up the
// difference with a bright albedo. The opening the beam came through (openingOfBeam), fitted as
// a light, gives the sky its light back.
// emptyRoom looking 32 degrees down: a window on its back wall is out of view.
SyntheticRoom roomLookingDown() {
  SyntheticRoom r = emptyRoom();
  r.camera.worldFromCamera = Eigen::AngleAxisd(-32 * M_PI / 180, Vec3::UnitX()).toRotationMatrix();
  return r;
}

// `r` rendered with `sw`'s sky and sun (r.photo) and clipped at 1, as a photo has it.
// t04's albedos on the synthetic room (roomLookingDown): walls 0.45, a floor 0.5, a white ceiling
// (0.88) the camera does not see.
SyntheticRoom whiteCeilingSunRoom() {
  SyntheticRoom r = roomLookingDown();
  const Vec3 wall(0.45, 0.45, 0.48);
  r.albedo = {Vec3(0.5, 0.47, 0.45), Vec3(0.88, 0.88, 0.9), wall, wall, wall, wall};
  return r;
}

// 128 gather rays a pixel on every second pixel, two threads.
LightingOptions sunRoomOptions() {
  LightingOptions opt;
  opt.gatherSamples = 128;
  opt.gatherStride = 2;
  opt.threads = 2;
  return opt;
}

ImageF clippedSunPhoto(SyntheticRoom& r, const SunWindow& sw) {
  r.photo = renderRoom(r, {sw.window}, {sw.sun}, 32);
  ImageF photo = r.photo;
  for (float& v : photo.data) v = std::min(v, 1.f);
  return photo;
}

TEST(Lighting, TheSkyOfAWindowOutOfViewLightsTheRoom) {
  SyntheticRoom r = roomLookingDown();
  const SunWindow sw = sunThroughWindow(r, Vec3(5, 4.6, 4));
  const ImageF photo = clippedSunPhoto(r, sw);
  const auto opening = openingOfBeam(sw.sun, r.camera, r.geometry);
  ASSERT_TRUE(opening.has_value());
  ASSERT_LT(opening->visibleShare, 0.5) << "the window must be out of view";
  LightingOptions opt;
  opt.gatherSamples = 128;
  opt.gatherStride = 2;
  opt.threads = 2;
  const auto without = estimateLighting(photo, r.camera, r.geometry, {}, {}, ImageF(), {sw.sun}, opt);
  const auto with =
      estimateLighting(photo, r.camera, r.geometry, {opening->light}, {true}, ImageF(), {sw.sun}, opt);
  ASSERT_TRUE(without.ok()) << without.error().message();
  ASSERT_TRUE(with.ok()) << with.error().message();
  // The albedo of every surface the camera sees, against the truth.
  double errWithout = 0, errWith = 0;
  int n = 0;
  std::vector<int> seen(r.albedo.size(), 0);
  for (int s : with->firstSurfacePerPixel)
    if (s >= 0) ++seen[size_t(s)];
  for (size_t s = 0; s < r.albedo.size(); ++s) {
    if (seen[s] < 200) continue;
    for (int c = 0; c < 3; ++c) {
      const double t = r.albedo[s][c];
      std::printf("surface %zu channel %d: albedo %.3f without the sky, %.3f with it (true %.3f)\n", s,
                  c, without->surfaceMeanAlbedo[s][c], with->surfaceMeanAlbedo[s][c], t);
      errWithout += std::abs(without->surfaceMeanAlbedo[s][c] / t - 1);
      errWith += std::abs(with->surfaceMeanAlbedo[s][c] / t - 1);
      ++n;
    }
  }
  ASSERT_GT(n, 6);
  errWithout /= n, errWith /= n;
  std::printf(
      "mean relative albedo error %.3f without the sky, %.3f with it; sky %.2f %.2f %.2f "
      "(true %.2f %.2f %.2f)\n",
      errWithout, errWith, with->lights[0].radiance.x(), with->lights[0].radiance.y(),
      with->lights[0].radiance.z(), sw.window.radiance.x(), sw.window.radiance.y(),
      sw.window.radiance.z());
  EXPECT_LT(errWith, 0.15);
  EXPECT_LT(errWith, 0.5 * errWithout);
  // Measured: the albedo's mean error 0.32 without the sky, 0.08 with it; the sky 1.33-1.49
  // times the truth and the sun 1.1-1.27 (the gathered light from what the photo shows low to
  // match; the light reaching the room is what the albedo says is right).
  for (int c = 0; c < 3; ++c) {
    std::printf("channel %d: sun %.2f (true %.2f)\n", c, with->suns[0].irradianceOverPi[c],
                sw.sun.irradianceOverPi[c]);
    EXPECT_GT(with->lights[0].radiance[c] / sw.window.radiance[c], 0.6) << "channel " << c;
    EXPECT_LT(with->lights[0].radiance[c] / sw.window.radiance[c], 1.7) << "channel " << c;
  }
}

// d4's case, synthetic: the sun and the sky through a window in view (sunThroughWindow, the sky
// given as no light: its clipped pixels carry it), the patch a flat colour that clips
// everywhere, the photo exposed at 1, 2 and 4 times (the patch 2, 4 and 8 times the clip level).
// The light the patch bounces onto the walls and ceiling, seen unclipped and shaped unlike the
// sky's, tells the strength (sun_ratio.h, sunStrengthFromBounce).
struct BounceCase {
  SyntheticRoom room;
  SunLight sun;  // the true sun, in the linear render's units
  ImageF linear;
};

// The estimate's bounce of its one sun (sun_ratio.h's SunBounceImages).
SunBounceImages bounceOf(const LightingEstimate& est) {
  SunBounceImages b{est.sunBounce.at(0), ImageF(), Vec3::Zero()};
  if (!est.sunBounceUnseen.empty())
    b.unseen = est.sunBounceUnseen[0], b.unseenAt = est.sunBounceUnseenAt[0];
  return b;
}

// `extra`: lights besides the sky's window (none: the sun and the sky alone).
BounceCase sunAndSkyRoom(const std::vector<AreaLight>& extra = {}) {
  BounceCase b;
  b.room = emptyRoom();
  b.room.albedo[0] = Vec3(0.6, 0.55, 0.5);  // a bright floor
  const SunWindow sw = sunThroughWindow(b.room, Vec3(5, 4.6, 4));
  b.sun = sw.sun;
  std::vector<AreaLight> lights = extra;
  lights.push_back(sw.window);
  b.linear = renderRoom(b.room, lights, {b.sun}, 64);
  return b;
}

ImageF exposed(const ImageF& linear, double exposure) {
  ImageF photo = linear;
  for (float& v : photo.data) v = std::min(float(v * exposure), 1.f);
  return photo;
}

TEST(Lighting, TheBounceOfAClippedPatchTellsTheSunsStrength) {
  const BounceCase b = sunAndSkyRoom();
  const SyntheticRoom& r = b.room;
  for (double exposure : {1.0, 2.0, 4.0}) {
    const ImageF photo = exposed(b.linear, exposure);
    const Vec3 truth = exposure * b.sun.irradianceOverPi;
    const auto est = estimateSunRoom(photo, r, b.sun, 128);
    ASSERT_TRUE(est.ok()) << est.error().message();
    ASSERT_EQ(est->sunBounce.size(), 1u);
    const auto fit = sunStrengthFromBounce(photo, r.camera, r.geometry, est->gathered, bounceOf(*est),
                                           est->lights, est->suns[0]);
    ASSERT_TRUE(fit.ok()) << fit.error().message();
    double errEstimate = 0, errBounce = 0;
    for (int c = 0; c < 3; ++c) {
      std::printf("exposure %.0f channel %d: estimate %.3f, bounce %.3f (lower bound %.3f), true %.3f\n",
                  exposure, c, est->suns[0].irradianceOverPi[c], fit->strength[c], fit->lowerBound[c],
                  truth[c]);
      EXPECT_GE(fit->strength[c], fit->lowerBound[c] * (1 - 1e-9));
      errEstimate += std::abs(std::log(est->suns[0].irradianceOverPi[c] / truth[c])) / 3;
      errBounce += std::abs(std::log(fit->strength[c] / truth[c])) / 3;
    }
    std::printf(
        "exposure %.0f: mean |log(strength / truth)| estimate %.3f, bounce %.3f (share %.2f, "
        "spread %.2f, %s)\n",
        exposure, errEstimate, errBounce, fit->bounceShare, fit->spread,
        fit->determined ? "determined" : fit->warning.c_str());
    EXPECT_TRUE(fit->determined) << fit->warning;
    EXPECT_LT(errBounce, 0.3) << "exposure " << exposure;
    // From exposure 2 the clipped patch alone says far less (a fifth of the truth or below).
    if (exposure >= 2) {
      EXPECT_GT(fit->strength.minCoeff(), 2 * fit->lowerBound.maxCoeff()) << "exposure " << exposure;
    }
  }
}

// Stiff inputs: no bounce visible (everything outside the beam clipped), no clipped patch,
// another light that swamps the bounce, no bounce at all, non-finite pixels, mismatched images
// and a non-finite strength: a clear error or a finite strength with a warning, never a NaN.
TEST(Lighting, TheBounceFitOnStiffInputsIsFiniteOrRefused) {
  const BounceCase b = sunAndSkyRoom();
  const SyntheticRoom& r = b.room;
  const ImageF photo = exposed(b.linear, 2.0);
  const auto est = estimateSunRoom(photo, r, b.sun, 32);
  ASSERT_TRUE(est.ok()) << est.error().message();
  ASSERT_EQ(est->sunBounce.size(), 1u);
  const SunLight& sun = est->suns[0];
  auto fit = [&](const ImageF& p, const ImageF& gathered, const ImageF& direct, const SunLight& s) {
    SunBounceImages images = bounceOf(*est);
    images.direct = direct;
    return sunStrengthFromBounce(p, r.camera, r.geometry, gathered, images, est->lights, s);
  };
  // Everything outside the beam clipped: nothing shows the bounce.
  ImageF allClipped = exposed(b.linear, 1e4);
  auto none = fit(allClipped, est->gathered, est->sunBounce[0], sun);
  ASSERT_FALSE(none.ok());
  EXPECT_NE(none.error().reason.find("too few unclipped"), std::string::npos) << none.error().reason;
  // Nothing clipped: no lower bound, nothing to do.
  auto unclipped = fit(exposed(b.linear, 0.1), est->gathered, est->sunBounce[0], sun);
  ASSERT_FALSE(unclipped.ok());
  EXPECT_NE(unclipped.error().reason.find("clipped pixels on the patch"), std::string::npos);
  // A bright ceiling panel (given, not fitted) swamps the bounce: kept (at least the bound), said.
  const AreaLight panel = ceilingPanel(Vec3(300, 300, 300));
  const BounceCase lamp = sunAndSkyRoom({panel});
  std::vector<float> patch;
  for (int y = 0; y < lamp.linear.height; ++y)
    for (int x = 0; x < lamp.linear.width; ++x)
      if (lamp.sun.litMask.at(x, y) > 0.9f) patch.push_back(lamp.linear.at(x, y, 1));
  std::nth_element(patch.begin(), patch.begin() + long(patch.size() / 2), patch.end());
  const ImageF lampPhoto = exposed(lamp.linear, 1.5 / patch[patch.size() / 2]);
  LightingOptions lo;
  lo.gatherSamples = 32;
  lo.gatherStride = 2;
  lo.threads = 2;
  lo.gatherSunBounceUnseen = true;
  const auto lampEst =
      estimateLighting(lampPhoto, r.camera, r.geometry, {panel}, {false}, ImageF(), {lamp.sun}, lo);
  ASSERT_TRUE(lampEst.ok()) << lampEst.error().message();
  ASSERT_EQ(lampEst->sunBounce.size(), 1u);
  const auto bright = sunStrengthFromBounce(lampPhoto, r.camera, r.geometry, lampEst->gathered,
                                            bounceOf(*lampEst), lampEst->lights, lampEst->suns[0]);
  ASSERT_TRUE(bright.ok()) << bright.error().message();
  std::printf("a bright panel: share %.3f, %s\n", bright->bounceShare, bright->warning.c_str());
  EXPECT_NE(bright->warning.find("of the light on the room"), std::string::npos) << bright->warning;
  EXPECT_FALSE(bright->determined);
  const Vec3& lampSun = lampEst->suns[0].irradianceOverPi;
  const double kept = std::max(1.0, (bright->lowerBound.array() / lampSun.array()).maxCoeff());
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(bright->strength[c], kept * lampSun[c], 1e-9 * lampSun[c]);
  // No bounce at all (a black bounce image): the same.
  auto flat = fit(photo, est->gathered, ImageF(photo.width, photo.height, 3, 0.f), sun);
  ASSERT_TRUE(flat.ok()) << flat.error().message();
  EXPECT_FALSE(flat->warning.empty());
  EXPECT_TRUE(flat->strength.allFinite());
  // NaN and infinite pixels in the photo, the gathered light and the bounce: finite.
  ImageF nanPhoto = photo, nanGathered = est->gathered, nanBounce = est->sunBounce[0];
  for (size_t i = 0; i < nanPhoto.data.size(); i += 7) nanPhoto.data[i] = std::nanf("");
  for (size_t i = 3; i < nanGathered.data.size(); i += 11)
    nanGathered.data[i] = std::numeric_limits<float>::infinity();
  for (size_t i = 5; i < nanBounce.data.size(); i += 13) nanBounce.data[i] = std::nanf("");
  auto withNan = fit(nanPhoto, nanGathered, nanBounce, sun);
  ASSERT_TRUE(withNan.ok()) << withNan.error().message();
  EXPECT_TRUE(withNan->strength.allFinite());
  EXPECT_TRUE(withNan->lowerBound.allFinite());
  // Mismatched images and a non-finite strength are named.
  auto small = fit(photo, ImageF(3, 3, 3, 0.f), est->sunBounce[0], sun);
  ASSERT_FALSE(small.ok());
  EXPECT_EQ(small.error().key, "suns");
  SunLight bad = sun;
  bad.irradianceOverPi[1] = std::nan("");
  EXPECT_FALSE(fit(photo, est->gathered, est->sunBounce[0], bad).ok());
}

// A tiled floor (bright tiles, dark grout) under a sun whose patch clips on the tiles: the
// grout inside the beam against the grout beside it tells the sun's strength whatever the
// decomposition makes of the albedo (sun_ratio.h). Measured: the estimate 2.43 / 3.70 / 3.39,
// the ratio 4.96 / 4.52 / 3.79 against the truth's 5 / 4.6 / 4 (the lowest shadow quantiles,
// 2-5%, gave 5.87 / 5.18 / 4.32: the render's noise widens the shadow's spread; at 32 samples
// per pixel 7.4 / 6.3 / 4.9, hence 256, a photo's noise rather than a preview's).
TEST(Lighting, TheLitPatchAgainstItsShadowTellsAClippedSunsStrength) {
  SyntheticRoom r = emptyRoom();
  const Vec3 truth(5, 4.6, 4), tile(0.6, 0.55, 0.5), grout(0.15, 0.14, 0.13);
  const SunWindow sw = sunThroughWindow(r, truth);
  const SunLight& sun = sw.sun;
  // The floor's albedo per pixel: 0.3 m tiles, 0.06 m grout.
  const int W = r.camera.widthPx, H = r.camera.heightPx;
  RenderScene scene;
  scene.camera = r.camera;
  scene.room = r.geometry;
  scene.roomAlbedo.camera = r.camera;
  scene.roomAlbedo.surfaceMean = r.albedo;
  scene.roomAlbedo.computeFirstSurfaces(r.geometry);
  scene.roomAlbedo.albedo = ImageF(W, H, 3, 0.f);
  const RoomTracer tracer(r.geometry);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const auto h = tracer.intersect(r.camera.rayThroughPixel(Vec2(x + 0.5, y + 0.5)), 1e-6);
      if (!h) continue;
      Vec3 a = r.albedo[size_t(h->surfaceId)];
      if (h->surfaceId == 0) {
        const double u = std::fmod(h->pointWorld.x() + 10, 0.3),
                     v = std::fmod(h->pointWorld.z() + 10, 0.3);
        a = std::min(u, v) < 0.06 ? grout : tile;
      }
      scene.roomAlbedo.albedo.setRgb(x, y, a);
    }
  scene.suns = {sun};
  scene.lights = {sw.window};  // the sky through the window: the shadow's light
  PathTracer pt(scene);
  DifferentialBuffers buf(W, H);
  ASSERT_TRUE(pt.render(buf, 0, 256, 3));
  ImageF photo = buf.meanWithout();
  for (float& v : photo.data) v = std::min(v, 1.f);
  const auto est = estimateSunRoom(photo, r, sun, 128);
  ASSERT_TRUE(est.ok()) << est.error().message();
  SunRatioOptions ro;
  ro.minPixels = 60;
  const auto ratio =
      sunStrengthFromShadowRatio(photo, r.camera, r.geometry, est->gathered, {}, est->suns[0], ro);
  ASSERT_TRUE(ratio.ok()) << ratio.error().message();
  double errEstimate = 0, errRatio = 0;
  for (int c = 0; c < 3; ++c) {
    std::printf("channel %d: estimate %.3f, ratio %.3f (%d lit, %d shadowed, %g quantiles), true %.3f\n",
                c, est->suns[0].irradianceOverPi[c], ratio->strength[c], ratio->litPixels,
                ratio->shadowPixels, ratio->quantilesUsed[c], truth[c]);
    errEstimate += std::abs(est->suns[0].irradianceOverPi[c] / truth[c] - 1) / 3;
    errRatio += std::abs(ratio->strength[c] / truth[c] - 1) / 3;
    EXPECT_NEAR(ratio->strength[c] / truth[c], 1.0, 0.12) << "channel " << c;
  }
  EXPECT_LT(errRatio, errEstimate);
  // A sun whose beam lights nothing in view, and a gathered image of the wrong size: refused.
  SunLight away = est->suns[0];
  away.litMask = ImageF(W, H, 1, 0.f);
  const auto none = sunStrengthFromShadowRatio(photo, r.camera, r.geometry, est->gathered, {}, away, ro);
  ASSERT_FALSE(none.ok());
  EXPECT_NE(none.error().message().find("suns"), std::string::npos);
  EXPECT_FALSE(
      sunStrengthFromShadowRatio(photo, r.camera, r.geometry, ImageF(3, 3, 3, 0.f), {}, away, ro).ok());
}

// A ceiling light behind the camera, pale walls: most of the light on what the camera sees has
// bounced off the walls it does not see, whose radiance the estimate predicts from its own fit.
// Two plain passes swung from too little gathered light (pass 1 guesses the unseen walls from
// the seen ones) to far too much (pass 2 predicts them with the overshooting first fit); the
// relaxed passes settle on the gathered light the photo implies.
struct BehindCameraResult {
  double worstGammaError = 0;  // max over seen surfaces of |mean Gamma / true mean Gamma - 1|
  double lightRatio = 0;       // estimated / true radiance (green)
  int passes = 0;
};

// The true Gamma of a seen pixel: B / rho - L E with the true albedo and light.
BehindCameraResult estimateBehindCamera(const SyntheticRoom& r, const AreaLight& trueLight,
                                        const LightingOptions& opt) {
  AreaLight given = trueLight;
  given.radiance = Vec3(1, 1, 1);
  const auto est = estimateLighting(r.photo, r.camera, r.geometry, {given}, {true}, ImageF(), {}, opt);
  EXPECT_TRUE(est.ok()) << est.error().message();
  BehindCameraResult out;
  if (!est.ok()) return out;
  const RoomTracer rt(r.geometry);
  for (int sid = 0; sid < int(r.albedo.size()); ++sid) {
    double trueGamma = 0, estGamma = 0;
    int n = 0;
    for (int y = 0; y < r.photo.height; y += 3)
      for (int x = 0; x < r.photo.width; x += 3) {
        const auto h = r.geometry.intersect(r.camera.rayThroughPixel(Vec2(x + 0.5, y + 0.5)));
        if (!h || h->surfaceId != sid) continue;
        const double le = trueLight.radiance[1] *
                          rt.unitLightIrradianceOverPi(trueLight, h->pointWorld + 1e-5 * h->normalWorld,
                                                       h->normalWorld, 64, 1);
        trueGamma += r.photo.at(x, y, 1) / r.albedo[size_t(sid)][1] - le;
        estGamma += est->gathered.at(x, y, 1);
        ++n;
      }
    if (n < 20) continue;  // not seen
    std::printf("  %-12s Gamma %.4f true %.4f\n", r.geometry.surfaces[size_t(sid)].name.c_str(),
                estGamma / n, trueGamma / n);
    out.worstGammaError = std::max(out.worstGammaError, std::abs(estGamma / trueGamma - 1));
  }
  out.lightRatio = est->lights[0].radiance[1] / trueLight.radiance[1];
  out.passes = est->passes;
  for (float v : est->gathered.data) EXPECT_TRUE(std::isfinite(v) && v >= 0);
  for (float v : est->albedo.data) EXPECT_TRUE(std::isfinite(v) && v >= 0 && v <= 1);
  return out;
}

TEST(Lighting, ALightBehindTheCameraGathersWhatThePhotoImplies) {
  SyntheticRoom r = emptyRoom();
  r.albedo = {Vec3(0.3, 0.3, 0.3),    Vec3(0.8, 0.8, 0.8),    Vec3(0.78, 0.78, 0.78),
              Vec3(0.78, 0.78, 0.78), Vec3(0.78, 0.78, 0.78), Vec3(0.78, 0.78, 0.78)};
  AreaLight light;
  const double y = 2.699;  // between the camera (z = 0) and the wall behind it (z = 0.5)
  light.cornersWorld = {Vec3(-0.3, y, 0.05), Vec3(-0.3, y, 0.4), Vec3(0.3, y, 0.4), Vec3(0.3, y, 0.05)};
  if (light.normal().y() > 0) std::swap(light.cornersWorld[1], light.cornersWorld[3]);
  light.radiance = Vec3(20, 20, 20);
  ASSERT_LT(r.camera.depthOf(light.centre()), 0);  // behind the camera
  r.photo = renderRoom(r, {light}, {}, 48);
  LightingOptions opt;
  opt.gatherSamples = 64;
  opt.gatherStride = 2;
  opt.objective = false;
  const BehindCameraResult relaxed = estimateBehindCamera(r, light, opt);
  std::printf("relaxed: %d passes, light x%.3f, worst Gamma error %.3f\n", relaxed.passes,
              relaxed.lightRatio, relaxed.worstGammaError);
  LightingOptions twoPasses = opt;  // what the estimate did before
  twoPasses.maxPasses = 2;
  twoPasses.passRelaxation = 1;
  const BehindCameraResult plain = estimateBehindCamera(r, light, twoPasses);
  std::printf("two plain passes: light x%.3f, worst Gamma error %.3f\n", plain.lightRatio,
              plain.worstGammaError);
  EXPECT_GT(relaxed.passes, 2);
  EXPECT_LT(relaxed.worstGammaError, 0.15);  // two plain passes: 0.26 (the wall facing the camera)
  EXPECT_LT(relaxed.worstGammaError, plain.worstGammaError);
  // The intensity stays the weakest part (docs/generalization.md): E and Gamma have nearly the
  // same shape on what the camera sees. Read pixel by pixel, this 48-sample photo's noise made
  // it 2.4 times too bright; the fit's window (LightingOptions::fitWindow) brings it to about 1.4.
  EXPECT_TRUE(std::isfinite(relaxed.lightRatio) && relaxed.lightRatio > 0);
  EXPECT_LT(relaxed.lightRatio, 1.7);
}

// A grainy photo (a high-ISO camera, or a path-traced room at few samples): most pixels a little
// dark, a few very bright, the mean right. The fit compares logarithms, and the log of such a
// pixel is biased low (further under the robust loss, which discounts the bright few): read
// pixel by pixel, every albedo came out too dark and the light too bright. The fit now reads
// the photo averaged over a small window of the same surface (LightingOptions::fitWindow).
TEST(Lighting, AGrainyPhotoDoesNotDarkenTheAlbedoNorBrightenTheLight) {
  const Vec3 trueRadiance(4, 4, 4);
  SyntheticRoom r = makeRoom(trueRadiance, 16);
  // Grain with mean 1 and a long bright tail: a gamma-distributed factor (shape 1.5, relative
  // standard deviation 0.82), the same for the three channels.
  std::mt19937 rng(5);
  std::gamma_distribution<double> grain(1.5, 1 / 1.5);
  ImageF grainy = r.photo;
  for (int y = 0; y < grainy.height; ++y)
    for (int x = 0; x < grainy.width; ++x) {
      const double g = grain(rng);
      grainy.setRgb(x, y, Vec3((r.photo.rgb(x, y) * g).cwiseMin(0.97)));
    }
  auto light = lightFromOutline(r.camera, r.geometry, r.lightOutlinePx, "lights[0].points");
  ASSERT_TRUE(light.ok()) << light.error().message();
  LightingOptions opt;
  opt.gatherSamples = 32;
  opt.gatherStride = 4;
  opt.objective = false;
  auto lightRatio = [&](int window) {
    LightingOptions o = opt;
    o.fitWindow = window;
    const auto est =
        estimateLighting(grainy, r.camera, r.geometry, {*light}, {true}, lightMaskOf(r), {}, o);
    EXPECT_TRUE(est.ok()) << est.error().message();
    if (!est.ok()) return 0.0;
    for (const auto& l : est->lights) EXPECT_TRUE(l.radiance.allFinite());
    return est->lights[0].radiance[1] / trueRadiance[1];
  };
  const double pixel = lightRatio(0), window = lightRatio(LightingOptions{}.fitWindow);
  std::printf("light x%.3f read pixel by pixel, x%.3f over the window\n", pixel, window);
  EXPECT_NEAR(window, 1.0, 0.1);
  EXPECT_LT(std::abs(window - 1), std::abs(pixel - 1));
}

// `photo` with its left 1 / blackPart black, some pixels NaN and some saturated.
ImageF withBlackNanAndSaturatedPixels(ImageF photo, int blackPart) {
  for (int y = 0; y < photo.height; ++y)
    for (int x = 0; x < photo.width; ++x) {
      if (x < photo.width / blackPart) photo.setRgb(x, y, Vec3::Zero());
      if ((x + y) % 17 == 0) photo.setRgb(x, y, Vec3(std::nan(""), 1, 2));
      if ((x * y) % 23 == 1) photo.setRgb(x, y, Vec3(1, 1, 1));
    }
  return photo;
}

TEST(Lighting, StiffPhotosStayFiniteOrAreRefusedClearly) {
  const SyntheticRoom r = makeRoom(Vec3(4, 4, 4), 4);
  auto light = lightFromOutline(r.camera, r.geometry, r.lightOutlinePx, "lights[0].points");
  ASSERT_TRUE(light.ok());
  LightingOptions opt;
  opt.gatherSamples = 16;
  // Black photo: nothing to fit, said so.
  ImageF black(r.photo.width, r.photo.height, 3, 0.f);
  auto e1 = estimateLighting(black, r.camera, r.geometry, {*light}, {true}, ImageF(), {}, opt);
  ASSERT_FALSE(e1.ok());
  EXPECT_NE(e1.error().message().find("black or saturated"), std::string::npos);
  // Saturated photo.
  ImageF white(r.photo.width, r.photo.height, 3, 1.f);
  EXPECT_FALSE(estimateLighting(white, r.camera, r.geometry, {*light}, {true}, ImageF(), {}, opt).ok());
  // Half the photo black, some pixels NaN, some saturated: finite, bounded output.
  const ImageF mixed = withBlackNanAndSaturatedPixels(r.photo, 2);
  auto e2 = estimateLighting(mixed, r.camera, r.geometry, {*light}, {true}, ImageF(), {}, opt);
  ASSERT_TRUE(e2.ok()) << e2.error().message();
  for (float v : e2->albedo.data) ASSERT_TRUE(std::isfinite(v) && v >= 0 && v <= 1);
  for (float v : e2->gathered.data) ASSERT_TRUE(std::isfinite(v) && v >= 0);
  for (const auto& l : e2->lights) ASSERT_TRUE(l.radiance.allFinite() && l.radiance.minCoeff() >= 0);
  // A light kept as given is not changed by the fit; huge and tiny radiances stay finite.
  for (double given : {1e-4, 1e4}) {
    AreaLight fixed = *light;
    fixed.radiance = Vec3(given, given, given);
    auto e3 = estimateLighting(r.photo, r.camera, r.geometry, {fixed}, {false}, lightMaskOf(r), {}, opt);
    ASSERT_TRUE(e3.ok());
    EXPECT_EQ(e3->lights[0].radiance, fixed.radiance);
    for (float v : e3->albedo.data) ASSERT_TRUE(std::isfinite(v) && v >= 0 && v <= 1);
  }
  // Under a shoulder at the family's bounds: every code 255 is refused as saturated, clearly;
  // half the room at the top code (1.0, thousands of times the rest) gives finite, bounded output.
  const CameraResponse bound = CameraResponse::toeShoulder({2.5, 2.0, 1000.0});
  ImageF white255(r.photo.width, r.photo.height, 3, bound.table8()[255]);
  auto e4 = estimateLighting(white255, r.camera, r.geometry, {*light}, {true}, ImageF(), {}, opt);
  ASSERT_FALSE(e4.ok());
  EXPECT_NE(e4.error().message().find("black or saturated"), std::string::npos);
  for (double power : {0.4, 2.5}) {
    const CameraResponse curve = CameraResponse::toeShoulder({power, 2.0, 1000.0});
    // The room's median at code 128, half the photo at the top code.
    std::vector<float> g;
    for (int y = 0; y < r.photo.height; ++y)
      for (int x = 0; x < r.photo.width; ++x) g.push_back(r.photo.at(x, y, 1));
    std::nth_element(g.begin(), g.begin() + long(g.size() / 2), g.end());
    const float exposure = curve.table8()[128] / std::max(g[g.size() / 2], 1e-6f);
    ImageF half = r.photo;
    for (float& v : half.data) v = curve.table8()[curve.encodeCode8(v * exposure)];
    for (int y = 0; y < half.height; ++y)
      for (int x = half.width / 2; x < half.width; ++x)
        half.setRgb(x, y, Vec3::Constant(curve.table8()[255]));
    // Read with the curve's black level (the pipeline's blackLevelOf): with sRGB's, power 0.4's
    // whole room (code 128 decodes to 2e-5) is black and refused.
    LightingOptions o = opt;
    o.blackBelow = 1e-4 * curve.table8()[1] / CameraResponse::srgb().table8()[1];
    auto e5 = estimateLighting(half, r.camera, r.geometry, {*light}, {true}, lightMaskOf(r), {}, o);
    ASSERT_TRUE(e5.ok()) << "power " << power << ": " << e5.error().message();
    for (float v : e5->albedo.data) ASSERT_TRUE(std::isfinite(v) && v >= 0 && v <= 1);
    for (float v : e5->gathered.data) ASSERT_TRUE(std::isfinite(v) && v >= 0);
    for (const auto& l : e5->lights) ASSERT_TRUE(l.radiance.allFinite() && l.radiance.minCoeff() >= 0);
  }
}

// A photo of `r` through a camera with a long highlight shoulder (toe_shoulder, shoulder 1000,
// the family's bound): exposed so that the brightest 2 % of the room reach code 250, one code of
// noise (JPEG, sensor) on every code, decoded by the same curve. The top codes decode many stops
// apart (244 -> 255 is a factor of 100), so the light's edge pixels outside a tight outline and
// the brightest wall read far above the rest. `exposure`: the decoded photo's units over the
// render's.
struct ShoulderPhoto {
  ImageF photo;
  double exposure = 1;
};

ShoulderPhoto throughALongShoulder(const SyntheticRoom& r, const ImageF& mask,
                                   const CameraResponse& camera) {
  std::vector<float> room;
  for (int y = 0; y < r.photo.height; ++y)
    for (int x = 0; x < r.photo.width; ++x)
      if (mask.at(x, y) < 0.5f) room.push_back(r.photo.at(x, y, 1));
  std::nth_element(room.begin(), room.begin() + long(room.size() * 98 / 100), room.end());
  ShoulderPhoto out;
  out.exposure = camera.table8()[250] / room[room.size() * 98 / 100];
  out.photo = r.photo;
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> noise(-1, 1);
  for (float& v : out.photo.data) {
    const int code = std::clamp(int(camera.encodeCode8(float(v * out.exposure))) + noise(rng), 0, 255);
    v = camera.table8()[size_t(code)];
  }
  return out;
}

// A long shoulder's top codes are decoded right, and the light fit holds up on them: with most of
// the room in codes where one step is more than a tenth in log radiance (and a code of noise on
// every pixel), the fitted light stays near the truth. Reading those codes as clipped instead
// (their light given the clipped pixels' fitted gain) made it x0.22 here: the gain took the
// light's part (docs/camera-response.md, "The decoded highlights in the light fit").
TEST(Lighting, TheLightFitHoldsOnALongShouldersDecodedHighlights) {
  const Vec3 trueRadiance(6, 6, 6);
  const SyntheticRoom r = makeRoom(trueRadiance, 64);
  const CameraResponse camera = CameraResponse::toeShoulder({1.0, 0.0, 1000.0});
  const ImageF mask = lightMaskOf(r, -1);  // tight: the panel's edge pixels stay in the room
  const ShoulderPhoto shot = throughALongShoulder(r, mask, camera);
  const auto& table = camera.table8();
  size_t firstSteep = 128;  // the first code whose step to the next exceeds 0.1 in log radiance
  while (firstSteep < 254 && std::log(table[firstSteep + 1] / table[firstSteep]) <= 0.1) ++firstSteep;
  size_t steep = 0, room = 0;
  for (int y = 0; y < shot.photo.height; ++y)
    for (int x = 0; x < shot.photo.width; ++x)
      if (mask.at(x, y) < 0.5f) ++room, steep += shot.photo.at(x, y, 1) >= table[firstSteep] ? 1 : 0;
  ASSERT_GT(double(steep) / double(room), 0.5) << "the room must lie in the shoulder's steep codes";
  auto light = lightFromOutline(r.camera, r.geometry, r.lightOutlinePx, "lights[0].points");
  ASSERT_TRUE(light.ok()) << light.error().message();
  LightingOptions opt;
  opt.gatherSamples = 64;
  opt.gatherStride = 2;
  const auto est = estimateLighting(shot.photo, r.camera, r.geometry, {*light}, {true}, mask, {}, opt);
  ASSERT_TRUE(est.ok()) << est.error().message();
  for (float v : est->albedo.data) ASSERT_TRUE(std::isfinite(v) && v >= 0 && v <= 1);
  for (float v : est->gathered.data) ASSERT_TRUE(std::isfinite(v) && v >= 0);
  const double ratio = est->lights[0].radiance[1] / (shot.exposure * trueRadiance[1]);
  std::printf("%.0f %% of the room at codes %zu and up; light x%.3f the truth\n",
              100.0 * double(steep) / double(room), firstSteep, ratio);
  EXPECT_NEAR(ratio, 1.0, 0.2);
}

// A curve that compresses the whole room into codes decoding under 1e-4, sRGB's black (power
// 0.5, toe 1, shoulder 1000: codes up to 113; the noise cue's own curves, power 1 and shoulder
// near 1000, put codes below 85 there): read with sRGB's black level the light fit
// finds no pixel and refuses the photo (as main did on scenes-train t09 through such a curve).
// With the level scaled by the response's code 1 (the pipeline's blackLevelOf) the same codes
// are black as under sRGB, and the fitted light is the truth's.
TEST(Lighting, ACompressingCurvesDarkCodesAreNotBlack) {
  const Vec3 trueRadiance(6, 6, 6);
  const SyntheticRoom r = makeRoom(trueRadiance, 64);
  const CameraResponse camera = CameraResponse::toeShoulder({0.5, 1.0, 1000.0});
  const ImageF mask = lightMaskOf(r);
  std::vector<float> room;
  for (int y = 0; y < r.photo.height; ++y)
    for (int x = 0; x < r.photo.width; ++x)
      if (mask.at(x, y) < 0.5f) room.push_back(r.photo.at(x, y, 1));
  // The room's brightest pixel at code 110, its median some 30 codes lower.
  const double exposure = camera.table8()[110] / *std::max_element(room.begin(), room.end());
  ImageF photo = r.photo;
  for (float& v : photo.data) v = camera.table8()[camera.encodeCode8(float(v * exposure))];
  auto light = lightFromOutline(r.camera, r.geometry, r.lightOutlinePx, "lights[0].points");
  ASSERT_TRUE(light.ok()) << light.error().message();
  LightingOptions opt;
  opt.gatherSamples = 64;
  opt.gatherStride = 2;
  const auto asSrgb = estimateLighting(photo, r.camera, r.geometry, {*light}, {true}, mask, {}, opt);
  ASSERT_FALSE(asSrgb.ok());
  EXPECT_NE(asSrgb.error().message().find("black or saturated"), std::string::npos);
  opt.blackBelow = 1e-4 * camera.table8()[1] / CameraResponse::srgb().table8()[1];
  const auto est = estimateLighting(photo, r.camera, r.geometry, {*light}, {true}, mask, {}, opt);
  ASSERT_TRUE(est.ok()) << est.error().message();
  for (float v : est->albedo.data) ASSERT_TRUE(std::isfinite(v) && v >= 0 && v <= 1);
  const double ratio = est->lights[0].radiance[1] / (exposure * trueRadiance[1]);
  std::printf("black level %.2g: light x%.3f the truth\n", opt.blackBelow, ratio);
  EXPECT_NEAR(ratio, 1.0, 0.2);
}

TEST(Lighting, OutlinesThatCannotBeLightsAreNamed) {
  const SyntheticRoom r = makeRoom(Vec3(1, 1, 1), 1);
  auto two = lightFromOutline(r.camera, r.geometry, {Vec2(10, 10), Vec2(20, 10)}, "lights[3].points");
  ASSERT_FALSE(two.ok());
  EXPECT_NE(two.error().message().find("lights[3].points"), std::string::npos);
  auto flat = lightFromOutline(r.camera, r.geometry, {Vec2(10, 10), Vec2(20, 10), Vec2(30, 10)},
                               "lights[0].points");
  ASSERT_FALSE(flat.ok());
  EXPECT_NE(flat.error().message().find("no area"), std::string::npos);
  auto nan = lightFromOutline(r.camera, r.geometry, {Vec2(10, 10), Vec2(std::nan(""), 10), Vec2(30, 20)},
                              "lights[0].points");
  EXPECT_FALSE(nan.ok());
}

// A window outlined on the left wall with one point on the back wall (where a box with its left
// wall too far out puts it): the point's ray never meets the left wall's plane in front of the
// camera. The message keeps the key, names the point, the two surfaces and the corner to drag.
TEST(Lighting, AnOutlineOffItsWallSaysWhichPointAndWhatToDrag) {
  const SyntheticRoom r = emptyRoom();
  std::vector<Vec2> outline;
  for (const Vec3& p : {Vec3(-2.5, 1.8, -4.6), Vec3(-2.5, 1.8, -5.2), Vec3(-2.5, 1.2, -5.2)})
    outline.push_back(*r.camera.project(p));
  for (const Vec2& p : outline) ASSERT_TRUE(p.x() > 0 && p.x() < 80 && p.y() > 0 && p.y() < 120);
  outline.push_back(Vec2(100, 70));  // right of the centre: on the back wall
  const auto l = lightFromOutline(r.camera, r.geometry, outline, "lights[0].points");
  ASSERT_FALSE(l.ok());
  const std::string m = l.error().message();
  EXPECT_EQ(l.error().key, "lights[0].points");
  EXPECT_EQ(m.find("the outline lies behind the camera"), std::string::npos);
  for (const std::string& words :
       {std::string("point 3 (100, 70) lies on the back wall"),
        std::string("most of the outline lies on the left wall"), std::string("only behind the camera"),
        std::string("drag the back wall's bottom-left corner at (")})
    EXPECT_NE(m.find(words), std::string::npos) << m;
  const Vec2 bl = backWallCornersPx(r.camera, r.geometry.box)[3];
  char at[64];
  std::snprintf(at, sizeof at, "corner at (%.0f, %.0f)", bl.x(), bl.y());
  EXPECT_NE(m.find(at), std::string::npos) << m;
  // The advice per surface names the corner that moves it.
  EXPECT_NE(roomBoxAdvice(r.camera, r.geometry.box, SurfaceKind::WallRight).find("bottom-right corner"),
            std::string::npos);
  EXPECT_NE(roomBoxAdvice(r.camera, r.geometry.box, SurfaceKind::Ceiling).find("top corners"),
            std::string::npos);
  // The same outline on the left wall alone is a light.
  outline.pop_back();
  outline.push_back(*r.camera.project(Vec3(-2.5, 1.2, -4.6)));
  EXPECT_TRUE(lightFromOutline(r.camera, r.geometry, outline, "lights[0].points").ok());
}

// The light fit's relative residual (LightingEstimate::fitResidualRelative) is what a response
// search would compare curves by: the photo's true radiance leaves less of it than the same
// photo through a power curve either way (the lights' fall-off is fixed by the geometry, so a
// bent photo cannot be matched by other albedos and strengths), and it is scale-free.
// What the render gives the surfaces the camera does not see. Box order: floor, ceiling,
// wall_left, wall_right, wall_back, wall_rear. An unseen ceiling over dark (tiled) walls is a
// white ceiling, not the walls' grey (which made an object lit from above 6-9 % too dark); over
// walls brighter than that it is the walls' mean; unseen walls stay the seen walls' mean.
TEST(Lighting, AnUnseenCeilingIsAWhiteCeilingOverDarkWalls) {
  const SceneGeometry geometry = emptyRoom().geometry;
  ASSERT_EQ(geometry.surfaces.size(), 6u);
  ASSERT_EQ(geometry.surfaces[1].kind, SurfaceKind::Ceiling);
  const std::vector<double> seen = {100, 0, 0, 50, 150, 0};  // floor, right and back walls
  std::vector<Vec3> albedo(6, Vec3::Zero());
  albedo[0] = Vec3(0.4, 0.3, 0.2), albedo[3] = Vec3(0.3, 0.3, 0.35), albedo[4] = Vec3(0.34, 0.34, 0.39);
  const std::vector<Vec3> dark = albedoOfUnseen(geometry, albedo, seen, kUnseenCeilingAlbedo);
  const Vec3 wallMean = (50 * albedo[3] + 150 * albedo[4]) / 200;
  EXPECT_TRUE(dark[1].isApprox(Vec3::Constant(kUnseenCeilingAlbedo), 1e-12)) << dark[1].transpose();
  EXPECT_TRUE(dark[2].isApprox(wallMean, 1e-12)) << dark[2].transpose();
  EXPECT_TRUE(dark[5].isApprox(wallMean, 1e-12)) << dark[5].transpose();
  EXPECT_TRUE(dark[0].isApprox(albedo[0], 1e-12));

  albedo[3] = Vec3(0.85, 0.82, 0.8), albedo[4] = Vec3(0.8, 0.8, 0.78);  // bright walls
  const std::vector<Vec3> bright = albedoOfUnseen(geometry, albedo, seen, kUnseenCeilingAlbedo);
  EXPECT_TRUE(bright[1].isApprox((50 * albedo[3] + 150 * albedo[4]) / 200, 1e-12))
      << bright[1].transpose();

  const std::vector<Vec3> seenCeiling =
      albedoOfUnseen(geometry, albedo, {1, 1, 1, 1, 1, 1}, kUnseenCeilingAlbedo);
  EXPECT_TRUE(seenCeiling[1].isApprox(albedo[1], 1e-12));  // a seen ceiling keeps its own (black)
  // The light fit's own model (no floor): the walls' mean, as before.
  albedo[3] = Vec3(0.3, 0.3, 0.35), albedo[4] = Vec3(0.34, 0.34, 0.39);
  EXPECT_TRUE(albedoOfUnseen(geometry, albedo, seen)[1].isApprox(wallMean, 1e-12));
}

TEST(Lighting, FitResidualIsLowestForTheTrueRadiance) {
  const SyntheticRoom r = makeRoom(Vec3(6.0, 5.0, 4.0), 32);
  LightingOptions opt;
  opt.gatherSamples = 32;
  opt.objective = false;
  const ImageF mask = lightMaskOf(r);
  auto residualOf = [&](double power, double scale) {
    ImageF photo = r.photo;
    for (float& v : photo.data)
      v = float(scale * std::pow(std::max(v, 0.f) / 0.9f, float(power)) * 0.9f);
    auto light = lightFromOutline(r.camera, r.geometry, r.lightOutlinePx, "lights[0].points");
    EXPECT_TRUE(light.ok());
    const auto est = estimateLighting(photo, r.camera, r.geometry, {*light}, {true}, mask, {}, opt);
    EXPECT_TRUE(est.ok());
    return est.ok() ? est->fitResidualRelative : std::nan("");
  };
  const double truth = residualOf(1.0, 1.0), darker = residualOf(1.0, 0.5);
  const double bentUp = residualOf(1.6, 1.0), bentDown = residualOf(0.6, 1.0);
  std::printf("relative residual: true %.4f, half exposure %.4f, power 1.6 %.4f, power 0.6 %.4f\n",
              truth, darker, bentUp, bentDown);
  ASSERT_TRUE(std::isfinite(truth) && truth > 0);
  EXPECT_NEAR(darker / truth, 1.0, 0.1);
  EXPECT_GT(bentUp, 1.2 * truth);
  EXPECT_GT(bentDown, 1.2 * truth);
}

// LightingEstimate::vignetting: the light fit's residual shows a radial fall-off put on the
// photo (1 - v r^2, r^2 over the corner's), and little where there is none.
TEST(Lighting, ResidualShowsTheVignettingPutOnAPhoto) {
  const SyntheticRoom r = makeRoom(Vec3(6.0, 5.0, 4.0), 32);
  LightingOptions opt;
  opt.gatherSamples = 32;
  opt.objective = false;
  const ImageF mask = lightMaskOf(r);
  auto estimateOf = [&](double v) {
    ImageF photo = r.photo;
    const double cx = photo.width / 2.0, cy = photo.height / 2.0;
    for (int y = 0; y < photo.height; ++y)
      for (int x = 0; x < photo.width; ++x) {
        const double r2 = ((x + 0.5 - cx) * (x + 0.5 - cx) + (y + 0.5 - cy) * (y + 0.5 - cy)) /
                          (cx * cx + cy * cy);
        for (int c = 0; c < 3; ++c) photo.at(x, y, c) *= float(1 - v * r2);
      }
    auto light = lightFromOutline(r.camera, r.geometry, r.lightOutlinePx, "lights[0].points");
    EXPECT_TRUE(light.ok());
    const auto est = estimateLighting(photo, r.camera, r.geometry, {*light}, {true}, mask, {}, opt);
    EXPECT_TRUE(est.ok());
    return est.ok() ? std::make_pair(est->vignetting, est->vignettingResidualRatio)
                    : std::make_pair(-1.0, -1.0);
  };
  const auto none = estimateOf(0), strong = estimateOf(0.35);
  std::printf("vignetting: none -> %.2f (residual x %.3f), 0.35 -> %.2f (residual x %.3f)\n", none.first,
              none.second, strong.first, strong.second);
  EXPECT_LE(none.first, 0.08);
  EXPECT_NEAR(strong.first, 0.35, 0.12);
  EXPECT_LT(strong.second, 0.95);
  EXPECT_LE(strong.second, 1.0);
}

// The gather's grid is capped (LightingOptions::gatherMaxPoints): the stride grows until the
// grid fits, and no further.
TEST(Lighting, TheGathersStrideKeepsItsGridWithinTheCap) {
  auto points = [](int w, int h, int s) { return int64_t((w + s - 1) / s) * ((h + s - 1) / s); };
  EXPECT_EQ(gatherStrideFor(640, 480, 4, 160 * 120), 4);  // a 0.3 MP photo: as before the cap
  EXPECT_EQ(gatherStrideFor(512, 384, 4, 160 * 120), 4);
  EXPECT_EQ(gatherStrideFor(816, 612, 4, 0), 4);  // no cap
  EXPECT_EQ(gatherStrideFor(816, 612, 0, 0), 1);  // a stride of at least 1
  EXPECT_EQ(gatherStrideFor(1, 1, 4, 160 * 120), 4);
  EXPECT_EQ(gatherStrideFor(3, 2, 1, 1), 3);   // one point
  EXPECT_EQ(gatherStrideFor(0, 5, 4, 10), 4);  // an empty photo: the stride as given
  const std::array<std::array<int, 2>, 6> sizes = {
      {{816, 612}, {4000, 3000}, {100000, 1}, {1, 100000}, {8000, 6000}, {46341, 46341}}};
  for (const auto& [w, h] : sizes)
    for (int cap : {1, 1000, 160 * 120}) {
      const int s = gatherStrideFor(w, h, 4, cap);
      EXPECT_LE(points(w, h, s), cap) << w << " x " << h << " cap " << cap;
      if (s > 4) {
        EXPECT_GT(points(w, h, s - 1), cap) << w << " x " << h << " cap " << cap;
      }
    }
}

// A capped grid is the grid of the stride it picks, bit for bit, and the steps' seconds are
// reported (LightingEstimate::steps).
TEST(Lighting, ACappedGatherIsTheSparserGrid) {
  const SyntheticRoom r = makeRoom(Vec3(4, 4, 4), 8);
  auto light = lightFromOutline(r.camera, r.geometry, r.lightOutlinePx, "lights[0].points");
  ASSERT_TRUE(light.ok()) << light.error().message();
  LightingOptions capped;
  capped.gatherSamples = 16;
  capped.threads = 1;
  capped.gatherStride = 2;
  capped.gatherMaxPoints = 40 * 30;  // 160 x 120 at stride 4
  LightingOptions sparse = capped;
  sparse.gatherStride = 4;
  sparse.gatherMaxPoints = 0;
  const auto a =
      estimateLighting(r.photo, r.camera, r.geometry, {*light}, {true}, lightMaskOf(r), {}, capped);
  const auto b =
      estimateLighting(r.photo, r.camera, r.geometry, {*light}, {true}, lightMaskOf(r), {}, sparse);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a->gatherStride, 4);
  EXPECT_EQ(a->gatherPoints, 40 * 30);
  EXPECT_EQ(a->lights[0].radiance, b->lights[0].radiance);
  EXPECT_EQ(a->gathered.data, b->gathered.data);
  EXPECT_EQ(a->albedo.data, b->albedo.data);
  std::vector<std::string> names;
  for (const LightingStepTime& step : a->steps) {
    names.push_back(step.name);
    EXPECT_TRUE(step.seconds >= 0 && step.cpuSeconds >= 0 && step.calls >= 1) << step.name;
  }
  for (const char* name : {"surfaces", "direct light", "gather", "light fit", "decomposition"})
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
}

// A working copy larger than a 640 x 480 photo is decomposed on 2 x 2 block means
// (kLightingDecomposeMaxPixels; odd sizes leave partial blocks at the edges): its albedo stays in
// [0, 1], finite, and each seen surface's mean as close to the true albedo as the
// full-resolution decomposition's (within 0.01; a 2-sample render, so its noise is large).
TEST(Lighting, AWorkingCopyAbove640x480IsDecomposedOnBlockMeans) {
  const SyntheticRoom r = makeRoom(Vec3(6.0, 5.0, 4.0), 2, 657);  // 657 x 492
  ASSERT_GT(int64_t(r.photo.width) * r.photo.height, 640 * 480);
  auto light = lightFromOutline(r.camera, r.geometry, r.lightOutlinePx, "lights[0].points");
  ASSERT_TRUE(light.ok()) << light.error().message();
  LightingOptions blocks;
  blocks.gatherSamples = 16;
  LightingOptions full = blocks;
  full.decompose.maxSolvePixels = 0;
  const auto a =
      estimateLighting(r.photo, r.camera, r.geometry, {*light}, {true}, lightMaskOf(r), {}, blocks);
  const auto b =
      estimateLighting(r.photo, r.camera, r.geometry, {*light}, {true}, lightMaskOf(r), {}, full);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_NE(a->decomposeReport.find("solved on 2x2 blocks of the 657x492 photo"), std::string::npos)
      << a->decomposeReport;
  EXPECT_EQ(b->decomposeReport.find("blocks"), std::string::npos) << b->decomposeReport;
  for (float v : a->albedo.data) ASSERT_TRUE(std::isfinite(v) && v >= 0 && v <= 1);
  for (float v : a->direct.data) ASSERT_TRUE(std::isfinite(v) && v >= 0);
  ASSERT_EQ(a->surfaceMeanAlbedo.size(), r.albedo.size());
  ASSERT_EQ(b->surfaceMeanAlbedo.size(), r.albedo.size());
  for (size_t s = 0; s < r.albedo.size(); ++s) {
    const double errorBlocks = (a->surfaceMeanAlbedo[s] - r.albedo[s]).cwiseAbs().maxCoeff();
    const double errorFull = (b->surfaceMeanAlbedo[s] - r.albedo[s]).cwiseAbs().maxCoeff();
    std::printf("surface %zu: albedo error on blocks %.4f, full %.4f\n", s, errorBlocks, errorFull);
    EXPECT_LE(errorBlocks, errorFull + 0.01) << "surface " << s;
  }
}

// A 1 x 1 photo and a strip 1500 x 2 (a working copy of an extreme panorama): finite output or
// a clear error, never NaN.
TEST(Lighting, OnePixelAndAStripPhotoStayFinite) {
  const SyntheticRoom room = makeRoom(Vec3(4, 4, 4), 1);
  for (const auto& [w, h] : std::array<std::array<int, 2>, 3>{{{1, 1}, {1500, 2}, {2, 900}}}) {
    Camera camera = levelCamera(w, h, 0.5 * std::max(w, h), 1.5);
    ImageF photo(w, h, 3, 0.f);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) photo.setRgb(x, y, Vec3(0.2 + 0.1 * x / w, 0.3, 0.25 + 0.1 * y / h));
    LightingOptions opt;
    opt.gatherSamples = 16;
    const auto est =
        estimateLighting(photo, camera, room.geometry, {room.light}, {true}, ImageF(), {}, opt);
    if (!est.ok()) {
      EXPECT_FALSE(est.error().message().empty());
      continue;
    }
    for (float v : est->albedo.data)
      ASSERT_TRUE(std::isfinite(v) && v >= 0 && v <= 1) << w << " x " << h;
    for (float v : est->direct.data) ASSERT_TRUE(std::isfinite(v) && v >= 0) << w << " x " << h;
    for (float v : est->gathered.data) ASSERT_TRUE(std::isfinite(v) && v >= 0) << w << " x " << h;
    EXPECT_TRUE(est->lights[0].radiance.allFinite()) << w << " x " << h;
    EXPECT_LE(int64_t(est->gatherPoints), int64_t(opt.gatherMaxPoints));
  }
}

}  // namespace
}  // namespace inlay

namespace inlay {
namespace {

// A ceiling panel behind the camera (out of view), centred at x, between the camera and the
// wall behind it.
AreaLight panelBehindCamera(double x, const Vec3& radiance) {
  AreaLight L;
  const double y = 2.699;
  L.cornersWorld = {Vec3(x - 0.25, y, 0.05), Vec3(x - 0.25, y, 0.4), Vec3(x + 0.25, y, 0.4),
                    Vec3(x + 0.25, y, 0.05)};
  if (L.normal().y() > 0) std::swap(L.cornersWorld[1], L.cornersWorld[3]);
  L.radiance = radiance;
  return L;
}

// Several estimated lights out of view share one radiance (LightingOptions::tieLightsOutOfView),
// with a note; the light in view keeps its own; off, each has its own. Stiff: two lights at one
// place, and a light the photo has no light of (the room lit by the others), stay finite.
TEST(Lighting, LightsOutOfViewShareOneRadiance) {
  SyntheticRoom r = makeRoom(Vec3(8, 8, 8), 1);
  // The room's panel moved to the back of the ceiling, where the photo shows it.
  for (auto& c : r.light.cornersWorld) c.z() -= 1.8;
  r.lightOutlinePx.clear();
  for (const Vec3& c : r.light.cornersWorld) r.lightOutlinePx.push_back(*r.camera.project(c));
  const auto seen = r.camera.project(r.light.centre());
  ASSERT_TRUE(seen && seen->y() > 0 && seen->y() < r.camera.heightPx);
  const AreaLight left = panelBehindCamera(-1.2, Vec3(10, 10, 10)),
                  right = panelBehindCamera(1.2, Vec3(30, 30, 30));
  ASSERT_LT(r.camera.depthOf(left.centre()), 0);  // behind the camera: out of view
  r.photo = renderRoom(r, {r.light, left, right}, {}, 16);
  LightingOptions opt;
  opt.gatherSamples = 16;
  opt.gatherStride = 3;
  opt.objective = false;
  std::vector<AreaLight> given = {r.light, left, right};
  for (auto& L : given) L.radiance = Vec3(1, 1, 1);
  const ImageF mask = lightMaskOf(r);
  auto tied = estimateLighting(r.photo, r.camera, r.geometry, given, {true, true, true}, mask, {}, opt);
  ASSERT_TRUE(tied.ok()) << tied.error().message();
  EXPECT_EQ(tied->lights[1].radiance, tied->lights[2].radiance);
  EXPECT_NE(tied->lights[0].radiance, tied->lights[1].radiance);
  bool noted = false;
  for (const auto& n : tied->notes)
    noted = noted || n.find("lights 1, 2 are out of view") != std::string::npos;
  EXPECT_TRUE(noted);
  for (const auto& L : tied->lights) EXPECT_TRUE(L.radiance.allFinite() && L.radiance.minCoeff() >= 0);

  LightingOptions free = opt;
  free.tieLightsOutOfView = false;
  auto untied =
      estimateLighting(r.photo, r.camera, r.geometry, given, {true, true, true}, mask, {}, free);
  ASSERT_TRUE(untied.ok());
  EXPECT_NE(untied->lights[1].radiance, untied->lights[2].radiance);
  for (const auto& L : untied->lights) EXPECT_TRUE(L.radiance.allFinite() && L.radiance.minCoeff() >= 0);

  // Two lights at one place, and the photo without the left light's light: finite.
  {
    auto twin = estimateLighting(r.photo, r.camera, r.geometry, {given[0], given[2], given[2]},
                                 {true, true, true}, mask, {}, opt);
    ASSERT_TRUE(twin.ok());
    for (const auto& L : twin->lights) EXPECT_TRUE(L.radiance.allFinite() && L.radiance.minCoeff() >= 0);
  }
  const ImageF withoutLeft = renderRoom(r, {r.light, right}, {}, 8);
  auto dark =
      estimateLighting(withoutLeft, r.camera, r.geometry, given, {true, true, true}, mask, {}, opt);
  ASSERT_TRUE(dark.ok());
  for (const auto& L : dark->lights) EXPECT_TRUE(L.radiance.allFinite() && L.radiance.minCoeff() >= 0);
}

// The largest |a - b| / max(|b|, floor) over two images' values (0 when both are empty).
double largestRelativeDifference(const ImageF& a, const ImageF& b, double floor) {
  EXPECT_EQ(a.data.size(), b.data.size());
  double worst = 0;
  for (size_t i = 0; i < std::min(a.data.size(), b.data.size()); ++i)
    worst = std::max(
        worst, std::abs(double(a.data[i]) - b.data[i]) / std::max(std::abs(double(b.data[i])), floor));
  return worst;
}

// A room exposed so that a tenth of it clips (ClippedPixelsSendMoreLightThanTheyShow), its first
// estimate (rays traced) and its light moved 15 cm, as the refinement would: the refit's case.
struct RefitCase {
  SyntheticRoom r;
  ImageF mask, photo;
  LightingOptions opt;
  std::optional<LightingEstimate> first;  // empty when it failed (a test failure)
  AreaLight moved;
};
RefitCase refitCase() {
  RefitCase k{makeRoom(Vec3(6.0, 5.0, 4.0), 16), {}, {}, {}, std::nullopt, {}};
  k.mask = lightMaskOf(k.r);
  const float exposure = exposureClippingATenth(k.r, k.mask);
  k.photo = k.r.photo;
  for (float& v : k.photo.data) v = std::min(1.f, v * exposure);
  auto light = lightFromOutline(k.r.camera, k.r.geometry, k.r.lightOutlinePx, "lights[0].points");
  EXPECT_TRUE(light.ok());
  if (!light.ok()) return k;
  k.opt.gatherSamples = 16;
  k.opt.gatherStride = 3;
  k.opt.threads = 2;
  auto first = estimateLighting(k.photo, k.r.camera, k.r.geometry, {*light}, {true}, k.mask, {}, k.opt);
  EXPECT_TRUE(first.ok()) << first.error().message();
  if (!first.ok()) return k;
  k.first = std::move(*first);
  k.moved = k.first->lights[0];
  for (Vec3& c : k.moved.cornersWorld) c += Vec3(0.15, 0, -0.1);
  return k;
}

// The refit after the lights' refinement replays the first estimate's rays (their hits do not
// depend on the lights): with a light moved 15 cm it gives the lights, gathered light and albedo
// of an estimate that traces its own rays, up to the order of the sums. Here with clipped pixels
// (their gathered light apart, its gain fitted) and an unseen rear wall (the patches' sweeps).
TEST(Lighting, ARefitReplayingTheFirstEstimatesRaysGivesWhatTracingGives) {
  const RefitCase k = refitCase();
  ASSERT_TRUE(k.first);
  const auto& first = k.first;
  const SyntheticRoom& r = k.r;
  ASSERT_TRUE(first->rays);
  EXPECT_FALSE(first->raysReused);
  const auto traced =
      estimateLighting(k.photo, r.camera, r.geometry, {k.moved}, {true}, k.mask, {}, k.opt);
  LightingOptions replay = k.opt;
  replay.reuseRays = first->rays;
  replay.warmStart = false;  // the same passes as tracing (the warm start: the test below)
  const auto replayed =
      estimateLighting(k.photo, r.camera, r.geometry, {k.moved}, {true}, k.mask, {}, replay);
  ASSERT_TRUE(traced.ok() && replayed.ok());
  EXPECT_FALSE(replayed->warmStarted);
  EXPECT_FALSE(traced->raysReused);
  EXPECT_TRUE(replayed->raysReused);
  EXPECT_EQ(replayed->rays, first->rays);
  EXPECT_EQ(replayed->passes, traced->passes);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(replayed->lights[0].radiance[c] / traced->lights[0].radiance[c], 1.0, 1e-6) << c;
  EXPECT_NEAR(replayed->fitRmsLog, traced->fitRmsLog, 1e-6);
  EXPECT_LT(largestRelativeDifference(replayed->gathered, traced->gathered, 1e-3), 1e-5);
  EXPECT_LT(largestRelativeDifference(replayed->physicalAlbedo, traced->physicalAlbedo, 1e-3), 1e-5);
  EXPECT_LT(largestRelativeDifference(replayed->albedo, traced->albedo, 1e-2), 1e-3);
  // The moved light changed the estimate: the replay is not the first estimate returned again.
  EXPECT_GT(std::abs(traced->lights[0].radiance[1] / first->lights[0].radiance[1] - 1), 1e-4);
}

// A decomposition report or note without its clock ("after 30 iterations (0.06 s)").
std::string withoutSeconds(const std::string& text) {
  static const std::regex seconds(R"( \([0-9.]+ s\))");
  return std::regex_replace(text, seconds, "");
}

// What finishDecomposition must give: the estimate made without deferring, value for value.
void expectTheSameDecomposition(const LightingEstimate& a, const LightingEstimate& b) {
  EXPECT_FALSE(a.pendingDecomposition);
  EXPECT_TRUE(a.albedo.data == b.albedo.data);
  EXPECT_TRUE(a.direct.data == b.direct.data);
  EXPECT_TRUE(a.retinexAlbedo.data == b.retinexAlbedo.data);
  EXPECT_TRUE(a.decomposeStart.data == b.decomposeStart.data);
  EXPECT_EQ(a.decomposeValid, b.decomposeValid);
  EXPECT_EQ(a.decomposeClipped, b.decomposeClipped);
  EXPECT_EQ(withoutSeconds(a.decomposeReport), withoutSeconds(b.decomposeReport));
  EXPECT_EQ(a.decomposeConverged, b.decomposeConverged);
  EXPECT_EQ(a.decomposeHistory.size(), b.decomposeHistory.size());
  ASSERT_EQ(a.notes.size(), b.notes.size());
  for (size_t i = 0; i < a.notes.size(); ++i)
    EXPECT_EQ(withoutSeconds(a.notes[i]), withoutSeconds(b.notes[i]));
  ASSERT_EQ(a.surfaceMeanAlbedo.size(), b.surfaceMeanAlbedo.size());
  for (size_t s = 0; s < a.surfaceMeanAlbedo.size(); ++s)
    EXPECT_EQ(a.surfaceMeanAlbedo[s], b.surfaceMeanAlbedo[s]) << s;
  for (float v : a.albedo.data) ASSERT_TRUE(std::isfinite(v) && v >= 0 && v <= 1);
}

// LightingOptions::deferDecomposition: the estimate returns after the light fit with its
// residuals and lights (the same as without deferring) and the decomposition pending;
// finishDecomposition then gives the estimate made without deferring, value for value, and a
// second call changes nothing; the gathered light doubled after the estimate does not reach it.
// Also on stiff photos (half black, NaN and saturated pixels), a
// 12 x 9 photo, the decomposition off (nothing pending) and a refusal (a black photo: the same
// error); cancelled before it finishes, the decomposition stops with a note and finite values.
TEST(Lighting, ADeferredDecompositionGivesWhatTheEstimateGives) {
  const RefitCase k = refitCase();
  ASSERT_TRUE(k.first);
  const SyntheticRoom& r = k.r;
  const ImageF mixed = withBlackNanAndSaturatedPixels(k.photo, 4);
  const SyntheticRoom tiny = makeRoom(Vec3(6.0, 5.0, 4.0), 4, 12);
  const ImageF black(k.photo.width, k.photo.height, 3, 0.f);
  LightingOptions plainRetinex = k.opt;
  plainRetinex.objective = false;
  struct Case {
    const char* name;
    const SyntheticRoom& room;
    const ImageF& photo;
    ImageF mask;
    LightingOptions opt;
  };
  const Case cases[] = {{"clipped tenth", r, k.photo, k.mask, k.opt},
                        {"black, NaN and saturated pixels", r, mixed, k.mask, k.opt},
                        {"12 x 9", tiny, tiny.photo, lightMaskOf(tiny), k.opt},
                        {"no decomposition", r, k.photo, k.mask, plainRetinex},
                        {"black", r, black, k.mask, k.opt}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    auto light =
        lightFromOutline(c.room.camera, c.room.geometry, c.room.lightOutlinePx, "lights[0].points");
    ASSERT_TRUE(light.ok());
    LightingOptions deferring = c.opt;
    deferring.deferDecomposition = true;
    const auto whole =
        estimateLighting(c.photo, c.room.camera, c.room.geometry, {*light}, {true}, c.mask, {}, c.opt);
    auto deferred = estimateLighting(c.photo, c.room.camera, c.room.geometry, {*light}, {true}, c.mask,
                                     {}, deferring);
    ASSERT_EQ(whole.ok(), deferred.ok());
    if (!whole.ok()) {
      EXPECT_EQ(whole.error().message(), deferred.error().message());
      continue;
    }
    EXPECT_FALSE(whole->pendingDecomposition);
    EXPECT_EQ(bool(deferred->pendingDecomposition), c.opt.objective);
    EXPECT_EQ(deferred->fitRmsLog, whole->fitRmsLog);
    EXPECT_EQ(deferred->fitResidualRelative, whole->fitResidualRelative);
    EXPECT_EQ(deferred->lights[0].radiance, whole->lights[0].radiance);
    if (c.opt.objective) {
      EXPECT_FALSE(deferred->albedo.data == whole->albedo.data);  // still the light fit's
    }
    // The gathered light changed after the estimate (the pipeline's sun ratio does): the
    // decomposition still reads the estimate's.
    for (float& v : deferred->gathered.data) v *= 2;
    EXPECT_FALSE(finishDecomposition(*deferred, c.room.geometry));
    expectTheSameDecomposition(*deferred, *whole);
    EXPECT_FALSE(finishDecomposition(*deferred, c.room.geometry));  // nothing pending: no change
    expectTheSameDecomposition(*deferred, *whole);
  }
  // Cancelled between the light fit and the decomposition: it stops at once, says so, finite.
  CancelToken cancel;
  LightingOptions deferring = k.opt;
  deferring.deferDecomposition = true;
  deferring.cancel = &cancel;
  auto light = lightFromOutline(r.camera, r.geometry, r.lightOutlinePx, "lights[0].points");
  ASSERT_TRUE(light.ok());
  auto deferred =
      estimateLighting(k.photo, r.camera, r.geometry, {*light}, {true}, k.mask, {}, deferring);
  ASSERT_TRUE(deferred.ok());
  cancel.cancel();
  const auto error = finishDecomposition(*deferred, r.geometry);
  if (!error) {
    EXPECT_FALSE(deferred->decomposeConverged);
    EXPECT_NE(deferred->decomposeReport.find("cancel"), std::string::npos) << deferred->decomposeReport;
  }
  for (float v : deferred->albedo.data) ASSERT_TRUE(std::isfinite(v) && v >= 0 && v <= 1);
}

// A refit that goes on from the first estimate's passes (LightingOptions::warmStart, the default)
// runs fewer passes than one starting cold from the same rays and gives the same lights within a
// percent (the refitCase: a light moved 15 cm, a tenth of the room clipped).
TEST(Lighting, AWarmStartedRefitRunsFewerPassesToTheSameLights) {
  const RefitCase k = refitCase();
  ASSERT_TRUE(k.first);
  EXPECT_FALSE(k.first->warmStarted);  // nothing to go on from
  LightingOptions cold = k.opt, warm = k.opt;
  cold.reuseRays = warm.reuseRays = k.first->rays;
  cold.warmStart = false;
  const SyntheticRoom& r = k.r;
  const auto a = estimateLighting(k.photo, r.camera, r.geometry, {k.moved}, {true}, k.mask, {}, cold);
  const auto b = estimateLighting(k.photo, r.camera, r.geometry, {k.moved}, {true}, k.mask, {}, warm);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_FALSE(a->warmStarted);
  EXPECT_TRUE(b->warmStarted);
  EXPECT_LT(b->passes, a->passes);
  // What it saves is passes (each a gather and a light fit); the light fit's solver iterations
  // are about the same in all (168 against 152 here: fewer passes, each from further away).
  EXPECT_LT(b->fitIterations, 1.25 * a->fitIterations) << b->passes << " passes against " << a->passes;
  for (int c = 0; c < 3; ++c) {
    ASSERT_TRUE(std::isfinite(b->lights[0].radiance[c]));
    EXPECT_NEAR(b->lights[0].radiance[c] / a->lights[0].radiance[c], 1.0, 0.01) << c;
  }
  // Going on from the first estimate's passes ends elsewhere on the passes' path: it moves the
  // fit's residual (0.0530 against 0.0505 here) and single pixels' Gamma (up to 11 %), not its
  // mean or the lights.
  EXPECT_NEAR(b->fitRmsLog, a->fitRmsLog, 0.1 * a->fitRmsLog);
  auto mean = [](const ImageF& g) {
    return std::accumulate(g.data.begin(), g.data.end(), 0.0) /
           double(std::max<size_t>(1, g.data.size()));
  };
  EXPECT_NEAR(mean(b->gathered) / mean(a->gathered), 1.0, 0.02);
}

// Rays traced for another photo, camera or room are not replayed: the estimate traces its own
// and gives exactly what it gives without them. A sun room: its sunlit patch's bounce is
// gathered from the rays too.
TEST(Lighting, RaysOfAnotherPhotoCameraOrRoomAreTracedAgain) {
  SyntheticRoom r = emptyRoom();
  const SunLight sun = sunThroughWindow(r, Vec3(5, 4.6, 4)).sun;
  r.photo = renderRoom(r, {}, {sun}, 8);
  ImageF photo = r.photo;
  for (float& v : photo.data) v = std::min(v, 1.f);
  LightingOptions opt;
  opt.gatherSamples = 16;
  opt.gatherStride = 3;
  opt.threads = 2;
  const auto plain = estimateLighting(photo, r.camera, r.geometry, {}, {}, ImageF(), {sun}, opt);
  ASSERT_TRUE(plain.ok()) << plain.error().message();
  ImageF brighter = photo;
  brighter.data[size_t(brighter.data.size() / 2)] += 0.01f;  // one value of one pixel
  const auto other = estimateLighting(brighter, r.camera, r.geometry, {}, {}, ImageF(), {sun}, opt);
  ASSERT_TRUE(other.ok());
  Camera turned = r.camera;
  turned.focalPx *= 1.001;
  const auto otherCamera = estimateLighting(photo, turned, r.geometry, {}, {}, ImageF(), {sun}, opt);
  SyntheticRoom wider = emptyRoom();
  RoomBox box = wider.geometry.box;
  box.xRightM += 0.01;
  const SceneGeometry otherRoom = buildSceneGeometry(box, {});
  const auto roomRays = estimateLighting(photo, r.camera, otherRoom, {}, {}, ImageF(), {sun}, opt);
  ASSERT_TRUE(otherCamera.ok() && roomRays.ok());
  const char* what[] = {"another photo", "another camera", "another room"};
  int k = 0;
  for (const auto* given : {&*other, &*otherCamera, &*roomRays}) {
    SCOPED_TRACE(what[k++]);
    LightingOptions reuse = opt;
    reuse.reuseRays = given->rays;
    const auto again = estimateLighting(photo, r.camera, r.geometry, {}, {}, ImageF(), {sun}, reuse);
    ASSERT_TRUE(again.ok());
    EXPECT_FALSE(again->raysReused);
    EXPECT_NE(again->rays, given->rays);
    EXPECT_EQ(again->suns[0].irradianceOverPi, plain->suns[0].irradianceOverPi);
    EXPECT_EQ(again->gathered.data, plain->gathered.data);
  }
  // Its own rays are replayed, and give the same sun.
  LightingOptions own = opt;
  own.reuseRays = plain->rays;
  const auto replayed = estimateLighting(photo, r.camera, r.geometry, {}, {}, ImageF(), {sun}, own);
  ASSERT_TRUE(replayed.ok());
  EXPECT_TRUE(replayed->raysReused);
  ASSERT_EQ(replayed->sunBounce.size(), plain->sunBounce.size());
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(replayed->suns[0].irradianceOverPi[c] / plain->suns[0].irradianceOverPi[c], 1.0, 1e-6);
  EXPECT_LT(largestRelativeDifference(replayed->gathered, plain->gathered, 1e-3), 1e-5);
}

// The light fit's model of a ceiling the camera does not see (LightingOptions::
// fitUnseenCeilingAlbedo, a diagnostic oracle): a sconce in a room with dark walls under a white
// ceiling that the photo does not show. The fit explains each surface as rho (L E + Gamma), and
// only the part of Gamma the photo shows (the seen walls' radiance) has an absolute scale; the
// unseen ceiling's bounce is proportional to L itself (from the previous pass's lights). So the
// brighter the fit's unseen ceiling, the brighter the fitted light: here 0.94 times the truth
// with the walls' mean (the product's rule) and about 2 times with the true white ceiling, the
// passes feeding the light's own bounce back (docs/generalization.md, "The lights' intensity
// and the unseen ceiling"; t09 0.75 -> 1.14). A ceiling override that is negative or not finite
// is no override: the same lights, finite.
// A sconce in view on dark walls (0.3) under a white ceiling (0.85) the photo does not show:
// a 0.3 x 0.3 m panel on the back wall, 2 m up (0.7 m under the ceiling), radiance 60, rendered
// with 32 samples.
// (Other walls', ceiling's and floor's albedos: `wall`, `ceiling`, `floor`.)
SyntheticRoom sconceUnderAnUnseenCeiling(const Vec3& wall = Vec3(0.3, 0.3, 0.3),
                                         const Vec3& ceiling = Vec3(0.85, 0.85, 0.85),
                                         const Vec3& floor = Vec3(0.3, 0.3, 0.3)) {
  SyntheticRoom r = emptyRoom();
  r.camera.worldFromCamera = Eigen::AngleAxisd(-14 * M_PI / 180, Vec3::UnitX()).toRotationMatrix();
  r.albedo = {floor, ceiling, wall, wall, wall, wall};
  const double z = -5.499;
  r.light.cornersWorld = {Vec3(0.85, 1.85, z), Vec3(1.15, 1.85, z), Vec3(1.15, 2.15, z),
                          Vec3(0.85, 2.15, z)};
  if (r.light.normal().z() < 0) std::swap(r.light.cornersWorld[1], r.light.cornersWorld[3]);
  r.light.radiance = Vec3(60, 60, 60);
  for (const Vec3& c : r.light.cornersWorld) {
    const auto p = r.camera.project(c);
    EXPECT_TRUE(p && p->x() > 0 && p->x() < 160 && p->y() > 0 && p->y() < 120);  // in view
    if (p) r.lightOutlinePx.push_back(*p);
  }
  r.photo = renderRoom(r, {r.light}, {}, 32);
  int ceilingPixels = 0;
  for (int y = 0; y < 120; ++y)
    for (int px = 0; px < 160; ++px) {
      const auto h = r.geometry.intersect(r.camera.rayThroughPixel(Vec2(px + 0.5, y + 0.5)));
      ceilingPixels += h && r.geometry.surfaces[size_t(h->surfaceId)].kind == SurfaceKind::Ceiling;
    }
  EXPECT_EQ(ceilingPixels, 0);  // the photo shows no ceiling
  return r;
}

// The fitted sconce over the truth (green) with the fit's unseen ceiling `fitCeiling` (negative:
// the product's rule) and the unseen bounce in the fit as a term of the light or not; NaN when
// the estimate fails. Every albedo and gathered value finite.
double sconceRatio(const SyntheticRoom& r, const Vec3& fitCeiling, bool bounceScales) {
  LightingOptions o;
  o.gatherSamples = 32;
  o.gatherStride = 4;
  o.fitUnseenCeilingAlbedo = fitCeiling;
  o.fitUnseenCeiling = false;  // negative fitCeiling: the walls' mean
  o.unseenBounceScalesWithLights = bounceScales;
  const auto est =
      estimateLighting(r.photo, r.camera, r.geometry, {r.light}, {true}, lightMaskOf(r), {}, o);
  EXPECT_TRUE(est.ok()) << est.error().message();
  if (!est.ok()) return std::numeric_limits<double>::quiet_NaN();
  for (float v : est->albedo.data) EXPECT_TRUE(std::isfinite(v));
  for (float v : est->gathered.data) EXPECT_TRUE(std::isfinite(v) && v >= 0);
  return est->lights[0].radiance[1] / r.light.radiance[1];
}

// The light fit's model of a ceiling the camera does not see (LightingOptions::
// fitUnseenCeilingAlbedo, a diagnostic oracle). The fit explains each surface as rho (L E + Gamma),
// and only the part of Gamma the photo shows (the seen walls' radiance) has an absolute scale;
// the unseen ceiling's bounce is proportional to L itself. Held fixed at the previous pass's
// lights, the passes fed the light's own bounce back: with the true white ceiling in the fit the
// sconce came out about 2 times the truth (docs/generalization.md, "The lights' intensity and the
// unseen ceiling"). Its first bounce taken as a term of the light (LightingOptions::
// unseenBounceScalesWithLights), the true ceiling gives the light within 20 % (0.83: the higher
// bounces stay fixed; docs/generalization.md, "The unseen room's bounce in the light fit"). A
// ceiling override that is negative or not finite is no override: the same lights, finite.
TEST(Lighting, TheUnseenCeilingInTheFitSetsTheLightsIntensity) {
  const SyntheticRoom r = sconceUnderAnUnseenCeiling();
  const Vec3 ceiling = r.albedo[1];
  const double rule = sconceRatio(r, Vec3::Constant(-1), true), truth = sconceRatio(r, ceiling, true);
  const double fixedTruth = sconceRatio(r, ceiling, false);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::printf("sconce / truth: walls' mean in the fit %.3f, true ceiling %.3f (bounce fixed: %.3f)\n",
              rule, truth, fixedTruth);
  ASSERT_TRUE(std::isfinite(rule) && std::isfinite(truth) && rule > 0 && truth > 0);
  // The fit's dark ceiling (the walls' 0.3 against 0.85) bounces too little of the light: the
  // light comes out brighter than with the true ceiling (with the bounce fixed it was darker,
  // 0.94 against 2.07).
  EXPECT_GT(rule, truth);
  EXPECT_LT(rule, 1.6);
  EXPECT_NEAR(truth, 1.0, 0.2);  // with the bounce fixed: about 2
  EXPECT_LT(std::abs(truth - 1), std::abs(fixedTruth - 1));
  EXPECT_EQ(sconceRatio(r, Vec3(nan, 0.5, 0.5), true), rule);  // not an override: the rule
  EXPECT_EQ(sconceRatio(r, Vec3(0.5, -0.1, 0.5), true), rule);
}

// The unseen bounce as a term of the light on stiff inputs: an unseen ceiling of albedo 0 (no
// bounce from it), 1e6 (a bounce far beyond the photo), a light kept at radiance 0 and at 1e6,
// and a photo of 4 x 3 pixels (almost all the room unseen): finite lights, albedo and Gamma.
TEST(Lighting, TheUnseenBounceTermStaysFiniteOnStiffInputs) {
  const SyntheticRoom r = sconceUnderAnUnseenCeiling();
  for (const double ceiling : {0.0, 1e6}) {
    const double ratio = sconceRatio(r, Vec3::Constant(ceiling), true);
    EXPECT_TRUE(std::isfinite(ratio) && ratio >= 0) << "unseen ceiling " << ceiling;
  }
  LightingOptions o;
  o.gatherSamples = 16;
  o.gatherStride = 4;
  for (const double given : {0.0, 1e6}) {
    AreaLight kept = r.light;
    kept.radiance = Vec3::Constant(given);
    const auto est =
        estimateLighting(r.photo, r.camera, r.geometry, {kept}, {false}, lightMaskOf(r), {}, o);
    ASSERT_TRUE(est.ok()) << est.error().message();
    EXPECT_EQ(est->lights[0].radiance, kept.radiance);
    for (float v : est->albedo.data) ASSERT_TRUE(std::isfinite(v) && v >= 0 && v <= 1) << given;
    for (float v : est->gathered.data) ASSERT_TRUE(std::isfinite(v) && v >= 0) << given;
  }
  Camera tiny = r.camera;
  tiny.widthPx = 4, tiny.heightPx = 3, tiny.focalPx = 3, tiny.principalPx = Vec2(2, 1.5);
  ImageF photo(4, 3, 3, 0.f);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) photo.setRgb(x, y, Vec3(0.2 + 0.05 * x, 0.3, 0.25 + 0.05 * y));
  const auto est = estimateLighting(photo, tiny, r.geometry, {r.light}, {true}, ImageF(), {}, o);
  if (est.ok()) {
    for (float v : est->gathered.data) EXPECT_TRUE(std::isfinite(v) && v >= 0);
    EXPECT_TRUE(est->lights[0].radiance.allFinite());
  } else {
    EXPECT_FALSE(est.error().message().empty());
  }
}

// t04's albedos on the synthetic room: walls 0.45, a floor 0.5 the sun patch clips, a white
// ceiling (0.88) the camera does not see, a blue sky through a window out of view and a warm sun
// (t04's radiances). The sun room's passes go on to a fixed point (LightingOptions::
// sunRoomToFixedPoint): the sky of either window within 10 % (measured: back wall 1.01 / 1.03 /
// 1.05, left wall 0.93 / 0.94 / 0.95), the sun within 25 % (0.80-0.82, 0.76-0.78). Stopped after
// two passes, as before, the left (side) wall's sky was 0.70 / 0.74 / 0.81 and its sun 0.61-0.70,
// as on t04. The truth's ceiling inside the fit (fitUnseenCeilingAlbedo), printed for the record,
// makes both too bright (1.3-1.5). docs/generalization.md, "The sun room's passes to a fixed
// point". Measured with the fit's unseen ceiling at the walls' mean (the rule before
// LightingOptions::sunRoomUnseenCeilingAtLeast, whose lights SunRoomAlbedoWithTheUnseenCeiling
// AtLeastWhite checks).
TEST(Lighting, TheSkyOfAWindowOutOfViewUnderAWhiteUnseenCeiling) {
  SyntheticRoom r = whiteCeilingSunRoom();
  for (const bool leftWall : {false, true}) {
    SunWindow sw = sunThroughWindow(r, Vec3(3.3, 3.1, 2.7), leftWall);
    sw.window.radiance = Vec3(2.4, 3.05, 4.4);
    const ImageF photo = clippedSunPhoto(r, sw);
    const auto opening = openingOfBeam(sw.sun, r.camera, r.geometry);
    ASSERT_TRUE(opening.has_value());
    ASSERT_LT(opening->visibleShare, 0.5) << "the window must be out of view";
    for (const bool trueCeiling : {false, true}) {
      LightingOptions opt = sunRoomOptions();
      opt.sunRoomUnseenCeilingAtLeast = 0;  // the walls' mean: the passes' fixed point alone
      if (trueCeiling) opt.fitUnseenCeilingAlbedo = r.albedo[1];
      const auto est = estimateLighting(photo, r.camera, r.geometry, {opening->light}, {true}, ImageF(),
                                        {sw.sun}, opt);
      ASSERT_TRUE(est.ok()) << est.error().message();
      const Vec3 sky = est->lights[0].radiance.cwiseQuotient(sw.window.radiance);
      const Vec3 sun = est->suns[0].irradianceOverPi.cwiseQuotient(sw.sun.irradianceOverPi);
      std::printf("window in the %s wall, %s: sky / true %.2f %.2f %.2f, sun / true %.2f %.2f %.2f\n",
                  leftWall ? "left" : "back",
                  trueCeiling ? "the truth's ceiling in the fit" : "the product", sky.x(), sky.y(),
                  sky.z(), sun.x(), sun.y(), sun.z());
      if (trueCeiling) continue;
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(sky[c], 1.0, 0.1) << "channel " << c;
        EXPECT_NEAR(sun[c], 1.0, 0.3) << "channel " << c;
      }
    }
  }
}

// The same rooms lit by the sky alone (no sun, no clipped patch: the fit's plain passes) give the
// sky of either window within 15 % (measured: back wall 1.09 / 1.09 / 1.10, left wall 0.94 /
// 0.94 / 0.95). With the sun, its passes settled, the side window's sky is the sky alone's within
// 0.1 (measured 0.01 left, 0.04-0.08 back; stopped after two passes the left was 0.24 lower), and
// going on to 8 passes changes it by less than 3 % (two, three and four passes swung by up to
// 0.3 before).
// (The fit's unseen ceiling at the walls' mean, as above.)
TEST(Lighting, TheSkyOfASideWindowAloneIsFittedRight) {
  SyntheticRoom r = whiteCeilingSunRoom();
  LightingOptions opt = sunRoomOptions();
  opt.sunRoomUnseenCeilingAtLeast = 0;  // the walls' mean: the passes' fixed point alone
  for (const bool leftWall : {false, true}) {
    SunWindow sw = sunThroughWindow(r, Vec3(3.3, 3.1, 2.7), leftWall);
    sw.window.radiance = Vec3(2.4, 3.05, 4.4);
    const auto opening = openingOfBeam(sw.sun, r.camera, r.geometry);
    ASSERT_TRUE(opening.has_value());
    ImageF skyOnly = renderRoom(r, {sw.window}, {}, 32);
    for (float& v : skyOnly.data) v = std::min(v, 1.f);
    const auto est =
        estimateLighting(skyOnly, r.camera, r.geometry, {opening->light}, {true}, ImageF(), {}, opt);
    ASSERT_TRUE(est.ok()) << est.error().message();
    const Vec3 sky = est->lights[0].radiance.cwiseQuotient(sw.window.radiance);
    std::printf("window in the %s wall, the sky alone: sky / true %.2f %.2f %.2f\n",
                leftWall ? "left" : "back", sky.x(), sky.y(), sky.z());
    const ImageF photo = clippedSunPhoto(r, sw);
    std::array<Vec3, 2> withSun;
    for (const int passes : {5, 8}) {
      LightingOptions o = opt;
      o.maxPasses = passes;
      const auto e =
          estimateLighting(photo, r.camera, r.geometry, {opening->light}, {true}, ImageF(), {sw.sun}, o);
      ASSERT_TRUE(e.ok()) << e.error().message();
      withSun[passes == 8] = e->lights[0].radiance.cwiseQuotient(sw.window.radiance);
      const Vec3& s = withSun[passes == 8];
      std::printf("  with the sun, at most %d passes (%d run): sky / true %.2f %.2f %.2f\n", passes,
                  e->passes, s.x(), s.y(), s.z());
    }
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(sky[c], 1.0, 0.15) << "channel " << c;
      EXPECT_NEAR(withSun[0][c], sky[c], 0.1) << "channel " << c;
      EXPECT_NEAR(withSun[1][c], withSun[0][c], 0.03) << "channel " << c;
    }
  }
}

// The sun room's passes on stiff inputs: a sun so strong that its patch clips in every channel
// far above the clip level, a black sky (the window sends nothing), a sun at a grazing angle to
// the floor, and passes capped at the least the scheme runs (3): finite lights and albedo, and
// where the passes did not settle a note says so.
TEST(Lighting, TheSunRoomsPassesStayFiniteOnStiffInputs) {
  SyntheticRoom r = whiteCeilingSunRoom();
  struct Case {
    const char* name;
    Vec3 sun, sky, travel;
    int maxPasses;
  };
  const Vec3 grazing = Vec3(1.0, -0.12, 0.2).normalized(), blue(2.4, 3.05, 4.4), warm(3.3, 3.1, 2.7);
  const Vec3 none = Vec3::Zero();  // the window's own sun direction
  for (const Case& k :
       {Case{"patch clipped far above", Vec3(300, 280, 250), blue, none, 5},
        Case{"black sky", warm, none, none, 5}, Case{"grazing sun", warm, blue, grazing, 5},
        Case{"three passes", warm, blue, none, 3}}) {
    SunWindow sw = sunThroughWindow(r, k.sun, true);
    sw.window.radiance = k.sky;
    if (k.travel.norm() > 0) sw.sun.travelDirection = k.travel;
    const ImageF photo = clippedSunPhoto(r, sw);
    // The product's opening (widened by the reveal; the beam of a thin window: the window and
    // a strip above it).
    const auto opening = openingOfBeam(sw.sun, r.camera, r.geometry, 50, kWindowRevealDepthM);
    std::vector<AreaLight> lights;
    if (opening) lights.push_back(opening->light);
    LightingOptions o = sunRoomOptions();
    o.maxPasses = k.maxPasses;
    const auto est = estimateLighting(photo, r.camera, r.geometry, lights,
                                      std::vector<bool>(lights.size(), true), ImageF(), {sw.sun}, o);
    ASSERT_TRUE(est.ok()) << k.name << ": " << est.error().message();
    for (const auto& l : est->lights)
      EXPECT_TRUE(l.radiance.allFinite() && (l.radiance.array() >= 0).all());
    const Vec3 sun = est->suns[0].irradianceOverPi;
    EXPECT_TRUE(sun.allFinite() && (sun.array() >= 0).all()) << k.name;
    for (float v : est->albedo.data) ASSERT_TRUE(std::isfinite(v) && v >= 0 && v <= 1) << k.name;
    for (float v : est->gathered.data) ASSERT_TRUE(std::isfinite(v) && v >= 0) << k.name;
    EXPECT_GE(est->passes, 3) << k.name;
    EXPECT_LE(est->passes, k.maxPasses) << k.name;
    const bool noted = std::any_of(est->notes.begin(), est->notes.end(), [](const std::string& n) {
      return n.find("gathered light still changed") != std::string::npos;
    });
    // The unseen ceiling (0.88) under walls of 0.45: lifted in the fit's model, and said so.
    EXPECT_TRUE(std::any_of(est->notes.begin(), est->notes.end(), [](const std::string& n) {
      return n.find("the ceiling the camera does not see") != std::string::npos;
    })) << k.name;
    std::printf("%s: %d passes%s, sun %.3g %.3g %.3g, sky %s\n", k.name, est->passes,
                noted ? " (noted: not settled)" : "", sun.x(), sun.y(), sun.z(),
                lights.empty() ? "none" : std::to_string(est->lights[0].radiance.y()).c_str());
    if (noted) {
      EXPECT_EQ(est->passes, k.maxPasses) << k.name;
    }
    if (k.maxPasses == 3) {
      EXPECT_TRUE(noted) << k.name;  // too few to tell it settled
    }
    if (lights.size() == 1 && k.sky.norm() == 0) {
      EXPECT_LT(est->lights[0].radiance.maxCoeff(), 1.0) << k.name;
    }
  }
}

// The light fit on a synthetic sun room (`r`, the window out of view in the left wall or the back
// wall, sky `sky`, sun `sun`, the photo clipped at 1) with the fit's model of the unseen ceiling
// at least `ceilingAtLeast` (LightingOptions::fitUnseenCeilingAtLeast): the sky and the sun over
// the truth, and the albedo's mean absolute error and its best single scale over the room pixels
// the photo shows (score_albedo.py's measure). Every albedo and gathered value finite.
struct SunRoomAlbedo {
  Vec3 sky, sun;
  Vec3 skyPower;  // the sky's radiance x the opening's area over the truth's
  double mae = 0, scale = 0;
  bool noted = false;  // the estimate's notes say the unseen ceiling was lifted
};
SunRoomAlbedo sunRoomAlbedo(SyntheticRoom r, const Vec3& sun, const Vec3& sky, bool leftWall,
                            double ceilingAtLeast, double wallDepth = 0, double revealDepth = 0) {
  SunWindow sw = sunThroughWindow(r, sun, leftWall, wallDepth);
  sw.window.radiance = sky;
  const ImageF photo = clippedSunPhoto(r, sw);
  const auto opening = openingOfBeam(sw.sun, r.camera, r.geometry, 50, revealDepth);
  EXPECT_TRUE(opening.has_value());
  if (!opening) return {};
  LightingOptions opt = sunRoomOptions();
  opt.sunRoomUnseenCeilingAtLeast = ceilingAtLeast;
  const auto est =
      estimateLighting(photo, r.camera, r.geometry, {opening->light}, {true}, ImageF(), {sw.sun}, opt);
  EXPECT_TRUE(est.ok()) << est.error().message();
  if (!est.ok()) return {};
  for (float v : est->gathered.data) EXPECT_TRUE(std::isfinite(v) && v >= 0);
  SunRoomAlbedo out;
  out.sky = est->lights[0].radiance.cwiseQuotient(sw.window.radiance);
  out.skyPower = out.sky * (opening->light.area() / sw.window.area());
  out.sun = est->suns[0].irradianceOverPi.cwiseQuotient(sw.sun.irradianceOverPi);
  out.noted = std::any_of(est->notes.begin(), est->notes.end(), [](const std::string& n) {
    return n.find("the ceiling the camera does not see") != std::string::npos;
  });
  double err = 0, te = 0, ee = 0;
  long n = 0;
  for (int y = 0; y < photo.height; ++y)
    for (int x = 0; x < photo.width; ++x) {
      const auto h = r.geometry.intersect(r.camera.rayThroughPixel(Vec2(x + 0.5, y + 0.5)));
      if (!h) continue;
      const Vec3 a = est->albedo.rgb(x, y), t = r.albedo[size_t(h->surfaceId)];
      EXPECT_TRUE(a.allFinite());
      err += (a - t).cwiseAbs().sum() / 3, te += t.dot(a), ee += a.dot(a), ++n;
    }
  out.mae = n ? err / double(n) : 0;
  out.scale = ee > 0 ? te / ee : 0;
  return out;
}

// The fit's model of a sun room's unseen ceiling at least white grey (LightingOptions::
// sunRoomUnseenCeilingAtLeast) on the synthetic sun rooms: t04's albedos (walls 0.45, floor 0.5,
// a white ceiling 0.88 the camera does not see, the patch clipped at about 1.5 times the clip
// level) with the window out of view in the back wall and in the left wall, and a room with dark
// walls (0.28, t10's) whose patch clips at about 15 times. With the walls' mean the albedo came
// out 1.3 to 1.8 times too bright (best scale 0.74, 0.76, 0.56; MAE 0.134, 0.151, 0.309): the
// sunlit patch's bounce off the ceiling is much of the seen walls' light. With the rule, measured:
// MAE 0.085, 0.067, 0.215, scale 0.99, 0.95, 0.79; the lights go up (t04's: sky 1.35 / 1.19, sun
// 1.08-1.13 / 0.99-1.06 of the truth, against 1.02 / 0.94 and 0.79 / 0.77 before), the dark room's
// stay wrong in colour either way (sky 0.44 / 0.66 / 1.59, sun 0.40 / 0.61 / 2.54). (The dark room
// with the window in the back wall, not run here for time: MAE 0.207 -> 0.274, worse.)
// docs/generalization.md, "The sun rooms' albedo: the unseen ceiling".
TEST(Lighting, SunRoomAlbedoWithTheUnseenCeilingAtLeastWhite) {
  struct Case {
    const char* name;
    Vec3 wall, ceiling, sun;
    bool leftWall;
  };
  const Vec3 sky(2.4, 3.05, 4.4), t04Wall(0.45, 0.45, 0.48), t04Ceiling(0.88, 0.88, 0.9);
  for (const Case& k : {Case{"t04-like", t04Wall, t04Ceiling, Vec3(3.3, 3.1, 2.7), false},
                        Case{"t04-like", t04Wall, t04Ceiling, Vec3(3.3, 3.1, 2.7), true},
                        Case{"dark walls, patch 15x", Vec3(0.28, 0.28, 0.3), Vec3(0.84, 0.81, 0.82),
                             Vec3(33, 31, 27), true}}) {
    SyntheticRoom r = roomLookingDown();
    r.albedo = {Vec3(0.5, 0.47, 0.45), k.ceiling, k.wall, k.wall, k.wall, k.wall};
    std::array<SunRoomAlbedo, 2> a;
    for (const bool rule : {false, true}) {
      a[rule] = sunRoomAlbedo(r, k.sun, sky, k.leftWall, rule ? kUnseenCeilingAlbedo : 0.0);
      std::printf(
          "%s, window %s, ceiling at least %.2f: albedo MAE %.4f scale %.3f, sky %.2f %.2f "
          "%.2f, sun %.2f %.2f %.2f, note %s\n",
          k.name, k.leftWall ? "left" : "back", rule ? kUnseenCeilingAlbedo : 0.0, a[rule].mae,
          a[rule].scale, a[rule].sky.x(), a[rule].sky.y(), a[rule].sky.z(), a[rule].sun.x(),
          a[rule].sun.y(), a[rule].sun.z(), a[rule].noted ? "yes" : "no");
    }
    SCOPED_TRACE(std::string(k.name) + (k.leftWall ? ", window left" : ", window back"));
    EXPECT_LT(a[1].mae, 0.75 * a[0].mae);  // measured 0.63, 0.44, 0.70
    EXPECT_LT(a[0].scale, 0.8);            // too bright with the walls' mean
    EXPECT_GT(a[1].scale, 0.75);
    EXPECT_LT(a[1].scale, 1.1);
    EXPECT_FALSE(a[0].noted);
    EXPECT_TRUE(a[1].noted);  // the photo does not show the ceiling: said so
    if (k.wall.x() > 0.4)
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(a[1].sun[c], 1.0, 0.25) << "channel " << c;  // 0.79 / 0.77 with the walls' mean
        EXPECT_NEAR(a[1].sky[c], 1.0, 0.45) << "channel " << c;  // 1.02 / 0.94 with the walls' mean
      }
  }
}

// The synthetic sun rooms of SunRoomAlbedoWithTheUnseenCeilingAtLeastWhite (t04's albedos, the
// window out of view in the back or the left wall) with the window through a wall 0.2 m thick:
// the beam is what passes the inner and the outer opening, the sky comes in through the inner
// one. The opening carried back from the beam alone lacks the window's top, and the fit makes
// up for it with a brighter sky (its radiance 1.50 / 1.31 times the truth's in green) and a
// darker albedo (best scale 0.967 / 0.917). Widened by the reveal (PrepareOptions::
// windowRevealDepthM) the opening is the window: the radiance comes closer (1.37 / 1.20), the
// albedo's scale within 3 % (1.017 / 0.977), the sun up by 6 %. Not everything improves: the
// sky's power (radiance x area) overshoots more (1.22 / 1.10 against 1.10 / 0.97: the too
// small window hid the overshoot of the unseen ceiling's rule, "The sun rooms' albedo") and
// the albedo's MAE is no better (0.0811 -> 0.0872, 0.0686 -> 0.0690; measured, printed).
// docs/generalization.md, "The unseen window's reveal".
TEST(Lighting, TheSunRoomsSkyThroughAThickWallsWindow) {
  const Vec3 sky(2.4, 3.05, 4.4), wall(0.45, 0.45, 0.48), ceiling(0.88, 0.88, 0.9);
  for (const bool leftWall : {false, true}) {
    SyntheticRoom r = roomLookingDown();
    r.albedo = {Vec3(0.5, 0.47, 0.45), ceiling, wall, wall, wall, wall};
    std::array<SunRoomAlbedo, 2> a;
    for (const bool reveal : {false, true}) {
      a[reveal] = sunRoomAlbedo(r, Vec3(3.3, 3.1, 2.7), sky, leftWall, kUnseenCeilingAlbedo, 0.2,
                                reveal ? 0.2 : 0.0);
      const SunRoomAlbedo& k = a[reveal];
      std::printf(
          "window %s, opening %s: albedo MAE %.4f scale %.3f, sky %.2f %.2f %.2f (power %.2f %.2f "
          "%.2f), sun %.2f %.2f %.2f\n",
          leftWall ? "left" : "back", reveal ? "widened by the reveal" : "the beam's section", k.mae,
          k.scale, k.sky.x(), k.sky.y(), k.sky.z(), k.skyPower.x(), k.skyPower.y(), k.skyPower.z(),
          k.sun.x(), k.sun.y(), k.sun.z());
    }
    SCOPED_TRACE(leftWall ? "window left" : "window back");
    EXPECT_LT(std::abs(a[1].scale - 1), std::abs(a[0].scale - 1));  // measured 0.02 against 0.03-0.08
    EXPECT_LT(std::abs(a[1].scale - 1), 0.05);
    for (int c = 0; c < 3; ++c) {
      EXPECT_LT(std::abs(a[1].sky[c] - 1), std::abs(a[0].sky[c] - 1)) << "channel " << c;
      EXPECT_GT(a[1].sun[c], a[0].sun[c]) << "channel " << c;
      EXPECT_NEAR(a[1].sun[c], 1.0, 0.25) << "channel " << c;
      EXPECT_NEAR(a[1].skyPower[c], 1.0, 0.35) << "channel " << c;
    }
    EXPECT_LT(a[1].mae, 1.15 * a[0].mae);  // no better: 0.0811 -> 0.0872, 0.0686 -> 0.0690
    // A window with no reveal (a thin wall, a glass door), widened all the same: the opening is
    // too tall by 0.17 m, and the fit spreads the sky over it (printed for the record).
    const SunRoomAlbedo thin =
        sunRoomAlbedo(r, Vec3(3.3, 3.1, 2.7), sky, leftWall, kUnseenCeilingAlbedo, 0.0, 0.2);
    std::printf(
        "window %s in a thin wall, widened: albedo MAE %.4f scale %.3f, sky %.2f (power %.2f), "
        "sun %.2f\n",
        leftWall ? "left" : "back", thin.mae, thin.scale, thin.sky.y(), thin.skyPower.y(), thin.sun.y());
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(thin.sky[c]) && std::isfinite(thin.sun[c]));
  }
}

// The unseen ceiling's albedo as an unknown of the light fit (LightingOptions::fitUnseenCeiling):
// the sconce on dark walls (0.3) under a white ceiling (0.85) the photo does not show. The light
// the ceiling bounces onto the seen walls and floor tells its albedo: the estimate moves from the
// walls' mean (0.3, the prior) most of the way to about 0.5, every channel told, and the sconce
// comes closer to the truth than with the walls' mean in the fit (about 1.2 against 1.43). Not
// all the way: the fit still trades the ceiling's bounce for the light's direct part
// (docs/generalization.md, "The unseen ceiling's albedo as an unknown of the light fit").
// Without the unknown the estimate holds no ceiling albedo (NaN).
TEST(Lighting, TheUnseenCeilingsAlbedoIsToldByTheLightItBouncesOntoTheWalls) {
  const SyntheticRoom r = sconceUnderAnUnseenCeiling();
  LightingOptions o;
  o.gatherSamples = 32;
  o.gatherStride = 4;
  const auto est =
      estimateLighting(r.photo, r.camera, r.geometry, {r.light}, {true}, lightMaskOf(r), {}, o);
  o.fitUnseenCeiling = false;
  const auto rule =
      estimateLighting(r.photo, r.camera, r.geometry, {r.light}, {true}, lightMaskOf(r), {}, o);
  ASSERT_TRUE(est.ok() && rule.ok());
  const double ratio = est->lights[0].radiance[1] / r.light.radiance[1];
  const double ruleRatio = rule->lights[0].radiance[1] / r.light.radiance[1];
  std::printf(
      "unseen ceiling %.3f %.3f %.3f (truth 0.85, walls 0.3); sconce / truth %.3f (walls' mean "
      "in the fit %.3f)\n",
      est->unseenCeilingAlbedo[0], est->unseenCeilingAlbedo[1], est->unseenCeilingAlbedo[2], ratio,
      ruleRatio);
  for (int c = 0; c < 3; ++c) {
    EXPECT_TRUE(est->unseenCeilingTold[size_t(c)]);
    EXPECT_GT(est->unseenCeilingAlbedo[c], 0.42);  // the walls' 0.3 plus 0.12
    EXPECT_LT(est->unseenCeilingAlbedo[c], 1.0);
  }
  EXPECT_LT(std::abs(ratio - 1), std::abs(ruleRatio - 1) - 0.1);
  EXPECT_TRUE(rule->unseenCeilingAlbedo.array().isNaN().all());
}

// Whether one of the estimate's notes speaks of the unseen ceiling.
bool notesTheUnseenCeiling(const LightingEstimate& est) {
  return std::any_of(est.notes.begin(), est.notes.end(),
                     [](const std::string& n) { return n.find("unseen ceiling") != std::string::npos; });
}

// The estimate's lights, unseen ceiling and albedo are finite (its albedo in [0, 1]).
void expectFinite(const LightingEstimate& est, const char* what) {
  SCOPED_TRACE(what);
  for (const AreaLight& l : est.lights) EXPECT_TRUE(l.radiance.allFinite());
  for (float v : est.albedo.data) ASSERT_TRUE(std::isfinite(v) && v >= 0 && v <= 1);
  for (float v : est.gathered.data) ASSERT_TRUE(std::isfinite(v) && v >= 0);
  for (const Vec3& a : est.surfaceMeanAlbedo) EXPECT_TRUE(a.allFinite());
  if (!est.unseenCeilingAlbedo.array().isNaN().all()) {
    EXPECT_TRUE(est.unseenCeilingAlbedo.allFinite());
    EXPECT_TRUE((est.unseenCeilingAlbedo.array() >= 0.05 - 1e-9).all());
    EXPECT_TRUE((est.unseenCeilingAlbedo.array() <= 1 + 1e-9).all());
  }
}

// The unseen ceiling's unknown on stiff inputs. Black walls and floor (0.02) give finite values
// (the log fit still sees the ceiling's share of their light); at 0 the estimate fails with one
// message (nothing to fit). A photo of one flat colour (no shape to tell the ceiling by) and a
// light kept at a quarter of its radiance (the ceiling must explain more light than an albedo
// of 1 can: at its bound) give finite values and a note. A room whose photo shows the ceiling
// estimates none (NaN) and says nothing of it.
TEST(Lighting, TheUnseenCeilingsUnknownStaysFiniteAndSaysWhenNotTold) {
  LightingOptions o;
  o.gatherSamples = 16;
  o.gatherStride = 4;
  const Vec3 dark = Vec3::Constant(0.02);
  const SyntheticRoom black = sconceUnderAnUnseenCeiling(dark, Vec3::Constant(0.85), dark);
  auto est = estimateLighting(black.photo, black.camera, black.geometry, {black.light}, {true},
                              lightMaskOf(black), {}, o);
  ASSERT_TRUE(est.ok()) << est.error().message();
  expectFinite(*est, "black walls");
  const SyntheticRoom zero =
      sconceUnderAnUnseenCeiling(Vec3::Zero(), Vec3::Constant(0.85), Vec3::Zero());
  est = estimateLighting(zero.photo, zero.camera, zero.geometry, {zero.light}, {true}, lightMaskOf(zero),
                         {}, o);
  ASSERT_FALSE(est.ok());  // nothing to fit: one message
  EXPECT_NE(est.error().message().find("black"), std::string::npos) << est.error().message();
  SyntheticRoom flat = sconceUnderAnUnseenCeiling();
  for (float& v : flat.photo.data) v = 0.3f;
  est = estimateLighting(flat.photo, flat.camera, flat.geometry, {flat.light}, {true}, lightMaskOf(flat),
                         {}, o);
  ASSERT_TRUE(est.ok()) << est.error().message();
  expectFinite(*est, "one flat colour");
  EXPECT_TRUE(notesTheUnseenCeiling(*est));
  const SyntheticRoom white = sconceUnderAnUnseenCeiling(Vec3::Constant(0.3), Vec3::Constant(1.0));
  AreaLight half = white.light;
  half.radiance *= 0.25;
  est = estimateLighting(white.photo, white.camera, white.geometry, {half}, {false}, lightMaskOf(white),
                         {}, o);
  ASSERT_TRUE(est.ok()) << est.error().message();
  expectFinite(*est, "at the bound");
  EXPECT_TRUE(notesTheUnseenCeiling(*est));
  const SyntheticRoom seen = makeRoom(Vec3(20, 20, 20), 8);
  est = estimateLighting(seen.photo, seen.camera, seen.geometry, {seen.light}, {true}, lightMaskOf(seen),
                         {}, o);
  ASSERT_TRUE(est.ok()) << est.error().message();
  expectFinite(*est, "the ceiling seen");
  EXPECT_TRUE(est->unseenCeilingAlbedo.array().isNaN().all());
  EXPECT_FALSE(notesTheUnseenCeiling(*est));
}

}  // namespace
}  // namespace inlay
