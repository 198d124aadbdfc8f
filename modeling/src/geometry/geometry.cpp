#include "inlay/modeling/geometry.h"

#include "extrude_cgal.h"
#include "geometry_internal.h"
#include "solid_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace inlay {

const char* surfaceKindName(SurfaceKind kind) {
  switch (kind) {
    case SurfaceKind::Floor: return "floor";
    case SurfaceKind::Ceiling: return "ceiling";
    case SurfaceKind::WallLeft: return "wall_left";
    case SurfaceKind::WallRight: return "wall_right";
    case SurfaceKind::WallBack: return "wall_back";
    case SurfaceKind::WallRear: return "wall_rear";
    case SurfaceKind::ExtrusionTop: return "extrusion_top";
    case SurfaceKind::ExtrusionSide: return "extrusion_side";
    case SurfaceKind::OccluderCard: return "occluder_card";
  }
  return "surface";
}

namespace detail {

double signedAreaTop(const std::vector<Vec3>& poly) {
  double a = 0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const Vec3& p = poly[i];
    const Vec3& q = poly[(i + 1) % poly.size()];
    a += p.x() * (-q.z()) - q.x() * (-p.z());
  }
  return 0.5 * a;
}

}  // namespace detail

namespace {

using detail::hitHorizontal;
using detail::pxText;
using detail::signedAreaTop;

std::string rowText(double y) {
  if (!std::isfinite(y)) return "undefined";
  char buf[32];
  std::snprintf(buf, sizeof buf, "y = %.0f", y);
  return buf;
}

std::string metreText(double m) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f m", m);
  return buf;
}

// Adds quad a b c d (counter-clockwise seen from the side its normal n points to).
void addQuad(TriangleMesh& m, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
             const Vec3& n) {
  const uint32_t base = uint32_t(m.positions.size());
  for (const Vec3* p : {&a, &b, &c, &d}) {
    m.positions.push_back(p->cast<float>());
    m.normals.push_back(n.cast<float>());
  }
  m.triangles.push_back({base, base + 1, base + 2});
  m.triangles.push_back({base, base + 2, base + 3});
}

Surface makeSurface(SurfaceKind kind, std::string name, bool supports, int group = -1) {
  Surface s;
  s.kind = kind;
  s.name = std::move(name);
  s.supportsObjects = supports;
  s.groupIndex = group;
  return s;
}

}  // namespace

std::optional<SurfaceHit> SceneGeometry::intersect(const Ray& ray, bool supportsOnly,
                                                   double tMin) const {
  std::optional<SurfaceHit> best;
  double bestT = std::numeric_limits<double>::infinity();
  for (size_t s = 0; s < surfaces.size(); ++s) {
    const Surface& surf = surfaces[s];
    if (supportsOnly && !surf.supportsObjects) continue;
    const auto& P = surf.meshWorld.positions;
    for (const auto& tri : surf.meshWorld.triangles) {
      // Moller-Trumbore in double precision.
      const Vec3 v0 = P[tri[0]].cast<double>(), v1 = P[tri[1]].cast<double>(),
                 v2 = P[tri[2]].cast<double>();
      const Vec3 e1 = v1 - v0, e2 = v2 - v0;
      const Vec3 pv = ray.direction.cross(e2);
      const double det = e1.dot(pv);
      if (std::abs(det) < 1e-14) continue;
      const double inv = 1.0 / det;
      const Vec3 tv = ray.origin - v0;
      const double u = tv.dot(pv) * inv;
      if (u < -1e-9 || u > 1 + 1e-9) continue;
      const Vec3 qv = tv.cross(e1);
      const double v = ray.direction.dot(qv) * inv;
      if (v < -1e-9 || u + v > 1 + 1e-9) continue;
      const double t = e2.dot(qv) * inv;
      if (t > tMin && t < bestT && surf.cardAlpha && surf.cardAlpha->alphaAt(ray.at(t)) < 0.5)
        continue;  // an occluder card where its matte is mostly clear
      if (t > tMin && t < bestT) {
        bestT = t;
        Vec3 n = e1.cross(e2).normalized();
        if (n.dot(ray.direction) > 0) n = -n;
        best = SurfaceHit{int(s), t, ray.at(t), n};
      }
    }
  }
  return best;
}

