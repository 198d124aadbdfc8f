// SphericalQuad (sampling.h) for four quads at once in AVX2 registers. Built with -mavx2 (not
// -mfma: a fused multiply-add would round once where the scalar code rounds twice); every
// operation is the scalar code's, lane by lane, in its order: Eigen's dot product as (x + y) + z,
// the cross product by its components, a normalisation as a division by the square root, the
// branches as selects. Nothing here is inline in a header the rest of the build shares.
#include "simd_lanes.h"

#if defined(__AVX2__)
#include <immintrin.h>

namespace inlay::detail {
namespace {

using V = __m256d;

struct V3 {
  V x, y, z;
};

inline V all(double v) { return _mm256_set1_pd(v); }
inline V add(V a, V b) { return _mm256_add_pd(a, b); }
inline V sub(V a, V b) { return _mm256_sub_pd(a, b); }
inline V mul(V a, V b) { return _mm256_mul_pd(a, b); }
inline V div(V a, V b) { return _mm256_div_pd(a, b); }
inline V neg(V a) { return _mm256_xor_pd(a, all(-0.0)); }
inline V absOf(V a) { return _mm256_andnot_pd(all(-0.0), a); }
inline V lt(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
inline V gt(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_GT_OQ); }
inline V ge(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_GE_OQ); }
inline V eq(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_EQ_OQ); }
inline V andOf(V a, V b) { return _mm256_and_pd(a, b); }
// Lane-wise `mask ? a : b`.
inline V select(V mask, V a, V b) { return _mm256_blendv_pd(b, a, mask); }
// std::clamp(v, lo, hi): v < lo ? lo : hi < v ? hi : v (NaN stays NaN).
inline V clampOf(V v, double lo, double hi) {
  return select(lt(v, all(lo)), all(lo), select(lt(all(hi), v), all(hi), v));
}
// std::max(0.0, v): 0 < v ? v : 0 (NaN gives 0).
inline V maxZero(V v) { return select(lt(all(0.0), v), v, all(0.0)); }
inline V finite(V v) { return lt(absOf(v), all(__builtin_inf())); }

inline V3 sub(const V3& a, const V3& b) { return {sub(a.x, b.x), sub(a.y, b.y), sub(a.z, b.z)}; }
inline V3 scaled(V s, const V3& a) { return {mul(s, a.x), mul(s, a.y), mul(s, a.z)}; }
inline V3 add(const V3& a, const V3& b) { return {add(a.x, b.x), add(a.y, b.y), add(a.z, b.z)}; }
inline V3 select(V m, const V3& a, const V3& b) {
  return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)};
}
inline V dot(const V3& a, const V3& b) { return add(add(mul(a.x, b.x), mul(a.y, b.y)), mul(a.z, b.z)); }
inline V3 cross(const V3& a, const V3& b) {
  return {sub(mul(a.y, b.z), mul(a.z, b.y)), sub(mul(a.z, b.x), mul(a.x, b.z)),
          sub(mul(a.x, b.y), mul(a.y, b.x))};
}
// Eigen's normalized(): divided by the norm where the squared norm is > 0, else as it is.
inline V3 normalized(const V3& v) {
  const V s = dot(v, v);
  const V q = select(gt(s, all(0.0)), _mm256_sqrt_pd(s), all(1.0));
  return {div(v.x, q), div(v.y, q), div(v.z, q)};
}
inline V3 load(const double (&p)[3][kQuadLanes]) {
  return {_mm256_loadu_pd(p[0]), _mm256_loadu_pd(p[1]), _mm256_loadu_pd(p[2])};
}

// atan2NonNegative(y, x); `ok` gets the lanes it did not hand to the library.
inline V atan2NonNegative(V y, V x, V* ok) {
  const V ax = absOf(x);
  const V steep = gt(y, ax);
  const V num = select(steep, ax, y), den = select(steep, y, ax);
  *ok = andOf(andOf(gt(den, all(0.0)), finite(den)), ge(num, all(0.0)));
  const V upper = gt(num, mul(all(0.41421356237309503), den));
  const V t = div(select(upper, sub(num, den), num), select(upper, add(num, den), den));
  const V z = mul(t, t);
  V r = sub(mul(all(8.05374449538e-2), z), all(1.38776856032e-1));
  r = add(mul(r, z), all(1.99777106478e-1));
  r = sub(mul(r, z), all(3.33329491539e-1));
  r = add(mul(mul(r, z), t), t);
  constexpr double kPi = 3.14159265358979323846;
  r = select(upper, add(r, all(kPi / 4)), r);
  r = select(steep, sub(all(kPi / 2), r), r);
  return select(lt(x, all(0.0)), sub(all(kPi), r), r);
}

