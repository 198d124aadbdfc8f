// The pieces of Inlay's model library, built procedurally from closed shapes (shapes.h): real
// sizes in metres (y up, standing on y = 0, centred on the y axis, front toward +z, as glTF
// expects), PBR metallic-roughness materials, one material index per triangle.
#pragma once

#include "inlay/modeling/mesh.h"

#include <string>
#include <vector>

namespace inlay::library {

struct Piece {
  std::string name;          // file stem and library id: "armchair"
  std::string title;         // shown to users (the studio translates it): "Armchair"
  std::string category;      // seating | tables | lighting | decor | storage | textiles
  std::string materialNote;  // the default material, in words
  Vec3f nominalSizeM;        // the intended width x depth x height (x, z, y extents), metres
  float thumbnailYawDeg = 30;
  TriangleMesh mesh;  // materials, triangleMaterial, normals and UVs filled
};

// Every piece, in the library's order. Throws std::runtime_error naming the piece and part when
// a part is not closed and outward-wound (OpenMesh check) or the built size misses the nominal
// size by more than a centimetre.
std::vector<Piece> buildLibrary();

// "" when `part` is one or more closed, consistently and outward-wound surfaces (welded by
// position, checked with OpenMesh); otherwise why not.
std::string closedOutwardProblem(const TriangleMesh& part);

}  // namespace inlay::library
