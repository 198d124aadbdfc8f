// Internal: the object and room BSDFs in a local shading frame (+z the normal on the side the
// path arrives from). Pure functions of their inputs, tested directly (white furnace,
// reciprocity, sampling against evaluation) in tests/render_bsdf_test.cpp.
#pragma once

#include "sampling.h"

namespace inlay::detail {

struct BsdfSample {
  Vec3 dir;
  Vec3 weight;        // f cos / pdf
  double pdf = 0;     // solid angle; 0 for specular
  bool specular = false;
  bool valid = false;
};

inline Vec3 reflect(const Vec3& wo, const Vec3& n) { return 2.0 * wo.dot(n) * n - wo; }

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
//   (4 cos_i cos_o): reciprocal, energy <= 1 (single scattering: rough metal loses a little).
struct SurfaceBsdf {
  Material::Kind kind = Material::Kind::Diffuse;
  Vec3 albedo{0.5, 0.5, 0.5};
  double alpha = 0.1;
  double ior = 1.5;

  bool nonSpecular() const {
    return kind == Material::Kind::Diffuse || kind == Material::Kind::Glossy ||
           kind == Material::Kind::Conductor;
  }
  double coatFresnel(double cosO) const {
    double cosT = 0;
    return fresnelDielectric(cosO, ior, &cosT);
  }
  // f * cos(wi) and the sampling pdf.
  Vec3 eval(const Vec3& wo, const Vec3& wi, double* pdf) const {
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
      *pdf = specPdf;
      return fresnelSchlick(albedo, wi.dot(h)) * spec;
    }
    const double f = coatFresnel(wo.z());
    *pdf = f * specPdf + (1.0 - f) * wi.z() / kPi;
    return Vec3::Constant(f * spec) + (1.0 - f) * albedo * (wi.z() / kPi);
  }
  BsdfSample sample(const Vec3& wo, double uLobe, double u1, double u2) const {
    BsdfSample s;
    if (wo.z() <= 0) return s;
    Vec3 wi;
    if (kind == Material::Kind::Conductor ||
        (kind == Material::Kind::Glossy && uLobe < coatFresnel(wo.z()))) {
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
// expression as reflection's. Treated as a specular vertex by the tracer (no NEE: lights
// behind the glass are reached by the sampled direction), which keeps it unbiased.
inline BsdfSample sampleRoughGlass(const Vec3& wo, double alpha, double eta, double uLobe, double u1, double u2) {
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
  s.dir = wi;
  s.weight = Vec3::Constant(w);
  s.specular = true;
  s.valid = true;
  return s;
}

}  // namespace inlay::detail
