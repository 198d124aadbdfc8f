// Debevec's differential composite and exposure (see composite.h).
#include "inlay/render/composite.h"

#include <algorithm>
#include <cmath>

namespace inlay {

namespace {

// Whether the photo clips pixel (x, y): the unclipped radiance exceeds it in some channel.
bool clippedAt(const ImageF& unclipped, const float* photo, int x, int y) {
  for (int c = 0; c < 3; ++c) {
    const float u = unclipped.at(x, y, c);
    if (std::isfinite(u) && u > photo[c]) return true;
  }
  return false;
}

}  // namespace

ImageF differentialComposite(const ImageF& photoLinear, const ImageF& withObjects,
                             const ImageF& withoutObjects, const ImageF& mask, const ImageF* unclipped) {
  const int w = photoLinear.width, h = photoLinear.height, ch = photoLinear.channels;
  INLAY_CHECK(withObjects.width == w && withObjects.height == h && withObjects.channels == 3);
  INLAY_CHECK(withoutObjects.width == w && withoutObjects.height == h && withoutObjects.channels == 3);
  INLAY_CHECK(mask.empty() || (mask.width == w && mask.height == h && mask.channels >= 1));
  if (unclipped && (unclipped->width != w || unclipped->height != h || unclipped->channels < 3))
    unclipped = nullptr;  // not this photo's: the photo alone
  ImageF out = photoLinear;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float m = mask.empty() ? 0.f : mask.at(x, y, 0);
      const float* io = withObjects.pixel(x, y);
      const float* in = withoutObjects.pixel(x, y);
      float* o = out.pixel(x, y);
      const bool clipped = unclipped && clippedAt(*unclipped, o, x, y);
      for (int c = 0; c < std::min(ch, 3); ++c) {  // further channels (alpha) kept
        const int rc = c;
        const float photo = o[c];
        if (m == 0.f && io[rc] == in[rc]) {
          // Untouched: the photo bit for bit (only a non-finite photo value is replaced).
          o[c] = std::isfinite(photo) ? photo : 0.f;
          continue;
        }
        const double mm = std::isfinite(m) ? std::clamp(double(m), 0.0, 1.0) : 0.0;
        // A pixel the photo clips: its value is at least the room's without the objects (the
        // render's, in every channel), so the objects' change is taken over that.
        const double base = clipped && std::isfinite(in[rc]) ? std::max(double(photo), double(in[rc]))
                                                             : double(photo);
        const double v = mm * io[rc] + (1.0 - mm) * (base + double(io[rc]) - double(in[rc]));
        o[c] = std::isfinite(v) && v > 0 ? float(v) : 0.f;
      }
    }
  return out;
}

void applyExposure(ImageF& linear, double stops) {
  const float scale = float(std::exp2(stops));
  if (scale == 1.f) return;
  for (float& v : linear.data) v *= scale;
}

}  // namespace inlay
