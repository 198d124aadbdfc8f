// Image input and output: the one unit that talks to OpenImageIO.
//
// Reading applies the EXIF orientation, converts to linear RGB float (sRGB-encoded 8/16-bit
// files are decoded; EXR/HDR are taken as linear), drops alpha, expands grey to RGB, and
// refuses images beyond ImageLimits with a message naming the file. Writing picks the format by
// extension (.png/.jpg/.jpeg/.tif/.tiff as 8-bit sRGB, .exr as linear half or float, .hdr
// linear), writes to a temporary file in the same folder and renames it over the target, so an
// interrupted write never leaves a half-written file where the user's file was.
// Thread-safe (no shared state beyond OpenImageIO's own).
#pragma once

#include "inlay/modeling/core.h"
#include "inlay/modeling/image.h"

#include <optional>
#include <string>
#include <vector>

namespace inlay {

class CameraResponse;

struct ImageLimits {
  long long maxPixels = 300'000'000LL;  // decompression-bomb guard (about 17k x 17k)
  int maxDimension = 65'536;            // either side
  int minDimension = 1;                 // either side
  // What a photo to insert objects into must satisfy: a room needs more than a few pixels.
  static ImageLimits photo() { return {.minDimension = 32}; }
};

// What the file says about the camera (a prior for the focal length, never a truth).
struct ExifInfo {
  std::optional<double> focalLengthMm;          // Exif:FocalLength
  std::optional<double> focalLength35mm;        // Exif:FocalLengthIn35mmFilm
  std::optional<double> focalPlaneXResolution;  // Exif:FocalPlaneXResolution, per unit below
  std::optional<int> focalPlaneResolutionUnit;  // 2 inch, 3 cm, 4 mm (EXIF)
  int orientation = 1;                          // as stored, before we applied it
  std::string make, model;
  // Focal length in pixels of the oriented image, from the 35 mm equivalent (36 mm across the
  // longer side) or from the focal plane resolution; nullopt when the file does not say.
  std::optional<double> focalPx(int width, int height) const;
};

struct LoadedImage {
  ImageF linearRgb;            // W x H x 3, linear, EXIF orientation applied
  bool wasSrgbEncoded = true;  // false for EXR/HDR (already linear)
  int sourceBitsPerChannel = 8;
  ExifInfo exif;
};

Expected<LoadedImage> loadImage(const std::string& path, const ImageLimits& limits = {});

struct SaveOptions {
  bool exrHalf = true;  // .exr: half (true) or float (false)
  int jpegQuality = 95;
  // PNG/JPEG/TIFF: the camera response that encodes the colour channels (modeling/response.h),
  // so a photo's pixels decoded with it are written back as the same codes; null: sRGB.
  const CameraResponse* response = nullptr;
};
// `linear`: linear values (C = 1, 3 or 4); encoded to 8-bit for PNG/JPEG/TIFF by
// options.response (sRGB when null), clamped.
Status saveImage(const std::string& path, const ImageF& linear, const SaveOptions& options = {});

// A multi-layer EXR: one part per named layer, each linear float or half, written atomically.
struct NamedLayer {
  std::string name;  // e.g. "composite", "with_objects", "without_objects", "mask"
  const ImageF* image = nullptr;
};
Status saveLayersExr(const std::string& path, const std::vector<NamedLayer>& layers, bool half = true);

// Write `bytes` to `path` through a temporary file in the same folder and a rename (fsync
// before it). Temporaries left beside `path` by processes that died mid-save are removed.
Status writeFileAtomically(const std::string& path, const std::string& bytes);

// Resample (area average when shrinking, bilinear when enlarging).
ImageF resizeImage(const ImageF& src, int width, int height);

}  // namespace inlay
