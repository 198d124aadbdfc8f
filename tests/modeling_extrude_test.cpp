// Extrusions, boxes and stairs (CGAL): bad outlines, metrology, solids, the table scene.
#include "inlay/modeling/camera.h"
#include "inlay/modeling/geometry.h"
#include "inlay/modeling/occluder.h"
#include "inlay/modeling/scene_file.h"
#include "test_support.h"

#include "../modeling/src/geometry/solid_mesh.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace inlay {
namespace {

using json = nlohmann::json;

Camera pitchedCamera() {
  Camera c = levelCamera(640, 480, 500, 1.5);
  c.worldFromCamera = (Eigen::AngleAxisd(5 * M_PI / 180, Vec3::UnitY()) *
                       Eigen::AngleAxisd(-20 * M_PI / 180, Vec3::UnitX()))
                          .toRotationMatrix();
  return c;
}

struct Table {
  double h = 0.75;
  std::vector<Vec3> top{{-0.5, 0.75, -3.3}, {0.5, 0.75, -3.3}, {0.5, 0.75, -2.7}, {-0.5, 0.75, -2.7}};
  std::vector<Vec2> outline;
  Vec2 click;
  explicit Table(const Camera& c) {
    for (const auto& p : top) outline.push_back(*c.project(p));
    click = *c.project(Vec3(top[0].x(), 0, top[0].z()));
  }
};

RoomBox roomBox() {
  RoomBox box;
  box.xLeftM = -3, box.xRightM = 3, box.zBackM = -6, box.zRearM = 0.5, box.ceilingM = 2.7;
  return box;
}

double minY(const TriangleMesh& m) {
  double y = 1e300;
  for (const auto& p : m.positions) y = std::min(y, double(p.y()));
  return y;
}

// Sum over triangles of the signed volume under the divergence theorem: the closed solid's
// volume when up and other faces together are closed and outward.
double closedVolume(const TriangleMesh& a, const TriangleMesh& b) {
  double v = 0;
  for (const TriangleMesh* m : {&a, &b})
    for (const auto& t : m->triangles) {
      const Vec3 p = m->positions[t[0]].cast<double>(), q = m->positions[t[1]].cast<double>(),
                 r = m->positions[t[2]].cast<double>();
      v += p.dot(q.cross(r)) / 6.0;
    }
  return v;
}

void expectError(const Expected<Extrusion>& e, const std::string& key, const std::string& words) {
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error().message().find(key), std::string::npos) << e.error().message();
  EXPECT_NE(e.error().message().find(words), std::string::npos) << e.error().message();
}

TEST(Extrude, BadOutlinesAreRefusedWithTheKey) {
  const Camera c = pitchedCamera();
  const Table t(c);
  expectError(extrusionFromOutline(c, {t.outline[0], t.outline[1]}, t.click, "surfaces[2]"),
              "surfaces[2].outline_px", "at least 3 distinct points");
  // Repeated points do not count as distinct.
  expectError(
      extrusionFromOutline(c, {t.outline[0], t.outline[1], t.outline[1]}, t.click, "surfaces[0]"),
      "surfaces[0].outline_px", "at least 3 distinct points");
  const Vec2 mid = 0.5 * (t.outline[0] + t.outline[1]), far = 2.0 * t.outline[1] - t.outline[0];
  expectError(extrusionFromOutline(c, {t.outline[0], mid, t.outline[1], far}, t.click, "surfaces[1]"),
              "surfaces[1].outline_px", "one line");
  const std::vector<Vec2> bow = {t.outline[0], t.outline[2], t.outline[1], t.outline[3]};
  expectError(extrusionFromOutline(c, bow, t.click, "surfaces[3]"), "surfaces[3].outline_px",
              "crosses itself");
  expectError(extrusionFromOutline(c, {t.outline[0], t.outline[1], Vec2(std::nan(""), 3)}, t.click,
                                   "surfaces[0]"),
              "surfaces[0].outline_px[2]", "finite");
}

