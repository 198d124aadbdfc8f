// Internals of estimate_camera.cpp that the tests check directly (no Ceres types here).
#pragma once

#include "inlay/modeling/core.h"

namespace inlay::detail {

// Largest relative difference between the automatic (Ceres Jet) and the central-difference
// derivatives of the segment residual (endpoint distance to the line through the midpoint and
// the vanishing point, in pixels) with respect to the rotation (angle-axis, 3) and the log
// focal length (1), over a set of segments and vanishing points that includes points at
// infinity and a segment aimed straight at its point. A correct functor gives about 1e-6.
double segmentResidualGradientError();

}  // namespace inlay::detail
