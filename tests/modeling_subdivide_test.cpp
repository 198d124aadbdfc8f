// OpenSubdiv subdivision: a cube becomes a smooth closed blob by Catmull-Clark (vertex counts of
// uniform refinement, watertight, volume converging between the inscribed sphere's and the
// cube's, rounder at every level); triangle meshes go through Loop; open borders stay put;
// UVs come through (seams kept, interiors interpolated); a non-manifold fin is refined and
// counted; bad requests and bad meshes are errors naming the reason.
#include "inlay/modeling/subdivide.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>

namespace inlay {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Every undirected edge used exactly twice, in opposite directions.
bool watertight(const TriangleMesh& m) {
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  for (const auto& [e, n] : directed)
    if (n != 1 || directed.count({e.second, e.first}) == 0) return false;
  return true;
}

// The mesh with vertices at identical positions merged (subdivide splits them at UV seams).
TriangleMesh weldedByPosition(const TriangleMesh& m) {
  std::map<std::array<float, 3>, uint32_t> index;
  std::vector<uint32_t> remap(m.positions.size());
  TriangleMesh w;
  for (size_t i = 0; i < m.positions.size(); ++i) {
    const auto& p = m.positions[i];
    const auto [it, added] =
        index.emplace(std::array<float, 3>{p.x(), p.y(), p.z()}, uint32_t(w.positions.size()));
    if (added) w.positions.push_back(p);
    remap[i] = it->second;
  }
  for (const auto& t : m.triangles) w.triangles.push_back({remap[t[0]], remap[t[1]], remap[t[2]]});
  return w;
}

double volume(const TriangleMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles)
    v += m.positions[t[0]].cast<double>().dot(
             m.positions[t[1]].cast<double>().cross(m.positions[t[2]].cast<double>())) /
         6;
  return v;
}

double area(const TriangleMesh& m) {
  double a = 0;
  for (const auto& t : m.triangles)
    a += 0.5 * (m.positions[t[1]] - m.positions[t[0]])
                   .cast<double>()
                   .cross((m.positions[t[2]] - m.positions[t[0]]).cast<double>())
                   .norm();
  return a;
}

// Isoperimetric quotient 36 pi V^2 / A^3: 1 for a sphere, 0.52 for a cube, 0.30 for a regular
// tetrahedron; rises as a shape rounds off.
double roundness(const TriangleMesh& m) {
  return 36 * kPi * std::pow(volume(m), 2) / std::pow(area(m), 3);
}

TEST(Subdivide, CubeConvergesToASmoothClosedShape) {
  const TriangleMesh cube = makeCube();  // 24 split vertices, 12 triangles, flat normals
  double previousVolume = volume(cube), previousRoundness = roundness(cube), previousStep = 1e300;
  EXPECT_NEAR(previousVolume, 1.0, 1e-6);
  for (int levels = 1; levels <= 4; ++levels) {
    const auto r = subdivide(cube, levels);
    ASSERT_TRUE(r.ok()) << r.error().message();
    const TriangleMesh m = weldedByPosition(r->mesh);  // makeCube's UV seams split vertices
    EXPECT_EQ(r->scheme, SubdivisionScheme::CatmullClark);
    const size_t quads = 6u << (2 * levels);
    EXPECT_EQ(m.positions.size(), quads + 2);  // Euler: V = F + 2 for a closed quad mesh of genus 0
    EXPECT_EQ(m.triangles.size(), 2 * quads);
    EXPECT_TRUE(watertight(m));
    EXPECT_EQ(r->mesh.normals.size(), r->mesh.positions.size());
    EXPECT_EQ(r->mesh.uvs.size(), r->mesh.positions.size());
    const double v = volume(m), q = roundness(m), step = previousVolume - v;
    std::printf("[ subdivide ] cube, %d levels: %zu vertices, volume %.5f (step %.5f), roundness %.4f\n",
                levels, m.positions.size(), v, step, q);
    EXPECT_GT(step, 0.0);  // Catmull-Clark shrinks a convex cage
    EXPECT_GT(q, previousRoundness);
    if (levels >= 2) {
      EXPECT_LT(step, 0.35 * previousStep);
    }  // geometric convergence (~1/4 per level)
    previousStep = step, previousVolume = v, previousRoundness = q;
  }
  // The limit surface of the unit cube: about 0.3276 (levels 3-4 extrapolated), well inside the
  // inscribed sphere (0.524): Catmull-Clark pulls a convex cage in. Roundness near a sphere's.
  EXPECT_GT(previousVolume, 0.32);
  EXPECT_LT(previousVolume, 0.335);
  EXPECT_GT(previousRoundness, 0.95);
}

