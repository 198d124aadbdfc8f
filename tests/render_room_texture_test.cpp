// The path tracer's room texture (render/src/room_texture.h) against ProjectedAlbedo, whose
// answers it must give to the bit: the pixel a room point shows, its albedo, its photo radiance.
#include "../render/src/room_texture.h"
#include "render_test_scenes.h"
#include "test_support.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace inlay
