// Small helpers shared by geometry.cpp and stairs.cpp (internal to modeling). pxText and
// hitHorizontal come from the camera room's room_box.h.
#pragma once

#include "inlay/modeling/core.h"
#include "inlay/modeling/room_box.h"

#include <vector>

namespace inlay::detail {

// Signed area of a polygon in the (x, -z) plane: positive when counter-clockwise seen from
// above with x to the right and -z (away from the camera) up.
double signedAreaTop(const std::vector<Vec3>& poly);

}  // namespace inlay::detail