std::string roomBoxAdvice(const Camera& camera, const RoomBox& box, SurfaceKind surface) {
  const auto c = backWallCornersPx(camera, box);
  auto at = [&](int i) {
    const bool inside = c[i].x() >= 0 && c[i].y() >= 0 && c[i].x() <= camera.widthPx &&
                        c[i].y() <= camera.heightPx;
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.0f, %.0f)%s", c[i].x(), c[i].y(),
                  inside ? "" : ", outside the photo");
    return std::string(buf);
  };
  switch (surface) {
    case SurfaceKind::WallLeft:
      return "check the room box: drag the back wall's bottom-left corner at " + at(3) +
             " onto the crease where the left wall meets the floor";
    case SurfaceKind::WallRight:
      return "check the room box: drag the back wall's bottom-right corner at " + at(2) +
             " onto the crease where the right wall meets the floor";
    case SurfaceKind::Ceiling:
      return "check the room box: drag the back wall's top corners at " + at(0) + " and " + at(1) +
             " onto the crease where the ceiling meets the back wall";
    case SurfaceKind::Floor:
    case SurfaceKind::WallBack:
      return "check the room box: drag the back wall's bottom corners at " + at(3) + " and " + at(2) +
             " onto the crease where the back wall meets the floor";
    default:
      return "check the room box: drag the back wall's corners at " + at(0) + ", " + at(1) + ", " +
             at(2) + " and " + at(3) + " onto the room's corners";
  }
}

double CardAlpha::alphaAt(const Vec3& pointWorld) const {
  if (alphaPx.empty()) return 0.0;
  const auto px = camera.project(pointWorld);
  if (!px || !px->allFinite()) return 0.0;
  // Pixel centres sit at +0.5; bilinear between the four around the point.
  const double fx = px->x() - 0.5, fy = px->y() - 0.5;
  if (fx < -0.5 || fy < -0.5 || fx > alphaPx.width - 0.5 || fy > alphaPx.height - 0.5) return 0.0;
  const int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  const double ax = fx - x0, ay = fy - y0;
  auto at = [&](int x, int y) {
    x = std::clamp(x, 0, alphaPx.width - 1);
    y = std::clamp(y, 0, alphaPx.height - 1);
    return double(alphaPx.at(x, y));
  };
  const double a = (1 - ax) * (1 - ay) * at(x0, y0) + ax * (1 - ay) * at(x0 + 1, y0) +
                   (1 - ax) * ay * at(x0, y0 + 1) + ax * ay * at(x0 + 1, y0 + 1);
  return std::clamp(a, 0.0, 1.0);
}

namespace {

// Fills ex.upWorld / ex.otherWorld: the prism of topOutlineWorld from yBottom up to heightM.
Status buildExtrusionSolid(Extrusion& ex, double yBottom, const std::string& key) {
  std::vector<Vec2> q;
  for (const Vec3& p : ex.topOutlineWorld) q.emplace_back(p.x(), -p.z());
  auto ccw = detail::counterClockwiseSimplePolygon(q, key + ".outline_px");
  if (!ccw) return ccw.error();
  auto prism = detail::buildPrism(*ccw, Vec3(0, yBottom, 0), Vec3(1, 0, 0), Vec3(0, 0, -1),
                                  Vec3(0, ex.heightM - yBottom, 0), key);
  if (!prism) return prism.error();
  ex.upWorld = std::move(prism->upWorld);
  ex.otherWorld = std::move(prism->otherWorld);
  ex.solid = std::move(prism->solid);
  return Status{};
}

}  // namespace

