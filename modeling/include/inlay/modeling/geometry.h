// The room and everything that supports or hides inserted objects, as world-space surfaces.
//
// The box room (RoomBox, roomFromBackWall) lives with the camera, in room_box.h: the camera
// estimate checks its boxes with it. Extrusions (table tops) are prisms from a top outline
// lifted to the height given by a floor click (single-view metrology). Every surface is a triangle mesh with a stable integer id (its index).
#pragma once

#include "inlay/modeling/camera.h"
#include "inlay/modeling/core.h"
#include "inlay/modeling/image.h"
#include "inlay/modeling/mesh.h"
#include "inlay/modeling/room_box.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace inlay {

enum class SurfaceKind {
  Floor,
  Ceiling,
  WallLeft,   // x = xLeftM, facing +x
  WallRight,  // x = xRightM, facing -x
  WallBack,   // z = zBackM (the wall the camera looks at), facing +z
  WallRear,   // z = zRearM (behind the camera), facing -z
  ExtrusionTop,
  ExtrusionSide,
  OccluderCard,
};
const char* surfaceKindName(SurfaceKind kind);
// The four walls of the box (not floor or ceiling).
inline bool isWall(SurfaceKind k) {
  return k == SurfaceKind::WallLeft || k == SurfaceKind::WallRight || k == SurfaceKind::WallBack ||
         k == SurfaceKind::WallRear;
}
// The six faces of the room's box (what an opening such as a window is cut into).
inline bool isBoxSurface(SurfaceKind k) {
  return k == SurfaceKind::Floor || k == SurfaceKind::Ceiling || isWall(k);
}

// The soft coverage of an occluder card (occluder.h makes it): the matte in photo pixels, looked
// up for a world point through the photo's camera. Immutable once built; any thread may read.
struct CardAlpha {
  Camera camera;   // the photo's camera
  ImageF alphaPx;  // H x W x 1, coverage in [0, 1], the photo's pixel frame
  // Bilinear coverage at the pixel a world point projects to; 0 outside the photo or behind
  // the camera.
  double alphaAt(const Vec3& pointWorld) const;
};

struct Surface {
  SurfaceKind kind = SurfaceKind::Floor;
  std::string name;              // "floor", "wall_left", "table_1_top", ...
  TriangleMesh meshWorld;        // world metres, normals facing into the room / up for tops
  bool supportsObjects = false;  // objects may stand on it (floor, tops)
  int groupIndex = -1;           // index of the extrusion / occluder it belongs to, -1 for the box
  // OccluderCard only: its matte. A ray crossing the card at p is stopped with probability
  // cardAlpha->alphaAt(p) and passes otherwise (a stochastic alpha test in the renderer).
  std::shared_ptr<const CardAlpha> cardAlpha;
};

struct SurfaceHit {
  int surfaceId = -1;
  double t = 0;  // ray parameter, metres
  Vec3 pointWorld;
  Vec3 normalWorld;  // geometric normal facing the ray's origin side
};

struct SceneGeometry {
  RoomBox box;
  std::vector<Surface> surfaces;  // id = index

  // Nearest hit along the ray (t > tMin). `supportsOnly`: only surfaces objects may stand on.
  // Occluder cards count where their matte covers at least half (as for the renderer's shadow
  // rays), so what is seen through a card's clear parts is the surface behind it.
  std::optional<SurfaceHit> intersect(const Ray& ray, bool supportsOnly = false,
                                      double tMin = 1e-6) const;
};

// For messages when a mark (a light's outline, a table top, a shaft box) does not land on the
// room: what the user can do about the box's `surface`, naming the back-wall corner that moves
// it and where that corner is in the photo, e.g. "check the room box: drag the back wall's
// bottom-left corner at (88, 402) onto the crease where the left wall meets the floor".
std::string roomBoxAdvice(const Camera& camera, const RoomBox& box, SurfaceKind surface);

// An extruded horizontal surface (a table top) from an outline and a floor click below
// outline point 0. Height by single-view metrology; the outline (either orientation) must be
// simple (CGAL), its top is triangulated (constrained Delaunay) and extruded down to the floor,
// or into a slab of `thicknessM` below the top; the solid, built in OpenMesh, is checked closed,
// manifold and bounding a volume. Errors name `keyForMessages` (e.g. "surfaces[0].outline_px"):
// fewer than 3 distinct points, collinear points, a crossing outline, a point or click at or
// above the horizon, a click above the top or not straight below outline point 0. On error
// nothing is built.
// The closed solid as built: an OpenMesh triangle mesh (defined inside modeling, in
// src/solid_mesh.h, so OpenMesh stays out of this header). Immutable once built.
struct SolidMesh;
// What OpenMesh's topology says about a solid: closed (no boundary halfedge), manifold (one
// closed fan of faces around every vertex), V - E + F (2 for a solid without holes), and the
// signed volume (positive: faces outward).
struct SolidSummary {
  size_t vertices = 0, edges = 0, faces = 0;
  bool closed = false;
  bool manifold = false;
  long eulerCharacteristic = 0;
  double volumeM3 = 0;
};
SolidSummary summarizeSolid(const SolidMesh& solid);

