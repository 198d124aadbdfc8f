// OpenSubdiv subdivision: a cube becomes a smooth closed blob by Catmull-Clark (vertex counts of
// uniform refinement, watertight, volume converging between the inscribed sphere's and the
// cube's, rounder at every level); triangle meshes go through Loop; open borders stay put;
// bad requests are errors.
#include "inlay/modeling/subdivide.h"

#include <gtest/gtest.h>

#include <map>

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
    const TriangleMesh& m = r->mesh;
    EXPECT_EQ(r->scheme, SubdivisionScheme::CatmullClark);
    const size_t quads = 6u << (2 * levels);
    EXPECT_EQ(m.positions.size(), quads + 2);  // Euler: V = F + 2 for a closed quad mesh of genus 0
    EXPECT_EQ(m.triangles.size(), 2 * quads);
    EXPECT_TRUE(watertight(m));
    EXPECT_EQ(m.normals.size(), m.positions.size());
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
  for (const auto& p : r->mesh.positions) EXPECT_TRUE(p.allFinite());
}

}  // namespace
}  // namespace inlay
