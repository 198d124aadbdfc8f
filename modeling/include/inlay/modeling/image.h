// Float images and the photo's colour conventions.
//
// ImageF is H x W x C floats, row-major, channels interleaved, row 0 at the top (pixel (x, y)
// covers [x, x+1) x [y, y+1) in the scene file's pixel frame). What the values mean is in the
// variable's name: `linearRgb` (scene-referred linear, the photo's units: 1.0 is a pure white
// pixel), `srgb` (display-encoded in [0,1]), `albedo` (reflectance in [0,1]), `mask` (C = 1).
#pragma once

#include "inlay/modeling/core.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>
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

// The sRGB transfer functions (IEC 61966-2-1), per channel, in float or double; input clamped to
// [0, 1] (NaN to 0). The one definition of the curve: every sRGB conversion goes through these.
template <class T>
inline T srgbToLinear(T v) {
  static_assert(std::is_floating_point_v<T>);
  if (!(v > T(0))) return T(0);
  if (v >= T(1)) return T(1);
  return v <= T(0.04045) ? v / T(12.92) : std::pow((v + T(0.055)) / T(1.055), T(2.4));
}
template <class T>
inline T linearToSrgb(T v) {
  static_assert(std::is_floating_point_v<T>);
  if (!(v > T(0))) return T(0);  // also maps NaN to 0
  if (v >= T(1)) return T(1);
  return v <= T(0.0031308) ? T(12.92) * v : T(1.055) * std::pow(v, T(1) / T(2.4)) - T(0.055);
}

// d linearToSrgb / dv: the error a small linear error becomes on screen. 12.92 on the linear
// toe; above 1 the slope at 1 (displays clip, so this bounds it).
inline double srgbSlope(double v) {
  if (!(v > 0.0031308)) return 12.92;
  v = std::min(v, 1.0);
  return 1.055 / 2.4 * std::pow(v, 1.0 / 2.4 - 1.0);
}

namespace detail {

// The 8-bit sRGB code of a linear value, exactly lround(255 * linearToSrgb(v)) but without a
// pow per value: the code is the number of code boundaries at or below v (linearToSrgb is
// monotone), each boundary found once by bisection on floats; a coarse table of 4096 buckets
// gives the first code to try, so a value takes a step or two.
class SrgbEncoder {
 public:
  SrgbEncoder() {
    for (int code = 1; code < 256; ++code) {
      float lo = 0.f, hi = 1.f;  // code(lo) < code <= code(hi)
      while (std::nextafter(lo, hi) < hi) {
        const float mid = 0.5f * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (codeOf(mid) >= code ? hi : lo) = mid;
      }
      boundary_[size_t(code - 1)] = hi;
    }
    for (int b = 0; b < kBuckets; ++b)  // the code of the bucket's least value
      start_[size_t(b)] =
          (unsigned char)(std::upper_bound(boundary_.begin(), boundary_.end(), float(b) / kBuckets) -
                          boundary_.begin());
  }
  unsigned char operator()(float v) const {
    if (!(v > 0.f)) return 0;  // also NaN
    if (v >= 1.f) return 255;
    unsigned code = start_[size_t(v * kBuckets)];
    while (code < 255 && v >= boundary_[code]) ++code;
    return (unsigned char)code;
  }
  static int codeOf(float v) { return int(std::lround(255.f * linearToSrgb(v))); }

 private:
  static constexpr int kBuckets = 4096;
  std::array<float, 255> boundary_{};  // boundary_[c - 1]: the least v of code c
  std::array<unsigned char, kBuckets> start_{};
};

}  // namespace detail

// The 8-bit sRGB code of a linear value: lround(255 * linearToSrgb(linear)), exactly.
inline unsigned char srgbCode8(float linear) {
  static const detail::SrgbEncoder encode;
  return encode(linear);
}

}  // namespace inlay