// sinCos(x) (sampling.h); `ok` gets the lanes with |x| < 1e6 (the others go to the library).
inline void sinCos(V x, V* sinX, V* cosX, V* ok) {
  *ok = lt(absOf(x), all(1e6));
  constexpr double kTwoOverPi = 0.63661977236758134308, kPiOver2Hi = 1.57079632673412561417,
                   kPiOver2Lo = 6.07710050650619224932e-11;
  const V q = _mm256_floor_pd(add(mul(x, all(kTwoOverPi)), all(0.5)));
  const V r = sub(sub(x, mul(q, all(kPiOver2Hi))), mul(q, all(kPiOver2Lo))), z = mul(r, r);
  constexpr double kSin[7] = {-1.0 / 6,        1.0 / 120,        -1.0 / 5040,         1.0 / 362880,
                              -1.0 / 39916800, 1.0 / 6227020800, -1.0 / 1307674368000};
  constexpr double kCos[8] = {-1.0 / 2,       1.0 / 24,        -1.0 / 720,         1.0 / 40320,
                              -1.0 / 3628800, 1.0 / 479001600, -1.0 / 87178291200, 1.0 / 20922789888000};
  auto pair = [&](double c0, double c1) { return add(all(c0), mul(z, all(c1))); };
  const V z2 = mul(z, z), z4 = mul(z2, z2);
  const V ps = add(add(pair(kSin[0], kSin[1]), mul(z2, pair(kSin[2], kSin[3]))),
                   mul(z4, add(pair(kSin[4], kSin[5]), mul(z2, all(kSin[6])))));
  const V pc = add(add(pair(kCos[0], kCos[1]), mul(z2, pair(kCos[2], kCos[3]))),
                   mul(z4, add(pair(kCos[4], kCos[5]), mul(z2, pair(kCos[6], kCos[7])))));
  const V s = add(r, mul(mul(r, z), ps)), c = add(all(1.0), mul(z, pc));
  // The quadrant q mod 4 (q is a whole number below 2^20 in magnitude: exact).
  const V quadrant = sub(q, mul(all(4.0), _mm256_floor_pd(mul(q, all(0.25)))));
  const V q1 = eq(quadrant, all(1.0)), q2 = eq(quadrant, all(2.0)), q3 = eq(quadrant, all(3.0));
  *sinX = select(q1, c, select(q2, neg(s), select(q3, neg(c), s)));
  *cosX = select(q1, neg(s), select(q2, neg(c), select(q3, s, c)));
}

// A spherical triangle as SphericalTriangle keeps it (nbc only for the degeneracy test).
struct Triangle {
  V3 a, b, c, planeNormal, nab, nca;
  V triple, solidAngle;
};

// SphericalTriangle's constructor; `ok` is cleared in the lanes the library's arctangent takes.
inline Triangle triangle(const V3& A, const V3& B, const V3& C, const V3& a, const V3& b, const V3& c,
                         V* ok) {
  Triangle t{a, b, c, cross(sub(B, A), sub(C, A)), cross(a, b), cross(c, a), {}, {}};
  const V3 nbc = cross(b, c);
  t.triple = absOf(dot(a, nbc));
  V atanOk;
  const V sa =
      mul(all(2.0),
          atan2NonNegative(t.triple, add(add(add(all(1.0), dot(a, b)), dot(b, c)), dot(c, a)), &atanOk));
  *ok = andOf(*ok, atanOk);
  const V zero = all(0.0);
  const V valid = andOf(
      andOf(andOf(gt(sa, zero), finite(sa)), andOf(_mm256_cmp_pd(dot(t.nab, t.nab), zero, _CMP_NEQ_UQ),
                                                   _mm256_cmp_pd(dot(nbc, nbc), zero, _CMP_NEQ_UQ))),
      _mm256_cmp_pd(dot(t.nca, t.nca), zero, _CMP_NEQ_UQ));
  t.solidAngle = _mm256_and_pd(valid, sa);
  return t;
}

// SphericalTriangle::orthoNormal.
inline V3 orthoNormal(const V3& v, const V3& w) {
  const V3 g = sub(v, scaled(dot(v, w), w));
  const V n = _mm256_sqrt_pd(dot(g, g));
  const V positive = gt(n, all(0.0));
  return {_mm256_and_pd(positive, div(g.x, n)), _mm256_and_pd(positive, div(g.y, n)),
          _mm256_and_pd(positive, div(g.z, n))};
}

