// Internal: random numbers, directions, quad and microfacet sampling shared by the tracers.
#pragma once

#include "inlay/modeling/core.h"
#include "inlay/render/scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace inlay::detail {

constexpr double kPi = 3.14159265358979323846;

// Emitter quads sit this far in front of the light's corners (along its normal) so that a light
// fitted onto a wall or ceiling does not z-fight with it; both tracers use the same offset.
constexpr double kLightOffsetM = 1e-3;

// PCG-style 32-bit hash (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering").
constexpr uint32_t pcgHash(uint32_t v) {
  const uint32_t state = v * 747796405u + 2891336453u;
  const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

inline constexpr uint32_t reverseBits(uint32_t x) {
  x = __builtin_bswap32(x);  // the bytes in one instruction, then the bits inside each byte
  x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
  x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
  x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
  return x;
}

// Laine and Karras' permutation, the core of the scramble below: it mixes each bit only into
// higher ones, so on reversed bits it is a nested uniform (Owen) scramble.
inline uint32_t laineKarras(uint32_t x, uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

// Hash-based Owen scrambling (Burley 2020, "Practical Hash-based Owen Scrambling").
inline uint32_t nestedUniformScramble(uint32_t x, uint32_t seed) {
  return reverseBits(laineKarras(reverseBits(x), seed));
}

// The first two Sobol' dimensions (a (0,2)-sequence in base 2).
inline uint32_t sobol0(uint32_t i) { return reverseBits(i); }
struct Sobol1Table {
  uint32_t v[32];
  constexpr Sobol1Table() : v() {
    v[0] = 0x80000000u;
    for (int k = 1; k < 32; ++k) v[k] = v[k - 1] ^ (v[k - 1] >> 1);
  }
};
inline constexpr Sobol1Table kSobol1{};
inline uint32_t sobol1(uint32_t i) {
  uint32_t r = 0;
  for (; i; i &= i - 1) r ^= kSobol1.v[__builtin_ctz(i)];
  return r;
}
// reverseBits(sobol1(i)) a byte of i at a time: table[b][v] is the XOR of the reversed
// direction numbers of the bits set in v, placed as byte b (four lookups instead of a loop over
// up to 32 bits and a reversal).
struct Sobol1ReversedTable {
  uint32_t byByte[4][256];
  constexpr Sobol1ReversedTable() : byByte() {
    for (int b = 0; b < 4; ++b)
      for (int v = 0; v < 256; ++v) {
        uint32_t r = 0;
        for (int j = 0; j < 8; ++j)
          if (v & (1 << j)) r ^= reverseBits(kSobol1.v[8 * b + j]);
        byByte[b][v] = r;
      }
  }
};
inline constexpr Sobol1ReversedTable kSobol1Reversed{};
inline uint32_t reversedSobol1(uint32_t i) {
  const auto& t = kSobol1Reversed.byByte;
  return t[0][i & 0xffu] ^ t[1][(i >> 8) & 0xffu] ^ t[2][(i >> 16) & 0xffu] ^ t[3][i >> 24];
}

// pcgHash(pair) of the first pairs of dimensions (SampleRng::get2).
struct PairHashes {
  static constexpr uint32_t count = 256;
  uint32_t hash[count];
  constexpr PairHashes() : hash() {
    for (uint32_t k = 0; k < count; ++k) hash[k] = pcgHash(k);
  }
};
inline constexpr PairHashes kPairHashes{};

// Random numbers as a pure function of (pixel x, y, sample, dimension, seed): every render
// replays exactly and the with-object and without-object paths share them. Dimensions come in
// pairs (2k, 2k+1), each pair an Owen-scrambled, index-shuffled 2D Sobol' point set per pixel
// (Burley's padding): stratified in 2D for every pair and in 1D for every dimension, so soft
// shadows and pixel footprints converge faster than with independent numbers; a pair's first
// 2^m samples form a (0,m,2)-net.
class SampleRng {
 public:
  SampleRng() = default;  // a placeholder (key 0) to assign a pixel's to
  // The same as SampleRng(x, y, sample, seed) from its pixel key pcgHash(y + pcgHash(x +
  // pcgHash(seed))) and reverseBits(sample), worked out elsewhere (simd_lanes.h).
  static SampleRng fromKey(uint32_t pixelKey, uint32_t sample, uint32_t reversedSample) {
    SampleRng r;
    r.pixelKey_ = pixelKey, r.sample_ = sample, r.reversedSample_ = reversedSample;
    return r;
  }
  // pcgHash(pair), from a table for the first pairs.
  static uint32_t pairHash(uint32_t pair) {
    return pair < kPairHashes.count ? kPairHashes.hash[pair] : pcgHash(pair);
  }
  SampleRng(uint32_t x, uint32_t y, uint32_t sample, uint32_t seed)
      : pixelKey_(pcgHash(y + pcgHash(x + pcgHash(seed)))),
        sample_(sample),
        reversedSample_(reverseBits(sample)) {}
  // Dimensions 2 pair and 2 pair + 1, uniform in [0, 1)^2.
  // The same bits as getReference2() with fewer steps: the scramble's first reversal undoes
  // sobol0's, sobol1 comes reversed from a table, the sample index is reversed once per sample
  // and the pair's hash of the first pairs (every path vertex's) comes from a table.
  std::array<double, 2> get2(uint32_t pair) const {
    const uint32_t pairSeed = pcgHash(pixelKey_ ^ pairHash(pair));
    const uint32_t index = reverseBits(laineKarras(reversedSample_, pairSeed));
    return {toUnit(reverseBits(laineKarras(index, pcgHash(pairSeed)))),
            toUnit(reverseBits(laineKarras(reversedSobol1(index), pcgHash(pairSeed + 1u))))};
  }
  // get2(first), ..., get2(first + 3): the same numbers, the four pairs' chains of hashes
  // interleaved (a path vertex draws its four pairs at once; one call's chain is latency-bound).
  std::array<std::array<double, 2>, 4> get2x4(uint32_t first) const {
    uint32_t seed[4], index[4], a[4], b[4];
    for (uint32_t k = 0; k < 4; ++k) {
      const uint32_t pair = first + k;
      seed[k] = pcgHash(pixelKey_ ^ pairHash(pair));
    }
    for (uint32_t k = 0; k < 4; ++k) index[k] = reverseBits(laineKarras(reversedSample_, seed[k]));
    for (uint32_t k = 0; k < 4; ++k) a[k] = reverseBits(laineKarras(index[k], pcgHash(seed[k])));
    for (uint32_t k = 0; k < 4; ++k)
      b[k] = reverseBits(laineKarras(reversedSobol1(index[k]), pcgHash(seed[k] + 1u)));
    return {{{toUnit(a[0]), toUnit(b[0])},
             {toUnit(a[1]), toUnit(b[1])},
             {toUnit(a[2]), toUnit(b[2])},
             {toUnit(a[3]), toUnit(b[3])}}};
  }
  // get2() as Burley's paper writes it (the tests hold get2() to it).
  std::array<double, 2> getReference2(uint32_t pair) const {
    const uint32_t pairSeed = pcgHash(pixelKey_ ^ pcgHash(pair));
    const uint32_t index = nestedUniformScramble(sample_, pairSeed);
    return {toUnit(nestedUniformScramble(sobol0(index), pcgHash(pairSeed))),
            toUnit(nestedUniformScramble(sobol1(index), pcgHash(pairSeed + 1u)))};
  }
  // One dimension, uniform in [0, 1).
  double get(uint32_t dimension) const { return get2(dimension >> 1)[dimension & 1u]; }

 private:
  static double toUnit(uint32_t bits) { return double(bits >> 8) * (1.0 / 16777216.0); }
  uint32_t pixelKey_ = 0;
  uint32_t sample_ = 0;
  uint32_t reversedSample_ = 0;  // reverseBits(sample_)
};

// sin x and cos x together for the samplers' angles (2 pi u, a spherical polygon's area): the
// nearest multiple q of pi/2 taken off in two parts (Cody and Waite; exact for |q| < 2^20), then
// Taylor polynomials to x^15 and x^16 on [-pi/4, pi/4] (truncation below 1e-17) turned by the
// quadrant. Within a few ulp of std::sin / std::cos, without glibc's sincos call and its
// general range reduction; |x| >= 1e6, Inf and NaN go to the library.
inline void sinCos(double x, double* sinX, double* cosX) {
  if (!(std::abs(x) < 1e6)) {
    *sinX = std::sin(x), *cosX = std::cos(x);
    return;
  }
  constexpr double kTwoOverPi = 0.63661977236758134308, kPiOver2Hi = 1.57079632673412561417,
                   kPiOver2Lo = 6.07710050650619224932e-11;
  const double q = std::floor(x * kTwoOverPi + 0.5);
  const double r = (x - q * kPiOver2Hi) - q * kPiOver2Lo, z = r * r;
  // Taylor coefficients: sin r = r + r z (kSin[0] + z kSin[1] + ...), cos r = 1 + z (kCos[0] + ...).
  constexpr double kSin[7] = {-1.0 / 6,        1.0 / 120,        -1.0 / 5040,         1.0 / 362880,
                              -1.0 / 39916800, 1.0 / 6227020800, -1.0 / 1307674368000};
  constexpr double kCos[8] = {-1.0 / 2,       1.0 / 24,        -1.0 / 720,         1.0 / 40320,
                              -1.0 / 3628800, 1.0 / 479001600, -1.0 / 87178291200, 1.0 / 20922789888000};
  // Estrin's scheme (pairs, then powers z^2 and z^4): a third of Horner's chain of dependent
  // multiply-adds, which sat on the critical path of every bounce direction and light point.
  const double z2 = z * z, z4 = z2 * z2;
  const double ps = (kSin[0] + z * kSin[1]) + z2 * (kSin[2] + z * kSin[3]) +
                    z4 * ((kSin[4] + z * kSin[5]) + z2 * kSin[6]);
  const double pc = (kCos[0] + z * kCos[1]) + z2 * (kCos[2] + z * kCos[3]) +
                    z4 * ((kCos[4] + z * kCos[5]) + z2 * (kCos[6] + z * kCos[7]));
  const double s = r + r * z * ps, c = 1.0 + z * pc;
  switch (int64_t(q) & 3) {
    case 0: *sinX = s, *cosX = c; break;
    case 1: *sinX = c, *cosX = -s; break;
    case 2: *sinX = -s, *cosX = -c; break;
    default: *sinX = -c, *cosX = s; break;
  }
}

// atan2(y, x) for y >= 0 (a spherical triangle's half solid angle, in [0, pi]) to a relative
// 2e-8 (the float arctangent it replaces: 2e-7), without a libm call: the octant by comparisons,
// one division, then Cephes' atanf polynomial on |t| <= tan(pi/8). Zero and non-finite
// arguments go to the library.
inline double atan2NonNegative(double y, double x) {
  const double ax = std::abs(x);
  const bool steep = y > ax;  // above the diagonal: pi/2 - atan(ax / y)
  const double num = steep ? ax : y, den = steep ? y : ax;
  if (!(den > 0) || !std::isfinite(den) || !(num >= 0)) return std::atan2(y, x);
  const bool upper = num > 0.41421356237309503 * den;  // t > tan(pi/8): pi/4 + atan((t-1)/(t+1))
  const double t = upper ? (num - den) / (num + den) : num / den, z = t * t;
  double r =
      (((8.05374449538e-2 * z - 1.38776856032e-1) * z + 1.99777106478e-1) * z - 3.33329491539e-1) * z *
          t +
      t;
  if (upper) r += kPi / 4;
  if (steep) r = kPi / 2 - r;
  return x < 0 ? kPi - r : r;
}

// An orthonormal frame around unit n (Duff et al. 2017, branchless).
struct Frame {
  Vec3 s, t, n;
  explicit Frame(const Vec3& normal) : n(normal) { set(nullptr, nullptr); }
  // The frame, and *wLocal = toLocal(w) taken from its axes as they are made: read back from
  // the frame's memory at once, they stalled on the stores that had just written them (each
  // 16-byte load straddled two stores: no store forwarding).
  Frame(const Vec3& normal, const Vec3& w, Vec3* wLocal) : n(normal) { set(&w, wLocal); }
  Vec3 toWorld(const Vec3& local) const { return local.x() * s + local.y() * t + local.z() * n; }
  Vec3 toLocal(const Vec3& world) const { return Vec3(world.dot(s), world.dot(t), world.dot(n)); }

 private:
  void set(const Vec3* w, Vec3* wLocal) {
    const double sign = std::copysign(1.0, n.z());
    const double a = -1.0 / (sign + n.z());
    const double b = n.x() * n.y() * a;
    const Vec3 s0(1.0 + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
    const Vec3 t0(b, sign + n.y() * n.y() * a, -n.y());
    s = s0, t = t0;
    if (w) *wLocal = Vec3(w->dot(s0), w->dot(t0), w->dot(n));
  }
};

// Cosine-weighted hemisphere around +z (local); pdf = cos / pi.
inline Vec3 sampleCosineHemisphere(double u1, double u2) {
  const double r = std::sqrt(u1);
  double sinPhi, cosPhi;
  sinCos(2.0 * kPi * u2, &sinPhi, &cosPhi);
  return Vec3(r * cosPhi, r * sinPhi, std::sqrt(std::max(0.0, 1.0 - u1)));
}

// The share of a planar quad's area in its first triangle (c0 c1 c2); 0.5 for a quad of no area.
inline double firstTriangleShare(const std::array<Vec3, 4>& c) {
  const double a1 = 0.5 * (c[1] - c[0]).cross(c[2] - c[0]).norm();
  const double a2 = 0.5 * (c[2] - c[0]).cross(c[3] - c[0]).norm();
  const double total = a1 + a2;
  return total > 0 ? a1 / total : 0.5;
}

// A point uniformly distributed over a planar quad given by corners in order (pdf = 1 / area),
// p1 = firstTriangleShare(c): u picks one of the two triangles (c0 c1 c2), (c0 c2 c3) by area and
// is reused inside it, so stratified (u, v) stay stratified.
inline Vec3 sampleQuadUniform(const std::array<Vec3, 4>& c, double p1, double u, double v) {
  Vec3 b, e1, e2;
  if (u < p1) {
    u = p1 > 0 ? u / p1 : 0.0;
    b = c[0], e1 = c[1], e2 = c[2];
  } else {
    u = p1 < 1 ? (u - p1) / (1.0 - p1) : 0.0;
    b = c[0], e1 = c[2], e2 = c[3];
  }
  u = std::clamp(u, 0.0, 1.0);
  const double su = std::sqrt(u);
  return (1.0 - su) * b + su * (1.0 - v) * e1 + su * v * e2;
}
inline Vec3 sampleQuadUniform(const std::array<Vec3, 4>& c, double u, double v) {
  return sampleQuadUniform(c, firstTriangleShare(c), u, v);
}

// Uniform sampling of the solid angle a rectangle subtends (Urena, Fajardo, King 2013, "An
// Area-Preserving Parametrization for Spherical Rectangles"): pdf = 1 / solidAngle, so the
// estimator has no 1/d^2 and stays bounded next to the light (a light touching a wall).
// Rectangle: corner s, perpendicular edges ex, ey. Seen from o.
struct SphericalRect {
  Vec3 o, x, y, z;
  double z0 = 0, x0 = 0, y0 = 0, x1 = 0, y1 = 0, b0 = 0, b1 = 0, k = 0;
  double solidAngle = 0;  // 0 when o lies in the rectangle's plane

  SphericalRect(const Vec3& s, const Vec3& ex, const Vec3& ey, const Vec3& origin) : o(origin) {
    const double exl = ex.norm(), eyl = ey.norm();
    x = ex / exl;
    y = ey / eyl;
    z = x.cross(y);
    const Vec3 d = s - o;
    z0 = d.dot(z);
    if (z0 > 0) z = -z, z0 = -z0;  // z points away from the rectangle as seen from o
    x0 = d.dot(x), y0 = d.dot(y);
    x1 = x0 + exl, y1 = y0 + eyl;
    if (!(z0 < 0)) return;
    const Vec3 v00(x0, y0, z0), v01(x0, y1, z0), v10(x1, y0, z0), v11(x1, y1, z0);
    const Vec3 n0 = v00.cross(v10).normalized(), n1 = v10.cross(v11).normalized(),
               n2 = v11.cross(v01).normalized(), n3 = v01.cross(v00).normalized();
    auto angle = [](double c) { return std::acos(std::clamp(c, -1.0, 1.0)); };
    const double g0 = angle(-n0.dot(n1)), g1 = angle(-n1.dot(n2)), g2 = angle(-n2.dot(n3)),
                 g3 = angle(-n3.dot(n0));
    b0 = n0.z();
    b1 = n2.z();
    k = 2.0 * kPi - g2 - g3;
    const double sa = g0 + g1 - k;
    solidAngle = std::isfinite(sa) && sa > 0 ? sa : 0.0;
  }

  Vec3 sample(double u, double v) const {
    double sinAu, cosAu;
    sinCos(u * solidAngle + k, &sinAu, &cosAu);
    const double fu = (cosAu * b0 - b1) / sinAu;
    double cu = std::copysign(1.0, fu) / std::sqrt(fu * fu + b0 * b0);
    cu = std::clamp(cu, -1.0, 1.0);
    double xu = -(cu * z0) / std::sqrt(std::max(1e-300, 1.0 - cu * cu));
    xu = std::clamp(xu, x0, x1);
    const double dd = std::sqrt(xu * xu + z0 * z0);
    const double h0 = y0 / std::sqrt(dd * dd + y0 * y0), h1 = y1 / std::sqrt(dd * dd + y1 * y1);
    const double hv = h0 + v * (h1 - h0), hv2 = hv * hv;
    const double yv = hv2 < 1.0 - 1e-12 ? hv * dd / std::sqrt(1.0 - hv2) : y1;
    return o + xu * x + std::clamp(yv, y0, y1) * y + z0 * z;
  }
};

// Uniform sampling of the solid angle a triangle subtends (Arvo 1995, "Stratified Sampling of
// Spherical Triangles", in pbrt-v4's form). solidAngle by Van Oosterom & Strackee (stable for
// small triangles); 0 when o lies in the triangle's plane.
struct SphericalTriangle {
  Vec3 o, a, b, c;  // unit directions to the corners
  Vec3 planePoint, planeNormal;
  Vec3 nab, nbc, nca;  // normals of the great circles through the corners (not unit)
  double triple = 0;   // |a . (b x c)|
  double solidAngle = 0;

  // The solid angle only: the triangle's angles are worked out when it is sampled (a quad
  // samples one of its two triangles; a pdf needs none).
  SphericalTriangle(const Vec3& A, const Vec3& B, const Vec3& C, const Vec3& origin)
      : SphericalTriangle(A, B, C, origin, (A - origin).normalized(), (B - origin).normalized(),
                          (C - origin).normalized()) {}
  // The same with the unit directions to the corners given (a quad's two triangles share two).
  SphericalTriangle(const Vec3& A, const Vec3& B, const Vec3& C, const Vec3& origin, const Vec3& unitA,
                    const Vec3& unitB, const Vec3& unitC)
      : o(origin), a(unitA), b(unitB), c(unitC), planePoint(A), planeNormal((B - A).cross(C - A)) {
    triple = std::abs(a.dot(b.cross(c)));
    // The arctangent to a relative 2e-8, far below any image's noise, without libm's call.
    const double sa = 2.0 * atan2NonNegative(triple, 1.0 + a.dot(b) + b.dot(c) + c.dot(a));
    nab = a.cross(b), nbc = b.cross(c), nca = c.cross(a);
    if (!(sa > 0) || !std::isfinite(sa) || nab.squaredNorm() == 0 || nbc.squaredNorm() == 0 ||
        nca.squaredNorm() == 0)
      return;
    solidAngle = sa;
  }

  // The point on the triangle in the sampled direction. Arvo's inversion needs the corner
  // angle alpha at a only as its cosine and sine (the great circles' normals' dot product, and
  // |nab x nca| = |a . (b x c)|, both over |nab| |nca|: no inverse trigonometry, one square
  // root), and the sub-triangle's area u0 x solidAngle (the same solid angle the pdf uses): one
  // sincos in all.
  Vec3 sample(double u0, double u1) const {
    const double inv = 1.0 / std::sqrt(nab.squaredNorm() * nca.squaredNorm());
    const double cosA = std::clamp(-nab.dot(nca) * inv, -1.0, 1.0), sinA = std::min(1.0, triple * inv);
    // sin and cos of pi + u0 solidAngle (the sub-triangle's angle sum).
    double sinSub, cosSub;
    sinCos(u0 * solidAngle, &sinSub, &cosSub);
    const double sinAp = -sinSub, cosAp = -cosSub;
    const double sinPhi = sinAp * cosA - cosAp * sinA;
    const double cosPhi = cosAp * cosA + sinAp * sinA;
    const double k1 = cosPhi + cosA;
    const double k2 = sinPhi - sinA * a.dot(b);
    double cosBp = (k2 + (k2 * cosPhi - k1 * sinPhi) * cosA) / ((k2 * sinPhi + k1 * cosPhi) * sinA);
    cosBp = std::isfinite(cosBp) ? std::clamp(cosBp, -1.0, 1.0) : 1.0;
    const double sinBp = std::sqrt(std::max(0.0, 1.0 - cosBp * cosBp));
    const Vec3 cp = cosBp * a + sinBp * orthoNormal(c, a);
    const double cosT = 1.0 - u1 * (1.0 - cp.dot(b));
    const double sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT));
    const Vec3 w = cosT * b + sinT * orthoNormal(cp, b);
    const double t = (planePoint - o).dot(planeNormal) / w.dot(planeNormal);
    return o + t * w;
  }

  static Vec3 orthoNormal(const Vec3& v, const Vec3& w) {
    const Vec3 g = v - v.dot(w) * w;
    const double n = g.norm();
    return n > 0 ? Vec3(g / n) : Vec3::Zero();
  }
};

// A planar convex quad's solid angle as two spherical triangles (c0 c1 c2) and (c0 c2 c3):
// u0 picks one by solid angle and is reused inside it.
struct SphericalQuad {
  SphericalTriangle t1, t2;
  double solidAngle = 0;
  SphericalQuad(const std::array<Vec3, 4>& c, const Vec3& o)
      : SphericalQuad(c, o, unitDirections(c, o)) {}
  SphericalQuad(const std::array<Vec3, 4>& c, const Vec3& o, const std::array<Vec3, 4>& u)
      : t1(c[0], c[1], c[2], o, u[0], u[1], u[2]), t2(c[0], c[2], c[3], o, u[0], u[2], u[3]) {
    if (t1.solidAngle > 0 && t2.solidAngle > 0) solidAngle = t1.solidAngle + t2.solidAngle;
  }
  Vec3 sample(double u0, double u1) const {
    const double p1 = t1.solidAngle / solidAngle;
    if (u0 < p1) return t1.sample(std::clamp(u0 / p1, 0.0, 1.0), u1);
    return t2.sample(std::clamp((u0 - p1) / (1.0 - p1), 0.0, 1.0), u1);
  }
  // The unit directions from o to the corners, each normalised once.
  static std::array<Vec3, 4> unitDirections(const std::array<Vec3, 4>& c, const Vec3& o) {
    return {(c[0] - o).normalized(), (c[1] - o).normalized(), (c[2] - o).normalized(),
            (c[3] - o).normalized()};
  }
};

// True when the quad's corners form a rectangle (to round-off); fills corner and edges.
inline bool asRectangle(const std::array<Vec3, 4>& c, Vec3* s, Vec3* ex, Vec3* ey) {
  const Vec3 e1 = c[1] - c[0], e2 = c[3] - c[0];
  const double l1 = e1.norm(), l2 = e2.norm();
  if (!(l1 > 0) || !(l2 > 0)) return false;
  if (std::abs(e1.dot(e2)) > 1e-6 * l1 * l2) return false;
  if ((c[2] - (c[0] + e1 + e2)).norm() > 1e-6 * (l1 + l2)) return false;
  *s = c[0], *ex = e1, *ey = e2;
  return true;
}

// The emitter geometry of a light: its corners moved kLightOffsetM along its normal.
inline std::array<Vec3, 4> emitterCorners(const AreaLight& light) {
  const Vec3 n = light.normal();
  std::array<Vec3, 4> c = light.cornersWorld;
  if (n.allFinite())
    for (auto& p : c) p += kLightOffsetM * n;
  return c;
}

// Fresnel reflectance of a smooth dielectric; cosI > 0 on the side the ray comes from, eta =
// n_transmitted / n_incident. Returns 1 on total internal reflection; cosT gets the
// transmitted cosine.
inline double fresnelDielectric(double cosI, double eta, double* cosT) {
  cosI = std::clamp(cosI, 0.0, 1.0);
  const double sin2T = (1.0 - cosI * cosI) / (eta * eta);
  if (sin2T >= 1.0) {
    *cosT = 0;
    return 1.0;
  }
  const double ct = std::sqrt(1.0 - sin2T);
  *cosT = ct;
  const double rs = (cosI - eta * ct) / (cosI + eta * ct);
  const double rp = (eta * cosI - ct) / (eta * cosI + ct);
  return 0.5 * (rs * rs + rp * rp);
}

// GGX (Trowbridge-Reitz) normal distribution and Smith masking, local frame (+z normal).
inline double ggxD(const Vec3& h, double alpha) {
  if (h.z() <= 0) return 0;
  const double a2 = alpha * alpha;
  const double c2 = h.z() * h.z();
  const double d = c2 * (a2 - 1.0) + 1.0;
  return a2 / (kPi * d * d);
}
inline double ggxG1(const Vec3& w, double alpha) {
  const double c = std::abs(w.z());
  if (c <= 0) return 0;
  const double c2 = c * c;
  const double tan2 = std::max(0.0, 1.0 - c2) / c2;
  return 2.0 / (1.0 + std::sqrt(1.0 + alpha * alpha * tan2));
}
// Half vector sampled with pdf D(h) cos(h).
inline Vec3 sampleGgxHalfVector(double alpha, double u1, double u2) {
  double sinPhi, cosPhi;
  sinCos(2.0 * kPi * u2, &sinPhi, &cosPhi);
  const double tan2 = alpha * alpha * u1 / std::max(1e-300, 1.0 - u1);
  const double cosT = 1.0 / std::sqrt(1.0 + tan2);
  const double sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT));
  return Vec3(sinT * cosPhi, sinT * sinPhi, cosT);
}

inline double maxComponent(const Vec3& v) { return std::max({v.x(), v.y(), v.z()}); }
inline double meanComponent(const Vec3& v) { return (v.x() + v.y() + v.z()) / 3.0; }

}  // namespace inlay::detail
