// Occluder mattes from scribbles (grabCut + alphamat) and the cards they stand as.
#include "inlay/modeling/camera.h"
#include "inlay/modeling/image_io.h"
#include "inlay/modeling/occluder.h"
#include "test_support.h"

#include <array>
#include <cmath>
#include <random>

namespace inlay {
namespace {

// A known matte: an ellipse with a 3 px soft edge; foreground orange with texture, background a
// blue-green gradient with noise. photo = alpha F + (1 - alpha) B in linear RGB.
struct Synthetic {
  ImageF photo{160, 120, 3};
  ImageF alpha{160, 120, 1};
  Synthetic() {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> noise(-0.03f, 0.03f);
    for (int y = 0; y < 120; ++y)
      for (int x = 0; x < 160; ++x) {
        const double dx = (x + 0.5 - 80) / 40.0, dy = (y + 0.5 - 62) / 30.0;
        const double r = std::sqrt(dx * dx + dy * dy);
        const double distPx = (r - 1.0) * 35.0;  // roughly pixels outside the rim
        const float a = float(std::clamp(0.5 - distPx / 3.0, 0.0, 1.0));
        alpha.at(x, y) = a;
        const Vec3 f(0.7 + noise(rng), 0.35 + noise(rng), 0.08);
        const Vec3 b(0.05 + 0.001 * x + noise(rng), 0.2 + 0.001 * y, 0.45 + noise(rng));
        photo.setRgb(x, y, a * f + (1 - a) * b);
      }
  }
  std::vector<std::vector<Vec2>> fg() const { return {{{60, 62}, {100, 62}}, {{80, 45}, {80, 80}}}; }
  std::vector<std::vector<Vec2>> bg() const {
    return {{{20, 15}, {140, 15}, {140, 110}, {20, 110}, {20, 15}}};
  }
};

TEST(Occluder, RecoversAKnownSoftMatte) {
  const Synthetic s;
  const auto m = matteFromScribbles(s.photo, s.fg(), s.bg(), "occluders[0]");
  ASSERT_TRUE(m.ok()) << m.error().message();
  double inter = 0, uni = 0, absErr = 0, edgeErr = 0;
  int edge = 0;
  for (int y = 0; y < 120; ++y)
    for (int x = 0; x < 160; ++x) {
      const float a = m->alphaPx.at(x, y), t = s.alpha.at(x, y);
      inter += (a >= 0.5f && t >= 0.5f);
      uni += (a >= 0.5f || t >= 0.5f);
      absErr += std::abs(a - t);
      if (t > 0.02f && t < 0.98f) edgeErr += std::abs(a - t), ++edge;
    }
  EXPECT_GT(inter / uni, 0.97);
  EXPECT_LT(absErr / (160 * 120), 0.02);
  ASSERT_GT(edge, 0);
  EXPECT_LT(edgeErr / edge, 0.25);  // soft edge pixels: close to the truth, not a hard cut
  // The box and lowest point follow the ellipse (bottom at y = 62 + 30 = 92).
  EXPECT_NEAR(m->lowestPx.y(), 92.0, 1.5);
  EXPECT_NEAR(m->lowestPx.x(), 80.0, 3.0);
  EXPECT_NEAR(m->boxPx[0], 40, 5);
  EXPECT_NEAR(m->boxPx[2], 120, 5);
}

TEST(Occluder, BadScribblesAreRefusedWithTheKey) {
  const Synthetic s;
  auto expectError = [](const Expected<OccluderMatte>& e, const std::string& key,
                        const std::string& words) {
    ASSERT_FALSE(e.ok());
    EXPECT_NE(e.error().message().find(key), std::string::npos) << e.error().message();
    EXPECT_NE(e.error().message().find(words), std::string::npos) << e.error().message();
  };
  expectError(matteFromScribbles(s.photo, {}, s.bg(), "occluders[1]"),
              "occluders[1].foreground_scribbles_px", "empty");
  expectError(matteFromScribbles(s.photo, {{}}, s.bg(), "occluders[1]"),
              "occluders[1].foreground_scribbles_px", "empty");
  expectError(matteFromScribbles(s.photo, s.fg(), {}, "occluders[0]"),
              "occluders[0].background_scribbles_px", "empty");
  // Strokes entirely outside the photo.
  expectError(matteFromScribbles(s.photo, {{{-50, -50}, {-40, -60}}}, s.bg(), "occluders[0]"),
              "occluders[0].foreground_scribbles_px", "inside the photo");
  // Foreground strokes covering the whole photo.
  MatteOptions wide;
  wide.strokeRadiusPx = 200;
  expectError(matteFromScribbles(s.photo, {{{80, 60}}}, {{{10, 10}}}, "occluders[0]", wide),
              "occluders[0].foreground_scribbles_px", "whole photo");
  std::vector<std::vector<Vec2>> rows;  // background strokes 5 px thick every 4 rows
  for (int y = 0; y <= 124; y += 4) rows.push_back({{-5.0, y + 0.5}, {165.0, y + 0.5}});
  expectError(matteFromScribbles(s.photo, {{{10, 10}}}, rows, "occluders[0]"),
              "occluders[0].background_scribbles_px", "whole photo");
  expectError(matteFromScribbles(s.photo, s.fg(), {{{std::nan(""), 3}}}, "occluders[0]"),
              "occluders[0].background_scribbles_px", "finite");
}

Camera pitchedCamera() {
  Camera c = levelCamera(160, 120, 130, 1.5);
  c.worldFromCamera = Eigen::AngleAxisd(-15 * M_PI / 180, Vec3::UnitX()).toRotationMatrix();
  return c;
}

TEST(Occluder, CardStandsAtTheFloorDepthOfTheLowestPoint) {
  const Camera c = pitchedCamera();
  // A matte whose lowest point projects from the floor point (0.1, 0, -3).
  const Vec3 foot(0.1, 0, -3.0);
  const Vec2 footPx = *c.project(foot);
  OccluderMatte m;
  m.alphaPx = ImageF(160, 120, 1, 0.f);
  const int x0 = int(footPx.x()) - 15, x1 = int(footPx.x()) + 15, y1 = int(footPx.y());
  for (int y = y1 - 40; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) m.alphaPx.at(x, y) = 1.f;
  m.boxPx = {x0, y1 - 40, x1 + 1, y1 + 1};
  m.lowestPx = footPx;
  const auto card = occluderCard(c, m, 2, "occluders[2]");
  ASSERT_TRUE(card.ok()) << card.error().message();
  EXPECT_EQ(card->kind, SurfaceKind::OccluderCard);
  EXPECT_EQ(card->name, "occluder_2_card");
  EXPECT_FALSE(card->supportsObjects);
  ASSERT_EQ(card->meshWorld.positions.size(), 4u);
  // Vertical, facing the camera (which looks along -z here): every corner at the foot's depth.
  for (const auto& p : card->meshWorld.positions) EXPECT_NEAR(p.z(), -3.0, 1e-4);
  const auto& P = card->meshWorld.positions;
  const auto& t0 = card->meshWorld.triangles[0];
  const Vec3 n = (P[t0[1]] - P[t0[0]]).cross(P[t0[2]] - P[t0[0]]).cast<double>().normalized();
  EXPECT_GT(n.z(), 0.999);
  // The card's bottom edge is near the floor, its alpha is the matte's.
  double lowY = 1e9;
  for (const auto& p : P) lowY = std::min(lowY, double(p.y()));
  EXPECT_NEAR(lowY, 0.0, 0.03);
  ASSERT_TRUE(card->cardAlpha);
  EXPECT_NEAR(card->cardAlpha->alphaAt(Vec3(0.1, 0.2, -3.0)), 1.0, 1e-6);
  EXPECT_NEAR(card->cardAlpha->alphaAt(Vec3(1.5, 0.2, -3.0)), 0.0, 1e-6);
  // In the scene geometry the card counts where the matte covers it, not through its clear parts.
  RoomBox box;
  box.xLeftM = -3, box.xRightM = 3, box.zBackM = -6, box.zRearM = 0.5, box.ceilingM = 2.7;
  SceneGeometry g = buildSceneGeometry(box, {});
  g.surfaces.push_back(*card);
  const auto covered = g.intersect(c.rayThroughPixel(*c.project(Vec3(0.1, 0.2, -3.0))));
  ASSERT_TRUE(covered.has_value());
  EXPECT_EQ(g.surfaces[size_t(covered->surfaceId)].kind, SurfaceKind::OccluderCard);
  const Vec2 clearPx(x1 + 5.5, y1 - 30.5);  // right of the matte
  ASSERT_LT(m.alphaPx.at(int(clearPx.x()), int(clearPx.y())), 0.5f);
  m.boxPx[2] = x1 + 10;  // widen the card so that pixel falls on it
  const auto wide = occluderCard(c, m, 2, "occluders[2]");
  ASSERT_TRUE(wide.ok());
  g.surfaces.back() = *wide;
  const auto clear = g.intersect(c.rayThroughPixel(clearPx));
  ASSERT_TRUE(clear.has_value());
  EXPECT_NE(g.surfaces[size_t(clear->surfaceId)].kind, SurfaceKind::OccluderCard);
  // A matte whose lowest point is above the horizon cannot stand on the floor.
  OccluderMatte sky = m;
  sky.lowestPx = Vec2(80, 5);
  const auto bad = occluderCard(c, sky, 0, "occluders[0]");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message().find("horizon"), std::string::npos);
}

// d6_behind_table's photo, its table's label (labels.png == 7) and the harness's scribbles:
// three strokes across the table (at 25, 50 and 80 % of its height, crossing the gaps between
// the legs), one loop 20 px around it.
struct D6Table {
  ImageF photo, labels;
  std::vector<std::vector<Vec2>> fg, bg;
  int y1 = 0;  // the table's lowest row
  bool isTable(int x, int y) const { return std::lround(linearToSrgb(labels.at(x, y, 0)) * 255) == 7; }
  bool load();
};

bool D6Table::load() {
  const std::string dir = test::sharedDir() + "/scenes/d6_behind_table/";
  const auto photoFile = loadImage(dir + "photo.png");
  const auto labelFile = loadImage(dir + "labels.png");
  if (!photoFile.ok() || !labelFile.ok()) return false;
  photo = photoFile->linearRgb, labels = labelFile->linearRgb;
  const ImageF& L = labels;
  int x0 = L.width, x1 = 0, y0 = L.height;
  for (int y = 0; y < L.height; ++y)
    for (int x = 0; x < L.width; ++x)
      if (isTable(x, y))
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  // The harness strokes rows of the table mask eroded by a 9 x 9 square, end to end.
  auto inEroded = [&](int x, int y) {
    for (int dy = -4; dy <= 4; ++dy)
      for (int dx = -4; dx <= 4; ++dx) {
        const int u = x + dx, v = y + dy;
        if (u < 0 || v < 0 || u >= L.width || v >= L.height || !isTable(u, v)) return false;
      }
    return true;
  };
  int e0 = L.height, e1 = -1, ex0 = L.width, ex1 = -1;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
      if (inEroded(x, y))
        e0 = std::min(e0, y), e1 = std::max(e1, y), ex0 = std::min(ex0, x), ex1 = std::max(ex1, x);
  if (e1 < e0) return false;
  for (double q : {0.25, 0.5, 0.8}) {
    const int y = e0 + int(q * (e1 - e0));
    int a = -1, b = -1;
    for (int x = x0; x <= x1; ++x)
      if (inEroded(x, y)) b = x, a = a < 0 ? x : a;
    if (a >= 0) fg.push_back({{a + 0.5, y + 0.5}, {b + 0.5, y + 0.5}});
  }
  // The loop: 20 px around the eroded mask's box, clipped to the photo.
  const double bx0 = std::max(0, ex0 - 20), bx1 = std::min(L.width - 1, ex1 + 20);
  const double by0 = std::max(0, e0 - 20), by1 = std::min(L.height - 1, e1 + 20);
  bg = {{{bx0, by0}, {bx1, by0}, {bx1, by1}, {bx0, by1}, {bx0, by0}}};
  return !fg.empty();
}

// The matte's overlap with the table (label 7) at k times the label's size: {of the union, of
// the table}.
std::array<double, 2> tableOverlap(const D6Table& d, const ImageF& alpha, int k) {
  double inter = 0, uni = 0, table = 0;
  for (int y = 0; y < alpha.height; ++y)
    for (int x = 0; x < alpha.width; ++x) {
      const bool a = alpha.at(x, y) >= 0.5f, t = d.isTable(x / k, y / k);
      inter += a && t, uni += a || t, table += t;
    }
  return {inter / uni, inter / table};
}

// d6_behind_table: the table's matte from the harness's scribbles against labels.png == 7.
TEST(Occluder, TableMatteOfTheOcclusionScene) {
  INLAY_REQUIRE_SHARED();
  D6Table d;
  ASSERT_TRUE(d.load());
  const auto m = matteFromScribbles(d.photo, d.fg, d.bg, "occluders[0]");
  ASSERT_TRUE(m.ok()) << m.error().message();
  const auto [iou, recall] = tableOverlap(d, m->alphaPx, 1);
  // The strokes cross the floor between the legs: that floor must stay out of the matte.
  EXPECT_GT(recall, 0.95);
  EXPECT_GT(iou, 0.9);
  // The legs leave the photo at its bottom row, where the loop runs (sure background): the
  // lowest point stays a few pixels above.
  EXPECT_NEAR(m->lowestPx.y(), d.y1 + 1.0, 12.0);
}

// Issue #18: the same photo 4 times larger (2048 x 1536, a phone photo's scale) and its
// scribbles scaled give the same matte. Matted at its own size, the pixel sizes (stroke radius,
// trimap band) were a quarter of the table's scale: the floor between the legs stayed in the
// matte (IoU 0.65 against 0.95) and the table's 4 cm top became a 22 cm slab (object RMSE 0.108
// against 0.029). Now a photo larger than MatteOptions::referenceLongSidePx is matted at that
// scale on its scribbles' region.
TEST(Occluder, TableMatteDoesNotDependOnThePhotosSize) {
  INLAY_REQUIRE_SHARED();
  D6Table d;
  ASSERT_TRUE(d.load());
  const auto small = matteFromScribbles(d.photo, d.fg, d.bg, "occluders[0]");
  ASSERT_TRUE(small.ok()) << small.error().message();
  constexpr int k = 4;
  auto scaled = [](std::vector<std::vector<Vec2>> strokes) {  // as the benchmarks scale them
    for (auto& stroke : strokes)
      for (Vec2& q : stroke) q *= double(k);
    return strokes;
  };
  const ImageF bigPhoto = resizeImage(d.photo, k * d.photo.width, k * d.photo.height);
  const auto big = matteFromScribbles(bigPhoto, scaled(d.fg), scaled(d.bg), "occluders[0]");
  ASSERT_TRUE(big.ok()) << big.error().message();
  const auto [iou, recall] = tableOverlap(d, big->alphaPx, k);
  EXPECT_GT(recall, 0.95);
  EXPECT_GT(iou, 0.9);
  // Brought back to the photo's own pixels, the two mattes put few pixels on different sides.
  const ImageF back = resizeImage(big->alphaPx, d.photo.width, d.photo.height);
  int differ = 0, covered = 0;
  for (int y = 0; y < back.height; ++y)
    for (int x = 0; x < back.width; ++x) {
      differ += (back.at(x, y) >= 0.5f) != (small->alphaPx.at(x, y) >= 0.5f);
      covered += small->alphaPx.at(x, y) >= 0.5f;
    }
  EXPECT_LT(differ, 0.05 * covered);
  EXPECT_NEAR(big->lowestPx.y() / k, d.y1 + 1.0, 12.0);  // as at its own size (legs leave the photo)
  EXPECT_NEAR(big->boxPx[1] / double(k), small->boxPx[1], 3.0);  // the top's upper edge
}

}  // namespace
}  // namespace inlay
