// Gathered indirect irradiance: Gamma(x) = (1/pi) * integral of the radiance arriving at a room
// point x from the rest of the room, over the cosine-weighted hemisphere of its normal. The
// radiance along each gather ray is supplied by the caller (read from the photo where the hit
// point is visible, predicted elsewhere). Used by the light fit and by the decomposition
// (estimate.cpp) so that both see the same Gamma.
//
// Sampling: n = k x k stratified cosine-weighted directions; the random numbers are a pure
// function of (pixelId, seed, sample), so any pixel's gather replays exactly.
// Thread-safe: RoomTracer queries are const.
#pragma once

#include "inlay/modeling/core.h"
#include "inlay/modeling/geometry.h"
#include "inlay/render/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace inlay {

// Radiance (photo units, RGB) leaving `hit` toward the gathering point; `sampleId` is unique
// per gather ray (for callers that sample further).
using RadianceAt = std::function<Vec3(const SurfaceHit& hit, uint32_t sampleId)>;

struct GatherSample {
  Vec3 mean = Vec3::Zero();           // Gamma estimate: mean radiance over the cosine lobe
  Vec3 standardError = Vec3::Zero();  // per channel, from the spread of the strata (conservative)
  int rays = 0;
};

// The gather's rays per side of its k x k strata for `samples` rays (k = round(sqrt(samples)),
// at least 1): a gather casts k^2 rays.
inline int gatherRaysPerSide(int samples) {
  return std::max(1, int(std::lround(std::sqrt(double(std::max(samples, 1))))));
}

namespace detail {
inline uint32_t gatherHash32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}
inline double gatherUniform(uint32_t a, uint32_t b, uint32_t c) {
  return (gatherHash32(a ^ gatherHash32(b ^ gatherHash32(c))) >> 8) * (1.0 / 16777216.0);
}
}  // namespace detail

// Casts the rays gatherIrradianceOverPi casts at a point (the same directions, in the same order)
// and calls visit(const SurfaceHit* hit, uint32_t sampleId) for each: hit is nullptr where the ray
// left the room, sampleId the one gatherIrradianceOverPi hands to RadianceAt. A caller that
// gathers the same point again with other radiances keeps the hits instead of tracing them again
// (estimate.cpp's GatherRays).
template <class Visit>
void forEachGatherRay(const RoomTracer& tracer, const Vec3& point, const Vec3& normal, int samples,
                      uint32_t pixelId, uint32_t seed, Visit&& visit) {
  const int nSide = gatherRaysPerSide(samples);
  const Vec3 t = (std::abs(normal.x()) > 0.9 ? Vec3(0, 1, 0) : Vec3(1, 0, 0)).cross(normal).normalized();
  const Vec3 b = normal.cross(t);
  for (int i = 0; i < nSide; ++i)
    for (int k = 0; k < nSide; ++k) {
      const uint32_t s = uint32_t(i * nSide + k);
      const double u1 = (i + detail::gatherUniform(pixelId, seed, 2 * s)) / nSide;
      const double u2 = (k + detail::gatherUniform(pixelId, seed, 2 * s + 1)) / nSide;
      const double r = std::sqrt(u1), phi = 2 * M_PI * u2;
      const Vec3 d =
          (r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0, 1 - u1)) * normal)
              .normalized();
      const auto h = tracer.intersect(Ray{point + 1e-5 * normal, d}, 1e-5);
      visit(h ? &*h : static_cast<const SurfaceHit*>(nullptr), pixelId * 1024u + s);
    }
}

// Gathers at a room point. `point`, `normal`: world frame, normal unit and facing the room.
GatherSample gatherIrradianceOverPi(const RoomTracer& tracer, const Vec3& point, const Vec3& normal,
                                    int samples, uint32_t pixelId, uint32_t seed,
                                    const RadianceAt& radianceAt);

struct GatherSampleCountOptions {
  double relativeNoise = 0.03;  // target standard error of Gamma over its mean (luminance)
  int minSamples = 16;
  int maxSamples = 256;
  int pilotSamples = 16;  // rays per pilot point
};

// The sample count that leaves about `relativeNoise` relative standard error in Gamma, from a
// pilot gather at `points` (world point and normal pairs, e.g. a sparse grid of pixels): the
// variance per ray is measured there and n = variance / (noise * mean)^2, rounded up to a
// square, clamped to [minSamples, maxSamples].
int gatherSamplesForNoise(const RoomTracer& tracer, const std::vector<std::pair<Vec3, Vec3>>& points,
                          uint32_t seed, const RadianceAt& radianceAt,
                          const GatherSampleCountOptions& options = {});

}  // namespace inlay

namespace inlay {

// The room's surfaces cut into square patches of about `sizeM` (keyed by surface, facing and
// position in the surface's plane), so that light gathered at points the photo does not show
// can vary over a surface: the ceiling above the camera sees a darker floor than the ceiling
// above the lamps, and one mean per surface would carry the bright part's light to the dark one.
// Immutable after construction except `gamma`, which the caller fills.
struct SurfacePatches {
  double sizeM = 0.3;
  std::vector<Vec3> point, normal;  // per patch: centroid of its samples, normal into the room
  std::vector<int> surface;         // per patch: surface id
  std::vector<Vec3> gamma;          // per patch: gathered irradiance / pi (caller's)
  // The patch a surface hit falls in, or -1 (a corner the sampling missed).
  int find(const SurfaceHit& hit) const;

  std::vector<std::pair<uint64_t, int>> keys;  // sorted (key, patch) for find()
  uint64_t keyOf(int surfaceId, const Vec3& p, const Vec3& n) const;
};

// Patches over every surface of `geometry` (sampled from its triangles at sizeM / 3).
SurfacePatches makeSurfacePatches(const SceneGeometry& geometry, double sizeM);

}  // namespace inlay
