// Triangle meshes as plain arrays (what the renderer and the tests consume), and the
// importers. OBJ and PLY go through OpenMesh, glTF/GLB through Assimp; builtins are generated.
// Every importer validates: finite coordinates, indices in range, at least one triangle with
// non-zero area; a failure names the file and the element.
#pragma once

#include "inlay/modeling/core.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace inlay {

// A material as a file describes it (OBJ/MTL or glTF metallic-roughness), before mapping to
// the renderer's models.
struct AssetMaterial {
  std::string name;
  Vec3 baseColor{0.8, 0.8, 0.8};
  double metallic = 0.0;
  double roughness = 0.5;
  double transmission = 0.0;
  double ior = 1.5;
  Vec3 emission{0, 0, 0};  // radiance multiplier (emissive colour x strength)
};

struct TriangleMesh {
  std::vector<Vec3f> positions;
  std::vector<Vec3f> normals;  // per vertex; empty = flat shading
  std::vector<Vec2f> uvs;      // per vertex; may be empty
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<uint32_t> triangleMaterial;  // per triangle index into `materials`; may be empty
  std::vector<AssetMaterial> materials;

  bool empty() const { return triangles.empty(); }
  Eigen::AlignedBox3f bounds() const;
  void computeVertexNormals();  // area-weighted; replaces `normals`
  void append(const TriangleMesh& other);
};

struct MeshLimits {
  size_t maxTriangles = 20'000'000;
  size_t maxVertices = 20'000'000;
  long long maxFileBytes = 2'000'000'000LL;
};

// What a file says about itself beyond its triangles.
struct MeshFileInfo {
  // Metres per unit of the returned positions when the format fixes it (glTF: 1; COLLADA: 1,
  // Assimp applies its <unit>; FBX: its UnitScaleFactor / 100), else 0 (OBJ, PLY, 3DS).
  double metresPerUnit = 0;
  std::string format;  // "obj", "ply", "gltf", "fbx", "dae", "3ds", "builtin"
};

// The mesh formats loadMesh reads, as lower-case extensions with the dot.
const std::vector<std::string>& meshFileExtensions();

// "builtin:sphere" (unit-diameter sphere, smooth), "builtin:cube" (unit cube), or a file path
// (.obj, .ply, .gltf, .glb by our validating readers; .fbx, .dae, .3ds through Assimp, by
// extension). The mesh is returned in the file's own units and axes with z-up files turned
// y-up when the file says so (FBX UpAxis; COLLADA up_axis through Assimp; 3DS is z-up).
Expected<TriangleMesh> loadMesh(const std::string& pathOrBuiltin, const MeshLimits& limits = {},
                                MeshFileInfo* info = nullptr);

// Triangulates one planar-ish polygon face (corners in order, either winding): projected onto
// its best-fit plane (Newell normal) and ear-clipped, so concave faces (an L, a U) come out
// right. Returns exactly corners.size() - 2 triangles of indices into `corners`, wound like the
// polygon; a degenerate (collinear, zero-area) or self-intersecting face still gets that many
// (possibly zero-area) triangles, never a crash. Convex faces are fanned.
std::vector<std::array<uint32_t, 3>> triangulatePolygon(const std::vector<Vec3f>& corners);

TriangleMesh makeSphere(int subdivisions = 4);  // icosphere, radius 0.5, centred at the origin
TriangleMesh makeCube();                        // [-0.5, 0.5]^3, flat normals

}  // namespace inlay
