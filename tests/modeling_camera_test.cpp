// Camera from vanishing points and the box room, against the ground-truth rooms in
// ../shared/scenes and against synthetic cameras (vanishing points at infinity, rolled).
#include "inlay/modeling/camera.h"
#include "inlay/modeling/geometry.h"
#include "test_support.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <filesystem>
#include <fstream>

namespace inlay {
namespace {

using nlohmann::json;

json readJson(const std::filesystem::path& p) {
  std::ifstream f(p);
  return json::parse(f);
}

double angleDeg(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
}

// Far vanishing points as the harness writes them: a huge coordinate along the direction.
Vec2 vpOf(const json& v, const Vec2& principal) {
  if (v["finite"].get<bool>()) return {v["pixel"][0].get<double>(), v["pixel"][1].get<double>()};
  return principal +
         1e7 * Vec2(v["image_direction"][0].get<double>(), v["image_direction"][1].get<double>());
}

TEST(Camera, MatchesGroundTruthOfEverySceneFromVanishingPointsAlone) {
  INLAY_REQUIRE_SHARED();
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::sharedDir() + "/scenes")) {
    if (!std::filesystem::exists(entry.path() / "truth.json")) continue;
    const json t = readJson(entry.path() / "truth.json");
    const json& cam = t["camera"];
    VanishingInput in;
    in.widthPx = t["image"]["width"];
    in.heightPx = t["image"]["height"];
    in.heightM = cam["height_above_floor"];
    const Vec2 pp(cam["principal_point_px"][0].get<double>(),
                  cam["principal_point_px"][1].get<double>());
    const auto& vps = t["vanishing_points"];
    in.vanishingPointsPx = {vpOf(vps["x"], pp), vpOf(vps["y"], pp), vpOf(vps["z"], pp)};
    // No focal length given: it must come from the vanishing points.
    const auto c = cameraFromVanishingPoints(in);
    ASSERT_TRUE(c.ok()) << entry.path() << ": " << c.error().message();
    const double fTrue = cam["focal_px"];
    EXPECT_NEAR(c->focalPx / fTrue, 1.0, 0.01) << entry.path();
    Mat3 rTrue;
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) rTrue(r, k) = cam["R_cam_to_world_opengl"][r][k];
    for (int k = 0; k < 3; ++k)
      EXPECT_LT(angleDeg(c->worldFromCamera.col(k), rTrue.col(k)), 0.2) << entry.path();
    // A world point projected and cast back lands on itself; compare with truth's pixels.
    const Vec3 camPos(cam["position"][0].get<double>(), 0, cam["position"][2].get<double>());
    for (const auto& [name, corner] : t["room"]["corners"].items()) {
      if (corner["pixel"].is_null() || !corner["in_image"].get<bool>()) continue;
      const Vec3 w = Vec3(corner["world"][0], corner["world"][1], corner["world"][2]) - camPos;
      const auto px = c->project(w);
      ASSERT_TRUE(px.has_value()) << name;
      EXPECT_NEAR(px->x(), corner["pixel"][0].get<double>(), 1.5) << name;
      EXPECT_NEAR(px->y(), corner["pixel"][1].get<double>(), 1.5) << name;
      const Ray r = c->rayThroughPixel(*px);
      const double dist = (w - r.origin).cross(r.direction).norm();
      EXPECT_LT(dist, 1e-9) << name;
    }
    ++scenes;
  }
  EXPECT_GE(scenes, 1);
}

