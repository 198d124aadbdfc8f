#include "inlay/lighting/gather.h"

#include <algorithm>
#include <cmath>

namespace inlay {

GatherSample gatherIrradianceOverPi(const RoomTracer& tracer, const Vec3& point, const Vec3& normal,
                                    int samples, uint32_t pixelId, uint32_t seed,
                                    const RadianceAt& radianceAt) {
  Vec3 sum = Vec3::Zero(), sum2 = Vec3::Zero();
  forEachGatherRay(tracer, point, normal, samples, pixelId, seed,
                   [&](const SurfaceHit* h, uint32_t sampleId) {
                     Vec3 L = Vec3::Zero();
                     if (h) L = radianceAt(*h, sampleId);
                     if (!L.allFinite()) L = Vec3::Zero();
                     sum += L;
                     sum2 += L.cwiseProduct(L);
                   });
  GatherSample g;
  g.rays = gatherRaysPerSide(samples) * gatherRaysPerSide(samples);
  g.mean = sum / g.rays;
  // The spread of the strata as if independent: an upper bound for the stratified estimate.
  const Vec3 var = (sum2 / g.rays - g.mean.cwiseProduct(g.mean)).cwiseMax(0.0);
  g.standardError = (var / std::max(1, g.rays - 1)).cwiseSqrt();
  return g;
}

int gatherSamplesForNoise(const RoomTracer& tracer, const std::vector<std::pair<Vec3, Vec3>>& points,
                          uint32_t seed, const RadianceAt& radianceAt,
                          const GatherSampleCountOptions& o) {
  double need = 0;
  int n = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const GatherSample g = gatherIrradianceOverPi(tracer, points[i].first, points[i].second,
                                                  o.pilotSamples, uint32_t(i) * 7919u + 13u, seed,
                                                  radianceAt);
    const double m = luminance(g.mean);
    if (!(m > 1e-9)) continue;
    // Variance per ray = se^2 * (rays - 1); samples for the target = that / (noise * m)^2.
    const double se = luminance(g.standardError);
    need += se * se * std::max(1, g.rays - 1) / (o.relativeNoise * o.relativeNoise * m * m);
    ++n;
  }
  int samples = n > 0 ? int(std::ceil(need / n)) : o.maxSamples;
  samples = std::clamp(samples, o.minSamples, std::max(o.minSamples, o.maxSamples));
  const int side = int(std::ceil(std::sqrt(double(samples))));
  return std::min(side * side, std::max(o.minSamples, o.maxSamples));
}

}  // namespace inlay

namespace inlay {

uint64_t SurfacePatches::keyOf(int surfaceId, const Vec3& p, const Vec3& n) const {
  // The plane's two in-plane axes are those other than the normal's largest component; its
  // sign and the plane's offset (rounded) tell parallel faces of one surface apart.
  int a = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) > std::abs(n[a])) a = k;
  const int u = (a + 1) % 3, v = (a + 2) % 3;
  auto cell = [&](double x, bool round) {
    const double q = x / sizeM;
    return uint64_t(int64_t(round ? std::lround(q) : std::floor(q)) + 32768) & 0xffffu;
  };
  return (uint64_t(uint32_t(surfaceId) & 0x1fffu) << 51) | (uint64_t(a) << 49) |
         (uint64_t(n[a] > 0) << 48) | (cell(p[a], true) << 32) | (cell(p[u], false) << 16) |
         cell(p[v], false);
}

int SurfacePatches::find(const SurfaceHit& hit) const {
  const uint64_t k = keyOf(hit.surfaceId, hit.pointWorld, hit.normalWorld);
  const auto it = std::lower_bound(keys.begin(), keys.end(), std::make_pair(k, -1));
  return it != keys.end() && it->first == k ? it->second : -1;
}

SurfacePatches makeSurfacePatches(const SceneGeometry& geometry, double sizeM) {
  SurfacePatches P;
  P.sizeM = std::max(sizeM, 1e-3);
  const Vec3 centre(0.5 * (geometry.box.xLeftM + geometry.box.xRightM), 0.5 * geometry.box.ceilingM,
                    0.5 * (geometry.box.zBackM + geometry.box.zRearM));
  std::vector<std::pair<uint64_t, int>> keys;
  std::vector<Vec3> sum;
  std::vector<double> count;
  for (size_t s = 0; s < geometry.surfaces.size(); ++s) {
    const Surface& surf = geometry.surfaces[s];
    const TriangleMesh& m = surf.meshWorld;
    for (const auto& t : m.triangles) {
      const Vec3 a = m.positions[t[0]].cast<double>(), b = m.positions[t[1]].cast<double>(),
                 c = m.positions[t[2]].cast<double>();
      Vec3 n = (b - a).cross(c - a);
      if (!(n.norm() > 1e-12)) continue;
      n.normalize();
      if (!m.normals.empty()) {
        const Vec3 vn = (m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]]).cast<double>();
        if (vn.dot(n) < 0) n = -n;
      }
      if (isBoxSurface(surf.kind) && n.dot(centre - a) < 0) n = -n;
      // Samples on a barycentric grid fine enough to touch every patch the triangle crosses.
      const double edge = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
      const int k = std::clamp(int(std::ceil(3 * edge / P.sizeM)), 1, 600);
      for (int i = 0; i <= k; ++i)
        for (int j = 0; i + j <= k; ++j) {
          const double u = (i + 1.0 / 3) / (k + 1), v = (j + 1.0 / 3) / (k + 1);
          if (u + v > 1) continue;
          const Vec3 p = a + u * (b - a) + v * (c - a);
          keys.emplace_back(P.keyOf(int(s), p, n), int(P.point.size()));
          P.point.push_back(p);
          P.normal.push_back(n);
          P.surface.push_back(int(s));
        }
    }
  }
  // One patch per key: the centroid of its samples.
  std::sort(keys.begin(), keys.end());
  SurfacePatches out;
  out.sizeM = P.sizeM;
  for (size_t i = 0; i < keys.size();) {
    size_t j = i;
    Vec3 c = Vec3::Zero();
    for (; j < keys.size() && keys[j].first == keys[i].first; ++j) c += P.point[size_t(keys[j].second)];
    const int first = keys[i].second;
    out.keys.emplace_back(keys[i].first, int(out.point.size()));
    out.point.push_back(c / double(j - i));
    out.normal.push_back(P.normal[size_t(first)]);
    out.surface.push_back(P.surface[size_t(first)]);
    i = j;
  }
  out.gamma.assign(out.point.size(), Vec3::Zero());
  return out;
}

}  // namespace inlay
