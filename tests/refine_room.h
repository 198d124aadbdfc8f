// A room with two ceiling lights whose direct light is known, for the light refinement's test
// and benchmark: D = rho * sum_j L_j E_j computed with many more (and other) light samples than
// the refinement uses, so its fixed-sample render never reproduces D exactly.
#pragma once

#include "inlay/lighting/refine.h"
#include "inlay/modeling/camera.h"
#include "inlay/modeling/geometry.h"
#include "inlay/modeling/parallel.h"
#include "inlay/render/path_tracer.h"

#include <tbb/blocked_range.h>

#include <cmath>

namespace inlay::test {

struct RefineRoom {
  Camera camera;
  SceneGeometry geometry;
  ImageF albedo, direct;         // W x H x 3
  std::vector<AreaLight> truth;  // the lights that made `direct`
};

inline AreaLight ceilingPanel(const Vec3& centre, double sx, double sz, double ceilingM,
                              const Vec3& radiance) {
  AreaLight L;
  const double y = ceilingM - 1e-3;
  L.cornersWorld = {Vec3(centre.x() - sx / 2, y, centre.z() - sz / 2),
                    Vec3(centre.x() + sx / 2, y, centre.z() - sz / 2),
                    Vec3(centre.x() + sx / 2, y, centre.z() + sz / 2),
                    Vec3(centre.x() - sx / 2, y, centre.z() + sz / 2)};
  if (L.normal().y() > 0) std::swap(L.cornersWorld[1], L.cornersWorld[3]);
  L.radiance = radiance;
  return L;
}

// W x H photo frame, a 5 x 6 m room 2.7 m high, a warm and a cool panel; per-surface albedo,
// a checker on the floor.
inline RefineRoom makeRefineRoom(int W, int H, int truthSamples) {
  RefineRoom r;
  r.camera = levelCamera(W, H, 0.8 * W, 1.5);
  r.camera.worldFromCamera = Eigen::AngleAxisd(-8 * M_PI / 180, Vec3::UnitX()).toRotationMatrix();
  RoomBox box;
  box.xLeftM = -2.5, box.xRightM = 2.5, box.zBackM = -5.5, box.zRearM = 0.5, box.ceilingM = 2.7;
  r.geometry = buildSceneGeometry(box, {});
  r.truth = {ceilingPanel(Vec3(-1.0, 0, -3.2), 0.6, 0.6, 2.7, Vec3(6, 5, 3.5)),
             ceilingPanel(Vec3(1.1, 0, -2.0), 0.7, 0.5, 2.7, Vec3(3.5, 4, 5))};
  const std::vector<Vec3> surfaceAlbedo = {Vec3(0.35, 0.3, 0.25), Vec3(0.8, 0.8, 0.8),
                                           Vec3(0.6, 0.55, 0.5),  Vec3(0.5, 0.6, 0.55),
                                           Vec3(0.7, 0.65, 0.6),  Vec3(0.6, 0.6, 0.6)};
  r.albedo = ImageF(W, H, 3, 0.f);
  r.direct = ImageF(W, H, 3, 0.f);
  const RoomTracer tracer(r.geometry);
  parallelFor(tbb::blocked_range<int>(0, H), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < W; ++x) {
        const auto h = tracer.intersect(r.camera.rayThroughPixel(Vec2(x + 0.5, y + 0.5)), 1e-6);
        if (!h) continue;
        Vec3 rho = surfaceAlbedo[size_t(h->surfaceId) % surfaceAlbedo.size()];
        if (h->normalWorld.y() > 0.9 &&
            (int(std::floor(2 * h->pointWorld.x())) + int(std::floor(2 * h->pointWorld.z()))) % 2 == 0)
          rho *= 0.5;
        Vec3 e = Vec3::Zero();
        for (size_t j = 0; j < r.truth.size(); ++j)
          e += r.truth[j].radiance *
               tracer.unitLightIrradianceOverPi(r.truth[j], h->pointWorld + 1e-5 * h->normalWorld,
                                                h->normalWorld, truthSamples,
                                                0x9e3779b9u ^ uint32_t(y * W + x + 977 * j));
        r.albedo.setRgb(x, y, rho);
        r.direct.setRgb(x, y, rho.cwiseProduct(e));
      }
  });
  return r;
}

// The truth lights moved by `shiftM` (alternating directions) and their radiance scaled.
inline std::vector<AreaLight> perturbed(const std::vector<AreaLight>& truth, double shiftM,
                                        double radianceScale) {
  std::vector<AreaLight> out = truth;
  for (size_t j = 0; j < out.size(); ++j) {
    const Vec3 d = j % 2 == 0 ? Vec3(shiftM, 0, -0.6 * shiftM) : Vec3(-0.7 * shiftM, 0, shiftM);
    for (auto& c : out[j].cornersWorld) c += d;
    out[j].radiance *= radianceScale;
  }
  return out;
}

}  // namespace inlay::test
