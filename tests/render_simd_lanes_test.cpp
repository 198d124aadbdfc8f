// The AVX2 lanes (simd_lanes.h) against the scalar code, bit for bit: spherical quads against
// SphericalQuad, the sampler against SampleRng, the tracer with them against the tracer without.
#include "../render/src/simd_lanes.h"
#include "../render/src/sampling.h"
#include "render_test_scenes.h"
#include "inlay/render/path_tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using namespace inlay;
using namespace inlay::detail;

namespace {

struct QuadCase {
  std::array<Vec3, 4> corner;
  Vec3 origin;
  double u0 = 0, u1 = 0;
};

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// A planar convex quad (a light's emitter) of random size, place and tilt, and a point near or far.
QuadCase randomCase(std::mt19937_64& gen) {
  std::uniform_real_distribution<double> unit(0.0, 1.0), sym(-1.0, 1.0);
  const Vec3 centre(3 * sym(gen), 2 + sym(gen), 3 * sym(gen));
  const Vec3 ex = Vec3(sym(gen), 0.2 * sym(gen), sym(gen)).normalized();
  const Vec3 ey = ex.cross(Vec3(sym(gen), 1.0, sym(gen))).normalized();
  const double w = 0.05 + unit(gen), h = 0.05 + unit(gen), skew = 0.3 * sym(gen);
  QuadCase c;
  c.corner = {centre - w * ex - h * ey, centre + w * ex - h * ey, centre + (w + skew) * ex + h * ey,
              centre - w * ex + h * ey};
  const double reach = unit(gen) < 0.5 ? 0.5 : 20.0;
  c.origin = centre + reach * Vec3(sym(gen), sym(gen) - 1.0, sym(gen));
  c.u0 = unit(gen), c.u1 = unit(gen);
  return c;
}

// Runs the cases through the kernel four at a time; counts the lanes it left to the scalar code
// and the values that differ from SphericalQuad's bits.
struct Outcome {
  int lanes = 0, leftToScalar = 0, differ = 0;
};
Outcome compare(const std::vector<QuadCase>& cases) {
  Outcome out;
  for (size_t first = 0; first < cases.size(); first += kQuadLanes) {
    QuadLanes q{};
    const int n = int(std::min<size_t>(kQuadLanes, cases.size() - first));
    for (int l = 0; l < kQuadLanes; ++l) {
      const QuadCase& c = cases[first + size_t(std::min(l, n - 1))];
      for (int k = 0; k < 4; ++k)
        for (int a = 0; a < 3; ++a) q.corner[k][a][l] = c.corner[size_t(k)][a];
      for (int a = 0; a < 3; ++a) q.origin[a][l] = c.origin[a];
      q.u0[l] = c.u0, q.u1[l] = c.u1;
    }
    const int scalarMask = sphericalQuadLanesAvx2(q);
    for (int l = 0; l < n; ++l) {
      ++out.lanes;
      if (scalarMask & (1 << l)) {
        ++out.leftToScalar;
        continue;
      }
      const QuadCase& c = cases[first + size_t(l)];
      const SphericalQuad sq(c.corner, c.origin);
      bool same = sameBits(sq.solidAngle, q.solidAngle[l]);
      if (sq.solidAngle > 0) {
        const Vec3 y = sq.sample(c.u0, c.u1);
        for (int a = 0; a < 3; ++a) same = same && sameBits(y[a], q.y[a][l]);
      }
      out.differ += same ? 0 : 1;
    }
  }
  return out;
}

}  // namespace

TEST(QuadLanes, MatchSphericalQuadBitForBit) {
  if (!cpuHasAvx2()) GTEST_SKIP() << "no AVX2 on this CPU: the tracer uses the scalar code";
  std::mt19937_64 gen(20261127);
  std::vector<QuadCase> cases;
  for (int i = 0; i < 40001; ++i) cases.push_back(randomCase(gen));  // not a multiple of 4
  const Outcome o = compare(cases);
  EXPECT_EQ(o.lanes, 40001);
  EXPECT_EQ(o.leftToScalar, 0);
  EXPECT_EQ(o.differ, 0);
}

TEST(QuadLanes, ExtremeInputsMatchOrGoToTheScalarCode) {
  if (!cpuHasAvx2()) GTEST_SKIP() << "no AVX2 on this CPU: the tracer uses the scalar code";
  std::mt19937_64 gen(7);
  const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
  std::vector<QuadCase> cases;
  for (int i = 0; i < 64; ++i) {
    QuadCase c = randomCase(gen);
    switch (i % 8) {
      case 0: c.origin = c.corner[0]; break;                                      // at a corner
      case 1: c.origin = 0.5 * (c.corner[0] + c.corner[2]); break;                // on the quad
      case 2: c.origin = c.corner[0] + 3.0 * (c.corner[1] - c.corner[0]); break;  // in its plane
      case 3: c.origin *= 1e300; break;
      case 4: c.origin.x() = inf; break;
      case 5: c.corner[2].y() = nan; break;
      case 6: c.u0 = 1.0, c.u1 = 1.0; break;                        // the far ends
      default: c.origin = c.corner[1] + Vec3(1e-300, 0, 0); break;  // a denormal away
    }
    cases.push_back(c);
  }
  const Outcome o = compare(cases);
  EXPECT_EQ(o.lanes, 64);
  EXPECT_EQ(o.differ, 0);
}

