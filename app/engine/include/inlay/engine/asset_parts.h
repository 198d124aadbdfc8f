// A mesh with several materials (a glTF asset: a lamp's brass stand and its glowing shade) as
// the renderer can draw it. The renderer gives each InsertedObject one Material, so an asset
// becomes one object per material, all sharing one transform. Each part's material is the
// file's, mapped as materialFromKeys() maps preset "asset" (emission -> Emissive, so a glowing
// part is a light; transmission -> glass; metallic -> metal; else glossy or diffuse).
#pragma once

#include "inlay/modeling/mesh.h"
#include "inlay/render/scene.h"

#include <memory>
#include <vector>

namespace inlay {

// One TriangleMesh per material of `mesh` that has triangles (in material order), each holding
// only that material (materials.size() == 1) and the vertices its triangles use. A mesh without
// per-triangle materials comes back as one part (itself).
std::vector<std::shared_ptr<const TriangleMesh>> meshPartsByMaterial(const TriangleMesh& mesh);

// The parts of `mesh` as objects placed by `worldFromObject`, each with its own material.
std::vector<InsertedObject> assetObjects(const TriangleMesh& mesh, const Mat4& worldFromObject);

}  // namespace inlay
