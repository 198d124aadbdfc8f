// Internal: the sunlit patches the photo shows, as a light for the path tracer's next-event
// estimation.
//
// A bounce that lands on room the camera sees takes the photo's radiance there (PathTracer), and a
// sunlit patch is many times brighter than the rest of the room: a patch the photo clips takes the
// light model's radiance (radianceForBounces, 10-50 times the clip level on a bright floor). Found
// by BSDF sampling alone it is a few rare, very bright samples: fireflies on an object standing
// near the patch and on the surroundings whose light the object blocks. Here each texel of the
// photo grid that shows a sunlit patch is a small planar emitter (its footprint on the surface it
// shows, a parallelogram) with the radiance a bounce reads there. NEE picks a texel by its power
// (luminance x area) and a point uniformly in its footprint; MIS weighs that against the BSDF,
// which reads the same density at the texel its bounce lands on (pdfArea).
#pragma once

#include "inlay/modeling/camera.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace inlay::detail {

class SunPatchLight {
 public:
  // One texel of the photo grid that shows a sunlit patch.
  struct Footprint {
    size_t texel = 0;              // y * gridWidth + x
    Vec3 corner, edgeU, edgeV;     // the parallelogram corner + a edgeU + b edgeV, a, b in [0, 1)
    Vec3 normal = Vec3(0, 1, 0);   // unit, on the side the camera sees
    Vec3 radiance = Vec3::Zero();  // what a bounce landing there reads
  };
  struct Sample {
    Vec3 y = Vec3::Zero(), normal = Vec3(0, 1, 0), radiance = Vec3::Zero();
    double pdfArea = 0;  // 0: no sample (an empty light)
  };

  SunPatchLight() = default;
  // Footprints with no area, no radiance or anything non-finite are left out; `texelCount` is
  // the grid's size (the texel indices must be below it, others are left out too).
  SunPatchLight(std::vector<Footprint> footprints, size_t texelCount);

  bool empty() const { return footprints_.empty(); }
  size_t size() const { return footprints_.size(); }
  // A point on the patches: a texel by power with uPick, a point uniform in it with (u, v); all
  // three in [0, 1).
  Sample sample(double uPick, double u, double v) const;
  // The density by area that sample() gives a point of this texel (0: not a patch texel).
  double pdfArea(size_t texel) const;

 private:
  std::vector<Footprint> footprints_;
  std::vector<double> cdf_;     // cumulative power, normalised: cdf_.back() == 1
  std::vector<float> pdfArea_;  // per texel of the grid
};

// The footprint of texel (x, y) of a gridWidth x gridHeight grid over the camera's image on the
// plane through planePoint with unit planeNormal: the pixel's corner rays met with the plane.
// nullopt when a corner ray misses the plane (parallel, or the plane behind the camera). The
// normal is turned toward the camera.
std::optional<SunPatchLight::Footprint> texelFootprint(const Camera& camera, int gridWidth,
                                                       int gridHeight, int x, int y,
                                                       const Vec3& planePoint, const Vec3& planeNormal);

}  // namespace inlay::detail