TEST(Subdivide, TrianglesGoThroughLoop) {
  TriangleMesh tet;
  tet.positions = {Vec3f(1, 1, 1), Vec3f(1, -1, -1), Vec3f(-1, 1, -1), Vec3f(-1, -1, 1)};
  tet.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  ASSERT_GT(volume(tet), 0);
  const auto r = subdivide(tet, 3);
  ASSERT_TRUE(r.ok()) << r.error().message();
  EXPECT_EQ(r->scheme, SubdivisionScheme::Loop);
  EXPECT_EQ(r->mesh.triangles.size(), 4u * 64u);
  EXPECT_EQ(r->mesh.positions.size(), 4u * 64u / 2 + 2);
  EXPECT_TRUE(watertight(r->mesh));
  EXPECT_GT(volume(r->mesh), 0);
  EXPECT_LT(volume(r->mesh), volume(tet));
  EXPECT_GT(roundness(r->mesh), roundness(tet) + 0.3);
}

TEST(Subdivide, OpenBorderKeepsItsCorners) {
  TriangleMesh quad;
  quad.positions = {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(1, 1, 0), Vec3f(0, 1, 0)};
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  const auto r = subdivide(quad, 2);
  ASSERT_TRUE(r.ok()) << r.error().message();
  EXPECT_EQ(r->scheme, SubdivisionScheme::CatmullClark);
  EXPECT_EQ(r->mesh.triangles.size(), 32u);
  const auto box = r->mesh.bounds();
  EXPECT_NEAR(box.min().x(), 0, 1e-6);
  EXPECT_NEAR(box.max().y(), 1, 1e-6);
  for (const auto& p : r->mesh.positions) EXPECT_EQ(p.z(), 0.f);
}

TEST(Subdivide, BadRequestsAreErrors) {
  EXPECT_FALSE(subdivide(makeCube(), -1).ok());
  EXPECT_FALSE(subdivide(makeCube(), kMaxSubdivisionLevels + 1).ok());
  EXPECT_FALSE(subdivide(TriangleMesh{}, 1).ok());
  const auto tooMany = subdivide(makeCube(), 5, 1000);
  ASSERT_FALSE(tooMany.ok());
  EXPECT_NE(tooMany.error().message().find("subdivide"), std::string::npos);
  TriangleMesh nan = makeCube();
  nan.positions[0].x() = std::numeric_limits<float>::quiet_NaN();
  nan.triangles.push_back({0, 1, 99});
  const auto r = subdivide(nan, 1);  // the NaN vertex's and the out-of-range triangles are dropped
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->droppedTriangles, 2u + 1u);  // vertex 0 is on its face's two triangles
  for (const auto& p : r->mesh.positions) EXPECT_TRUE(p.allFinite());
}

TEST(Subdivide, BadMeshesSayWhy) {
  TriangleMesh fewUvs = makeCube();
  fewUvs.uvs.pop_back();
  const auto a = subdivide(fewUvs, 1);
  ASSERT_FALSE(a.ok());
  EXPECT_NE(a.error().message().find("23 UVs for 24 vertices"), std::string::npos)
      << a.error().message();
  TriangleMesh nanUv = makeCube();
  nanUv.uvs[5].y() = std::numeric_limits<float>::infinity();
  const auto b = subdivide(nanUv, 1);
  ASSERT_FALSE(b.ok());
  EXPECT_NE(b.error().message().find("UV of vertex 5 is not a finite"), std::string::npos)
      << b.error().message();
  TriangleMesh flat;  // every triangle has two corners at one position
  flat.positions = {Vec3f(0, 0, 0), Vec3f(0, 0, 0), Vec3f(1, 0, 0)};
  flat.triangles = {{0, 1, 2}};
  const auto c = subdivide(flat, 1);
  ASSERT_FALSE(c.ok());
  EXPECT_NE(c.error().message().find("no usable triangle"), std::string::npos) << c.error().message();
}

