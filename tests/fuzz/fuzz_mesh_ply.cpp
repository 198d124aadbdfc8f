// Fuzz target: the .ply importer (see loadMeshInput).
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return inlay::fuzz::loadMeshInput("input.ply", data, size);
}
