// A packet's camera directions two lanes at a time (render/src/camera_directions.h) must be
// Camera::directionThroughPixel()'s to the bit: the renderer's camera rays, and so every path,
// stay the same whether a pixel is rendered alone or in a packet.
#include "../render/src/camera_directions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace inlay {
namespace {

bool sameBits(const Vec3& a, const Vec3& b) {
  return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0;
}

// A camera looking anywhere (a random rotation), with a random focal length and principal point.
Camera randomCamera(std::mt19937_64& g) {
  std::uniform_real_distribution<double> u(-1, 1), focal(50, 8000), size(64, 6000);
  Camera cam;
  cam.widthPx = int(size(g)), cam.heightPx = int(size(g));
  cam.focalPx = focal(g);
  cam.principalPx = Vec2((0.5 + 0.2 * u(g)) * cam.widthPx, (0.5 + 0.2 * u(g)) * cam.heightPx);
  cam.worldFromCamera = Eigen::Quaterniond(u(g), u(g), u(g), u(g)).normalized().toRotationMatrix();
  return cam;
}

// Pixels in and far outside the frame, every lane count 0..8 (the odd lane goes alone).
TEST(CameraDirections, MatchDirectionThroughPixelBitForBit) {
  std::mt19937_64 g(18);
  std::uniform_real_distribution<double> u(-0.5, 1.5);
  int mismatches = 0, checked = 0;
  for (int c = 0; c < 2000; ++c) {
    const Camera cam = randomCamera(g);
    for (int n = 0; n <= 8; ++n) {
      double px[8], py[8];
      for (int k = 0; k < n; ++k) px[k] = u(g) * cam.widthPx, py[k] = u(g) * cam.heightPx;
      Vec3 out[8];
      detail::directionsThroughPixels(cam, n, px, py, out);
      for (int k = 0; k < n; ++k, ++checked)
        mismatches += sameBits(out[k], cam.directionThroughPixel(Vec2(px[k], py[k]))) ? 0 : 1;
    }
  }
  EXPECT_EQ(mismatches, 0) << "of " << checked;
}

// Extreme pixels and cameras: the direction is the library's also where it is not finite, and
// a zero-length direction (a zero matrix) is returned as it is, as normalized() does.
TEST(CameraDirections, ExtremeInputsMatchTheLibrary) {
  const double inf = std::numeric_limits<double>::infinity(),
               nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Camera> cams(3, levelCamera(640, 480, 500, 1.6));
  cams[1].focalPx = 1e-300;
  cams[2].worldFromCamera = Mat3::Zero();
  const std::vector<double> xs = {0, 320, -1e300, 1e300, inf, -inf, nan, 1e-310};
  for (const Camera& cam : cams)
    for (double x : xs)
      for (double y : xs) {
        const double px[2] = {x, 320}, py[2] = {y, 240};
        Vec3 out[2];
        detail::directionsThroughPixels(cam, 2, px, py, out);
        const Vec3 ref = cam.directionThroughPixel(Vec2(x, y));
        for (int i = 0; i < 3; ++i) {
          EXPECT_EQ(std::isnan(out[0][i]), std::isnan(ref[i])) << x << " " << y;
          if (!std::isnan(ref[i])) {
            EXPECT_EQ(out[0][i], ref[i]) << x << " " << y;
          }
        }
        EXPECT_TRUE(sameBits(out[1], cam.directionThroughPixel(Vec2(320, 240))));
      }
}

}  // namespace
}  // namespace inlay
