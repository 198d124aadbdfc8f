// The engine pipeline on the bundled example (needs nothing from ../shared): the whole chain
// with no inserted object returns the photo bit for bit; moving an object re-places it exactly
// as a fresh placement would; the composite is finite and differs from the photo only where
// paths met the object.
#include "inlay/engine/pipeline.h"
#include "inlay/render/composite.h"
#include "inlay/render/path_tracer.h"
#include "inlay/modeling/image_io.h"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <regex>

namespace inlay {
namespace {

SceneDoc exampleDoc() {
  const std::string path = std::string(INLAY_SOURCE_DIR) + "/resources/example/scene.json";
  auto loaded = loadSceneFile(path);
  EXPECT_TRUE(loaded.ok()) << (loaded.ok() ? "" : loaded.error().message());
  return loaded->doc;
}

// The unchanged example prepared once, for the tests that only read it or edit their own copy:
// preparing (decomposition, light estimate and refinement) is most of this suite's time, the
// more so under the sanitizers. prepareScene is deterministic, so a copy is what a fresh call
// would return.
Expected<PreparedScene> preparedExample() {
  static const Expected<PreparedScene> prepared = prepareScene(exampleDoc());
  return prepared;
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

TEST(Engine, NoObjectGivesThePhotoBitForBit) {
  SceneDoc doc = exampleDoc();
  doc.objects.clear();
  // A camera response other than sRGB: the photo is linearised by it and the PNG encoded by it.
  doc.camera.response = {ResponseKeys::Mode::ToeShoulder, 0.8, 0.3, 12.0};
  auto ps = prepareScene(doc);
  ASSERT_TRUE(ps.ok()) << ps.error().message();
  EXPECT_EQ(ps->response, CameraResponse::toeShoulder({0.8, 0.3, 12.0}));
  const ImageF composite = compositeOf(*ps, renderFrame(*ps, 2));
  ASSERT_EQ(composite.data.size(), ps->photo.linearRgb.data.size());
  size_t differing = 0;
  for (size_t i = 0; i < composite.data.size(); ++i)
    differing += composite.data[i] != ps->photo.linearRgb.data[i];
  EXPECT_EQ(differing, 0u);
  // Written through the response, the PNG holds the photo's own codes.
  const auto dir = test::tempDir("engine_response_png");
  SaveOptions so;
  so.response = &ps->response;
  ASSERT_TRUE(saveImage((dir / "composite.png").string(), composite, so).ok());
  auto written = loadImage((dir / "composite.png").string());
  auto photo = loadImage(doc.photoResolved.empty() ? doc.photo : doc.photoResolved);
  ASSERT_TRUE(written.ok() && photo.ok());
  EXPECT_EQ(srgbCodesOf(written->linearRgb), srgbCodesOf(photo->linearRgb));
}

// An EXR/HDR photo is linear whatever camera.response says (with a warning when it says
// otherwise); an 8-bit photo takes what the key asks.
TEST(Engine, TheResponseOfALinearPhotoIsTheIdentity) {
  LoadedImage linearPhoto;
  linearPhoto.linearRgb = ImageF(64, 48, 3, 0.25f);
  linearPhoto.wasSrgbEncoded = false;
  ChosenResponse auto_ = responseOf({}, linearPhoto);
  EXPECT_EQ(auto_.response.family(), ResponseFamily::Linear);
  EXPECT_FALSE(auto_.estimate);
  EXPECT_TRUE(auto_.warnings.empty());
  ChosenResponse asked = responseOf({ResponseKeys::Mode::Srgb}, linearPhoto);
  EXPECT_EQ(asked.response.family(), ResponseFamily::Linear);
  ASSERT_EQ(asked.warnings.size(), 1u);
  EXPECT_NE(asked.warnings[0].find("camera.response"), std::string::npos);
  LoadedImage eightBit = linearPhoto;
  eightBit.wasSrgbEncoded = true;
  EXPECT_EQ(responseOf({ResponseKeys::Mode::Srgb}, eightBit).response, CameraResponse::srgb());
  EXPECT_EQ(responseOf({ResponseKeys::Mode::Linear}, eightBit).response, CameraResponse::linear());
  // "auto" on a flat 8-bit photo: sRGB, with the estimate's warning.
  ChosenResponse flat = responseOf({}, eightBit);
  EXPECT_EQ(flat.response, CameraResponse::srgb());
  ASSERT_TRUE(flat.estimate);
  EXPECT_FALSE(flat.estimate->determined);
  EXPECT_EQ(flat.warnings.size(), 1u);
}

// "room.materials": the floor marked as a mirror reaches the render scene; with no object the
// composite is still the photo bit for bit; a surface this room lacks is refused by its key.
TEST(Engine, RoomMaterialsReachTheRenderSceneAndKeepThePhoto) {
  SceneDoc doc = exampleDoc();
  doc.objects.clear();
  RoomMaterialKeys mirror;
  mirror.preset = "mirror";
  doc.room.materials["floor"] = mirror;
  auto ps = prepareScene(doc);
  ASSERT_TRUE(ps.ok()) << ps.error().message();
  const auto& surfaces = ps->renderScene.room.surfaces;
  const auto& materials = ps->renderScene.roomMaterials;
  ASSERT_EQ(materials.size(), surfaces.size());
  size_t marked = 0;
  for (size_t i = 0; i < surfaces.size(); ++i) {
    marked += materials[i].has_value();
    if (surfaces[i].name == "floor") {
      ASSERT_TRUE(materials[i].has_value());
      EXPECT_EQ(materials[i]->kind, Material::Kind::Mirror);
    }
  }
  EXPECT_EQ(marked, 1u);
  const ImageF composite = compositeOf(*ps, renderFrame(*ps, 2));
  size_t differing = 0;
  for (size_t i = 0; i < composite.data.size(); ++i)
    differing += composite.data[i] != ps->photo.linearRgb.data[i];
  EXPECT_EQ(differing, 0u);

  doc.room.materials["surface_99_top"] = mirror;
  auto refused = prepareScene(doc);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().key, "room.materials.surface_99_top");
  EXPECT_NE(refused.error().reason.find("no surface"), std::string::npos);
}

// The example photo (a path-traced room, 8-bit) has measurable grain; compositeOf gives it to
// the pixels the object changes, leaves the others the photo bit for bit, and gives none with
// render.grain false, withGrain false (the clean EXR layers) or a linear photo's empty model.
TEST(Engine, CompositeGrainOnlyWhereTheObjectChangesThePhoto) {
  auto ps = preparedExample();
  ASSERT_TRUE(ps.ok()) << ps.error().message();
  EXPECT_FALSE(ps->photoNoise.empty()) << describeNoise(ps->photoNoise);
  const RenderFrame f = renderFrame(*ps, 4);
  const ImageF grained = compositeOf(*ps, f), clean = compositeOf(*ps, f, /*withGrain=*/false);
  EXPECT_EQ(clean.data, compositeOf(ps->photo.linearRgb, ps->doc.render.exposure, f).data);
  size_t changed = 0, grainedPixels = 0;
  for (int y = 0; y < clean.height; ++y)
    for (int x = 0; x < clean.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const bool touched = f.mask.at(x, y) != 0.f ||
                             f.withObjects.at(x, y, c) != f.withoutObjects.at(x, y, c);
        changed += touched;
        grainedPixels += grained.at(x, y, c) != clean.at(x, y, c);
        ASSERT_TRUE(std::isfinite(grained.at(x, y, c)));
        if (!touched) {
          ASSERT_EQ(grained.at(x, y, c), ps->photo.linearRgb.at(x, y, c)) << x << "," << y;
        }
      }
  EXPECT_GT(grainedPixels, changed / 10);
  PreparedScene off = *ps;
  off.doc.render.grain = false;
  EXPECT_EQ(compositeOf(off, f).data, clean.data);
  off.doc.render.grain = true;
  off.photoNoise = PhotoNoise{};
  EXPECT_EQ(compositeOf(off, f).data, clean.data);
}

// The same noisy pixels saved as PNG and as EXR: the PNG's grain is measured, the linear EXR
// gets none.
TEST(Engine, ALinearPhotoGetsNoGrain) {
  ImageF noisy(160, 120, 3);
  uint32_t state = 9;
  for (int y = 0; y < noisy.height; ++y)
    for (int x = 0; x < noisy.width; ++x)
      for (int c = 0; c < 3; ++c) {
        state = state * 1664525u + 1013904223u;
        noisy.at(x, y, c) = 0.05f + 0.8f * float(x) / float(noisy.width) +
                            0.05f * (float(state >> 8) / 16777216.f - 0.5f);
      }
  const auto dir = test::tempDir("linear_grain");
  for (const char* ext : {"png", "exr"}) {
    const std::string path = (dir / (std::string("photo.") + ext)).string();
    ASSERT_TRUE(saveImage(path, noisy).ok());
    auto photo = loadImage(path);
    ASSERT_TRUE(photo.ok());
    const PhotoNoise n = photoNoiseOf(*photo);
    EXPECT_EQ(n.empty(), std::string(ext) == "exr") << ext << ": " << describeNoise(n);
  }
  std::filesystem::remove_all(dir);
}

// A big photo's grain is measured on a sparser grid of patches (kGrainMaxPatches): on a 4.3 MP
// photo it finds the noise level and the grain's width that every patch finds.
TEST(Engine, ABigPhotosGrainFromFewerPatchesIsTheSame) {
  ImageF noisy(2400, 1800, 3);
  uint32_t state = 5;
  for (int y = 0; y < noisy.height; ++y)
    for (int x = 0; x < noisy.width; ++x)
      for (int c = 0; c < 3; ++c) {
        state = state * 1664525u + 1013904223u;
        noisy.at(x, y, c) = 0.05f + 0.7f * float(x + y) / float(noisy.width + noisy.height) +
                            0.04f * (float(state >> 8) / 16777216.f - 0.5f);
      }
  const auto dir = test::tempDir("big_grain");
  const std::string path = (dir / "photo.png").string();
  ASSERT_TRUE(saveImage(path, noisy).ok());
  auto photo = loadImage(path);
  ASSERT_TRUE(photo.ok());
  const PhotoNoise sparse = photoNoiseOf(*photo);
  NoiseMeasureOptions every;
  ASSERT_GE(every.maxPatches, 4 * kGrainMaxPatches);
  const PhotoNoise full = measurePhotoNoise(photo->linearRgb, every);
  ASSERT_FALSE(sparse.empty() || full.empty()) << describeNoise(sparse);
  EXPECT_LT(sparse.patchesUsed[1], full.patchesUsed[1] / 2);  // it did measure fewer
  for (int c = 0; c < 3; ++c)
    for (double intensity : {0.1, 0.3, 0.6}) {
      const double a = sparse.sigma(c, intensity), b = full.sigma(c, intensity);
      EXPECT_NEAR(a, b, 0.05 * b) << "channel " << c << " at " << intensity;
    }
  EXPECT_NEAR(sparse.grainWidthPx, full.grainWidthPx, 0.1);
  std::filesystem::remove_all(dir);
}

TEST(Engine, ObjectChangesThePhotoNearItAndStaysFinite) {
  auto ps = preparedExample();
  ASSERT_TRUE(ps.ok()) << ps.error().message();
  ASSERT_EQ(ps->renderScene.objects.size(), 1u);
  const RenderFrame f = renderFrame(*ps, 4);
  const ImageF composite = compositeOf(*ps, f);
  const auto base = ps->camera.project(ps->placements[0].baseWorld);
  ASSERT_TRUE(base.has_value());
  double maskSum = 0;
  size_t changed = 0;
  for (int y = 0; y < composite.height; ++y)
    for (int x = 0; x < composite.width; ++x) {
      for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(composite.at(x, y, c)));
      maskSum += f.mask.at(x, y);
      changed += composite.rgb(x, y) != ps->photo.linearRgb.rgb(x, y);
    }
  // The sphere (0.6 m across, about 4000 px in the truth) covers a few thousand pixels.
  EXPECT_GT(maskSum, 2000);
  EXPECT_LT(maskSum, 8000);
  EXPECT_GT(changed, size_t(maskSum));
  // The object sits where base_px says: its mask is around the base pixel.
  const int bx = int(base->x()), by = int(base->y()) - 20;
  EXPECT_GT(f.mask.at(bx, by), 0.5f);
}

// The decomposition is once-per-photo-and-geometry work: prepareScene runs it once (twice when
// the light refinement moved a light: the lighting is estimated again with the refined
// positions), and moving an object (placeObjectAt and the object's new transform) never runs it
// again nor changes the room's albedo.
TEST(Engine, MovingAnObjectNeverRedoesTheDecomposition) {
  const uint64_t before = decompositionRuns();
  auto ps = prepareScene(exampleDoc());
  ASSERT_TRUE(ps.ok()) << ps.error().message();
  bool refit = false;
  for (const StageRecord& stage : ps->stages)
    refit = refit || (stage.name == "lighting refit" && stage.ran);
  EXPECT_EQ(decompositionRuns(), before + (refit ? 2 : 1));
  const uint64_t prepared = decompositionRuns();
  ASSERT_FALSE(ps->lighting.albedo.empty());
  ASSERT_FALSE(ps->lighting.direct.empty());
  const std::vector<float> albedo = ps->renderScene.roomAlbedo.albedo.data;
  for (int k = 1; k <= 5; ++k) {
    ps->doc.objects[0].basePx += Vec2(-6, -2);
    const auto moved = placeObjectAt(*ps, 0);
    ASSERT_TRUE(moved.ok()) << moved.error().message();
    ps->renderScene.objects[0].worldFromObject = moved->worldFromObject;
  }
  EXPECT_EQ(decompositionRuns(), prepared);
  EXPECT_EQ(ps->renderScene.roomAlbedo.albedo.data, albedo);
}

// Preparation has its own seed (PrepareOptions::seed), never the render seed: another
// render.seed prepares the same lights, albedo and gathered light bit for bit, so renders with
// other seeds converge to one image.
bool sameBits(const ImageF& a, const ImageF& b) {
  return a.width == b.width && a.height == b.height && a.data.size() == b.data.size() &&
         std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}
TEST(Engine, PreparationIgnoresTheRenderSeed) {
  const auto first = preparedExample();
  ASSERT_TRUE(first.ok()) << first.error().message();
  SceneDoc doc = exampleDoc();
  doc.render.seed = first->doc.render.seed + 1;
  const auto second = prepareScene(doc);
  ASSERT_TRUE(second.ok()) << second.error().message();
  ASSERT_EQ(first->renderScene.lights.size(), second->renderScene.lights.size());
  for (size_t i = 0; i < first->renderScene.lights.size(); ++i) {
    const AreaLight &a = first->renderScene.lights[i], &b = second->renderScene.lights[i];
    EXPECT_EQ(a.radiance, b.radiance) << "light " << i;
    for (size_t k = 0; k < 4; ++k) EXPECT_EQ(a.cornersWorld[k], b.cornersWorld[k]) << "light " << i;
  }
  EXPECT_TRUE(sameBits(first->renderScene.roomAlbedo.albedo, second->renderScene.roomAlbedo.albedo));
  EXPECT_TRUE(sameBits(first->lighting.gathered, second->lighting.gathered));
  EXPECT_TRUE(sameBits(first->renderScene.roomAlbedo.photoRadiance,
                       second->renderScene.roomAlbedo.photoRadiance));
}

TEST(Engine, MovingAnObjectMatchesAFreshPlacement) {
  auto ps = preparedExample();
  ASSERT_TRUE(ps.ok()) << ps.error().message();
  ps->doc.objects[0].basePx += Vec2(60, -10);
  ps->doc.objects[0].yawDeg = 30;
  const auto moved = placeObjectAt(*ps, 0);
  ASSERT_TRUE(moved.ok()) << moved.error().message();
  const auto fresh = placeObject(*ps->renderScene.objects[0].meshObject, ps->geometry, ps->camera,
                                 ps->doc.objects[0].basePx, ps->doc.objects[0].heightM, 30,
                                 "objects[0]");
  ASSERT_TRUE(fresh.ok());
  EXPECT_TRUE(moved->worldFromObject.isApprox(fresh->worldFromObject, 1e-12));
  EXPECT_NEAR(moved->baseWorld.y(), 0.0, 1e-9);  // still on the floor
  // Onto the ceiling: refused with the key named.
  ps->doc.objects[0].basePx = Vec2(200, 20);
  const auto bad = placeObjectAt(*ps, 0);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().message().find("objects[0].base_px"), std::string::npos);
}

}  // namespace
}  // namespace inlay

