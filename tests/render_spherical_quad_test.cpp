// A quad light's two spherical triangles set up in two SSE2 lanes (SphericalQuad(corners,
// origin), render/src/sampling.h) must be the scalar constructors' to the bit: NEE's light
// points, its pdfs and the MIS weights, and so every path, stay the same.
#include "../render/src/sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace inlay {
namespace {

using detail::SphericalQuad;
using detail::SphericalTriangle;

bool same(const Vec3& a, const Vec3& b) {
  return std::memcmp(a.data(), b.data(), 3 * sizeof(double)) == 0;
}
bool same(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }
bool same(const SphericalTriangle& a, const SphericalTriangle& b) {
  return same(a.o, b.o) && same(a.a, b.a) && same(a.b, b.b) && same(a.c, b.c) &&
         same(a.planePoint, b.planePoint) && same(a.planeNormal, b.planeNormal) && same(a.nab, b.nab) &&
         same(a.nbc, b.nbc) && same(a.nca, b.nca) && same(a.triple, b.triple) &&
         same(a.solidAngle, b.solidAngle);
}
// The lanes' quad against the scalar one (triangle after triangle), with a sample point too.
bool sameQuad(const std::array<Vec3, 4>& c, const Vec3& o) {
  const SphericalQuad lanes(c, o), scalar(c, o, SphericalQuad::unitDirections(c, o));
  if (!same(lanes.t1, scalar.t1) || !same(lanes.t2, scalar.t2) ||
      !same(lanes.solidAngle, scalar.solidAngle))
    return false;
  return !(scalar.solidAngle > 0) || same(lanes.sample(0.3, 0.7), scalar.sample(0.3, 0.7));
}

// A planar quad: a random parallelogram, sheared to a trapezoid, anywhere around the origin.
std::array<Vec3, 4> randomQuad(std::mt19937_64& g, double size) {
  std::uniform_real_distribution<double> u(-1, 1), s(0.05, 1);
  const Vec3 centre(3 * u(g), 3 * u(g), 3 * u(g));
  const Vec3 e1 = size * Vec3(u(g), u(g), u(g)), e2 = size * Vec3(u(g), u(g), u(g));
  const double shear = s(g);
  return {centre, centre + e1, centre + e1 * shear + e2, centre + e2};
}

// Near and far lights, large and tiny, seen from points all around (both triangles, both
// octants of the arctangent, the steep and the upper branch, behind the light too).
TEST(SphericalQuadLanes, MatchTheScalarTrianglesBitForBit) {
  std::mt19937_64 g(18);
  std::uniform_real_distribution<double> u(-1, 1);
  int mismatches = 0, n = 0;
  for (double size : {1e-6, 1e-3, 0.1, 1.0, 30.0})
    for (int k = 0; k < 20000; ++k, ++n) {
      const std::array<Vec3, 4> c = randomQuad(g, size);
      const Vec3 o = c[0] + Vec3(u(g), u(g), u(g)) * (k % 3 == 0 ? 0.01 : 2.0);
      mismatches += sameQuad(c, o) ? 0 : 1;
    }
  EXPECT_EQ(mismatches, 0) << "of " << n;
}

// Degenerate and extreme inputs: a point in the light's plane or on its corner, a quad of no
// area, corners far away or not finite: the same (zero, NaN) answers as the scalar set-up.
TEST(SphericalQuadLanes, DegenerateAndExtremeQuadsMatchTheScalarOnes) {
  const double inf = std::numeric_limits<double>::infinity(),
               nan = std::numeric_limits<double>::quiet_NaN();
  const std::array<Vec3, 4> unit = {Vec3(0, 2, 0), Vec3(1, 2, 0), Vec3(1, 2, 1), Vec3(0, 2, 1)};
  const std::vector<Vec3> origins = {Vec3(0.5, 0, 0.5), Vec3(0.5, 2, 0.5),     Vec3(0, 2, 0),
                                     Vec3(3, 2, 3),     Vec3(0.5, 1e300, 0.5), Vec3(0.5, 1e-300, 0.5),
                                     Vec3(nan, 0, 0),   Vec3(inf, 0, 0)};
  const std::vector<std::array<Vec3, 4>> quads = {
      unit,
      {Vec3(0, 2, 0), Vec3(0, 2, 0), Vec3(0, 2, 0), Vec3(0, 2, 0)},  // no area
      {Vec3(0, 2, 0), Vec3(1, 2, 0), Vec3(2, 2, 0), Vec3(3, 2, 0)},  // a line
      {Vec3(0, 1e300, 0), Vec3(1, 1e300, 0), Vec3(1, 1e300, 1), Vec3(0, 1e300, 1)},
      {Vec3(0, 2, 0), Vec3(inf, 2, 0), Vec3(1, 2, 1), Vec3(0, 2, 1)},
      {Vec3(0, 2, 0), Vec3(1, 2, 0), Vec3(nan, 2, 1), Vec3(0, 2, 1)}};
  int mismatches = 0;
  for (const auto& q : quads)
    for (const Vec3& o : origins) mismatches += sameQuad(q, o) ? 0 : 1;
  EXPECT_EQ(mismatches, 0);
  // And the answers are the expected ones where they are known.
  EXPECT_EQ(SphericalQuad(quads[1], origins[0]).solidAngle, 0.0);
  EXPECT_EQ(SphericalQuad(unit, origins[1]).solidAngle, 0.0);  // in the light's plane
  EXPECT_NEAR(SphericalQuad(unit, Vec3(0.5, 1.5, 0.5)).solidAngle, 2 * M_PI / 3, 1e-7);  // a cube face
}

}  // namespace
}  // namespace inlay
