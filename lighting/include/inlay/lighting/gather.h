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
#include "inlay/render/path_tracer.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace inlay {

// Radiance (photo units, RGB) leaving `hit` toward the gathering point; `sampleId` is unique
// per gather ray (for callers that sample further).
using RadianceAt = std::function<Vec3(const SurfaceHit& hit, uint32_t sampleId)>;

struct GatherSample {
  Vec3 mean = Vec3::Zero();          // Gamma estimate: mean radiance over the cosine lobe
  Vec3 standardError = Vec3::Zero(); // per channel, from the spread of the strata (conservative)
  int rays = 0;
};

// Gathers at a room point. `point`, `normal`: world frame, normal unit and facing the room.
GatherSample gatherIrradianceOverPi(const RoomTracer& tracer, const Vec3& point,
                                    const Vec3& normal, int samples, uint32_t pixelId,
                                    uint32_t seed, const RadianceAt& radianceAt);

struct GatherSampleCountOptions {
  double relativeNoise = 0.03;  // target standard error of Gamma over its mean (luminance)
  int minSamples = 16;
  int maxSamples = 256;
  int pilotSamples = 16;        // rays per pilot point
};

// The sample count that leaves about `relativeNoise` relative standard error in Gamma, from a
// pilot gather at `points` (world point and normal pairs, e.g. a sparse grid of pixels): the
// variance per ray is measured there and n = variance / (noise * mean)^2, rounded up to a
// square, clamped to [minSamples, maxSamples].
int gatherSamplesForNoise(const RoomTracer& tracer,
                          const std::vector<std::pair<Vec3, Vec3>>& points, uint32_t seed,
                          const RadianceAt& radianceAt, const GatherSampleCountOptions& options = {});

}  // namespace inlay