namespace inlay {
namespace {

// The render uses the refined lights (their positions; when one moved, the radiances are fitted
// again with them, together with the albedo); a locked light keeps the estimate's position and
// intensity while the other is refined; --initial-lights (refineLights = false) renders the
// estimate's.
// A sun shaft whose window is out of view (a shaft box and a direction, no source box): the
// opening its beam came through joins the lights after the scene file's, with a warning; the
// lighting stage fits its intensity and the refinement, which moves the outlined lights, holds it
// where the beam put it. The photo: the example's with a clipped patch painted on its floor, the
// sun coming from behind and above the camera.
TEST(Engine, AShaftsWindowOutOfViewBecomesALight) {
  SceneDoc doc = exampleDoc();
  auto photo = loadImage(doc.photoResolved.empty() ? doc.photo : doc.photoResolved);
  ASSERT_TRUE(photo.ok()) << photo.error().message();
  for (int y = 310; y < 360; ++y)
    for (int x = 200; x < 300; ++x) photo->linearRgb.setRgb(x, y, Vec3(1, 1, 1));
  const auto dir = test::tempDir("engine_sky_window");
  const std::string photoPath = (dir / "photo.png").string();
  ASSERT_TRUE(saveImage(photoPath, photo->linearRgb).ok());
  doc.photo = doc.photoResolved = photoPath;
  ShaftKeys shaft;
  shaft.shaftBoxPx = std::array<double, 4>{180, 295, 320, 375};
  shaft.direction = Vec3(0, -0.7, -0.7);
  doc.shafts = {shaft};
  auto ps = prepareScene(doc);
  ASSERT_TRUE(ps.ok()) << ps.error().message();
  ASSERT_EQ(ps->lighting.suns.size(), 1u);
  ASSERT_EQ(ps->lighting.lights.size(), doc.lights.size() + 1);
  ASSERT_EQ(ps->initialLights.size(), doc.lights.size() + 1);
  bool warned = false;
  for (const std::string& w : ps->warnings)
    warned = warned || w.find("shafts[0]: the window the sun comes through is out of view") == 0;
  EXPECT_TRUE(warned);
  const AreaLight& sky = ps->lighting.lights.back();
  for (int k = 0; k < 4; ++k)
    EXPECT_EQ(sky.cornersWorld[size_t(k)], ps->initialLights.back().cornersWorld[size_t(k)]);
  EXPECT_TRUE(sky.radiance.allFinite());
  EXPECT_GE(sky.radiance.minCoeff(), 0.0);
  EXPECT_EQ(ps->renderScene.lights.size(), ps->lighting.lights.size());
  // It lies behind or above the camera, where the beam came from: out of the photo.
  EXPECT_FALSE(ps->camera.project(sky.centre()).has_value() &&
               ps->camera.project(sky.centre())->y() > 0 &&
               ps->camera.project(sky.centre())->y() < photo->linearRgb.height &&
               ps->camera.project(sky.centre())->x() > 0 &&
               ps->camera.project(sky.centre())->x() < photo->linearRgb.width);
  // The painted patch clips everywhere: the shadow ratio refuses it and, by default, the sun
  // keeps its estimated strength. Asked of the light the patch bounces
  // (PrepareOptions::sunsFromBounce, opt-in), it says what it found or why it cannot tell.
  auto sunWarning = [](const std::vector<std::string>& warnings) {
    std::string all;
    for (const std::string& w : warnings)
      if (w.rfind("sun 0:", 0) == 0) all += w + "\n";
    return all;
  };
  EXPECT_NE(sunWarning(ps->warnings).find("strength kept as estimated"), std::string::npos);
  EXPECT_EQ(sunWarning(ps->warnings).find("bounce"), std::string::npos) << sunWarning(ps->warnings);
  PrepareOptions withBounce;
  withBounce.sunsFromBounce = true;
  auto bounced = prepareScene(doc, withBounce);
  ASSERT_TRUE(bounced.ok()) << bounced.error().message();
  EXPECT_NE(sunWarning(bounced->warnings).find("bounce"), std::string::npos)
      << sunWarning(bounced->warnings);
  // Turned off, no light is added.
  PrepareOptions off;
  off.skyThroughUnseenWindows = false;
  off.refineLights = false;
  auto without = prepareScene(doc, off);
  ASSERT_TRUE(without.ok()) << without.error().message();
  EXPECT_EQ(without->lighting.lights.size(), doc.lights.size());
  // The opening is the beam's section widened by the window's reveal
  // (PrepareOptions::windowRevealDepthM, 0.2 m): larger than the section alone, on the same plane.
  PrepareOptions flat = off;
  flat.skyThroughUnseenWindows = true;
  flat.windowRevealDepthM = 0;
  auto section = prepareScene(doc, flat);
  ASSERT_TRUE(section.ok()) << section.error().message();
  ASSERT_EQ(section->lighting.lights.size(), doc.lights.size() + 1);
  const AreaLight& beam = section->lighting.lights.back();
  std::printf("the sky's opening: %.3f m2 widened by the reveal, %.3f m2 the beam's section\n",
              sky.area(), beam.area());
  EXPECT_GT(sky.area(), 1.05 * beam.area());
  EXPECT_NEAR(std::abs(sky.normal().dot(beam.normal())), 1.0, 1e-9);
  EXPECT_NEAR((sky.centre() - beam.centre()).dot(beam.normal()), 0.0, 1e-9);
}

TEST(Engine, TheRenderUsesTheRefinedLightsAndALockedLightStays) {
  SceneDoc doc = exampleDoc();
  ASSERT_GE(doc.lights.size(), 2u);
  auto ps = preparedExample();  // the unchanged doc
  ASSERT_TRUE(ps.ok()) << ps.error().message();
  ASSERT_FALSE(ps->refinement.history.empty());
  EXPECT_LE(ps->refinement.finalObjective, ps->refinement.initialObjective);
  ASSERT_EQ(ps->renderScene.lights.size(), ps->initialLights.size());
  // The render takes the preparation's lights: refined and fitted again, or the first estimate
  // when that fits the photo better (the next test).
  bool anyChanged = false;
  for (size_t j = 0; j < ps->initialLights.size(); ++j) {
    EXPECT_EQ(ps->renderScene.lights[j].centre(), ps->lighting.lights[j].centre());
    EXPECT_EQ(ps->renderScene.lights[j].radiance, ps->lighting.lights[j].radiance);
    anyChanged = anyChanged || ps->refinement.lights[j].radiance != ps->initialLights[j].radiance;
  }
  EXPECT_TRUE(anyChanged);

  doc.lights[0].lock = true;
  auto locked = prepareScene(doc);
  ASSERT_TRUE(locked.ok());
  EXPECT_EQ(locked->renderScene.lights[0].radiance, locked->initialLights[0].radiance);
  EXPECT_EQ(locked->renderScene.lights[0].centre(), locked->initialLights[0].centre());
  EXPECT_EQ(locked->refinement.lights[0].radiance, locked->initialLights[0].radiance);
  EXPECT_NE(locked->refinement.lights[1].radiance, locked->initialLights[1].radiance);

  PrepareOptions initial;
  initial.refineLights = false;
  const uint64_t refinements = lightRefinementRuns();
  auto unrefined = prepareScene(doc, initial);
  ASSERT_TRUE(unrefined.ok());
  EXPECT_TRUE(unrefined->refinement.history.empty());
  EXPECT_EQ(lightRefinementRuns(), refinements);  // skipped, and the stage says why
  for (const StageRecord& s : unrefined->stages) {
    if (s.name == "refine") {
      EXPECT_EQ(s.reason, "the lights are kept as estimated (initial lights asked for)");
    }
  }
  for (size_t j = 0; j < unrefined->initialLights.size(); ++j)
    EXPECT_EQ(unrefined->renderScene.lights[j].radiance, unrefined->initialLights[j].radiance);
}

// After the refinement the lighting is fitted again; the preparation keeps the refit unless the
// first estimate explains the photo better (LightingEstimate::fitRmsLog smaller by more than
// PrepareOptions::keepBetterFitTolerance), and the refit stage's detail says which it kept with
// both residuals. An outlined light never moves farther than its outline's uncertainty
// (lighting/refine.h, outlineDisplacementBoundM).
TEST(Engine, ThePreparationKeepsTheLightingThatFitsThePhotoBetter) {
  const SceneDoc doc = exampleDoc();
  // The example's lights move less than refitMinLightMove: the refit is asked for here.
  PrepareOptions refitting;
  refitting.refitMinLightMove = 0;
  auto kept = prepareScene(doc, refitting);
  ASSERT_TRUE(kept.ok()) << kept.error().message();
  PrepareOptions always = refitting;
  always.keepBetterFit = false;
  auto refitted = prepareScene(doc, always);
  ASSERT_TRUE(refitted.ok());
  const double refit = refitted->lighting.fitRmsLog;
  ASSERT_TRUE(std::isfinite(refit) && std::isfinite(kept->lighting.fitRmsLog));
  bool warned = false;
  bool saidRefitKept = false;
  for (const auto& stage : kept->stages) {
    warned = warned || stage.detail.find("first estimate fits the photo better") != std::string::npos;
    saidRefitKept = saidRefitKept ||
                    stage.detail.find("the refit is kept (log residual") != std::string::npos;
  }
  EXPECT_NE(warned, saidRefitKept);  // the detail names exactly one choice
  for (const auto& w : kept->warnings) EXPECT_EQ(w.find("first estimate"), std::string::npos) << w;
  // Kept: the first estimate, which fits better than the refit; else the refit itself.
  const auto& chosen = warned ? kept->initialLights : refitted->renderScene.lights;
  if (warned) EXPECT_LT(kept->lighting.fitRmsLog * (1 + kKeepBetterFitTolerance), refit);
  else EXPECT_EQ(kept->lighting.fitRmsLog, refit);
  ASSERT_EQ(kept->renderScene.lights.size(), chosen.size());
  for (size_t j = 0; j < chosen.size(); ++j) {
    EXPECT_EQ(kept->renderScene.lights[j].radiance, chosen[j].radiance) << j;
    EXPECT_EQ(kept->renderScene.lights[j].centre(), chosen[j].centre()) << j;
  }
  // The example's lights are outlined: each refined one stays within its outline's bound.
  const PreparedScene& r = *refitted;
  for (size_t j = 0; j < doc.lights.size(); ++j) {
    if (doc.lights[j].kind != LightKeys::Kind::PolygonPx) continue;
    const double bound =
        outlineDisplacementBoundM(r.camera, r.initialLights[j], doc.lights[j].pointsPx, {});
    const Vec3 moved = r.refinement.lights[j].centre() - r.initialLights[j].centre();
    EXPECT_LE(moved.cwiseAbs().maxCoeff(), bound + 1e-9) << j;
  }
}

// The keep-better-fit rule on its own, with extreme residuals and tolerances: a relative tie
// keeps the refit, a residual that is not finite never wins, a tolerance that is negative or NaN
// counts as 0 (an infinite one keeps every finite refit); never a NaN decision.
TEST(Engine, TheRefitIsKeptUnlessItFitsWorseByMoreThanTheTolerance) {
  const double nan = std::numeric_limits<double>::quiet_NaN(),
               inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(refitFitsWorse(0.1, 0.1, 0.0));      // equal: the refit
  EXPECT_TRUE(refitFitsWorse(0.1, 0.1001, 0.0));    // any excess without a tolerance
  EXPECT_FALSE(refitFitsWorse(0.1, 0.1001, 0.01));  // within 1 %: a tie, the refit
  EXPECT_TRUE(refitFitsWorse(0.1, 0.1011, 0.01));   // beyond it: the first estimate
  EXPECT_FALSE(refitFitsWorse(0.1, 0.05, 0.0));     // better: the refit
  EXPECT_FALSE(refitFitsWorse(0.0, 0.0, 0.01));     // a perfect fit both times
  EXPECT_TRUE(refitFitsWorse(0.0, 1e-300, 0.01));   // nothing is within a tolerance of zero
  EXPECT_TRUE(refitFitsWorse(0.1, nan, 0.01));      // the refit failed: the first estimate
  EXPECT_TRUE(refitFitsWorse(0.1, inf, 1e9));
  EXPECT_FALSE(refitFitsWorse(nan, 0.1, 0.01));  // the first failed: the refit
  EXPECT_FALSE(refitFitsWorse(inf, inf, 0.01));  // neither finite: the refit (the stage ran)
  EXPECT_FALSE(refitFitsWorse(nan, nan, 0.01));
  EXPECT_TRUE(refitFitsWorse(0.1, 0.1001, -5.0));  // a negative tolerance is 0
  EXPECT_TRUE(refitFitsWorse(0.1, 0.1001, nan));   // so is one that is not a number
  EXPECT_TRUE(refitFitsWorse(0.1, 0.1001, -inf));
  EXPECT_FALSE(refitFitsWorse(0.1, 1e6, inf));   // an infinite tolerance keeps every finite refit
  EXPECT_TRUE(refitFitsWorse(1e308, inf, 1.0));  // no overflow to a tie
  EXPECT_GE(kKeepBetterFitTolerance, 0.0);
  EXPECT_LT(kKeepBetterFitTolerance, 0.1);  // below t05's 10 %: half A's one real trigger stays
}

}  // namespace
}  // namespace inlay

