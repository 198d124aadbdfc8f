// The scene file: every key parsed and round-tripped, every bad input named by its key path.
#include "inlay/modeling/scene_file.h"

#include "test_support.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>

namespace inlay {
namespace {

namespace fs = std::filesystem;

void writeText(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream out(p, std::ios::binary);
  out << text;
}

// A folder with a photo and a mesh the scene files below refer to.
fs::path sceneDir(const std::string& name) {
  fs::path dir = test::tempDir("scene_" + name);
  writeText(dir / "room.jpg", "not decoded by the scene reader");
  writeText(dir / "models" / "chair.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  return dir;
}

const char* kFullScene = R"({
  "format": "inlay-scene",
  "version": 1,
  "photo": "room.jpg",
  "camera": {
    "height_m": 1.5,
    "focal_px": 620.25,
    "principal_px": [256.0, 192.5],
    "vanishing_points_px": [[10000000.0, 190.0], [256.0, -9000.5], [250.0, 180.0]]
  },
  "layout": { "back_wall_px": [[100, 50], [400, 52], [398, 300], [102, 298]], "rear_m": 0.85 },
  "lights": [
    { "kind": "polygon_px", "points": [[200, 10], [300, 10], [300, 40], [200, 40]],
      "lock": true, "refine_size": true, "weights": { "position": 50, "intensity": 0.5, "size": 3 } },
    { "kind": "rect_m", "corners": [[-1, 2.5, -3], [1, 2.5, -3], [1, 2.5, -2], [-1, 2.5, -2]],
      "rgb": [5, 4.5, 4], "refine": false }
  ],
  "shafts": [
    { "shaft_box_px": [10, 200, 120, 300], "source_box_px": [0, 20, 60, 150] },
    { "shaft_box_px": [10, 200, 120, 300], "direction": [0.3, -0.8, 0.2] }
  ],
  "surfaces": [
    { "kind": "extrusion", "outline_px": [[150, 220], [260, 220], [270, 260], [140, 260]],
      "height_click_px": [150, 330] }
  ],
  "occluders": [
    { "foreground_scribbles_px": [[[10, 10], [12, 14]], [[30, 30]]],
      "background_scribbles_px": [[[50, 50], [60, 65], [70, 80]]] }
  ],
  "objects": [
    { "mesh": "builtin:sphere", "base_px": [210.5, 250.25], "height_m": 0.25, "yaw_deg": 30,
      "material": { "preset": "glossy", "albedo": [0.7, 0.1, 0.05], "roughness": 0.35 } },
    { "mesh": "models/chair.obj", "base_px": [300, 280], "height_m": 0.9, "yaw_deg": -15.5,
      "material": { "preset": "glass", "ior": 1.45 } },
    { "mesh": "builtin:cube", "base_px": [100, 290], "subdivide": 2,
      "material": { "preset": "emissive", "rgb": [3, 2, 1] } }
  ],
  "render": { "spp": 64, "seconds": 12.5, "noise": 0.01, "exposure": -0.5, "seed": 7, "grain": false, "clamp_indirect": 6.5 }
})";

void expectDocsEqual(const SceneDoc& a, const SceneDoc& b) {
  EXPECT_EQ(a.photo, b.photo);
  EXPECT_EQ(a.photoResolved, b.photoResolved);
  EXPECT_EQ(a.camera.heightM, b.camera.heightM);
  EXPECT_EQ(a.camera.focalPx, b.camera.focalPx);
  EXPECT_EQ(a.camera.principalPx.has_value(), b.camera.principalPx.has_value());
  if (a.camera.principalPx && b.camera.principalPx) {
    EXPECT_EQ(*a.camera.principalPx, *b.camera.principalPx);
  }
  ASSERT_EQ(a.camera.vanishingPointsPx.has_value(), b.camera.vanishingPointsPx.has_value());
  if (a.camera.vanishingPointsPx) {
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ((*a.camera.vanishingPointsPx)[i], (*b.camera.vanishingPointsPx)[i]);
  }
  ASSERT_EQ(a.layout.backWallPx.has_value(), b.layout.backWallPx.has_value());
  if (a.layout.backWallPx) {
    for (int i = 0; i < 4; ++i) EXPECT_EQ((*a.layout.backWallPx)[i], (*b.layout.backWallPx)[i]);
  }
  EXPECT_EQ(a.layout.rearM, b.layout.rearM);
  ASSERT_EQ(a.lights.size(), b.lights.size());
  for (size_t i = 0; i < a.lights.size(); ++i) {
    EXPECT_EQ(a.lights[i].kind, b.lights[i].kind);
    EXPECT_EQ(a.lights[i].pointsPx, b.lights[i].pointsPx);
    if (a.lights[i].kind == LightKeys::Kind::RectM) {
      for (int k = 0; k < 4; ++k) EXPECT_EQ(a.lights[i].cornersM[k], b.lights[i].cornersM[k]);
    }
    EXPECT_EQ(a.lights[i].rgb.has_value(), b.lights[i].rgb.has_value());
    if (a.lights[i].rgb && b.lights[i].rgb) {
      EXPECT_EQ(*a.lights[i].rgb, *b.lights[i].rgb);
    }
    EXPECT_EQ(a.lights[i].refine, b.lights[i].refine);
    EXPECT_EQ(a.lights[i].lock, b.lights[i].lock);
    EXPECT_EQ(a.lights[i].positionWeight, b.lights[i].positionWeight);
    EXPECT_EQ(a.lights[i].intensityWeight, b.lights[i].intensityWeight);
    EXPECT_EQ(a.lights[i].refineSize, b.lights[i].refineSize);
    EXPECT_EQ(a.lights[i].sizeWeight, b.lights[i].sizeWeight);
  }
  ASSERT_EQ(a.shafts.size(), b.shafts.size());
  for (size_t i = 0; i < a.shafts.size(); ++i) {
    EXPECT_EQ(a.shafts[i].shaftBoxPx, b.shafts[i].shaftBoxPx);
    EXPECT_EQ(a.shafts[i].sourceBoxPx, b.shafts[i].sourceBoxPx);
    EXPECT_EQ(a.shafts[i].direction.has_value(), b.shafts[i].direction.has_value());
    if (a.shafts[i].direction && b.shafts[i].direction) {
      EXPECT_EQ(*a.shafts[i].direction, *b.shafts[i].direction);
    }
  }
  ASSERT_EQ(a.surfaces.size(), b.surfaces.size());
  for (size_t i = 0; i < a.surfaces.size(); ++i) {
    EXPECT_EQ(a.surfaces[i].kind, b.surfaces[i].kind);
    EXPECT_EQ(a.surfaces[i].outlinePx, b.surfaces[i].outlinePx);
    EXPECT_EQ(a.surfaces[i].heightClickPx, b.surfaces[i].heightClickPx);
  }
  ASSERT_EQ(a.occluders.size(), b.occluders.size());
  for (size_t i = 0; i < a.occluders.size(); ++i) {
    EXPECT_EQ(a.occluders[i].foregroundScribblesPx, b.occluders[i].foregroundScribblesPx);
    EXPECT_EQ(a.occluders[i].backgroundScribblesPx, b.occluders[i].backgroundScribblesPx);
  }
  ASSERT_EQ(a.objects.size(), b.objects.size());
  for (size_t i = 0; i < a.objects.size(); ++i) {
    const ObjectKeys &x = a.objects[i], &y = b.objects[i];
    EXPECT_EQ(x.mesh, y.mesh);
    EXPECT_EQ(x.meshResolved, y.meshResolved);
    EXPECT_EQ(x.basePx, y.basePx);
    EXPECT_EQ(x.heightM, y.heightM);
    EXPECT_EQ(x.yawDeg, y.yawDeg);
    EXPECT_EQ(x.subdivideLevels, y.subdivideLevels);
    EXPECT_EQ(x.material.preset, y.material.preset);
    EXPECT_EQ(x.material.albedo, y.material.albedo);
    EXPECT_EQ(x.material.roughness, y.material.roughness);
    EXPECT_EQ(x.material.ior, y.material.ior);
    EXPECT_EQ(x.material.rgb, y.material.rgb);
  }
  EXPECT_EQ(a.render.spp, b.render.spp);
  EXPECT_EQ(a.render.seconds, b.render.seconds);
  EXPECT_EQ(a.render.exposure, b.render.exposure);
  EXPECT_EQ(a.render.noise, b.render.noise);
  EXPECT_EQ(a.render.seed, b.render.seed);
  EXPECT_EQ(a.render.grain, b.render.grain);
  EXPECT_EQ(a.render.clampIndirect, b.render.clampIndirect);
}

TEST(SceneFile, FullSceneParsesEveryKey) {
  const fs::path dir = sceneDir("full");
  writeText(dir / "scene.json", kFullScene);
  auto r = loadSceneFile((dir / "scene.json").string());
  ASSERT_TRUE(r.ok()) << r.error().message();
  EXPECT_TRUE(r->warnings.empty());
  const SceneDoc& d = r->doc;
  EXPECT_EQ(d.photo, "room.jpg");
  EXPECT_EQ(fs::path(d.photoResolved), (dir / "room.jpg").lexically_normal());
  EXPECT_EQ(d.camera.heightM, 1.5);
  EXPECT_EQ(d.camera.focalPx, 620.25);
  EXPECT_EQ(*d.camera.principalPx, Vec2(256.0, 192.5));
  EXPECT_EQ((*d.camera.vanishingPointsPx)[0], Vec2(1e7, 190.0));  // far away: kept as given
  EXPECT_EQ((*d.layout.backWallPx)[2], Vec2(398, 300));
  ASSERT_TRUE(d.layout.rearM.has_value());
  EXPECT_DOUBLE_EQ(*d.layout.rearM, 0.85);
  ASSERT_EQ(d.lights.size(), 2u);
  EXPECT_EQ(d.lights[0].kind, LightKeys::Kind::PolygonPx);
  EXPECT_EQ(d.lights[0].pointsPx.size(), 4u);
  EXPECT_TRUE(d.lights[0].refine);
  EXPECT_FALSE(d.lights[0].rgb.has_value());
  EXPECT_EQ(d.lights[1].kind, LightKeys::Kind::RectM);
  EXPECT_EQ(d.lights[1].cornersM[3], Vec3(-1, 2.5, -2));
  EXPECT_EQ(*d.lights[1].rgb, Vec3(5, 4.5, 4));
  EXPECT_FALSE(d.lights[1].refine);
  EXPECT_TRUE(d.lights[0].lock);
  EXPECT_EQ(d.lights[0].positionWeight, 50);
  EXPECT_EQ(d.lights[0].intensityWeight, 0.5);
  EXPECT_TRUE(d.lights[0].refineSize);
  EXPECT_EQ(d.lights[0].sizeWeight, 3);
  EXPECT_FALSE(d.lights[1].refineSize);
  EXPECT_EQ(d.lights[1].sizeWeight, 10);
  EXPECT_FALSE(d.lights[1].lock);
  EXPECT_EQ(d.lights[1].positionWeight, 10);
  EXPECT_EQ(d.lights[1].intensityWeight, 1);
  ASSERT_EQ(d.shafts.size(), 2u);
  EXPECT_EQ(d.shafts[0].sourceBoxPx, (std::array<double, 4>{0, 20, 60, 150}));
  EXPECT_FALSE(d.shafts[0].direction.has_value());
  EXPECT_EQ(*d.shafts[1].direction, Vec3(0.3, -0.8, 0.2));
  ASSERT_EQ(d.surfaces.size(), 1u);
  EXPECT_EQ(d.surfaces[0].heightClickPx, Vec2(150, 330));
  ASSERT_EQ(d.occluders.size(), 1u);
  EXPECT_EQ(d.occluders[0].foregroundScribblesPx.size(), 2u);
  EXPECT_EQ(d.occluders[0].backgroundScribblesPx[0].size(), 3u);
  ASSERT_EQ(d.objects.size(), 3u);
  EXPECT_EQ(d.objects[0].mesh, "builtin:sphere");
  EXPECT_TRUE(d.objects[0].meshResolved.empty());
  EXPECT_EQ(d.objects[0].material.preset, "glossy");
  EXPECT_EQ(d.objects[0].material.roughness, 0.35);
  EXPECT_EQ(d.objects[1].mesh, "models/chair.obj");
  EXPECT_EQ(fs::path(d.objects[1].meshResolved), (dir / "models" / "chair.obj").lexically_normal());
  EXPECT_TRUE(fs::path(d.objects[1].meshResolved).is_absolute());
  EXPECT_EQ(d.objects[1].material.ior, 1.45);
  EXPECT_EQ(d.objects[0].subdivideLevels, 0);
  EXPECT_EQ(d.objects[2].subdivideLevels, 2);
  EXPECT_EQ(d.objects[2].heightM, 0.5);  // default
  EXPECT_EQ(d.objects[2].material.rgb, Vec3(3, 2, 1));
  EXPECT_EQ(d.render.spp, 64);
  EXPECT_EQ(d.render.seconds, 12.5);
  EXPECT_EQ(d.render.exposure, -0.5);
  EXPECT_EQ(d.render.noise, 0.01);
  EXPECT_EQ(d.render.seed, 7u);
  EXPECT_FALSE(d.render.grain);
}

TEST(SceneFile, SaveAndLoadRoundTripsEveryKey) {
  const fs::path dir = sceneDir("roundtrip");
  writeText(dir / "scene.json", kFullScene);
  auto first = loadSceneFile((dir / "scene.json").string());
  ASSERT_TRUE(first.ok()) << first.error().message();
  // Values that decimal text cannot hold exactly must survive too.
  SceneDoc doc = first->doc;
  doc.camera.focalPx = 1.0 / 3.0;
  doc.objects[0].yawDeg = 0.1 + 0.2;
  const fs::path saved = dir / "saved.json";
  ASSERT_TRUE(saveSceneFile(saved.string(), doc).ok());
  auto second = loadSceneFile(saved.string());
  ASSERT_TRUE(second.ok()) << second.error().message();
  EXPECT_TRUE(second->warnings.empty());
  expectDocsEqual(doc, second->doc);
  // And the text is stable.
  EXPECT_EQ(sceneToJson(doc), sceneToJson(second->doc));
  // Spec order: format, version, photo first; render last.
  const std::string text = sceneToJson(doc);
  EXPECT_LT(text.find("\"format\""), text.find("\"version\""));
  EXPECT_LT(text.find("\"version\""), text.find("\"photo\""));
  EXPECT_LT(text.find("\"photo\""), text.find("\"camera\""));
  EXPECT_LT(text.find("\"objects\""), text.find("\"render\""));
}

// "room.materials": surfaces marked as a real mirror or a glossy floor, by surface name.
// layout.rear_m alone (the back wall estimated) is kept on save; without it no layout is written.
// render.clamp_indirect: a number of times white or "off" (0); the default when missing; kept on
// save ("off" written for 0).
TEST(SceneFile, ClampIndirectOffNumberAndDefault) {
  const fs::path dir = sceneDir("clamp");
  auto parse = [&](const std::string& render) {
    return parseSceneJson(
        R"({"format": "inlay-scene", "version": 1, "photo": "room.jpg", "render": )" + render + "}",
        dir.string(), "scene.json");
  };
  auto off = parse(R"({"clamp_indirect": "off"})");
  ASSERT_TRUE(off.ok()) << off.error().message();
  EXPECT_EQ(off->doc.render.clampIndirect, 0.0);
  auto four = parse(R"({"clamp_indirect": 4})");
  ASSERT_TRUE(four.ok()) << four.error().message();
  EXPECT_EQ(four->doc.render.clampIndirect, 4.0);
  auto none = parse("{}");
  ASSERT_TRUE(none.ok()) << none.error().message();
  EXPECT_EQ(none->doc.render.clampIndirect, RenderKeys::kDefaultClampIndirect);
  SceneDoc d = four->doc;
  d.render.clampIndirect = 0;
  EXPECT_NE(sceneToJson(d).find("\"clamp_indirect\": \"off\""), std::string::npos);
}

TEST(SceneFile, RearWallDistanceAloneRoundTrips) {
  const fs::path dir = sceneDir("rear_m");
  writeText(dir / "scene.json", R"({"format": "inlay-scene", "version": 1, "photo": "room.jpg",
                                    "layout": {"rear_m": 1.25}})");
  auto r = loadSceneFile((dir / "scene.json").string());
  ASSERT_TRUE(r.ok()) << r.error().message();
  EXPECT_TRUE(r->warnings.empty());
  EXPECT_FALSE(r->doc.layout.backWallPx.has_value());
  ASSERT_TRUE(r->doc.layout.rearM.has_value());
  EXPECT_DOUBLE_EQ(*r->doc.layout.rearM, 1.25);
  const std::string text = sceneToJson(r->doc);
  EXPECT_NE(text.find("\"rear_m\""), std::string::npos);
  EXPECT_EQ(text.find("\"back_wall_px\""), std::string::npos);
  SceneDoc noLayout = r->doc;
  noLayout.layout.rearM.reset();
  EXPECT_EQ(sceneToJson(noLayout).find("\"layout\""), std::string::npos);
}

