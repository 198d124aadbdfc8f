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
