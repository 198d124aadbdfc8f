// Thumbnails of library pieces rendered by Inlay's own path tracer into the bundled example
// room: the piece stands on the floor as near the camera as it fits in the photo, turned to a
// three-quarter view; the square around it is path traced at up to 3x the photo's resolution
// (the photo there is upsampled), composited differentially and averaged down to the thumbnail.
#pragma once

#include "inlay/engine/pipeline.h"

#include <string>
#include <vector>

namespace inlay::library {

struct ThumbnailOptions {
  int sizePx = 160;  // square thumbnail side
  int spp = 64;      // samples per rendered pixel
  uint32_t seed = 1;
  int maxUpscale = 3;  // at most this many rendered pixels per photo pixel (each axis)
};

struct ThumbnailStats {
  double seconds = 0;
  uint64_t nonFiniteSamples = 0;  // dropped by the tracer (a warning when > 0)
  Vec2 basePx{0, 0};              // where the piece stands in the example photo
};

// The example scene (resources/example) prepared once without its objects. Warnings from the
// preparation go to `warnings`.
Expected<PreparedScene> prepareExampleRoom(std::vector<std::string>* warnings);

// The thumbnail (sizePx x sizePx, linear RGB, exposure applied) of `mesh` standing `heightM`
// tall, turned `yawDeg`, in `room`. Errors name the piece.
Expected<ImageF> renderThumbnail(const PreparedScene& room, const TriangleMesh& mesh, double heightM,
                                 double yawDeg, const ThumbnailOptions& options,
                                 ThumbnailStats* stats = nullptr);

// The thumbnails in a grid of `columns`, each with its title under it (DejaVu Sans when the font
// is installed; without it the titles are left out and `warnings` says so). Linear RGB.
ImageF contactSheet(const std::vector<ImageF>& thumbnails, const std::vector<std::string>& titles,
                    int columns, std::vector<std::string>* warnings);

}  // namespace inlay::library
