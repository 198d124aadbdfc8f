// Stairs: a straight flight from step count, rise and run, or from a side profile drawn on a
// wall. Both are a 2D profile swept straight across the flight (solid_mesh.h).
#include "inlay/modeling/geometry.h"

#include "extrude_cgal.h"
#include "geometry_internal.h"
#include "solid_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace inlay {

namespace {

using detail::hitHorizontal;
using detail::pxText;

// The stairs' Extrusion: the solid, its height and its footprint (floor corners, any order
// around it) lifted to the top as the outline.
Extrusion stairsExtrusion(detail::PrismMeshes&& prism, std::vector<Vec3> footprint, double heightM) {
  Extrusion ex;
  ex.heightM = heightM;
  for (Vec3& p : footprint) p.y() = heightM;
  if (detail::signedAreaTop(footprint) < 0) std::reverse(footprint.begin(), footprint.end());
  ex.topOutlineWorld = std::move(footprint);
  ex.upWorld = std::move(prism.upWorld);
  ex.otherWorld = std::move(prism.otherWorld);
  ex.solid = std::move(prism.solid);
  return ex;
}

// A wall of the box as a 2D frame: a point is origin + a * u + y * (0, 1, 0); `inward` is the
// wall's normal into the room; a runs over [aMin, aMax] on the wall.
struct WallFrame {
  SurfaceKind kind;
  Vec3 origin, u, inward;
  double aMin, aMax;
  double oppositeM;  // distance to the opposite wall; 0 when it is behind the camera
};

WallFrame wallFrame(SurfaceKind kind, const RoomBox& b) {
  const double span = b.xRightM - b.xLeftM;
  switch (kind) {
    case SurfaceKind::WallLeft:
      return {kind, Vec3(b.xLeftM, 0, 0), Vec3(0, 0, -1), Vec3(1, 0, 0), -b.zRearM, -b.zBackM, span};
    case SurfaceKind::WallRight:
      return {kind, Vec3(b.xRightM, 0, 0), Vec3(0, 0, -1), Vec3(-1, 0, 0), -b.zRearM, -b.zBackM, span};
    default:
      INLAY_CHECK(kind == SurfaceKind::WallBack);
      return {kind, Vec3(0, 0, b.zBackM), Vec3(1, 0, 0), Vec3(0, 0, 1), b.xLeftM, b.xRightM, 0.0};
  }
}

// The face of the box a ray from inside it leaves through.
SurfaceKind exitFace(const Ray& r, const RoomBox& b) {
  double best = std::numeric_limits<double>::infinity();
  SurfaceKind face = SurfaceKind::Floor;
  auto consider = [&](double t, SurfaceKind k) {
    if (t > 0 && t < best) best = t, face = k;
  };
  const Vec3 &o = r.origin, &d = r.direction;
  if (d.x() < 0) consider((b.xLeftM - o.x()) / d.x(), SurfaceKind::WallLeft);
  if (d.x() > 0) consider((b.xRightM - o.x()) / d.x(), SurfaceKind::WallRight);
  if (d.z() < 0) consider((b.zBackM - o.z()) / d.z(), SurfaceKind::WallBack);
  if (d.z() > 0) consider((b.zRearM - o.z()) / d.z(), SurfaceKind::WallRear);
  if (d.y() < 0) consider(-o.y() / d.y(), SurfaceKind::Floor);
  if (d.y() > 0) consider((b.ceilingM - o.y()) / d.y(), SurfaceKind::Ceiling);
  return face;
}

// The wall most of the points' rays leave the room through (left, right or back), if any.
std::optional<SurfaceKind> wallUnder(const Camera& camera, const RoomBox& box,
                                     const std::vector<Vec2>& px) {
  int counts[3] = {0, 0, 0};
  const SurfaceKind walls[3] = {SurfaceKind::WallLeft, SurfaceKind::WallRight, SurfaceKind::WallBack};
  for (const Vec2& p : px) {
    const SurfaceKind f = exitFace(camera.rayThroughPixel(p), box);
    for (int w = 0; w < 3; ++w) counts[w] += f == walls[w];
  }
  const int best = int(std::max_element(counts, counts + 3) - counts);
  if (counts[best] == 0) return std::nullopt;
  return walls[best];
}

// Union-find over point indices (the snapping groups).
struct Groups {
  std::vector<size_t> parent;
  explicit Groups(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  size_t find(size_t i) { return parent[i] == i ? i : parent[i] = find(parent[i]); }
  void join(size_t i, size_t j) { parent[find(i)] = find(j); }
};

// Makes edges within `snapDeg` of level exactly level and those within it of vertical exactly
// vertical: the points joined by such edges share their mean y (resp. a).
void snapRectilinear(std::vector<Vec2>& q, double snapDeg) {
  const size_t n = q.size();
  const double tanSnap = std::tan(snapDeg * M_PI / 180.0);
  Groups level(n), plumb(n);
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    const Vec2 d = q[j] - q[i];
    if (std::abs(d.y()) <= tanSnap * std::abs(d.x())) level.join(i, j);
    else if (std::abs(d.x()) <= tanSnap * std::abs(d.y())) plumb.join(i, j);
  }
  auto average = [&](Groups& g, int axis) {
    std::vector<double> sum(n, 0.0);
    std::vector<int> count(n, 0);
    for (size_t i = 0; i < n; ++i) sum[g.find(i)] += q[i][axis], ++count[g.find(i)];
    for (size_t i = 0; i < n; ++i) q[i][axis] = sum[g.find(i)] / count[g.find(i)];
  };
  average(level, 1);
  average(plumb, 0);
}

const char* wallName(SurfaceKind k) {
  return k == SurfaceKind::WallLeft ? "left" : k == SurfaceKind::WallRight ? "right" : "back";
}

// The profile's pixels lifted onto the wall, in its (a, y) frame; errors name each point.
Expected<std::vector<Vec2>> liftOntoWall(const Camera& camera, const RoomBox& box, const WallFrame& w,
                                         const std::vector<Vec2>& px, const std::string& key) {
  const double tolA = 0.05 * (w.aMax - w.aMin), tolY = 0.05 * box.ceilingM;
  std::vector<Vec2> q;
  for (size_t i = 0; i < px.size(); ++i) {
    const std::string ki = key + "[" + std::to_string(i) + "]";
    if (!px[i].allFinite()) return Error{"", ki, "is not a finite number"};
    const Ray r = camera.rayThroughPixel(px[i]);
    const double toward = r.direction.dot(w.inward);
    const double t = toward < 0 ? (w.origin - r.origin).dot(w.inward) / toward : -1.0;
    if (!(t > 0) || !std::isfinite(t))
      return Error{"", ki,
                   "the point " + pxText(px[i]) + " is not on the " + wallName(w.kind) +
                       " wall: its ray never meets it"};
    const Vec3 p = r.at(t);
    const double a = (p - w.origin).dot(w.u);
    if (a < w.aMin - tolA || a > w.aMax + tolA || p.y() > box.ceilingM + tolY)
      return Error{"", ki,
                   "the point " + pxText(px[i]) + " lands off the " + wallName(w.kind) +
                       " wall (beyond its corner or above the ceiling)"};
    q.emplace_back(a, p.y());
  }
  return q;
}

// Puts the profile on the floor: the lowest point must be below the horizon and within
// `floorSnapM` of the floor; points that close to it are set on it.
Status restOnFloor(std::vector<Vec2>& q, const Camera& camera, const std::vector<Vec2>& px,
                   double floorSnapM, const std::string& key) {
  const size_t low = size_t(
      std::min_element(q.begin(), q.end(), [](const Vec2& a, const Vec2& b) { return a.y() < b.y(); }) -
      q.begin());
  const double yLow = q[low].y();
  const std::string ki = key + "[" + std::to_string(low) + "]";
  if (yLow >= camera.heightM)
    return Error{"", ki,
                 "the profile's lowest point " + pxText(px[low]) +
                     " is at or above the horizon, "
                     "so the stairs cannot stand on the floor"};
  if (yLow < -floorSnapM)
    return Error{"", ki,
                 "the point " + pxText(px[low]) + " lies " + std::to_string(-yLow) +
                     " m below the wall's floor line"};
  if (yLow > floorSnapM)
    return Error{"", key,
                 "the profile does not reach the floor (its lowest point is " + std::to_string(yLow) +
                     " m up): draw it down to the wall's floor line"};
  for (Vec2& p : q)
    if (p.y() <= floorSnapM) p.y() = 0.0;
  return Status{};
}

}  // namespace