TEST(SceneFile, RoomMaterialsParseAndRoundTrip) {
  const fs::path dir = sceneDir("room_materials");
  auto r = parseSceneJson(
      R"({"format": "inlay-scene", "version": 1, "photo": "room.jpg", "room": {"materials": {
            "floor": {"preset": "glossy", "roughness": 0.1, "ior": 1.4},
            "wall_left": {"preset": "mirror", "reflectance": [0.8, 0.85, 0.9]},
            "surface_2_top": {}}}})",
      dir.string(), "scene.json");
  ASSERT_TRUE(r.ok()) << r.error().message();
  EXPECT_TRUE(r->warnings.empty());
  const auto& m = r->doc.room.materials;
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m.at("floor").preset, "glossy");
  EXPECT_EQ(m.at("floor").roughness, 0.1);
  EXPECT_EQ(m.at("floor").ior, 1.4);
  EXPECT_EQ(m.at("wall_left").preset, "mirror");
  EXPECT_EQ(m.at("wall_left").reflectance, Vec3(0.8, 0.85, 0.9));
  EXPECT_EQ(m.at("surface_2_top").preset, "glossy");  // the default preset
  auto again = parseSceneJson(sceneToJson(r->doc), dir.string(), "scene.json");
  ASSERT_TRUE(again.ok()) << again.error().message();
  EXPECT_EQ(sceneToJson(again->doc), sceneToJson(r->doc));
  EXPECT_EQ(again->doc.room.materials.at("wall_left").reflectance, Vec3(0.8, 0.85, 0.9));
}

