// Fuzz target: the .gltf importer (see loadMeshInput).
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return inlay::fuzz::loadMeshInput("input.gltf", data, size);
}
