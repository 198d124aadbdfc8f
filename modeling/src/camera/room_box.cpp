// The box room from the camera (room_box.h): the back wall's corners to a box and back.
#include "inlay/modeling/room_box.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace inlay {

namespace detail {

std::string pxText(const Vec2& p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%.1f, %.1f)", p.x(), p.y());
  return buf;
}

std::optional<Vec3> hitHorizontal(const Ray& ray, double h) {
  if (std::abs(ray.direction.y()) < 1e-12) return std::nullopt;
  const double t = (h - ray.origin.y()) / ray.direction.y();
  if (!(t > 1e-9) || !std::isfinite(t)) return std::nullopt;
  return ray.at(t);
}

}  // namespace detail

using detail::hitHorizontal;
using detail::pxText;

Expected<RoomBox> roomFromBackWall(const Camera& camera, const std::array<Vec2, 4>& c,
                                   const RoomOptions& options) {
  const std::string key = "layout.back_wall_px";
  const char* names[4] = {"top-left", "top-right", "bottom-right", "bottom-left"};
  for (int i = 0; i < 4; ++i)
    if (!std::isfinite(c[i].x()) || !std::isfinite(c[i].y()))
      return Error{"", key + "[" + std::to_string(i) + "]", "is not a finite number"};
  // Floor corners: the bottom edge's rays meet the floor.
  const auto bl = hitHorizontal(camera.rayThroughPixel(c[3]), 0.0);
  const auto br = hitHorizontal(camera.rayThroughPixel(c[2]), 0.0);
  if (!bl)
    return Error{"", key + "[3]",
                 std::string("the ") + names[3] + " corner " + pxText(c[3]) +
                     " is at or above the horizon, so it cannot be on the floor"};
  if (!br)
    return Error{"", key + "[2]",
                 std::string("the ") + names[2] + " corner " + pxText(c[2]) +
                     " is at or above the horizon, so it cannot be on the floor"};
  RoomBox box;
  box.zBackM = 0.5 * (bl->z() + br->z());
  box.xLeftM = bl->x();
  box.xRightM = br->x();
  if (!(box.zBackM < -0.05)) return Error{"", key, "the back wall would stand behind the camera"};
  if (!(box.xRightM - box.xLeftM > 0.05))
    return Error{"", key,
                 "the corners give a back wall of no width (are they in the order top-left, "
                 "top-right, bottom-right, bottom-left?)"};
  // Ceiling: the top corners' rays meet the vertical corner lines of the back wall.
  double sumH = 0;
  int n = 0;
  for (int i : {0, 1}) {
    const Ray r = camera.rayThroughPixel(c[i]);
    if (std::abs(r.direction.z()) < 1e-12) continue;
    const double t = (box.zBackM - r.origin.z()) / r.direction.z();
    if (!(t > 0)) continue;
    sumH += r.at(t).y();
    ++n;
  }
  if (n == 0) return Error{"", key + "[0]", "the top corners do not lie on the back wall"};
  box.ceilingM = sumH / n;
  if (!(box.ceilingM > camera.heightM + 0.02))
    return Error{"", key,
                 "the top edge gives a ceiling at " + std::to_string(box.ceilingM) +
                     " m, not above the camera (" + std::to_string(camera.heightM) +
                     " m): is the top edge below the horizon, or camera.height_m too large?"};
  // The camera stands inside the room.
  box.xLeftM = std::min(box.xLeftM, -0.1);
  box.xRightM = std::max(box.xRightM, 0.1);
  box.zRearM = std::max(options.rearMarginM, 0.05);
  return box;
}

double rearWallDistanceM(std::optional<double> givenM, double defaultM, const std::vector<Vec3>& inside,
                         double clearanceM) {
  constexpr double kMinM = 0.05;
  if (givenM && std::isfinite(*givenM)) return std::max(*givenM, kMinM);
  double rear = std::isfinite(defaultM) ? defaultM : 0.5;
  for (const Vec3& p : inside)
    if (std::isfinite(p.z()) && p.z() > 0) rear = std::max(rear, p.z() + std::max(clearanceM, 0.0));
  return std::max(rear, kMinM);
}

std::array<Vec2, 4> backWallCornersPx(const Camera& camera, const RoomBox& box) {
  const Vec3 w[4] = {{box.xLeftM, box.ceilingM, box.zBackM},
                     {box.xRightM, box.ceilingM, box.zBackM},
                     {box.xRightM, 0.0, box.zBackM},
                     {box.xLeftM, 0.0, box.zBackM}};
  std::array<Vec2, 4> out;
  for (int i = 0; i < 4; ++i) {
    const auto p = camera.project(w[i]);
    out[i] = p ? *p : Vec2(std::nan(""), std::nan(""));
  }
  return out;
}

double horizonRowPx(const Camera& camera, double x) {
  const Vec3 line = camera.vanishingPointOf(Vec3::UnitX()).cross(camera.vanishingPointOf(Vec3::UnitZ()));
  if (!line.allFinite() || std::abs(line.y()) < 1e-12) return std::nan("");
  return -(line.x() * x + line.z()) / line.y();
}

}  // namespace inlay
