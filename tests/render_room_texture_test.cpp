// The path tracer's room texture (render/src/room_texture.h) against ProjectedAlbedo, whose
// answers it must give to the bit: the pixel a room point shows, its albedo, its photo radiance.
#include "../render/src/room_texture.h"
#include "render_test_scenes.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace inlay {
namespace {

using detail::RoomTexture;

// A box room seen by a small camera, with an albedo and a photo radiance that differ in every
// pixel, some radiance unusable, and some pixels' surface ids replaced by -1, an id no surface
// has, and a large id.
ProjectedAlbedo testAlbedo(int w, int h) {
  ProjectedAlbedo pa;
  pa.camera = test::testCamera(w, h, 60);
  pa.albedo = ImageF(w, h, 3);
  pa.photoRadiance = ImageF(w, h, 3);
  pa.photoRadianceUsable.assign(size_t(w) * h, 1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      pa.albedo.setRgb(x, y, Vec3(x / 64.0, y / 64.0, 0.25 + 1e-7 * x));
      pa.photoRadiance.setRgb(x, y, Vec3(1.0 + x, 2.0 + y / 3.0, 0.1 * (x + y)));
      if ((x + 2 * y) % 7 == 0) pa.photoRadianceUsable[size_t(y) * w + x] = 0;
    }
  const SceneGeometry room = test::boxRoom();
  pa.surfaceMean.assign(room.surfaces.size(), Vec3(0.1, 0.2, 0.3));
  pa.computeFirstSurfaces(room);
  pa.firstSurfacePerPixel[0] = -1;
  pa.firstSurfacePerPixel[1] = 17;
  pa.firstSurfacePerPixel[2] = 1 << 29;
  return pa;
}

TEST(RoomTexture, AnswersAsProjectedAlbedoToTheBit) {
  const int w = 32, h = 24;
  const ProjectedAlbedo pa = testAlbedo(w, h);
  const RoomTexture room(pa);
  ASSERT_EQ(room.texelCount(), size_t(w) * h);
  int shown = 0, usable = 0;
  // Points through every pixel (and beyond the frame) at several depths, claimed by every id.
  for (int y = -2; y < h + 2; ++y)
    for (int x = -2; x < w + 2; ++x)
      for (double depth : {0.5, 2.0, 3.999}) {
        const Ray r = pa.camera.rayThroughPixel(Vec2(x + 0.25, y + 0.75));
        const Vec3 p = r.at(depth / std::max(1e-9, -r.direction.z()));
        for (int id : {-1, 0, 1, 2, 3, 4, 5, 17, 1 << 29}) {
          const std::optional<size_t> pixel = pa.pixelShowing(id, p);
          const RoomTexture::Texel* t = room.texelShowing(id, p);
          ASSERT_EQ(pixel.has_value(), t != nullptr) << x << " " << y << " " << id;
          if (pixel) {
            ASSERT_EQ(room.indexOf(t), *pixel);
          }
          ASSERT_EQ(room.albedo(id, t), pa.albedoAtPixel(id, pixel)) << x << " " << y << " " << id;
          Vec3 fromTexture = Vec3::Zero(), fromAlbedo = Vec3::Zero();
          const bool a = RoomTexture::radiance(t, &fromTexture),
                     b = pa.radianceAtPixel(pixel, &fromAlbedo);
          ASSERT_EQ(a, b) << x << " " << y << " " << id;
          if (a) {
            ASSERT_EQ(fromTexture, fromAlbedo);
          }
          shown += t != nullptr, usable += a;
          // texelAt() and shows() are texelShowing() in two steps.
          ASSERT_EQ(RoomTexture::shows(room.texelAt(p), id), t);
        }
      }
  EXPECT_GT(shown, w * h);  // the test met shown pixels, usable and unusable ones
  EXPECT_GT(usable, 0);
  EXPECT_LT(usable, shown);
  // The texels keep the ids and flags as given.
  EXPECT_EQ(room.texel(0).surface(), -1);
  EXPECT_EQ(room.texel(1).surface(), 17);
  EXPECT_EQ(room.texel(2).surface(), 1 << 29);
  EXPECT_FALSE(room.texel(0).radianceUsable());
  EXPECT_TRUE(room.texel(3).radianceUsable());
}

// prefetchRun() asks for the texels camera hits through a run of pixels read first: through
// every pixel centre of a run of a frame at the grid's size and at a preview's coarser ones, a
// point at any depth lands in a texel of the range it returns (a coarse pixel's centre that falls
// on the grid's lines between rows or columns may show either: those are left out). Fractions
// outside [0, 1), NaN and reversed runs ask for nothing.
TEST(RoomTexture, PrefetchRunCoversTheTexelsItsPixelsShow) {
  const int w = 32, h = 24;
  const ProjectedAlbedo pa = testAlbedo(w, h);
  const RoomTexture room(pa);
  int checked = 0;
  for (const auto& [bw, bh] : std::vector<std::array<int, 2>>{{w, h}, {21, 16}, {13, 10}}) {
    for (int y = 0; y < bh; ++y)
      for (int x0 = 0; x0 < bw; x0 += 8) {
        const int n = std::min(8, bw - x0);
        const auto [first, last] =
            room.prefetchRun((x0 + 0.5) / bw, (x0 + n - 0.5) / bw, (y + 0.5) / bh);
        ASSERT_LE(first, last);
        for (int x = x0; x < x0 + n; ++x) {
          const Vec2 centre((x + 0.5) * w / bw, (y + 0.5) * h / bh);
          if (std::abs(centre.x() - std::round(centre.x())) < 1e-9 ||
              std::abs(centre.y() - std::round(centre.y())) < 1e-9)
            continue;
          const Ray r = pa.camera.rayThroughPixel(centre);
          for (double depth : {0.5, 2.0, 3.999}) {
            const RoomTexture::Texel* t = room.texelAt(r.at(depth / std::max(1e-9, -r.direction.z())));
            ASSERT_NE(t, nullptr);
            EXPECT_GE(room.indexOf(t), first) << bw << " " << x << " " << y;
            EXPECT_LE(room.indexOf(t), last) << bw << " " << x << " " << y;
            ++checked;
          }
        }
      }
  }
  EXPECT_GT(checked, 3 * w * h);
  const double nan = std::nan("");
  for (const auto& [a, b, c] : std::vector<std::array<double, 3>>{{0.0, 1.0, 0.5},
                                                                  {-0.1, 0.5, 0.5},
                                                                  {0.6, 0.5, 0.5},
                                                                  {0.1, 0.5, 1.0},
                                                                  {0.1, 0.5, -1e-300},
                                                                  {nan, 0.5, 0.5},
                                                                  {0.1, nan, 0.5},
                                                                  {0.1, 0.5, nan},
                                                                  {0.1, 1e300, 0.5}}) {
    const auto range = room.prefetchRun(a, b, c);
    EXPECT_GT(range.first, range.second) << a << " " << b << " " << c;
  }
  EXPECT_GT(RoomTexture().prefetchRun(0.1, 0.2, 0.3).first, 0u);  // an empty texture
}

}  // namespace
}  // namespace inlay
