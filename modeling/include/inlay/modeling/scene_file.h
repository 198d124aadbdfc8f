// The scene file (../shared/spec/scene-file.md, format "inlay-scene", version 1): the one
// document a user saves. SceneDoc mirrors its keys one to one; every optional key is a
// std::optional (missing = estimate automatically). Parsing validates every value and returns
// an Error naming the file, the key (e.g. "objects[1].height_m") and the reason; unknown keys
// are reported as warnings, never errors. Saving writes atomically and round-trips: what
// loadSceneFile reads back equals what was saved.
#pragma once

#include "inlay/modeling/core.h"

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace inlay {

// "camera.response": how the photo's encoded values map to radiance (modeling/response.h).
// "auto" (the default; also when missing): estimated from the photo; "srgb"; "linear"; or
// {"family": "toe_shoulder", "power": p, "toe": t, "shoulder": s} (missing numbers: sRGB's
// 1, 0, 0), {"family": "srgb"} or {"family": "linear"}. EXR/HDR photos are linear whatever it says.
struct ResponseKeys {
  enum class Mode { Auto, Srgb, Linear, ToeShoulder };
  Mode mode = Mode::Auto;
  double power = 1.0, toe = 0.0, shoulder = 0.0;  // ToeShoulder
  bool operator==(const ResponseKeys&) const = default;
};

// "camera.vignetting": the camera's radial fall-off V = 1 - v r^2 (r^2: the squared distance
// from the image centre over the corner's). "none" (the default; also when missing): the photo
// is taken as it is; "auto": the light fit's residual estimate, applied when it is between
// kMinAutoVignetting and kMaxAutoVignetting (engine/pipeline.h; measured worse than "none" on
// half A of the random cameras, so not the default: docs/camera-response.md); a number v in
// [0, kMax]: that strength. The physics works in the devignetted radiance f^-1(photo) / V, and
// the composite puts V back.
struct VignettingKeys {
  enum class Mode { Auto, None, Given };
  static constexpr double kMax = 0.9;
  Mode mode = Mode::None;
  double v = 0.0;  // Given
  bool operator==(const VignettingKeys&) const = default;
};

struct CameraKeys {
  std::optional<double> heightM;  // default 1.6 when missing
  std::optional<double> focalPx;
  std::optional<Vec2> principalPx;
  std::optional<std::array<Vec2, 3>> vanishingPointsPx;  // world x, y, z axes, in that order
  // "vanishing_lines_px": {"x"|"y"|"z": [[a0, b0], [a1, b1]]}: per world axis, two line
  // segments the user drew along that direction ({a0, b0, a1, b1} here); their lines meet at the
  // axis's vanishing point. Each segment is >= 2 px long and the two are not one line.
  std::array<std::optional<std::array<Vec2, 4>>, 3> vanishingLinesPx;
  ResponseKeys response;
  VignettingKeys vignetting;
};

struct LayoutKeys {
  // Top-left, top-right, bottom-right, bottom-left corners of the back wall.
  std::optional<std::array<Vec2, 4>> backWallPx;
  // "rear_m": how far the unseen rear wall stands behind the camera (metres, > 0). Missing: the
  // default margin, pushed back so that every light placed in 3D lies inside the box.
  std::optional<double> rearM;
};

struct LightKeys {
  enum class Kind { PolygonPx, RectM };
  Kind kind = Kind::PolygonPx;
  std::vector<Vec2> pointsPx;      // PolygonPx: the outline on the photo (>= 3 points)
  std::array<Vec3, 4> cornersM{};  // RectM: corners in the world frame (metres)
  std::optional<Vec3> rgb;         // starting intensity (RectM), linear photo units
  bool refine = true;              // "refine": false keeps the light as given
  // The refinement against the photo (lighting/refine.h): "lock": true keeps the light where
  // the estimate put it (position and intensity); "weights": {"position", "intensity"} are the
  // priors' weights toward that start (>= 0; larger holds the light closer).
  bool lock = false;
  double positionWeight = 10;
  double intensityWeight = 1;
  // "refine_size": true also fits the light's two edge lengths (within a factor 2), pulled
  // toward the start with "weights": {"size"}.
  bool refineSize = false;
  double sizeWeight = 10;
};

struct ShaftKeys {
  std::optional<std::array<double, 4>> shaftBoxPx;  // x0, y0, x1, y1
  std::optional<std::array<double, 4>> sourceBoxPx;
  std::optional<Vec3> direction;  // direction the light travels (world)
};

struct SurfaceKeys {
  std::string kind = "extrusion";  // "extrusion" | "box" | "stairs"
  // extrusion, box:
  std::vector<Vec2> outlinePx;  // closed outline around a horizontal top
  Vec2 heightClickPx{0, 0};     // a floor click straight below outlinePx[0]
  // "thickness_m": > 0 a slab this thick; 0 a solid to the floor; missing: a solid to the floor
  // unless an occluder's matte shows the floor under the top (then a slab, see slabFromMatte)
  std::optional<double> thicknessM;
  // stairs (a straight flight standing on the floor):
  Vec2 basePx{0, 0};             // "base_px": floor pixel, middle of the bottom step's front edge
  int steps = 0;                 // "steps": >= 1
  double riseM = 0;              // "rise_m": height of one step
  double runM = 0;               // "run_m": depth of one tread
  double widthM = 0;             // "width_m": across the flight
  std::string climbAxis = "-z";  // "climb_axis": "+x" | "-x" | "+z" | "-z" (default -z: away
                                 // from the camera)
  // stairs from a side profile drawn on a wall (instead of base_px, steps, rise_m, run_m):
  std::vector<Vec2> profilePx;  // "profile_px": closed polygon on the wall, >= 3 points
  std::string wall;             // "wall": "left" | "right" | "back"; "" = the wall it is on
                                // (widthM 0 = "width_m" missing: to the opposite wall)
};

struct OccluderKeys {
  std::vector<std::vector<Vec2>> foregroundScribblesPx;
  std::vector<std::vector<Vec2>> backgroundScribblesPx;
};

struct MaterialKeys {
  // "diffuse" | "glossy" | "metal" | "mirror" | "glass" | "rough_glass" | "emissive" | "asset"
  std::string preset = "diffuse";
  Vec3 albedo{0.8, 0.8, 0.8};
  double roughness = 0.3;
  double ior = 1.5;
  Vec3 rgb{1, 1, 1};  // emissive radiance, photo linear units
};

struct ObjectKeys {
  std::string mesh;          // "builtin:sphere", "builtin:cube", or a path as written
  std::string meshResolved;  // absolute path (empty for builtins), filled by the parser
  Vec2 basePx{0, 0};
  double heightM = 0.5;
  double yawDeg = 0.0;
  int subdivideLevels = 0;  // "subdivide": smooth subdivision levels (0: none)
  MaterialKeys material;
  std::string name;     // "name": what the user calls it (the file's name on insert)
  bool hidden = false;  // "hidden": kept in the scene, not rendered
};

// "room": {"materials": {"<surface name>": {...}}}: a real surface of the photo marked as
// reflective. Names are the room's surface names (floor, ceiling, wall_left, wall_right,
// wall_back, wall_rear, surface_<i>_top, surface_<i>_side, occluder_<i>_card); the parser checks
// their spelling, the engine that the room has them.
struct RoomMaterialKeys {
  std::string preset = "glossy";    // "glossy" (the projected albedo under a dielectric coat)
                                    // | "mirror" | "diffuse" (as if unmarked)
  double roughness = 0.2;           // glossy
  double ior = 1.5;                 // glossy: the coat
  Vec3 reflectance{0.9, 0.9, 0.9};  // mirror
};

struct RoomKeys {
  std::map<std::string, RoomMaterialKeys> materials;  // by surface name
};

struct RenderKeys {
  int spp = 256;
  std::optional<double> seconds;  // null / missing: no time limit
  // Adaptive sampling's target: each pixel's composite is sampled until its estimated standard
  // error (sRGB [0,1]) is below this (0: until spp or seconds). 0.004 is about one 8-bit step.
  double noise = 0.004;
  double exposure = 0.0;  // stops applied to the composite before encoding
  unsigned seed = 1;
  // Give the pixels the objects change the photo's own grain (its measured noise against
  // intensity), so an object is as grainy as the photo around it. Linear and noise-free photos
  // get none; the EXR layers stay clean.
  bool grain = true;
  // Clamp of indirect light (docs/generalization.md "The clamp of indirect light"): each sample's
  // light that reached the camera after two or more surfaces is scaled down to at most this many
  // times white (the photo's linear 1.0) in its largest channel, as Blender Cycles' "clamp
  // indirect" does. It removes fireflies (caustics through glass, highlights in mirrors) at the
  // price of a little energy. 0: off (unbiased). Light reaching the first surface the camera
  // sees is never clamped.
  double clampIndirect = kDefaultClampIndirect;
  // Chosen on half A of the training rooms (docs/generalization.md): the lowest object error
  // there, median and worst, among off, 1, 2, 4 and 8.
  static constexpr double kDefaultClampIndirect = 1.0;
};

// What the user marks on the photo: every key but the photo, the objects and the render
// settings. A change of any of them needs a new scene preparation (the studio's undo unit).
struct SceneMarks {
  CameraKeys camera;
  LayoutKeys layout;
  std::vector<LightKeys> lights;
  std::vector<ShaftKeys> shafts;
  std::vector<SurfaceKeys> surfaces;
  std::vector<OccluderKeys> occluders;
  RoomKeys room;  // room.materials: real surfaces marked glossy or mirror
};

struct SceneDoc : SceneMarks {
  std::string photo;          // as written in the file
  std::string photoResolved;  // absolute path, filled by the parser
  std::vector<ObjectKeys> objects;
  RenderKeys render;
};

struct SceneLoadResult {
  SceneDoc doc;
  std::vector<std::string> warnings;  // unknown keys and the like, one line each
};

struct SceneLimits {
  size_t maxFileBytes = 64u << 20;  // 64 MiB
  size_t maxObjects = 10'000;
  size_t maxPointsPerPolyline = 100'000;
  int maxNesting = 64;
};

// Parse from a file. Relative paths in the file are resolved against the file's folder.
Expected<SceneLoadResult> loadSceneFile(const std::string& path, const SceneLimits& limits = {});
// Parse from text; `baseDir` resolves relative paths; `fileNameForMessages` names the file in
// errors.
Expected<SceneLoadResult> parseSceneJson(const std::string& text, const std::string& baseDir,
                                         const std::string& fileNameForMessages,
                                         const SceneLimits& limits = {});
// Serialise (stable key order, indented). Paths are written as in `photo` / `mesh`.
std::string sceneToJson(const SceneDoc& doc);
// Atomic save.
Status saveSceneFile(const std::string& path, const SceneDoc& doc);

}  // namespace inlay
