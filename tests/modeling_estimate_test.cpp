// Camera and layout from the photo alone (estimate_camera.h): synthetic line drawings of box rooms
// from known cameras (vanishing points at infinity, two families only, ten segments, noise, tiny
// and huge photos, wide-angle, tele, roll), the correction API, the Ceres functor's derivatives,
// and the ground-truth rooms of ../shared/scenes.
#include "inlay/modeling/estimate_camera.h"
#include "inlay/modeling/geometry.h"
#include "inlay/modeling/image_io.h"
#include "../modeling/src/camera/estimate_camera_internal.h"
#include "../modeling/src/camera/lines.h"
#include "test_support.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

namespace inlay {
namespace {

constexpr double kDeg = M_PI / 180.0;

double angleDeg(const Vec3& a, const Vec3& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) / kDeg;
}

// Largest angle between corresponding world axes of two cameras.
double rotationErrorDeg(const Camera& a, const Camera& b) {
  double worst = 0;
  for (int k = 0; k < 3; ++k)
    worst = std::max(worst, angleDeg(a.worldFromCamera.col(k), b.worldFromCamera.col(k)));
  return worst;
}

bool isRotation(const Mat3& r) {
  return r.allFinite() && (r * r.transpose() - Mat3::Identity()).norm() < 1e-6 &&
         std::abs(r.determinant() - 1) < 1e-6;
}

// Everything a caller may read is finite and in range.
void expectSane(const CameraEstimate& e) {
  EXPECT_TRUE(isRotation(e.camera.worldFromCamera));
  EXPECT_TRUE(std::isfinite(e.camera.focalPx) && e.camera.focalPx > 0);
  EXPECT_TRUE(e.focalMinPx <= e.camera.focalPx * (1 + 1e-9) &&
              e.focalMaxPx >= e.camera.focalPx * (1 - 1e-9));
  for (int k = 0; k < 3; ++k) {
    EXPECT_TRUE(e.vanishingPointsPx[k].allFinite());
    EXPECT_TRUE(e.vanishingPoints[k].homogeneousPx.allFinite());
    EXPECT_GE(e.confidence[k], 0.0);
    EXPECT_LE(e.confidence[k], 1.0);
  }
  EXPECT_GE(e.overallConfidence, 0.0);
  EXPECT_LE(e.overallConfidence, 1.0);
  for (const Vec2& c : e.backWallPx) EXPECT_TRUE(c.allFinite());
  EXPECT_GE(e.layoutScore, 0.0);
  EXPECT_LE(e.layoutScore, 1.0);
}

Camera makeCamera(int w, int h, double f, double yawDeg, double pitchDeg, double rollDeg) {
  Camera c = levelCamera(w, h, f, 1.5);
  c.worldFromCamera = (Eigen::AngleAxisd(yawDeg * kDeg, Vec3::UnitY()) *
                       Eigen::AngleAxisd(pitchDeg * kDeg, Vec3::UnitX()) *
                       Eigen::AngleAxisd(rollDeg * kDeg, Vec3::UnitZ()))
                          .toRotationMatrix();
  return c;
}

struct Seg3 {
  Vec3 a, b;
};

// A 5 m x 2.7 m room, back wall 5 m ahead (camera at x = z = 0), with floor tiles, a door on
// the back wall and a window on the left wall: lines in all three directions.
std::vector<Seg3> roomLines(bool xAndYOnly = false, double zb = -5, double hc = 2.7) {
  const double xl = -2.5, xr = 2.5, zf = 0.5;
  std::vector<Seg3> s;
  // Back wall: edges and a door; horizontal x lines (a dado rail).
  s.push_back({{xl, 0, zb}, {xr, 0, zb}});
  s.push_back({{xl, hc, zb}, {xr, hc, zb}});
  s.push_back({{xl, 0, zb}, {xl, hc, zb}});
  s.push_back({{xr, 0, zb}, {xr, hc, zb}});
  s.push_back({{0.4, 0, zb}, {0.4, 2.0, zb}});
  s.push_back({{1.3, 0, zb}, {1.3, 2.0, zb}});
  s.push_back({{0.4, 2.0, zb}, {1.3, 2.0, zb}});
  s.push_back({{xl, 0.9, zb}, {0.2, 0.9, zb}});
  s.push_back({{-1.6, 0.3, zb}, {-1.6, 1.6, zb}});
  if (xAndYOnly) return s;
  // Receding room edges.
  for (double x : {xl, xr})
    for (double y : {0.0, hc}) s.push_back({{x, y, zb}, {x, y, zf}});
  // Floor tiles.
  for (double z = zb + 1; z <= -1; z += 1) s.push_back({{xl, 0, z}, {xr, 0, z}});
  for (double x = -1.5; x <= 1.5; x += 1) s.push_back({{x, 0, zb}, {x, 0, zf}});
  // Window on the left wall.
  const double w0 = zb + 1.5, w1 = zb + 3.5;
  s.push_back({{xl, 1.0, w0}, {xl, 1.0, w1}});
  s.push_back({{xl, 2.1, w0}, {xl, 2.1, w1}});
  s.push_back({{xl, 1.0, w0}, {xl, 2.1, w0}});
  s.push_back({{xl, 1.0, w1}, {xl, 2.1, w1}});
  return s;
}

// Project a world segment (world as in the scene file: camera at (0, h, 0)), clipped to the
// part in front of the camera; false when none of it is.
bool projectSegment(const Camera& cam, const Seg3& s, Vec2& a, Vec2& b) {
  const double near = 0.05;
  const double da = cam.depthOf(s.a), db = cam.depthOf(s.b);
  if (da < near && db < near) return false;
  Vec3 p = s.a, q = s.b;
  if (da < near) p = s.a + (s.b - s.a) * ((near - da) / (db - da));
  if (db < near) q = s.b + (s.a - s.b) * ((near - db) / (da - db));
  const auto pa = cam.project(p), pb = cam.project(q);
  if (!pa || !pb) return false;
  a = *pa;
  b = *pb;
  return true;
}

// Dark anti-aliased line of the given width on a 1-channel image, touching only its box.
void drawLine(ImageF& im, Vec2 a, Vec2 b, double widthPx, float value) {
  // Clip far-away endpoints to a generous box so the loops stay small.
  const double m = 4 * widthPx;
  const double xs[2] = {-m, im.width + m}, ys[2] = {-m, im.height + m};
  Vec2 d = b - a;
  double t0 = 0, t1 = 1;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double qv[4] = {a.x() - xs[0], xs[1] - a.x(), a.y() - ys[0], ys[1] - a.y()};
  for (int i = 0; i < 4; ++i) {
    if (std::abs(p[i]) < 1e-12) {
      if (qv[i] < 0) return;
      continue;
    }
    const double r = qv[i] / p[i];
    if (p[i] < 0) t0 = std::max(t0, r);
    else t1 = std::min(t1, r);
  }
  if (t0 > t1) return;
  const Vec2 a0 = a;
  a = a0 + t0 * d;
  b = a0 + t1 * d;
  d = b - a;
  const double len2 = std::max(1e-12, d.squaredNorm());
  const int x0 = std::max(0, int(std::floor(std::min(a.x(), b.x()) - widthPx - 1)));
  const int x1 = std::min(im.width - 1, int(std::ceil(std::max(a.x(), b.x()) + widthPx + 1)));
  const int y0 = std::max(0, int(std::floor(std::min(a.y(), b.y()) - widthPx - 1)));
  const int y1 = std::min(im.height - 1, int(std::ceil(std::max(a.y(), b.y()) + widthPx + 1)));
  const Vec2 n = Vec2(-d.y(), d.x()).normalized();
  for (int y = y0; y <= y1; ++y) {
    // Only the band around the line in this row.
    for (int x = x0; x <= x1; ++x) {
      const Vec2 c(x + 0.5, y + 0.5);
      const double dist = std::abs((c - a).dot(n));
      if (dist > widthPx) continue;
      const double t = (c - a).dot(d) / len2;
      if (t < 0 || t > 1) continue;
      const float cover = float(std::clamp(0.5 * widthPx + 0.5 - dist, 0.0, 1.0));
      float& v = im.at(x, y, 0);
      v = v + (value - v) * cover;
    }
  }
}

ImageF drawRoom(const Camera& cam, const std::vector<Seg3>& lines, double widthPx = 1.5) {
  ImageF im(cam.widthPx, cam.heightPx, 1, 0.5f);
  for (const Seg3& s : lines) {
    Vec2 a, b;
    if (projectSegment(cam, s, a, b)) drawLine(im, a, b, widthPx, 0.05f);
  }
  return im;
}

std::array<Vec2, 4> trueBackWall(const Camera& cam, double zb = -5, double hc = 2.7) {
  RoomBox box;
  box.xLeftM = -2.5;
  box.xRightM = 2.5;
  box.zBackM = zb;
  box.ceilingM = hc;
  return backWallCornersPx(cam, box);
}

TEST(EstimateCamera, SrgbCodeTableMatchesTheCurveEverywhere) {
  // Every float bit pattern of [0, 1] would take seconds: a dense sweep plus both neighbours of
  // every code boundary (where a table is wrong if it is wrong at all), and non-finite input.
  int boundaries = 0;
  float prev = 0.f;
  for (int i = 0; i <= 1 << 20; ++i) {
    const float v = float(i) / float(1 << 20);
    const int want = int(std::lround(255.f * linearToSrgb(v)));
    ASSERT_EQ(int(detail::srgbCode8(v)), want) << v;
    if (i > 0 && want != int(std::lround(255.f * linearToSrgb(prev)))) {
      ++boundaries;
      for (float w = prev; w <= v; w = std::nextafter(w, 2.f))
        ASSERT_EQ(int(detail::srgbCode8(w)), int(std::lround(255.f * linearToSrgb(w)))) << w;
    }
    prev = v;
  }
  EXPECT_EQ(boundaries, 255);
  EXPECT_EQ(detail::srgbCode8(-1.f), 0);
  EXPECT_EQ(detail::srgbCode8(std::nanf("")), 0);
  EXPECT_EQ(detail::srgbCode8(2.f), 255);
  EXPECT_EQ(detail::srgbCode8(INFINITY), 255);
}

// Two bright squares (turned 7.3 and 31 degrees) on a dark ground, each pixel the exact-ish
// area average of the scene (16 x 16 samples, linear light) plus a little noise: the detected
// segments must lie on the squares' edges to a small fraction of a pixel, in angle and offset,
// which the detector's fit to integer edge pixels alone does not reach (sub-pixel refinement in
// lines.cpp; without it the worst angle error here is 0.12 deg and the worst offset 0.35 px).
TEST(EstimateCamera, DetectedSegmentsLieOnTheEdgesToASubPixel) {
  struct Square {
    Vec2 c;
    double half, turnDeg;
  };
  const Square squares[2] = {{{110, 120}, 70, 7.3}, {{300, 150}, 60, 31.0}};
  auto inside = [&](const Square& q, double x, double y) {
    const double a = q.turnDeg * kDeg;
    const Vec2 d(x - q.c.x(), y - q.c.y());
    const double u = std::cos(a) * d.x() + std::sin(a) * d.y(),
                 v = -std::sin(a) * d.x() + std::cos(a) * d.y();
    return std::abs(u) <= q.half && std::abs(v) <= q.half;
  };
  ImageF im(400, 300, 3);
  std::mt19937 rng(5);
  std::normal_distribution<float> noise(0.f, 0.004f);
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      int in = 0;
      for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i)
          in += inside(squares[0], x + (i + 0.5) / 16, y + (j + 0.5) / 16) ||
                inside(squares[1], x + (i + 0.5) / 16, y + (j + 0.5) / 16);
      const float v = 0.03f + 0.5f * in / 256.f + noise(rng);
      for (int c = 0; c < 3; ++c) im.pixel(x, y)[c] = v;
    }
  const auto dl = detail::detectLineSegments(im, 800, 300, nullptr);
  double worstAngleDeg = 0, worstOffsetPx = 0;
  int edgesFound = 0;
  for (const Square& q : squares)
    for (int side = 0; side < 4; ++side) {
      // Edge: points c + R (+-half, t) or R (t, +-half).
      const double a = q.turnDeg * kDeg;
      const Vec2 ex(std::cos(a), std::sin(a)), ey(-std::sin(a), std::cos(a));
      const Vec2 normal = side < 2 ? ex : ey;
      const Vec2 p0 = q.c + (side % 2 ? -1.0 : 1.0) * q.half * normal;
      const LineSegment* best = nullptr;
      for (const LineSegment& s : dl.segments) {
        const double da = std::abs((s.aPx - p0).dot(normal)), db = std::abs((s.bPx - p0).dot(normal));
        if (da < 2 && db < 2 && s.lengthPx() > 0.5 * q.half &&
            (!best || s.lengthPx() > best->lengthPx()))
          best = &s;
      }
      if (!best) continue;
      ++edgesFound;
      const Vec2 t = (best->bPx - best->aPx).normalized();
      worstAngleDeg = std::max(worstAngleDeg, std::asin(std::min(1.0, std::abs(t.dot(normal)))) / kDeg);
      const Vec2 mid = 0.5 * (best->aPx + best->bPx);
      worstOffsetPx = std::max(worstOffsetPx, std::abs((mid - p0).dot(normal)));
    }
  EXPECT_EQ(edgesFound, 8);
  EXPECT_LT(worstAngleDeg, 0.08);
  EXPECT_LT(worstOffsetPx, 0.25);
  std::printf("sub-pixel edges: %d found, worst angle %.3f deg, worst offset %.3f px\n", edgesFound,
              worstAngleDeg, worstOffsetPx);
}