TEST(Extrude, EitherOrientationGivesTheSameClosedSolid) {
  const Camera c = pitchedCamera();
  const Table t(c);
  const auto a = extrusionFromOutline(c, t.outline, t.click, "surfaces[0]");
  ASSERT_TRUE(a.ok()) << a.error().message();
  // Reversed, still starting at point 0 (the click is below it).
  std::vector<Vec2> rev = {t.outline[0], t.outline[3], t.outline[2], t.outline[1]};
  const auto b = extrusionFromOutline(c, rev, t.click, "surfaces[0]");
  ASSERT_TRUE(b.ok()) << b.error().message();
  EXPECT_NEAR(a->heightM, t.h, 1e-6);
  EXPECT_NEAR(b->heightM, t.h, 1e-6);
  for (const Extrusion* e : {&*a, &*b}) {
    EXPECT_NEAR(closedVolume(e->upWorld, e->otherWorld), 1.0 * 0.6 * t.h, 1e-4);
    EXPECT_EQ(e->upWorld.triangles.size(), 2u);  // a quad top: two triangles
    for (const auto& n : e->upWorld.normals) EXPECT_GT(n.y(), 0.99f);
    EXPECT_NEAR(minY(e->otherWorld), 0.0, 1e-6);
  }
  // A concave (L-shaped) top: the triangles cover exactly its area.
  const double h = 0.75;
  std::vector<Vec3> L = {{-0.5, h, -3.3}, {0.5, h, -3.3}, {0.5, h, -3.0},
                         {0.0, h, -3.0},  {0.0, h, -2.7}, {-0.5, h, -2.7}};
  std::vector<Vec2> lpx;
  lpx.reserve(L.size());
  for (const auto& p : L) lpx.push_back(*c.project(p));
  const auto l = extrusionFromOutline(c, lpx, t.click, "surfaces[0]");
  ASSERT_TRUE(l.ok()) << l.error().message();
  EXPECT_NEAR(closedVolume(l->upWorld, l->otherWorld), (0.3 + 0.15) * h, 1e-4);
}

// The solid is kept as an OpenMesh mesh whose topology says closed, manifold, a sphere
// (V - E + F = 2) and outward; its volume agrees with the renderer's meshes converted from it.
void expectClosedSolid(const Extrusion& e, size_t outlinePoints, double volumeM3) {
  ASSERT_TRUE(e.solid) << "no OpenMesh solid";
  const SolidSummary s = summarizeSolid(*e.solid);
  EXPECT_TRUE(s.closed);
  EXPECT_TRUE(s.manifold);
  EXPECT_EQ(s.eulerCharacteristic, 2);
  EXPECT_EQ(s.vertices, 2 * outlinePoints);  // the two caps share the side walls' vertices
  EXPECT_EQ(s.faces, 2 * (outlinePoints - 2) + 2 * outlinePoints);
  EXPECT_NEAR(s.volumeM3, volumeM3, 1e-4);
  EXPECT_NEAR(closedVolume(e.upWorld, e.otherWorld), s.volumeM3, 1e-4);
}

// The checks themselves: a tetrahedron is closed, manifold and outward; without a face it is
// open; wound inside out its volume is negative.
TEST(Extrude, SolidChecksSeeOpenAndInsideOutMeshes) {
  auto tetra = [](bool withLastFace, bool inverted) {
    SolidMesh s;
    detail::SolidTriMesh::VertexHandle v[4] = {
        s.mesh.add_vertex({0, 0, 0}), s.mesh.add_vertex({1, 0, 0}), s.mesh.add_vertex({0, 1, 0}),
        s.mesh.add_vertex({0, 0, 1})};
    const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    for (int f = 0; f < (withLastFace ? 4 : 3); ++f) {
      const auto& i = faces[f];
      if (inverted) s.mesh.add_face(v[i[0]], v[i[2]], v[i[1]]);
      else s.mesh.add_face(v[i[0]], v[i[1]], v[i[2]]);
    }
    return summarizeSolid(s);
  };
  const SolidSummary closed = tetra(true, false);
  EXPECT_TRUE(closed.closed && closed.manifold);
  EXPECT_EQ(closed.eulerCharacteristic, 2);
  EXPECT_NEAR(closed.volumeM3, 1.0 / 6.0, 1e-12);
  const SolidSummary open = tetra(false, false);
  EXPECT_FALSE(open.closed);
  EXPECT_FALSE(open.manifold);
  EXPECT_NEAR(tetra(true, true).volumeM3, -1.0 / 6.0, 1e-12);
}