// "objects[].name" and "objects[].hidden", and the meshes Assimp reads (FBX, COLLADA, 3DS).
TEST(SceneFile, ObjectNameHiddenAndAssimpMeshes) {
  const fs::path dir = sceneDir("object_name_hidden");
  for (const char* f : {"chair.fbx", "lamp.dae", "vase.3ds"}) std::ofstream(dir / f) << "x";
  auto r = parseSceneJson(
      R"({"format": "inlay-scene", "version": 1, "photo": "room.jpg", "objects": [
            {"mesh": "chair.fbx", "base_px": [10, 20], "name": "armchair", "hidden": true},
            {"mesh": "lamp.dae", "base_px": [30, 40]},
            {"mesh": "vase.3ds", "base_px": [50, 60], "hidden": false}]})",
      dir.string(), "scene.json");
  ASSERT_TRUE(r.ok()) << r.error().message();
  ASSERT_EQ(r->doc.objects.size(), 3u);
  EXPECT_EQ(r->doc.objects[0].name, "armchair");
  EXPECT_TRUE(r->doc.objects[0].hidden);
  EXPECT_EQ(r->doc.objects[1].name, "");
  EXPECT_FALSE(r->doc.objects[1].hidden);
  const std::string text = sceneToJson(r->doc);
  EXPECT_NE(text.find("\"hidden\": true"), std::string::npos);
  EXPECT_EQ(text.find("\"hidden\": false"), std::string::npos);  // the default is not written
  auto again = parseSceneJson(text, dir.string(), "scene.json");
  ASSERT_TRUE(again.ok()) << again.error().message();
  EXPECT_EQ(sceneToJson(again->doc), text);
  // A hidden key that is not a boolean is refused with its key.
  auto bad = parseSceneJson(
      R"({"format": "inlay-scene", "version": 1, "photo": "room.jpg", "objects": [
            {"mesh": "chair.fbx", "base_px": [10, 20], "hidden": "yes"}]})",
      dir.string(), "scene.json");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message().find("objects[0].hidden"), std::string::npos) << bad.error().message();
  auto obj = parseSceneJson(
      R"({"format": "inlay-scene", "version": 1, "photo": "room.jpg", "objects": [
            {"mesh": "chair.blend", "base_px": [10, 20]}]})",
      dir.string(), "scene.json");
  ASSERT_FALSE(obj.ok());
  EXPECT_NE(obj.error().message().find(".fbx, .dae or .3ds"), std::string::npos)
      << obj.error().message();
}