TEST(EstimateCamera, CeresFunctorDerivativesMatchCentralDifferences) {
  EXPECT_LT(detail::segmentResidualGradientError(), 1e-5);
}

TEST(EstimateCamera, RecoversFocalRotationAndBackWallOfACleanRoom) {
  const Camera truth = makeCamera(640, 480, 420, 8, -6, 0);
  const auto bw = trueBackWall(truth);
  for (const Vec2& c : bw) ASSERT_TRUE(c.x() > 0 && c.x() < 640 && c.y() > 0 && c.y() < 480);
  const auto e = estimateCamera(drawRoom(truth, roomLines()));
  ASSERT_TRUE(e.ok()) << e.error().message();
  expectSane(*e);
  EXPECT_TRUE(e->manhattan);
  EXPECT_NEAR(e->camera.focalPx / truth.focalPx, 1.0, 0.03);
  EXPECT_LT(rotationErrorDeg(e->camera, truth), 1.0);
  EXPECT_GT(e->overallConfidence, 0.5);
  EXPECT_FALSE(e->focalFromPrior);
  EXPECT_LE(e->focalMinPx, truth.focalPx * 1.03);
  EXPECT_GE(e->focalMaxPx, truth.focalPx * 0.97);
  for (int i = 0; i < 4; ++i) EXPECT_LT((e->backWallPx[i] - bw[i]).norm(), 3.0) << "corner " << i;
  EXPECT_TRUE(roomFromBackWall(e->camera, e->backWallPx).ok());
  // Supporting segments are reported with their families and residuals.
  int supported = 0;
  for (const auto& s : e->segments)
    if (s.family >= 0) {
      ++supported;
      EXPECT_LT(s.residualPx, 5.0);
    }
  EXPECT_GE(supported, 10);
  EXPECT_GT(e->timings.totalMs, 0.0);
  EXPECT_FALSE(e->progress.empty());
}

