// When an automatic box is implausible for the camera that took the photo (internal to
// modeling; used by layout.cpp's search, free of OpenCV so tests can include it).
#pragma once

#include "inlay/modeling/camera.h"

#include <array>
#include <limits>
#include <string>

namespace inlay::detail {

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
Implausible implausibility(const Camera& camera, const std::array<Vec2, 4>& cornersPx, bool showsCeiling,
                           const BoxRules& rules);

}  // namespace inlay::detail