TEST(SceneFile, VanishingLinesParseAndRoundTrip) {
  const fs::path dir = sceneDir("vanishing_lines");
  auto r = parseSceneJson(
      R"({"format": "inlay-scene", "version": 1, "photo": "room.jpg", "camera": {
            "vanishing_lines_px": {"z": [[[10, 300], [200, 200]], [[10, 20], [200, 120.5]]],
                                   "x": [[[0, 0], [100, 1]], [[0, 50], [100, 52]]]}}})",
      dir.string(), "scene.json");
  ASSERT_TRUE(r.ok()) << r.error().message();
  EXPECT_TRUE(r->warnings.empty());
  const auto& l = r->doc.camera.vanishingLinesPx;
  ASSERT_TRUE(l[0] && l[2]);
  EXPECT_FALSE(l[1]);
  EXPECT_EQ((*l[2])[3], Vec2(200, 120.5));
  EXPECT_EQ((*l[0])[1], Vec2(100, 1));
  auto again = parseSceneJson(sceneToJson(r->doc), dir.string(), "scene.json");
  ASSERT_TRUE(again.ok()) << again.error().message();
  EXPECT_EQ(sceneToJson(again->doc), sceneToJson(r->doc));
  EXPECT_EQ(again->doc.camera.vanishingLinesPx, l);
}

// A scene whose camera has `key` set to the JSON `value`.
Expected<SceneLoadResult> parseCameraKey(const fs::path& dir, const std::string& key,
                                         const std::string& value) {
  return parseSceneJson(R"({"format": "inlay-scene", "version": 1, "photo": "room.jpg", "camera": {")" +
                            key + "\": " + value + "}}",
                        dir.string(), "scene.json");
}

TEST(SceneFile, CameraResponseParsesAndRoundTrips) {
  const fs::path dir = sceneDir("response");
  auto parse = [&](const std::string& response) { return parseCameraKey(dir, "response", response); };
  auto missing = parseSceneJson(R"({"format": "inlay-scene", "version": 1, "photo": "room.jpg"})",
                                dir.string(), "scene.json");
  ASSERT_TRUE(missing.ok());
  EXPECT_EQ(missing->doc.camera.response.mode, ResponseKeys::Mode::Auto);
  EXPECT_EQ(sceneToJson(missing->doc).find("response"), std::string::npos);  // auto is not written
  const std::pair<const char*, ResponseKeys::Mode> modes[] = {
      {R"("auto")", ResponseKeys::Mode::Auto},
      {R"("srgb")", ResponseKeys::Mode::Srgb},
      {R"("linear")", ResponseKeys::Mode::Linear},
      {R"({"family": "linear"})", ResponseKeys::Mode::Linear},
      {R"({"family": "toe_shoulder", "power": 0.8, "toe": 0.25, "shoulder": 40})",
       ResponseKeys::Mode::ToeShoulder}};
  for (const auto& [text, mode] : modes) {
    auto r = parse(text);
    ASSERT_TRUE(r.ok()) << text << ": " << r.error().message();
    EXPECT_TRUE(r->warnings.empty()) << text;
    EXPECT_EQ(r->doc.camera.response.mode, mode) << text;
    auto again = parseSceneJson(sceneToJson(r->doc), dir.string(), "scene.json");
    ASSERT_TRUE(again.ok()) << again.error().message();
    EXPECT_EQ(again->doc.camera.response, r->doc.camera.response) << text;
  }
  auto explicitCurve = parse(R"({"family": "toe_shoulder", "power": 0.8, "toe": 0.25, "shoulder": 40})");
  ASSERT_TRUE(explicitCurve.ok());
  EXPECT_EQ(explicitCurve->doc.camera.response.power, 0.8);
  EXPECT_EQ(explicitCurve->doc.camera.response.toe, 0.25);
  EXPECT_EQ(explicitCurve->doc.camera.response.shoulder, 40);
  auto defaults = parse(R"({"family": "toe_shoulder"})");  // sRGB's parameters
  ASSERT_TRUE(defaults.ok());
  EXPECT_EQ(defaults->doc.camera.response.power, 1.0);
  EXPECT_EQ(defaults->doc.camera.response.shoulder, 0.0);
}

TEST(SceneFile, BadCameraResponseNamesItsKey) {
  const fs::path dir = sceneDir("bad_response");
  const std::pair<const char*, const char*> cases[] = {
      {R"("gamma")", "camera.response"},
      {R"(2.2)", "camera.response"},
      {R"(null)", "camera.response"},
      {R"({"power": 1})", "camera.response.family"},
      {R"({"family": "filmic"})", "camera.response.family"},
      {R"({"family": 3})", "camera.response.family"},
      {R"({"family": "toe_shoulder", "power": 0})", "camera.response.power"},
      {R"({"family": "toe_shoulder", "power": "1"})", "camera.response.power"},
      {R"({"family": "toe_shoulder", "toe": -0.1})", "camera.response.toe"},
      {R"({"family": "toe_shoulder", "shoulder": 1e9})", "camera.response.shoulder"},
      {R"({"family": "srgb", "power": 1})", "camera.response.power"}};
  for (const auto& [text, key] : cases) {
    auto r = parseCameraKey(dir, "response", text);
    ASSERT_FALSE(r.ok()) << text;
    EXPECT_EQ(r.error().key, key) << text << ": " << r.error().message();
  }
}

