// Fuzz target: the scene-file parser (JSON, every key's validation, limits). Paths in the input
// resolve against a scratch folder holding a photo.png and a mesh.obj, so inputs that name them
// reach the code past the path checks.
#include "fuzz_support.h"
#include "inlay/modeling/scene_file.h"

#include <fstream>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string base = [] {
    const auto& d = inlay::fuzz::scratchDir();
    std::ofstream(d / "photo.png") << "not decoded by the parser";
    std::ofstream(d / "mesh.obj") << "v 0 0 0\n";
    return d.string();
  }();
  const std::string text(reinterpret_cast<const char*>(data), size);
  inlay::SceneLimits limits;
  limits.maxFileBytes = 1 << 20;
  auto loaded = inlay::parseSceneJson(text, base, "fuzz.json", limits);
  if (loaded) {  // what parses must serialise and parse back
    auto again = inlay::parseSceneJson(inlay::sceneToJson(loaded->doc), base, "again.json", limits);
    if (!again) __builtin_trap();
  }
  return 0;
}
