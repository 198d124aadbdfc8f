// The object materials the render benchmarks compare (bench_render, bench_denoise): one case per
// kind of BSDF the path tracer samples differently, plus an emitter.
#pragma once

#include "inlay/render/scene.h"

#include <vector>

namespace inlay::bench {

struct MaterialCase {
  const char* name;
  Material material;
};

inline std::vector<MaterialCase> materialCases() {
  auto make = [](Material::Kind k, const Vec3& albedo, double roughness = 0.3) {
    Material m;
    m.kind = k;
    m.albedo = albedo;
    m.roughness = roughness;
    return m;
  };
  Material glow = make(Material::Kind::Emissive, Vec3::Zero());
  glow.emission = Vec3(3.0, 2.4, 1.6);
  return {{"diffuse", make(Material::Kind::Diffuse, Vec3(0.7, 0.7, 0.7))},
          {"glossy", make(Material::Kind::Glossy, Vec3(0.6, 0.1, 0.1), 0.3)},
          {"mirror", make(Material::Kind::Mirror, Vec3(0.9, 0.9, 0.9))},
          {"glass", make(Material::Kind::Glass, Vec3(1, 1, 1))},
          {"glowing", glow}};
}

}  // namespace inlay::bench