Expected<Extrusion> stairsFromSpec(const Camera& camera, const StairsSpec& st, const std::string& key) {
  if (!st.basePx.allFinite()) return Error{"", key + ".base_px", "is not a finite number"};
  if (st.steps < 1 || st.steps > 1000)
    return Error{"", key + ".steps", "must be a whole number from 1 to 1000"};
  auto positive = [](double v) { return v > 0 && std::isfinite(v); };
  if (!positive(st.riseM)) return Error{"", key + ".rise_m", "must be a positive number"};
  if (!positive(st.runM)) return Error{"", key + ".run_m", "must be a positive number"};
  if (!positive(st.widthM)) return Error{"", key + ".width_m", "must be a positive number"};
  const Vec3 c = st.climbWorld;
  const bool axis = std::abs(c.y()) < 1e-9 && std::abs(std::abs(c.x()) + std::abs(c.z()) - 1) < 1e-9 &&
                    (std::abs(c.x()) < 1e-9 || std::abs(c.z()) < 1e-9);
  if (!axis) return Error{"", key + ".climb_axis", "must be one of +x, -x, +z, -z"};
  const auto base = hitHorizontal(camera.rayThroughPixel(st.basePx), 0.0);
  if (!base)
    return Error{"", key + ".base_px",
                 "the point " + pxText(st.basePx) +
                     " is at or above the horizon, so it cannot be "
                     "on the floor"};
  // Side profile in (along the climb, up), counter-clockwise: the floor line, the back, then
  // down the staircase edge: nosing of step k at ((k) run, (k + 1) rise).
  std::vector<Vec2> profile = {{0, 0}, {st.steps * st.runM, 0}};
  for (int k = st.steps - 1; k >= 0; --k) {
    profile.emplace_back((k + 1) * st.runM, (k + 1) * st.riseM);
    profile.emplace_back(k * st.runM, (k + 1) * st.riseM);
  }
  auto ccw = detail::counterClockwiseSimplePolygon(profile, key);
  if (!ccw) return ccw.error();
  const Vec3 across = Vec3(0, 1, 0).cross(c).normalized();
  const Vec3 origin = *base - 0.5 * st.widthM * across;
  auto prism = detail::buildPrism(*ccw, origin, c, Vec3(0, 1, 0), st.widthM * across, key);
  if (!prism) return prism.error();
  const Vec3 far = *base + st.steps * st.runM * c;
  const Vec3 hw = 0.5 * st.widthM * across;
  return stairsExtrusion(std::move(*prism), {*base - hw, *base + hw, far + hw, far - hw},
                         st.steps * st.riseM);
}

