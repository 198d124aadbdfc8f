// Synthetic layers with a known answer for the intrinsic decomposition (its unit tests and
// bench_decompose): a checker reflectance of two colours under a smooth direct light and a smooth
// indirect Gamma, B = rho * (D + Gamma).
#pragma once

#include "inlay/modeling/image.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace inlay::test {

struct Layers {
  ImageF B, gamma, rhoTrue;
  std::vector<uint8_t> valid, clipped;
};

inline Layers makeLayers(int W, int H, int cell = 8) {
  Layers l{ImageF(W, H, 3), ImageF(W, H, 3), ImageF(W, H, 3), std::vector<uint8_t>(size_t(W) * H, 1),
           std::vector<uint8_t>(size_t(W) * H, 0)};
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const bool odd = ((x / cell) + (y / cell)) & 1;
      const Vec3 rho = odd ? Vec3(0.7, 0.6, 0.5) : Vec3(0.3, 0.35, 0.4);
      const double u = double(x) / W, v = double(y) / H;
      const double direct = 0.4 + 0.3 * std::exp(-4 * ((u - 0.4) * (u - 0.4) + (v - 0.3) * (v - 0.3)));
      const double gamma = 0.2 + 0.1 * u;
      l.rhoTrue.setRgb(x, y, rho);
      l.gamma.setRgb(x, y, Vec3::Constant(gamma));
      l.B.setRgb(x, y, rho * (direct + gamma));
    }
  return l;
}

}  // namespace inlay::test