namespace inlay {
namespace {

// "camera.vanishing_lines_px": the camera is re-estimated with that vanishing point where the
// user's two lines meet (render and estimate both go through cameraAndLayoutOf); lines that
// cannot be used fail naming the file's key.
TEST(Engine, UserVanishingLinesFixTheirVanishingPoint) {
  SceneDoc doc = exampleDoc();
  doc.camera.vanishingPointsPx.reset();
  doc.camera.focalPx.reset();
  doc.layout.backWallPx.reset();
  auto photo = loadImage(doc.photoResolved, ImageLimits::photo());
  ASSERT_TRUE(photo.ok());
  auto plain = cameraAndLayoutOf(doc.camera, doc.layout, *photo, true);
  ASSERT_TRUE(plain.ok()) << plain.error().message();
  const Vec3 h0 = plain->estimate->vanishingPoints[2].homogeneousPx;
  ASSERT_GT(std::abs(h0.z()), 1e-9);
  const Vec2 vp0(h0.x() / h0.z(), h0.y() / h0.z());
  const Vec2 wanted = vp0 + Vec2(25, -12);
  const Vec2 p0(40, 330), p1(470, 350);
  doc.camera.vanishingLinesPx[2] =
      std::array<Vec2, 4>{p0, p0 + 0.45 * (wanted - p0), p1, p1 + 0.45 * (wanted - p1)};
  auto fixed = cameraAndLayoutOf(doc.camera, doc.layout, *photo, true);
  ASSERT_TRUE(fixed.ok()) << fixed.error().message();
  const Vec3 h1 = fixed->estimate->vanishingPoints[2].homogeneousPx;
  const Vec2 vp1(h1.x() / h1.z(), h1.y() / h1.z());
  EXPECT_LT((vp1 - wanted).norm(), 0.2 * (vp0 - wanted).norm()) << vp1.transpose();
  int user = 0;
  for (const LineSegment& s : fixed->estimate->segments)
    if (s.userGiven) {
      ++user;
      EXPECT_EQ(s.family, 2);
      EXPECT_TRUE(std::isfinite(s.residualPx));
    }
  EXPECT_EQ(user, 2);
  // Through the whole preparation as `render` runs it.
  auto ps = prepareScene(doc);
  ASSERT_TRUE(ps.ok()) << ps.error().message();
  const Vec3 h2 = ps->camera.vanishingPointOf(Vec3::UnitZ());
  EXPECT_LT((Vec2(h2.x() / h2.z(), h2.y() / h2.z()) - vp1).norm(), 1.0);

  // Two lines through one vanishing point that no camera can have with the others: the error
  // names the file's key, not the solver's.
  doc.camera.vanishingLinesPx[2] =
      std::array<Vec2, 4>{Vec2(10, 10), Vec2(10.5, 10), Vec2(0, 50), Vec2(100, 60)};
  auto bad = cameraAndLayoutOf(doc.camera, doc.layout, *photo, true);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().key, "camera.vanishing_lines_px.z") << bad.error().message();
}

}  // namespace
}  // namespace inlay

