// Smooth subdivision of coarse meshes with OpenSubdiv (the only OpenSubdiv unit): Catmull-Clark
// when the triangles pair up into quads (a mesh that was made of quads, like builtin:cube),
// Loop otherwise. Vertices at the same position are welded first (files split them for flat
// normals or UV seams), open borders keep their edges and corners (OpenSubdiv's
// edge-and-corner boundary rule). The result has smooth area-weighted vertex normals and no UVs
// or per-triangle materials (the renderer uses one material per object).
#pragma once

#include "inlay/modeling/core.h"
#include "inlay/modeling/mesh.h"

namespace inlay {

constexpr int kMaxSubdivisionLevels = 5;

enum class SubdivisionScheme { CatmullClark, Loop };

struct SubdivisionResult {
  TriangleMesh mesh;
  SubdivisionScheme scheme = SubdivisionScheme::Loop;
};

// `levels` in [0, kMaxSubdivisionLevels]; 0 returns the welded mesh unchanged in shape.
// Errors: levels out of range, an empty mesh, or a result above `maxTriangles`.
Expected<SubdivisionResult> subdivide(const TriangleMesh& mesh, int levels,
                                      size_t maxTriangles = 20'000'000);

}  // namespace inlay
