// Conversions between the engine's float images and QImage, for display (and export of what is shown).
// Thread-safe (pure functions); the render thread calls them on every frame.
#pragma once

#include "inlay/modeling/image.h"
#include "inlay/modeling/response.h"

#include <QImage>

namespace inlay::studio {

// linearRgb: W x H x C (C = 1 or >= 3), linear photo units. Returns a W x H QImage
// (Format_RGB32) holding the sRGB encoding of linearRgb * 2^exposureStops, clamped to [0,1].
QImage srgb8FromLinear(const ImageF& linearRgb, double exposureStops = 0.0);
// The same encoded with the photo's camera response (so the photo shows its own codes);
// sRGB for a linear response (an EXR/HDR photo is shown as sRGB).
QImage encoded8FromLinear(const ImageF& linearRgb, const CameraResponse& response,
                          double exposureStops = 0.0);
// The inverse of srgb8FromLinear at exposure 0: W x H x 3 linear values whose sRGB codes are the
// image's own (so image_io writes the shown image back code for code).
ImageF linearFromSrgb8(const QImage& image);

}  // namespace inlay::studio