// camera.vignetting: "none" (the default, not written back), "auto" or a strength in [0, 0.9].
TEST(SceneFile, CameraVignettingParsesAndRoundTrips) {
  const fs::path dir = sceneDir("vignetting");
  auto parse = [&](const std::string& v) { return parseCameraKey(dir, "vignetting", v); };
  const auto missing = parseCameraKey(dir, "height_m", "1.5");  // a camera without the key
  ASSERT_TRUE(missing.ok()) << missing.error().message();
  EXPECT_EQ(missing->doc.camera.vignetting.mode, VignettingKeys::Mode::None);
  EXPECT_EQ(sceneToJson(missing->doc).find("vignetting"), std::string::npos);  // none is not written
  const std::tuple<const char*, VignettingKeys::Mode, double> cases[] = {
      {R"("auto")", VignettingKeys::Mode::Auto, 0.0},
      {R"("none")", VignettingKeys::Mode::None, 0.0},
      {"0", VignettingKeys::Mode::Given, 0.0},
      {"0.25", VignettingKeys::Mode::Given, 0.25},
      {"0.9", VignettingKeys::Mode::Given, 0.9}};
  for (const auto& [text, mode, v] : cases) {
    auto r = parse(text);
    ASSERT_TRUE(r.ok()) << text << ": " << r.error().message();
    EXPECT_EQ(r->doc.camera.vignetting.mode, mode) << text;
    EXPECT_EQ(r->doc.camera.vignetting.v, v) << text;
    auto again = parseSceneJson(sceneToJson(r->doc), dir.string(), "scene.json");
    ASSERT_TRUE(again.ok()) << again.error().message();
    EXPECT_EQ(again->doc.camera.vignetting, r->doc.camera.vignetting) << text;
  }
}

TEST(SceneFile, BadCameraVignettingNamesItsKeyAndRange) {
  const fs::path dir = sceneDir("bad_vignetting");
  const std::pair<const char*, const char*> cases[] = {{R"("strong")", "unknown vignetting 'strong'"},
                                                       {"-0.1", "must be in [0, 0.9]"},
                                                       {"0.95", "must be in [0, 0.9]"},
                                                       {"1e308", "must be in [0, 0.9]"},
                                                       {"null", "got null"},
                                                       {"[0.2]", "got an array"},
                                                       {"true", "got a boolean"},
                                                       {R"({"v": 0.2})", "got an object"}};
  for (const auto& [text, reason] : cases) {
    auto r = parseCameraKey(dir, "vignetting", text);
    ASSERT_FALSE(r.ok()) << text;
    EXPECT_EQ(r.error().key, "camera.vignetting") << text;
    EXPECT_NE(r.error().message().find(reason), std::string::npos)
        << text << ": " << r.error().message();
  }
}

TEST(SceneFile, SaveRefusesWhatCouldNotBeReadBack) {
  const fs::path dir = sceneDir("save_refuses");
  writeText(dir / "scene.json", kFullScene);
  auto r = loadSceneFile((dir / "scene.json").string());
  ASSERT_TRUE(r.ok()) << r.error().message();
  const std::string before = sceneToJson(r->doc);
  SceneDoc doc = r->doc;
  doc.objects[1].heightM = std::nan("");
  auto s = saveSceneFile((dir / "scene.json").string(), doc);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().key, "objects[1].height_m");
  doc = r->doc;
  doc.photo = std::string("bad\xff\xfe.jpg");
  s = saveSceneFile((dir / "scene.json").string(), doc);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().reason.find("UTF-8"), std::string::npos);
  EXPECT_FALSE(sceneToJson(doc).empty());  // replaced, not thrown
  // The user's file is untouched.
  auto again = loadSceneFile((dir / "scene.json").string());
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(sceneToJson(again->doc), before);
}

TEST(SceneFile, DuplicateKeysWarn) {
  const fs::path dir = sceneDir("dup");
  auto r = parseSceneJson(
      R"({"format": "inlay-scene", "version": 1, "photo": "room.jpg", "render": {"spp": 4, "spp": 8}})",
      dir.string(), "scene.json");
  ASSERT_TRUE(r.ok()) << r.error().message();
  EXPECT_EQ(r->doc.render.spp, 8);
  ASSERT_EQ(r->warnings.size(), 1u);
  EXPECT_NE(r->warnings[0].find("render.spp"), std::string::npos) << r->warnings[0];
}

TEST(SceneFile, MinimalSceneGetsDefaults) {
  const fs::path dir = sceneDir("minimal");
  auto r = parseSceneJson(R"({"format": "inlay-scene", "version": 1, "photo": "room.jpg"})",
                          dir.string(), "scene.json");
  ASSERT_TRUE(r.ok()) << r.error().message();
  const SceneDoc& d = r->doc;
  EXPECT_FALSE(d.camera.heightM.has_value());  // 1.6 is applied by the consumer
  EXPECT_FALSE(d.camera.focalPx.has_value());
  EXPECT_FALSE(d.camera.vanishingPointsPx.has_value());
  EXPECT_FALSE(d.layout.backWallPx.has_value());
  EXPECT_FALSE(d.layout.rearM.has_value());
  EXPECT_TRUE(d.lights.empty() && d.objects.empty() && d.shafts.empty());
  EXPECT_EQ(d.render.spp, 256);
  EXPECT_EQ(d.render.noise, 0.004);
  EXPECT_EQ(d.render.seed, 1u);
  EXPECT_EQ(d.render.exposure, 0.0);
  EXPECT_TRUE(d.render.grain);  // on by default
  EXPECT_FALSE(d.render.seconds.has_value());
  // Minimal round trip too.
  auto again = parseSceneJson(sceneToJson(d), dir.string(), "scene.json");
  ASSERT_TRUE(again.ok()) << again.error().message();
  expectDocsEqual(d, again->doc);
  // An absolute photo path is kept as it is.
  const std::string abs = (dir / "room.jpg").string();
  auto a = parseSceneJson(R"({"format": "inlay-scene", "version": 1, "photo": ")" + abs + R"("})",
                          "/nonexistent", "scene.json");
  ASSERT_TRUE(a.ok()) << a.error().message();
  EXPECT_EQ(a->doc.photoResolved, abs);
}

TEST(SceneFile, UnknownKeysAreWarningsNotErrors) {
  const fs::path dir = sceneDir("unknown");
  auto r = parseSceneJson(R"({"format": "inlay-scene", "version": 1, "photo": "room.jpg",
      "foo": 3, "camera": {"bar": true},
      "objects": [{"mesh": "builtin:cube", "base_px": [1, 2], "colour": "red"}]})",
                          dir.string(), "scene.json");
  ASSERT_TRUE(r.ok()) << r.error().message();
  const auto& w = r->warnings;
  ASSERT_EQ(w.size(), 3u);
  EXPECT_NE(std::find(w.begin(), w.end(), "scene.json: unknown key 'foo' ignored"), w.end());
  EXPECT_NE(std::find(w.begin(), w.end(), "scene.json: unknown key 'camera.bar' ignored"), w.end());
  EXPECT_NE(std::find(w.begin(), w.end(), "scene.json: unknown key 'objects[0].colour' ignored"),
            w.end());
}