// Eight lanes' SampleRng numbers (pixels, samples and seeds at random, pairs from the camera's
// jitter to beyond the pair-hash table) against SampleRng::get2's bits.
TEST(SamplerLanes, MatchSampleRngBitForBit) {
  if (!cpuHasAvx2()) GTEST_SKIP() << "no AVX2 on this CPU: the tracer uses the scalar code";
  std::mt19937 gen(18);
  int differ = 0, compared = 0;
  for (int round = 0; round < 2000; ++round) {
    SamplerLanes s;
    s.seed = gen();
    s.pairs = 1 + round % kSamplerPairs;
    const uint32_t firstPair = round % 3 == 0 ? 0u : round % 3 == 1 ? gen() % 300u : gen();
    for (int k = 0; k < s.pairs; ++k) s.pairHash[k] = SampleRng::pairHash(firstPair + uint32_t(k));
    s.sobol1Reversed = &kSobol1Reversed.byByte[0][0];
    for (int l = 0; l < kSamplerLanes; ++l)
      s.x[l] = gen() % 5000u, s.y[l] = gen() % 5000u, s.sample[l] = round % 2 ? gen() : gen() % 64u;
    samplerLanesAvx2(s);
    for (int l = 0; l < kSamplerLanes; ++l) {
      const SampleRng rng(s.x[l], s.y[l], s.sample[l], s.seed);
      const SampleRng fromKey = SampleRng::fromKey(s.pixelKey[l], s.sample[l], s.reversedSample[l]);
      for (int k = 0; k < s.pairs; ++k) {
        const auto u = rng.get2(firstPair + uint32_t(k)), v = fromKey.get2(firstPair + uint32_t(k));
        for (int c = 0; c < 2; ++c) {
          ++compared;
          differ += sameBits(u[size_t(c)], s.u[k][c][l]) && sameBits(u[size_t(c)], v[size_t(c)]) ? 0 : 1;
        }
      }
    }
  }
  EXPECT_GT(compared, 90000);
  EXPECT_EQ(differ, 0);
}

namespace {

// A room under a trapezoid ceiling light (not a rectangle: Arvo's spherical quad, near for most
// of the room) with a diffuse, a glossy and a frosted-glass sphere, rendered with the lanes on or
// off (the tracer reads the switch when it is made).
DifferentialBuffers renderRoom(bool lanes) {
  const int w = 64, h = 48;
  RenderScene s = test::roomScene(test::testCamera(w, h, 70, 1.3, -20), RoomBox{}, 0.5);
  AreaLight light;
  light.cornersWorld = {Vec3(-0.3, 2.6, -2.4), Vec3(0.3, 2.6, -2.4), Vec3(0.2, 2.6, -2.0),
                        Vec3(-0.2, 2.6, -2.0)};
  light.radiance = Vec3::Constant(6.0);
  s.lights.push_back(light);
  const std::array<Material::Kind, 3> kinds = {Material::Kind::Diffuse, Material::Kind::Conductor,
                                               Material::Kind::RoughGlass};
  for (size_t i = 0; i < kinds.size(); ++i) {
    InsertedObject o;
    o.meshObject = test::sphereMesh(0.25, 16, 32);
    o.worldFromObject = Mat4::Identity();
    o.worldFromObject.topRightCorner<3, 1>() = Vec3(-0.6 + 0.6 * double(i), 0.25, -2.3);
    o.material.kind = kinds[i];
    o.material.albedo = Vec3(0.7, 0.6, 0.5);
    o.material.roughness = 0.4;
    s.objects.push_back(o);
  }
  TracerOptions opt;
  opt.maxDepth = 3;
  opt.roughGlassNee = true;
  setSimdLanesEnabled(lanes);
  PathTracer tracer(s, opt);
  setSimdLanesEnabled(true);
  DifferentialBuffers b(w, h);
  b.enableGuides();
  EXPECT_TRUE(tracer.render(b, 0, 4, 11));
  return b;
}

int differingValues(const ImageF& a, const ImageF& b) {
  if (a.data.size() != b.data.size()) return -1;
  int n = 0;
  for (size_t i = 0; i < a.data.size(); ++i)
    n += std::memcmp(&a.data[i], &b.data[i], sizeof(float)) ? 1 : 0;
  return n;
}

}  // namespace

// The tracer with the lanes (a camera packet's first vertices and near-light points worked out
// ahead, firstVertices) renders every buffer to the bit as without them.
TEST(QuadLanes, TracerRendersTheSameBitsWithAndWithoutThem) {
  if (!cpuHasAvx2()) GTEST_SKIP() << "no AVX2 on this CPU: the tracer uses the scalar code";
  const DifferentialBuffers on = renderRoom(true), off = renderRoom(false);
  EXPECT_EQ(differingValues(on.sumWith, off.sumWith), 0);
  EXPECT_EQ(differingValues(on.sumWithout, off.sumWithout), 0);
  EXPECT_EQ(differingValues(on.sumChange, off.sumChange), 0);
  EXPECT_EQ(differingValues(on.sumMask, off.sumMask), 0);
  EXPECT_EQ(differingValues(on.sumDiffSq, off.sumDiffSq), 0);
  EXPECT_EQ(differingValues(on.sumGuideAlbedo, off.sumGuideAlbedo), 0);
  EXPECT_EQ(on.samples, off.samples);
  double total = 0;
  for (float v : on.sumWith.data) total += v;
  EXPECT_GT(total, 0.0);  // the light reaches the room
}
