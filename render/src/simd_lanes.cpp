// The run-time choice of quad_lanes_avx2.cpp's kernel (this file is built for the baseline CPU).
#include "simd_lanes.h"

#include <atomic>

namespace inlay::detail {

bool cpuHasAvx2() {
#if defined(INLAY_SIMD_LANES_AVX2)
  static const bool has = __builtin_cpu_supports("avx2");
  return has;
#else
  return false;
#endif
}

namespace {
std::atomic<bool> lanesOn{true};
}  // namespace

bool simdLanesEnabled() { return lanesOn.load(std::memory_order_relaxed) && cpuHasAvx2(); }
void setSimdLanesEnabled(bool on) { lanesOn.store(on, std::memory_order_relaxed); }

}  // namespace inlay::detail
