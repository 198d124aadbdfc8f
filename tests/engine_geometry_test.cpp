// The engine builds the scene file's extra geometry (stairs, boxes, occluder cards) on the
// bundled example; bad occluder input is refused with its key and leaves nothing built.
#include "inlay/engine/pipeline.h"
#include "test_support.h"

#include <cmath>

namespace inlay {
namespace {

SceneDoc exampleDoc() {
  auto loaded = loadSceneFile(std::string(INLAY_SOURCE_DIR) + "/resources/example/scene.json");
  EXPECT_TRUE(loaded.ok()) << (loaded.ok() ? "" : loaded.error().message());
  return loaded->doc;
}

TEST(EngineGeometry, StairsAndAnOccluderCardFromTheSceneFile) {
  SceneDoc doc = exampleDoc();
  SurfaceKeys stairs;
  stairs.kind = "stairs";
  stairs.basePx = Vec2(150, 330);
  stairs.steps = 3;
  stairs.riseM = 0.2;
  stairs.runM = 0.3;
  stairs.widthM = 0.8;
  stairs.climbAxis = "-z";
  doc.surfaces = {stairs};
  OccluderKeys occ;
  occ.foregroundScribblesPx = {{{300, 300}, {330, 300}}};
  occ.backgroundScribblesPx = {{{270, 270}, {360, 270}, {360, 340}, {270, 340}, {270, 270}}};
  doc.occluders = {occ};
  auto ps = prepareScene(doc);
  ASSERT_TRUE(ps.ok()) << ps.error().message();
  int cards = 0, treads = 0;
  for (const Surface& s : ps->geometry.surfaces) {
    if (s.kind == SurfaceKind::OccluderCard) {
      ++cards;
      ASSERT_TRUE(s.cardAlpha);
      EXPECT_EQ(s.cardAlpha->alphaPx.width, ps->photo.linearRgb.width);
    }
    if (s.kind == SurfaceKind::ExtrusionTop) treads += int(s.meshWorld.triangles.size()) / 2;
  }
  EXPECT_EQ(cards, 1);
  EXPECT_EQ(treads, 3);
  // The renderer gets the same geometry; an object placed on the second step (0.4 m, its tread
  // 0.3 to 0.6 m behind the front edge) stands on it.
  EXPECT_EQ(ps->renderScene.room.surfaces.size(), ps->geometry.surfaces.size());
  ASSERT_FALSE(ps->extrusions.empty());
  const auto floorHit = ps->geometry.intersect(ps->camera.rayThroughPixel(stairs.basePx), true);
  ASSERT_TRUE(floorHit.has_value());
  const Vec3 tread2 = floorHit->pointWorld + Vec3(0, 0.4, -0.45);
  const auto px = ps->camera.project(tread2);
  ASSERT_TRUE(px.has_value());
  ASSERT_FALSE(ps->doc.objects.empty());
  PreparedScene moved = *ps;
  moved.doc.objects[0].basePx = *px;
  const auto placed = placeObjectAt(moved, 0);
  ASSERT_TRUE(placed.ok()) << placed.error().message();
  EXPECT_NEAR(placed->baseWorld.y(), 0.4, 1e-4);
}

// The unseen rear wall: by default 0.5 m behind the camera, pushed back behind a light the user
// placed in 3D behind the camera (so the wall does not hide it); layout.rear_m sets it.
TEST(EngineGeometry, TheRearWallEnclosesALightPlacedBehindTheCamera) {
  PrepareOptions fast;
  fast.refineLights = false;
  fast.workingMaxPixels = 40'000;
  SceneDoc doc = exampleDoc();
  const double y = 2.2;  // under the example's ceiling
  LightKeys behind;
  behind.kind = LightKeys::Kind::RectM;
  behind.cornersM = {Vec3(-0.3, y, 0.6), Vec3(0.3, y, 0.6), Vec3(0.3, y, 1.2), Vec3(-0.3, y, 1.2)};
  behind.rgb = Vec3(3, 3, 3);
  behind.refine = false;
  doc.lights.push_back(behind);
  auto enclosed = prepareScene(doc, fast);
  ASSERT_TRUE(enclosed.ok()) << enclosed.error().message();
  EXPECT_NEAR(enclosed->box.zRearM, 1.25, 1e-9);
  bool rearWallThere = false;
  for (const Surface& s : enclosed->geometry.surfaces)
    if (s.kind == SurfaceKind::WallRear)
      rearWallThere = std::abs(double(s.meshWorld.positions.front().z()) - 1.25) < 1e-5;
  EXPECT_TRUE(rearWallThere);
  // The user's distance wins, even in front of the light.
  doc.layout.rearM = 0.9;
  auto given = prepareScene(doc, fast);
  ASSERT_TRUE(given.ok()) << given.error().message();
  EXPECT_DOUBLE_EQ(given->box.zRearM, 0.9);
}

TEST(EngineGeometry, BadOccluderAndSurfaceInputNamesTheKey) {
  SceneDoc doc = exampleDoc();
  OccluderKeys occ;
  occ.backgroundScribblesPx = {{{270, 270}, {360, 270}}};
  doc.occluders = {occ};
  auto ps = prepareScene(doc);
  ASSERT_FALSE(ps.ok());
  EXPECT_NE(ps.error().message().find("occluders[0].foreground_scribbles_px"), std::string::npos)
      << ps.error().message();
  doc = exampleDoc();
  SurfaceKeys bow;
  bow.outlinePx = {{100, 300}, {200, 340}, {200, 300}, {100, 340}};
  bow.heightClickPx = Vec2(100, 360);
  doc.surfaces = {bow};
  ps = prepareScene(doc);
  ASSERT_FALSE(ps.ok());
  EXPECT_NE(ps.error().message().find("surfaces[0].outline_px"), std::string::npos)
      << ps.error().message();
}

}  // namespace
}  // namespace inlay
