// Closed prisms assembled and checked in OpenMesh (see solid_mesh.h).
#include "solid_mesh.h"

#include "extrude_cgal.h"

#include <cmath>

namespace inlay {

namespace {

using detail::SolidTriMesh;

Vec3 toVec(const OpenMesh::Vec3d& p) { return Vec3(p[0], p[1], p[2]); }

// Signed volume by the divergence theorem: positive when the faces point outward.
double signedVolume(const SolidTriMesh& m) {
  double v = 0;
  for (const auto f : m.faces()) {
    Vec3 p[3];
    int k = 0;
    for (const auto vh : f.vertices()) p[k++] = toVec(m.point(vh));
    v += p[0].dot(p[1].cross(p[2])) / 6.0;
  }
  return v;
}

}  // namespace

SolidSummary summarizeSolid(const SolidMesh& solid) {
  const SolidTriMesh& m = solid.mesh;
  SolidSummary s;
  s.vertices = m.n_vertices();
  s.edges = m.n_edges();
  s.faces = m.n_faces();
  s.closed = s.faces > 0;
  for (const auto h : m.halfedges())
    if (h.is_boundary()) s.closed = false;  // an edge with a face on one side only
  // Consistent orientation needs no loop here: OpenMesh's add_face refuses a face that would
  // run an edge the same way as its neighbour (buildPrism reports that as a failed face).
  s.manifold = true;
  for (const auto v : m.vertices())
    if (!m.is_manifold(v) || v.is_boundary()) s.manifold = false;
  s.eulerCharacteristic = long(s.vertices) - long(s.edges) + long(s.faces);
  s.volumeM3 = signedVolume(m);
  return s;
}

namespace detail {

namespace {

// Appends the OpenMesh solid's faces to the renderer's meshes, flat-shaded.
void convertFaces(const SolidTriMesh& m, PrismMeshes& out) {
  for (const auto f : m.faces()) {
    Vec3 p[3];
    int k = 0;
    for (const auto vh : f.vertices()) p[k++] = toVec(m.point(vh));
    const Vec3 nrm = (p[1] - p[0]).cross(p[2] - p[0]);
    if (!(nrm.norm() > 0)) continue;  // a sliver from collinear outline points carries no area
    const Vec3 nUnit = nrm.normalized();
    TriangleMesh& mesh = nUnit.y() > 0.99 ? out.upWorld : out.otherWorld;
    const uint32_t base = uint32_t(mesh.positions.size());
    for (const Vec3& q : p) {
      mesh.positions.push_back(q.cast<float>());
      mesh.normals.push_back(nUnit.cast<float>());
    }
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
}

}  // namespace

Expected<PrismMeshes> buildPrism(const std::vector<Vec2>& polygonCcw, const Vec3& origin, const Vec3& u,
                                 const Vec3& v, const Vec3& sweep, const std::string& key) {
  INLAY_CHECK(polygonCcw.size() >= 3);
  if (!(sweep.norm() > 1e-6) || !sweep.allFinite())
    return Error{"", key, "the solid would have no thickness"};
  const double side = u.cross(v).normalized().dot(sweep.normalized());
  if (!(std::abs(side) > 1e-3))
    return Error{"", key, "the sweep lies in the outline's plane: the solid would be flat"};
  // The polygon's own normal (u x v) points along the sweep or against it: the far cap faces
  // the sweep, so its winding follows that sign and every face comes out outward.
  const bool alongNormal = side > 0;
  const auto tris = triangulatePolygon(polygonCcw);
  const size_t n = polygonCcw.size();
  auto solid = std::make_shared<SolidMesh>();
  SolidTriMesh& m = solid->mesh;
  std::vector<SolidTriMesh::VertexHandle> near(n), far(n);
  auto place = [&](const Vec2& q, const Vec3& offset) {
    const Vec3 p = origin + q.x() * u + q.y() * v + offset;
    return OpenMesh::Vec3d(p.x(), p.y(), p.z());
  };
  for (size_t i = 0; i < n; ++i) {
    near[i] = m.add_vertex(place(polygonCcw[i], Vec3::Zero()));
    far[i] = m.add_vertex(place(polygonCcw[i], sweep));
  }
  bool facesOk = true;
  auto face = [&](SolidTriMesh::VertexHandle a, SolidTriMesh::VertexHandle b,
                  SolidTriMesh::VertexHandle c) {
    if (!alongNormal) std::swap(b, c);
    facesOk = facesOk && m.add_face(a, b, c).is_valid();  // invalid: a complex edge or vertex
  };
  for (const auto& t : tris) {
    face(far[t[0]], far[t[1]], far[t[2]]);
    face(near[t[0]], near[t[2]], near[t[1]]);
  }
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    face(near[i], near[j], far[j]);
    face(near[i], far[j], far[i]);
  }
  const SolidSummary check = summarizeSolid(*solid);
  if (!facesOk || !check.closed || !check.manifold || check.eulerCharacteristic != 2 ||
      !(check.volumeM3 > 0))
    return Error{"", key, "the solid is not a closed mesh bounding a volume"};
  PrismMeshes out;
  out.volumeM3 = check.volumeM3;
  convertFaces(m, out);
  out.solid = std::move(solid);
  return out;
}

}  // namespace detail
}  // namespace inlay