// SphericalTriangle::sample(u0, u1), the plane's point A and the origin o given.
inline V3 sampleTriangle(const Triangle& t, const V3& A, const V3& o, V u0, V u1, V* ok) {
  const V inv = div(all(1.0), _mm256_sqrt_pd(mul(dot(t.nab, t.nab), dot(t.nca, t.nca))));
  const V cosA = clampOf(mul(neg(dot(t.nab, t.nca)), inv), -1.0, 1.0);
  const V sinAraw = mul(t.triple, inv);
  const V sinA = select(lt(sinAraw, all(1.0)), sinAraw, all(1.0));
  V sinSub, cosSub, sinOk;
  sinCos(mul(u0, t.solidAngle), &sinSub, &cosSub, &sinOk);
  *ok = andOf(*ok, sinOk);
  const V sinAp = neg(sinSub), cosAp = neg(cosSub);
  const V sinPhi = sub(mul(sinAp, cosA), mul(cosAp, sinA));
  const V cosPhi = add(mul(cosAp, cosA), mul(sinAp, sinA));
  const V k1 = add(cosPhi, cosA);
  const V k2 = sub(sinPhi, mul(sinA, dot(t.a, t.b)));
  V cosBp = div(add(k2, mul(sub(mul(k2, cosPhi), mul(k1, sinPhi)), cosA)),
                mul(add(mul(k2, sinPhi), mul(k1, cosPhi)), sinA));
  cosBp = select(finite(cosBp), clampOf(cosBp, -1.0, 1.0), all(1.0));
  const V sinBp = _mm256_sqrt_pd(maxZero(sub(all(1.0), mul(cosBp, cosBp))));
  const V3 cp = add(scaled(cosBp, t.a), scaled(sinBp, orthoNormal(t.c, t.a)));
  const V cosT = sub(all(1.0), mul(u1, sub(all(1.0), dot(cp, t.b))));
  const V sinT = _mm256_sqrt_pd(maxZero(sub(all(1.0), mul(cosT, cosT))));
  const V3 w = add(scaled(cosT, t.b), scaled(sinT, orthoNormal(cp, t.b)));
  const V tw = div(dot(sub(A, o), t.planeNormal), dot(w, t.planeNormal));
  return add(o, scaled(tw, w));
}

// The triangle lanes `m` take from t1, the others from t2.
inline Triangle selectTriangle(V m, const Triangle& t1, const Triangle& t2) {
  return {select(m, t1.a, t2.a),           select(m, t1.b, t2.b),
          select(m, t1.c, t2.c),           select(m, t1.planeNormal, t2.planeNormal),
          select(m, t1.nab, t2.nab),       select(m, t1.nca, t2.nca),
          select(m, t1.triple, t2.triple), select(m, t1.solidAngle, t2.solidAngle)};
}

}  // namespace

int sphericalQuadLanesAvx2(QuadLanes& q) {
  const V3 o = load(q.origin);
  const V3 c0 = load(q.corner[0]), c1 = load(q.corner[1]), c2 = load(q.corner[2]),
           c3 = load(q.corner[3]);
  const V3 u0 = normalized(sub(c0, o)), u1 = normalized(sub(c1, o)), u2 = normalized(sub(c2, o)),
           u3 = normalized(sub(c3, o));
  V ok = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
  const Triangle t1 = triangle(c0, c1, c2, u0, u1, u2, &ok), t2 = triangle(c0, c2, c3, u0, u2, u3, &ok);
  const V zero = all(0.0);
  const V both = andOf(gt(t1.solidAngle, zero), gt(t2.solidAngle, zero));
  const V solidAngle = _mm256_and_pd(both, add(t1.solidAngle, t2.solidAngle));
  // SphericalQuad::sample: u0 picks a triangle by solid angle and is reused inside it.
  const V su0 = _mm256_loadu_pd(q.u0), su1 = _mm256_loadu_pd(q.u1);
  const V p1 = div(t1.solidAngle, solidAngle);
  const V first = lt(su0, p1);
  const V uu = select(first, clampOf(div(su0, p1), 0.0, 1.0),
                      clampOf(div(sub(su0, p1), sub(all(1.0), p1)), 0.0, 1.0));
  const V3 y = sampleTriangle(selectTriangle(first, t1, t2), c0, o, uu, su1, &ok);
  _mm256_storeu_pd(q.solidAngle, solidAngle);
  _mm256_storeu_pd(q.y[0], y.x), _mm256_storeu_pd(q.y[1], y.y), _mm256_storeu_pd(q.y[2], y.z);
  return _mm256_movemask_pd(ok) ^ ((1 << kQuadLanes) - 1);
}

}  // namespace inlay::detail
#else
namespace inlay::detail {
// Not an x86-64 build: cpuHasAvx2() is false and this is never called.
int sphericalQuadLanesAvx2(QuadLanes&) { return (1 << kQuadLanes) - 1; }
}  // namespace inlay::detail
#endif