namespace inlay {
namespace {

const StageRecord* stageNamed(const PreparedScene& ps, const std::string& name) {
  for (const StageRecord& s : ps.stages)
    if (s.name == name) return &s;
  return nullptr;
}

std::vector<std::string> stageNames(const PreparedScene& ps) {
  std::vector<std::string> names;
  for (const StageRecord& s : ps.stages) names.push_back(s.name);
  return names;
}

// Counts, per label, the stages PrepareOptions::progress announced (fraction 0 at a stage's start).
void countStageStarts(PrepareOptions& opt, std::map<std::string, int>& starts) {
  opt.progress = [&starts](const std::string& label, double fraction) {
    if (fraction == 0) ++starts[label];
  };
}

// What the render and the composite read of a prepared scene, bit for bit.
void expectSameRenderInputs(const PreparedScene& a, const PreparedScene& b) {
  EXPECT_EQ(a.response, b.response);
  EXPECT_TRUE(a.photo.linearRgb.data == b.photo.linearRgb.data);
  const ProjectedAlbedo &pa = a.renderScene.roomAlbedo, &pb = b.renderScene.roomAlbedo;
  EXPECT_TRUE(pa.albedo.data == pb.albedo.data);
  EXPECT_TRUE(pa.photoRadiance.data == pb.photoRadiance.data);
  EXPECT_EQ(pa.firstSurfacePerPixel, pb.firstSurfacePerPixel);
  ASSERT_EQ(a.renderScene.lights.size(), b.renderScene.lights.size());
  for (size_t i = 0; i < a.renderScene.lights.size(); ++i) {
    EXPECT_EQ(a.renderScene.lights[i].radiance, b.renderScene.lights[i].radiance) << i;
    EXPECT_EQ(a.renderScene.lights[i].cornersWorld, b.renderScene.lights[i].cornersWorld) << i;
  }
  EXPECT_EQ(a.photoNoise.grainWidthPx, b.photoNoise.grainWidthPx);
  EXPECT_EQ(a.photoNoise.channelCorrelation, b.photoNoise.channelCorrelation);
  for (size_t c = 0; c < 3; ++c) {
    ASSERT_EQ(a.photoNoise.levels[c].size(), b.photoNoise.levels[c].size()) << c;
    for (size_t k = 0; k < a.photoNoise.levels[c].size(); ++k)
      EXPECT_EQ(a.photoNoise.levels[c][k].sigma, b.photoNoise.levels[c][k].sigma) << c << " " << k;
  }
  ASSERT_EQ(a.placements.size(), b.placements.size());
  for (size_t i = 0; i < a.placements.size(); ++i)
    EXPECT_TRUE(a.placements[i].worldFromObject == b.placements[i].worldFromObject) << i;
}

// The noise cue's evidence gate and acceptance off: the example (a plain sRGB render) gets a
// false shoulder (about 880), a curve for the response check to check.
PrepareOptions optionsGivingTheExampleACurve() {
  PrepareOptions opt;
  opt.responseEstimate.minSrgbResidual = 0;
  opt.responseEstimate.minImprovement = 0;
  return opt;
}

// PrepareOptions::checkResponseByLightFit: the example (a plain sRGB render) with the noise cue's
// evidence gate and acceptance off gets a false shoulder (about 880). The light fit explains
// the photo worse with it (residual about 0.71 against sRGB's 0.15), so the check prepares the
// scene again with sRGB and says why; off, the curve stays. The plain example under the
// default gate keeps sRGB and is not prepared twice (no "response check" stage).
TEST(Engine, TheLightFitTakesAwayACurveItExplainsThePhotoWorseWith) {
  SceneDoc doc = exampleDoc();
  PrepareOptions opt = optionsGivingTheExampleACurve();
  opt.checkResponseByLightFit = false;
  auto curved = prepareScene(doc, opt);
  ASSERT_TRUE(curved.ok()) << curved.error().message();
  ASSERT_EQ(curved->response.family(), ResponseFamily::ToeShoulder);
  EXPECT_GT(curved->response.params().shoulder, 100);
  EXPECT_EQ(stageNamed(*curved, "response check"), nullptr);
  opt.checkResponseByLightFit = true;
  std::map<std::string, int> starts;
  countStageStarts(opt, starts);
  auto checked = prepareScene(doc, opt);
  ASSERT_TRUE(checked.ok()) << checked.error().message();
  EXPECT_EQ(checked->response, CameraResponse::srgb());
  ASSERT_TRUE(checked->responseEstimate);
  EXPECT_EQ(checked->responseEstimate->response, CameraResponse::srgb());
  EXPECT_EQ(checked->responseEstimate->decision.rfind("kept sRGB: the light fit's residual", 0), 0u)
      << checked->responseEstimate->decision;
  EXPECT_EQ(checked->doc.camera.response.mode, ResponseKeys::Mode::Auto);  // not written back as sRGB
  EXPECT_LT(checked->lighting.fitResidualRelative, curved->lighting.fitResidualRelative);
  const StageRecord* check = stageNamed(*checked, "response check");
  ASSERT_NE(check, nullptr);
  EXPECT_EQ(check->detail.rfind("sRGB kept: ", 0), 0u) << check->detail;
  EXPECT_EQ(stageNamed(*checked, "response")->detail, "estimated");
  size_t warned = 0;
  for (const auto& w : checked->warnings)
    warned += w.find("the estimated curve was not used") != std::string::npos;
  EXPECT_EQ(warned, 1u);
  // The same as preparing with sRGB outright: the lights are those of the plain example.
  auto plain = preparedExample();
  ASSERT_TRUE(plain.ok());
  EXPECT_EQ(stageNamed(*plain, "response check"), nullptr);
  ASSERT_EQ(checked->lighting.lights.size(), plain->lighting.lights.size());
  for (size_t i = 0; i < plain->lighting.lights.size(); ++i)
    EXPECT_EQ(checked->lighting.lights[i].radiance, plain->lighting.lights[i].radiance) << i;
  // ... and everything the render reads; the photo loaded once, the stages after the refit run
  // once (for sRGB), the check's record before them.
  expectSameRenderInputs(*checked, *plain);
  EXPECT_EQ(starts["photo"], 1);
  EXPECT_EQ(starts["objects"], 1);
  std::vector<std::string> expected = stageNames(*plain);
  expected.insert(std::find(expected.begin(), expected.end(), "photo size"), "response check");
  EXPECT_EQ(stageNames(*checked), expected);
}

// The response check prepares sRGB only up to the lighting refit, from the photo as loaded: the
// photo is loaded once, and the stages after the refit (photo size, render scene, objects,
// grain) run once, for the kept candidate. Its record stands before them, with the stages it
// ran again as its steps; its seconds and the curve's stages' cover them (side by side, since
// resp20). A curve the check keeps (an infinite tolerance keeps any finite residual) gives the
// scene prepared with the check off, bit for bit, with the same progress reports.
TEST(Engine, TheResponseCheckRunsTheStagesAfterTheRefitOnlyForTheKeptResponse) {
  SceneDoc doc = exampleDoc();
  PrepareOptions opt = optionsGivingTheExampleACurve();
  opt.checkResponseByLightFit = false;
  std::map<std::string, int> offStarts, onStarts;
  countStageStarts(opt, offStarts);
  auto off = prepareScene(doc, opt);
  ASSERT_TRUE(off.ok()) << off.error().message();
  ASSERT_EQ(off->response.family(), ResponseFamily::ToeShoulder);
  opt.checkResponseByLightFit = true;
  opt.responseFitTolerance = std::numeric_limits<double>::infinity();
  opt.responseQuick.maxPixels = 0;  // the full check (with an infinite tolerance copies never decide)
  countStageStarts(opt, onStarts);
  auto kept = prepareScene(doc, opt);
  ASSERT_TRUE(kept.ok()) << kept.error().message();
  expectSameRenderInputs(*kept, *off);
  // The progress is the curve's (on the calling thread); sRGB's candidate, prepared beside it,
  // reports none.
  EXPECT_EQ(onStarts, offStarts);
  std::vector<std::string> expected = stageNames(*off);
  expected.insert(std::find(expected.begin(), expected.end(), "photo size"), "response check");
  EXPECT_EQ(stageNames(*kept), expected);
  const StageRecord* check = stageNamed(*kept, "response check");
  ASSERT_NE(check, nullptr);
  EXPECT_EQ(check->detail.rfind("the curve kept: ", 0), 0u) << check->detail;
  std::vector<std::string> again;
  double againSeconds = 0;
  const StageStep* both = nullptr;  // both candidates' block (the last step)
  for (const StageStep& s : check->steps) {
    if (s.name.rfind("both candidates, ", 0) == 0) {
      both = &s;
      continue;
    }
    again.push_back(s.name);
    againSeconds += s.seconds;
  }
  ASSERT_NE(both, nullptr);
  EXPECT_EQ(&check->steps.back(), both);
  ASSERT_FALSE(again.empty());
  EXPECT_EQ(again.front(), "response");
  EXPECT_NE(std::find(again.begin(), again.end(), "lighting"), again.end());
  for (const char* once : {"photo", "photo size", "render scene", "objects", "grain"})
    EXPECT_EQ(std::find(again.begin(), again.end(), once), again.end()) << once;
  // The check's record and the curve's records after the response together cover sRGB's
  // candidate, prepared beside the curve's stages (or after them with one thread).
  double curveSeconds = 0;
  for (auto it = std::find(expected.begin(), expected.end(), "response") + 1; *it != "response check";
       ++it)
    curveSeconds += stageNamed(*kept, *it)->seconds;
  EXPECT_GE(check->seconds + curveSeconds, againSeconds - 1e-6);
  EXPECT_GE(both->seconds, againSeconds - 1e-6);
  EXPECT_GE(both->seconds, curveSeconds - 1e-6);
  EXPECT_GE(check->seconds, 0);
  EXPECT_GE(check->cpuSeconds, 0);
}

// Whether the decomposition ran in `stage`'s record before the response check's (the stages of
// the response the check saw first, the curve's).
bool decomposedIn(const PreparedScene& ps, const std::string& stage) {
  for (const StageRecord& s : ps.stages) {
    if (s.name == "response check") break;
    if (s.name == stage && s.ran)
      for (const StageStep& step : s.steps)
        if (step.name == "decomposition") return true;
  }
  return false;
}

// The full response check (copies off) decomposes only the response it keeps: the curve's last
// lighting estimate (the refit's with lights; the first's without, no refinement) waits for the
// verdict. sRGB kept: the scene is the one prepared with sRGB outright, bit for bit, and the
// curve's record has no decomposition (before, every estimate was decomposed and the curve's
// record had one); the curve kept: the scene prepared with the check off, its estimate
// decomposed after the verdict.
TEST(Engine, TheFullResponseCheckDecomposesOnlyTheResponseKept) {
  for (const bool withLights : {true, false}) {
    SCOPED_TRACE(withLights ? "the example's lights, refined and refitted" : "no light: no refit");
    SceneDoc doc = exampleDoc();
    if (!withLights) doc.lights.clear();
    const char* last = withLights ? "lighting refit" : "lighting";
    PrepareOptions opt = optionsGivingTheExampleACurve();
    opt.refitMinLightMove =
        0;  // the example's lights move less than the default's 5 %: refit all the same
    opt.workingMaxPixels = 320 * 240;  // a quarter of the photo: the test's time
    PrepareOptions plainOpt;
    plainOpt.refitMinLightMove = 0;
    plainOpt.workingMaxPixels = opt.workingMaxPixels;
    auto plain = prepareScene(doc, plainOpt);  // the default gate: sRGB, no check
    ASSERT_TRUE(plain.ok()) << plain.error().message();
    ASSERT_EQ(stageNamed(*plain, "response check"), nullptr);
    ASSERT_TRUE(stageNamed(*plain, last)->ran);
    EXPECT_TRUE(decomposedIn(*plain, last));
    opt.responseQuick.maxPixels = 0;
    auto srgbKept = prepareScene(doc, opt);
    ASSERT_TRUE(srgbKept.ok()) << srgbKept.error().message();
    ASSERT_EQ(srgbKept->response, CameraResponse::srgb());
    expectSameRenderInputs(*srgbKept, *plain);
    EXPECT_FALSE(decomposedIn(*srgbKept, last));
    opt.checkResponseByLightFit = false;
    auto off = prepareScene(doc, opt);
    ASSERT_TRUE(off.ok()) << off.error().message();
    opt.checkResponseByLightFit = true;
    opt.responseFitTolerance = std::numeric_limits<double>::infinity();  // the curve kept
    auto curveKept = prepareScene(doc, opt);
    ASSERT_TRUE(curveKept.ok()) << curveKept.error().message();
    ASSERT_EQ(curveKept->response.family(), ResponseFamily::ToeShoulder);
    expectSameRenderInputs(*curveKept, *off);
    EXPECT_FALSE(curveKept->lighting.pendingDecomposition);
    EXPECT_FALSE(curveKept->lighting.decomposeReport.empty());  // the estimate kept was decomposed
    EXPECT_EQ(curveKept->warnings.size(), off->warnings.size());
  }
}

// Cancelling while the full check prepares its two candidates side by side (at the curve's
// camera stage, sRGB's beside it) cancels the preparation: both stop, and it fails "cancelled".
TEST(Engine, CancellingTheResponseCheckCancelsThePreparation) {
  SceneDoc doc = exampleDoc();
  PrepareOptions opt = optionsGivingTheExampleACurve();
  opt.responseQuick.maxPixels = 0;
  CancelToken cancel;
  opt.cancel = &cancel;
  int cameras = 0;
  opt.progress = [&](const std::string& label, double) {
    if (label == "camera" && ++cameras == 1) cancel.cancel();
  };
  auto ps = prepareScene(doc, opt);
  EXPECT_EQ(cameras, 1);
  ASSERT_FALSE(ps.ok());
  EXPECT_EQ(ps.error().reason, "cancelled");
}

// The example's photo made stiff for the response check, saved as a PNG in `dir`: "clipped"
// over-exposed 3 times in linear light (about a tenth of it clipped to white), "flat" with its
// left two thirds one grey (codes 130, 125, 120) with a little deterministic noise (3 codes).
// With the evidence gate open both still get a curve, and their two residuals lie within a few
// percent of each other (the clipped one's 0.197 against 0.179, the flat one's 0.764 against 0.751).
std::string stiffExamplePhoto(const std::string& kind, const std::filesystem::path& dir) {
  auto photo = loadImage(std::string(INLAY_SOURCE_DIR) + "/resources/example/photo.png");
  EXPECT_TRUE(photo.ok());
  ImageF image = photo->linearRgb;
  const CameraResponse srgb = CameraResponse::srgb();
  const std::array<float, 256>& decode = srgb.table8();
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 3.0);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) {
        float& v = image.at(x, y, c);
        if (kind == "clipped") {
          v = std::min(1.f, 3 * v);
        } else if (3 * x < 2 * image.width) {
          const long code = std::lround(std::clamp(130.0 - 5 * c + noise(rng), 0.0, 255.0));
          v = float(decode[size_t(code)]);
        }
      }
  const std::string path = (dir / (kind + ".png")).string();
  EXPECT_TRUE(saveImage(path, image).ok());
  return path;
}