struct Extrusion {
  std::vector<Vec3> topOutlineWorld;  // counter-clockwise seen from above, at y = heightM
  double heightM = 0;
  double thicknessM = 0;  // 0: solid down to the floor; > 0: a slab this thick
  // The closed solid (OpenMesh), checked closed, manifold and outward when it was built. Null
  // for a hand-made Extrusion.
  std::shared_ptr<const SolidMesh> solid;
  // The solid converted for the renderer, flat-shaded with outward normals: the faces looking
  // up (the top, stair treads: objects stand on them) and all the others. Empty for a hand-made
  // Extrusion: buildSceneGeometry then prisms topOutlineWorld down to the floor itself.
  TriangleMesh upWorld;
  TriangleMesh otherWorld;
};
struct ExtrusionOptions {
  double thicknessM = 0;  // 0 (default): down to the floor; > 0: a slab, at most heightM
  // How far (pixels) outline point 0 may lie from the vertical through the click (the line
  // from the click toward the vertical vanishing point) before the click is refused as not
  // below it. Default 12 px: a careful click is within a few pixels.
  double maxClickOffsetPx = 12.0;
};
Expected<Extrusion> extrusionFromOutline(const Camera& camera, const std::vector<Vec2>& outlinePx,
                                         const Vec2& heightClickPx, const std::string& keyForMessages,
                                         const ExtrusionOptions& options = {});

// An axis-aligned box (a cabinet, a bed) by the same metrology: the outline is the top's outline
// as drawn, the click is on the floor below outline point 0; the box is the smallest rectangle
// aligned with the room's x and z axes around the lifted outline. Errors as extrusionFromOutline.
Expected<Extrusion> boxFromOutline(const Camera& camera, const std::vector<Vec2>& outlinePx,
                                   const Vec2& heightClickPx, const std::string& keyForMessages,
                                   const ExtrusionOptions& options = {});

// A straight flight of stairs standing on the floor: `steps` steps of `riseM` and `runM`,
// `widthM` wide, climbing along one room axis. The profile polygon (in the climb / up plane) is
// checked simple with CGAL and extruded across the width (OpenMesh); every tread is a surface
// objects stand on.
struct StairsSpec {
  Vec2 basePx{0, 0};          // floor pixel at the middle of the bottom step's front edge
  int steps = 0;              // >= 1
  double riseM = 0;           // height of one step, > 0
  double runM = 0;            // depth of one tread, > 0
  double widthM = 0;          // across the flight, > 0
  Vec3 climbWorld{0, 0, -1};  // unit room axis the stairs climb along (+-x or +-z)
};
Expected<Extrusion> stairsFromSpec(const Camera& camera, const StairsSpec& spec,
                                   const std::string& keyForMessages);

// Stairs from their side profile as drawn on a wall of the room: a closed polygon in photo
// pixels around the flight's side (treads, risers, the back and the floor line), lifted onto the
// wall's plane and extruded straight across the room from that wall, `widthM` wide or to the
// opposite wall. Drawn edges within `snapDeg` of level become exactly level (treads objects stand
// on), those within `snapDeg` of vertical exactly vertical, and points within `floorSnapM` of the
// floor rest on it; the result must be simple (CGAL), a crossing is refused with the two edges.
// Errors name `keyForMessages` + ".profile_px" (fewer than 3 points, collinear, crossing, a point
// whose ray misses the wall or lands off it, a profile not reaching the floor or whose lowest
// point is at or above the horizon), ".wall" or ".width_m" (stairs enclosing the camera, no
// opposite wall in front of the camera).
struct StairsProfileSpec {
  std::vector<Vec2> profilePx;  // closed polygon on the wall, >= 3 points, either orientation
  // The wall drawn on: WallLeft, WallRight or WallBack; nullopt: the wall most of the points'
  // rays meet first.
  std::optional<SurfaceKind> wall;
  double widthM = 0;         // > 0: across the flight from the wall; 0: to the opposite wall
                             // (left and right walls only)
  double snapDeg = 10.0;     // default 10 deg: a hand-drawn step is within a few degrees
  double floorSnapM = 0.05;  // default 5 cm: the floor line as drawn, give or take a pixel
};
Expected<Extrusion> stairsFromProfile(const Camera& camera, const RoomBox& box,
                                      const StairsProfileSpec& spec, const std::string& keyForMessages);

// The room's six faces plus the given extrusions (the up-looking faces and the rest each a
// surface: "surface_<i>_top" supports objects, "surface_<i>_side").
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
                                const Camera& camera, const Vec2& basePx, double heightM, double yawDeg,
                                const std::string& keyForMessages);

}  // namespace inlay
