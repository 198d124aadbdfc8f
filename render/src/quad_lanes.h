// Internal: several spherical quads set up and sampled together, one per SIMD lane (the near
// lights' points of a camera packet's first vertices). Plain arrays only, so that the AVX2
// translation unit (quad_lanes_avx2.cpp, built with -mavx2) shares no inline function with the
// rest of the build: a CPU without AVX2 never runs its code.
#pragma once

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

// True when the CPU (and the OS) run AVX2 and the build has the kernel (x86-64).
bool cpuHasAvx2();

// Whether tracers made from now on use the lanes: cpuHasAvx2() unless a test or a benchmark
// turned them off (to compare with the scalar code in one process).
bool quadLanesEnabled();
void setQuadLanesEnabled(bool on);

}  // namespace inlay::detail