// The warnings without the seconds they quote ("(1.12 s)"), which differ between runs.
std::vector<std::string> withoutSeconds(std::vector<std::string> warnings) {
  const std::regex seconds(R"(\([0-9.]+ s\))");
  for (std::string& w : warnings) w = std::regex_replace(w, seconds, "(s)");
  return warnings;
}

// The full check's two candidates (copies off) prepared side by side (PrepareOptions::threads 0,
// runAlongside) give what they give one after the other (threads 1, the order before): the same
// response kept for the same reason (both residuals), the same warnings and the same scene bit
// for bit, every residual finite. The example with its false curve (sRGB kept), and two stiff
// photos that still reach the full check, one with an infinite tolerance (the curve kept).
TEST(Engine, TheFullChecksCandidatesSideBySideGiveWhatTheyGiveOneAfterTheOther) {
  const auto dir = test::tempDir("response_check_side_by_side");
  struct Case {
    std::string name, photo;
    double tolerance;
  };
  const double keepTheCurve = std::numeric_limits<double>::infinity();
  const std::vector<Case> cases = {
      {"example, sRGB kept", "", 0.0},
      {"clipped, the curve kept", stiffExamplePhoto("clipped", dir), keepTheCurve},
      {"flat, sRGB kept", stiffExamplePhoto("flat", dir), 0.0}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    SceneDoc doc = exampleDoc();
    if (!c.photo.empty()) doc.photo = doc.photoResolved = c.photo;
    PrepareOptions opt = optionsGivingTheExampleACurve();
    opt.responseQuick.maxPixels = 0;  // the full check always
    opt.responseFitTolerance = c.tolerance;
    opt.workingMaxPixels = 320 * 240;  // the test's time
    opt.threads = 1;
    auto oneAfterTheOther = prepareScene(doc, opt);
    opt.threads = 0;
    auto sideBySide = prepareScene(doc, opt);
    ASSERT_TRUE(oneAfterTheOther.ok()) << oneAfterTheOther.error().message();
    ASSERT_TRUE(sideBySide.ok()) << sideBySide.error().message();
    const StageRecord* a = stageNamed(*oneAfterTheOther, "response check");
    const StageRecord* b = stageNamed(*sideBySide, "response check");
    ASSERT_TRUE(a && b);  // a curve was fitted and checked
    // The verdict and both residuals ("... is 0.1969, with sRGB 0.1786; no quick comparison").
    EXPECT_EQ(a->detail, b->detail);
    EXPECT_EQ(b->detail.find("nan"), std::string::npos) << b->detail;
    EXPECT_EQ(oneAfterTheOther->response, sideBySide->response);
    EXPECT_EQ(withoutSeconds(oneAfterTheOther->warnings), withoutSeconds(sideBySide->warnings));
    EXPECT_EQ(stageNames(*oneAfterTheOther), stageNames(*sideBySide));
    expectSameRenderInputs(*oneAfterTheOther, *sideBySide);
    EXPECT_TRUE(std::isfinite(sideBySide->lighting.fitResidualRelative));
    for (const float v : sideBySide->renderScene.roomAlbedo.albedo.data) ASSERT_TRUE(std::isfinite(v));
    for (const AreaLight& l : sideBySide->renderScene.lights) EXPECT_TRUE(l.radiance.allFinite());
    EXPECT_FALSE(sideBySide->lighting.pendingDecomposition);
    EXPECT_GE(b->seconds, 0);
    EXPECT_GE(b->cpuSeconds, 0);
  }
  std::filesystem::remove_all(dir);
}

