// A big photo prepares on a working copy (PrepareOptions::workingMaxPixels): the bundled
// example enlarged to 4000 x 3000 (its scene's pixel keys scaled with it) runs its image stages
// at the working size, each reporting it, while the render scene stays at the photo's size:
// the albedo (joint bilateral upsampling) keeps each surface's mean, every pixel's surface is cast
// again at full size, and the light outline's pixels are kept out of the render's bounces.
#include "inlay/engine/pipeline.h"
#include "inlay/modeling/image_io.h"
#include "inlay/modeling/image_resample.h"
#include "test_support.h"
#include "scene_scaling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>

namespace inlay {
namespace {

// The process's peak resident memory (VmHWM of /proc/self/status), bytes; 0 when unknown.
double peakMemoryBytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::atof(line.c_str() + 6) * 1024.0;  // kB
  return 0;
}

// Sets the peak back to the memory resident now (Linux: "5" to /proc/self/clear_refs), so a
// test's peak is its own and not an earlier test's; false when the system does not allow it.
bool resetPeakMemory() {
  std::ofstream refs("/proc/self/clear_refs");
  refs << "5";
  refs.flush();
  return bool(refs);
}

// The example scene photographed `k` times larger: its photo enlarged and saved as a JPEG in
// `dir`, its pixel keys scaled.
SceneDoc enlargedExample(double k, int W, int H, const std::filesystem::path& dir) {
  auto loaded = loadSceneFile(std::string(INLAY_SOURCE_DIR) + "/resources/example/scene.json");
  EXPECT_TRUE(loaded.ok());
  SceneDoc doc = loaded->doc;
  auto photo = loadImage(doc.photoResolved.empty() ? doc.photo : doc.photoResolved);
  EXPECT_TRUE(photo.ok());
  const std::string path = (dir / "big.jpg").string();
  EXPECT_TRUE(saveImage(path, resizeImage(photo->linearRgb, W, H)).ok());
  doc.photo = doc.photoResolved = path;
  inlay::test::scalePixelKeys(doc, k);
  return doc;
}

TEST(BigPhoto, PreparesOnAWorkingCopyAndRendersAtThePhotosSize) {
  const int W = 4000, H = 3000;
  const auto dir = test::tempDir("engine_big_photo");
  SceneDoc doc = enlargedExample(W / 512.0, W, H, dir);
  for (LightKeys& l : doc.lights) l.lock = true;  // no refinement and refit: the test's time
  PrepareOptions opt;
  opt.workingMaxPixels = 0.03e6;  // small, for the test's time; the default is kWorkingMaxPixels
  const bool peakReset = resetPeakMemory();
  const double before = peakMemoryBytes();
  auto ps = prepareScene(doc, opt);
  ASSERT_TRUE(ps.ok()) << ps.error().message();
  // Memory: the prepared scene holds the photo and a few maps of its size (albedo, the bounces'
  // radiance, the surface per pixel); the preparation's
  // peak stays within 12 photos' worth of float RGB (a stage that kept a double copy of every
  // map, or several full-size temporaries at once, would not).
  const double photoBytes = double(W) * H * 3 * sizeof(float);
#if defined(__SANITIZE_ADDRESS__)
  const bool sanitized = true;  // ASan's shadow and quarantine are not the preparation's
#else
  const bool sanitized = false;
#endif
  if (peakReset && before > 0 && !sanitized) {
    EXPECT_LT(peakMemoryBytes() - before, 12 * photoBytes)
        << "peak " << peakMemoryBytes() / 1e6 << " MB, before " << before / 1e6 << " MB";
  }
  std::printf("prepared %d x %d: peak memory %.0f MB above the %.0f MB before (%.1f photos)\n", W, H,
              (peakMemoryBytes() - before) / 1e6, before / 1e6,
              (peakMemoryBytes() - before) / photoBytes);
  const std::array<int, 2> work = workingSizeFor(W, H, opt.workingMaxPixels);
  EXPECT_EQ(ps->workingPx, work);
  EXPECT_LT(work[0], W / 10);

  // Each image stage says the size it worked at; the photo and the render scene the photo's.
  std::map<std::string, const StageRecord*> stages;
  for (const StageRecord& s : ps->stages) stages[s.name] = &s;
  for (const char* name : {"working copy", "lights", "lighting"}) {
    ASSERT_TRUE(stages.count(name) && stages[name]->ran) << name;
    EXPECT_EQ(stages[name]->workingWidth, work[0]) << name;
    EXPECT_EQ(stages[name]->workingHeight, work[1]) << name;
    EXPECT_TRUE(stages[name]->reducedImage) << name;
  }
  const std::string lighting = describeStage(*stages["lighting"]);
  EXPECT_NE(lighting.find(" at " + std::to_string(work[0]) + " x " + std::to_string(work[1]) + " px"),
            std::string::npos)
      << lighting;
  for (const char* name : {"photo", "photo size", "render scene", "grain"}) {
    ASSERT_TRUE(stages[name]->ran) << name;
    EXPECT_EQ(stages[name]->workingWidth, W) << name;
    EXPECT_FALSE(stages[name]->reducedImage) << name;
  }

  // The maps the render reads are at the photo's size, finite, the albedo in [0, 1]; those it
  // does not read (the direct light, and the gathered light of a room without a sun) stay at the
  // working copy's.
  const LightingEstimate& L = ps->lighting;
  const ImageF& radiance = ps->renderScene.roomAlbedo.photoRadiance;
  for (const ImageF* img : {&L.albedo, &radiance, &L.direct, &L.gathered}) {
    const bool full = img == &L.albedo || img == &radiance;
    ASSERT_EQ(img->width, full ? W : work[0]);
    ASSERT_EQ(img->height, full ? H : work[1]);
    for (float v : img->data) ASSERT_TRUE(std::isfinite(v) && v >= 0);
  }
  for (float v : L.albedo.data) ASSERT_LE(v, 1.f);
  ASSERT_EQ(L.firstSurfacePerPixel.size(), size_t(W) * H);
  ASSERT_EQ(ps->renderScene.roomAlbedo.firstSurfacePerPixel.size(), size_t(W) * H);
  EXPECT_EQ(L.decomposeValid.size(), size_t(work[0]) * work[1]);  // the decomposition's own

  // Upsampling keeps each surface's mean albedo (the working copy's, surfaceMeanAlbedo).
  std::vector<Vec3> sum(L.surfaceMeanAlbedo.size(), Vec3::Zero());
  std::vector<size_t> count(L.surfaceMeanAlbedo.size(), 0);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const int id = L.firstSurfacePerPixel[size_t(y) * W + x];
      if (id < 0 || size_t(id) >= sum.size()) continue;
      sum[size_t(id)] += L.albedo.rgb(x, y);
      ++count[size_t(id)];
    }
  int checked = 0;
  for (size_t id = 0; id < sum.size(); ++id) {
    if (count[id] < size_t(W) * H / 20) continue;
    const Vec3 mean = sum[id] / double(count[id]);
    EXPECT_LT((mean - L.surfaceMeanAlbedo[id]).cwiseAbs().maxCoeff(), 0.03)
        << "surface " << id << ": " << mean.transpose() << " against "
        << L.surfaceMeanAlbedo[id].transpose();
    ++checked;
  }
  EXPECT_GE(checked, 3);

  // The outlined light's pixels (its outline's centre, at the photo's size) are no bounce data.
  const std::vector<Vec2>& outline = doc.lights.front().pointsPx;
  Vec2 c = Vec2::Zero();
  for (const Vec2& v : outline) c += v / double(outline.size());
  const size_t centre = size_t(c.y()) * W + size_t(c.x());
  ASSERT_EQ(ps->renderScene.roomAlbedo.photoRadianceUsable.size(), size_t(W) * H);
  EXPECT_EQ(ps->renderScene.roomAlbedo.photoRadianceUsable[centre], 0);
  EXPECT_EQ(ps->renderScene.roomAlbedo.photoRadianceUsable[0], 1);
}

}  // namespace
}  // namespace inlay
