// Line segments of a photo at a working size (internal to modeling; see estimate_camera.h).
#pragma once

#include "inlay/modeling/core.h"
#include "inlay/modeling/image.h"
#include "inlay/modeling/line_segment.h"

#include <memory>
#include <vector>

namespace inlay::detail {

struct PhotoEdges;

struct DetectedLines {
  std::vector<LineSegment> segments;  // photo pixels, longest first, family -1
  double workingScale = 1;            // working image size / photo size
  int workingWidth = 0, workingHeight = 0;
  std::shared_ptr<const PhotoEdges> edges;  // for the layout; null when too small
};

using inlay::srgbCode8;  // image.h

// Grey (luminance, sRGB-encoded) at a long side of at most maxWorkingSidePx, area-averaged
// without ever holding a full-size grey copy; then OpenCV's FastLineDetector, each segment
// moved onto the gradient peaks across it (sub-pixel). At most maxSegments segments (the
// longest). Returns nothing when `cancel` stops it.
DetectedLines detectLineSegments(const ImageF& linearRgb, int maxWorkingSidePx, int maxSegments,
                                 const CancelToken* cancel);

}  // namespace inlay::detail
