// The box room from the camera: the floor is y = 0, the back wall's bottom edge fixes its depth
// and the side walls, its top edge the ceiling. The wall behind the camera is never seen; it is
// placed `rearMarginM` behind the camera so the box is closed (light and bounces must stay
// inside). Part of the camera room (src/camera/room_box.cpp): the camera estimate tests its
// candidate boxes with roomFromBackWall, and geometry.h builds the room's surfaces on it.
#pragma once

#include "inlay/modeling/camera.h"
#include "inlay/modeling/core.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace inlay {

// Axis-aligned box of the room, world metres.
struct RoomBox {
  double xLeftM = -2, xRightM = 2;
  double zBackM = -4, zRearM = 0.5;
  double ceilingM = 2.6;
};

struct RoomOptions {
  double rearMarginM = 0.5;  // distance of the unseen rear wall behind the camera
};

// Least-squares box from the four back-wall corners (TL, TR, BR, BL). Errors name
// "layout.back_wall_px" and say why (a floor corner at or above the horizon, a ceiling below
// the floor, a wall behind the camera, a degenerate quad).
Expected<RoomBox> roomFromBackWall(const Camera& camera, const std::array<Vec2, 4>& cornersPx,
                                   const RoomOptions& options = {});

// How far behind the camera the rear wall stands: `givenM` when the user gave it; otherwise
// `defaultM`, pushed back so that every point of `inside` (the corners of lights placed in 3D)
// lies at least `clearanceM` in front of it. A light at or in front of the camera changes
// nothing. Never less than 0.05 m (a camera against its rear wall still has a closed box);
// non-finite points are ignored.
double rearWallDistanceM(std::optional<double> givenM, double defaultM, const std::vector<Vec3>& inside,
                         double clearanceM = 0.05);

// Where the back wall's corners appear in the photo (TL, TR, BR, BL); may lie outside it.
std::array<Vec2, 4> backWallCornersPx(const Camera& camera, const RoomBox& box);

// The horizon's row (photo pixels) at column x: where horizontal planes vanish, the image of
// the camera's own height. NaN when the camera looks straight up or down.
double horizonRowPx(const Camera& camera, double x);

namespace detail {

// "(x, y)" with one decimal, for messages (also the geometry room's).
std::string pxText(const Vec2& p);

// Ray / horizontal plane y = h; nullopt when parallel or behind (also the geometry room's).
std::optional<Vec3> hitHorizontal(const Ray& ray, double h);

}  // namespace detail

}  // namespace inlay
