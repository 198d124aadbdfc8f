// Differential composite and exposure: the header's formula, bit-identity where nothing
// changed, clamping, and no non-finite output.
#include "test_support.h"

#include "inlay/render/composite.h"

#include "inlay/modeling/image_io.h"
#include "inlay/modeling/response.h"

#include <cstring>

namespace inlay {
namespace {

namespace fs = std::filesystem;

ImageF filled(int w, int h, int c, uint32_t seed, float scale) {
  ImageF im(w, h, c);
  for (float& v : im.data) {
    seed = seed * 1664525u + 1013904223u;
    v = float(seed >> 8) / 16777216.f * scale;
  }
  return im;
}

TEST(Composite, FollowsDebevecFormula) {
  const int w = 16, h = 8;
  const ImageF photo = filled(w, h, 3, 1, 1.f), with = filled(w, h, 3, 2, 2.f),
               without = filled(w, h, 3, 3, 2.f), mask = filled(w, h, 1, 4, 1.f);
  const ImageF out = differentialComposite(photo, with, without, mask);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const double m = mask.at(x, y);
        const double expected =
            std::max(0.0, m * with.at(x, y, c) +
                              (1 - m) * (photo.at(x, y, c) + with.at(x, y, c) - without.at(x, y, c)));
        ASSERT_NEAR(out.at(x, y, c), expected, 1e-6 * (1 + expected));
      }
}

TEST(Composite, UnchangedPixelsAreThePhotoBitForBit) {
  const int w = 16, h = 8;
  const ImageF photo = filled(w, h, 3, 5, 3.f);  // including values above 1
  ImageF render = filled(w, h, 3, 6, 1.f);
  ImageF mask(w, h, 1, 0.f);
  const ImageF out = differentialComposite(photo, render, render, mask);
  EXPECT_EQ(std::memcmp(out.data.data(), photo.data.data(), photo.data.size() * sizeof(float)), 0);
  // One pixel differs: only that pixel changes.
  ImageF with = render;
  with.at(3, 2, 1) += 0.25f;
  const ImageF out2 = differentialComposite(photo, with, render, mask);
  for (size_t i = 0; i < out2.data.size(); ++i) {
    if (i == (size_t(2) * w + 3) * 3 + 1) EXPECT_FLOAT_EQ(out2.data[i], photo.data[i] + 0.25f);
    else ASSERT_EQ(out2.data[i], photo.data[i]);
  }
}

TEST(Composite, ClampsNegativeAndNeverProducesNonFinite) {
  ImageF photo(2, 1, 3, 0.1f), with(2, 1, 3, 0.f), without(2, 1, 3, 1.f), mask(2, 1, 1, 0.f);
  with.at(1, 0, 0) = std::numeric_limits<float>::quiet_NaN();
  with.at(1, 0, 1) = std::numeric_limits<float>::infinity();
  const ImageF out = differentialComposite(photo, with, without, mask);
  for (float v : out.data) {
    EXPECT_TRUE(std::isfinite(v));
    EXPECT_GE(v, 0.f);
  }
  EXPECT_EQ(out.at(0, 0, 0), 0.f);  // 0.1 + 0 - 1 clamps to 0
}

// An object's shadow on a sunlit patch the photo clips (1.0 in red and green, the model's
// radiance 6 there): the photo + with - without would be 1 + 0.4 - 6 < 0 in the clipped
// channels (a black or blue hole); with the unclipped radiance the shadow is the render's 0.4.
// Untouched clipped pixels stay the photo's 1.0, bit for bit; an unclipped image of another size
// is ignored; a NaN in it marks nothing (the photo as before).
TEST(Composite, ShadowOnAClippedPatchUsesTheUnclippedRadiance) {
  ImageF photo(3, 1, 3, 1.0f), with(3, 1, 3, 6.0f), without(3, 1, 3, 6.0f), unclipped(3, 1, 3, 6.0f);
  for (int x = 0; x < 3; ++x)  // blue is not clipped
    photo.at(x, 0, 2) = 0.8f, unclipped.at(x, 0, 2) = 0.8f, with.at(x, 0, 2) = 0.8f,
                   without.at(x, 0, 2) = 0.8f;
  with.setRgb(0, 0, Vec3(0.4, 0.4, 0.3));  // in the shadow
  without.setRgb(0, 0, Vec3(6.0, 6.0, 0.8));
  for (int c = 0; c < 3; ++c) unclipped.at(2, 0, c) = std::nanf("");
  with.setRgb(2, 0, Vec3(0.4, 0.4, 0.3));
  without.setRgb(2, 0, Vec3(6.0, 6.0, 0.8));
  const ImageF noMask;
  const ImageF plain = differentialComposite(photo, with, without, noMask);
  EXPECT_EQ(plain.at(0, 0, 0), 0.f);  // the hole the change removes
  const ImageF out = differentialComposite(photo, with, without, noMask, &unclipped);
  EXPECT_NEAR(out.at(0, 0, 0), 0.4f, 1e-6);
  EXPECT_NEAR(out.at(0, 0, 1), 0.4f, 1e-6);
  EXPECT_NEAR(out.at(0, 0, 2), 0.3f, 1e-6);  // blue, not clipped: the photo's 0.8 + 0.3 - 0.8
  for (int c = 0; c < 3; ++c) EXPECT_EQ(out.at(1, 0, c), photo.at(1, 0, c));  // untouched
  EXPECT_EQ(out.at(2, 0, 0), 0.f);  // a NaN model marks nothing: the photo's 1 + 0.4 - 6, clamped
  const ImageF small(2, 1, 3, 6.0f);
  EXPECT_TRUE(std::memcmp(differentialComposite(photo, with, without, noMask, &small).data.data(),
                          plain.data.data(), plain.data.size() * sizeof(float)) == 0);
}

TEST(Composite, FullMaskShowsTheRender) {
  const ImageF photo = filled(4, 4, 3, 7, 1.f), with = filled(4, 4, 3, 8, 1.f),
               without = filled(4, 4, 3, 9, 1.f);
  const ImageF out = differentialComposite(photo, with, without, ImageF(4, 4, 1, 1.f));
  for (size_t i = 0; i < out.data.size(); ++i) EXPECT_FLOAT_EQ(out.data[i], with.data[i]);
}

// out = f(f^-1(photo) + with - without): the photo linearised by its camera response, the
// composite encoded with it. Untouched pixels keep the photo's codes in the PNG bit for bit;
// changed ones are the response's encoding of the composite radiance.
TEST(Composite, ReencodedThroughTheCameraResponseKeepsUntouchedCodes) {
  const int w = 32, h = 16;
  const CameraResponse response = CameraResponse::toeShoulder({0.7, 0.3, 20});
  ImageF photo(w, h, 3);
  std::vector<unsigned char> codes(photo.data.size());
  for (size_t i = 0; i < codes.size(); ++i) {
    codes[i] = (unsigned char)((i * 37) % 251);
    photo.data[i] = response.table8()[codes[i]];  // f^-1(photo)
  }
  ImageF with = filled(w, h, 3, 2, 0.5f), without = with, mask(w, h, 1, 0.f);
  for (int x = 4; x < 12; ++x)  // the object adds light to a band of rows 5 and 6 only
    for (int y = 5; y < 7; ++y)
      for (int c = 0; c < 3; ++c) with.at(x, y, c) += 0.05f;
  const ImageF out = differentialComposite(photo, with, without, mask);
  const fs::path dir = test::tempDir("composite_response");
  SaveOptions so;
  so.response = &response;
  ASSERT_TRUE(saveImage((dir / "out.png").string(), out, so).ok());
  auto back = loadImage((dir / "out.png").string());
  ASSERT_TRUE(back.ok());
  const std::vector<unsigned char> written = srgbCodesOf(back->linearRgb);
  int changed = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const size_t i = (size_t(y) * w + x) * 3 + size_t(c);
        const bool touched = x >= 4 && x < 12 && y >= 5 && y < 7;
        const int expected = touched ? int(std::lround(255 * response.encode(photo.data[i] + 0.05)))
                                     : codes[i];
        EXPECT_NEAR(int(written[i]), expected, touched ? 1 : 0) << x << "," << y;
        changed += written[i] != codes[i];
      }
  EXPECT_GT(changed, 0);
}

TEST(Exposure, ScalesByPowersOfTwo) {
  ImageF im = filled(4, 4, 3, 10, 1.f);
  const ImageF original = im;
  applyExposure(im, 0.0);
  EXPECT_EQ(std::memcmp(im.data.data(), original.data.data(), im.data.size() * sizeof(float)), 0);
  applyExposure(im, 1.0);
  for (size_t i = 0; i < im.data.size(); ++i) EXPECT_FLOAT_EQ(im.data[i], 2.f * original.data[i]);
  applyExposure(im, -2.5);
  for (size_t i = 0; i < im.data.size(); ++i)
    EXPECT_NEAR(im.data[i], original.data[i] * std::exp2(-1.5), 1e-6);
}

}  // namespace
}  // namespace inlay
