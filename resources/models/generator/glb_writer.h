// A library piece as a glTF 2.0 binary (.glb): one node and mesh named after the piece, one
// primitive per material (POSITION with its bounds, NORMAL, TEXCOORD_0 in metres, indices
// 16-bit where they fit), metallic-roughness materials; an emission brighter than 1 is written
// as emissiveFactor x KHR_materials_emissive_strength (which modeling's glTF reader honours).
#pragma once

#include "inlay/modeling/core.h"
#include "inlay/modeling/mesh.h"

#include <string>

namespace inlay::library {

// The GLB bytes of `mesh` (its materials and triangleMaterial) as node `name`.
std::string glbOf(const TriangleMesh& mesh, const std::string& name);

// Writes glbOf() to `path` atomically.
Status writeGlb(const TriangleMesh& mesh, const std::string& name, const std::string& path);

}  // namespace inlay::library