TEST(Extrude, SolidsAreClosedOpenMeshMeshes) {
  const Camera c = pitchedCamera();
  const Table t(c);
  const auto table = extrusionFromOutline(c, t.outline, t.click, "surfaces[0]");
  ASSERT_TRUE(table.ok()) << table.error().message();
  expectClosedSolid(*table, 4, 1.0 * 0.6 * t.h);
  ExtrusionOptions o;
  o.thicknessM = 0.04;
  const auto slab = extrusionFromOutline(c, t.outline, t.click, "surfaces[0]", o);
  ASSERT_TRUE(slab.ok()) << slab.error().message();
  expectClosedSolid(*slab, 4, 0.6 * 0.04);
  // Stairs sweep their profile across the width, against the profile plane's normal: still
  // outward.
  StairsSpec st;
  st.basePx = *c.project(Vec3(0.2, 0, -2.5));
  st.steps = 3;
  st.riseM = 0.2;
  st.runM = 0.25;
  st.widthM = 0.8;
  for (const Vec3& climb : {Vec3(0, 0, -1), Vec3(1, 0, 0), Vec3(-1, 0, 0)}) {
    st.climbWorld = climb;
    const auto s = stairsFromSpec(c, st, "surfaces[0]");
    ASSERT_TRUE(s.ok()) << s.error().message();
    expectClosedSolid(*s, 2 + 2 * 3, 0.25 * 0.2 * (1 + 2 + 3) * 0.8);
  }
  // A hand-made extrusion has no solid.
  EXPECT_FALSE(Extrusion{}.solid);
}

TEST(Extrude, AboveTheHorizonAndWrongClicksAreRefused) {
  const Camera c = pitchedCamera();
  const Table t(c);
  const Vec3 vp = c.vanishingPointOf(Vec3(0, 0, -1));
  const double horizonY = vp.y() / vp.z();
  ASSERT_GT(horizonY, 5.0);
  // Click above the horizon: the message says where the horizon is there and what to click.
  const auto high = extrusionFromOutline(c, t.outline, Vec2(t.click.x(), horizonY - 5), "surfaces[0]");
  expectError(high, "surfaces[0].height_click_px", "horizon");
  expectError(high, "surfaces[0].height_click_px",
              "(row y = " + std::to_string(int(std::lround(horizonRowPx(c, t.click.x())))) + " there)");
  expectError(high, "surfaces[0].height_click_px", "click the floor straight below outline point 0");
  // Click on the wrong side: above the outline point (not below it) on its vertical.
  const Vec2 above = *c.project(Vec3(t.top[0].x(), 1.2, t.top[0].z()));
  const Vec2 wrong = t.outline[0] + 0.5 * (above - t.outline[0]);
  expectError(extrusionFromOutline(c, t.outline, wrong, "surfaces[0]"), "surfaces[0].height_click_px",
              "not below");
  // A floor click beside the point, not under it.
  const Vec2 beside = *c.project(Vec3(t.top[0].x() + 0.4, 0, t.top[0].z()));
  expectError(extrusionFromOutline(c, t.outline, beside, "surfaces[0]"), "surfaces[0].height_click_px",
              "not straight below");
  // An outline point above the horizon cannot lie on a table top below the camera.
  std::vector<Vec2> sky = t.outline;
  sky[2] = Vec2(sky[2].x(), horizonY - 30);
  sky[3] = Vec2(sky[3].x(), horizonY - 30);
  const auto skyTop = extrusionFromOutline(c, sky, t.click, "surfaces[0]");
  expectError(skyTop, "surfaces[0].outline_px[2]", "it is above the horizon");
  expectError(skyTop, "surfaces[0].outline_px[2]", "outline the top below the horizon");
  // The horizon's row is where the level plane through the eye vanishes: a point on it at any
  // depth projects there.
  for (double z : {-3.0, -30.0}) {
    const Vec2 p = *c.project(Vec3(0.7, c.heightM, z));
    EXPECT_NEAR(horizonRowPx(c, p.x()), p.y(), 1e-6);
  }
}