TEST(EstimateCamera, FrontalLevelCameraHasVanishingPointsAtInfinityAndFocalFromPrior) {
  const Camera truth = makeCamera(640, 480, 600, 0, 0, 0);
  EstimateOptions o;
  o.priorFocalPx = 640.0;  // EXIF says 640: a prior, the lines cannot say better here
  const auto e = estimateCamera(drawRoom(truth, roomLines()), o);
  ASSERT_TRUE(e.ok()) << e.error().message();
  expectSane(*e);
  EXPECT_TRUE(e->manhattan);
  EXPECT_LT(rotationErrorDeg(e->camera, truth), 1.0);
  EXPECT_TRUE(e->vanishingPoints[0].atInfinity);
  EXPECT_TRUE(e->vanishingPoints[1].atInfinity);
  EXPECT_FALSE(e->vanishingPoints[2].atInfinity);
  EXPECT_TRUE(e->focalFromPrior);
  EXPECT_NEAR(e->camera.focalPx, 640.0, 640.0 * 0.02);
  bool warned = false;
  for (const auto& w : e->warnings) warned |= w.find("focal length") != std::string::npos;
  EXPECT_TRUE(warned);
  // The scene file form of a point at infinity is a huge coordinate, and the lead's
  // cameraFromVanishingPoints accepts it with the focal length given.
  VanishingInput in;
  in.widthPx = 640;
  in.heightPx = 480;
  in.vanishingPointsPx = e->vanishingPointsPx;
  in.focalPx = e->camera.focalPx;
  const auto c = cameraFromVanishingPoints(in);
  ASSERT_TRUE(c.ok()) << c.error().message();
  EXPECT_LT(rotationErrorDeg(*c, e->camera), 0.05);
}

TEST(EstimateCamera, TwoFamiliesOnlyStillGiveFocalAndRotation) {
  // A facade seen from the side and below: a grid of x and y lines, nothing along z.
  const Camera truth = makeCamera(640, 480, 520, 25, 10, 0);
  std::vector<Seg3> grid;
  for (double x = -3; x <= 3.01; x += 0.5) grid.push_back({{x, 0.2, -5}, {x, 4.5, -5}});
  for (double y = 0.3; y <= 4.51; y += 0.4) grid.push_back({{-3.2, y, -5}, {3.2, y, -5}});
  const auto e = estimateCamera(drawRoom(truth, grid));
  ASSERT_TRUE(e.ok()) << e.error().message();
  expectSane(*e);
  EXPECT_NEAR(e->camera.focalPx / truth.focalPx, 1.0, 0.05);
  EXPECT_LT(rotationErrorDeg(e->camera, truth), 1.0);
  // The third direction has no lines of its own: it says so.
  EXPECT_LT(e->confidence[2], 0.2);
  EXPECT_GT(std::min(e->confidence[0], e->confidence[1]), 0.3);
}

