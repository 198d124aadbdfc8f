// OpenSubdiv uniform refinement (see subdivide.h). The only translation unit that includes
// OpenSubdiv. Steps: weld the triangles' corners into an OpenMesh half-edge mesh (which also
// finds the non-manifold triangles), pair triangles into quads across OpenMesh's opposite
// half-edges, hand the faces to a Far topology refiner with the UVs as a face-varying channel,
// refine positions (PrimvarRefiner::Interpolate) and UVs (InterpolateFaceVarying) level by level,
// and split the last level's vertices where their UVs differ (the seams).
#include "inlay/modeling/subdivide.h"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>
#include <unordered_map>

namespace inlay {

namespace {

using namespace OpenSubdiv;
using HalfEdgeMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

// What PrimvarRefiner interpolates: a position, or a UV.
struct Point {
  Vec3 p = Vec3::Zero();
  void Clear(void* = nullptr) { p.setZero(); }
  void AddWithWeight(const Point& src, float weight) { p += double(weight) * src.p; }
};
struct Uv {
  Vec2 uv = Vec2::Zero();
  void Clear(void* = nullptr) { uv.setZero(); }
  void AddWithWeight(const Uv& src, float weight) { uv += double(weight) * src.uv; }
};

// Bit patterns of a float vector, -0 folded into +0 (they weld, as they compare equal).
template <int N>
struct Bits {
  std::array<uint32_t, N> v{};
  explicit Bits(const Eigen::Matrix<float, N, 1>& x) {
    for (int i = 0; i < N; ++i) {
      const float f = x[i] + 0.0f;
      std::memcpy(&v[size_t(i)], &f, sizeof f);
    }
  }
  bool operator==(const Bits& o) const { return v == o.v; }
};
struct BitsHash {
  template <int N>
  size_t operator()(const Bits<N>& b) const {
    size_t h = 0;
    for (uint32_t x : b.v) h = (h ^ x) * 0x100000001b3ULL;
    return h;
  }
};

// The welded input: vertices at bit-identical positions merged; OpenMesh's half-edge mesh over
// them holding every triangle it can keep 2-manifold (face i = triangle i while none was
// refused); per triangle corner its UV value, a UV being one (welded vertex, uv) pair.
struct Welded {
  std::vector<Vec3> positions;
  std::vector<std::array<int, 3>> triangles;
  HalfEdgeMesh halfEdges;
  size_t nonManifold = 0;       // triangles the half-edge mesh refused (a third face on an edge, ...)
  size_t dropped = 0;           // out of range, a non-finite corner, or collapsed by the weld
  std::vector<Vec2f> uvValues;  // empty without UVs
  std::vector<std::array<int, 3>> triangleUv;  // per triangle corner, into uvValues
};

// Whether OpenMesh's add_face would take the triangle: each corner on a boundary (or free),
// each edge new or a boundary half-edge, and where two of its edges exist already, a boundary
// gap to re-link them into. The same tests as OpenMesh's own, made first so a refused face is
// counted, not printed on OpenMesh's error stream.
bool keepsManifold(const HalfEdgeMesh& m, const std::array<HalfEdgeMesh::VertexHandle, 3>& v) {
  std::array<HalfEdgeMesh::HalfedgeHandle, 3> he;
  for (size_t i = 0; i < 3; ++i) {
    if (!m.is_boundary(v[i])) return false;
    he[i] = m.find_halfedge(v[i], v[(i + 1) % 3]);
    if (he[i].is_valid() && !m.is_boundary(he[i])) return false;
  }
  for (size_t i = 0; i < 3; ++i) {
    const auto innerPrev = he[i], innerNext = he[(i + 1) % 3];
    if (!innerPrev.is_valid() || !innerNext.is_valid() || m.next_halfedge_handle(innerPrev) == innerNext)
      continue;
    auto boundaryPrev = m.opposite_halfedge_handle(innerNext);
    do boundaryPrev = m.opposite_halfedge_handle(m.next_halfedge_handle(boundaryPrev));
    while (!m.is_boundary(boundaryPrev));
    if (boundaryPrev == innerPrev) return false;
  }
  return true;
}

std::vector<int> weldPositions(const TriangleMesh& mesh, Welded& w) {
  std::unordered_map<Bits<3>, int, BitsHash> index(mesh.positions.size());
  std::vector<int> remap(mesh.positions.size(), -1);
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const Vec3f& p = mesh.positions[i];
    if (!p.allFinite()) continue;
    const auto [it, added] = index.emplace(Bits<3>(p), int(w.positions.size()));
    if (added) w.positions.push_back(p.cast<double>());
    remap[i] = it->second;
  }
  return remap;
}

// One UV value per (welded vertex, uv) pair, so a seam (one position, two UVs) keeps both.
void weldUvs(const TriangleMesh& mesh, const std::vector<std::array<uint32_t, 3>>& kept,
             const std::vector<int>& remap, Welded& w) {
  struct Key {
    int vertex;
    Bits<2> uv;
    bool operator==(const Key& o) const { return vertex == o.vertex && uv == o.uv; }
  };
  struct KeyHash {
    size_t operator()(const Key& k) const { return BitsHash{}(k.uv) * 31 + size_t(k.vertex); }
  };
  std::unordered_map<Key, int, KeyHash> index(mesh.positions.size());
  for (const auto& t : kept) {
    std::array<int, 3> corners{};
    for (size_t k = 0; k < 3; ++k) {
      const Vec2f& uv = mesh.uvs[t[k]];
      const auto [it, added] = index.emplace(Key{remap[t[k]], Bits<2>(uv)}, int(w.uvValues.size()));
      if (added) w.uvValues.push_back(uv);
      corners[k] = it->second;
    }
    w.triangleUv.push_back(corners);
  }
}

Expected<Welded> weld(const TriangleMesh& mesh) {
  const bool withUvs = !mesh.uvs.empty();
  if (withUvs && mesh.uvs.size() != mesh.positions.size())
    return Error{"", "subdivide",
                 "the mesh has " + std::to_string(mesh.uvs.size()) + " UVs for " +
                     std::to_string(mesh.positions.size()) +
                     " vertices (one per vertex or none); re-export it with one UV per vertex"};
  Welded w;
  const std::vector<int> remap = weldPositions(mesh, w);
  std::vector<std::array<uint32_t, 3>> kept;
  for (const auto& t : mesh.triangles) {
    if (std::max({t[0], t[1], t[2]}) >= mesh.positions.size()) {
      ++w.dropped;
      continue;
    }
    const std::array<int, 3> r = {remap[t[0]], remap[t[1]], remap[t[2]]};
    if (r[0] < 0 || r[1] < 0 || r[2] < 0 || r[0] == r[1] || r[1] == r[2] || r[0] == r[2]) {
      ++w.dropped;
      continue;
    }
    for (size_t k = 0; withUvs && k < 3; ++k)
      if (!mesh.uvs[t[k]].allFinite())
        return Error{"", "subdivide",
                     "the UV of vertex " + std::to_string(t[k]) +
                         " is not a finite number; fix or drop the mesh's texture coordinates"};
    kept.push_back(t);
    w.triangles.push_back(r);
  }
  if (withUvs) weldUvs(mesh, kept, remap, w);
  for (const Vec3& p : w.positions)
    w.halfEdges.add_vertex(HalfEdgeMesh::Point(float(p.x()), float(p.y()), float(p.z())));
  for (const auto& t : w.triangles) {
    const std::array<HalfEdgeMesh::VertexHandle, 3> v = {w.halfEdges.vertex_handle(unsigned(t[0])),
                                                         w.halfEdges.vertex_handle(unsigned(t[1])),
                                                         w.halfEdges.vertex_handle(unsigned(t[2]))};
    if (!keepsManifold(w.halfEdges, v) || !w.halfEdges.add_face(v[0], v[1], v[2]).is_valid())
      ++w.nonManifold;
  }
  return w;
}

// OpenSubdiv's faces: the vertices of each face in order, and the UV value of each corner
// (empty without UVs).
struct Faces {
  int size = 3;  // corners per face
  std::vector<int> vertices, uvs;
};

Faces trianglesOf(const Welded& w) {
  Faces f;
  for (const auto& t : w.triangles) f.vertices.insert(f.vertices.end(), t.begin(), t.end());
  for (const auto& t : w.triangleUv) f.uvs.insert(f.uvs.end(), t.begin(), t.end());
  return f;
}

// The triangles as quads when every triangle pairs with the coplanar neighbour across its
// longest edge (that edge being the neighbour's longest too: a quad's diagonal) and the two
// agree on the diagonal's UVs; nullopt otherwise. The neighbour comes from the half-edge mesh;
// a mesh with a non-manifold triangle does not pair.
std::optional<Faces> pairIntoQuads(const Welded& w) {
  if (w.nonManifold > 0) return std::nullopt;
  const size_t n = w.triangles.size();
  auto longestEdge = [&](size_t t) {
    int best = 0;
    double bestLen = -1;
    for (int k = 0; k < 3; ++k) {
      const double len =
          (w.positions[size_t(w.triangles[t][(k + 1) % 3])] - w.positions[size_t(w.triangles[t][k])])
              .squaredNorm();
      if (len > bestLen) bestLen = len, best = k;
    }
    return best;  // the edge from vertex k to vertex k + 1
  };
  auto normal = [&](size_t t) {
    const auto& v = w.triangles[t];
    return Vec3((w.positions[size_t(v[1])] - w.positions[size_t(v[0])])
                    .cross(w.positions[size_t(v[2])] - w.positions[size_t(v[0])])
                    .normalized());
  };
  const bool withUvs = !w.triangleUv.empty();
  auto uv = [&](size_t t, int k) { return withUvs ? w.triangleUv[t][size_t(k % 3)] : -1; };
  const HalfEdgeMesh& m = w.halfEdges;
  Faces quads;
  quads.size = 4;
  std::vector<bool> used(n, false);
  for (size_t t = 0; t < n; ++t) {
    if (used[t]) continue;
    const int k = longestEdge(t);
    const auto& tv = w.triangles[t];
    const int a = tv[size_t(k)], b = tv[size_t(k + 1) % 3], c = tv[size_t(k + 2) % 3];
    const auto across = m.opposite_halfedge_handle(
        m.find_halfedge(m.vertex_handle(unsigned(a)), m.vertex_handle(unsigned(b))));
    if (m.is_boundary(across)) return std::nullopt;
    const size_t u = size_t(m.face_handle(across).idx());
    if (used[u] || u == t) return std::nullopt;
    const int ku = longestEdge(u);
    const auto& uvx = w.triangles[u];
    if (uvx[size_t(ku)] != b || uvx[size_t(ku + 1) % 3] != a) return std::nullopt;
    if (!(normal(t).dot(normal(u)) > 0.999)) return std::nullopt;
    if (uv(t, k) != uv(u, ku + 1) || uv(t, k + 1) != uv(u, ku)) return std::nullopt;  // a seam
    used[t] = used[u] = true;
    quads.vertices.insert(quads.vertices.end(), {a, uvx[size_t(ku + 2) % 3], b, c});
    if (withUvs)
      quads.uvs.insert(quads.uvs.end(), {uv(t, k), uv(u, ku + 2), uv(t, k + 1), uv(t, k + 2)});
  }
  return quads;
}

// Far's refiner over the faces, refined `levels` times: positions keep their open borders'
// edges and corners; UVs interpolate linearly along their borders and seams (so a texture's
// islands keep their straight outlines) and smoothly inside.
std::unique_ptr<Far::TopologyRefiner> refine(const Welded& w, const Faces& faces, int levels) {
  const std::vector<int> counts(faces.vertices.size() / size_t(faces.size), faces.size);
  Far::TopologyDescriptor desc;
  desc.numVertices = int(w.positions.size());
  desc.numFaces = int(counts.size());
  desc.numVertsPerFace = counts.data();
  desc.vertIndicesPerFace = faces.vertices.data();
  Far::TopologyDescriptor::FVarChannel uvChannel;
  if (!faces.uvs.empty()) {
    uvChannel.numValues = int(w.uvValues.size());
    uvChannel.valueIndices = faces.uvs.data();
    desc.numFVarChannels = 1;
    desc.fvarChannels = &uvChannel;
  }
  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  sdc.SetFVarLinearInterpolation(Sdc::Options::FVAR_LINEAR_BOUNDARIES);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(
      desc, Factory::Options(faces.size == 4 ? Sdc::SCHEME_CATMARK : Sdc::SCHEME_LOOP, sdc)));
  if (!refiner) return nullptr;
  refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(levels));
  return refiner;
}

