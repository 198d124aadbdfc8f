// The BSDFs on their own (render/src/bsdf.h): white-furnace directional albedo (never above 1,
// close to 1 for the lossless ones), importance sampling that agrees with evaluation (the pdf
// is the one the samples follow), and reciprocity where the model is reciprocal.
#include "../render/src/bsdf.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace inlay::detail {
namespace {

Vec3 direction(double thetaDeg, double phi = 0.3) {
  const double t = thetaDeg * kPi / 180.0;
  return Vec3(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t));
}

SurfaceBsdf bsdf(Material::Kind kind, double albedo, double roughness) {
  SurfaceBsdf b;
  b.kind = kind;
  b.albedo = Vec3::Constant(albedo);
  b.alpha = std::max(1e-4, roughness * roughness);
  return b;
}

// Directional albedo by the BSDF's own importance sampling (stratified 2D Sobol' points).
double sampledAlbedo(const SurfaceBsdf& b, const Vec3& wo, int n = 1 << 14) {
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const SampleRng rng(7, 9, uint32_t(i), 3);
    const auto u = rng.get2(0);
    const BsdfSample s = b.sample(wo, rng.get(2), u[0], u[1]);
    if (s.valid) sum += s.weight.x();
  }
  return sum / n;
}

// Directional albedo by uniform hemisphere integration of eval (independent of the sampler).
double integratedAlbedo(const SurfaceBsdf& b, const Vec3& wo, int n = 1 << 16) {
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const SampleRng rng(1, 2, uint32_t(i), 5);
    const auto u = rng.get2(0);
    const double z = u[0], r = std::sqrt(std::max(0.0, 1 - z * z)), phi = 2 * kPi * u[1];
    double pdf = 0;
    sum += b.eval(wo, Vec3(r * std::cos(phi), r * std::sin(phi), z), &pdf).x() * 2 * kPi;
  }
  return sum / n;
}

double roughGlassAlbedo(double roughness, double eta, const Vec3& wo, double* transmitted, int n = 1 << 14) {
  const double alpha = std::max(1e-4, roughness * roughness);
  double sum = 0, through = 0;
  for (int i = 0; i < n; ++i) {
    const SampleRng rng(3, 4, uint32_t(i), 8);
    const auto u = rng.get2(0);
    const BsdfSample s = sampleRoughGlass(wo, alpha, eta, rng.get(2), u[0], u[1]);
    if (!s.valid) continue;
    sum += s.weight.x();
    if (s.dir.z() < 0) through += s.weight.x();
  }
  *transmitted = through / n;
  return sum / n;
}

TEST(BsdfFurnace, AlbedoNeverAboveOneAndLosslessNearOne) {
  struct Case {
    const char* name;
    Material::Kind kind;
    double roughness;
    double minAlbedo;  // below 75 degrees
  };
  const Case cases[] = {{"diffuse", Material::Kind::Diffuse, 0.3, 0.999},
                        {"glossy r0.05", Material::Kind::Glossy, 0.05, 0.97},
                        {"glossy r0.3", Material::Kind::Glossy, 0.3, 0.95},
                        {"glossy r0.8", Material::Kind::Glossy, 0.8, 0.85},
                        {"conductor r0.05", Material::Kind::Conductor, 0.05, 0.97},
                        {"conductor r0.3", Material::Kind::Conductor, 0.3, 0.93},
                        // GGX single scattering loses energy at high roughness: an independent
                        // quadrature gives 0.555 at normal incidence for alpha = 0.64.
                        {"conductor r0.8", Material::Kind::Conductor, 0.8, 0.54}};
  for (const Case& c : cases) {
    const SurfaceBsdf b = bsdf(c.kind, 1.0, c.roughness);
    for (double theta : {0.0, 30.0, 60.0, 75.0, 88.0}) {
      const double a = sampledAlbedo(b, direction(theta));
      std::printf("[ bsdf furnace ] %-16s theta %4.0f: albedo %.4f\n", c.name, theta, a);
      EXPECT_LE(a, 1.005) << c.name << " at " << theta;
      EXPECT_TRUE(std::isfinite(a));
      if (theta <= 75) EXPECT_GE(a, c.minAlbedo) << c.name << " at " << theta;
    }
  }
}