TEST(EstimateCamera, RolledCamera) {
  const Camera truth = makeCamera(640, 480, 500, -12, -6, 20);
  const auto e = estimateCamera(drawRoom(truth, roomLines()));
  ASSERT_TRUE(e.ok()) << e.error().message();
  expectSane(*e);
  EXPECT_NEAR(e->camera.focalPx / truth.focalPx, 1.0, 0.03);
  EXPECT_LT(rotationErrorDeg(e->camera, truth), 1.0);
}

TEST(EstimateCamera, ExtremeWideAngle) {
  const Camera truth = makeCamera(640, 480, 0.3 * 640, 10, -12, 0);
  const auto e = estimateCamera(drawRoom(truth, roomLines()));
  ASSERT_TRUE(e.ok()) << e.error().message();
  expectSane(*e);
  EXPECT_NEAR(e->camera.focalPx / truth.focalPx, 1.0, 0.05);
  EXPECT_LT(rotationErrorDeg(e->camera, truth), 1.0);
}

TEST(EstimateCamera, TeleIsFiniteAndHonestAboutFocal) {
  // f = 5 W: the view is a 1 m patch of the back wall around the door; lines nearly parallel.
  const Camera truth = makeCamera(640, 480, 5 * 640, 4, -3, 0);
  std::vector<Seg3> lines;
  for (double x = -0.6; x <= 0.61; x += 0.15) lines.push_back({{x, 0.6, -5}, {x, 2.4, -5}});
  for (double y = 0.7; y <= 2.31; y += 0.15) lines.push_back({{-0.8, y, -5}, {0.8, y, -5}});
  for (double x = -0.4; x <= 0.41; x += 0.2) lines.push_back({{x, 0.0, -5}, {x, 0.0, -2}});
  const auto e = estimateCamera(drawRoom(truth, lines));
  ASSERT_TRUE(e.ok()) << e.error().message();
  expectSane(*e);
  const bool focalRight = std::abs(e->camera.focalPx / truth.focalPx - 1) < 0.1;
  const bool honest = e->focalFromPrior ||
                      (e->focalMinPx <= truth.focalPx && truth.focalPx <= e->focalMaxPx);
  EXPECT_TRUE(focalRight || honest) << "f " << e->camera.focalPx << " in [" << e->focalMinPx << ", "
                                    << e->focalMaxPx << "]";
  // Up is still up.
  EXPECT_LT(
      angleDeg(e->camera.worldFromCamera.row(1).transpose(), truth.worldFromCamera.row(1).transpose()),
      3.0);
}

TEST(EstimateCamera, TenSegmentsGiveAnHonestAnswer) {
  const Camera truth = makeCamera(640, 480, 560, 15, -8, 0);
  const auto all = roomLines();
  std::vector<LineSegment> segs;
  for (int i : {0, 1, 2, 3, 4, 5, 9, 10, 13, 14}) {
    Vec2 a, b;
    ASSERT_TRUE(projectSegment(truth, all[i], a, b));
    segs.push_back({a, b});
  }
  ASSERT_EQ(segs.size(), 10u);
  const auto e = estimateCameraFromSegments(640, 480, segs);
  ASSERT_TRUE(e.ok()) << e.error().message();
  expectSane(*e);
  // Four, four and two lines cannot beat the chance bar that random-line photos reach: either
  // a right answer, or the fallback saying it is not sure. Never a wrong answer claimed sure.
  if (e->manhattan) EXPECT_LT(rotationErrorDeg(e->camera, truth), 2.0);
  else EXPECT_LT(e->overallConfidence, 0.2);
  const auto full = estimateCamera(drawRoom(truth, roomLines()));
  ASSERT_TRUE(full.ok());
  EXPECT_LT(e->overallConfidence, full->overallConfidence);
}

TEST(EstimateCamera, PureNoiseIsAFallbackWithLowConfidence) {
  ImageF im(320, 240, 3);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  for (float& v : im.data) v = u(rng);
  const auto e = estimateCamera(im);
  ASSERT_TRUE(e.ok()) << e.error().message();
  expectSane(*e);
  EXPECT_FALSE(e->manhattan);
  EXPECT_LT(e->overallConfidence, 0.2);
  EXPECT_NEAR(e->camera.horizontalFovDeg(), 60.0, 0.5);  // no EXIF: 60 degrees, level
  EXPECT_LT(rotationErrorDeg(e->camera, levelCamera(320, 240, 300, 1.6)), 1e-9);
  EXPECT_FALSE(e->warnings.empty());
  // A blank wall: no lines at all.
  const auto blank = estimateCamera(ImageF(320, 240, 3, 0.4f));
  ASSERT_TRUE(blank.ok());
  expectSane(*blank);
  EXPECT_FALSE(blank->manhattan);
  EXPECT_EQ(blank->overallConfidence, 0.0);
}

TEST(EstimateCamera, TinyPhoto) {
  const Camera truth = makeCamera(16, 16, 14, 15, -8, 0);
  const auto e = estimateCamera(drawRoom(truth, roomLines(), 1.0));
  ASSERT_TRUE(e.ok()) << e.error().message();
  expectSane(*e);
  EXPECT_EQ(e->camera.widthPx, 16);
  EXPECT_EQ(e->camera.heightPx, 16);
}

TEST(EstimateCamera, HugePhotoIsDownscaledFirst) {
  // 10000 x 8000 (80 MP, one channel to keep the test's own memory at 320 MB).
  const Camera truth = makeCamera(10000, 8000, 8750, 15, -8, 0);
  const ImageF im = drawRoom(truth, roomLines(), 24.0);
  // Downscaled before the line search (how fast is for a benchmark to say, not a test).
  const auto e = estimateCamera(im);
  ASSERT_TRUE(e.ok()) << e.error().message();
  expectSane(*e);
  EXPECT_LT(e->workingScale, 0.1);
  EXPECT_NEAR(e->camera.focalPx / truth.focalPx, 1.0, 0.03);
  EXPECT_LT(rotationErrorDeg(e->camera, truth), 1.0);
}

