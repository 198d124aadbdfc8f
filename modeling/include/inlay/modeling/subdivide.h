// Smooth subdivision of coarse meshes with OpenSubdiv (the only OpenSubdiv unit): Catmull-Clark
// when the triangles pair up into quads (a mesh that was made of quads, like builtin:cube),
// Loop otherwise. Vertices at the same position are welded first (files split them for flat
// normals or UV seams) into an OpenMesh half-edge mesh, which finds each triangle's neighbours
// and the triangles that would make it non-manifold (a third face on an edge, a second fan at
// a vertex, a flipped face); OpenSubdiv still refines those (its non-manifold rules make their
// edges sharp) and the result counts them. Open borders keep their edges and corners
// (OpenSubdiv's edge-and-corner boundary rule). UVs, when the mesh has them, are refined as
// OpenSubdiv face-varying data: smooth inside a texture island, linear along its borders and
// seams, and a seam stays a seam (its vertices come out once per side, same position and
// normal, each side's UV). The result has smooth area-weighted vertex normals and no
// per-triangle materials (the renderer uses one material per object).
#pragma once

#include "inlay/modeling/core.h"
#include "inlay/modeling/mesh.h"

namespace inlay {

constexpr int kMaxSubdivisionLevels = 5;

enum class SubdivisionScheme { CatmullClark, Loop };

struct SubdivisionResult {
  TriangleMesh mesh;
  SubdivisionScheme scheme = SubdivisionScheme::Loop;
  size_t droppedTriangles = 0;      // out of range, a non-finite corner, or collapsed by welding
  size_t nonManifoldTriangles = 0;  // kept, but refused by the half-edge mesh (see above)
};

// `levels` in [0, kMaxSubdivisionLevels]; 0 returns the welded mesh unchanged in shape.
// Errors (key "subdivide"): levels out of range, no usable triangle, UVs not one per vertex or
// not finite, a result above `maxTriangles`, or a topology OpenSubdiv refuses.
Expected<SubdivisionResult> subdivide(const TriangleMesh& mesh, int levels,
                                      size_t maxTriangles = 20'000'000);

}  // namespace inlay
