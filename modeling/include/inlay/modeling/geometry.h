// The room and everything that supports or hides inserted objects, as world-space surfaces.
//
// The box room comes from the back wall's four image corners plus the camera: the floor is
// y = 0, the back wall's bottom edge fixes its depth and the side walls, its top edge the
// ceiling. The wall behind the camera is never seen; it is placed `rearMarginM` behind the
// camera so the box is closed (light and bounces must stay inside). Extrusions (table tops) are
// prisms from a top outline lifted to the height given by a floor click (single-view
// metrology). Every surface is a triangle mesh with a stable integer id (its index).
#pragma once

#include "inlay/modeling/camera.h"
#include "inlay/modeling/core.h"
#include "inlay/modeling/mesh.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace inlay {

enum class SurfaceKind {
  Floor,
  Ceiling,
  WallLeft,    // x = xLeftM, facing +x
  WallRight,   // x = xRightM, facing -x
  WallBack,    // z = zBackM (the wall the camera looks at), facing +z
  WallRear,    // z = zRearM (behind the camera), facing -z
  ExtrusionTop,
  ExtrusionSide,
  OccluderCard,
};
const char* surfaceKindName(SurfaceKind kind);

// Axis-aligned box of the room, world metres.
struct RoomBox {
  double xLeftM = -2, xRightM = 2;
  double zBackM = -4, zRearM = 0.5;
  double ceilingM = 2.6;
};

struct Surface {
  SurfaceKind kind = SurfaceKind::Floor;
  std::string name;          // "floor", "wall_left", "table_1_top", ...
  TriangleMesh meshWorld;    // world metres, normals facing into the room / up for tops
  bool supportsObjects = false;  // objects may stand on it (floor, tops)
  int groupIndex = -1;       // index of the extrusion / occluder it belongs to, -1 for the box
};

struct SurfaceHit {
  int surfaceId = -1;
  double t = 0;              // ray parameter, metres
  Vec3 pointWorld;
  Vec3 normalWorld;          // geometric normal facing the ray's origin side
};

struct SceneGeometry {
  RoomBox box;
  std::vector<Surface> surfaces;  // id = index

  // Nearest hit along the ray (t > tMin). `supportsOnly`: only surfaces objects may stand on.
  std::optional<SurfaceHit> intersect(const Ray& ray, bool supportsOnly = false,
                                      double tMin = 1e-6) const;
};

struct RoomOptions {
  double rearMarginM = 0.5;  // distance of the unseen rear wall behind the camera
};

// Least-squares box from the four back-wall corners (TL, TR, BR, BL). Errors name
// "layout.back_wall_px" and say why (a floor corner at or above the horizon, a ceiling below
// the floor, a wall behind the camera, a degenerate quad).
Expected<RoomBox> roomFromBackWall(const Camera& camera, const std::array<Vec2, 4>& cornersPx,
                                   const RoomOptions& options = {});

// Where the back wall's corners appear in the photo (TL, TR, BR, BL); may lie outside it.
std::array<Vec2, 4> backWallCornersPx(const Camera& camera, const RoomBox& box);

// An extruded horizontal surface (a table top) from an outline and a floor click below
// outline point 0. Height by single-view metrology; the top is triangulated and extruded down
// to the floor. Errors name `keyForMessages` (e.g. "surfaces[0]").
struct Extrusion {
  std::vector<Vec3> topOutlineWorld;  // counter-clockwise seen from above, at y = heightM
  double heightM = 0;
};
Expected<Extrusion> extrusionFromOutline(const Camera& camera, const std::vector<Vec2>& outlinePx,
                                         const Vec2& heightClickPx,
                                         const std::string& keyForMessages);

// The room's six faces plus the given extrusions (top and sides each a surface).
SceneGeometry buildSceneGeometry(const RoomBox& box, const std::vector<Extrusion>& extrusions);

// Where an object stands: cast the pixel's ray onto the surfaces that support objects.
// Returns the object-to-world transform that scales the mesh uniformly to `heightM` (by its
// bounding box), turns it by `yawDeg` about +y (counter-clockwise seen from above), and rests
// the centre of its bounding box's base on the hit point. Errors name `keyForMessages`.
struct Placement {
  Mat4 worldFromObject = Mat4::Identity();
  Vec3 baseWorld{0, 0, 0};
  int supportSurfaceId = -1;
};
Expected<Placement> placeObject(const TriangleMesh& mesh, const SceneGeometry& geometry,
                                const Camera& camera, const Vec2& basePx, double heightM,
                                double yawDeg, const std::string& keyForMessages);

}  // namespace inlay