TEST(BsdfFurnace, RoughGlassKeepsEnergyBothWays) {
  for (double roughness : {0.05, 0.3, 0.7})
    for (double eta : {1.5, 1.0 / 1.5})
      for (double theta : {0.0, 30.0, 60.0, 80.0}) {
        double transmitted = 0;
        const double a = roughGlassAlbedo(roughness, eta, direction(theta), &transmitted);
        std::printf("[ bsdf furnace ] rough glass r%.2f eta %.3f theta %2.0f: albedo %.4f (transmitted %.4f)\n",
                    roughness, eta, theta, a, transmitted);
        EXPECT_LE(a, 1.01);
        // Lossless up to GGX's single-scattering loss (largest from the dense side, where
        // rays refracted out at grazing microfacets are masked).
        EXPECT_GE(a, roughness < 0.1 ? 0.999 : roughness < 0.5 ? 0.88 : 0.6);
        if (eta > 1) EXPECT_GT(transmitted, 0.5 * a);
      }
  // Near-smooth and at normal incidence it is the smooth interface: T = 1 - ((n-1)/(n+1))^2.
  double transmitted = 0;
  roughGlassAlbedo(0.01, 1.5, direction(0), &transmitted);
  EXPECT_NEAR(transmitted, 0.96, 0.005);
}

// Importance sampling agrees with evaluation: the sampler's estimate equals uniform
// integration of eval (a wrong pdf in either would bias one of them).
TEST(BsdfSampling, SampledMatchesIntegratedAlbedo) {
  for (auto kind : {Material::Kind::Diffuse, Material::Kind::Glossy, Material::Kind::Conductor})
    for (double roughness : {0.3, 0.6})
      for (double theta : {10.0, 50.0}) {
        const SurfaceBsdf b = bsdf(kind, 0.7, roughness);
        const double s = sampledAlbedo(b, direction(theta)), i = integratedAlbedo(b, direction(theta));
        EXPECT_NEAR(s, i, 0.02 * i) << int(kind) << " roughness " << roughness << " theta " << theta;
      }
}

// f(wo, wi) = f(wi, wo) for the reciprocal models (eval returns f cos(wi)). The coated Glossy
// model weights by F(cos_o) alone and is not: checked to differ, so the test can fail.
TEST(BsdfReciprocity, DiffuseAndConductorAreSymmetric) {
  int asymmetricGlossy = 0;
  for (int i = 0; i < 200; ++i) {
    const SampleRng rng(uint32_t(i), 0, 0, 1);
    const auto a = rng.get2(0), c = rng.get2(1);
    const Vec3 wo = sampleCosineHemisphere(a[0], a[1]), wi = sampleCosineHemisphere(c[0], c[1]);
    if (wo.z() < 1e-3 || wi.z() < 1e-3) continue;
    for (auto kind : {Material::Kind::Diffuse, Material::Kind::Conductor, Material::Kind::Glossy}) {
      SurfaceBsdf b = bsdf(kind, 0.6, 0.4);
      b.albedo = Vec3(0.9, 0.6, 0.3);
      double p = 0;
      const Vec3 f1 = b.eval(wo, wi, &p) / wi.z(), f2 = b.eval(wi, wo, &p) / wo.z();
      if (kind == Material::Kind::Glossy) {
        asymmetricGlossy += (f1 - f2).norm() > 1e-6 * f1.norm();
        continue;
      }
      EXPECT_LT((f1 - f2).norm(), 1e-9 * (1 + f1.norm())) << int(kind);
    }
  }
  EXPECT_GT(asymmetricGlossy, 50);
}

}  // namespace
}  // namespace inlay::detail