// A shaded box room (one grey per face, linear, plus noise) with lines drawn on it: face
// boundaries are steps in brightness, as in a photo, so the back wall's right edge can be made a
// faint crease by giving the right wall almost the back wall's grey.
ImageF shadedRoom(const Camera& cam, const std::vector<Seg3>& lines, float rightWallGrey) {
  ImageF im(cam.widthPx, cam.heightPx, 1, 0.f);
  const double lo[3] = {-2.5, 0, -5}, hi[3] = {2.5, 2.7, 0.5};
  // Faces by the axis and side the ray leaves through: x-, x+, y-, y+, z-, z+.
  const float grey[6] = {0.22f, rightWallGrey, 0.16f, 0.45f, 0.30f, 0.30f};
  std::mt19937 rng(3);
  std::normal_distribution<float> noise(0.f, 0.004f);
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const Ray r = cam.rayThroughPixel(Vec2(x + 0.5, y + 0.5));
      double tBest = 1e300;
      int face = 4;
      for (int k = 0; k < 3; ++k) {
        if (std::abs(r.direction[k]) < 1e-12) continue;
        const bool up = r.direction[k] > 0;
        const double t = ((up ? hi[k] : lo[k]) - r.origin[k]) / r.direction[k];
        if (t > 0 && t < tBest) {
          tBest = t;
          face = 2 * k + (up ? 1 : 0);
        }
      }
      im.at(x, y, 0) = std::max(0.f, grey[face] + noise(rng));
    }
  for (const Seg3& s : lines) {
    Vec2 a, b;
    if (projectSegment(cam, s, a, b)) drawLine(im, a, b, 1.5, 0.05f);
  }
  return im;
}

TEST(EstimateCamera, FaintWallCornerIsFoundFromThePhotosContrast) {
  // A longer lens turned toward the right wall: the back wall's right edge is in view but its
  // floor and ceiling corners are not, no line is drawn on it and the right wall is almost the
  // back wall's grey (about 6 levels in sRGB, below the line detector's threshold). A rail on the
  // right wall ends 1 m short of the corner (like d4's window). The layout finds the edge from
  // the photo's contrast.
  const Camera truth = makeCamera(640, 480, 1000, -18, -3, 0);
  std::vector<Seg3> lines;
  for (double x = -1.8; x <= 1.81; x += 0.3) lines.push_back({{x, 0.5, -5}, {x, 2.3, -5}});
  for (double y = 0.5; y <= 2.31; y += 0.3) lines.push_back({{-2.0, y, -5}, {1.9, y, -5}});
  for (double y : {0.3, 1.0, 2.2}) lines.push_back({{2.5, y, -4.0}, {2.5, y, -0.5}});
  const auto e = estimateCamera(shadedRoom(truth, lines, 0.33f));
  ASSERT_TRUE(e.ok()) << e.error().message();
  expectSane(*e);
  ASSERT_TRUE(e->photoEdges);
  EXPECT_LT(rotationErrorDeg(e->camera, truth), 1.0);
  const auto want = trueBackWall(truth);
  // Where the right edge crosses the middle row.
  auto rightEdgeX = [](const std::array<Vec2, 4>& c) {
    const Vec2 d = c[2] - c[1];
    return c[1].x() + d.x() * (240 - c[1].y()) / d.y();
  };
  const double wantX = rightEdgeX(want);
  ASSERT_GT(wantX, 300);
  ASSERT_LT(wantX, 560);  // in view, with the right wall beside it
  EXPECT_NEAR(rightEdgeX(e->backWallPx), wantX, 3.0);
  // The premise: the same segments without the photo do not show that edge.
  const auto segsOnly = estimateCameraFromSegments(640, 480, e->segments);
  ASSERT_TRUE(segsOnly.ok());
  EXPECT_GT(std::abs(rightEdgeX(segsOnly->backWallPx) - wantX), 8.0);
  // A correction keeps the same evidence without the photo.
  EstimateCorrection fix;
  fix.backWallCornersPx[0] = e->backWallPx[0];
  const auto c = correctEstimate(*e, fix);
  ASSERT_TRUE(c.ok()) << c.error().message();
  EXPECT_EQ(c->photoEdges, e->photoEdges);
  EXPECT_NEAR(rightEdgeX(c->backWallPx), wantX, 3.0);
}

TEST(EstimateCamera, SupportersAreIndexedPerVanishingPoint) {
  const Camera truth = makeCamera(640, 480, 560, 15, -8, 0);
  const auto e = estimateCamera(drawRoom(truth, roomLines()));
  ASSERT_TRUE(e.ok()) << e.error().message();
  ASSERT_TRUE(e->manhattan);
  size_t supported = 0;
  for (int k = 0; k < 3; ++k) {
    const auto& v = e->vanishingPoints[k];
    EXPECT_EQ(int(v.segmentIndices.size()), v.segmentCount);
    EXPECT_GE(v.segmentCount, 3) << "axis " << k;
    for (int i : v.segmentIndices) {
      ASSERT_GE(i, 0);
      ASSERT_LT(size_t(i), e->segments.size());
      EXPECT_EQ(e->segments[i].family, k);
      EXPECT_TRUE(std::isfinite(e->segments[i].residualPx));
      EXPECT_LT(e->segments[i].residualPx, 3.0);
    }
    supported += v.segmentIndices.size();
  }
  size_t withFamily = 0;
  for (const auto& s : e->segments) withFamily += s.family >= 0;
  EXPECT_EQ(supported, withFamily);
  // A fallback's points are not the lines': nothing claims to support them.
  ImageF noise(320, 240, 1);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  for (float& v : noise.data) v = u(rng);
  const auto f = estimateCamera(noise);
  ASSERT_TRUE(f.ok());
  ASSERT_FALSE(f->manhattan);
  EXPECT_TRUE(f->vanishingPoints[0].segmentIndices.empty());
  EXPECT_TRUE(f->vanishingPoints[2].segmentIndices.empty());
  for (const auto& s : f->segments) EXPECT_TRUE(s.family == -1 || s.family == 1);
}