TEST(Extrude, SlabAndBoxAndSceneGeometry) {
  const Camera c = pitchedCamera();
  const Table t(c);
  ExtrusionOptions o;
  o.thicknessM = 0.04;
  const auto slab = extrusionFromOutline(c, t.outline, t.click, "surfaces[0]", o);
  ASSERT_TRUE(slab.ok()) << slab.error().message();
  EXPECT_NEAR(minY(slab->otherWorld), t.h - 0.04, 1e-6);
  EXPECT_NEAR(closedVolume(slab->upWorld, slab->otherWorld), 0.6 * 0.04, 1e-5);
  o.thicknessM = 0.9;
  expectError(extrusionFromOutline(c, t.outline, t.click, "surfaces[0]", o), "surfaces[0].thickness_m",
              "thicker");
  // Box: a skewed outline becomes the axis-aligned rectangle around it.
  std::vector<Vec2> skew = t.outline;
  skew[2] = *c.project(Vec3(0.6, t.h, -2.8));
  const auto box = boxFromOutline(c, skew, t.click, "surfaces[0]");
  ASSERT_TRUE(box.ok()) << box.error().message();
  EXPECT_NEAR(closedVolume(box->upWorld, box->otherWorld), 1.1 * 0.6 * t.h, 1e-4);
  // The scene geometry holds the solid; an object placed on the top stands at its height.
  const SceneGeometry g = buildSceneGeometry(roomBox(), {*slab});
  ASSERT_EQ(g.surfaces.size(), 8u);
  EXPECT_EQ(g.surfaces[6].kind, SurfaceKind::ExtrusionTop);
  EXPECT_TRUE(g.surfaces[6].supportsObjects);
  const auto p = placeObject(makeCube(), g, c, *c.project(Vec3(0.1, t.h, -3.0)), 0.2, 0, "objects[0]");
  ASSERT_TRUE(p.ok()) << p.error().message();
  EXPECT_NEAR(p->baseWorld.y(), t.h, 1e-6);
}

TEST(Stairs, ObjectsStandOnAnyStep) {
  const Camera c = pitchedCamera();
  StairsSpec s;
  s.basePx = *c.project(Vec3(0.2, 0, -2.5));
  s.steps = 4;
  s.riseM = 0.18;
  s.runM = 0.3;
  s.widthM = 1.0;
  s.climbWorld = Vec3(0, 0, -1);
  const auto st = stairsFromSpec(c, s, "surfaces[1]");
  ASSERT_TRUE(st.ok()) << st.error().message();
  EXPECT_NEAR(st->heightM, 0.72, 1e-9);
  // Profile area: sum over steps of run x (k + 1) rise, times the width.
  EXPECT_NEAR(closedVolume(st->upWorld, st->otherWorld), 0.3 * 0.18 * (1 + 2 + 3 + 4) * 1.0, 1e-4);
  EXPECT_EQ(st->upWorld.triangles.size(), 8u);  // four treads
  const SceneGeometry g = buildSceneGeometry(roomBox(), {*st});
  for (int k = 0; k < 4; ++k) {
    // The middle of tread k: climbing along -z from z = -2.5.
    const Vec3 tread(0.2, (k + 1) * 0.18, -2.5 - (k + 0.5) * 0.3);
    const auto p = placeObject(makeCube(), g, c, *c.project(tread), 0.1, 0, "objects[0]");
    ASSERT_TRUE(p.ok()) << p.error().message();
    EXPECT_NEAR(p->baseWorld.y(), (k + 1) * 0.18, 1e-5) << "step " << k;
    EXPECT_EQ(g.surfaces[size_t(p->supportSurfaceId)].kind, SurfaceKind::ExtrusionTop);
  }
  // Bad specs name their key.
  StairsSpec bad = s;
  bad.steps = 0;
  expectError(stairsFromSpec(c, bad, "surfaces[1]"), "surfaces[1].steps", "1 to 1000");
  bad = s;
  bad.basePx = Vec2(320, 1);
  expectError(stairsFromSpec(c, bad, "surfaces[1]"), "surfaces[1].base_px", "horizon");
  bad = s;
  bad.climbWorld = Vec3(1, 0, 1).normalized();
  expectError(stairsFromSpec(c, bad, "surfaces[1]"), "surfaces[1].climb_axis", "+x");
}

