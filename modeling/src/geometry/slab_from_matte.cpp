// A table top's slab thickness read from the user's occluder matte (occluder.h).
#include "inlay/modeling/occluder.h"

#include <algorithm>
#include <cmath>

namespace inlay {

namespace {

// The covered band under one top point: the depth (m) where the matte first gives way going
// straight down, 0 when it does not cover the point, the full height when it does not give way
// above the bottom tenth (where the matte's edge on the floor blurs into it anyway).
double coveredBandBelow(const CardAlpha& matte, const Vec3& topPoint, double heightM) {
  constexpr double kStepM = 0.002, kCovered = 0.5;
  // Just under the edge: the top's own pixels are the matte's, whatever the sides do.
  if (matte.alphaAt(topPoint - Vec3(0, kStepM, 0)) < kCovered) return 0.0;
  for (double depth = 2 * kStepM; depth < 0.9 * heightM; depth += kStepM)
    if (matte.alphaAt(topPoint - Vec3(0, depth, 0)) < kCovered) return depth;
  return heightM;
}

}  // namespace

SlabEvidence slabFromMatte(const Camera& camera, const Extrusion& ex, const ImageF& alphaPx,
                           const SlabOptions& options) {
  SlabEvidence out;
  const size_t n = ex.topOutlineWorld.size();
  if (n < 3 || alphaPx.empty() || !(ex.heightM > 0)) return out;
  CardAlpha matte;
  matte.camera = camera;
  matte.alphaPx = alphaPx;
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& p : ex.topOutlineWorld) centroid += p / double(n);
  const Vec3 eye(0, camera.heightM, 0);
  std::vector<double> bands;
  for (size_t i = 0; i < n; ++i) {
    const Vec3 a = ex.topOutlineWorld[i], b = ex.topOutlineWorld[(i + 1) % n];
    const Vec3 mid = 0.5 * (a + b);
    Vec3 outward = (b - a).cross(Vec3(0, 1, 0));
    if (outward.dot(mid - centroid) < 0) outward = -outward;
    if (!(outward.dot(eye - mid) > 0)) continue;  // a side the camera does not see
    const auto pa = camera.project(a), pb = camera.project(b);
    if (!pa || !pb) continue;
    const int samples = std::clamp(int((*pa - *pb).norm() / 2.0), 0, 400);  // one per 2 px
    for (int k = 0; k < samples; ++k) {
      const Vec3 p = a + (b - a) * ((k + 0.5) / samples);
      const double band = coveredBandBelow(matte, p, ex.heightM);
      if (band <= 0) continue;
      ++out.coveredSamples;
      if (band < ex.heightM) ++out.openSamples, bands.push_back(band);
    }
  }
  if (out.coveredSamples < options.minSamples ||
      out.openSamples < options.openShare * out.coveredSamples)
    return out;
  std::nth_element(bands.begin(), bands.begin() + long(bands.size() / 2), bands.end());
  const double thickness = bands[bands.size() / 2];
  out.open = true;
  out.thicknessM = thickness;
  return out;
}

}  // namespace inlay