// The last level's positions, refined level by level from the welded ones.
std::vector<Point> refinedPositions(const Far::TopologyRefiner& refiner, const Welded& w, int levels) {
  std::vector<Point> points(size_t(refiner.GetNumVerticesTotal()));
  for (size_t i = 0; i < w.positions.size(); ++i) points[i].p = w.positions[i];
  const Far::PrimvarRefiner primvar(refiner);
  Point* src = points.data();
  for (int level = 1; level <= levels; ++level) {
    Point* dst = src + refiner.GetLevel(level - 1).GetNumVertices();
    primvar.Interpolate(level, src, dst);
    src = dst;
  }
  return {src, src + refiner.GetLevel(levels).GetNumVertices()};
}

// The last level's UV values (face-varying channel 0), refined level by level.
std::vector<Uv> refinedUvs(const Far::TopologyRefiner& refiner, const Welded& w, int levels) {
  std::vector<Uv> values(size_t(refiner.GetNumFVarValuesTotal(0)));
  for (size_t i = 0; i < w.uvValues.size(); ++i) values[i].uv = w.uvValues[i].cast<double>();
  const Far::PrimvarRefiner primvar(refiner);
  Uv* src = values.data();
  for (int level = 1; level <= levels; ++level) {
    Uv* dst = src + refiner.GetLevel(level - 1).GetNumFVarValues(0);
    primvar.InterpolateFaceVarying(level, src, dst, 0);
    src = dst;
  }
  return {src, src + refiner.GetLevel(levels).GetNumFVarValues(0)};
}

