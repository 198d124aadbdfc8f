// Gathering (gather.h) against analytic view factors: a closed room of constant radiance gives
// that radiance with zero spread; a floor point under a ceiling that alone is bright gathers
// the differential-to-parallel-rectangle view factor; the sample count follows the noise.
#include "inlay/lighting/gather.h"

#include <gtest/gtest.h>

#include <cmath>

namespace inlay {
namespace {

SceneGeometry cubeRoom(double halfM, double heightM) {
  RoomBox box;
  box.xLeftM = -halfM, box.xRightM = halfM, box.zBackM = -halfM, box.zRearM = halfM;
  box.ceilingM = heightM;
  return buildSceneGeometry(box, {});
}

// View factor from a differential area to a parallel rectangle a x b at distance c, the area
// below one corner (Howell's catalogue, B-3).
double cornerViewFactor(double a, double b, double c) {
  const double A = a / c, B = b / c;
  return (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
          B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B))) /
         (2 * M_PI);
}

TEST(Gather, ClosedRoomOfConstantRadiance) {
  const SceneGeometry g = cubeRoom(2, 2.5);
  RoomTracer tracer(g);
  const RadianceAt constant = [](const SurfaceHit&, uint32_t) { return Vec3(0.5, 0.25, 0.125); };
  const GatherSample s =
      gatherIrradianceOverPi(tracer, Vec3(0.3, 0, -0.7), Vec3(0, 1, 0), 64, 17, 7, constant);
  EXPECT_EQ(s.rays, 64);
  EXPECT_NEAR(s.mean.x(), 0.5, 1e-12);
  EXPECT_NEAR(s.mean.z(), 0.125, 1e-12);
  EXPECT_NEAR(s.standardError.norm(), 0, 1e-9);
  // No spread: the fewest samples.
  GatherSampleCountOptions o;
  EXPECT_EQ(gatherSamplesForNoise(tracer, {{Vec3(0, 0, 0), Vec3(0, 1, 0)}}, 7, constant, o),
            o.minSamples);
}

TEST(Gather, CeilingViewFactorFromTheFloorCentre) {
  const double half = 2, h = 2.5;
  const SceneGeometry g = cubeRoom(half, h);
  RoomTracer tracer(g);
  const RadianceAt ceilingOnly = [&](const SurfaceHit& hit, uint32_t) {
    return g.surfaces[size_t(hit.surfaceId)].kind == SurfaceKind::Ceiling ? Vec3(1, 1, 1)
                                                                          : Vec3(0, 0, 0);
  };
  const double truth = 4 * cornerViewFactor(half, half, h);
  const GatherSample s =
      gatherIrradianceOverPi(tracer, Vec3(0, 0, 0), Vec3(0, 1, 0), 1024, 3, 7, ceilingOnly);
  EXPECT_NEAR(s.mean.y(), truth, 0.01) << "se " << s.standardError.y();
  EXPECT_GT(s.standardError.y(), 0);
  // Stratification: the error is well within the independent-sample bound.
  EXPECT_LT(std::abs(s.mean.y() - truth), 3 * s.standardError.y() + 1e-3);
  // Half the radiance lit: the sample count rises as the target noise falls.
  GatherSampleCountOptions loose, tight;
  loose.relativeNoise = 0.2;
  tight.relativeNoise = 0.05;
  tight.maxSamples = 4096;
  const std::vector<std::pair<Vec3, Vec3>> pts{{Vec3(0, 0, 0), Vec3(0, 1, 0)},
                                               {Vec3(1, 0, 1), Vec3(0, 1, 0)}};
  const int nLoose = gatherSamplesForNoise(tracer, pts, 7, ceilingOnly, loose);
  const int nTight = gatherSamplesForNoise(tracer, pts, 7, ceilingOnly, tight);
  EXPECT_LT(nLoose, nTight);
  EXPECT_GT(nTight, 100);
  const int side = int(std::lround(std::sqrt(nTight)));
  EXPECT_EQ(side * side, nTight);
}

}  // namespace
}  // namespace inlay

namespace inlay {
namespace {

// Every gather ray from inside the room lands in a patch of the surface it hit, near the hit.
TEST(SurfacePatches, CoverTheRoomAndAreFoundFromTheirHits) {
  const SceneGeometry g = cubeRoom(2, 2.5);
  const SurfacePatches P = makeSurfacePatches(g, 0.3);
  ASSERT_GT(P.point.size(), 200u);
  RoomTracer tracer(g);
  int hits = 0;
  const RadianceAt check = [&](const SurfaceHit& h, uint32_t) -> Vec3 {
    const int p = P.find(h);
    EXPECT_GE(p, 0) << h.pointWorld.transpose();
    if (p < 0) return Vec3(0, 0, 0);
    EXPECT_EQ(P.surface[size_t(p)], h.surfaceId);
    EXPECT_LT((P.point[size_t(p)] - h.pointWorld).norm(), 0.3 * std::sqrt(2.0) + 1e-9);
    EXPECT_GT(P.normal[size_t(p)].dot(h.normalWorld), 0.99);
    ++hits;
    return Vec3(1, 1, 1);
  };
  for (const Vec3& o : {Vec3(0, 1, 0), Vec3(1.9, 0.01, -1.9), Vec3(-1.2, 2.4, 0.5)})
    gatherIrradianceOverPi(tracer, o, Vec3(0, 1, 0), 256, 5, 3, check);
  EXPECT_EQ(hits, 3 * 256);
}

// Radiosity in a closed room that the photo does not show at all: every surface emits Le and
// reflects rho of what it gathers, so k Jacobi sweeps from Gamma = 0 give exactly
// Le (1 - rho^k) / (1 - rho) (the fixed point Le / (1 - rho)), at every patch.
TEST(SurfacePatches, RadiositySweepsMatchTheFurnace) {
  const SceneGeometry g = cubeRoom(1.5, 2.5);
  SurfacePatches P = makeSurfacePatches(g, 0.5);
  RoomTracer tracer(g);
  const double rho = 0.6, Le = 1.0;
  const RadianceAt radiance = [&](const SurfaceHit& h, uint32_t) -> Vec3 {
    const int p = P.find(h);
    EXPECT_GE(p, 0) << h.pointWorld.transpose();
    return Vec3::Constant(Le) + rho * (p >= 0 ? P.gamma[size_t(p)] : Vec3(NAN, NAN, NAN));
  };
  for (int sweep = 1; sweep <= 4; ++sweep) {
    std::vector<Vec3> next(P.point.size());
    for (size_t i = 0; i < P.point.size(); ++i)
      next[i] = gatherIrradianceOverPi(tracer, P.point[i] + 1e-4 * P.normal[i], P.normal[i], 16,
                                       uint32_t(i), 1, radiance)
                    .mean;
    P.gamma = next;
    const double expect = Le * (1 - std::pow(rho, sweep)) / (1 - rho);
    for (size_t i = 0; i < P.gamma.size(); ++i)
      ASSERT_NEAR(P.gamma[i].x(), expect, 1e-9) << "sweep " << sweep << " patch " << i;
  }
}

}  // namespace
}  // namespace inlay
