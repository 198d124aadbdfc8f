// Fuzz target: the .ply importer through loadMesh (the path the CLI and the studio use), with
// small limits so that a header promising a huge mesh is refused rather than allocated.
#include "fuzz_support.h"
#include "inlay/modeling/mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path = inlay::fuzz::writeInput("input.ply", data, size);
  inlay::MeshLimits limits;
  limits.maxTriangles = 100'000;
  limits.maxVertices = 100'000;
  auto mesh = inlay::loadMesh(path, limits);
  if (mesh && mesh->triangles.empty()) __builtin_trap();  // success means a usable mesh
  return 0;
}