// The last level as triangles (quads split along their first diagonal) with smooth normals
// over the positions; with UVs, one output vertex per UV value, so a vertex on a seam appears
// once per side with its side's UV and the same position and normal.
TriangleMesh lastLevelMesh(const Far::TopologyRefiner& refiner, const Welded& w, int levels) {
  const Far::TopologyLevel& last = refiner.GetLevel(levels);
  const std::vector<Point> points = refinedPositions(refiner, w, levels);
  TriangleMesh shape;
  for (const Point& p : points) shape.positions.push_back(p.p.cast<float>());
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    const Far::ConstIndexArray v = last.GetFaceVertices(f);
    for (int k = 1; k + 1 < v.size(); ++k)
      shape.triangles.push_back({uint32_t(v[0]), uint32_t(v[k]), uint32_t(v[k + 1])});
  }
  shape.computeVertexNormals();
  if (w.uvValues.empty()) return shape;

  const std::vector<Uv> uvs = refinedUvs(refiner, w, levels);
  TriangleMesh out;
  out.positions.resize(uvs.size());
  out.normals.resize(uvs.size());
  out.uvs.resize(uvs.size());
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    const Far::ConstIndexArray v = last.GetFaceVertices(f);
    const Far::ConstIndexArray fv = last.GetFaceFVarValues(f, 0);
    for (int k = 0; k < v.size(); ++k) {
      const size_t value = size_t(fv[k]), vertex = size_t(v[k]);
      out.positions[value] = shape.positions[vertex];
      out.normals[value] = shape.normals[vertex];
      out.uvs[value] = uvs[value].uv.cast<float>();
    }
    for (int k = 1; k + 1 < fv.size(); ++k)
      out.triangles.push_back({uint32_t(fv[0]), uint32_t(fv[k]), uint32_t(fv[k + 1])});
  }
  return out;
}

}  // namespace