TEST(Room, BackWallCornersOfEverySceneGiveTheTrueBox) {
  INLAY_REQUIRE_SHARED();
  for (const auto& entry : std::filesystem::directory_iterator(test::sharedDir() + "/scenes")) {
    if (!std::filesystem::exists(entry.path() / "truth.json")) continue;
    const json t = readJson(entry.path() / "truth.json");
    const json& cam = t["camera"];
    Camera c;
    c.widthPx = t["image"]["width"];
    c.heightPx = t["image"]["height"];
    c.focalPx = cam["focal_px"];
    c.principalPx = {cam["principal_point_px"][0].get<double>(),
                     cam["principal_point_px"][1].get<double>()};
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) c.worldFromCamera(r, k) = cam["R_cam_to_world_opengl"][r][k];
    c.heightM = cam["height_above_floor"];
    const auto& k = t["room"]["corners"];
    auto px = [&](const char* n) {
      return Vec2(k[n]["pixel"][0].get<double>(), k[n]["pixel"][1].get<double>());
    };
    const std::array<Vec2, 4> corners = {px("ceiling_front_left"), px("ceiling_front_right"),
                                         px("floor_front_right"), px("floor_front_left")};
    const auto box = roomFromBackWall(c, corners);
    ASSERT_TRUE(box.ok()) << box.error().message();
    const double cx = cam["position"][0], cz = cam["position"][2];
    EXPECT_NEAR(box->xLeftM, t["world_frame"]["room_extent"]["x"][0].get<double>() - cx, 0.01);
    EXPECT_NEAR(box->xRightM, t["world_frame"]["room_extent"]["x"][1].get<double>() - cx, 0.01);
    EXPECT_NEAR(box->zBackM, t["world_frame"]["room_extent"]["z"][0].get<double>() - cz, 0.01);
    EXPECT_NEAR(box->ceilingM, t["room"]["height"].get<double>(), 0.01);
    const auto back = backWallCornersPx(c, *box);
    for (int i = 0; i < 4; ++i) EXPECT_LT((back[i] - corners[i]).norm(), 1.0);
  }
}

Camera syntheticCamera(double yawDeg, double pitchDeg, double rollDeg, double f) {
  Camera c = levelCamera(640, 480, f, 1.5);
  c.worldFromCamera = (Eigen::AngleAxisd(yawDeg * M_PI / 180, Vec3::UnitY()) *
                       Eigen::AngleAxisd(pitchDeg * M_PI / 180, Vec3::UnitX()) *
                       Eigen::AngleAxisd(rollDeg * M_PI / 180, Vec3::UnitZ()))
                          .toRotationMatrix();
  return c;
}

// Vanishing point of a world axis as a pixel, or a huge coordinate along its image direction.
Vec2 vpPixel(const Camera& c, const Vec3& axis) {
  const Vec3 h = c.vanishingPointOf(axis);
  if (std::abs(h.z()) > 1e-9) return Vec2(h.x() / h.z(), h.y() / h.z());
  return c.principalPx + 1e9 * Vec2(h.x(), h.y()).normalized();
}

TEST(Camera, StableWithVanishingPointsAtInfinityAndRoll) {
  struct Case {
    double yaw, pitch, roll, f;
    bool giveFocal;
  };
  // yaw 0, pitch 0: x and y vanishing points at infinity (frontal wall, level camera).
  for (const Case& k :
       {Case{0, 0, 0, 500, true}, Case{20, -10, 0, 500, false}, Case{-35, 8, 15, 300, false},
        Case{10, -5, -30, 2500, false}, Case{30, -20, 5, 150, false}, Case{0, -15, 0, 600, true}}) {
    const Camera truth = syntheticCamera(k.yaw, k.pitch, k.roll, k.f);
    VanishingInput in;
    in.widthPx = 640;
    in.heightPx = 480;
    in.heightM = 1.5;
    in.vanishingPointsPx = {vpPixel(truth, Vec3::UnitX()), vpPixel(truth, Vec3::UnitY()),
                            vpPixel(truth, Vec3::UnitZ())};
    if (k.giveFocal) in.focalPx = k.f;
    const auto c = cameraFromVanishingPoints(in);
    ASSERT_TRUE(c.ok()) << c.error().message();
    EXPECT_NEAR(c->focalPx / k.f, 1.0, 1e-4);
    EXPECT_TRUE(c->worldFromCamera.allFinite());
    for (int i = 0; i < 3; ++i)
      EXPECT_LT(angleDeg(c->worldFromCamera.col(i), truth.worldFromCamera.col(i)), 1e-3)
          << "yaw " << k.yaw << " roll " << k.roll << " axis " << i;
  }
}