// The camera a preparation ran with, value for value: the camera stage's result and the room.
void expectSameCamera(const PreparedScene& a, const PreparedScene& b) {
  EXPECT_EQ(a.camera.focalPx, b.camera.focalPx);
  EXPECT_EQ(a.camera.principalPx, b.camera.principalPx);
  EXPECT_TRUE(a.camera.worldFromCamera == b.camera.worldFromCamera);
  EXPECT_EQ(a.camera.heightM, b.camera.heightM);
  EXPECT_EQ(a.backWallPx, b.backWallPx);
  EXPECT_EQ(a.box.xLeftM, b.box.xLeftM);
  EXPECT_EQ(a.box.xRightM, b.box.xRightM);
  EXPECT_EQ(a.box.zRearM, b.box.zRearM);
  EXPECT_EQ(a.box.ceilingM, b.box.ceilingM);
  EXPECT_EQ(a.cameraEstimate.has_value(), b.cameraEstimate.has_value());
}

// The response check's verdict without the copies' part ("the curve kept: the light fit's
// residual with ... is 0.1969, with sRGB 0.1786").
std::string verdictOf(const StageRecord& check) {
  return check.detail.substr(0, check.detail.find("; "));
}

// The response check's copies estimate each response's camera, and the full-size preparation
// of the same response takes its copy's instead of estimating it again (its camera stage says
// so): the curve's copy reads the curve's decoded photo, sRGB's the photo decoded as the sRGB
// candidates' response stage decodes it (srgbDecoded; the loader's values differ in some
// values). The example with its camera and back wall taken out of the scene file (estimated from
// the photo) and no object: with the false curve (optionsGivingTheExampleACurve) the copies keep
// sRGB, and the full check keeps sRGB or, with an infinite tolerance, the curve; its photo saved
// through a strong curve and "auto" given it, the copies keep the curve. Each time the verdict,
// the residuals, camera, room and scene are those of the check without copies (which estimates
// every camera at full size) bit for bit, side by side (threads 0) and one after the other
// (threads 1) alike, and the copies' step says which. Without the hand-over the camera stage
// reads "estimated from the photo"; with the sRGB copy given the photo as loaded, sRGB's does.
TEST(Engine, TheResponseCheckEstimatesEachResponsesCameraOnce) {
  SceneDoc doc = exampleDoc();
  doc.camera.vanishingPointsPx.reset();
  doc.layout.backWallPx.reset();
  doc.objects.clear();
  const auto dir = test::tempDir("response_check_camera_once");
  const ResponseParams strong{0.8, 0.3, 12.0};
  const CameraResponse curve = CameraResponse::toeShoulder(strong);
  auto plain = preparedExample();
  ASSERT_TRUE(plain.ok());
  SaveOptions so;
  so.response = &curve;
  const std::string curvedPhoto = (dir / "photo.png").string();
  ASSERT_TRUE(saveImage(curvedPhoto, plain->photo.linearRgb, so).ok());
  struct Case {
    std::string name;
    bool trueCurve;
    double margin, tolerance;
    int threads;
  };
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<Case> cases = {{"the copies keep the curve, side by side", true, 0.1, 0.0, 0},
                                   {"the copies keep the curve, one after the other", true, 0.1, 0.0, 1},
                                   {"the copies keep sRGB", false, 0.1, 0.0, 0},
                                   {"the full check keeps sRGB", false, inf, 0.0, 0},
                                   {"the full check keeps the curve", false, inf, inf, 1}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    SceneDoc d = doc;
    PrepareOptions opt = optionsGivingTheExampleACurve();
    if (c.trueCurve) {
      d.photo = d.photoResolved = curvedPhoto;
      opt = PrepareOptions();
      opt.responseEstimate.evaluateAt = strong;
    }
    opt.responseFitTolerance = c.tolerance;
    opt.responseQuick.margin = c.margin;
    opt.threads = c.threads;
    opt.workingMaxPixels = 320 * 240;  // the test's time
    PrepareOptions noCopies = opt;
    noCopies.responseQuick.maxPixels = 0;
    auto alone = prepareScene(d, noCopies);
    auto handed = prepareScene(d, opt);
    ASSERT_TRUE(alone.ok()) << alone.error().message();
    ASSERT_TRUE(handed.ok()) << handed.error().message();
    const StageRecord* a = stageNamed(*alone, "response check");
    const StageRecord* b = stageNamed(*handed, "response check");
    ASSERT_TRUE(a && b);   // a curve was fitted and checked
    if (c.margin < inf) {  // the copies decided: their verdict quotes their residuals
      EXPECT_NE(b->detail.find(" beyond "), std::string::npos) << b->detail;
      EXPECT_EQ(a->detail.substr(0, 16), b->detail.substr(0, 16));
    } else {
      EXPECT_EQ(verdictOf(*a), verdictOf(*b));
      EXPECT_EQ(withoutSeconds(alone->warnings), withoutSeconds(handed->warnings));
    }
    EXPECT_EQ(verdictOf(*b).find("nan"), std::string::npos) << b->detail;
    EXPECT_EQ(a->detail.rfind(c.tolerance < inf && !c.trueCurve ? "sRGB kept: " : "the curve kept: ", 0),
              0u)
        << a->detail;
    EXPECT_EQ(stageNames(*alone), stageNames(*handed));
    expectSameCamera(*alone, *handed);
    expectSameRenderInputs(*alone, *handed);
    ASSERT_TRUE(handed->cameraEstimate.has_value());
    EXPECT_EQ(stageNamed(*alone, "camera")->detail, "estimated from the photo");
    EXPECT_EQ(stageNamed(*handed, "camera")->detail,
              "estimated from the photo once, for the response check's copy");
    const auto step = std::find_if(b->steps.begin(), b->steps.end(), [](const StageStep& s) {
      return s.name.rfind("both copies, ", 0) == 0;
    });
    ASSERT_NE(step, b->steps.end());
    EXPECT_EQ(step->name,
              c.threads == 1 ? "both copies, one after the other" : "both copies, side by side");
    EXPECT_GE(step->seconds, 0);
  }
  std::filesystem::remove_all(dir);
}

// ResponseQuickCheck's verdict: beyond the margin either way it decides, inside it (ties
// included) it leaves the choice to the full check; residuals that are not finite and positive,
// and a NaN margin, never decide; the tolerance widens sRGB's residual as refitFitsWorse does.
TEST(Engine, TheResponseCopiesDecideOnlyBeyondTheMargin) {
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(quickResponseVerdict(0.09, 0.13, 0, 0.1), 1);    // log 0.69 = -0.37: the curve
  EXPECT_EQ(quickResponseVerdict(0.20, 0.17, 0, 0.1), -1);   // +0.16: sRGB
  EXPECT_EQ(quickResponseVerdict(0.100, 0.105, 0, 0.1), 0);  // -0.05: the full check
  EXPECT_EQ(quickResponseVerdict(0.1, 0.1, 0, 0), 0);        // a tie never decides
  EXPECT_EQ(quickResponseVerdict(0.1, 0.1, 0, -1), 0);
  EXPECT_EQ(quickResponseVerdict(0.2, 0.17, 0.5, 0.1), 1);   // the tolerance moves the centre
  EXPECT_EQ(quickResponseVerdict(0.2, 0.17, -3, 0.1), -1);   // a negative tolerance is 0
  EXPECT_EQ(quickResponseVerdict(0.2, 0.17, nan, 0.1), -1);  // so is NaN
  EXPECT_EQ(quickResponseVerdict(0.2, 0.17, inf, 0.1), 0);   // an infinite one: never decides
  EXPECT_EQ(quickResponseVerdict(0.09, 0.13, 0, inf), 0);    // an infinite margin: never
  EXPECT_EQ(quickResponseVerdict(0.09, 0.13, 0, nan), 0);
  for (double bad : {nan, inf, -inf, 0.0, -0.1}) {
    EXPECT_EQ(quickResponseVerdict(bad, 0.13, 0, 0.1), 0) << bad;
    EXPECT_EQ(quickResponseVerdict(0.13, bad, 0, 0.1), 0) << bad;
  }
  EXPECT_EQ(quickResponseVerdict(1e-300, 1e300, 0, 0.1), 1);  // extreme but finite: no overflow
  EXPECT_EQ(quickResponseVerdict(1e300, 1e-300, 0, 0.1), -1);
  EXPECT_EQ(quickResponseVerdict(5e-324, 1.0, 0, 0.1), 1);  // a denormal residual
}

