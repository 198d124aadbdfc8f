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
inline uint32_t pcgHash(uint32_t v) {
  const uint32_t state = v * 747796405u + 2891336453u;
  const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// Random numbers as a pure function of (pixel x, y, sample, dimension, seed): every render
// replays exactly and the with-object and without-object paths share them.
class SampleRng {
 public:
  SampleRng(uint32_t x, uint32_t y, uint32_t sample, uint32_t seed)
      : key_(pcgHash(sample + pcgHash(y + pcgHash(x + pcgHash(seed))))) {}
  // Uniform in [0, 1).
  double get(uint32_t dimension) const {
    const uint32_t h = pcgHash(key_ ^ pcgHash(dimension * 0x9E3779B9u + 0x632BE5ABu));
    return double(h >> 8) * (1.0 / 16777216.0);
  }

 private:
  uint32_t key_;
};

// An orthonormal frame around unit n (Duff et al. 2017, branchless).
struct Frame {
  Vec3 s, t, n;
  explicit Frame(const Vec3& normal) : n(normal) {
    const double sign = std::copysign(1.0, n.z());
    const double a = -1.0 / (sign + n.z());
    const double b = n.x() * n.y() * a;
    s = Vec3(1.0 + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
    t = Vec3(b, sign + n.y() * n.y() * a, -n.y());
  }
  Vec3 toWorld(const Vec3& local) const { return local.x() * s + local.y() * t + local.z() * n; }
  Vec3 toLocal(const Vec3& world) const { return Vec3(world.dot(s), world.dot(t), world.dot(n)); }
};

// Cosine-weighted hemisphere around +z (local); pdf = cos / pi.
inline Vec3 sampleCosineHemisphere(double u1, double u2) {
  const double r = std::sqrt(u1);
  const double phi = 2.0 * kPi * u2;
  return Vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u1)));
}

// A point uniformly distributed over a planar quad given by corners in order (pdf = 1 / area):
// u picks one of the two triangles (c0 c1 c2), (c0 c2 c3) by area and is reused inside it, so
// stratified (u, v) stay stratified.
inline Vec3 sampleQuadUniform(const std::array<Vec3, 4>& c, double u, double v) {
  const double a1 = 0.5 * (c[1] - c[0]).cross(c[2] - c[0]).norm();
  const double a2 = 0.5 * (c[2] - c[0]).cross(c[3] - c[0]).norm();
  const double total = a1 + a2;
  const double p1 = total > 0 ? a1 / total : 0.5;
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
  const double phi = 2.0 * kPi * u2;
  const double tan2 = alpha * alpha * u1 / std::max(1e-300, 1.0 - u1);
  const double cosT = 1.0 / std::sqrt(1.0 + tan2);
  const double sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT));
  return Vec3(sinT * std::cos(phi), sinT * std::sin(phi), cosT);
}

inline double maxComponent(const Vec3& v) { return std::max({v.x(), v.y(), v.z()}); }
inline double meanComponent(const Vec3& v) { return (v.x() + v.y() + v.z()) / 3.0; }

}  // namespace inlay::detail
