// The camera's pixel filter (TracerOptions::pixelFilterWidth, render/src/pixel_filter.h): the
// box keeps each sample in its pixel; Cycles' Blackman-Harris window of width w reaches w
// pixels either side of the centre with the spread Cycles gives it, so an object's outline
// reaches into the next pixel; bad widths and uniform numbers give finite positions.
#include "../render/src/pixel_filter.h"
#include "render_test_scenes.h"

#include "inlay/render/path_tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace inlay {
namespace {

using detail::PixelFilter;

// Mean and standard deviation of the sample positions over evenly spaced u (the filter's own
// moments: the positions are its inverse CDF).
std::pair<double, double> moments(const PixelFilter& f) {
  const int n = 100000;
  double s = 0, s2 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = f.position((i + 0.5) / n) - 0.5;
    s += x, s2 += x * x;
  }
  return {s / n, std::sqrt(s2 / n - (s / n) * (s / n))};
}

TEST(PixelFilter, TheBoxKeepsTheSampleInItsPixel) {
  for (double w : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
    const PixelFilter f(w);
    EXPECT_EQ(f.width(), 0.0);
    for (double u : {0.0, 0.25, 0.999}) EXPECT_DOUBLE_EQ(f.position(u), u);
  }
  const auto [mean, sd] = moments(PixelFilter(0));
  EXPECT_NEAR(mean, 0.0, 1e-9);
  EXPECT_NEAR(sd, std::sqrt(1.0 / 12), 1e-4);
}

// Cycles' 1.5 px window: support [-1.5, 1.5] px around the centre, symmetric, monotone in u,
// standard deviation 0.4155 px (the Blackman-Harris window over a width of 3 px).
TEST(PixelFilter, BlackmanHarrisHasCyclesSupportAndSpread) {
  const PixelFilter f(1.5);
  EXPECT_NEAR(f.position(0), 0.5 - 1.5, 1e-9);
  EXPECT_NEAR(f.position(1), 0.5 + 1.5, 1e-9);
  EXPECT_NEAR(f.position(0.5), 0.5, 1e-6);
  for (double u = 0.01; u < 0.5; u += 0.01)
    EXPECT_NEAR(f.position(u) - 0.5, 0.5 - f.position(1 - u), 1e-6);
  double last = -1e9;
  for (int i = 0; i <= 1000; ++i) {
    const double x = f.position(i / 1000.0);
    EXPECT_GE(x, last);
    last = x;
  }
  const auto [mean, sd] = moments(f);
  EXPECT_NEAR(mean, 0.0, 1e-6);
  EXPECT_NEAR(sd, 0.4155, 0.002);
}

TEST(PixelFilter, StiffWidthsAndNumbersGiveFinitePositions) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double w : {1e-12, 1e-6, 1.5, 8.0, 1e9, inf}) {
    const PixelFilter f(w);
    EXPECT_LE(f.width(), PixelFilter::kMaxWidth);
    for (double u : {-1.0, 0.0, 1e-300, 0.5, 1.0 - 1e-16, 1.0, 2.0, nan, inf, -inf}) {
      const double x = f.position(u);
      EXPECT_TRUE(std::isfinite(x)) << "width " << w << " u " << u;
      const double reach = f.width() > 0 ? f.width() : 0.5;  // not finite: the box
      EXPECT_GE(x, 0.5 - reach - 1e-9);
      EXPECT_LE(x, 0.5 + reach + 1e-9);
    }
  }
}

// A wall-sized object covering the right half of a w x h picture, its edge on the boundary
// between pixels w/2 - 1 and w/2.
RenderScene halfCoveredScene(int w, int h) {
  RenderScene s = test::roomScene(test::testCamera(w, h, 60), RoomBox{}, 0.5);
  s.lights.push_back(
      test::rectLight(Vec3(0, 2.5, -2), Vec3(0.3, 0, 0), Vec3(0, 0, 0.3), Vec3::Constant(5)));
  RoomBox slab;
  slab.xLeftM = 0, slab.xRightM = 1.9, slab.zBackM = -2.2, slab.zRearM = -2.0, slab.ceilingM = 3;
  s.objects.push_back(
      test::placedObject(test::boxMesh(slab), Vec3(0, -0.5, 0), Material::Kind::Diffuse));
  return s;
}

// The object's coverage (the mask) of column x of buffers bw x bh, rows of its middle third.
double maskCoverage(const RenderScene& s, const TracerOptions& o, int bw, int bh, int x) {
  PathTracer tracer(s, o);
  DifferentialBuffers b(bw, bh);
  EXPECT_TRUE(tracer.render(b, 0, 64, 3));
  double m = 0, n = 0;
  for (int y = bh / 3; y < 2 * bh / 3; ++y) m += b.sumMask.at(x, y), n += b.samples[size_t(y) * bw + x];
  return m / n;
}

// The edge between pixels 19 and 20 of 40. The object's coverage of pixel 19: none with the box,
// the window's tail beyond half a pixel with Cycles' 1.5 px (12 %); pixel 18 stays uncovered
// (its window ends at the edge). The default is the window.
TEST(PixelFilter, AnObjectsOutlineReachesTheNextPixelAsInCycles) {
  const int w = 40, h = 30;
  const RenderScene s = halfCoveredScene(w, h);
  TracerOptions box;
  box.pixelFilterWidth = 0;
  const TracerOptions cycles;  // the default
  EXPECT_EQ(cycles.pixelFilterWidth, 1.5);
  EXPECT_EQ(maskCoverage(s, box, w, h, 19), 0.0);
  EXPECT_EQ(maskCoverage(s, box, w, h, 20), 1.0);
  EXPECT_NEAR(maskCoverage(s, cycles, w, h, 19), 0.12, 0.03);
  EXPECT_NEAR(maskCoverage(s, cycles, w, h, 20), 0.88, 0.03);
  EXPECT_EQ(maskCoverage(s, cycles, w, h, 18), 0.0);
}

// The studio's coarse previews render buffers d times smaller than the camera: the filter's
// width is in the camera's pixels, so a coarse pixel samples its own d x d cell (the box) and
// the edge stays on its boundary; a 1.5-pixel window there would reach 1.5 coarse pixels
// (24 camera pixels at 1/16 resolution) and blur a dragged object's first frames away.
TEST(PixelFilter, ACoarsePreviewsPixelSamplesItsOwnCell) {
  const int w = 40, h = 30, d = 2;
  const RenderScene s = halfCoveredScene(w, h);
  const TracerOptions cycles;
  EXPECT_EQ(maskCoverage(s, cycles, w / d, h / d, 9), 0.0);
  EXPECT_EQ(maskCoverage(s, cycles, w / d, h / d, 10), 1.0);
}

}  // namespace
}  // namespace inlay