// The response (given as `params` through ResponseEstimateOptions::evaluateAt) of the example's
// photo, saved through `encodeWith` (null: as sRGB, the example's own codes), checked by the full
// check alone (copies off) and by the copies first (the default): the same response kept, and
// the copies decided it without the second preparation (their record says so, the scene is the
// full check's bit for bit).
void expectTheCopiesDecideAsTheFullCheck(const CameraResponse* encodeWith, const ResponseParams& params,
                                         bool curveKept, const std::string& name) {
  SceneDoc doc = exampleDoc();
  doc.objects.clear();
  const auto dir = test::tempDir(name);
  if (encodeWith) {
    auto plain = preparedExample();
    ASSERT_TRUE(plain.ok());
    SaveOptions so;
    so.response = encodeWith;
    const std::string photoPath = (dir / "photo.png").string();
    ASSERT_TRUE(saveImage(photoPath, plain->photo.linearRgb, so).ok());
    doc.photo = doc.photoResolved = photoPath;
  }
  PrepareOptions opt;
  opt.responseEstimate.evaluateAt = params;
  PrepareOptions full = opt;
  full.responseQuick.maxPixels = 0;
  auto byFull = prepareScene(doc, full);
  auto byCopies = prepareScene(doc, opt);
  ASSERT_TRUE(byFull.ok() && byCopies.ok()) << name;
  const StageRecord* fullCheck = stageNamed(*byFull, "response check");
  const StageRecord* copiesCheck = stageNamed(*byCopies, "response check");
  ASSERT_TRUE(fullCheck && copiesCheck) << name;
  const std::string kept = curveKept ? "the curve kept: " : "sRGB kept: ";
  EXPECT_EQ(fullCheck->detail.rfind(kept, 0), 0u) << fullCheck->detail;
  EXPECT_EQ(copiesCheck->detail.rfind(kept, 0), 0u) << copiesCheck->detail;
  EXPECT_NE(copiesCheck->detail.find(" copies "), std::string::npos) << copiesCheck->detail;
  EXPECT_NE(copiesCheck->detail.find(" beyond "), std::string::npos) << copiesCheck->detail;
  EXPECT_EQ(byCopies->response, byFull->response) << name;
  EXPECT_EQ(stageNames(*byCopies), stageNames(*byFull)) << name;
  expectSameRenderInputs(*byCopies, *byFull);
  for (const StageStep& step : copiesCheck->steps)  // the second preparation never ran
    EXPECT_TRUE(step.name.rfind("copy, ", 0) == 0 || step.name.rfind("both copies, ", 0) == 0 ||
                step.name == "sRGB: response")
        << step.name;
  // The copies cost less than the full check's two candidates (its last step times them
  // together: side by side, its own record holds only what they took beyond the curve's stages).
  EXPECT_LT(copiesCheck->cpuSeconds, fullCheck->steps.back().cpuSeconds) << name;
  EXPECT_EQ(fullCheck->steps.back().name.rfind("both candidates, ", 0), 0u) << name;
  std::filesystem::remove_all(dir);
}

// PrepareOptions::responseQuick on a synthetic photo pair: the example's linear radiance saved
// through a strong toe-and-shoulder curve and "auto" given exactly that curve (right: the curve
// kept), and the example's own sRGB photo given that curve (wrong: sRGB kept).
TEST(Engine, TheResponseCopiesReachTheFullChecksVerdict) {
  const ResponseParams strong{0.8, 0.3, 12.0};
  const CameraResponse curve = CameraResponse::toeShoulder(strong);
  expectTheCopiesDecideAsTheFullCheck(&curve, strong, true, "response_copies_right");
  expectTheCopiesDecideAsTheFullCheck(nullptr, strong, false, "response_copies_wrong");
}

// The copies' solver tolerance (ResponseQuickCheck::fitTolerance, LightingOptions::
// fitFunctionTolerance) outside (0, 1) falls back to Ceres' default: the example's false curve is
// still taken away by the copies, with finite residuals.
TEST(Engine, TheResponseCopiesSurviveAToleranceThatIsNoTolerance) {
  SceneDoc doc = exampleDoc();
  doc.objects.clear();
  for (const double tolerance : {std::nan(""), 0.0, -1.0, 1e300}) {
    PrepareOptions opt = optionsGivingTheExampleACurve();
    opt.responseQuick.fitTolerance = tolerance;
    auto ps = prepareScene(doc, opt);
    ASSERT_TRUE(ps.ok()) << ps.error().message();
    EXPECT_EQ(ps->response, CameraResponse::srgb()) << tolerance;
    const StageRecord* check = stageNamed(*ps, "response check");
    ASSERT_NE(check, nullptr);
    EXPECT_NE(check->detail.find(" beyond "), std::string::npos) << check->detail;
    EXPECT_EQ(check->detail.find("nan"), std::string::npos) << check->detail;
    EXPECT_TRUE(std::isfinite(ps->lighting.fitResidualRelative)) << tolerance;
  }
}

// Stiff photos under "auto" with the check on: a black photo and a clipped one give no curve to
// check (sRGB with a warning saying why), and their preparation either succeeds with finite
// residuals or fails with one message naming the photo; never a crash or a NaN decision.
TEST(Engine, StiffPhotosNeverReachTheResponseCheck) {
  SceneDoc base = exampleDoc();
  base.objects.clear();
  const auto dir = test::tempDir("response_check_stiff");
  for (const float value : {0.0f, 1.0f}) {
    ImageF flat(320, 240, 3);
    for (float& v : flat.data) v = value;
    const std::string photoPath = (dir / (value > 0 ? "clipped.png" : "black.png")).string();
    ASSERT_TRUE(saveImage(photoPath, flat).ok());
    SceneDoc doc = base;
    doc.photo = doc.photoResolved = photoPath;
    doc.lights.clear();
    PrepareOptions opt;
    opt.responseEstimate.evaluateAt = ResponseParams{0.8, 0.3, 12.0};
    auto ps = prepareScene(doc, opt);
    if (!ps.ok()) {
      EXPECT_EQ(ps.error().key, "photo") << ps.error().message();
      EXPECT_FALSE(ps.error().reason.empty());
      continue;
    }
    EXPECT_EQ(ps->response, CameraResponse::srgb()) << value;
    EXPECT_EQ(stageNamed(*ps, "response check"), nullptr) << value;
    size_t warned = 0;
    for (const auto& w : ps->warnings) warned += w.rfind("camera response: ", 0) == 0;
    EXPECT_EQ(warned, 1u) << value;
    EXPECT_FALSE(std::isinf(ps->lighting.fitResidualRelative)) << value;
  }
  std::filesystem::remove_all(dir);
}

// Every stage of the preparation is on record, in order, with its seconds or the reason this
// scene skipped it: the example marks no occluder, surface or shaft.
TEST(Engine, EveryStageIsReportedWithItsSecondsOrWhyItWasSkipped) {
  auto ps = preparedExample();
  ASSERT_TRUE(ps.ok()) << ps.error().message();
  std::vector<std::string> names;
  for (const StageRecord& s : ps->stages) {
    names.push_back(s.name);
    EXPECT_EQ(s.ran, s.reason.empty()) << s.name;
    EXPECT_TRUE(std::isfinite(s.seconds) && s.seconds >= 0) << s.name;
    if (!s.ran) {
      EXPECT_EQ(s.seconds, 0.0) << s.name;
    }
  }
  const std::vector<std::string> expected = {
      "photo",          "response",   "working copy", "camera",   "layout",     "occluders", "surfaces",
      "room",           "lights",     "shafts",       "lighting", "vignetting", "sun ratio", "refine",
      "lighting refit", "photo size", "render scene", "objects",  "grain"};
  EXPECT_EQ(names, expected);
  for (const char* skipped : {"occluders", "surfaces", "shafts", "sun ratio", "photo size"})
    EXPECT_FALSE(stageNamed(*ps, skipped)->ran) << skipped;
  for (const char* ran : {"photo", "camera", "lighting", "refine", "objects"})
    EXPECT_TRUE(stageNamed(*ps, ran)->ran) << ran;
  EXPECT_EQ(describeStage(*stageNamed(*ps, "shafts")), "shafts: skipped, no sun marked");
  EXPECT_EQ(describeStage(*stageNamed(*ps, "occluders")), "occluders: skipped, none marked");
  // The example (512 x 384) is smaller than the working size: every stage at the photo's size.
  EXPECT_EQ(ps->workingPx, (std::array<int, 2>{512, 384}));
  EXPECT_EQ(describeStage(*stageNamed(*ps, "photo size")),
            "photo size: skipped, the working copy is the photo");
  for (const StageRecord& s : ps->stages) EXPECT_FALSE(s.reducedImage) << s.name;
  EXPECT_EQ(stageNamed(*ps, "lighting")->workingWidth, 512);
  EXPECT_EQ(stageNamed(*ps, "camera")->detail, "the file's vanishing points and back wall");
  const std::string refine = describeStage(*stageNamed(*ps, "refine"));
  EXPECT_EQ(refine.rfind("refine: ", 0), 0u) << refine;
  EXPECT_NE(refine.find(" s (2 of 2 lights refined"), std::string::npos) << refine;
  // The lighting stages say where their seconds went: disjoint steps inside the stage's time.
  for (const char* name : {"lighting", "lighting refit"}) {
    const StageRecord& lighting = *stageNamed(*ps, name);
    if (!lighting.ran) continue;  // the refit: when a light moved
    ASSERT_FALSE(lighting.steps.empty()) << name;
    std::vector<std::string> steps;
    double stepsCpu = 0, stepsWall = 0;
    for (const StageStep& step : lighting.steps) {
      steps.push_back(step.name);
      stepsCpu += step.cpuSeconds, stepsWall += step.seconds;
    }
    EXPECT_EQ(steps.front(), "surfaces") << name;
    EXPECT_NE(std::find(steps.begin(), steps.end(), "gather"), steps.end()) << name;
    EXPECT_NE(std::find(steps.begin(), steps.end(), "decomposition"), steps.end()) << name;
    EXPECT_LE(stepsCpu, lighting.cpuSeconds) << name;
    EXPECT_LE(stepsWall, lighting.seconds) << name;
    const std::string line = describeStage(lighting);
    EXPECT_NE(line.find(" light fit iterations); CPU s: surfaces "), std::string::npos) << line;
  }
  for (const Surface& s : ps->geometry.surfaces) EXPECT_NE(s.kind, SurfaceKind::OccluderCard);
  EXPECT_TRUE(ps->lighting.suns.empty());
}