TEST(Camera, RefusesWhatCannotGiveAFocalLength) {
  const Camera truth = syntheticCamera(0, 0, 0, 500);
  VanishingInput in;
  in.widthPx = 640;
  in.heightPx = 480;
  in.vanishingPointsPx = {vpPixel(truth, Vec3::UnitX()), vpPixel(truth, Vec3::UnitY()),
                          vpPixel(truth, Vec3::UnitZ())};
  const auto c = cameraFromVanishingPoints(in);  // two at infinity, no focal: not determined
  ASSERT_FALSE(c.ok());
  EXPECT_NE(c.error().message().find("camera.vanishing_points_px"), std::string::npos);
  in.vanishingPointsPx[0] = Vec2(std::nan(""), 1);
  EXPECT_FALSE(cameraFromVanishingPoints(in).ok());
}

TEST(Room, BadCornersAreNamed) {
  const Camera c = syntheticCamera(0, -10, 0, 500);
  // Floor corners above the horizon.
  const auto r = roomFromBackWall(c, {Vec2(100, 10), Vec2(500, 10), Vec2(500, 20), Vec2(100, 20)});
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message().find("layout.back_wall_px"), std::string::npos);
  // Left and right swapped.
  const auto s = roomFromBackWall(c, {Vec2(500, 100), Vec2(100, 100), Vec2(100, 400), Vec2(500, 400)});
  EXPECT_FALSE(s.ok());
}

// The rear wall: the user's distance wins; otherwise the default, pushed back behind every light
// placed in 3D behind the camera; never closer than 0.05 m, never NaN.
TEST(Room, RearWallEnclosesPlacedLights) {
  const std::vector<Vec3> none;
  EXPECT_DOUBLE_EQ(rearWallDistanceM(std::nullopt, 0.5, none), 0.5);
  // A light 0.2 .. 0.8 m behind the camera: the wall stands 0.05 m behind its far edge.
  const std::vector<Vec3> behind = {
      {-0.3, 2.9, 0.2}, {0.3, 2.9, 0.2}, {0.3, 2.9, 0.8}, {-0.3, 2.9, 0.8}};
  EXPECT_NEAR(rearWallDistanceM(std::nullopt, 0.5, behind), 0.85, 1e-12);
  EXPECT_NEAR(rearWallDistanceM(std::nullopt, 0.5, behind, 0.0), 0.8, 1e-12);
  // Lights in front of the camera, or exactly at it (z = 0), leave the default.
  const std::vector<Vec3> front = {{-0.3, 2.9, -2}, {0.3, 2.9, -2}, {0.3, 2.9, -1}, {-0.3, 2.9, -1}};
  EXPECT_DOUBLE_EQ(rearWallDistanceM(std::nullopt, 0.5, front), 0.5);
  const std::vector<Vec3> atCamera = {{0, 1.5, 0}, {0, 1.5, 0}, {0, 1.5, 0}, {0, 1.5, 0}};
  EXPECT_DOUBLE_EQ(rearWallDistanceM(std::nullopt, 0.5, atCamera), 0.5);
  // A light just behind a camera that stands against its wall: the wall moves just behind it.
  const std::vector<Vec3> touching = {{0, 2.5, 0.01}};
  EXPECT_NEAR(rearWallDistanceM(std::nullopt, 0.0, touching), 0.06, 1e-12);
  // The user's distance is kept even with a light beyond it (the user said where the wall is).
  EXPECT_DOUBLE_EQ(rearWallDistanceM(1.2, 0.5, behind), 1.2);
  EXPECT_DOUBLE_EQ(rearWallDistanceM(0.3, 0.5, behind), 0.3);
  // A camera against its rear wall: never closer than 0.05 m.
  EXPECT_DOUBLE_EQ(rearWallDistanceM(0.0, 0.5, none), 0.05);
  EXPECT_DOUBLE_EQ(rearWallDistanceM(std::nullopt, -1.0, none), 0.05);
  // Non-finite input never escapes.
  const double nan = std::nan("");
  const std::vector<Vec3> bad = {{nan, nan, nan}, {0, 0, std::numeric_limits<double>::infinity()}};
  EXPECT_DOUBLE_EQ(rearWallDistanceM(std::nullopt, 0.5, bad), 0.5);
  EXPECT_DOUBLE_EQ(rearWallDistanceM(nan, nan, bad), 0.5);
  // Far lights are enclosed however far (the box grows; it stays finite).
  const std::vector<Vec3> far = {{0, 2.5, 40.0}};
  EXPECT_NEAR(rearWallDistanceM(std::nullopt, 0.5, far), 40.05, 1e-9);
}