// A unit quad textured with uv = (x, y): the corners keep their UVs, the borders stay linear,
// and the interior UVs, interpolated by OpenSubdiv's face-varying rules, match the positions
// (both are refined with the same Catmull-Clark weights on a flat, regular quad).
TEST(Subdivide, TexturedQuadCarriesItsUvs) {
  TriangleMesh quad;
  quad.positions = {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(1, 1, 0), Vec3f(0, 1, 0)};
  quad.uvs = {Vec2f(0, 0), Vec2f(1, 0), Vec2f(1, 1), Vec2f(0, 1)};
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  const auto r = subdivide(quad, 3);
  ASSERT_TRUE(r.ok()) << r->mesh.positions.size();
  EXPECT_EQ(r->scheme, SubdivisionScheme::CatmullClark);
  ASSERT_EQ(r->mesh.uvs.size(), r->mesh.positions.size());
  EXPECT_EQ(r->mesh.positions.size(), 81u);  // 9 x 9, no seam to split
  int interior = 0;
  for (size_t i = 0; i < r->mesh.positions.size(); ++i) {
    const Vec3f& p = r->mesh.positions[i];
    const Vec2f& uv = r->mesh.uvs[i];
    EXPECT_NEAR(uv.x(), p.x(), 1e-5);
    EXPECT_NEAR(uv.y(), p.y(), 1e-5);
    interior += p.x() > 0.01f && p.x() < 0.99f && p.y() > 0.01f && p.y() < 0.99f;
  }
  EXPECT_EQ(interior, 49);
}

// Vertices that repeat another's position and UV (a UV seam is only where the UVs differ, so
// these weld into one UV value).
size_t repeatedUvVertices(const TriangleMesh& m) {
  std::set<std::array<float, 5>> distinct;
  for (size_t i = 0; i < m.positions.size(); ++i)
    distinct.insert(
        {m.positions[i].x(), m.positions[i].y(), m.positions[i].z(), m.uvs[i].x(), m.uvs[i].y()});
  return m.positions.size() - distinct.size();
}

// Per position, the number of distinct UVs there, as a sorted list (the seams' shape).
std::vector<size_t> uvsPerPosition(const TriangleMesh& m, const std::vector<size_t>& which) {
  std::map<std::array<float, 3>, std::set<std::pair<float, float>>> uvs;
  for (size_t i : which)
    uvs[{m.positions[i].x(), m.positions[i].y(), m.positions[i].z()}].insert(
        {m.uvs[i].x(), m.uvs[i].y()});
  std::vector<size_t> sizes;
  sizes.reserve(uvs.size());
  for (const auto& [p, set] : uvs) sizes.push_back(set.size());
  std::sort(sizes.begin(), sizes.end());
  return sizes;
}

// Signed area of a triangle in UV space.
double uvArea(const TriangleMesh& m, const std::array<uint32_t, 3>& t) {
  const Vec2f a = m.uvs[t[1]] - m.uvs[t[0]], b = m.uvs[t[2]] - m.uvs[t[0]];
  return 0.5 * (double(a.x()) * b.y() - double(a.y()) * b.x());
}

// makeCube maps each face onto the whole texture: six islands, every cube edge a seam. After
// Catmull-Clark each island still covers [0, 1]^2 exactly once, its borders stay on the square's
// edges, the face centres sit at uv (0.5, 0.5), and a cube corner comes out with the UVs it
// had (one per face, less those two faces happen to share).
TEST(Subdivide, CubeKeepsItsUvSeams) {
  const TriangleMesh cube = makeCube();
  const auto r = subdivide(cube, 2);
  ASSERT_TRUE(r.ok()) << r.error().message();
  const TriangleMesh& m = r->mesh;
  ASSERT_EQ(m.uvs.size(), m.positions.size());
  const size_t shared = repeatedUvVertices(cube);
  EXPECT_EQ(m.positions.size(), 6u * 25u - shared);      // 5 x 5 per island
  EXPECT_EQ(weldedByPosition(m).positions.size(), 98u);  // 6 * 16 + 2 shared positions
  EXPECT_TRUE(watertight(weldedByPosition(m)));
  double total = 0;
  for (const auto& t : m.triangles) {
    const double a = uvArea(m, t);
    EXPECT_GT(std::abs(a), 1e-4);
    total += std::abs(a);
    for (uint32_t v : t) {
      EXPECT_GE(m.uvs[v].minCoeff(), -1e-6f);
      EXPECT_LE(m.uvs[v].maxCoeff(), 1 + 1e-6f);
    }
  }
  EXPECT_NEAR(total, 6.0, 1e-5);
  int centres = 0, border = 0;
  for (const Vec2f& uv : m.uvs) {
    centres += (uv - Vec2f(0.5f, 0.5f)).norm() < 1e-6f;
    const bool onEdge = uv.minCoeff() < 1e-6f || uv.maxCoeff() > 1 - 1e-6f;
    if (!onEdge) continue;
    ++border;  // linear along the seam: quarters of the square's edge
    for (int k = 0; k < 2; ++k) EXPECT_NEAR(4 * uv[k], std::round(4 * uv[k]), 1e-5) << uv.transpose();
  }
  EXPECT_EQ(centres, 6);
  EXPECT_EQ(border, 6 * 16 - int(shared));
  // The islands' corners: on 8 positions, with the UVs the cube's corners had.
  std::vector<size_t> corners, all(cube.positions.size());
  for (size_t i = 0; i < m.positions.size(); ++i)
    if ((m.uvs[i].array() * (1 - m.uvs[i].array())).abs().maxCoeff() < 1e-6f) corners.push_back(i);
  for (size_t i = 0; i < all.size(); ++i) all[i] = i;
  EXPECT_EQ(uvsPerPosition(m, corners), uvsPerPosition(cube, all));
  EXPECT_EQ(uvsPerPosition(m, corners).size(), 8u);
}

