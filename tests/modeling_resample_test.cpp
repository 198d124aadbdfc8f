// Working sizes and joint bilateral upsampling (image_resample.h): the working size keeps the
// aspect and the pixel budget; upsampling the ratio to the photo keeps the photo's full-size
// detail where the target is a smooth multiple of it (an albedo under smooth shading), which
// bilinear upsampling blurs; a shadow's edge stays where the photo has it; a constant stays that
// constant; a non-finite guide pixel leaves no NaN.
#include "inlay/modeling/image_io.h"
#include "inlay/modeling/image_resample.h"

#include <gtest/gtest.h>

#include <cmath>

namespace inlay {
namespace {

TEST(Resample, WorkingSizeKeepsTheAspectWithinTheBudget) {
  EXPECT_EQ(workingSizeFor(512, 384, 0.5e6), (std::array<int, 2>{512, 384}));
  EXPECT_EQ(workingSizeFor(512, 384, 0), (std::array<int, 2>{512, 384}));
  const auto s = workingSizeFor(4000, 3000, 0.5e6);
  EXPECT_LE(double(s[0]) * s[1], 0.5e6);
  EXPECT_GT(double(s[0]) * s[1], 0.49e6);
  EXPECT_NEAR(double(s[0]) / s[1], 4.0 / 3.0, 0.01);
  const auto thin = workingSizeFor(100000, 3, 1000);  // never a zero side
  EXPECT_GE(thin[0], 1);
  EXPECT_GE(thin[1], 1);
}

// A textured "photo" at full size and its shading-free albedo (photo over a smooth shading):
// the albedo known only at a quarter of the size comes back with the photo's texture.
TEST(Resample, GuidedUpsamplingKeepsTheGuidesDetailWhereBilinearBlursIt) {
  const int W = 400, H = 300, w = 100, h = 75;
  ImageF photo(W, H, 3), albedo(W, H, 3);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const double shading = 0.3 + 0.6 * x / W + 0.1 * std::sin(y * 0.02);
      const bool tile = ((x / 3) + (y / 3)) % 2 == 0;  // detail finer than a working pixel
      for (int c = 0; c < 3; ++c) {
        const double rho = (tile ? 0.7 : 0.3) + 0.1 * c + (x > W / 2 ? 0.1 : 0.0);
        albedo.at(x, y, c) = float(rho);
        photo.at(x, y, c) = float(rho * shading);
      }
    }
  const ImageF lowPhoto = resizeImage(photo, w, h), lowAlbedo = resizeImage(albedo, w, h);
  JointBilateralOptions ratio;
  ratio.ratio = true;
  const ImageF guided = jointBilateralUpsample(lowAlbedo, lowPhoto, photo, ratio);
  const ImageF bilinear = resizeImage(lowAlbedo, W, H);
  ASSERT_EQ(guided.width, W);
  ASSERT_EQ(guided.height, H);
  ASSERT_EQ(guided.channels, 3);
  double eGuided = 0, eBilinear = 0;
  for (size_t i = 0; i < albedo.data.size(); ++i) {
    ASSERT_TRUE(std::isfinite(guided.data[i]));
    eGuided += std::pow(guided.data[i] - albedo.data[i], 2);
    eBilinear += std::pow(bilinear.data[i] - albedo.data[i], 2);
  }
  eGuided = std::sqrt(eGuided / albedo.data.size());
  eBilinear = std::sqrt(eBilinear / albedo.data.size());
  EXPECT_LT(eGuided, 0.01) << "bilinear " << eBilinear;
  EXPECT_LT(eGuided, 0.1 * eBilinear);
}

// The direct light under a hard shadow edge that falls inside a working pixel: the photo drops
// five-fold there, the direct light's share of it from 0.9 to 0.1. Near the edge the upsampled
// direct light follows the photo's edge; bilinear smears it over the working pixels.
TEST(Resample, AShadowsEdgeStaysWhereThePhotoHasIt) {
  const int W = 403, H = 40, w = 100, h = 10;
  ImageF photo(W, H, 3), direct(W, H, 3);
  const int edge = 201;  // not on the working grid (4.03 photo pixels per working pixel)
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int c = 0; c < 3; ++c) {
        const double b = (x < edge ? 0.6 : 0.12) * (0.8 + 0.05 * c);
        photo.at(x, y, c) = float(b);
        direct.at(x, y, c) = float(b * (x < edge ? 0.9 : 0.1));
      }
  const ImageF lowPhoto = resizeImage(photo, w, h), lowDirect = resizeImage(direct, w, h);
  JointBilateralOptions ratio;
  ratio.ratio = true;
  const ImageF up = jointBilateralUpsample(lowDirect, lowPhoto, photo, ratio);
  const ImageF bilinear = resizeImage(lowDirect, W, H);
  double eUp = 0, eBilinear = 0;
  int n = 0;
  for (int y = 0; y < H; ++y)
    for (int x = edge - 8; x < edge + 8; ++x, ++n) {
      eUp += std::pow(up.at(x, y, 1) - direct.at(x, y, 1), 2);
      eBilinear += std::pow(bilinear.at(x, y, 1) - direct.at(x, y, 1), 2);
    }
  eUp = std::sqrt(eUp / n);
  eBilinear = std::sqrt(eBilinear / n);
  EXPECT_LT(eUp, 0.35 * eBilinear) << eUp << " against bilinear " << eBilinear;
}

TEST(Resample, GuidedUpsamplingOfAConstantIsThatConstantAndNeverNaN) {
  const int W = 90, H = 60;
  ImageF photo(W, H, 3);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int c = 0; c < 3; ++c) photo.at(x, y, c) = float(((x * 7 + y * 13 + c) % 17) / 17.0);
  photo.at(5, 5, 1) = std::numeric_limits<float>::quiet_NaN();
  photo.at(6, 5, 0) = std::numeric_limits<float>::infinity();
  const ImageF low = resizeImage(photo, 30, 20);
  const ImageF constant(30, 20, 1, 0.25f);
  const ImageF up = jointBilateralUpsample(constant, low, photo);
  ASSERT_EQ(up.channels, 1);
  for (float v : up.data) {
    ASSERT_TRUE(std::isfinite(v));
    EXPECT_NEAR(v, 0.25f, 1e-4);
  }
  // No larger guide: the target as it is.
  const ImageF same = jointBilateralUpsample(constant, low, low);
  EXPECT_EQ(same.data, constant.data);
}

}  // namespace
}  // namespace inlay