struct BadCase {
  const char* name;
  std::string body;        // keys after format/version/photo (with a leading comma)
  std::string key;         // expected Error::key
  std::string reasonPart;  // expected substring of Error::reason
};

std::string withHeader(const std::string& body) {
  return R"({"format": "inlay-scene", "version": 1, "photo": "room.jpg")" + body + "}";
}
const std::string kPolygon = R"("kind": "polygon_px", "points": [[0,0],[10,0],[10,10],[0,10]])";
const std::string kSphere = R"({"mesh": "builtin:sphere", "base_px": [1, 2]})";

class SceneFileBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(SceneFileBadInput, NamesTheKeyAndTheReason) {
  const BadCase& c = GetParam();
  const fs::path dir = sceneDir("bad");
  auto r = parseSceneJson(withHeader(c.body), dir.string(), "scene.json");
  ASSERT_FALSE(r.ok()) << c.name;
  EXPECT_EQ(r.error().file, "scene.json") << c.name;
  EXPECT_EQ(r.error().key, c.key) << c.name << ": " << r.error().message();
  EXPECT_NE(r.error().reason.find(c.reasonPart), std::string::npos)
      << c.name << ": " << r.error().message();
  EXPECT_NE(r.error().message().find(c.key), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(
    AllKeys, SceneFileBadInput,
    ::testing::Values(
        BadCase{"camera_nan_string", R"(, "camera": {"focal_px": "NaN"})", "camera.focal_px",
                "expected a number"},
        BadCase{"camera_overflow", R"(, "camera": {"height_m": 1e999})", "camera.height_m",
                "out of range"},
        BadCase{"camera_height_zero", R"(, "camera": {"height_m": 0})", "camera.height_m", "> 0"},
        BadCase{"vp_count", R"(, "camera": {"vanishing_points_px": [[1,2],[3,4]]})",
                "camera.vanishing_points_px", "expected 3 elements"},
        BadCase{"vp_type", R"(, "camera": {"vanishing_points_px": [[1,2],[3,4],[5,null]]})",
                "camera.vanishing_points_px[2][1]", "expected a number, got null"},
        BadCase{"vlines_nan",
                R"(, "camera": {"vanishing_lines_px": {"z": [[[0,0],[9,"NaN"]], [[0,5],[9,9]]]}})",
                "camera.vanishing_lines_px.z[0][1][1]", "expected a number"},
        BadCase{"vlines_overflow",
                R"(, "camera": {"vanishing_lines_px": {"y": [[[0,0],[9,9]], [[1e999,5],[9,9]]]}})",
                "camera.vanishing_lines_px.y[1][0][0]", "out of range"},
        BadCase{"vlines_degenerate",
                R"(, "camera": {"vanishing_lines_px": {"z": [[[0,0],[90,9]], [[5,5],[5.5,5]]]}})",
                "camera.vanishing_lines_px.z[1]", "degenerate segment"},
        BadCase{"vlines_one_line",
                R"(, "camera": {"vanishing_lines_px": {"x": [[[0,0],[10,10]], [[20,20],[30,30]]]}})",
                "camera.vanishing_lines_px.x", "lie on one line"},
        BadCase{"vlines_count", R"(, "camera": {"vanishing_lines_px": {"x": [[[0,0],[10,10]]]}})",
                "camera.vanishing_lines_px.x", "expected 2 elements"},
        BadCase{"vlines_type", R"(, "camera": {"vanishing_lines_px": [1, 2]})",
                "camera.vanishing_lines_px", "expected an object"},
        BadCase{"principal_type", R"(, "camera": {"principal_px": "centre"})", "camera.principal_px",
                "expected an array"},
        BadCase{"back_wall", R"(, "layout": {"back_wall_px": [[1,2],[3,4],[5,6]]})",
                "layout.back_wall_px", "expected 4 elements"},
        BadCase{"rear_zero", R"(, "layout": {"rear_m": 0})", "layout.rear_m", "must be > 0"},
        BadCase{"rear_negative", R"(, "layout": {"rear_m": -0.5})", "layout.rear_m", "must be > 0"},
        BadCase{"rear_huge", R"(, "layout": {"rear_m": 1000})", "layout.rear_m", "at most 100 m"},
        BadCase{"rear_type", R"(, "layout": {"rear_m": "far"})", "layout.rear_m", "expected a number"},
        BadCase{"lights_not_array", R"(, "lights": {})", "lights", "expected an array"},
        BadCase{"light_kind", R"(, "lights": [{"kind": "spot"}])", "lights[0].kind",
                "unknown light kind"},
        BadCase{"light_bowtie",
                R"(, "lights": [{"kind": "polygon_px", "points": [[0,0],[10,10],[10,0],[0,10]]}])",
                "lights[0].points", "self-intersecting"},
        BadCase{"light_zero_area",
                R"(, "lights": [{"kind": "polygon_px", "points": [[0,0],[5,5],[10,10]]}])",
                "lights[0].points", "zero area"},
        BadCase{"light_two_points", R"(, "lights": [{"kind": "polygon_px", "points": [[0,0],[5,5]]}])",
                "lights[0].points", "at least 3 points"},
        BadCase{"light_second_bad",
                ", \"lights\": [{" + kPolygon +
                    R"(}, {"kind": "polygon_px", "points": [[0,0],[1,1],[1,"x"]]}])",
                "lights[1].points[2][1]", "expected a number"},
        BadCase{"rect_corner_size",
                R"(, "lights": [{"kind": "rect_m", "corners": [[0,0,0],[1,0],[1,0,1],[0,0,1]]}])",
                "lights[0].corners[1]", "expected 3 elements"},
        BadCase{"rect_three_corners",
                R"(, "lights": [{"kind": "rect_m", "corners": [[0,0,0],[1,0,0],[1,0,1]]}])",
                "lights[0].corners", "expected 4 elements"},
        BadCase{"rect_degenerate",
                R"(, "lights": [{"kind": "rect_m", "corners": [[0,0,0],[0,0,0],[0,0,0],[0,0,0]]}])",
                "lights[0].corners", "zero area"},
        BadCase{"light_refine_type", ", \"lights\": [{" + kPolygon + R"(, "refine": "yes"}])",
                "lights[0].refine", "expected true or false"},
        BadCase{"light_lock_type", ", \"lights\": [{" + kPolygon + R"(, "lock": 1}])", "lights[0].lock",
                "expected true or false"},
        BadCase{"light_weight_negative",
                ", \"lights\": [{" + kPolygon + R"(, "weights": {"position": -1}}])",
                "lights[0].weights.position", ">= 0"},
        BadCase{"light_size_weight_negative",
                ", \"lights\": [{" + kPolygon + R"(, "weights": {"size": -2}}])",
                "lights[0].weights.size", ">= 0"},
        BadCase{"light_refine_size_not_bool", ", \"lights\": [{" + kPolygon + R"(, "refine_size": 1}])",
                "lights[0].refine_size", "expected true or false"},
        BadCase{"light_weight_nan",
                ", \"lights\": [{" + kPolygon + R"(, "weights": {"intensity": "a"}}])",
                "lights[0].weights.intensity", "expected a number"},
        BadCase{"light_weights_not_object", ", \"lights\": [{" + kPolygon + R"(, "weights": [1, 2]}])",
                "lights[0].weights", "object"},
        BadCase{"light_rgb_negative", ", \"lights\": [{" + kPolygon + R"(, "rgb": [1, -1, 1]}])",
                "lights[0].rgb[1]", ">= 0"},
        BadCase{"shaft_no_direction", R"(, "shafts": [{"shaft_box_px": [0, 0, 10, 10]}])",
                "shafts[0].direction", "required"},
        BadCase{"shaft_box_order",
                R"(, "shafts": [{"shaft_box_px": [10, 0, 0, 10], "source_box_px": [0,0,1,1]}])",
                "shafts[0].shaft_box_px", "x0 < x1"},
        BadCase{"shaft_zero_direction", R"(, "shafts": [{"direction": [0, 0, 0]}])",
                "shafts[0].direction", "non-zero"},
        BadCase{
            "surface_bowtie",
            R"(, "surfaces": [{"kind": "extrusion", "outline_px": [[0,0],[10,10],[10,0],[0,10]], "height_click_px": [0, 20]}])",
            "surfaces[0].outline_px", "self-intersecting"},
        BadCase{
            "surface_fold_back",
            R"(, "surfaces": [{"outline_px": [[0,0],[10,0],[5,0],[5,5]], "height_click_px": [0, 20]}])",
            "surfaces[0].outline_px", "self-intersecting"},
        BadCase{
            "surface_kind",
            R"(, "surfaces": [{"kind": "ramp", "outline_px": [[0,0],[1,0],[1,1]], "height_click_px": [0, 2]}])",
            "surfaces[0].kind", "unknown surface kind"},
        BadCase{"surface_no_click", R"(, "surfaces": [{"outline_px": [[0,0],[10,0],[10,10]]}])",
                "surfaces[0].height_click_px", "missing"},
        BadCase{"occluder_scribble", R"(, "occluders": [{"foreground_scribbles_px": [[]]}])",
                "occluders[0].foreground_scribbles_px[0]", "at least 1"},
        BadCase{"height_zero",
                ", \"objects\": [" + kSphere +
                    R"(, {"mesh": "builtin:cube", "base_px": [1, 2], "height_m": 0}])",
                "objects[1].height_m", "> 0"},
        BadCase{"height_negative",
                R"(, "objects": [{"mesh": "builtin:cube", "base_px": [1, 2], "height_m": -2}])",
                "objects[0].height_m", "> 0"},
        BadCase{"height_overflow",
                R"(, "objects": [{"mesh": "builtin:cube", "base_px": [1, 2], "height_m": -1e999}])",
                "objects[0].height_m", "out of range"},
        BadCase{"mesh_missing_file", R"(, "objects": [{"mesh": "models/nope.obj", "base_px": [1, 2]}])",
                "objects[0].mesh", "file not found"},
        BadCase{"mesh_unknown_builtin", R"(, "objects": [{"mesh": "builtin:torus", "base_px": [1, 2]}])",
                "objects[0].mesh", "unknown builtin"},
        BadCase{"mesh_format", R"(, "objects": [{"mesh": "models/chair.stl", "base_px": [1, 2]}])",
                "objects[0].mesh", "unsupported mesh format"},
        BadCase{"mesh_absent", R"(, "objects": [{"base_px": [1, 2]}])", "objects[0].mesh", "missing"},
        BadCase{"base_missing", R"(, "objects": [{"mesh": "builtin:cube"}])", "objects[0].base_px",
                "missing"},
        BadCase{
            "preset",
            R"(, "objects": [{"mesh": "builtin:cube", "base_px": [1, 2], "material": {"preset": "velvet"}}])",
            "objects[0].material.preset", "unknown material preset"},
        BadCase{
            "albedo_range",
            R"(, "objects": [{"mesh": "builtin:cube", "base_px": [1, 2], "material": {"albedo": [0.5, 1.5, 0.5]}}])",
            "objects[0].material.albedo[1]", "[0, 1]"},
        BadCase{
            "ior_range",
            R"(, "objects": [{"mesh": "builtin:cube", "base_px": [1, 2], "material": {"preset": "glass", "ior": 0.5}}])",
            "objects[0].material.ior", "[1, 5]"},
        BadCase{"subdivide_fraction",
                R"(, "objects": [{"mesh": "builtin:cube", "base_px": [1, 2], "subdivide": 1.5}])",
                "objects[0].subdivide", "[0, 5]"},
        BadCase{"subdivide_too_many",
                R"(, "objects": [{"mesh": "builtin:cube", "base_px": [1, 2], "subdivide": 9}])",
                "objects[0].subdivide", "[0, 5]"},
        BadCase{"room_surface_name", R"(, "room": {"materials": {"flor": {"preset": "mirror"}}})",
                "room.materials.flor", "unknown room surface"},
        BadCase{"room_preset", R"(, "room": {"materials": {"floor": {"preset": "glass"}}})",
                "room.materials.floor.preset", "unknown room material preset"},
        BadCase{"room_roughness", R"(, "room": {"materials": {"wall_left": {"roughness": 2}}})",
                "room.materials.wall_left.roughness", "[0, 1]"},
        BadCase{"room_materials_type", R"(, "room": {"materials": [1]})", "room.materials", "object"},
        BadCase{"spp_negative", R"(, "render": {"spp": -4})", "render.spp", ">= 1"},
        BadCase{"spp_fraction", R"(, "render": {"spp": 2.5})", "render.spp", "integer"},
        BadCase{"noise_negative", R"(, "render": {"noise": -0.01})", "render.noise", "[0, 1)"},
        BadCase{"noise_string", R"(, "render": {"noise": "low"})", "render.noise", "number"},
        BadCase{"seconds_negative", R"(, "render": {"seconds": -1})", "render.seconds", "> 0"},
        BadCase{"seed_string", R"(, "render": {"seed": "abc"})", "render.seed", "integer"},
        BadCase{"grain_string", R"(, "render": {"grain": "yes"})", "render.grain",
                "expected true or false, got a string"},
        BadCase{"grain_number", R"(, "render": {"grain": 1})", "render.grain", "expected true or false"},
        BadCase{"clamp_negative", R"(, "render": {"clamp_indirect": -1})", "render.clamp_indirect",
                "times white"},
        BadCase{"clamp_string", R"(, "render": {"clamp_indirect": "high"})", "render.clamp_indirect",
                "\"off\""},
        BadCase{"clamp_nan", R"(, "render": {"clamp_indirect": NaN})", "render.clamp_indirect", ""},
        BadCase{"clamp_infinite", R"(, "render": {"clamp_indirect": 1e999})", "render.clamp_indirect",
                "out of range"},
        BadCase{"clamp_bool", R"(, "render": {"clamp_indirect": true})", "render.clamp_indirect",
                "times white"},
        BadCase{"exposure_bool", R"(, "render": {"exposure": true})", "render.exposure",
                "expected a number, got a boolean"},
        BadCase{"invalid_json", R"(, "render": {"spp": 4,}})", "render", "invalid JSON"}),
    [](const ::testing::TestParamInfo<BadCase>& p) { return std::string(p.param.name); });

TEST(SceneFile, HeaderErrors) {
  const fs::path dir = sceneDir("header");
  auto parse = [&](const std::string& text) { return parseSceneJson(text, dir.string(), "scene.json"); };
  auto e = parse(R"({"format": "inlay-scene", "version": 1})");
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.error().key, "photo");
  e = parse(R"({"format": "inlay-scene", "version": 1, "photo": "missing.jpg"})");
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.error().key, "photo");
  EXPECT_NE(e.error().reason.find("not found"), std::string::npos);
  e = parse(R"({"format": "other", "version": 1, "photo": "room.jpg"})");
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.error().key, "format");
  e = parse(R"({"version": 1, "photo": "room.jpg"})");
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.error().key, "format");
  e = parse(R"({"format": "inlay-scene", "version": 2, "photo": "room.jpg"})");
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.error().key, "version");
  EXPECT_NE(e.error().reason.find("unsupported version 2"), std::string::npos);
  e = parse(R"([1, 2, 3])");
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error().reason.find("expected an object"), std::string::npos);
  e = parse("");
  ASSERT_FALSE(e.ok());
  e = parse("{\"format\": \"inlay-scene\", \"version\": 1, \"photo\": \"room.jpg\"");  // cut short
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error().reason.find("invalid JSON"), std::string::npos);
  auto missing = loadSceneFile((dir / "nope.json").string());
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.error().file, (dir / "nope.json").string());
}

