#include "image_convert.h"

#include <array>
#include <cmath>

namespace inlay::studio {
namespace {

// linear in [0,1] quantised to 1/65535 -> 8-bit sRGB. At the steepest part of the curve (near
// black, slope 12.92) one step is 0.05 of an 8-bit code, so the table is exact to rounding.
constexpr int kLutSize = 65536;

const std::array<uchar, kLutSize>& srgbLut() {
  static const std::array<uchar, kLutSize> lut = [] {
    std::array<uchar, kLutSize> t{};
    for (int i = 0; i < kLutSize; ++i)
      t[i] = uchar(std::lround(255.0f * linearToSrgb(float(i) / float(kLutSize - 1))));
    return t;
  }();
  return lut;
}

inline uchar encode(float linear, const std::array<uchar, kLutSize>& lut) {
  if (!(linear > 0.f)) return 0;  // also NaN
  if (linear >= 1.f) return 255;
  return lut[size_t(linear * float(kLutSize - 1) + 0.5f)];
}

}  // namespace

namespace {

// Encodes each pixel's channels (grey images repeat their one channel) after the exposure gain
// with `code`: linear -> 8-bit code.
template <class Code>
QImage encodedImage(const ImageF& linearRgb, double exposureStops, Code code) {
  if (linearRgb.empty() || linearRgb.width <= 0 || linearRgb.height <= 0) return {};
  const float gain = float(std::exp2(exposureStops));
  const int c = linearRgb.channels;
  QImage out(linearRgb.width, linearRgb.height, QImage::Format_RGB32);
  for (int y = 0; y < linearRgb.height; ++y) {
    auto* row = reinterpret_cast<QRgb*>(out.scanLine(y));
    for (int x = 0; x < linearRgb.width; ++x) {
      const float* p = linearRgb.pixel(x, y);
      row[x] = qRgb(code(p[0] * gain), code((c >= 3 ? p[1] : p[0]) * gain), code((c >= 3 ? p[2] : p[0]) * gain));
    }
  }
  return out;
}

}  // namespace

QImage srgb8FromLinear(const ImageF& linearRgb, double exposureStops) {
  const auto& lut = srgbLut();
  return encodedImage(linearRgb, exposureStops, [&lut](float v) { return encode(v, lut); });
}

QImage encoded8FromLinear(const ImageF& linearRgb, const CameraResponse& response, double exposureStops) {
  if (response.family() != ResponseFamily::ToeShoulder) return srgb8FromLinear(linearRgb, exposureStops);
  return encodedImage(linearRgb, exposureStops, [&response](float v) { return response.encodeCode8(v); });
}

}  // namespace inlay::studio
