// camera.vignetting (engine/pipeline.h): the fall-off V = 1 - v r^2, devignetting a photo and
// putting V back, and the rule "auto" applies to the light fit's estimate (the pipeline on the
// bundled example: engine_pipeline_test.cpp, Engine.AVignettedPhotosLightIsFittedInDevignettedRadiance).
#include "inlay/engine/pipeline.h"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace inlay {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Vignetting, FalloffIsOneAtTheCentreAndOneMinusVAtTheCornerForAnyV) {
  // A 4 x 2 image: every pixel centre is off-centre; r^2 <= 1 (the corner pixel's centre < 1).
  for (double v : {0.0, 0.05, 0.3, VignettingKeys::kMax}) {
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 4; ++x) {
        const double V = vignettingFalloff(v, x, y, 4, 2);
        EXPECT_TRUE(V <= 1 && V >= 1 - v) << v << " " << x << "," << y;
      }
  }
  // A big image: the centre pixel is 1 to 1e-5, the corner pixel 1 - v to 1e-3.
  EXPECT_NEAR(vignettingFalloff(0.3, 1000, 750, 2001, 1501), 1.0, 1e-5);
  EXPECT_NEAR(vignettingFalloff(0.3, 0, 0, 2001, 1501), 0.7, 2e-3);
  // Stiff strengths: clamped to [0, kMax] (V >= 0.1), a non-finite one is none.
  EXPECT_NEAR(vignettingFalloff(5.0, 0, 0, 2001, 1501), 1 - VignettingKeys::kMax, 2e-3);
  EXPECT_EQ(vignettingFalloff(-1.0, 0, 0, 2001, 1501), 1.0);
  EXPECT_EQ(vignettingFalloff(kNaN, 0, 0, 2001, 1501), 1.0);
  EXPECT_EQ(vignettingFalloff(kInf, 0, 0, 2001, 1501), 1.0);
  // A one-pixel image is its own centre.
  EXPECT_EQ(vignettingFalloff(0.5, 0, 0, 1, 1), 1.0);
}

TEST(Vignetting, DevignettingAndPuttingItBackKeepsThePhotoAndItsNonFiniteValues) {
  ImageF photo(9, 7, 4);
  for (int y = 0; y < photo.height; ++y)
    for (int x = 0; x < photo.width; ++x)
      for (int c = 0; c < 4; ++c) photo.at(x, y, c) = 0.1f + 0.02f * float(x + y + c);
  photo.at(0, 0, 0) = std::numeric_limits<float>::quiet_NaN();
  photo.at(8, 6, 1) = std::numeric_limits<float>::infinity();
  photo.at(8, 0, 2) = 0.f;
  for (double v : {0.0, 0.3, VignettingKeys::kMax, 7.0, kNaN, -0.2}) {
    ImageF image = photo;
    divideByVignetting(image, v);
    const double applied = std::isfinite(v) ? std::clamp(v, 0.0, VignettingKeys::kMax) : 0.0;
    EXPECT_EQ(image.at(8, 0, 3), photo.at(8, 0, 3)) << v;  // alpha is kept
    EXPECT_EQ(image.at(8, 0, 2), 0.f) << v;
    EXPECT_TRUE(std::isnan(image.at(0, 0, 0))) << v;  // not made finite, nor spread
    EXPECT_TRUE(std::isinf(image.at(8, 6, 1))) << v;
    // A corner is brightened by 1 / V, up to 1 / (1 - v).
    const double corner = image.at(0, 0, 1) / photo.at(0, 0, 1);
    EXPECT_GE(corner, 1.0) << v;
    EXPECT_LE(corner, 1 / (1 - applied) + 1e-6) << v;
    if (applied > 0) {  // the corner pixel's centre is at r^2 = 0.77
      EXPECT_GT(corner, 1 / (1 - 0.7 * applied)) << v;
    }
    divideByVignetting(image, v, /*undo=*/true);
    for (size_t i = 0; i < image.data.size(); ++i) {
      if (std::isfinite(photo.data[i])) {
        EXPECT_NEAR(image.data[i], photo.data[i], 1e-6f * photo.data[i]) << v;
      }
    }
  }
  // A flat photo becomes a radial bowl: brighter toward the corners, never below the photo.
  ImageF flat(16, 12, 3);
  for (float& f : flat.data) f = 0.5f;
  divideByVignetting(flat, 0.4);
  EXPECT_GT(flat.at(0, 0, 0), flat.at(4, 3, 0));
  EXPECT_GT(flat.at(4, 3, 0), flat.at(8, 6, 0));
  for (float f : flat.data) EXPECT_TRUE(std::isfinite(f) && f >= 0.5f);
  ImageF empty;
  divideByVignetting(empty, 0.3);  // no pixel: nothing to do, no crash
  EXPECT_TRUE(empty.data.empty());
}

TEST(Vignetting, AutoAppliesOnlyAConfidentEstimate) {
  const VignettingKeys none, automatic{VignettingKeys::Mode::Auto, 0.0};  // "none" is the default
  const VignettingKeys given{VignettingKeys::Mode::Given, 0.25};
  EXPECT_EQ(vignettingToApply(automatic, 0.2), 0.2);
  EXPECT_EQ(vignettingToApply(automatic, kMinAutoVignetting), kMinAutoVignetting);
  EXPECT_EQ(vignettingToApply(automatic, 0.03), 0.0);  // a plain photo's estimate
  EXPECT_EQ(vignettingToApply(automatic, 0.0), 0.0);
  EXPECT_EQ(vignettingToApply(automatic, kMaxAutoVignetting), 0.0);  // at the search's bound
  EXPECT_EQ(vignettingToApply(automatic, kNaN), 0.0);
  EXPECT_EQ(vignettingToApply(automatic, kInf), 0.0);
  EXPECT_EQ(vignettingToApply(none, 0.3), 0.0);
  EXPECT_EQ(none.mode, VignettingKeys::Mode::None);
  EXPECT_EQ(vignettingToApply(given, 0.0), 0.25);  // the scene file's strength, estimate or not
  EXPECT_EQ(vignettingToApply(given, kNaN), 0.25);
  EXPECT_EQ(vignettingToApply({VignettingKeys::Mode::Given, 0.0}, 0.4), 0.0);
}

}  // namespace
}  // namespace inlay
