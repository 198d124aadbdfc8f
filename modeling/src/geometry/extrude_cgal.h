// Polygon validity and constrained triangulation, computed with CGAL (internal to modeling;
// CGAL itself stays in extrude_cgal.cpp so only that one heavy translation unit includes it).
// The solids built from these polygons are OpenMesh meshes (solid_mesh.h).
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

// Whether `p` lies inside a simple polygon or on its outline (CGAL's exact predicate).
bool insideOrOnPolygon(const std::vector<Vec2>& polygon, const Vec2& p);

}  // namespace inlay::detail
