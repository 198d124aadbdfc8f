// Sunlight beams and the photo's radiance as seen on the room.
#include "inlay/render/path_tracer.h"
#include "inlay/render/scene.h"

#include <cmath>

namespace inlay {

namespace {

// Bilinear read of a one-channel image at a pixel position (pixel centres at +0.5); 0 outside.
double bilinear(const ImageF& img, const Vec2& px) {
  const double x = px.x() - 0.5, y = px.y() - 0.5;
  if (!(x > -1 && y > -1 && x < img.width && y < img.height)) return 0;
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const double ax = x - x0, ay = y - y0;
  double v = 0;
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      const int xx = std::clamp(x0 + dx, 0, img.width - 1), yy = std::clamp(y0 + dy, 0, img.height - 1);
      v += (dx ? ax : 1 - ax) * (dy ? ay : 1 - ay) * img.at(xx, yy, 0);
    }
  return v;
}

}  // namespace

double SunLight::beamAt(const Vec3& p) const {
  if (litMask.empty()) return 1.0;
  const Vec3 n = receiverPlane.head<3>();
  const double den = n.dot(travelDirection);
  if (std::abs(den) < 1e-12) return 0;
  // The line through p along the light meets the receiver downstream (a lit patch) or upstream
  // (the window itself).
  const double t = -(n.dot(p) + receiverPlane.w()) / den;
  if (!std::isfinite(t)) return 0;
  const auto px = camera.project(p + t * travelDirection);
  if (!px) return 0;
  return std::clamp(bilinear(litMask, *px), 0.0, 1.0);
}

bool ProjectedAlbedo::radianceAt(int surfaceId, const Vec3& pointWorld, Vec3* radiance) const {
  return radianceAtPixel(pixelShowing(surfaceId, pointWorld), radiance);
}

bool ProjectedAlbedo::radianceAtPixel(std::optional<size_t> i, Vec3* radiance) const {
  // The photo shares the albedo's pixel grid.
  const int w = photoRadiance.width, h = photoRadiance.height;
  if (photoRadiance.channels < 3 || w != albedo.width || h != albedo.height ||
      photoRadianceUsable.size() != size_t(w) * h)
    return false;
  if (!i || !photoRadianceUsable[*i]) return false;
  const Vec3 r = photoRadiance.rgb(int(*i % size_t(w)), int(*i / size_t(w)));
  if (!r.allFinite()) return false;
  *radiance = r.cwiseMax(0.0);
  return true;
}

double unitSunIrradianceOverPi(const RoomTracer& tracer, const SceneGeometry& room, const SunLight& sun,
                               const Vec3& p, const Vec3& n) {
  const Vec3 toSun = -sun.travelDirection;
  const double cosR = n.dot(toSun);
  if (!(cosR > 0)) return 0;
  const double beam = sun.beamAt(p);
  if (!(beam > 0)) return 0;
  const auto hit = tracer.intersect(Ray{p, toSun}, 1e-5);
  if (hit && size_t(hit->surfaceId) < room.surfaces.size() &&
      !isBoxSurface(room.surfaces[size_t(hit->surfaceId)].kind))
    return 0;
  return beam * cosR;
}

}  // namespace inlay