// A scene with no occluder, no sun, no object and every light locked does less: the refinement
// and the lighting refit are skipped, and neither runs (the process-wide counters of the
// refinement and the decomposition say so); the lights are the estimate's.
TEST(Engine, ASceneWithEveryLightLockedSkipsTheRefinementAndItsRefit) {
  SceneDoc doc = exampleDoc();
  for (LightKeys& l : doc.lights) l.lock = true;
  doc.objects.clear();
  const uint64_t refinements = lightRefinementRuns(), decompositions = decompositionRuns();
  auto ps = prepareScene(doc);
  ASSERT_TRUE(ps.ok()) << ps.error().message();
  EXPECT_EQ(lightRefinementRuns(), refinements);
  EXPECT_EQ(decompositionRuns(), decompositions + 1);
  EXPECT_EQ(describeStage(*stageNamed(*ps, "refine")), "refine: skipped, every light locked");
  EXPECT_EQ(describeStage(*stageNamed(*ps, "lighting refit")),
            "lighting refit: skipped, the lights were not refined");
  EXPECT_EQ(describeStage(*stageNamed(*ps, "objects")), "objects: skipped, none inserted");
  EXPECT_TRUE(ps->refinement.history.empty());
  EXPECT_TRUE(ps->renderScene.objects.empty());
  ASSERT_EQ(ps->renderScene.lights.size(), ps->initialLights.size());
  for (size_t j = 0; j < ps->initialLights.size(); ++j) {
    EXPECT_EQ(ps->renderScene.lights[j].radiance, ps->initialLights[j].radiance);
    EXPECT_EQ(ps->renderScene.lights[j].cornersWorld, ps->initialLights[j].cornersWorld);
  }
  // The unlocked example did refine (the same counter moves for it).
  const auto example = preparedExample();
  ASSERT_TRUE(example.ok());
  EXPECT_TRUE(stageNamed(*example, "refine")->ran);
}

// A refinement cut short by its last-resort time guard (here one of a nanosecond) is not hidden:
// the preparation warns that the lights may differ on another machine, and the refine stage's
// record says so. The example's own refinement ends on its tolerances, well within its budget.
TEST(Engine, ARefinementCutShortByItsTimeGuardIsAWarning) {
  SceneDoc doc = exampleDoc();
  doc.objects.clear();
  PrepareOptions opt;
  opt.refine.guardSeconds = 1e-9;
  auto ps = prepareScene(doc, opt);
  ASSERT_TRUE(ps.ok()) << ps.error().message();
  EXPECT_TRUE(ps->refinement.stoppedByGuard);
  const bool warned = std::any_of(ps->warnings.begin(), ps->warnings.end(), [](const std::string& w) {
    return w.rfind("light refinement: stopped by its time guard", 0) == 0 &&
           w.find("may differ on another machine") != std::string::npos;
  });
  EXPECT_TRUE(warned) << ::testing::PrintToString(ps->warnings);
  EXPECT_NE(describeStage(*stageNamed(*ps, "refine")).find("stopped by the time guard"),
            std::string::npos)
      << describeStage(*stageNamed(*ps, "refine"));
  const auto example = preparedExample();
  ASSERT_TRUE(example.ok());
  EXPECT_FALSE(example->refinement.stoppedByGuard || example->refinement.stoppedByBudget)
      << example->refinement.report;
  EXPECT_LT(example->refinement.evaluations, opt.refine.maxEvaluations / 10);
  for (const std::string& w : example->warnings) EXPECT_EQ(w.find("time guard"), std::string::npos) << w;
}

}  // namespace
}  // namespace inlay

namespace inlay {
namespace {

AreaLight squareLight(double side, const Vec3& at) {
  AreaLight l;
  l.cornersWorld = {at, at + Vec3(side, 0, 0), at + Vec3(side, 0, side), at + Vec3(0, 0, side)};
  return l;
}

// PrepareOptions::refitMinLightMove's measure: a corner's largest move over its light's size
// (the square root of its area), the largest over the lights; extreme and broken inputs give a
// number that refits (infinite), never NaN.
TEST(Engine, TheLargestLightMoveIsInUnitsOfEachLightsSize) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<AreaLight> lights{squareLight(1.0, {0, 2, 0}), squareLight(0.1, {1, 2, 1})};
  EXPECT_EQ(largestLightMove(lights, lights), 0.0);
  EXPECT_EQ(largestLightMove({}, {}), 0.0);
  auto moved = lights;
  for (Vec3& c : moved[0].cornersWorld) c.x() += 0.02;  // 2 % of the big light
  EXPECT_NEAR(largestLightMove(lights, moved), 0.02, 1e-9);
  moved[1].cornersWorld[2].z() += 0.01;  // one corner, 10 % of the small light
  EXPECT_NEAR(largestLightMove(lights, moved), 0.1, 1e-9);
  EXPECT_EQ(largestLightMove(lights, {lights[0]}), inf);  // not the same lights
  auto degenerate = lights;
  degenerate[1].cornersWorld.fill(Vec3(1, 2, 1));  // no area: any move is infinite
  EXPECT_EQ(largestLightMove(degenerate, degenerate), 0.0);
  EXPECT_EQ(largestLightMove(degenerate, lights), inf);
  moved[0].cornersWorld[1].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(largestLightMove(lights, moved), inf);
  moved[0].cornersWorld[1].x() = 1e308;
  EXPECT_EQ(largestLightMove(lights, moved), inf);
}

// The refit is skipped when the refinement moved no light by refitMinLightMove of its size (the
// stage says by how much; the first estimate's lights are kept, one decomposition), and runs
// when it moved one by more.
TEST(Engine, TheRefitIsSkippedWhenTheLightsHardlyMoved) {
  const auto example = preparedExample();
  ASSERT_TRUE(example.ok());
  const double move = largestLightMove(example->initialLights, example->refinement.lights);
  ASSERT_GT(move, 0.0);  // the example's refinement moves its lights
  ASSERT_TRUE(std::isfinite(move));
  PrepareOptions skip, refit;
  skip.refitMinLightMove = move * 1.01;
  refit.refitMinLightMove = move * 0.99;
  const uint64_t before = decompositionRuns();
  auto skipped = prepareScene(exampleDoc(), skip);
  ASSERT_TRUE(skipped.ok()) << skipped.error().message();
  EXPECT_EQ(decompositionRuns(), before + 1);
  const StageRecord* stage = stageNamed(*skipped, "lighting refit");
  ASSERT_NE(stage, nullptr);
  EXPECT_FALSE(stage->ran);
  EXPECT_NE(describeStage(*stage).find("skipped, lights moved by at most"), std::string::npos)
      << describeStage(*stage);
  ASSERT_EQ(skipped->renderScene.lights.size(), skipped->initialLights.size());
  for (size_t j = 0; j < skipped->initialLights.size(); ++j) {
    EXPECT_EQ(skipped->renderScene.lights[j].cornersWorld, skipped->initialLights[j].cornersWorld);
    EXPECT_EQ(skipped->renderScene.lights[j].radiance, skipped->initialLights[j].radiance);
  }
  auto ran = prepareScene(exampleDoc(), refit);
  ASSERT_TRUE(ran.ok()) << ran.error().message();
  EXPECT_EQ(decompositionRuns(), before + 3);
  EXPECT_TRUE(stageNamed(*ran, "lighting refit")->ran);
  // The refit goes on from the first estimate's passes (LightingOptions::warmStart).
  EXPECT_NE(describeStage(*stageNamed(*ran, "lighting refit")).find("going on from its passes"),
            std::string::npos);
}

double lightLuminance(const PreparedScene& ps) {
  double sum = 0;
  for (const AreaLight& l : ps.lighting.lights) sum += l.radiance.mean() * l.area();
  return sum;
}

// The example (a plain render, no vignetting) through a camera with v = 0.3, prepared with
// "auto": the estimate is applied, the light fit in the devignetted radiance finds the plain
// photo's lights within half of "none"'s error on the vignetted photo, and with no object
// the PNG keeps the vignetted photo's codes bit for bit. "auto" leaves the plain example alone,
// and "none" (the default) skips the stage.
TEST(Engine, AVignettedPhotosLightIsFittedInDevignettedRadiance) {
  const SceneDoc plainDoc = exampleDoc();
  auto plain = preparedExample();
  ASSERT_TRUE(plain.ok()) << plain.error().message();
  EXPECT_EQ(plain->vignetting, 0.0);
  EXPECT_FALSE(stageNamed(*plain, "vignetting")->ran);
  EXPECT_EQ(describeStage(*stageNamed(*plain, "vignetting")),
            "vignetting: skipped, camera.vignetting is \"none\" (the default)");
  SceneDoc plainAuto = plainDoc;
  plainAuto.objects.clear();
  plainAuto.camera.vignetting.mode = VignettingKeys::Mode::Auto;
  auto untouched = prepareScene(plainAuto);
  ASSERT_TRUE(untouched.ok()) << untouched.error().message();
  EXPECT_TRUE(stageNamed(*untouched, "vignetting")->ran);
  EXPECT_EQ(untouched->vignetting, 0.0);  // a plain photo: nothing applied
  EXPECT_LT(untouched->vignettingEstimated, kMinAutoVignetting);

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
