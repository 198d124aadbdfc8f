// Internal: a camera packet's lanes worked out together in AVX2 registers: the sampler's random
// numbers of its pixels (SampleRng) and the near lights' points of its first vertices (spherical
// quads). Plain arrays only, so that the AVX2 translation units (*_lanes_avx2.cpp, built with
// -mavx2) share no inline function with the rest of the build: a CPU without AVX2 never runs
// their code.
#pragma once

#include <cstdint>

namespace inlay::detail {

constexpr int kQuadLanes = 4;

// Lane l holds SphericalQuad(corner[.][.][l], origin[.][l]).sample(u0[l], u1[l]), structure of
// arrays: corner k, then x/y/z, then the lane.
struct QuadLanes {
  double corner[4][3][kQuadLanes];
  double origin[3][kQuadLanes];
  double u0[kQuadLanes], u1[kQuadLanes];
  // Out: the quad's solid angle (0 when a triangle is degenerate) and the sampled point (any
  // value where the solid angle is not above the caller's minimum).
  double solidAngle[kQuadLanes];
  double y[3][kQuadLanes];
};

// The lanes in AVX2 registers, the scalar SphericalQuad's operations in its order (no FMA), so
// its bits. Returns a mask of the lanes it could not do (an argument the scalar code hands to the
// library: a zero or non-finite arctangent argument, an angle that is not finite), which the
// caller computes alone. Call only when cpuHasAvx2().
int sphericalQuadLanesAvx2(QuadLanes& q);

constexpr int kSamplerLanes = 8;
constexpr int kSamplerPairs = 5;

// Lane l holds SampleRng(x[l], y[l], sample[l], seed); u[k][0 or 1][l] gets its get2(pair[k]) for
// k < pairs <= kSamplerPairs. The pairs' hashes (pcgHash(pair)) and the reversed Sobol' table
// (kSobol1Reversed.byByte, 4 x 256) come from the caller, so that this code takes no table of
// sampling.h's.
struct SamplerLanes {
  uint32_t x[kSamplerLanes], y[kSamplerLanes], sample[kSamplerLanes];
  uint32_t seed = 0;
  int pairs = 0;
  uint32_t pairHash[kSamplerPairs];
  const uint32_t* sobol1Reversed = nullptr;
  // Out: the numbers, and the lanes' pixel keys and reversed sample indices (SampleRng::fromKey).
  double u[kSamplerPairs][2][kSamplerLanes];
  uint32_t pixelKey[kSamplerLanes], reversedSample[kSamplerLanes];
};

// SampleRng's hashes for eight lanes at once (32-bit integer lanes: the same bits).
void samplerLanesAvx2(SamplerLanes& s);

// True when the CPU (and the OS) run AVX2 and the build has the kernel (x86-64).
bool cpuHasAvx2();

// Whether tracers made from now on use the lanes: cpuHasAvx2() unless a test or a benchmark
// turned them off (to compare with the scalar code in one process).
bool simdLanesEnabled();
void setSimdLanesEnabled(bool on);

}  // namespace inlay::detail
