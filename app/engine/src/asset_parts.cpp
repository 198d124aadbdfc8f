// Splitting a multi-material asset into single-material objects (see asset_parts.h).
#include "inlay/engine/asset_parts.h"

#include "inlay/engine/pipeline.h"

namespace inlay {

namespace {

// The triangles of `mesh` whose material is `material`, with their vertices renumbered.
TriangleMesh partOf(const TriangleMesh& mesh, uint32_t material) {
  TriangleMesh part;
  part.materials = {mesh.materials[material]};
  std::vector<int64_t> remap(mesh.positions.size(), -1);
  const bool normals = mesh.normals.size() == mesh.positions.size();
  const bool uvs = mesh.uvs.size() == mesh.positions.size();
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (mesh.triangleMaterial[t] != material) continue;
    std::array<uint32_t, 3> tri;
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = mesh.triangles[t][size_t(k)];
      if (remap[v] < 0) {
        remap[v] = int64_t(part.positions.size());
        part.positions.push_back(mesh.positions[v]);
        if (normals) part.normals.push_back(mesh.normals[v]);
        if (uvs) part.uvs.push_back(mesh.uvs[v]);
      }
      tri[size_t(k)] = uint32_t(remap[v]);
    }
    part.triangles.push_back(tri);
  }
  part.triangleMaterial.assign(part.triangles.size(), 0u);
  return part;
}

}  // namespace

std::vector<std::shared_ptr<const TriangleMesh>> meshPartsByMaterial(const TriangleMesh& mesh) {
  const bool perTriangle = mesh.materials.size() > 1 && mesh.triangleMaterial.size() == mesh.triangles.size();
  if (!perTriangle) return {std::make_shared<const TriangleMesh>(mesh)};
  std::vector<size_t> count(mesh.materials.size(), 0);
  for (uint32_t m : mesh.triangleMaterial)
    if (m < count.size()) ++count[m];
  std::vector<std::shared_ptr<const TriangleMesh>> parts;
  for (uint32_t m = 0; m < mesh.materials.size(); ++m)
    if (count[m] > 0) parts.push_back(std::make_shared<const TriangleMesh>(partOf(mesh, m)));
  return parts;
}

std::vector<InsertedObject> assetObjects(const TriangleMesh& mesh, const Mat4& worldFromObject) {
  MaterialKeys asset;
  asset.preset = "asset";
  std::vector<InsertedObject> objects;
  for (auto& part : meshPartsByMaterial(mesh)) {
    InsertedObject o;
    o.material = materialFromKeys(asset, part.get());
    o.meshObject = std::move(part);
    o.worldFromObject = worldFromObject;
    objects.push_back(std::move(o));
  }
  return objects;
}

}  // namespace inlay