TEST(EstimateCamera, PrincipalPointKnownOrRefined) {
  // A camera 30 px right of and 20 px above the centre, three finite vanishing points.
  Camera truth = makeCamera(640, 480, 420, 30, -18, 0);
  truth.principalPx = Vec2(350, 220);
  const ImageF im = drawRoom(truth, roomLines());
  // Given: held exactly, and the rotation fits it.
  EstimateOptions known;
  known.principalPx = truth.principalPx;
  const auto k = estimateCamera(im, known);
  ASSERT_TRUE(k.ok()) << k.error().message();
  expectSane(*k);
  EXPECT_EQ(k->camera.principalPx, truth.principalPx);
  EXPECT_LT(rotationErrorDeg(k->camera, truth), 0.5);
  EXPECT_NEAR(k->camera.focalPx / truth.focalPx, 1.0, 0.02);
  // Refined under its prior: moves toward the truth and stays finite.
  EstimateOptions free;
  free.principalSigma = 0.2;
  const auto r = estimateCamera(im, free);
  ASSERT_TRUE(r.ok()) << r.error().message();
  expectSane(*r);
  EXPECT_LT((r->camera.principalPx - truth.principalPx).norm(), 12.0)
      << r->camera.principalPx.transpose();
  // Default: held at the centre.
  const auto d = estimateCamera(im);
  ASSERT_TRUE(d.ok());
  EXPECT_EQ(d->camera.principalPx, Vec2(320, 240));
}

// The room's lines as exact segments of `cam` (the estimator's input without a line detector).
std::vector<LineSegment> projectedRoom(const Camera& cam) {
  std::vector<LineSegment> segs;
  for (const Seg3& s : roomLines()) {
    Vec2 a, b;
    if (projectSegment(cam, s, a, b) && (b - a).norm() > 5) segs.push_back({a, b});
  }
  return segs;
}

TEST(EstimateCamera, ThreeFiniteVanishingPointsLocateAnOffCentrePrincipalPoint) {
  // Turned and tilted: all three vanishing points finite and spread around the photo, so their
  // orthocentre (the principal point) is determined; the prior (64 px) is far looser than that
  // and the posterior a quarter of it at most.
  Camera truth = makeCamera(640, 480, 450, 35, -22, 0);
  truth.principalPx = Vec2(347, 221);
  EstimateOptions o;
  o.principalSigma = 0.2;
  const auto e = estimateCameraFromSegments(640, 480, projectedRoom(truth), o);
  ASSERT_TRUE(e.ok()) << e.error().message();
  expectSane(*e);
  for (int k = 0; k < 3; ++k) EXPECT_FALSE(e->vanishingPoints[k].atInfinity);
  EXPECT_LT((e->camera.principalPx - truth.principalPx).norm(), 2.0)
      << e->camera.principalPx.transpose();
  EXPECT_FALSE(e->principalFromPrior);
  EXPECT_GT(e->principalSigmaPx.minCoeff(), 0.0);
  EXPECT_LT(e->principalSigmaPx.maxCoeff(), 0.25 * 0.2 * 320) << e->principalSigmaPx.transpose();
  EXPECT_NEAR(e->camera.focalPx / truth.focalPx, 1.0, 0.005);
  EXPECT_LT(rotationErrorDeg(e->camera, truth), 0.2);
  // Held (the default prior strength 0 or a given point): sigma 0, an assumption.
  EstimateOptions held;
  held.principalSigma = 0;
  const auto h = estimateCameraFromSegments(640, 480, projectedRoom(truth), held);
  ASSERT_TRUE(h.ok());
  EXPECT_EQ(h->camera.principalPx, Vec2(320, 240));
  EXPECT_EQ(h->principalSigmaPx, Vec2(0, 0));
  EXPECT_TRUE(h->principalFromPrior);
}

TEST(EstimateCamera, VanishingPointAtInfinityLeavesThePrincipalPointAtItsPrior) {
  // Level camera: the vertical vanishing point is at infinity. The principal point then lies on
  // the horizon (the line through the two finite points, which the lines do locate), but where
  // along it trades exactly against the focal length ((x_vp - p)(z_vp - p) = -f^2 along the
  // horizon): the orthocentre is undefined. Along the horizon it must stay at the prior's centre
  // (not wander to fit noise), say so, and keep the prior's uncertainty.
  Camera truth = makeCamera(640, 480, 520, 30, 0, 0);
  truth.principalPx = Vec2(347, 221);
  EstimateOptions o;
  o.principalSigma = 0.05;  // 16 px
  const double priorPx = 0.05 * 320;
  const auto e = estimateCameraFromSegments(640, 480, projectedRoom(truth), o);
  ASSERT_TRUE(e.ok()) << e.error().message();
  expectSane(*e);
  EXPECT_TRUE(e->vanishingPoints[1].atInfinity);
  EXPECT_TRUE(e->camera.principalPx.allFinite());
  EXPECT_TRUE(e->principalFromPrior);
  EXPECT_NEAR(e->camera.principalPx.x(), 320.0, 0.25 * priorPx) << e->camera.principalPx.transpose();
  EXPECT_GT(e->principalSigmaPx.x(), 0.9 * priorPx) << e->principalSigmaPx.transpose();
  EXPECT_LE(e->principalSigmaPx.x(), priorPx * 1.001);
  // Across the horizon the lines do place it.
  EXPECT_NEAR(e->camera.principalPx.y(), truth.principalPx.y(), 2.0);
  EXPECT_LT(e->principalSigmaPx.y(), 0.25 * priorPx);
  // Honest: the truth lies within three of the reported sigmas on each axis.
  for (int a = 0; a < 2; ++a)
    EXPECT_LT(std::abs(e->camera.principalPx[a] - truth.principalPx[a]), 3 * e->principalSigmaPx[a])
        << a;
  for (int k : {0, 2}) {
    const Vec3 th = truth.vanishingPointOf(Vec3::Unit(k));
    const Vec2 tp(th.x() / th.z(), th.y() / th.z());
    EXPECT_LT((e->vanishingPointsPx[k] - tp).norm(), 0.01 * (tp - truth.principalPx).norm()) << k;
  }
}

