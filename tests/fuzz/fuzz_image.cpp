// Fuzz target: loadImage (OpenImageIO behind our checks: PNG structure, header limits,
// orientation, channel handling). The file is named by its signature, as a user's would be.
#include "fuzz_support.h"
#include "inlay/modeling/image_io.h"

#include <cmath>
#include <cstring>

namespace {

const char* extensionFor(const uint8_t* d, size_t n) {
  auto starts = [&](const char* magic, size_t len) {
    return n >= len && std::memcmp(d, magic, len) == 0;
  };
  if (starts("\xFF\xD8", 2)) return ".jpg";
  // The TIFF magics hold a NUL; `len` says how many bytes to compare.
  // NOLINTNEXTLINE(bugprone-string-literal-with-embedded-nul)
  if (starts("II*\0", 4) || starts("MM\0*", 4)) return ".tif";
  if (starts("\x76\x2F\x31\x01", 4)) return ".exr";
  if (starts("#?", 2)) return ".hdr";
  return ".png";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path =
      inlay::fuzz::writeInput(std::string("input") + extensionFor(data, size), data, size);
  // Small images only: the seeds are at most 8 x 16, and a header that claims more than 64 x 64
  // pixels is refused by our header check before anything is decoded. With the product's limits
  // (or 4 megapixels) most mutated headers made the decoder allocate and clear tens of MB per
  // run, and the target managed about 30 runs/s; the limit check itself is still exercised.
  inlay::ImageLimits limits;
  limits.maxPixels = 64 * 64;
  limits.maxDimension = 1024;
  auto loaded = inlay::loadImage(path, limits);
  if (loaded) {  // success: a finite, non-negative, 3-channel image
    const inlay::ImageF& img = loaded->linearRgb;
    if (img.channels != 3 || img.empty()) __builtin_trap();
    for (float v : img.data)
      if (!std::isfinite(v) || v < 0) __builtin_trap();
  }
  return 0;
}