// Three steps (rise 0.25, run 0.4) drawn on the left wall (x = -3), climbing toward -z from
// z = -4.2, as a user clicks them: each corner projected, off by up to a pixel.
std::vector<Vec2> drawnLeftWallProfile(const Camera& c) {
  const std::vector<Vec2> zy = {{-4.2, 0},   {-4.2, 0.25}, {-4.6, 0.25}, {-4.6, 0.5},
                                {-5.0, 0.5}, {-5.0, 0.75}, {-5.4, 0.75}, {-5.4, 0}};
  const Vec2 jitter[8] = {{0.6, -0.8}, {-0.9, 0.4},  {0.3, 0.9}, {-0.5, -0.7},
                          {0.8, 0.2},  {-0.2, -0.9}, {0.7, 0.6}, {-0.6, 0.3}};
  std::vector<Vec2> px;
  for (size_t i = 0; i < zy.size(); ++i)
    px.push_back(*c.project(Vec3(-3, zy[i].y(), zy[i].x())) + jitter[i]);
  return px;
}

TEST(Stairs, FromAProfileDrawnOnASideWall) {
  const Camera c = pitchedCamera();
  StairsProfileSpec sp;
  sp.profilePx = drawnLeftWallProfile(c);
  sp.widthM = 1.0;  // the wall is found from the points
  const auto st = stairsFromProfile(c, roomBox(), sp, "surfaces[0]");
  ASSERT_TRUE(st.ok()) << st.error().message();
  EXPECT_NEAR(st->heightM, 0.75, 0.01);
  ASSERT_TRUE(st->solid);
  const SolidSummary s = summarizeSolid(*st->solid);
  EXPECT_TRUE(s.closed && s.manifold);
  EXPECT_EQ(s.eulerCharacteristic, 2);
  EXPECT_NEAR(s.volumeM3, 0.4 * 0.25 * (1 + 2 + 3) * 1.0, 0.02);
  // The drawn treads were snapped level: every up face is exactly horizontal, three treads.
  EXPECT_EQ(st->upWorld.triangles.size(), 6u);
  for (const auto& n : st->upWorld.normals) EXPECT_NEAR(n.y(), 1.0f, 1e-6f);
  const SceneGeometry g = buildSceneGeometry(roomBox(), {*st});
  for (int k = 0; k < 3; ++k) {
    const Vec3 tread(-2.5, (k + 1) * 0.25, -4.2 - (k + 0.5) * 0.4);
    const auto p = placeObject(makeCube(), g, c, *c.project(tread), 0.1, 0, "objects[0]");
    ASSERT_TRUE(p.ok()) << p.error().message();
    EXPECT_NEAR(p->baseWorld.y(), (k + 1) * 0.25, 0.01) << "step " << k;
    EXPECT_NEAR(p->baseWorld.x(), -2.5, 0.02) << "step " << k;
    EXPECT_EQ(g.surfaces[size_t(p->supportSurfaceId)].kind, SurfaceKind::ExtrusionTop);
  }
  // No width: across the room to the opposite wall.
  sp.widthM = 0;
  sp.wall = SurfaceKind::WallLeft;
  const auto full = stairsFromProfile(c, roomBox(), sp, "surfaces[0]");
  ASSERT_TRUE(full.ok()) << full.error().message();
  EXPECT_NEAR(summarizeSolid(*full->solid).volumeM3, 0.4 * 0.25 * 6 * 6.0, 0.1);
}

void expectProfileError(const Camera& c, const StairsProfileSpec& sp, const std::string& key,
                        const std::string& words) {
  expectError(stairsFromProfile(c, roomBox(), sp, "surfaces[0]"), key, words);
}