Expected<Extrusion> extrusionFromOutline(const Camera& camera, const std::vector<Vec2>& outlinePx,
                                         const Vec2& clickPx, const std::string& key,
                                         const ExtrusionOptions& options) {
  // Simple, at least 3 distinct points, not collinear (CGAL); either orientation.
  auto outline = detail::counterClockwiseSimplePolygon(outlinePx, key + ".outline_px");
  if (!outline) return outline.error();
  if (!clickPx.allFinite()) return Error{"", key + ".height_click_px", "is not a finite number"};
  if (!(options.thicknessM >= 0) || !std::isfinite(options.thicknessM))
    return Error{"", key + ".thickness_m", "must be a positive number (or missing)"};
  const size_t n = outlinePx.size();
  // Height by single-view metrology: the click is on the floor straight below outline point 0;
  // the height is where point 0's ray passes closest to the vertical line through the click.
  const auto floorPt = hitHorizontal(camera.rayThroughPixel(clickPx), 0.0);
  if (!floorPt)
    return Error{"", key + ".height_click_px",
                 "the click " + pxText(clickPx) + " is at or above the horizon (row " +
                     rowText(horizonRowPx(camera, clickPx.x())) +
                     " there), so it cannot be on "
                     "the floor: click the floor straight below outline point 0, below the horizon"};
  {
    // Point 0 must lie on the image of the vertical through the click: the line from the click
    // toward the vertical vanishing point (possibly at infinity).
    const Vec3 vp = camera.vanishingPointOf(Vec3(0, 1, 0));
    const Vec3 line = Vec3(clickPx.x(), clickPx.y(), 1.0).cross(vp);
    const double norm2 = std::hypot(line.x(), line.y());
    if (norm2 > 0) {
      const double off = std::abs(line.dot(Vec3(outlinePx[0].x(), outlinePx[0].y(), 1.0))) / norm2;
      if (off > options.maxClickOffsetPx)
        return Error{"", key + ".height_click_px",
                     "the click " + pxText(clickPx) + " is not straight below outline point 0 " +
                         pxText(outlinePx[0]) + " (" + std::to_string(int(std::lround(off))) +
                         " px off the vertical through it)"};
    }
  }
  const Ray r0 = camera.rayThroughPixel(outlinePx[0]);
  // Closest points of r0.origin + t d and floorPt + s up.
  const Vec3 up(0, 1, 0);
  const Vec3 w0 = r0.origin - *floorPt;
  const double a = r0.direction.dot(r0.direction), b = r0.direction.dot(up), cc = 1.0;
  const double d = r0.direction.dot(w0), e = up.dot(w0);
  const double den = a * cc - b * b;
  if (den < 1e-12)
    return Error{"", key + ".height_click_px", "the outline point is straight above the camera"};
  const double s = (a * e - b * d) / den;      // along the vertical line: the height
  const double tRay = (b * e - cc * d) / den;  // along the ray
  if (!(tRay > 0))
    return Error{"", key + ".height_click_px",
                 "outline point 0 " + pxText(outlinePx[0]) + " and the floor click " + pxText(clickPx) +
                     " do not meet in front of the camera (the vertical through "
                     "the click passes behind it): click the floor straight below outline point 0"};
  const double h = s;
  if (!(h > 0.01))
    return Error{"", key + ".height_click_px",
                 "the click " + pxText(clickPx) +
                     " is not below the outline's first point "
                     "(the height would be " +
                     std::to_string(h) + " m): click the floor under it"};
  if (std::abs(h - camera.heightM) < 0.01)
    return Error{"", key + ".height_click_px",
                 "the top would be at the camera's height, seen edge-on: its outline cannot be "
                 "placed"};
  if (options.thicknessM >= h)
    return Error{"", key + ".thickness_m",
                 "the slab (" + std::to_string(options.thicknessM) +
                     " m) is thicker than the top "
                     "is high (" +
                     std::to_string(h) + " m)"};
  Extrusion ex;
  ex.heightM = h;
  ex.thicknessM = options.thicknessM;
  for (size_t i = 0; i < n; ++i) {
    const auto p = hitHorizontal(camera.rayThroughPixel(outlinePx[i]), h);
    if (!p)
      return Error{"", key + ".outline_px[" + std::to_string(i) + "]",
                   "the point " + pxText(outlinePx[i]) + " cannot lie on a top at " + metreText(h) +
                       ": it is " + (h < camera.heightM ? "above" : "below") + " the horizon (row " +
                       rowText(horizonRowPx(camera, outlinePx[i].x())) + " there), and a top " +
                       (h < camera.heightM ? "below" : "above") + " the camera's eye is seen " +
                       (h < camera.heightM ? "from above" : "from below") + ": outline the top " +
                       (h < camera.heightM ? "below" : "above") +
                       " the horizon, or check the height click"};
    ex.topOutlineWorld.push_back(*p);
  }
  const double area = signedAreaTop(ex.topOutlineWorld);
  if (std::abs(area) < 1e-6) return Error{"", key + ".outline_px", "the outline has no area"};
  if (area < 0) std::reverse(ex.topOutlineWorld.begin(), ex.topOutlineWorld.end());
  const Status built = buildExtrusionSolid(ex, ex.thicknessM > 0 ? h - ex.thicknessM : 0.0, key);
  if (!built) return built.error();
  return ex;
}

