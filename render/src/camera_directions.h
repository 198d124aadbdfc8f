// Internal: the directions of a packet's camera rays, two lanes at a time. The same operations
// in the same order as Camera::directionThroughPixel() (so the same bits), with the divisions
// and square roots of two pixels in one SSE2 instruction instead of one call per pixel.
#pragma once

#include "inlay/modeling/camera.h"

#include <cstddef>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace inlay::detail {

// out[k] = camera.directionThroughPixel(Vec2(px[k], py[k])) for k < n, to the bit.
inline void directionsThroughPixels(const Camera& camera, int n, const double* px, const double* py,
                                    Vec3* out) {
  int k = 0;
#if defined(__SSE2__)
  const Mat3& m = camera.worldFromCamera;
  const __m128d cx = _mm_set1_pd(camera.principalPx.x()), cy = _mm_set1_pd(camera.principalPx.y());
  const __m128d f = _mm_set1_pd(camera.focalPx), minusOne = _mm_set1_pd(-1.0);
  const __m128d zero = _mm_setzero_pd(), sign = _mm_set1_pd(-0.0);
  auto col = [&](int r, int c) { return _mm_set1_pd(m(r, c)); };
  const __m128d m00 = col(0, 0), m01 = col(0, 1), m02 = col(0, 2), m10 = col(1, 0), m11 = col(1, 1),
                m12 = col(1, 2), m20 = col(2, 0), m21 = col(2, 1), m22 = col(2, 2);
  for (; k + 2 <= n; k += 2) {
    // The camera-frame direction ((px - cx) / f, -(py - cy) / f, -1).
    const __m128d x = _mm_div_pd(_mm_sub_pd(_mm_loadu_pd(px + k), cx), f);
    const __m128d y = _mm_div_pd(_mm_xor_pd(_mm_sub_pd(_mm_loadu_pd(py + k), cy), sign), f);
    // Eigen's 3x3 product: rows 0 and 1 as (m0 x + m1 y) + m2 z, row 2 as (m22 z + m21 y) + m20 x.
    const __m128d w0 =
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(m00, x), _mm_mul_pd(m01, y)), _mm_mul_pd(m02, minusOne));
    const __m128d w1 =
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(m10, x), _mm_mul_pd(m11, y)), _mm_mul_pd(m12, minusOne));
    const __m128d w2 =
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(m22, minusOne), _mm_mul_pd(m21, y)), _mm_mul_pd(m20, x));
    // normalized(): divided by sqrt((w0^2 + w1^2) + w2^2) where that is > 0, else as it is.
    const __m128d s = _mm_add_pd(_mm_add_pd(_mm_mul_pd(w0, w0), _mm_mul_pd(w1, w1)), _mm_mul_pd(w2, w2));
    const __m128d positive = _mm_cmpgt_pd(s, zero);
    const __m128d q =
        _mm_or_pd(_mm_and_pd(positive, _mm_sqrt_pd(s)), _mm_andnot_pd(positive, _mm_set1_pd(1.0)));
    alignas(16) double r0[2], r1[2], r2[2];
    _mm_store_pd(r0, _mm_div_pd(w0, q)), _mm_store_pd(r1, _mm_div_pd(w1, q)),
        _mm_store_pd(r2, _mm_div_pd(w2, q));
    out[k] = Vec3(r0[0], r1[0], r2[0]);
    out[k + 1] = Vec3(r0[1], r1[1], r2[1]);
  }
#endif
  for (; k < n; ++k) out[k] = camera.directionThroughPixel(Vec2(px[k], py[k]));
}

}  // namespace inlay::detail