TEST(Stairs, BadProfilesAreRefusedWithTheKey) {
  const Camera c = pitchedCamera();
  const std::vector<Vec2> good = drawnLeftWallProfile(c);
  StairsProfileSpec sp;
  sp.widthM = 1.0;
  sp.profilePx = {good[0], good[1]};
  expectProfileError(c, sp, "surfaces[0].profile_px", "at least 3 points");
  // Drawn on the floor, not on a wall.
  sp.profilePx.clear();
  for (const Vec3& p : {Vec3(0, 0, -3), Vec3(0.5, 0, -3), Vec3(0.5, 0, -3.5)})
    sp.profilePx.push_back(*c.project(p));
  expectProfileError(c, sp, "surfaces[0].profile_px", "not on a wall");
  // High on the wall: above the horizon (the camera is 1.5 m up), it cannot reach the floor.
  sp.profilePx.clear();
  for (const Vec2& zy : {Vec2(-4.4, 1.8), Vec2(-4.4, 2.2), Vec2(-5.0, 2.2), Vec2(-5.0, 1.8)})
    sp.profilePx.push_back(*c.project(Vec3(-3, zy.y(), zy.x())));
  expectProfileError(c, sp, "surfaces[0].profile_px[", "horizon");
  // Below the horizon but floating above the floor.
  sp.profilePx.clear();
  for (const Vec2& zy : {Vec2(-4.4, 0.3), Vec2(-4.4, 0.8), Vec2(-5.0, 0.8), Vec2(-5.0, 0.3)})
    sp.profilePx.push_back(*c.project(Vec3(-3, zy.y(), zy.x())));
  expectProfileError(c, sp, "surfaces[0].profile_px", "does not reach the floor");
  // Crossing edges (the tread corners swapped).
  sp.profilePx = good;
  std::swap(sp.profilePx[2], sp.profilePx[5]);
  expectProfileError(c, sp, "surfaces[0].profile_px", "crosses itself");
  // Said to be on the back wall, where these points do not land.
  sp.profilePx = good;
  sp.wall = SurfaceKind::WallBack;
  expectProfileError(c, sp, "surfaces[0].profile_px[", "back wall");
  sp.wall = SurfaceKind::Floor;
  expectProfileError(c, sp, "surfaces[0].wall", "left");
  sp.wall.reset();
  sp.widthM = 7.0;
  expectProfileError(c, sp, "surfaces[0].width_m", "wider than the room");
  // A tall flight on the back wall swept all the way to the rear would enclose the camera.
  sp.profilePx.clear();
  for (const Vec2& xy : {Vec2(-1, 0), Vec2(1, 0), Vec2(1, 2.0), Vec2(-1, 2.0)})
    sp.profilePx.push_back(*c.project(Vec3(xy.x(), xy.y(), -6)));
  sp.widthM = 6.4;
  expectProfileError(c, sp, "surfaces[0].width_m", "enclose the camera");
  sp.widthM = 0;
  expectProfileError(c, sp, "surfaces[0].width_m", "required");
  sp.widthM = 1.0;
  EXPECT_TRUE(stairsFromProfile(c, roomBox(), sp, "surfaces[0]").ok());
}

// A matte as a user's segmentation would give it: 1 where the pixel's ray meets one of the
// boxes (min corner, max corner), 0 elsewhere.
ImageF matteOfBoxes(const Camera& c, const std::vector<std::pair<Vec3, Vec3>>& boxes) {
  ImageF a(c.widthPx, c.heightPx, 1, 0.f);
  for (int y = 0; y < c.heightPx; ++y)
    for (int x = 0; x < c.widthPx; ++x) {
      const Ray r = c.rayThroughPixel(Vec2(x + 0.5, y + 0.5));
      for (const auto& [lo, hi] : boxes) {
        double t0 = 0, t1 = 1e9;
        for (int k = 0; k < 3; ++k) {
          const double inv = 1.0 / r.direction[k];
          double ta = (lo[k] - r.origin[k]) * inv, tb = (hi[k] - r.origin[k]) * inv;
          if (ta > tb) std::swap(ta, tb);
          t0 = std::max(t0, ta), t1 = std::min(t1, tb);
        }
        if (t0 <= t1) a.at(x, y) = 1.f;
      }
    }
  return a;
}