Expected<Extrusion> boxFromOutline(const Camera& camera, const std::vector<Vec2>& outlinePx,
                                   const Vec2& clickPx, const std::string& key,
                                   const ExtrusionOptions& options) {
  auto ex = extrusionFromOutline(camera, outlinePx, clickPx, key, options);
  if (!ex) return ex;
  double x0 = 1e300, x1 = -1e300, z0 = 1e300, z1 = -1e300;
  for (const Vec3& p : ex->topOutlineWorld) {
    x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x());
    z0 = std::min(z0, p.z()), z1 = std::max(z1, p.z());
  }
  const double h = ex->heightM;
  // Counter-clockwise seen from above (x right, -z up).
  ex->topOutlineWorld = {{x0, h, z1}, {x1, h, z1}, {x1, h, z0}, {x0, h, z0}};
  const Status built = buildExtrusionSolid(*ex, ex->thicknessM > 0 ? h - ex->thicknessM : 0.0, key);
  if (!built) return built.error();
  return ex;
}

SceneGeometry buildSceneGeometry(const RoomBox& b, const std::vector<Extrusion>& extrusions) {
  SceneGeometry g;
  g.box = b;
  const double x0 = b.xLeftM, x1 = b.xRightM, z0 = b.zBackM, z1 = b.zRearM, y1 = b.ceilingM;
  {
    Surface s = makeSurface(SurfaceKind::Floor, "floor", true);
    addQuad(s.meshWorld, {x0, 0, z1}, {x1, 0, z1}, {x1, 0, z0}, {x0, 0, z0}, {0, 1, 0});
    g.surfaces.push_back(std::move(s));
  }
  {
    Surface s = makeSurface(SurfaceKind::Ceiling, "ceiling", false);
    addQuad(s.meshWorld, {x0, y1, z0}, {x1, y1, z0}, {x1, y1, z1}, {x0, y1, z1}, {0, -1, 0});
    g.surfaces.push_back(std::move(s));
  }
  {
    Surface s = makeSurface(SurfaceKind::WallLeft, "wall_left", false);
    addQuad(s.meshWorld, {x0, 0, z1}, {x0, 0, z0}, {x0, y1, z0}, {x0, y1, z1}, {1, 0, 0});
    g.surfaces.push_back(std::move(s));
  }
  {
    Surface s = makeSurface(SurfaceKind::WallRight, "wall_right", false);
    addQuad(s.meshWorld, {x1, 0, z0}, {x1, 0, z1}, {x1, y1, z1}, {x1, y1, z0}, {-1, 0, 0});
    g.surfaces.push_back(std::move(s));
  }
  {
    Surface s = makeSurface(SurfaceKind::WallBack, "wall_back", false);
    addQuad(s.meshWorld, {x0, 0, z0}, {x1, 0, z0}, {x1, y1, z0}, {x0, y1, z0}, {0, 0, 1});
    g.surfaces.push_back(std::move(s));
  }
  {
    Surface s = makeSurface(SurfaceKind::WallRear, "wall_rear", false);
    addQuad(s.meshWorld, {x1, 0, z1}, {x0, 0, z1}, {x0, y1, z1}, {x1, y1, z1}, {0, 0, -1});
    g.surfaces.push_back(std::move(s));
  }
  for (size_t e = 0; e < extrusions.size(); ++e) {
    const auto& ex = extrusions[e];
    const std::string base = "surface_" + std::to_string(e);
    if (!ex.upWorld.empty()) {  // the solid built in OpenMesh, converted
      Surface top = makeSurface(SurfaceKind::ExtrusionTop, base + "_top", true, int(e));
      top.meshWorld = ex.upWorld;
      g.surfaces.push_back(std::move(top));
      Surface side = makeSurface(SurfaceKind::ExtrusionSide, base + "_side", false, int(e));
      side.meshWorld = ex.otherWorld;
      g.surfaces.push_back(std::move(side));
      continue;
    }
    Surface top = makeSurface(SurfaceKind::ExtrusionTop, base + "_top", true, int(e));
    std::vector<Vec2> pts2;
    for (const Vec3& p : ex.topOutlineWorld) {
      top.meshWorld.positions.push_back(p.cast<float>());
      top.meshWorld.normals.push_back(Vec3f(0, 1, 0));
      pts2.emplace_back(p.x(), -p.z());
    }
    for (const auto& t : detail::triangulatePolygon(pts2)) {
      // (x, -z) counter-clockwise is clockwise in (x, z): flip so the normal points up.
      top.meshWorld.triangles.push_back({t[0], t[2], t[1]});
    }
    g.surfaces.push_back(std::move(top));
    Surface side = makeSurface(SurfaceKind::ExtrusionSide, base + "_side", false, int(e));
    const size_t n = ex.topOutlineWorld.size();
    for (size_t i = 0; i < n; ++i) {
      const Vec3 a = ex.topOutlineWorld[i], c = ex.topOutlineWorld[(i + 1) % n];
      const Vec3 a0(a.x(), 0, a.z()), c0(c.x(), 0, c.z());
      Vec3 nrm = (c - a).cross(Vec3(0, 1, 0));
      if (nrm.norm() < 1e-12) continue;
      nrm.normalize();
      // Outward for a counter-clockwise outline seen from above.
      addQuad(side.meshWorld, a0, c0, c, a, -nrm);
    }
    g.surfaces.push_back(std::move(side));
  }
  return g;
}

