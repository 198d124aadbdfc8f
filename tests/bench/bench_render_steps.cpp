// CPU nanoseconds per call of the path tracer's latency-bound steps, one thread, each timed in a
// loop over varied inputs (docs/benchmarks.md, bench_throughput's tenth pass):
//   camera_direction_scalar / _lanes: a packet's 8 camera directions by
//     Camera::directionThroughPixel one at a time, and two lanes at a time
//     (directionsThroughPixels); per direction;
//   quad_setup / quad_sample: a quad light's spherical quad seen from a point near it (its two
//     triangles' solid angles), and one point sampled on it;
//   quad_point_scalar / _lanes: the same quads' set-up and one point on each (NEE's light point),
//     one SphericalQuad after the other, and four at a time in AVX2 lanes (simd_lanes.h, the
//     lanes filled from the quads as the tracer fills them; only where the CPU runs AVX2); per quad;
//   sampler_jitter_scalar / _lanes: a camera packet's eight SampleRngs and their jitter (pair 0),
//     one rng after the other, and in one samplerLanesAvx2 call (only where the CPU runs AVX2);
//     per lane; sampler_vertex_*: the same with the first vertex's four pairs too;
//   sincos_chain: sinCos with each call's argument taken from the last one's result (its latency).
// Writes STEP,ns_per_call,repeats as CSV to stdout: the median of `repeats` timings.
//
// usage: bench_render_steps [--repeats 7]
#include "../../render/src/camera_directions.h"
#include "../../render/src/simd_lanes.h"
#include "../../render/src/sampling.h"

#include <algorithm>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <random>
#include <vector>

namespace {

using namespace inlay;
using namespace inlay::detail;

volatile double gSink = 0;  // keeps the timed results alive

// This thread's CPU time in nanoseconds (a loaded machine's waits left out).
double threadCpuNs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e9 + double(t.tv_nsec);
}

// The median over `repeats` of the CPU nanoseconds per call of `run(calls)`.
double medianNs(int repeats, long calls, const std::function<double(long)>& run) {
  std::vector<double> ns;
  for (int r = 0; r < repeats; ++r) {
    const double t0 = threadCpuNs();
    gSink = gSink + run(calls);
    ns.push_back((threadCpuNs() - t0) / double(calls));
  }
  std::sort(ns.begin(), ns.end());
  return ns[ns.size() / 2];
}

struct Pixels {
  std::vector<double> x, y;
};
Pixels randomPixels(std::mt19937_64& g, const Camera& cam, size_t n) {
  std::uniform_real_distribution<double> u(0, 1);
  Pixels p;
  for (size_t i = 0; i < n; ++i) p.x.push_back(u(g) * cam.widthPx), p.y.push_back(u(g) * cam.heightPx);
  return p;
}

// A ceiling light of 0.5 x 0.4 m (a trapezoid: not a rectangle) and points up to 1.5 m from it.
struct QuadCases {
  std::vector<std::array<Vec3, 4>> quads;
  std::vector<Vec3> from;
};
QuadCases nearQuads(std::mt19937_64& g, size_t n) {
  std::uniform_real_distribution<double> u(-1, 1);
  QuadCases q;
  for (size_t i = 0; i < n; ++i) {
    const Vec3 c(u(g), 2.5, u(g));
    q.quads.push_back({c, c + Vec3(0.5, 0, 0), c + Vec3(0.6, 0, 0.4), c + Vec3(0, 0, 0.4)});
    q.from.push_back(c + Vec3(1.5 * u(g), -0.2 - 0.6 * (u(g) + 1), 1.5 * u(g)));
  }
  return q;
}

}  // namespace

