// Our side of the Blender Cycles comparison (bench_cycles.py): prepares a scene file through the
// engine, exports it as glTF (what Cycles renders), and path traces the same scene in full
// (bounces never take the photo's radiance, as Cycles cannot) at W x H, writing a linear EXR
// with the layers "with_objects" (RGB) and "region" (per pixel: room surface id, 100 + object
// index, -1 none; what the pixel centre sees) and a JSON line with timings.
//
// usage: bench_cycles_ours SCENE.json OUT_DIR WIDTH HEIGHT SPP [THREADS]
#include "inlay/engine/pipeline.h"
#include "inlay/modeling/image_io.h"
#include "inlay/render/path_tracer.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

using namespace inlay;

namespace {

// What each pixel centre of a W x H view of the camera sees first.
ImageF regionIds(const RenderScene& s, const ImageF& mask, int w, int h) {
  ImageF region(w, h, 1, -1.f);
  const double sx = double(s.camera.widthPx) / w, sy = double(s.camera.heightPx) / h;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (mask.at(x, y) > 0.5f) {
        region.at(x, y) = 100.f;  // every object counts as one region here (one object per scene)
        continue;
      }
      const auto hit = s.room.intersect(s.camera.rayThroughPixel(Vec2((x + 0.5) * sx, (y + 0.5) * sy)));
      if (hit) region.at(x, y) = float(hit->surfaceId);
    }
  return region;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 6) {
    std::fprintf(stderr, "usage: bench_cycles_ours SCENE.json OUT_DIR WIDTH HEIGHT SPP [THREADS]\n");
    return 2;
  }
  const std::filesystem::path out = argv[2];
  const int w = std::atoi(argv[3]), h = std::atoi(argv[4]), spp = std::atoi(argv[5]);
  const int threads = argc > 6 ? std::atoi(argv[6]) : 0;
  auto loaded = loadSceneFile(argv[1]);
  if (!loaded) return std::fprintf(stderr, "%s\n", loaded.error().message().c_str()), 2;
  auto prepared = prepareScene(loaded->doc);
  if (!prepared) return std::fprintf(stderr, "%s\n", prepared.error().message().c_str()), 2;
  std::filesystem::create_directories(out);
  std::vector<std::string> warnings;
  if (Status st = exportSceneGltf(*prepared, (out / "scene.gltf").string(), &warnings); !st.ok())
    return std::fprintf(stderr, "%s\n", st.error().message().c_str()), 2;
  for (const auto& wline : warnings) std::fprintf(stderr, "warning: %s\n", wline.c_str());

  RenderScene scene = prepared->renderScene;
  scene.roomAlbedo.photoRadiance = ImageF();  // full path tracing, as Cycles does
  scene.roomAlbedo.photoRadianceUsable.clear();
  TracerOptions options;
  options.maxDepth = 8;
  PathTracer tracer(scene, options);
  DifferentialBuffers b(w, h);
  const auto t0 = std::chrono::steady_clock::now();
  if (!tracer.render(b, 0, spp, 1, threads)) return 1;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const ImageF with = b.meanWith(), mask = b.meanMask();
  const ImageF region = regionIds(scene, mask, w, h);
  if (Status st = saveLayersExr((out / "ours.exr").string(),
                                {{"with_objects", &with}, {"region", &region}}, false);
      !st.ok())
    return std::fprintf(stderr, "%s\n", st.error().message().c_str()), 2;
  std::printf("{\"seconds\": %.3f, \"spp\": %d, \"width\": %d, \"height\": %d, \"rays\": %llu}\n",
              seconds, spp, w, h, (unsigned long long)tracer.stats().rays);
  return 0;
}
