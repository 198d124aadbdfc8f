// Internal: the object and room BSDFs in a local shading frame (+z the normal on the side the
// path arrives from). Pure functions of their inputs, tested directly (white furnace,
// reciprocity, sampling against evaluation) in tests/render_bsdf_test.cpp.
#pragma once

#include "sampling.h"

namespace inlay::detail {

struct BsdfSample {
  Vec3 dir;
  Vec3 weight;     // f cos / pdf
  double pdf = 0;  // solid angle; 0 for specular
  bool specular = false;
  bool valid = false;
};

inline Vec3 reflect(const Vec3& wo, const Vec3& n) { return 2.0 * wo.dot(n) * n - wo; }

// A GGX microfacet normal sampled in proportion to its visible area from wo (Heitz 2018,
// "Sampling the GGX Distribution of Visible Normals"): pdf G1(wo) max(0, wo.h) D(h) / wo.z.
inline Vec3 sampleGgxVisibleNormal(const Vec3& wo, double alpha, double u1, double u2) {
  const Vec3 v = Vec3(alpha * wo.x(), alpha * wo.y(), wo.z()).normalized();  // the stretched view
  const double lenSq = v.x() * v.x() + v.y() * v.y();
  const Vec3 t1 = lenSq > 0 ? Vec3(Vec3(-v.y(), v.x(), 0) / std::sqrt(lenSq)) : Vec3(1, 0, 0);
  const Vec3 t2 = v.cross(t1);
  const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
  const double p1 = r * std::cos(phi), s = 0.5 * (1.0 + v.z());
  const double p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * r * std::sin(phi);
  const Vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * v;
  return Vec3(alpha * nh.x(), alpha * nh.y(), std::max(0.0, nh.z())).normalized();
}

// Directional albedo E(mu, alpha) of the GGX reflection lobe with Fresnel 1 (single
// scattering, Smith G1 G1), and its cosine-weighted mean E_avg(alpha) = 2 int E mu dmu: the
// energy that multiple scattering between microfacets would return (Kulla & Conty 2017,
// "Revisiting Physically Based Shading at Imageworks"). Computed once, on first use, by
// sampling the visible normals (128 Sobol' points per node, each weighing G1(wi): low variance
// even at grazing angles, where D(h) cos(h) sampling is noisy): a pure function of the code.
// Nodes are uniform in sqrt(mu) and in roughness = sqrt(alpha) (E changes fastest at grazing
// mu and small alpha); lookups interpolate bilinearly in those, and E_avg integrates that
// interpolant, so the compensated lobe's albedo is 1 for the table's own E.
class GgxAlbedoTable {
 public:
  static constexpr int kSize = 32;  // nodes per axis, ends included
  static const GgxAlbedoTable& instance() {
    static const GgxAlbedoTable table;
    return table;
  }
  double albedo(double mu, double alpha) const {
    const double x = std::sqrt(std::clamp(mu, 0.0, 1.0)) * (kSize - 1);
    const double y = std::clamp(std::sqrt(std::max(alpha, 0.0)), 0.0, 1.0) * (kSize - 1);
    const int i = std::min(int(x), kSize - 2), j = std::min(int(y), kSize - 2);
    const double fx = x - i, fy = y - j;
    auto at = [&](int a, int b) { return e_[size_t(b) * kSize + size_t(a)]; };
    return (1 - fy) * ((1 - fx) * at(i, j) + fx * at(i + 1, j)) +
           fy * ((1 - fx) * at(i, j + 1) + fx * at(i + 1, j + 1));
  }
  double average(double alpha) const {
    const double y = std::clamp(std::sqrt(std::max(alpha, 0.0)), 0.0, 1.0) * (kSize - 1);
    const int j = std::min(int(y), kSize - 2);
    return eAvg_[size_t(j)] + (y - j) * (eAvg_[size_t(j) + 1] - eAvg_[size_t(j)]);
  }