TEST(EstimateCamera, CeilingOutOfViewFollowsTheVisibleFloorCrease) {
  // A 3.2 m deep room seen from 1.5 m, tilted down so the back wall's top edge is above the
  // photo. The floor crease fixes the wall's distance; the ceiling then comes from the height
  // prior (2.7 m over a 1.6 m eye, scaled to the camera's height), not from a 5 m-deep wall.
  const double zb = -3.2, hc = 2.7 * 1.5 / 1.6;
  const Camera truth = makeCamera(640, 480, 350, 3, -24, 0);
  const auto wall = trueBackWall(truth, zb, hc);
  ASSERT_LT(std::max(wall[0].y(), wall[1].y()), -20.0);  // the top edge is out of view
  for (int i = 2; i < 4; ++i)                            // the floor crease in view
    ASSERT_TRUE(wall[i].x() > 0 && wall[i].x() < 640 && wall[i].y() > 0 && wall[i].y() < 480);
  EstimateOptions o;
  o.cameraHeightM = truth.heightM;
  const auto e = estimateCamera(drawRoom(truth, roomLines(false, zb, hc)), o);
  ASSERT_TRUE(e.ok()) << e.error().message();
  expectSane(*e);
  for (int i = 2; i < 4; ++i) EXPECT_LT((e->backWallPx[i] - wall[i]).norm(), 3.0) << i;
  for (int i = 0; i < 2; ++i)
    EXPECT_LT((e->backWallPx[i] - wall[i]).norm(), 8.0)
        << i << ": " << e->backWallPx[i].transpose() << " vs " << wall[i].transpose();
}

TEST(EstimateCamera, BadInputAndCancellation) {
  const auto empty = estimateCamera(ImageF());
  ASSERT_FALSE(empty.ok());
  EXPECT_EQ(empty.error().key, "photo");
  const auto two = estimateCamera(ImageF(32, 32, 2));
  ASSERT_FALSE(two.ok());
  EXPECT_EQ(two.error().key, "photo");
  CancelToken token;
  token.cancel();
  EstimateOptions o;
  o.cancel = &token;
  const auto c = estimateCamera(drawRoom(makeCamera(640, 480, 560, 15, -8, 0), roomLines()), o);
  ASSERT_FALSE(c.ok());
  EXPECT_EQ(c.error().reason, "cancelled");
  // Non-finite pixels do not poison the estimate.
  ImageF nan = drawRoom(makeCamera(640, 480, 560, 15, -8, 0), roomLines());
  nan.at(10, 10) = std::nanf("");
  nan.at(11, 10) = INFINITY;
  const auto n = estimateCamera(nan);
  ASSERT_TRUE(n.ok());
  expectSane(*n);
}

TEST(CorrectEstimate, KeepsWhatTheUserFixedAndStaysConsistent) {
  const Camera truth = makeCamera(640, 480, 560, 15, -8, 0);
  const auto first = estimateCamera(drawRoom(truth, roomLines()));
  ASSERT_TRUE(first.ok());

  // A locked focal length is kept exactly; the rotation is re-fitted to it.
  EstimateCorrection lock;
  lock.lockedFocalPx = 600.0;
  const auto locked = correctEstimate(*first, lock);
  ASSERT_TRUE(locked.ok()) << locked.error().message();
  expectSane(*locked);
  EXPECT_DOUBLE_EQ(locked->camera.focalPx, 600.0);
  EXPECT_DOUBLE_EQ(locked->focalMinPx, 600.0);
  EXPECT_LT(rotationErrorDeg(locked->camera, truth), 3.0);

  // A moved corner is kept exactly, and the box is one the room builder accepts.
  EstimateCorrection move;
  const Vec2 tl = first->backWallPx[0] + Vec2(-12, -9);
  move.backWallCornersPx[0] = tl;
  const auto moved = correctEstimate(*first, move);
  ASSERT_TRUE(moved.ok()) << moved.error().message();
  EXPECT_EQ(moved->backWallPx[0], tl);
  EXPECT_TRUE(roomFromBackWall(moved->camera, moved->backWallPx).ok());
  // The other corners stay on lines through the vanishing points: TR on the top edge through
  // the x vanishing point, BL on the left edge through the y one.
  const Vec3 top = Vec3(tl.x(), tl.y(), 1).cross(moved->vanishingPoints[0].homogeneousPx);
  const Vec2 tr = moved->backWallPx[1];
  EXPECT_LT(std::abs(top.dot(Vec3(tr.x(), tr.y(), 1))) / top.head<2>().norm(), 1.0);

  // A vanishing point given by two user lines: the user's lines are met (residual < 1 px),
  // even where they disagree with the photo's lines (here: a camera turned by 2 degrees).
  const Camera turned = makeCamera(640, 480, 560, 17, -8, 0);
  EstimateCorrection vp;
  {
    Vec2 a0, b0, a1, b1;
    ASSERT_TRUE(projectSegment(turned, {{-2.5, 0, -4.5}, {-2.5, 0, -1.0}}, a0, b0));
    ASSERT_TRUE(projectSegment(turned, {{2.5, 0, -4.5}, {2.5, 0, -1.0}}, a1, b1));
    vp.vanishingLinesPx[2] = std::array<Vec2, 4>{a0, b0, a1, b1};
  }
  const auto user = correctEstimate(*first, vp);
  ASSERT_TRUE(user.ok()) << user.error().message();
  expectSane(*user);
  int userLines = 0;
  for (const auto& s : user->segments)
    if (s.userGiven) {
      ++userLines;
      EXPECT_EQ(s.family, 2);
      EXPECT_LT(s.residualPx, 1.0);
    }
  EXPECT_EQ(userLines, 2);
  EXPECT_DOUBLE_EQ(user->confidence[2], user->vanishingPoints[2].confidence);

  // Bad corrections are named.
  EstimateCorrection bad;
  bad.lockedFocalPx = -3;
  const auto b = correctEstimate(*first, bad);
  ASSERT_FALSE(b.ok());
  EXPECT_NE(b.error().key.find("correction"), std::string::npos);
  EstimateCorrection above;
  above.backWallCornersPx[3] = Vec2(100, 5);  // a floor corner far above the horizon
  above.backWallCornersPx[2] = Vec2(500, 5);
  EXPECT_FALSE(correctEstimate(*first, above).ok());
}

