// OpenSubdiv uniform refinement (see subdivide.h). The only translation unit that includes
// OpenSubdiv: the Far topology refiner from a TopologyDescriptor, PrimvarRefiner for the
// positions level by level.
#include "inlay/modeling/subdivide.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <unordered_map>

namespace inlay {

namespace {

using namespace OpenSubdiv;

// What PrimvarRefiner interpolates: a position.
struct Point {
  Vec3 p = Vec3::Zero();
  void Clear(void* = nullptr) { p.setZero(); }
  void AddWithWeight(const Point& src, float weight) { p += double(weight) * src.p; }
};

struct Welded {
  std::vector<Vec3> positions;
  std::vector<std::array<int, 3>> triangles;
};

// Merges vertices at bit-identical positions and drops triangles that are out of range or
// collapse after welding.
Welded weld(const TriangleMesh& mesh) {
  Welded w;
  std::map<std::array<float, 3>, int> index;
  std::vector<int> remap(mesh.positions.size(), -1);
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const Vec3f& p = mesh.positions[i];
    if (!p.allFinite()) continue;
    const auto [it, added] =
        index.emplace(std::array<float, 3>{p.x(), p.y(), p.z()}, int(w.positions.size()));
    if (added) w.positions.push_back(p.cast<double>());
    remap[i] = it->second;
  }
  for (const auto& t : mesh.triangles) {
    if (std::max({t[0], t[1], t[2]}) >= mesh.positions.size()) continue;
    const std::array<int, 3> r = {remap[t[0]], remap[t[1]], remap[t[2]]};
    if (r[0] < 0 || r[1] < 0 || r[2] < 0 || r[0] == r[1] || r[1] == r[2] || r[0] == r[2]) continue;
    w.triangles.push_back(r);
  }
  return w;
}

// The triangles as quads when every triangle pairs with the coplanar neighbour across its
// longest edge (that edge being the neighbour's longest too: a quad's diagonal); empty otherwise.
std::vector<std::array<int, 4>> pairIntoQuads(const Welded& w) {
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
  std::map<std::pair<int, int>, size_t> directed;  // edge (a, b) -> triangle holding a -> b
  for (size_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) directed[{w.triangles[t][k], w.triangles[t][(k + 1) % 3]}] = t;
  std::vector<std::array<int, 4>> quads;
  std::vector<bool> used(n, false);
  for (size_t t = 0; t < n; ++t) {
    if (used[t]) continue;
    const int k = longestEdge(t);
    const int a = w.triangles[t][k], b = w.triangles[t][(k + 1) % 3], c = w.triangles[t][(k + 2) % 3];
    const auto it = directed.find({b, a});
    if (it == directed.end() || used[it->second] || it->second == t) return {};
    const size_t u = it->second;
    const int ku = longestEdge(u);
    if (w.triangles[u][ku] != b || w.triangles[u][(ku + 1) % 3] != a) return {};
    if (!(normal(t).dot(normal(u)) > 0.999)) return {};
    const int o = w.triangles[u][(ku + 2) % 3];
    used[t] = used[u] = true;
    quads.push_back({a, o, b, c});
  }
  return quads;
}

}  // namespace

Expected<SubdivisionResult> subdivide(const TriangleMesh& mesh, int levels, size_t maxTriangles) {
  if (levels < 0 || levels > kMaxSubdivisionLevels)
    return Error{"", "subdivide",
                 "must be an integer in [0, " + std::to_string(kMaxSubdivisionLevels) + "]"};
  const Welded w = weld(mesh);
  if (w.triangles.empty()) return Error{"", "subdivide", "the mesh has no usable triangle"};
  const std::vector<std::array<int, 4>> quads = pairIntoQuads(w);
  SubdivisionResult result;
  result.scheme = quads.empty() ? SubdivisionScheme::Loop : SubdivisionScheme::CatmullClark;
  const size_t baseTriangles = quads.empty() ? w.triangles.size() : 2 * quads.size();
  if (double(baseTriangles) * std::pow(4.0, levels) > double(maxTriangles))
    return Error{"", "subdivide",
                 std::to_string(levels) + " levels would make more than " +
                     std::to_string(maxTriangles) + " triangles"};

  std::vector<int> counts, indices;
  if (quads.empty()) {
    counts.assign(w.triangles.size(), 3);
    for (const auto& t : w.triangles) indices.insert(indices.end(), t.begin(), t.end());
  } else {
    counts.assign(quads.size(), 4);
    for (const auto& q : quads) indices.insert(indices.end(), q.begin(), q.end());
  }
  Far::TopologyDescriptor desc;
  desc.numVertices = int(w.positions.size());
  desc.numFaces = int(counts.size());
  desc.numVertsPerFace = counts.data();
  desc.vertIndicesPerFace = indices.data();
  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(
      desc, Factory::Options(quads.empty() ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, sdc)));
  if (!refiner) return Error{"", "subdivide", "OpenSubdiv rejected the mesh's topology (non-manifold?)"};
  refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(levels));

  std::vector<Point> points(size_t(refiner->GetNumVerticesTotal()));
  for (size_t i = 0; i < w.positions.size(); ++i) points[i].p = w.positions[i];
  Far::PrimvarRefiner primvar(*refiner);
  Point* src = points.data();
  for (int level = 1; level <= levels; ++level) {
    Point* dst = src + refiner->GetLevel(level - 1).GetNumVertices();
    primvar.Interpolate(level, src, dst);
    src = dst;
  }
  const Far::TopologyLevel& last = refiner->GetLevel(levels);
  TriangleMesh& out = result.mesh;
  out.positions.reserve(size_t(last.GetNumVertices()));
  for (int i = 0; i < last.GetNumVertices(); ++i) out.positions.push_back(src[i].p.cast<float>());
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    const Far::ConstIndexArray v = last.GetFaceVertices(f);
    for (int k = 1; k + 1 < v.size(); ++k)
      out.triangles.push_back({uint32_t(v[0]), uint32_t(v[k]), uint32_t(v[k + 1])});
  }
  out.computeVertexNormals();
  return result;
}

}  // namespace inlay