 private:
  GgxAlbedoTable();
  std::array<double, kSize * kSize> e_{};  // [roughness node][mu node]
  std::array<double, kSize> eAvg_{};
};

inline GgxAlbedoTable::GgxAlbedoTable() {
  constexpr int kSamples = 128;
  for (int j = 0; j < kSize; ++j) {
    const double r = double(j) / (kSize - 1), alpha = std::max(1e-4, r * r);
    for (int i = 0; i < kSize; ++i) {
      const double s = double(i) / (kSize - 1),
                   mu = std::max(1e-4, s * s);  // grazing: the limit's neighbour
      const Vec3 wo(std::sqrt(1 - mu * mu), 0, mu);
      double sum = 0;
      for (int k = 0; k < kSamples; ++k) {
        const SampleRng rng(uint32_t(i), uint32_t(j), uint32_t(k), 0x6a09e667u);
        const auto u = rng.get2(0);
        const Vec3 wi = reflect(wo, sampleGgxVisibleNormal(wo, alpha, u[0], u[1]));
        if (wi.z() > 0) sum += ggxG1(wi, alpha);  // f cos / pdf = G1 G1 / G1(wo)
      }
      e_[size_t(j) * kSize + size_t(i)] = std::min(1.0, sum / kSamples);
    }
  }
  // E_avg of the interpolant along mu at each roughness node (linear in between, as albedo()
  // interpolates): the midpoint rule on 4096 steps.
  constexpr int kSteps = 4096;
  for (int j = 0; j < kSize; ++j) {
    const double r = double(j) / (kSize - 1), alpha = r * r;  // exactly on the node
    double avg = 0;
    for (int k = 0; k < kSteps; ++k) {
      const double mu = (k + 0.5) / kSteps;
      avg += 2.0 * albedo(mu, alpha) * mu / kSteps;
    }
    eAvg_[size_t(j)] = std::min(avg, 1.0);
  }
}

// Schlick's Fresnel for a conductor of normal-incidence reflectance f0 (RGB).
inline Vec3 fresnelSchlick(const Vec3& f0, double cosTheta) {
  const double m = std::pow(std::clamp(1.0 - cosTheta, 0.0, 1.0), 5.0);
  return f0 + (Vec3::Ones() - f0) * m;
}

// The reflecting (NEE-able) BSDFs:
// - Diffuse: Lambertian.
// - Glossy (dielectric-coated): f = F(cos_o) * DG / (4 cos_i cos_o) + (1 - F(cos_o)) albedo / pi,
//   where the GGX lobe without Fresnel has directional albedo <= 1, so the total never exceeds
//   F + (1 - F) albedo <= 1. Not reciprocal (F of the outgoing direction only); a
//   unidirectional tracer does not need reciprocity.
// - Conductor: GGX with Schlick Fresnel of F0 = albedo, f = F(wi.h) D G1(wo) G1(wi) /
//   (4 cos_i cos_o), plus Kulla-Conty's multiple-scattering lobe f_ms = F_ms (1 - E(cos_o))
//   (1 - E(cos_i)) / (pi (1 - E_avg)), which returns what single scattering loses at high
//   roughness (a white rough metal keeps its energy). Reciprocal, energy <= 1. Sampled by
//   GGX half vectors with probability E(cos_o), else cosine-weighted.
// - RoughGlass (two-sided: wi may lie below, transmitted): see roughGlassEval().
struct SurfaceBsdf {
  Material::Kind kind = Material::Kind::Diffuse;
  Vec3 albedo{0.5, 0.5, 0.5};
  double alpha = 0.1;
  double ior = 1.5;
  double eta = 1.5;  // RoughGlass: n on wi's far side / n on wo's side (ior or 1 / ior)