TEST(SceneFile, LimitsAreEnforcedWithoutDeepRecursion) {
  const fs::path dir = sceneDir("limits");
  // 200,000 nested arrays under an unknown key: refused by depth, quickly, without recursion.
  const std::string deep =
      withHeader(", \"junk\": " + std::string(200000, '[') + std::string(200000, ']'));
  const auto t0 = std::chrono::steady_clock::now();
  auto r = parseSceneJson(deep, dir.string(), "scene.json");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 2.0);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().reason.find("nesting"), std::string::npos) << r.error().message();
  EXPECT_EQ(r.error().key.rfind("junk", 0), 0u) << r.error().key;

  SceneLimits small;
  small.maxObjects = 2;
  r = parseSceneJson(withHeader(", \"objects\": [" + kSphere + "," + kSphere + "," + kSphere + "]"),
                     dir.string(), "scene.json", small);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().key, "objects");
  EXPECT_NE(r.error().reason.find("limit"), std::string::npos);

  SceneLimits tiny;
  tiny.maxFileBytes = 20;
  r = parseSceneJson(withHeader(""), dir.string(), "scene.json", tiny);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().reason.find("exceeds"), std::string::npos);
  writeText(dir / "big.json", withHeader(""));
  r = loadSceneFile((dir / "big.json").string(), tiny);
  ASSERT_FALSE(r.ok());

  SceneLimits fewPoints;
  fewPoints.maxPointsPerPolyline = 3;
  r = parseSceneJson(withHeader(", \"lights\": [{" + kPolygon + "}]"), dir.string(), "scene.json",
                     fewPoints);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().key, "lights[0].points");
}

