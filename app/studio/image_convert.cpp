#include "image_convert.h"

#include <cmath>

namespace inlay::studio {
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
      row[x] = qRgb(code(p[0] * gain), code((c >= 3 ? p[1] : p[0]) * gain),
                    code((c >= 3 ? p[2] : p[0]) * gain));
    }
  }
  return out;
}

}  // namespace

QImage srgb8FromLinear(const ImageF& linearRgb, double exposureStops) {
  return encodedImage(linearRgb, exposureStops, [](float v) { return srgbCode8(v); });
}

QImage encoded8FromLinear(const ImageF& linearRgb, const CameraResponse& response,
                          double exposureStops) {
  if (response.family() != ResponseFamily::ToeShoulder) return srgb8FromLinear(linearRgb, exposureStops);
  return encodedImage(linearRgb, exposureStops,
                      [&response](float v) { return response.encodeCode8(v); });
}

ImageF linearFromSrgb8(const QImage& image) {
  if (image.isNull()) return {};
  const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
  ImageF out(rgb.width(), rgb.height(), 3);
  for (int y = 0; y < rgb.height(); ++y) {
    const auto* row = reinterpret_cast<const QRgb*>(rgb.constScanLine(y));
    for (int x = 0; x < rgb.width(); ++x) {
      float* d = out.pixel(x, y);
      d[0] = srgbToLinear(float(qRed(row[x])) / 255.f);
      d[1] = srgbToLinear(float(qGreen(row[x])) / 255.f);
      d[2] = srgbToLinear(float(qBlue(row[x])) / 255.f);
    }
  }
  return out;
}

}  // namespace inlay::studio