TEST(Extrude, TheOccluderMatteTellsASlabFromASolid) {
  const Camera c = pitchedCamera();
  const Table t(c);
  const auto ex = extrusionFromOutline(c, t.outline, t.click, "surfaces[0]");
  ASSERT_TRUE(ex.ok()) << ex.error().message();
  // A 5 cm top on four 4 cm legs: the floor shows under the top between the legs.
  const double th = 0.05, leg = 0.04;
  std::vector<std::pair<Vec3, Vec3>> table = {{Vec3(-0.5, t.h - th, -3.3), Vec3(0.5, t.h, -2.7)}};
  for (double x : {-0.5, 0.5 - leg})
    for (double z : {-3.3, -2.7 - leg}) table.push_back({Vec3(x, 0, z), Vec3(x + leg, t.h, z + leg)});
  const SlabEvidence open = slabFromMatte(c, *ex, matteOfBoxes(c, table));
  EXPECT_TRUE(open.open);
  EXPECT_GT(open.coveredSamples, 60);
  EXPECT_GT(open.openSamples, 0.8 * open.coveredSamples);  // all but the legs
  EXPECT_NEAR(open.thicknessM, th, 0.006);
  // A cabinet: the matte covers the front down to the floor: solid.
  const SlabEvidence block =
      slabFromMatte(c, *ex, matteOfBoxes(c, {{Vec3(-0.5, 0, -3.3), Vec3(0.5, t.h, -2.7)}}));
  EXPECT_GT(block.coveredSamples, 60);
  EXPECT_EQ(block.openSamples, 0);
  EXPECT_FALSE(block.open);
  // A matte of something else (a box 1.5 m to the right): no evidence about this top.
  const SlabEvidence other =
      slabFromMatte(c, *ex, matteOfBoxes(c, {{Vec3(1.0, 0, -3.3), Vec3(1.6, t.h, -2.7)}}));
  EXPECT_EQ(other.coveredSamples, 0);
  EXPECT_FALSE(other.open);
  EXPECT_FALSE(slabFromMatte(c, *ex, ImageF()).open);
}

TEST(Extrude, SceneFileKeysRoundTrip) {
  const std::string text = R"({"format": "inlay-scene", "version": 1, "photo": "p.png",
    "surfaces": [
      {"kind": "extrusion", "outline_px": [[10, 10], [50, 10], [50, 40]], "height_click_px": [10, 90],
       "thickness_m": 0.05},
      {"kind": "box", "outline_px": [[10, 10], [50, 10], [50, 40]], "height_click_px": [10, 90]},
      {"kind": "stairs", "base_px": [100, 300], "steps": 3, "rise_m": 0.2, "run_m": 0.25,
       "width_m": 0.9, "climb_axis": "+x"},
      {"kind": "stairs", "profile_px": [[10, 300], [10, 250], [60, 250], [60, 300]], "wall": "left"}]})";
  const auto dir = test::tempDir("extrude_keys");
  std::ofstream(dir / "p.png") << "x";  // the parser only checks that the photo exists
  const auto r = parseSceneJson(text, dir.string(), "s.json");
  ASSERT_TRUE(r.ok()) << r.error().message();
  const auto& s = r->doc.surfaces;
  ASSERT_EQ(s.size(), 4u);
  EXPECT_DOUBLE_EQ(*s[0].thicknessM, 0.05);
  EXPECT_EQ(s[3].profilePx.size(), 4u);
  EXPECT_EQ(s[3].wall, "left");
  EXPECT_EQ(s[3].widthM, 0.0);  // to the opposite wall
  EXPECT_EQ(s[1].kind, "box");
  EXPECT_FALSE(s[1].thicknessM.has_value());
  EXPECT_EQ(s[2].steps, 3);
  EXPECT_EQ(s[2].climbAxis, "+x");
  const auto back = parseSceneJson(sceneToJson(r->doc), dir.string(), "s.json");
  ASSERT_TRUE(back.ok()) << back.error().message();
  EXPECT_EQ(back->doc.surfaces[2].widthM, 0.9);
  EXPECT_EQ(*back->doc.surfaces[0].thicknessM, 0.05);
  EXPECT_EQ(back->doc.surfaces[3].profilePx, s[3].profilePx);
  EXPECT_EQ(back->doc.surfaces[3].wall, "left");
  EXPECT_FALSE(parseSceneJson(
                   R"({"format": "inlay-scene", "version": 1, "photo": "p.png", "surfaces": [
         {"kind": "stairs", "profile_px": [[1, 2], [3, 4], [5, 1]], "steps": 3}]})",
                   dir.string(), "s.json")
                   .ok());
  const auto badWall = parseSceneJson(
      R"({"format": "inlay-scene", "version": 1, "photo": "p.png", "surfaces": [
         {"kind": "stairs", "profile_px": [[1, 2], [3, 4], [5, 1]], "wall": "ceiling"}]})",
      dir.string(), "s.json");
  ASSERT_FALSE(badWall.ok());
  EXPECT_NE(badWall.error().message().find("surfaces[0].wall"), std::string::npos);
  // thickness_m 0: a solid to the floor, said explicitly; below 0 refused.
  const auto zero = parseSceneJson(
      R"({"format": "inlay-scene", "version": 1, "photo": "p.png", "surfaces": [
         {"kind": "extrusion", "outline_px": [[10, 10], [50, 10], [50, 40]], "height_click_px": [10, 90],
          "thickness_m": 0}]})",
      dir.string(), "s.json");
  ASSERT_TRUE(zero.ok()) << zero.error().message();
  EXPECT_EQ(zero->doc.surfaces[0].thicknessM, 0.0);
  const auto negative = parseSceneJson(
      R"({"format": "inlay-scene", "version": 1, "photo": "p.png", "surfaces": [
         {"kind": "extrusion", "outline_px": [[10, 10], [50, 10], [50, 40]], "height_click_px": [10, 90],
          "thickness_m": -0.1}]})",
      dir.string(), "s.json");
  ASSERT_FALSE(negative.ok());
  EXPECT_NE(negative.error().message().find("surfaces[0].thickness_m"), std::string::npos);
  const auto bad = parseSceneJson(
      R"({"format": "inlay-scene", "version": 1, "photo": "p.png", "surfaces": [
         {"kind": "stairs", "base_px": [1, 2], "steps": 3, "rise_m": 0.2, "run_m": 0.25}]})",
      dir.string(), "s.json");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message().find("surfaces[0].width_m"), std::string::npos);
}

