// Closed procedural shapes for the model library (inlay-make-library): each builder returns one
// closed, outward-wound triangle mesh with per-vertex normals and UVs in metres (a texture
// tiles per metre). Units are metres, y up; the caller places a shape with transformed().
//
// Every shape is closed by construction (its seams weld by position), so the generator can
// check it with OpenMesh (checkClosedOutward in pieces.cpp) before it goes into a piece.
#pragma once

#include "inlay/modeling/mesh.h"

#include <Eigen/Geometry>

#include <vector>

namespace inlay::library {

using Affine = Eigen::Affine3f;

// A box of `size` (x, y, z) centred at the origin whose 12 edges are rounded with `radiusM`
// (clamped to half the smallest side) in `segments` steps per quarter circle; radius 0 gives a
// sharp box with flat normals.
TriangleMesh roundedBox(const Vec3f& size, float radiusM, int segments = 3);

// A solid of revolution about +y. `profile` is (radius, y) from the axis at the bottom, around
// the outside (and, for a hollow shape, over the lip and down the inside) back to the axis; the
// solid lies to the right of the walk (outward normal = (dy, -dr)). Profile corners sharper than
// `creaseDeg` keep hard normals. `sides` segments around.
TriangleMesh lathe(const std::vector<Eigen::Vector2f>& profile, int sides, float creaseDeg = 35.f);

// A round rod from `a` to `b`, radius `ra` at a and `rb` at b, flat ends.
TriangleMesh rod(const Vec3f& a, const Vec3f& b, float ra, float rb, int sides = 12);

// A torus about +y: ring radius `majorM`, tube radius `minorM`.
TriangleMesh torus(float majorM, float minorM, int ringSides = 32, int tubeSides = 10);

// A tube swept along `path` (at least 2 points) with an elliptical cross-section: half-width
// `halfWidth[i]` along the side vector and half-thickness `halfThick[i]` along `up[i]` (kept
// perpendicular to the path). A zero width at either end closes it to a point (a leaf's tip);
// otherwise the end is capped flat.
TriangleMesh sweep(const std::vector<Vec3f>& path, const std::vector<Vec3f>& up,
                   const std::vector<float>& halfWidth, const std::vector<float>& halfThick,
                   int sides = 10);

// The mesh moved by `t` (normals by its inverse transpose; a mirroring transform flips the
// winding so the mesh stays outward-wound).
TriangleMesh transformed(const TriangleMesh& mesh, const Affine& t);

}  // namespace inlay::library
