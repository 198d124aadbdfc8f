// Internal: the caustic photon map (TracerOptions::causticPhotons). Photons from the lights that
// passed one or more smooth glass vertices and landed on a Lambertian surface are stored with
// their flux; irradiance() is their density around a point (Epanechnikov kernel in the
// tangent plane), what the path tracer adds at its Lambertian vertices in place of the
// paths diffuse -> glass -> light it no longer counts.
#pragma once

#include "inlay/modeling/core.h"

#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace inlay::detail {

struct CausticPhoton {
  Vec3 point;   // where it landed
  Vec3 normal;  // the surface's geometric normal on the side it arrived from
  Vec3 flux;    // watts (radiance x area x solid angle, as the lights are given)
};

class CausticMap {
 public:
  CausticMap() = default;
  // Photons with a non-finite value or no flux are dropped; radius > 0 (metres).
  CausticMap(std::vector<CausticPhoton> photons, double radius);
  bool empty() const { return photons_.empty(); }
  size_t size() const { return photons_.size(); }  // after merging
  double radius() const { return radius_; }
  double totalFlux() const { return totalFlux_; }  // W, the photons' flux summed (mean over RGB)
  // Irradiance (W/m^2) at p on a surface facing n (unit, the side the path arrived from): the
  // photons within the radius whose normal agrees with n (cos > 0.5) and that lie within a tenth
  // of the radius of p's tangent plane, weighed by 2 / (pi r^2) (1 - d^2 / r^2).
  Vec3 irradiance(const Vec3& p, const Vec3& n) const;

 private:
  static constexpr double kMergeCells = 6;  // merge cells per radius (merged())
  uint64_t cellKey(int64_t x, int64_t y, int64_t z) const;
  uint64_t cellOf(const Vec3& p, double size) const;
  std::vector<CausticPhoton> merged(std::vector<CausticPhoton> photons) const;
  std::vector<CausticPhoton> photons_;  // sorted by cell (radius-sized cubes)
  std::unordered_map<uint64_t, std::pair<uint32_t, uint32_t>> cells_;  // cell -> [first, end)
  double radius_ = 0;
  double totalFlux_ = 0;
  Vec3 lo_ = Vec3::Zero(), hi_ = Vec3::Zero();  // the photons' bounds, grown by the radius
};

}  // namespace inlay::detail
