// One straight line segment of the photo, as the line detector finds it and the camera estimate
// (estimate_camera.h) assigns it to a vanishing point. On its own so that the estimate's parts
// (the line detector, the box layout) need not include the estimate's header: photo pixels, as
// in camera.h.
#pragma once

#include "inlay/modeling/core.h"

namespace inlay {

// One straight line segment of the photo. `family`: the world axis (0 x, 1 y, 2 z) whose
// vanishing point it supports, -1 when it supports none. `residualPx`: the distance of its
// endpoints to the line through its midpoint and that vanishing point (0 when family < 0).
struct LineSegment {
  Vec2 aPx{0, 0};
  Vec2 bPx{0, 0};
  int family = -1;
  double residualPx = 0;
  bool userGiven = false;  // drawn by the user (a correction), not detected
  double lengthPx() const { return (bPx - aPx).norm(); }
};

}  // namespace inlay
