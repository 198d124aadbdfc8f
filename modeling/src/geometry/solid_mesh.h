// The closed solids of extrusions, boxes and stairs as OpenMesh triangle meshes (internal to
// modeling; OpenMesh stays in solid_mesh.cpp and this header, CGAL in extrude_cgal.cpp).
//
// A prism is a simple counter-clockwise 2D polygon q_i placed in 3D as originWorld +
// q.x * uWorld + q.y * vWorld and swept along sweepWorld (its length is the sweep's length).
// Table tops sweep a footprint vertically; stairs sweep their side profile horizontally across
// the stair width. The polygon's validity and its constrained triangulation come from CGAL
// (extrude_cgal.h); the solid is assembled in an OpenMesh TriMesh, where it is checked closed
// (no boundary halfedge), manifold (every vertex one fan), a sphere (V - E + F = 2) and outward
// (positive volume) before it is converted to the renderer's triangle meshes.
#pragma once

#include "inlay/modeling/core.h"
#include "inlay/modeling/geometry.h"
#include "inlay/modeling/mesh.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <memory>
#include <string>
#include <vector>

namespace inlay {

namespace detail {
struct SolidTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;  // world metres; double so thin slabs keep their thickness
  using Normal = OpenMesh::Vec3d;
};
using SolidTriMesh = OpenMesh::TriMesh_ArrayKernelT<SolidTraits>;
}  // namespace detail

// The opaque type geometry.h names: one closed, outward-oriented triangle solid.
struct SolidMesh {
  detail::SolidTriMesh mesh;
};

namespace detail {

// The renderer's meshes of a solid, split by face orientation: faces whose outward normal
// points up (n.y > 0.99: tops, stair treads) and all other faces. Flat-shaded (three vertices
// and the face normal per triangle). `solid` is the OpenMesh mesh they were converted from.
struct PrismMeshes {
  TriangleMesh upWorld;
  TriangleMesh otherWorld;
  std::shared_ptr<const SolidMesh> solid;
  double volumeM3 = 0;
};

// Errors (naming `key`): a degenerate sweep, or a solid that fails the closed-mesh checks
// (which a valid polygon never gives: then it is reported, not built).
Expected<PrismMeshes> buildPrism(const std::vector<Vec2>& polygonCcw, const Vec3& originWorld,
                                 const Vec3& uWorld, const Vec3& vWorld, const Vec3& sweepWorld,
                                 const std::string& key);

}  // namespace detail
}  // namespace inlay