Expected<Extrusion> stairsFromProfile(const Camera& camera, const RoomBox& box,
                                      const StairsProfileSpec& spec, const std::string& key) {
  const std::string kp = key + ".profile_px";
  if (spec.profilePx.size() < 3)
    return Error{"", kp,
                 "a stair profile needs at least 3 points, this one has " +
                     std::to_string(spec.profilePx.size())};
  if (!(spec.widthM >= 0) || !std::isfinite(spec.widthM))
    return Error{"", key + ".width_m", "must be a positive number (or missing)"};
  std::optional<SurfaceKind> wall = spec.wall;
  if (wall && *wall != SurfaceKind::WallLeft && *wall != SurfaceKind::WallRight &&
      *wall != SurfaceKind::WallBack)
    return Error{"", key + ".wall", "must be \"left\", \"right\" or \"back\""};
  for (size_t i = 0; i < spec.profilePx.size(); ++i)
    if (!spec.profilePx[i].allFinite())
      return Error{"", kp + "[" + std::to_string(i) + "]", "is not a finite number"};
  if (!wall) wall = wallUnder(camera, box, spec.profilePx);
  if (!wall)
    return Error{"", kp,
                 "the profile is not on a wall: its points fall on the floor or the ceiling "
                 "(draw it on the left, right or back wall)"};
  const WallFrame w = wallFrame(*wall, box);
  auto lifted = liftOntoWall(camera, box, w, spec.profilePx, kp);
  if (!lifted) return lifted.error();
  std::vector<Vec2> q = std::move(*lifted);
  snapRectilinear(q, spec.snapDeg);
  const Status onFloor = restOnFloor(q, camera, spec.profilePx, spec.floorSnapM, kp);
  if (!onFloor) return onFloor.error();
  auto ccw = detail::counterClockwiseSimplePolygon(q, kp);
  if (!ccw) return ccw.error();
  const double widthM = spec.widthM > 0 ? spec.widthM : w.oppositeM;
  if (!(widthM > 0))
    return Error{"", key + ".width_m",
                 "required for stairs on the back wall (the opposite wall is behind the camera)"};
  if (w.oppositeM > 0 && widthM > w.oppositeM + 1e-9)
    return Error{"", key + ".width_m",
                 "the stairs (" + std::to_string(widthM) + " m) are wider than the room (" +
                     std::to_string(w.oppositeM) + " m)"};
  const Vec3 eye(0, camera.heightM, 0);
  const double across = (eye - w.origin).dot(w.inward);
  if (across > 0 && across < widthM &&
      detail::insideOrOnPolygon(*ccw, Vec2((eye - w.origin).dot(w.u), eye.y())))
    return Error{"", key + ".width_m", "the stairs would enclose the camera: give a narrower width_m"};
  auto prism = detail::buildPrism(*ccw, w.origin, w.u, Vec3(0, 1, 0), widthM * w.inward, key);
  if (!prism) return prism.error();
  double aLo = 1e300, aHi = -1e300, yHi = 0;
  for (const Vec2& p : *ccw)
    aLo = std::min(aLo, p.x()), aHi = std::max(aHi, p.x()), yHi = std::max(yHi, p.y());
  const Vec3 lo = w.origin + aLo * w.u, hi = w.origin + aHi * w.u, sweep = widthM * w.inward;
  return stairsExtrusion(std::move(*prism), {lo, hi, hi + sweep, lo + sweep}, yHi);
}

}  // namespace inlay