Expected<SubdivisionResult> subdivide(const TriangleMesh& mesh, int levels, size_t maxTriangles) {
  if (levels < 0 || levels > kMaxSubdivisionLevels)
    return Error{"", "subdivide",
                 "must be an integer in [0, " + std::to_string(kMaxSubdivisionLevels) + "]"};
  auto welded = weld(mesh);
  if (!welded) return welded.error();
  const Welded& w = *welded;
  if (w.triangles.empty())
    return Error{"", "subdivide",
                 "the mesh has no usable triangle (" + std::to_string(mesh.triangles.size()) +
                     " given: each has an index out of range, a non-finite corner or two corners "
                     "at one position)"};
  const std::optional<Faces> quads = pairIntoQuads(w);
  const Faces faces = quads ? *quads : trianglesOf(w);
  SubdivisionResult result;
  result.scheme = quads ? SubdivisionScheme::CatmullClark : SubdivisionScheme::Loop;
  result.droppedTriangles = w.dropped;
  result.nonManifoldTriangles = w.nonManifold;
  const size_t baseTriangles = faces.vertices.size() / size_t(faces.size) * size_t(faces.size - 2);
  if (double(baseTriangles) * std::pow(4.0, levels) > double(maxTriangles))
    return Error{"", "subdivide",
                 std::to_string(levels) + " levels would make more than " +
                     std::to_string(maxTriangles) + " triangles"};
  const auto refiner = refine(w, faces, levels);
  if (!refiner)
    return Error{"", "subdivide",
                 "OpenSubdiv rejected the mesh's topology (" + std::to_string(w.nonManifold) +
                     " non-manifold triangles); repair the mesh (e.g. merge its faces in Blender) "
                     "or set subdivide to 0"};
  result.mesh = lastLevelMesh(*refiner, w, levels);
  return result;
}

}  // namespace inlay
