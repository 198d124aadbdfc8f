// Shared by the fuzz targets: a private scratch folder, and writing one input to a file there
// (the importers read files by path, as the CLI and the studio call them).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "inlay/modeling/mesh.h"

namespace inlay::fuzz {

// A folder of this process's own (libFuzzer may run several processes at once).
inline const std::filesystem::path& scratchDir() {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() / ("inlay_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

inline std::string writeInput(const std::string& name, const uint8_t* data, size_t size) {
  std::string path = (scratchDir() / name).string();
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

// One mesh target: the input saved as `name` (its extension picks the importer) and read
// through loadMesh, the path the CLI and the studio use, with small limits so that a header
// promising a huge mesh is refused rather than allocated. Success must mean a usable mesh.
inline int loadMeshInput(const std::string& name, const uint8_t* data, size_t size) {
  const std::string path = writeInput(name, data, size);
  MeshLimits limits;
  limits.maxTriangles = 100'000;
  limits.maxVertices = 100'000;
  auto mesh = loadMesh(path, limits);
  if (mesh && mesh->triangles.empty()) __builtin_trap();
  return 0;
}

}  // namespace inlay::fuzz