TEST(CorrectEstimate, UserLinesOnABlankPhotoGiveTheCamera) {
  // Nothing to detect: a fallback. The user draws two lines along x and two along z.
  const auto blank = estimateCamera(ImageF(640, 480, 3, 0.4f));
  ASSERT_TRUE(blank.ok());
  ASSERT_FALSE(blank->manhattan);
  const Camera truth = makeCamera(640, 480, 500, 20, -10, 0);
  auto lines = [&](const Seg3& a, const Seg3& b) {
    Vec2 a0, b0, a1, b1;
    EXPECT_TRUE(projectSegment(truth, a, a0, b0));
    EXPECT_TRUE(projectSegment(truth, b, a1, b1));
    return std::array<Vec2, 4>{a0, b0, a1, b1};
  };
  EstimateCorrection c;
  c.vanishingLinesPx[0] = lines({{-2, 0, -5}, {2, 0, -5}}, {{-2, 2.5, -5}, {2, 2.5, -5}});
  c.vanishingLinesPx[2] = lines({{-2, 0, -5}, {-2, 0, -1.5}}, {{2, 0, -5}, {2, 0, -1.5}});
  const auto e = correctEstimate(*blank, c);
  ASSERT_TRUE(e.ok()) << e.error().message();
  expectSane(*e);
  EXPECT_NEAR(e->camera.focalPx / truth.focalPx, 1.0, 0.02);
  EXPECT_LT(rotationErrorDeg(e->camera, truth), 0.5);
  EXPECT_GT(e->confidence[0], 0.5);
  EXPECT_GT(e->confidence[2], 0.5);
}

TEST(CorrectEstimate, AFixedCameraIsKeptAndTheBackWallFoundForIt) {
  const Camera truth = makeCamera(640, 480, 420, 8, -6, 0);
  const ImageF photo = drawRoom(truth, roomLines());
  // A poor first estimate (a level camera from a wrong prior), then the user's exact camera.
  EstimateOptions o;
  o.priorFocalPx = 700;
  const auto first = estimateCameraFromSegments(640, 480, {}, o);
  ASSERT_TRUE(first.ok());
  auto withLines = estimateCamera(photo);
  ASSERT_TRUE(withLines.ok());
  CameraEstimate previous = *first;
  previous.segments = withLines->segments;
  EstimateCorrection c;
  Camera given = truth;
  given.principalPx = Vec2(318, 243);  // kept, even off centre
  c.fixedCamera = given;
  const auto e = correctEstimate(previous, c);
  ASSERT_TRUE(e.ok()) << e.error().message();
  expectSane(*e);
  EXPECT_EQ(e->camera.focalPx, given.focalPx);
  EXPECT_EQ(e->camera.principalPx, given.principalPx);
  EXPECT_LT(rotationErrorDeg(e->camera, given), 1e-9);
  const auto bw = backWallCornersPx(given, RoomBox{-2.5, 2.5, -5, 0.5, 2.7});
  for (int i = 0; i < 4; ++i) EXPECT_LT((e->backWallPx[i] - bw[i]).norm(), 4.0) << "corner " << i;
  Camera wrong = given;
  wrong.widthPx = 320;
  c.fixedCamera = wrong;
  EXPECT_FALSE(correctEstimate(previous, c).ok());
}

TEST(EstimateCamera, GroundTruthRooms) {
  INLAY_REQUIRE_SHARED();
  int scenes = 0, goodLayouts = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::sharedDir() + "/scenes")) {
    if (!std::filesystem::exists(entry.path() / "truth.json")) continue;
    std::ifstream f(entry.path() / "truth.json");
    const auto t = nlohmann::json::parse(f);
    const auto& cam = t["camera"];
    const auto loaded = loadImage((entry.path() / "photo.png").string());
    ASSERT_TRUE(loaded.ok()) << loaded.error().message();
    const ImageF& im = loaded->linearRgb;
    const auto e = estimateCamera(im);
    ASSERT_TRUE(e.ok()) << e.error().message();
    expectSane(*e);
    Camera truth;
    truth.widthPx = t["image"]["width"];
    truth.heightPx = t["image"]["height"];
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) truth.worldFromCamera(r, k) = cam["R_cam_to_world_opengl"][r][k];
    const double fTrue = cam["focal_px"];
    EXPECT_NEAR(e->camera.focalPx / fTrue, 1.0, 0.05) << entry.path();
    EXPECT_LT(rotationErrorDeg(e->camera, truth), 1.0) << entry.path();
    const auto& k = t["room"]["corners"];
    const char* names[4] = {"ceiling_front_left", "ceiling_front_right", "floor_front_right",
                            "floor_front_left"};
    double worst = 0;
    for (int i = 0; i < 4; ++i) {
      ASSERT_FALSE(k[names[i]]["pixel"].is_null());
      const Vec2 p(k[names[i]]["pixel"][0].get<double>(), k[names[i]]["pixel"][1].get<double>());
      worst = std::max(worst, (e->backWallPx[i] - p).norm());
    }
    goodLayouts += worst < 3.0;
    ++scenes;
  }
  EXPECT_GE(scenes, 1);
  // Stated accuracy: half the rooms within 3 px at every back-wall corner (the others miss a
  // wall corner hidden by clutter or outside the photo; see the benchmark).
  EXPECT_GE(2 * goodLayouts, scenes);
}

}  // namespace
}  // namespace inlay