int main(int argc, char** argv) {
  int repeats = 7;
  for (int i = 1; i + 1 < argc; ++i)
    if (!std::strcmp(argv[i], "--repeats")) repeats = std::max(1, std::atoi(argv[i + 1]));
  std::mt19937_64 g(18);
  Camera cam = levelCamera(512, 384, 450, 1.6);
  cam.worldFromCamera = Eigen::AngleAxisd(0.3, Vec3(0.2, 1, 0.1).normalized()).toRotationMatrix();
  const size_t n = 4096;
  const Pixels px = randomPixels(g, cam, 8 * n);
  std::printf("step,ns_per_call,repeats\n");
  auto report = [&](const char* step, double ns) { std::printf("%s,%.2f,%d\n", step, ns, repeats); };

  Vec3 dirs[8];
  report("camera_direction_scalar", medianNs(repeats, long(8 * n) * 50, [&](long calls) {
           double s = 0;
           for (long k = 0; k < calls / 8; ++k) {
             const size_t i = 8 * (size_t(k) % n);
             for (int j = 0; j < 8; ++j)
               dirs[j] = cam.directionThroughPixel(Vec2(px.x[i + j], px.y[i + j]));
             s += dirs[3].x();
           }
           return s;
         }));
  report("camera_direction_lanes", medianNs(repeats, long(8 * n) * 50, [&](long calls) {
           double s = 0;
           for (long k = 0; k < calls / 8; ++k) {
             const size_t i = 8 * (size_t(k) % n);
             directionsThroughPixels(cam, 8, &px.x[i], &px.y[i], dirs);
             s += dirs[3].x();
           }
           return s;
         }));

  const QuadCases q = nearQuads(g, n);
  report("quad_setup", medianNs(repeats, long(n) * 100, [&](long calls) {
           double s = 0;
           for (long k = 0; k < calls; ++k) {
             const size_t i = size_t(k) % n;
             s += SphericalQuad(q.quads[i], q.from[i]).solidAngle;
           }
           return s;
         }));
  std::vector<SphericalQuad> set;
  for (size_t i = 0; i < n; ++i) set.emplace_back(q.quads[i], q.from[i]);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> u0(n), u1(n);
  for (size_t i = 0; i < n; ++i) u0[i] = u(g), u1[i] = u(g);
  report("quad_sample", medianNs(repeats, long(n) * 100, [&](long calls) {
           double s = 0;
           for (long k = 0; k < calls; ++k) {
             const size_t i = size_t(k) % n;
             if (set[i].solidAngle > 0) s += set[i].sample(u0[i], u1[i]).x();
           }
           return s;
         }));
  report("quad_point_scalar", medianNs(repeats, long(n) * 100, [&](long calls) {
           double s = 0;
           for (long k = 0; k < calls; ++k) {
             const size_t i = size_t(k) % n;
             const SphericalQuad sq(q.quads[i], q.from[i]);
             if (sq.solidAngle > 0) s += sq.sample(u0[i], u1[i]).x();
           }
           return s;
         }));
  if (cpuHasAvx2())
    report("quad_point_lanes", medianNs(repeats, long(n) * 100, [&](long calls) {
             double s = 0;
             QuadLanes lanes;
             for (long k = 0; k < calls; k += kQuadLanes) {
               for (int l = 0; l < kQuadLanes; ++l) {
                 const size_t i = size_t(k + l) % n;
                 for (int a = 0; a < 3; ++a) {
                   for (int c = 0; c < 4; ++c) lanes.corner[c][a][l] = q.quads[i][size_t(c)][a];
                   lanes.origin[a][l] = q.from[i][a];
                 }
                 lanes.u0[l] = u0[i], lanes.u1[l] = u1[i];
               }
               s += double(sphericalQuadLanesAvx2(lanes)) + lanes.y[0][1];
             }
             return s;
           }));
  // The packet's numbers: pairs 0 .. pairs - 1 of eight lanes, every number summed (none left out).
  auto samplerScalar = [&](int pairs) {
    return medianNs(repeats, 8L * 200000, [&, pairs](long calls) {
      double s = 0;
      for (long k = 0; k < calls / 8; ++k)
        for (uint32_t l = 0; l < 8; ++l) {
          const SampleRng rng(uint32_t(k % 512) * 8 + l, uint32_t(k / 512), 3, 7);
          const auto jitter = rng.get2(0);
          s += jitter[0] + jitter[1];
          if (pairs > 1)
            for (const auto& pair : rng.get2x4(1)) s += pair[0] + pair[1];
        }
      return s;
    });
  };
  auto samplerLanes = [&](int pairs) {
    return medianNs(repeats, 8L * 200000, [&, pairs](long calls) {
      double s = 0;
      SamplerLanes lanes;
      lanes.seed = 7, lanes.pairs = pairs, lanes.sobol1Reversed = &kSobol1Reversed.byByte[0][0];
      for (int p = 0; p < pairs; ++p) lanes.pairHash[p] = SampleRng::pairHash(uint32_t(p));
      for (long k = 0; k < calls / 8; ++k) {
        for (int l = 0; l < 8; ++l)
          lanes.x[l] = uint32_t(k % 512) * 8 + uint32_t(l), lanes.y[l] = uint32_t(k / 512),
          lanes.sample[l] = 3;
        samplerLanesAvx2(lanes);
        for (int p = 0; p < pairs; ++p)
          for (int l = 0; l < 8; ++l) s += lanes.u[p][0][l] + lanes.u[p][1][l];
      }
      return s;
    });
  };
  report("sampler_jitter_scalar", samplerScalar(1));
  if (cpuHasAvx2()) report("sampler_jitter_lanes", samplerLanes(1));
  report("sampler_vertex_scalar", samplerScalar(5));
  if (cpuHasAvx2()) report("sampler_vertex_lanes", samplerLanes(5));
  report("sincos_chain", medianNs(repeats, 5000000, [&](long calls) {
           double x = 0.1, sn = 0, cs = 0;
           for (long k = 0; k < calls; ++k) {
             sinCos(x, &sn, &cs);
             x = 0.5 + 0.25 * sn * cs + double(k) * 1e-7;
           }
           return x;
         }));
  return 0;
}