TEST(SceneFile, RelativePathsResolveAgainstTheSceneFolder) {
  const fs::path dir = sceneDir("relative");
  writeText(dir / "sub" / "scene.json",
            withHeader(R"(, "objects": [{"mesh": "../models/chair.obj", "base_px": [1, 2]}])"));
  // The photo is one level up from the scene: "room.jpg" alone must not be found.
  auto r = loadSceneFile((dir / "sub" / "scene.json").string());
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().key, "photo");
  writeText(dir / "sub" / "scene.json",
            R"({"format": "inlay-scene", "version": 1, "photo": "../room.jpg",
                "objects": [{"mesh": "../models/chair.obj", "base_px": [1, 2]}]})");
  r = loadSceneFile((dir / "sub" / "scene.json").string());
  ASSERT_TRUE(r.ok()) << r.error().message();
  EXPECT_EQ(fs::path(r->doc.objects[0].meshResolved), (dir / "models" / "chair.obj").lexically_normal());
  EXPECT_EQ(r->doc.objects[0].mesh, "../models/chair.obj");  // written back as given
  EXPECT_NE(sceneToJson(r->doc).find("\"../models/chair.obj\""), std::string::npos);
}

TEST(SceneFile, OutlineChecksAcceptValidShapes) {
  const fs::path dir = sceneDir("shapes");
  // A concave L-shaped table top and a clockwise triangle are fine.
  auto r = parseSceneJson(
      withHeader(
          R"(, "surfaces": [{"outline_px": [[0,0],[20,0],[20,10],[10,10],[10,20],[0,20]], "height_click_px": [0, 30]}],
                    "lights": [{"kind": "polygon_px", "points": [[0,0],[0,10],[10,0]]}])"),
      dir.string(), "scene.json");
  ASSERT_TRUE(r.ok()) << r.error().message();
  EXPECT_EQ(r->doc.surfaces[0].outlinePx.size(), 6u);
  // Touching itself at a vertex is a self-intersection.
  r = parseSceneJson(
      withHeader(
          R"(, "lights": [{"kind": "polygon_px", "points": [[0,0],[10,0],[5,5],[10,10],[0,10],[5,5]]}])"),
      dir.string(), "scene.json");
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().key.rfind("lights[0].points", 0), 0u);
}

}  // namespace
}  // namespace inlay
