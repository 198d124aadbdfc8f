// The box layout: the back wall's four corners from rays through the vanishing points, scored
// by edge support and a line-based orientation map (internal to modeling; see
// estimate_camera.h). Hedau et al. 2009 (rays through vanishing points), Lee et al. 2009
// (orientation from line sweeps, reduced here to which face each line sample lies on).
#pragma once

#include "inlay/modeling/camera.h"
#include "inlay/modeling/line_segment.h"
#include "layout_rules.h"

#include <opencv2/core.hpp>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace inlay::detail {

// The photo's brightness gradient at the layout's scale (long side at most kLayoutSidePx): where
// no segment was found, a faint crease between two walls still shows as contrast across the
// hypothesised edge.
constexpr double kLayoutSidePx = 400;
struct PhotoEdges {
  cv::Mat gx, gy;    // CV_32F, d(sRGB grey in [0, 1]) per layout pixel
  double noise = 0;  // median gradient magnitude (texture and noise level)
  cv::Mat clipped;   // CV_8U, non-zero within 2 pixels of a (nearly) saturated pixel; the
                     // gradient is 0 there
};

// From the working grey image (sRGB-encoded, [0, 255], already lightly blurred) of a photo of
// photoW x photoH pixels.
std::shared_ptr<const PhotoEdges> photoEdgesOf(const cv::Mat& grey8, int photoW, int photoH);

struct LayoutInput {
  const Camera* camera = nullptr;                      // photo pixels; its heightM shapes the default
  const std::vector<LineSegment>* segments = nullptr;  // photo pixels, families 0 x, 1 y, 2 z
  std::array<std::optional<Vec2>, 4> fixedCornersPx;   // TL, TR, BR, BL kept (their lines fixed)
  std::optional<std::array<Vec2, 4>> startCornersPx;   // search locally from here (a correction)
  const PhotoEdges* edges = nullptr;                   // none: segments only
  const CancelToken* cancel = nullptr;
  // Refuse implausible boxes (BoxRules) when no corner is fixed and no start given.
  bool refuseImplausible = true;
  BoxRules rules;
};

struct LayoutResult {
  bool ok = false;  // false: no box (the camera looks away from every wall); default corners
  std::array<Vec2, 4> cornersPx;  // TL, TR, BR, BL, photo pixels
  double score01 = 0;             // share of the box's visible edges and faces the lines support
  std::string problem;            // why not ok
  BoxDoubts doubts;               // why the automatic box is in doubt (refused, its floor crease unseen)
  // The one sentence for CameraEstimate::warnings when the box is doubtful (boxAdvice); empty
  // otherwise.
  std::string advice;
};

LayoutResult estimateLayout(const LayoutInput& input);

}  // namespace inlay::detail