// Loop keeps UVs too: a tetrahedron with each face on the texture's lower-left half.
TEST(Subdivide, LoopCarriesUvIslands) {
  TriangleMesh tet;
  const Vec3f c[4] = {Vec3f(1, 1, 1), Vec3f(1, -1, -1), Vec3f(-1, 1, -1), Vec3f(-1, -1, 1)};
  const std::array<int, 3> faces[4] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  for (const auto& f : faces) {
    const uint32_t base = uint32_t(tet.positions.size());
    for (int k = 0; k < 3; ++k) tet.positions.push_back(c[f[size_t(k)]]);
    tet.uvs.insert(tet.uvs.end(), {Vec2f(0, 0), Vec2f(1, 0), Vec2f(0, 1)});
    tet.triangles.push_back({base, base + 1, base + 2});
  }
  const auto r = subdivide(tet, 2);
  ASSERT_TRUE(r.ok()) << r.error().message();
  EXPECT_EQ(r->scheme, SubdivisionScheme::Loop);
  const TriangleMesh& m = r->mesh;
  EXPECT_EQ(m.positions.size(), 4u * 15u - repeatedUvVertices(tet));  // 15 per island (5 rows)
  EXPECT_TRUE(watertight(weldedByPosition(m)));
  double total = 0;
  for (const auto& t : m.triangles) total += uvArea(m, t);
  EXPECT_NEAR(total, 4 * 0.5, 1e-5);  // positive: no island folded over
  for (const Vec2f& uv : m.uvs) {
    EXPECT_GE(uv.minCoeff(), -1e-6f);
    EXPECT_LE(uv.sum(), 1 + 1e-5f);
  }
}

// Zero levels: the welded mesh as it was, UVs and all (the cube's 6 quads, each split once).
TEST(Subdivide, ZeroLevelsKeepTheWeldedMesh) {
  const TriangleMesh cube = makeCube();
  const auto r = subdivide(cube, 0);
  ASSERT_TRUE(r.ok()) << r.error().message();
  EXPECT_EQ(r->mesh.triangles.size(), 12u);
  EXPECT_EQ(r->mesh.positions.size(), cube.positions.size() - repeatedUvVertices(cube));
  ASSERT_EQ(r->mesh.uvs.size(), r->mesh.positions.size());
  EXPECT_NEAR(volume(r->mesh), 1.0, 1e-6);
}

// A fin: a third triangle on the quad's diagonal. The half-edge mesh refuses it (three faces on
// one edge), the result counts it, and OpenSubdiv still refines all three into finite triangles.
TEST(Subdivide, NonManifoldFinStaysSane) {
  TriangleMesh fin;
  fin.positions = {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(1, 1, 0), Vec3f(0, 1, 0), Vec3f(0.5f, 0.5f, 1)};
  fin.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 2, 4}};
  const auto r = subdivide(fin, 2);
  ASSERT_TRUE(r.ok()) << r.error().message();
  EXPECT_EQ(r->nonManifoldTriangles, 1u);
  EXPECT_EQ(r->scheme, SubdivisionScheme::Loop);
  EXPECT_EQ(r->mesh.triangles.size(), 3u * 16u);
  for (const auto& p : r->mesh.positions) EXPECT_TRUE(p.allFinite());
  for (const auto& n : r->mesh.normals) EXPECT_TRUE(n.allFinite());
  const auto box = r->mesh.bounds();
  EXPECT_GE(box.min().minCoeff(), -1e-6f);
  EXPECT_LE(box.max().maxCoeff(), 1 + 1e-6f);
}

}  // namespace
}  // namespace inlay
