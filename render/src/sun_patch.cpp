// The sunlit patches as a light for next-event estimation (see sun_patch.h).
#include "sun_patch.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace inlay::detail {

namespace {

// Where the ray from the camera through pixel position px meets the plane; nullopt when it
// runs parallel to it or meets it behind the camera.
std::optional<Vec3> onPlane(const Camera& camera, const Vec2& px, const Vec3& planePoint,
                            const Vec3& n) {
  const Vec3 o = camera.centreWorld(), d = camera.directionThroughPixel(px);
  const double den = n.dot(d);
  if (!(std::abs(den) > 1e-12)) return std::nullopt;
  const double t = n.dot(planePoint - o) / den;
  if (!(t > 0) || !std::isfinite(t)) return std::nullopt;
  return Vec3(o + t * d);
}

}  // namespace

SunPatchLight::SunPatchLight(std::vector<Footprint> footprints, size_t texelCount) {
  std::vector<double> power;
  for (Footprint& f : footprints) {
    const double area = f.edgeU.cross(f.edgeV).norm();
    const double p = area * luminance(f.radiance.cwiseMax(0.0));
    const bool finite = f.corner.allFinite() && f.edgeU.allFinite() && f.edgeV.allFinite() &&
                        f.normal.allFinite() && f.radiance.allFinite();
    if (!finite || f.texel >= texelCount || !(area > 0) || !(p > 0) || !std::isfinite(p)) continue;
    f.radiance = f.radiance.cwiseMax(0.0);
    footprints_.push_back(f);
    power.push_back(p);
  }
  if (footprints_.empty()) return;
  double total = 0;
  for (double p : power) total += p;
  cdf_.resize(power.size());
  pdfArea_.assign(texelCount, 0.0f);
  double running = 0;
  for (size_t i = 0; i < power.size(); ++i) {
    running += power[i];
    cdf_[i] = running / total;
    const Footprint& f = footprints_[i];
    pdfArea_[f.texel] += float(power[i] / total / f.edgeU.cross(f.edgeV).norm());
  }
  cdf_.back() = 1.0;
}

SunPatchLight::Sample SunPatchLight::sample(double uPick, double u, double v) const {
  Sample s;
  if (footprints_.empty()) return s;
  const size_t i = size_t(std::upper_bound(cdf_.begin(), cdf_.end(), uPick) - cdf_.begin());
  const Footprint& f = footprints_[std::min(i, footprints_.size() - 1)];
  s.y = f.corner + u * f.edgeU + v * f.edgeV;
  s.normal = f.normal;
  s.radiance = f.radiance;
  s.pdfArea = double(pdfArea_[f.texel]);
  return s;
}

double SunPatchLight::pdfArea(size_t texel) const {
  return texel < pdfArea_.size() ? double(pdfArea_[texel]) : 0.0;
}

std::optional<SunPatchLight::Footprint> texelFootprint(const Camera& camera, int gridWidth,
                                                       int gridHeight, int x, int y,
                                                       const Vec3& planePoint, const Vec3& planeNormal) {
  if (gridWidth <= 0 || gridHeight <= 0 || camera.widthPx <= 0 || camera.heightPx <= 0)
    return std::nullopt;
  const Vec3 n = planeNormal.normalized();
  if (!n.allFinite() || !planePoint.allFinite()) return std::nullopt;
  const double sx = double(camera.widthPx) / gridWidth, sy = double(camera.heightPx) / gridHeight;
  const auto c00 = onPlane(camera, Vec2(x * sx, y * sy), planePoint, n);
  const auto c10 = onPlane(camera, Vec2((x + 1) * sx, y * sy), planePoint, n);
  const auto c01 = onPlane(camera, Vec2(x * sx, (y + 1) * sy), planePoint, n);
  if (!c00 || !c10 || !c01) return std::nullopt;
  SunPatchLight::Footprint f;
  f.texel = size_t(y) * size_t(gridWidth) + size_t(x);
  f.corner = *c00;
  f.edgeU = *c10 - *c00;
  f.edgeV = *c01 - *c00;
  f.normal = n.dot(camera.centreWorld() - *c00) >= 0 ? n : Vec3(-n);
  return f;
}

}  // namespace inlay::detail
