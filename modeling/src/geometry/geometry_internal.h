// Small helpers shared by geometry.cpp and stairs.cpp (internal to modeling).
#pragma once

#include "inlay/modeling/core.h"

#include <optional>
#include <string>
#include <vector>

namespace inlay::detail {

// "(x, y)" with one decimal, for messages.
std::string pxText(const Vec2& p);

// Ray / horizontal plane y = h; nullopt when parallel or behind.
std::optional<Vec3> hitHorizontal(const Ray& ray, double h);

// Signed area of a polygon in the (x, -z) plane: positive when counter-clockwise seen from
// above with x to the right and -z (away from the camera) up.
double signedAreaTop(const std::vector<Vec3>& poly);

}  // namespace inlay::detail