  bool nonSpecular() const {
    return kind == Material::Kind::Diffuse || kind == Material::Kind::Glossy ||
           kind == Material::Kind::Conductor || kind == Material::Kind::RoughGlass;
  }
  bool transmits() const { return kind == Material::Kind::RoughGlass; }
  double coatFresnel(double cosO) const {
    double cosT = 0;
    return fresnelDielectric(cosO, ior, &cosT);
  }
  // f * cos(wi) and the sampling pdf.
  Vec3 eval(const Vec3& wo, const Vec3& wi, double* pdf) const;
  Vec3 evalReflecting(const Vec3& wo, const Vec3& wi, double* pdf) const {
    *pdf = 0;
    if (wo.z() <= 0 || wi.z() <= 0) return Vec3::Zero();
    if (kind == Material::Kind::Diffuse) {
      *pdf = wi.z() / kPi;
      return albedo * (wi.z() / kPi);
    }
    Vec3 h = wo + wi;
    const double hn = h.norm();
    if (!(hn > 0)) return Vec3::Zero();
    h /= hn;
    const double d = ggxD(h, alpha);
    const double spec = d * ggxG1(wo, alpha) * ggxG1(wi, alpha) / (4.0 * wo.z());  // * cos_i / cos_i
    const double specPdf = d * h.z() / (4.0 * std::max(1e-12, wo.dot(h)));
    if (kind == Material::Kind::Conductor) {
      const GgxAlbedoTable& table = GgxAlbedoTable::instance();
      const double eo = table.albedo(wo.z(), alpha), pickSpec = std::max(eo, 0.05);
      *pdf = pickSpec * specPdf + (1.0 - pickSpec) * wi.z() / kPi;
      return fresnelSchlick(albedo, wi.dot(h)) * spec + multipleScattering(eo, wi.z()) * wi.z();
    }
    const double f = coatFresnel(wo.z());
    *pdf = f * specPdf + (1.0 - f) * wi.z() / kPi;
    return Vec3::Constant(f * spec) + (1.0 - f) * albedo * (wi.z() / kPi);
  }
  // Kulla-Conty's f_ms (per colour channel) for outgoing albedo eo = E(cos_o) and cos_i.
  // F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), with Schlick's hemispherical average
  // F_avg = F0 + (1 - F0) / 21 (2 int (1 - mu)^5 mu dmu = 1/21).
  Vec3 multipleScattering(double eo, double cosI) const {
    const GgxAlbedoTable& table = GgxAlbedoTable::instance();
    const double eAvg = table.average(alpha);
    if (!(eAvg < 1.0 - 1e-6)) return Vec3::Zero();
    const Vec3 fAvg = albedo + (Vec3::Ones() - albedo) / 21.0;
    const Vec3 fms = (fAvg.cwiseProduct(fAvg) * eAvg).cwiseQuotient(Vec3::Ones() - fAvg * (1.0 - eAvg));
    return fms * ((1.0 - eo) * (1.0 - table.albedo(cosI, alpha)) / (kPi * (1.0 - eAvg)));
  }
  BsdfSample sample(const Vec3& wo, double uLobe, double u1, double u2) const;
  BsdfSample sampleReflecting(const Vec3& wo, double uLobe, double u1, double u2) const {
    BsdfSample s;
    if (wo.z() <= 0) return s;
    Vec3 wi;
    const bool specLobe = kind == Material::Kind::Conductor
                              ? uLobe < std::max(GgxAlbedoTable::instance().albedo(wo.z(), alpha), 0.05)
                              : kind == Material::Kind::Glossy && uLobe < coatFresnel(wo.z());
    if (specLobe) {
      const Vec3 h = sampleGgxHalfVector(alpha, u1, u2);
      wi = reflect(wo, h);
    } else {
      wi = sampleCosineHemisphere(u1, u2);
    }
    if (wi.z() <= 0) return s;
    const Vec3 fcos = eval(wo, wi, &s.pdf);
    if (!(s.pdf > 0)) return s;
    s.dir = wi;
    s.weight = fcos / s.pdf;
    s.valid = true;
    return s;
  }
};

// Rough glass (Walter, Marschner, Li, Torrance 2007, "Microfacet Models for Refraction through
// Rough Surfaces"): a GGX microfacet normal h sampled with pdf D(h) cos(h), reflection with the
// dielectric Fresnel F(wo.h) and refraction otherwise. wo.z > 0; eta = n_inside_of_wi /
// n_side_of_wo. As for smooth glass, radiance is not scaled by eta^2 (it cancels on the way
// out), which makes the transmission weight G1(wo) G1(wi) |wo.h| / (wo.z h.z), the same
// expression as reflection's. roughGlassEval() is the f |cos_i| and pdf this sampler follows
// (so NEE through it and BSDF sampling combine by MIS without bias):
//   reflection   f|cos_i| = F D G1 G1 / (4 wo.z),   pdf = F D h.z / (4 wo.h),  h ~ wo + wi;
//   transmission f|cos_i| = (1 - F) D G1 G1 eta^2 |wo.h| |wi.h| / (wo.z (wo.h + eta wi.h)^2),
//                pdf = (1 - F) D h.z eta^2 |wi.h| / (wo.h + eta wi.h)^2,  h ~ -(wo + eta wi).
inline Vec3 roughGlassEval(const Vec3& wo, const Vec3& wi, double alpha, double eta, double* pdf) {
  *pdf = 0;
  if (wo.z() <= 0 || wi.z() == 0) return Vec3::Zero();
  const bool reflected = wi.z() > 0;
  Vec3 h = reflected ? Vec3(wo + wi) : Vec3(-(wo + eta * wi));
  const double hn = h.norm();
  if (!(hn > 0)) return Vec3::Zero();
  h /= hn;
  if (h.z() < 0) h = -h;
  const double cosO = wo.dot(h), cosI = wi.dot(h);
  // The microfacet must face wo, and wi must leave on the side the lobe says.
  if (!(cosO > 0) || (reflected ? cosI <= 0 : cosI >= 0)) return Vec3::Zero();
  double cosT = 0;
  const double f = fresnelDielectric(cosO, eta, &cosT);
  const double d = ggxD(h, alpha);
  const double g = ggxG1(wo, alpha) * ggxG1(wi, alpha);
  double value = 0;
  if (reflected) {
    value = f * d * g / (4.0 * wo.z());
    *pdf = f * d * h.z() / (4.0 * cosO);
  } else {
    const double denom = cosO + eta * cosI;
    if (!(std::abs(denom) > 1e-12)) return Vec3::Zero();
    const double jacobian = eta * eta * std::abs(cosI) / (denom * denom);  // dh / dwi
    value = (1.0 - f) * d * g * cosO * jacobian / wo.z();
    *pdf = (1.0 - f) * d * h.z() * jacobian;
  }
  if (!std::isfinite(value) || !std::isfinite(*pdf)) return *pdf = 0, Vec3::Zero();
  return Vec3::Constant(value);
}

inline BsdfSample sampleRoughGlass(const Vec3& wo, double alpha, double eta, double uLobe, double u1,
                                   double u2) {
  BsdfSample s;
  if (wo.z() <= 0) return s;
  const Vec3 h = sampleGgxHalfVector(alpha, u1, u2);
  const double cosI = wo.dot(h);
  if (!(cosI > 0)) return s;
  double cosT = 0;
  const double f = fresnelDielectric(cosI, eta, &cosT);
  Vec3 wi;
  if (uLobe < f) {
    wi = reflect(wo, h);
    if (wi.z() <= 0) return s;
  } else {
    wi = (-wo / eta + (cosI / eta - cosT) * h).normalized();
    if (wi.z() >= 0) return s;
  }
  const double w = ggxG1(wo, alpha) * ggxG1(wi, alpha) * cosI / (wo.z() * h.z());
  if (!std::isfinite(w)) return s;
  roughGlassEval(wo, wi, alpha, eta, &s.pdf);
  if (!(s.pdf > 0)) return s;
  s.dir = wi;
  s.weight = Vec3::Constant(w);
  s.valid = true;
  return s;
}

// A shading normal ns (unit, on wo's side of the geometric normal ng) whose mirror reflection of
// wo leaves the surface: ns itself when reflect(wo, ns) rises at least min(0.9 wo.ng, 0.01)
// above the real surface (a reflection may always be as shallow as the incoming ray), else the
// half vector of wo and that reflection lifted, keeping its azimuth, to exactly that elevation.
// At an interpolated normal's silhouette the mirror direction otherwise points into the
// surface, and a path that ends there is black (the dark outline a low-polygon glass object had).
inline Vec3 reflectableNormal(const Vec3& wo, const Vec3& ng, const Vec3& ns) {
  const Vec3 r = reflect(wo, ns);
  const double floor = std::min(0.9 * wo.dot(ng), 0.01);
  if (r.dot(ng) >= floor) return ns;
  const Vec3 along = r - r.dot(ng) * ng;  // r's tangential part: its azimuth
  const double len = along.norm();
  const double lift = std::max(floor, 0.0);
  const Vec3 tangent = len > 1e-12 ? Vec3(along / len) : Vec3(-(wo - wo.dot(ng) * ng).normalized());
  const Vec3 lifted = std::sqrt(std::max(0.0, 1.0 - lift * lift)) * tangent + lift * ng;
  const Vec3 h = wo + lifted;
  const double hn = h.norm();
  return hn > 1e-12 && h.allFinite() ? Vec3(h / hn) : ng;
}

// A smooth dielectric interface (clear: no absorption) hit from wo: the reflected or refracted
// direction, chosen with the Fresnel probability by u in [0, 1) (so the weight is 1 either way;
// radiance is not scaled by eta^2, which cancels on the way out of a closed object). eta = n on
// the far side of the interface / n on wo's side; ngFacing the geometric normal on wo's side,
// ns the shading normal (the geometric one without vertex normals), turned to wo's side too.
// The shading normal is made reflectable first (reflectableNormal); where it would still send
// the refracted ray out on wo's side of the real surface (or a reflection below it), the
// geometric normal decides instead: a sample is never lost, so the object never turns black at
// its outline. `reflected` says which side the direction leaves on.
struct SmoothGlassSample {
  Vec3 dir = Vec3::Zero();
  bool reflected = false;
  double fresnel = 0;  // the reflectance that chose
};
inline SmoothGlassSample sampleSmoothGlassWith(const Vec3& wo, const Vec3& n, double eta, double u) {
  SmoothGlassSample s;
  const double cosI = std::max(0.0, wo.dot(n));
  double cosT = 0;
  s.fresnel = fresnelDielectric(cosI, eta, &cosT);
  s.reflected = u < s.fresnel;
  s.dir = s.reflected ? reflect(wo, n) : Vec3(-wo / eta + (cosI / eta - cosT) * n);
  s.dir.normalize();
  return s;
}
inline SmoothGlassSample sampleSmoothGlass(const Vec3& wo, const Vec3& ngFacing, const Vec3& ns,
                                           double eta, double u) {
  Vec3 n = ns.dot(ngFacing) > 0 && wo.dot(ns) > 0 ? reflectableNormal(wo, ngFacing, ns) : ngFacing;
  SmoothGlassSample s = sampleSmoothGlassWith(wo, n, eta, u);
  const double side = s.dir.dot(ngFacing);
  if (!(s.reflected ? side > 0 : side < 0) || !s.dir.allFinite())
    s = sampleSmoothGlassWith(wo, ngFacing, eta, u);
  return s;
}

inline Vec3 SurfaceBsdf::eval(const Vec3& wo, const Vec3& wi, double* pdf) const {
  if (kind == Material::Kind::RoughGlass) return roughGlassEval(wo, wi, alpha, eta, pdf);
  return evalReflecting(wo, wi, pdf);
}

inline BsdfSample SurfaceBsdf::sample(const Vec3& wo, double uLobe, double u1, double u2) const {
  if (kind == Material::Kind::RoughGlass) return sampleRoughGlass(wo, alpha, eta, uLobe, u1, u2);
  return sampleReflecting(wo, uLobe, u1, u2);
}

}  // namespace inlay::detail
