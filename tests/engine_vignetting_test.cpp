// camera.vignetting (engine/pipeline.h): the fall-off V = 1 - v r^2, devignetting a photo and
// putting V back, the rule "auto" applies to the light fit's estimate, and the pipeline on the
// bundled example: the physics in devignetted radiance, the photo's codes kept where no object
// changes them, a vignetted photo's light fitted as the unvignetted photo's.
#include "inlay/engine/pipeline.h"
#include "inlay/modeling/image_io.h"
#include "inlay/render/path_tracer.h"
#include "test_support.h"

#include <cmath>
#include <filesystem>
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
  const VignettingKeys automatic, none{VignettingKeys::Mode::None, 0.0};
  const VignettingKeys given{VignettingKeys::Mode::Given, 0.25};
  EXPECT_EQ(vignettingToApply(automatic, 0.2), 0.2);
  EXPECT_EQ(vignettingToApply(automatic, kMinAutoVignetting), kMinAutoVignetting);
  EXPECT_EQ(vignettingToApply(automatic, 0.03), 0.0);  // a plain photo's estimate
  EXPECT_EQ(vignettingToApply(automatic, 0.0), 0.0);
  EXPECT_EQ(vignettingToApply(automatic, kMaxAutoVignetting), 0.0);  // at the search's bound
  EXPECT_EQ(vignettingToApply(automatic, kNaN), 0.0);
  EXPECT_EQ(vignettingToApply(automatic, kInf), 0.0);
  EXPECT_EQ(vignettingToApply(none, 0.3), 0.0);
  EXPECT_EQ(vignettingToApply(given, 0.0), 0.25);  // the scene file's strength, estimate or not
  EXPECT_EQ(vignettingToApply(given, kNaN), 0.25);
  EXPECT_EQ(vignettingToApply({VignettingKeys::Mode::Given, 0.0}, 0.4), 0.0);
}

SceneDoc exampleDoc() {
  auto loaded = loadSceneFile(std::string(INLAY_SOURCE_DIR) + "/resources/example/scene.json");
  EXPECT_TRUE(loaded.ok()) << (loaded.ok() ? "" : loaded.error().message());
  return loaded->doc;
}

RenderFrame renderFrame(const PreparedScene& ps, int spp) {
  PathTracer tracer(ps.renderScene);
  DifferentialBuffers buf(ps.photo.linearRgb.width, ps.photo.linearRgb.height);
  EXPECT_TRUE(tracer.render(buf, 0, spp, 1));
  RenderFrame f;
  f.width = buf.width, f.height = buf.height, f.spp = spp;
  f.withObjects = buf.meanWith();
  f.withoutObjects = buf.meanWithout();
  f.mask = buf.meanMask();
  return f;
}

const StageRecord* stageNamed(const PreparedScene& ps, const std::string& name) {
  for (const StageRecord& s : ps.stages)
    if (s.name == name) return &s;
  return nullptr;
}

double lightLuminance(const PreparedScene& ps) {
  double sum = 0;
  for (const AreaLight& l : ps.lighting.lights) sum += l.radiance.mean() * l.area();
  return sum;
}

// The example (a plain render, no vignetting) through a camera with v = 0.3, prepared with
// "auto": the estimate is applied, the light fit in the devignetted radiance finds the plain
// photo's lights within half of "none"'s error on the vignetted photo, and with no object
// the PNG keeps the vignetted photo's codes bit for bit. The plain example keeps "auto" at 0.
TEST(Vignetting, AVignettedPhotosLightIsFittedInDevignettedRadiance) {
  SceneDoc plainDoc = exampleDoc();
  auto plain = prepareScene(plainDoc);
  ASSERT_TRUE(plain.ok()) << plain.error().message();
  EXPECT_EQ(plain->vignetting, 0.0);  // a plain photo: nothing applied
  EXPECT_LT(plain->vignettingEstimated, kMinAutoVignetting);
  ASSERT_NE(stageNamed(*plain, "vignetting"), nullptr);
  EXPECT_TRUE(stageNamed(*plain, "vignetting")->ran);

  ImageF vignetted = plain->photo.linearRgb;
  divideByVignetting(vignetted, 0.3, /*undo=*/true);
  const auto dir = test::tempDir("engine_vignetting");
  const std::string photoPath = (dir / "vignetted.png").string();
  ASSERT_TRUE(saveImage(photoPath, vignetted).ok());
  SceneDoc doc = plainDoc;
  doc.photo = doc.photoResolved = photoPath;
  doc.objects.clear();
  doc.camera.vignetting.mode = VignettingKeys::Mode::None;
  auto none = prepareScene(doc);
  ASSERT_TRUE(none.ok()) << none.error().message();
  EXPECT_EQ(none->vignetting, 0.0);
  EXPECT_FALSE(stageNamed(*none, "vignetting")->ran);
  doc.camera.vignetting.mode = VignettingKeys::Mode::Auto;
  auto fixed = prepareScene(doc);
  ASSERT_TRUE(fixed.ok()) << fixed.error().message();
  EXPECT_GT(fixed->vignetting, 0.15);
  EXPECT_LT(fixed->vignetting, 0.45);
  const double truth = lightLuminance(*plain);
  const double errNone = std::abs(std::log(lightLuminance(*none) / truth));
  const double errFixed = std::abs(std::log(lightLuminance(*fixed) / truth));
  std::printf("lights over the plain photo's: none %.3f, auto (v %.2f) %.3f\n",
              lightLuminance(*none) / truth, fixed->vignetting, lightLuminance(*fixed) / truth);
  EXPECT_LT(errFixed, 0.5 * errNone);

  // No object: V (f^-1(photo) / V) encodes back to the vignetted photo's own codes.
  const ImageF composite = compositeOf(*fixed, renderFrame(*fixed, 1));
  for (float f : composite.data) ASSERT_TRUE(std::isfinite(f));
  SaveOptions so;
  so.response = &fixed->response;
  ASSERT_TRUE(saveImage((dir / "composite.png").string(), composite, so).ok());
  auto written = loadImage((dir / "composite.png").string());
  auto photo = loadImage(photoPath);
  ASSERT_TRUE(written.ok() && photo.ok());
  EXPECT_EQ(srgbCodesOf(written->linearRgb), srgbCodesOf(photo->linearRgb));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace inlay