// The table of d3_table_cube from the outline and click a user gives (the truth's pixels).
TEST(Extrude, TableTopOfTheTableSceneMatchesTruth) {
  INLAY_REQUIRE_SHARED();
  std::ifstream f(test::sharedDir() + "/scenes/d3_table_cube/truth.json");
  const json t = json::parse(f);
  const json& cam = t["camera"];
  VanishingInput in;
  in.widthPx = t["image"]["width"];
  in.heightPx = t["image"]["height"];
  in.heightM = cam["height_above_floor"];
  in.focalPx = cam["focal_px"].get<double>();
  const Vec2 pp(cam["principal_point_px"][0].get<double>(), cam["principal_point_px"][1].get<double>());
  in.principalPx = pp;
  auto vp = [&](const json& v) {
    if (v["finite"].get<bool>()) return Vec2(v["pixel"][0].get<double>(), v["pixel"][1].get<double>());
    return Vec2(
        pp + 1e7 * Vec2(v["image_direction"][0].get<double>(), v["image_direction"][1].get<double>()));
  };
  const auto& vps = t["vanishing_points"];
  in.vanishingPointsPx = {vp(vps["x"]), vp(vps["y"]), vp(vps["z"])};
  const auto c = cameraFromVanishingPoints(in);
  ASSERT_TRUE(c.ok()) << c.error().message();
  const json& top = t["table"]["top_surface"];
  std::vector<Vec2> outline;
  for (const auto& p : top["image_polygon"])
    outline.emplace_back(p[0].get<double>(), p[1].get<double>());
  const json& c0 = top["corners"][0]["world"];
  Vec2 click;
  std::vector<Vec2> floorTruthPx;
  for (const auto& b : t["table"]["bbox_corners"])
    if (b["world"][1].get<double>() == 0.0) {
      if (std::abs(b["world"][0].get<double>() - c0[0].get<double>()) < 1e-6 &&
          std::abs(b["world"][2].get<double>() - c0[2].get<double>()) < 1e-6)
        click = Vec2(b["pixel"][0].get<double>(), b["pixel"][1].get<double>());
      floorTruthPx.emplace_back(b["pixel"][0].get<double>(), b["pixel"][1].get<double>());
    }
  const auto ex = extrusionFromOutline(*c, outline, click, "surfaces[0]");
  ASSERT_TRUE(ex.ok()) << ex.error().message();
  const double hTrue = t["table"]["top_height"];
  EXPECT_NEAR(ex->heightM / hTrue, 1.0, 0.02);
  // The footprint on the floor (the solid's bottom corners) against the truth's floor corners.
  ASSERT_EQ(floorTruthPx.size(), 4u);
  for (const Vec3& p : ex->topOutlineWorld) {
    const auto px = c->project(Vec3(p.x(), 0, p.z()));
    ASSERT_TRUE(px.has_value());
    double best = 1e300;
    for (const Vec2& q : floorTruthPx) best = std::min(best, (*px - q).norm());
    EXPECT_LT(best, 3.0);
  }
}

}  // namespace
}  // namespace inlay
