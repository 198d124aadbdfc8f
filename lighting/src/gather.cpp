#include "inlay/lighting/gather.h"

#include <algorithm>
#include <cmath>

namespace inlay {

namespace {

inline uint32_t hash32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}
inline double uniform(uint32_t a, uint32_t b, uint32_t c) {
  return (hash32(a ^ hash32(b ^ hash32(c))) >> 8) * (1.0 / 16777216.0);
}

double luminance(const Vec3& c) { return 0.2126 * c.x() + 0.7152 * c.y() + 0.0722 * c.z(); }

}  // namespace

GatherSample gatherIrradianceOverPi(const RoomTracer& tracer, const Vec3& point,
                                    const Vec3& normal, int samples, uint32_t pixelId,
                                    uint32_t seed, const RadianceAt& radianceAt) {
  const int nSide = std::max(1, int(std::lround(std::sqrt(double(std::max(samples, 1))))));
  const Vec3 t = (std::abs(normal.x()) > 0.9 ? Vec3(0, 1, 0) : Vec3(1, 0, 0)).cross(normal).normalized();
  const Vec3 b = normal.cross(t);
  Vec3 sum = Vec3::Zero(), sum2 = Vec3::Zero();
  for (int i = 0; i < nSide; ++i)
    for (int k = 0; k < nSide; ++k) {
      const uint32_t s = uint32_t(i * nSide + k);
      const double u1 = (i + uniform(pixelId, seed, 2 * s)) / nSide;
      const double u2 = (k + uniform(pixelId, seed, 2 * s + 1)) / nSide;
      const double r = std::sqrt(u1), phi = 2 * M_PI * u2;
      const Vec3 d = (r * std::cos(phi) * t + r * std::sin(phi) * b +
                      std::sqrt(std::max(0.0, 1 - u1)) * normal).normalized();
      const auto h = tracer.intersect(Ray{point + 1e-5 * normal, d}, 1e-5);
      Vec3 L = Vec3::Zero();
      if (h) L = radianceAt(*h, pixelId * 1024u + s);
      if (!L.allFinite()) L = Vec3::Zero();
      sum += L;
      sum2 += L.cwiseProduct(L);
    }
  GatherSample g;
  g.rays = nSide * nSide;
  g.mean = sum / g.rays;
  // The spread of the strata as if independent: an upper bound for the stratified estimate.
  const Vec3 var = (sum2 / g.rays - g.mean.cwiseProduct(g.mean)).cwiseMax(0.0);
  g.standardError = (var / std::max(1, g.rays - 1)).cwiseSqrt();
  return g;
}

int gatherSamplesForNoise(const RoomTracer& tracer,
                          const std::vector<std::pair<Vec3, Vec3>>& points, uint32_t seed,
                          const RadianceAt& radianceAt, const GatherSampleCountOptions& o) {
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
