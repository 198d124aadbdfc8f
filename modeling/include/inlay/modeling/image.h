// Float images and the photo's colour conventions.
//
// ImageF is H x W x C floats, row-major, channels interleaved, row 0 at the top (pixel (x, y)
// covers [x, x+1) x [y, y+1) in the scene file's pixel frame). What the values mean is in the
// variable's name: `linearRgb` (scene-referred linear, the photo's units: 1.0 is a pure white
// pixel), `srgb` (display-encoded in [0,1]), `albedo` (reflectance in [0,1]), `mask` (C = 1).
#pragma once

#include "inlay/modeling/core.h"

#include <cmath>
#include <vector>

namespace inlay {

struct ImageF {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<float> data;

  ImageF() = default;
  ImageF(int w, int h, int c, float fill = 0.f)
      : width(w), height(h), channels(c), data(size_t(w) * size_t(h) * size_t(c), fill) {}

  bool empty() const { return data.empty(); }
  size_t pixelCount() const { return size_t(width) * size_t(height); }
  float& at(int x, int y, int c = 0) { return data[(size_t(y) * width + x) * channels + c]; }
  float at(int x, int y, int c = 0) const { return data[(size_t(y) * width + x) * channels + c]; }
  float* pixel(int x, int y) { return &data[(size_t(y) * width + x) * channels]; }
  const float* pixel(int x, int y) const { return &data[(size_t(y) * width + x) * channels]; }
  Vec3 rgb(int x, int y) const {
    const float* p = pixel(x, y);
    return channels >= 3 ? Vec3(p[0], p[1], p[2]) : Vec3(p[0], p[0], p[0]);
  }
  void setRgb(int x, int y, const Vec3& v) {
    float* p = pixel(x, y);
    for (int c = 0; c < std::min(channels, 3); ++c) p[c] = float(v[c]);
  }
};

// The sRGB transfer functions (IEC 61966-2-1), per channel; input clamped to [0, 1] on encode.
inline float srgbToLinear(float v) {
  if (!(v > 0.f)) return 0.f;
  if (v >= 1.f) return 1.f;
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}
inline float linearToSrgb(float v) {
  if (!(v > 0.f)) return 0.f;  // also maps NaN to 0
  if (v >= 1.f) return 1.f;
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.f / 2.4f) - 0.055f;
}

}  // namespace inlay
