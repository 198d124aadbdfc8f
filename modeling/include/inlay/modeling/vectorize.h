#pragma once

// Hints for the per-pixel kernels' loops (render/src/denoise.cpp, lighting/src/decompose.cpp).
// INLAY_IVDEP: the loop carries no dependence between iterations (GCC then skips the run-time
// alias checks that stop the vectoriser; those files are built with -fno-trapping-math so that
// clamps and selects are if-converted). INLAY_INLINE: always inline a kernel's per-pixel lambda
// or helper, so the loop around it vectorises.
#if defined(__GNUC__) && !defined(__clang__)
#define INLAY_IVDEP _Pragma("GCC ivdep")
#define INLAY_INLINE __attribute__((always_inline))
#else
#define INLAY_IVDEP
#define INLAY_INLINE
#endif
