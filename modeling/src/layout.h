// The box layout: the back wall's four corners from rays through the vanishing points, scored
// by edge support and a line-based orientation map (internal to modeling; see
// estimate_camera.h). Hedau et al. 2009 (rays through vanishing points), Lee et al. 2009
// (orientation from line sweeps, reduced here to which face each line sample lies on).
#pragma once

#include "inlay/modeling/camera.h"
#include "inlay/modeling/estimate_camera.h"

#include <opencv2/core.hpp>

#include <array>
#include <limits>
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
  cv::Mat gx, gy;      // CV_32F, d(sRGB grey in [0, 1]) per layout pixel
  double noise = 0;    // median gradient magnitude (texture and noise level)
  cv::Mat clipped;     // CV_8U, non-zero within 2 pixels of a (nearly) saturated pixel; the
                       // gradient is 0 there
};

// From the working grey image (sRGB-encoded, [0, 255], already lightly blurred) of a photo of
// photoW x photoH pixels.
std::shared_ptr<const PhotoEdges> photoEdgesOf(const cv::Mat& grey8, int photoW, int photoH);

// A box's size in metres as the room builder measures it (roomFromBackWall): the bottom corners'
// rays meet the floor (the camera stands heightM above it), the back wall's plane is their mean
// depth, the top corners' rays meet that plane at the ceiling. creaseRad: the angle below the
// horizon at which the camera sees the back wall's foot straight ahead (atan(heightM / depth)).
struct BoxSize {
  bool ok = false;  // false: a bottom corner at or above the horizon, or the wall behind
  double depthM = 0, widthM = 0, creaseRad = 0;
  double ceilingM = std::numeric_limits<double>::quiet_NaN();  // NaN: the top corners miss it
};
BoxSize boxSizeOf(const Camera& camera, const std::array<Vec2, 4>& cornersPx);

// When an automatic box is implausible for the camera (checked on the search's boxes; placed
// corners are the user's and never refused). Geometry, in units of the photo and of the
// camera's height above the floor:
//  - depth: the back wall's distance is h / tan(a), a the crease's angle below the horizon. The
//    horizon is known to horizonSigmaRad (the vertical vanishing point's 1-sigma) and a crease to
//    creaseSigmaPx; a box whose depth the photo cannot bound within depthFactor at 2 sigma
//    (tan(a + 2s) / tan(a - 2s) > depthFactor) is beyond what the photo can show at that height.
//  - ceiling: a ceiling crease the photo shows more than maxCeilingOverEye camera heights up.
//    The ceiling is h (1 + tan(above) / tan(below)) for the top and bottom edges' angles from the
//    horizon: a high ceiling over a floor crease means that floor crease lies near the horizon,
//    the top of furniture or a sill taken for the floor, which is what makes a box tens of
//    metres deep. The search then holds the top edge and looks for the floor crease lower down.
//  - width: a room narrower than minWidthOverEye camera heights cannot hold the photographer.
struct BoxRules {
  double horizonSigmaRad = 0;
  double creaseSigmaPx = 1;
  double depthFactor = 2;
  double maxCeilingOverEye = 3;
  double minWidthOverEye = 0.5;
};
// Which rule refuses a box (none: plausible) and why, as a sentence fragment with the box's
// metres. showsCeiling: the photo shows the top edge as a ceiling crease (else the ceiling rule
// does not apply: the top of a facade against the sky is no ceiling).
struct Implausible {
  enum Rule { kNone, kDepth, kWidth, kCeiling } rule = kNone;
  std::string why;
  explicit operator bool() const { return rule != kNone; }
};
Implausible implausibility(const Camera& camera, const std::array<Vec2, 4>& cornersPx,
                           bool showsCeiling, const BoxRules& rules);

struct LayoutInput {
  const Camera* camera = nullptr;                    // photo pixels; its heightM shapes the default
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
  bool ok = false;          // false: no box (the camera looks away from every wall); default corners
  std::array<Vec2, 4> cornersPx;  // TL, TR, BR, BL, photo pixels
  double score01 = 0;       // share of the box's visible edges and faces the lines support
  std::string problem;      // why not ok
  // When the best-supported box was refused as implausible: why, and what replaced it (a
  // sentence for CameraEstimate::warnings); empty otherwise.
  std::string refused;
};

LayoutResult estimateLayout(const LayoutInput& input);

}  // namespace inlay::detail
