// Polygon validity and closed prisms, computed with CGAL (internal to modeling; CGAL itself
// stays in extrude_cgal.cpp so only that one heavy translation unit includes it).
//
// A prism here is a simple 2D polygon q_i placed in 3D as originWorld + q.x * uWorld +
// q.y * vWorld and swept along sweepWorld (its length is the sweep's length). Table tops sweep
// a footprint vertically; stairs sweep their side profile horizontally across the stair width.
#pragma once

#include "inlay/modeling/core.h"
#include "inlay/modeling/mesh.h"

#include <string>
#include <vector>

namespace inlay::detail {

// Checks a closed outline (either orientation): at least 3 distinct points, not all on one line,
// simple (no edge crosses or touches another). Consecutive duplicates are dropped. Returns the
// points counter-clockwise in their own 2D frame (x right, y up: a pixel outline, whose y points
// down, comes back clockwise on screen). Errors name `key` and, for a crossing, the two edges.
Expected<std::vector<Vec2>> counterClockwiseSimplePolygon(const std::vector<Vec2>& points,
                                                          const std::string& key);

// Constrained Delaunay triangulation of a simple counter-clockwise polygon: index triples into
// `polygon`, each counter-clockwise, covering exactly its inside.
std::vector<std::array<uint32_t, 3>> triangulatePolygon(const std::vector<Vec2>& polygon);

// The closed solid of a prism, split by face orientation: faces whose outward normal points up
// (|n.y| > 0.99, n.y > 0: tops, stair treads) and all other faces. Flat-shaded (three vertices
// and the face normal per triangle), outward normals.
struct PrismMeshes {
  TriangleMesh upWorld;
  TriangleMesh otherWorld;
  double volumeM3 = 0;
};
// Errors (naming `key`): a degenerate sweep, or a result that CGAL does not find closed and
// bounding a volume (which a valid polygon never gives: then it is reported, not built).
Expected<PrismMeshes> buildPrism(const std::vector<Vec2>& polygonCcw, const Vec3& originWorld,
                                 const Vec3& uWorld, const Vec3& vWorld, const Vec3& sweepWorld,
                                 const std::string& key);

}  // namespace inlay::detail