Expected<Placement> placeObject(const TriangleMesh& mesh, const SceneGeometry& geometry,
                                const Camera& camera, const Vec2& basePx, double heightM, double yawDeg,
                                const std::string& key) {
  if (mesh.empty()) return Error{"", key + ".mesh", "the mesh has no triangles"};
  if (!basePx.allFinite()) return Error{"", key + ".base_px", "is not a finite number"};
  if (!(heightM > 0 && std::isfinite(heightM)))
    return Error{"", key + ".height_m", "must be a positive finite number"};
  if (!std::isfinite(yawDeg)) return Error{"", key + ".yaw_deg", "is not a finite number"};
  const auto hit = geometry.intersect(camera.rayThroughPixel(basePx), true);
  if (!hit || hit->normalWorld.y() < 0.5)
    return Error{"", key + ".base_px",
                 "the pixel " + pxText(basePx) +
                     " is not on the floor or any surface an "
                     "object can stand on"};
  const Eigen::AlignedBox3f bb = mesh.bounds();
  const double sizeY = double(bb.max().y() - bb.min().y());
  if (!(sizeY > 1e-12) || !std::isfinite(sizeY))
    return Error{"", key + ".mesh", "the mesh is flat (zero height): it cannot be scaled"};
  const double s = heightM / sizeY;
  const Vec3 baseCentre(0.5 * (bb.min().x() + bb.max().x()), bb.min().y(),
                        0.5 * (bb.min().z() + bb.max().z()));
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  t.translate(hit->pointWorld);
  t.rotate(Eigen::AngleAxisd(yawDeg * M_PI / 180.0, Vec3::UnitY()));
  t.scale(s);
  t.translate(-baseCentre);
  Placement p;
  p.worldFromObject = t.matrix();
  p.baseWorld = hit->pointWorld;
  p.supportSurfaceId = hit->surfaceId;
  return p;
}

}  // namespace inlay