TEST(Room, RearWallDistanceReachesTheBox) {
  const Camera c = syntheticCamera(0, -10, 0, 500);
  const Vec3 w[4] = {{-2, 2.6, -5}, {2, 2.6, -5}, {2, 0, -5}, {-2, 0, -5}};
  std::array<Vec2, 4> corners;
  for (int i = 0; i < 4; ++i) corners[size_t(i)] = *c.project(w[i]);
  RoomOptions o;
  o.rearMarginM = rearWallDistanceM(std::nullopt, o.rearMarginM, {{0, 2.6, 1.1}});
  const auto box = roomFromBackWall(c, corners, o);
  ASSERT_TRUE(box.ok()) << box.error().message();
  EXPECT_NEAR(box->zRearM, 1.15, 1e-9);
  EXPECT_NEAR(box->zBackM, -5, 1e-6);
}

TEST(Extrusion, HeightBySingleViewMetrologyAndPlacementOnTop) {
  const Camera c = syntheticCamera(5, -20, 0, 500);
  // A table top 0.75 m high, 1 x 0.6 m, 3 m in front of the camera.
  const double h = 0.75;
  std::vector<Vec3> top = {{-0.5, h, -3.3}, {0.5, h, -3.3}, {0.5, h, -2.7}, {-0.5, h, -2.7}};
  std::vector<Vec2> outline;
  outline.reserve(top.size());
  for (const auto& p : top) outline.push_back(*c.project(p));
  const Vec2 click = *c.project(Vec3(top[0].x(), 0, top[0].z()));
  const auto ex = extrusionFromOutline(c, outline, click, "surfaces[0]");
  ASSERT_TRUE(ex.ok()) << ex.error().message();
  EXPECT_NEAR(ex->heightM, h, 1e-6);
  for (size_t i = 0; i < 4; ++i) {
    bool found = false;
    for (const auto& q : ex->topOutlineWorld) found |= (q - top[i]).norm() < 1e-6;
    EXPECT_TRUE(found);
  }
  RoomBox box;
  box.xLeftM = -3;
  box.xRightM = 3;
  box.zBackM = -6;
  box.zRearM = 0.5;
  box.ceilingM = 2.7;
  const SceneGeometry g = buildSceneGeometry(box, {*ex});
  const TriangleMesh cube = makeCube();
  const auto p = placeObject(cube, g, c, *c.project(Vec3(0.1, h, -3.0)), 0.2, 30, "objects[0]");
  ASSERT_TRUE(p.ok()) << p.error().message();
  EXPECT_NEAR(p->baseWorld.y(), h, 1e-6);
  EXPECT_EQ(g.surfaces[p->supportSurfaceId].kind, SurfaceKind::ExtrusionTop);
  // The cube's bottom rests on the top, its height is 0.2.
  const Vec4 lo = p->worldFromObject * Vec4(0, -0.5, 0, 1), hi = p->worldFromObject * Vec4(0, 0.5, 0, 1);
  EXPECT_NEAR(lo.y(), h, 1e-9);
  EXPECT_NEAR(hi.y() - lo.y(), 0.2, 1e-9);
  // Click above the horizon; self-intersecting outline; two points.
  EXPECT_FALSE(extrusionFromOutline(c, outline, Vec2(320, 5), "surfaces[0]").ok());
  std::vector<Vec2> bow = {outline[0], outline[2], outline[1], outline[3]};
  const auto b = extrusionFromOutline(c, bow, click, "surfaces[0]");
  ASSERT_FALSE(b.ok());
  EXPECT_NE(b.error().message().find("crosses itself"), std::string::npos);
  EXPECT_FALSE(extrusionFromOutline(c, {outline[0], outline[1]}, click, "surfaces[0]").ok());
  // A pixel in the sky is not a support.
  EXPECT_FALSE(placeObject(cube, g, c, Vec2(320, 2), 0.2, 0, "objects[0]").ok());
}

}  // namespace
}  // namespace inlay
