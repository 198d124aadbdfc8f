// The renderer's ray rate against a bare Embree loop casting the same rays, in one process, on a
// prepared scene (the bundled example by default) at the photo's full resolution.
//
// - types.csv: rays per second per thread by type (camera, bounce, shadow). The renderer's
//   figure charges every CPU second of a one-sample frame (PathTracer::renderRect on the calling
//   thread, thread CPU time, median of REPEATS) to one type:
//     camera: a frame with maxDepth 0 (camera rays and their first hit only), per camera ray;
//     shadow: next-event estimation as a whole (light pick, point on the light, BSDF evaluation,
//             shadow rays; RayCounters::neeNs as a share of a frame that reads the clock around
//             NEE only, TracerOptions::timeNee, applied to the untimed frame's CPU time; the
//             share in a frame that also times every ray, timeRays, as the passes before the
//             seventh measured it, is printed too: its two clock reads per shadow ray fall
//             inside NEE and overstate it);
//     bounce: the rest of the full frame (its camera rays at the camera rate, and NEE, taken off).
//   The bare loop casts the very rays the frame cast (TracerOptions::rayLog), each type on its
//   own, as the renderer cast them (rtcIntersect8 for its camera packets, rtcIntersect1 /
//   rtcOccluded1 for the rest; the single-ray figure of every type is printed too) into scenes
//   built here from the same RenderScene (room
//   surfaces, light quads, one instanced BVH per object; the sun scenes without box walls and
//   emitters), nothing else in the loop.
// - triangles.csv: CPU milliseconds per sample of the full frame, and of its rays in the bare
//   loop, with the example's object replaced by a sphere of 10k to 1M triangles.
// - lights.csv: the same against the number of lights: the first light cut into 1 to 64 strips
//   (the same light in total), the others removed.
//
// - waves.csv: one sample in every pixel as the session's focused waves rendered it before
//   (renderRect per pixel), as they do now (PathTracer::renderCounts, tile by tile) and as a
//   uniform wave: CPU seconds on one thread, wall seconds on two.
//
// usage: bench_throughput SCENE.json OUT_DIR [--parts types,waves,triangles,lights] [--repeats N]
#include "inlay/engine/pipeline.h"
#include "inlay/render/path_tracer.h"

#include <embree3/rtcore.h>
#include <pmmintrin.h>
#include <xmmintrin.h>

#include <algorithm>
#include <atomic>
#include <functional>
#include <thread>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

using namespace inlay;

namespace {

double threadSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

// ---- the bare Embree loop -------------------------------------------------------------------

void attachMesh(RTCDevice device, RTCScene scene, const std::vector<Vec3f>& positions,
                const std::vector<std::array<uint32_t, 3>>& triangles) {
  if (positions.empty() || triangles.empty()) return;
  RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                        3 * sizeof(float), positions.size()));
  for (size_t i = 0; i < positions.size(); ++i)
    for (int k = 0; k < 3; ++k) v[3 * i + size_t(k)] = positions[i].allFinite() ? positions[i][k] : 0.f;
  auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles.size()));
  for (size_t i = 0; i < triangles.size(); ++i)
    for (int k = 0; k < 3; ++k)
      idx[3 * i + size_t(k)] = triangles[i][size_t(k)] < positions.size() ? triangles[i][size_t(k)] : 0;
  rtcCommitGeometry(g);
  rtcAttachGeometry(scene, g);
  rtcReleaseGeometry(g);
}

// The scenes a RenderScene makes, built the plain way.
class BareScenes {
 public:
  explicit BareScenes(const RenderScene& scene) : device_(rtcNewDevice(nullptr)) {
    for (int t = 0; t < 4; ++t) targets_[t] = rtcNewScene(device_);
    for (const Surface& s : scene.room.surfaces) {
      const int last = isBoxSurface(s.kind) ? 1 : 3;  // sun scenes: what stands inside the room
      for (int t = 0; t <= last; ++t)
        attachMesh(device_, targets_[t], s.meshWorld.positions, s.meshWorld.triangles);
    }
    for (const AreaLight& l : scene.lights) {
      std::vector<Vec3f> quad;
      for (const Vec3& c : l.cornersWorld) quad.push_back(c.cast<float>());
      for (int t = 0; t < 2; ++t) attachMesh(device_, targets_[t], quad, {{0, 1, 2}, {0, 2, 3}});
    }
    for (const InsertedObject& o : scene.objects) {
      if (!o.meshObject || o.meshObject->empty()) continue;
      RTCScene s = rtcNewScene(device_);
      rtcSetSceneBuildQuality(s, RTC_BUILD_QUALITY_HIGH);
      attachMesh(device_, s, o.meshObject->positions, o.meshObject->triangles);
      rtcCommitScene(s);
      objects_.push_back(s);
      float m[12];
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 3; ++r) m[c * 3 + r] = float(o.worldFromObject(r, c));
      for (int t : {0, 2}) {  // With, SunWith
        RTCGeometry inst = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(inst, s);
        rtcSetGeometryTransform(inst, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, m);
        rtcCommitGeometry(inst);
        rtcAttachGeometry(targets_[t], inst);
        rtcReleaseGeometry(inst);
      }
    }
    for (RTCScene s : targets_) rtcCommitScene(s);
  }
  ~BareScenes() {
    for (RTCScene s : targets_) rtcReleaseScene(s);
    for (RTCScene s : objects_) rtcReleaseScene(s);
    rtcReleaseDevice(device_);
  }
  BareScenes(const BareScenes&) = delete;
  BareScenes& operator=(const BareScenes&) = delete;

  // Casts the logged rays of `type`; thread CPU seconds, and their count into *count. As cast:
  // camera rays into the scene with the objects go in packets of 8 as the renderer casts them
  // (8 pixels of a row, logged one after the other: exact for a frame whose width is a multiple
  // of 8), the rest one by one; otherwise every ray alone (rtcIntersect1 / rtcOccluded1).
  double cast(const std::vector<LoggedRay>& rays, LoggedRay::Type type, bool asCast,
              size_t* count) const {
    const unsigned csr = _mm_getcsr();
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    size_t n = 0;
    unsigned hits = 0;
    const double t0 = threadSeconds();
    for (size_t i = 0; i < rays.size(); ++i) {
      const LoggedRay& r = rays[i];
      if (r.type != type) continue;
      const int run = asCast ? cameraRun(rays, i) : 1;
      if (run > 1) {
        hits += castPacket(&r, run);
        n += size_t(run), i += size_t(run) - 1;
      } else {
        hits += castOne(r);
        ++n;
      }
    }
    const double seconds = threadSeconds() - t0;
    _mm_setcsr(csr);
    *count = n;
    sink_ += hits;
    return seconds;
  }

 private:
  // How many camera rays into the scene with the objects follow one another from rays[i] (at
  // most 8; 0 or 1: cast alone).
  static int cameraRun(const std::vector<LoggedRay>& rays, size_t i) {
    int n = 0;
    while (n < 8 && i + size_t(n) < rays.size() && rays[i + size_t(n)].type == LoggedRay::Type::Camera &&
           rays[i + size_t(n)].target == LoggedRay::Target::With)
      ++n;
    return n;
  }
  unsigned castOne(const LoggedRay& r) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRayHit rh;
    rh.ray.org_x = r.org[0], rh.ray.org_y = r.org[1], rh.ray.org_z = r.org[2];
    rh.ray.dir_x = r.dir[0], rh.ray.dir_y = r.dir[1], rh.ray.dir_z = r.dir[2];
    rh.ray.tnear = r.tnear, rh.ray.tfar = r.tfar;
    rh.ray.time = 0, rh.ray.mask = 0xFFFFFFFFu, rh.ray.id = 0, rh.ray.flags = 0;
    RTCScene s = targets_[int(r.target)];
    if (r.type == LoggedRay::Type::Shadow) {
      rtcOccluded1(s, &ctx, &rh.ray);
      return rh.ray.tfar < 0;
    }
    rh.hit.geomID = rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(s, &ctx, &rh);
    return rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
  }
  // Rays r[0 .. n-1] (n <= 8, one target, closest hits) in one rtcIntersect8.
  unsigned castPacket(const LoggedRay* r, int n) const {
    alignas(32) RTCRayHit8 rh;
    alignas(32) int valid[8];
    for (int k = 0; k < 8; ++k) {
      const LoggedRay& q = r[std::min(k, n - 1)];
      valid[k] = k < n ? -1 : 0;
      rh.ray.org_x[k] = q.org[0], rh.ray.org_y[k] = q.org[1], rh.ray.org_z[k] = q.org[2];
      rh.ray.dir_x[k] = q.dir[0], rh.ray.dir_y[k] = q.dir[1], rh.ray.dir_z[k] = q.dir[2];
      rh.ray.tnear[k] = q.tnear, rh.ray.tfar[k] = q.tfar;
      rh.ray.time[k] = 0, rh.ray.mask[k] = 0xFFFFFFFFu, rh.ray.id[k] = 0, rh.ray.flags[k] = 0;
      rh.hit.geomID[k] = rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
    }
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcIntersect8(valid, targets_[int(r[0].target)], &ctx, &rh);
    unsigned hits = 0;
    for (int k = 0; k < n; ++k) hits += rh.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID;
    return hits;
  }

  RTCDevice device_;
  RTCScene targets_[4] = {};  // indexed by LoggedRay::Target
  std::vector<RTCScene> objects_;
  mutable unsigned sink_ = 0;
};

// ---- the renderer ---------------------------------------------------------------------------

struct Frame {
  double cpuSeconds = 0;  // median over the repeats
  RayCounters rays;       // of one frame
  double neeShare = 0;    // NEE's share of the frame's time (timed frames only)
  uint64_t checksum = 0;  // FNV-1a of one frame's sums (a change that keeps every bit keeps it)
};

uint64_t checksumOf(const DifferentialBuffers& b) {
  uint64_t h = 1469598103934665603ull;
  for (const ImageF* im : {&b.sumWith, &b.sumWithout, &b.sumMask, &b.sumChange})
    for (float f : im->data) {
      uint32_t bits = 0;
      std::memcpy(&bits, &f, 4);
      h = (h ^ bits) * 1099511628211ull;
    }
  return h;
}

// One-sample frames of `scene` on the calling thread (the same sample each time: the same rays).
Frame renderFrames(const RenderScene& scene, TracerOptions opt, int repeats) {
  PathTracer tracer(scene, opt);
  const int w = scene.camera.widthPx, h = scene.camera.heightPx;
  DifferentialBuffers b(w, h);
  std::vector<double> cpu, share;
  Frame f;
  for (int r = 0; r < repeats; ++r) {
    const RayCounters c0 = tracer.stats().byType;
    const auto wall0 = std::chrono::steady_clock::now();
    const double t0 = threadSeconds();
    tracer.renderRect(b, 0, 0, w, h, 0, 1, 7);
    cpu.push_back(threadSeconds() - t0);
    if (r == 0) f.checksum = checksumOf(b);
    const double wallNs =
        std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - wall0).count();
    const RayCounters c1 = tracer.stats().byType;
    f.rays.cameraRays = c1.cameraRays - c0.cameraRays;
    f.rays.bounceRays = c1.bounceRays - c0.bounceRays;
    f.rays.shadowRays = c1.shadowRays - c0.shadowRays;
    share.push_back(double(c1.neeNs - c0.neeNs) / wallNs);
  }
  f.cpuSeconds = median(cpu);
  f.neeShare = median(share);
  return f;
}

std::vector<LoggedRay> logRays(const RenderScene& scene, TracerOptions opt) {
  RayLog log;
  opt.rayLog = &log;
  PathTracer tracer(scene, opt);
  DifferentialBuffers b(scene.camera.widthPx, scene.camera.heightPx);
  tracer.renderRect(b, 0, 0, b.width, b.height, 0, 1, 7);
  return std::move(log.rays);
}

double bareSeconds(const BareScenes& bare, const std::vector<LoggedRay>& rays, LoggedRay::Type type,
                   int repeats, size_t* count, bool asCast = true) {
  std::vector<double> t;
  t.reserve(size_t(std::max(0, repeats)));
  for (int r = 0; r < repeats; ++r) t.push_back(bare.cast(rays, type, asCast, count));
  return median(t);
}

void types(const RenderScene& scene, int repeats, std::ofstream& csv) {
  TracerOptions camOnly;
  camOnly.maxDepth = 0;
  TracerOptions timed, neeTimed;
  timed.timeRays = true;
  neeTimed.timeNee = true;
  const Frame cam = renderFrames(scene, camOnly, repeats);
  const Frame full = renderFrames(scene, {}, repeats);
  const Frame fullTimed = renderFrames(scene, timed, repeats);
  const Frame fullNeeTimed = renderFrames(scene, neeTimed, repeats);
  const double perCamera = cam.cpuSeconds / double(std::max<uint64_t>(1, cam.rays.cameraRays));
  const double neeSeconds = fullNeeTimed.neeShare * full.cpuSeconds;
  const double bounceSeconds = full.cpuSeconds - neeSeconds - perCamera * double(full.rays.cameraRays);
  const BareScenes bare(scene);
  const std::vector<LoggedRay> rays = logRays(scene, {});
  const std::vector<LoggedRay> camRays = logRays(scene, camOnly);
  struct Row {
    const char* name;
    LoggedRay::Type type;
    uint64_t count;
    double seconds;
    const std::vector<LoggedRay>* rays;
  };
  const Row rows[] = {{"camera", LoggedRay::Type::Camera, cam.rays.cameraRays, cam.cpuSeconds, &camRays},
                      {"bounce", LoggedRay::Type::Bounce, full.rays.bounceRays, bounceSeconds, &rays},
                      {"shadow", LoggedRay::Type::Shadow, full.rays.shadowRays, neeSeconds, &rays}};
  double bareRate[3] = {0, 0, 0};
  for (const Row& r : rows) {
    size_t n = 0;
    const double bareS = bareSeconds(bare, *r.rays, r.type, repeats, &n);
    if (n != r.count)
      std::fprintf(stderr, "warning: %s: %zu rays logged, %llu counted\n", r.name, n,
                   static_cast<unsigned long long>(r.count));
    const double single = double(n) / bareSeconds(bare, *r.rays, r.type, repeats, &n, false);
    const double ours = double(r.count) / r.seconds, plain = double(n) / bareS;
    bareRate[&r - rows] = plain;
    csv << r.name << ',' << r.count << ',' << ours << ',' << plain << ',' << ours / plain << ','
        << single << ',' << ours / single << '\n';
    std::printf(
        "%-7s %9llu rays  renderer %6.2f M/s/thread  bare Embree %6.2f M/s/thread  ratio %.3f"
        "  (bare one ray at a time %6.2f, ratio %.3f)\n",
        r.name, static_cast<unsigned long long>(r.count), ours * 1e-6, plain * 1e-6, ours / plain,
        single * 1e-6, ours / single);
  }
  std::printf(
      "frame: %.3f s CPU (maxDepth 0: %.3f s), NEE %.1f %% of it, timing overhead %.1f %%, checksum %016llx\n",
      full.cpuSeconds, cam.cpuSeconds, 100 * fullNeeTimed.neeShare,
      100 * (fullNeeTimed.cpuSeconds / full.cpuSeconds - 1),
      static_cast<unsigned long long>(full.checksum));
  // The passes before the seventh took NEE's share from the frame that times every ray too.
  const double perRayNee = fullTimed.neeShare * full.cpuSeconds;
  const double perRayBounce = full.cpuSeconds - perRayNee - perCamera * double(full.rays.cameraRays);
  std::printf(
      "with every ray timed: NEE %.1f %%, timing overhead %.1f %%, ratios bounce %.3f shadow %.3f\n",
      100 * fullTimed.neeShare, 100 * (fullTimed.cpuSeconds / full.cpuSeconds - 1),
      double(full.rays.bounceRays) / perRayBounce / bareRate[1],
      double(full.rays.shadowRays) / perRayNee / bareRate[2]);
  csv.flush();
}

// A sphere of 4 rings^2 triangles with the radius `radius`, centred on the origin.
std::shared_ptr<TriangleMesh> sphere(int rings, float radius, const Vec3f& centre) {
  auto m = std::make_shared<TriangleMesh>();
  const int segments = 2 * rings;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j <= segments; ++j) {
      const double th = M_PI * i / rings, ph = 2 * M_PI * j / segments;
      const Vec3f n =
          Vec3(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph)).cast<float>();
      m->positions.push_back(centre + radius * n);
      m->normals.push_back(n);
    }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const uint32_t a = uint32_t(i * (segments + 1) + j), b = a + 1, c = a + uint32_t(segments + 1),
                     d = c + 1;
      m->triangles.push_back({a, b, c});
      m->triangles.push_back({b, d, c});
    }
  return m;
}

// CPU ms per sample of the full frame and of its rays in the bare loop.
void perSample(const RenderScene& scene, int repeats, double* renderMs, double* bareMs) {
  const Frame f = renderFrames(scene, {}, repeats);
  const std::vector<LoggedRay> rays = logRays(scene, {});
  const BareScenes bare(scene);
  double bareS = 0;
  for (LoggedRay::Type t : {LoggedRay::Type::Camera, LoggedRay::Type::Bounce, LoggedRay::Type::Shadow}) {
    size_t n = 0;
    bareS += bareSeconds(bare, rays, t, repeats, &n);
  }
  *renderMs = 1e3 * f.cpuSeconds;
  *bareMs = 1e3 * bareS;
}

void triangles(const RenderScene& base, int repeats, std::ofstream& csv) {
  const TriangleMesh& original = *base.objects.at(0).meshObject;
  Vec3f lo = Vec3f::Constant(1e30f), hi = Vec3f::Constant(-1e30f);
  for (const Vec3f& p : original.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  for (int rings : {50, 158, 500}) {  // 10k, 100k, 1M triangles
    RenderScene scene = base;
    scene.objects.resize(1);
    scene.objects[0].meshObject = sphere(rings, 0.5f * (hi - lo).maxCoeff(), 0.5f * (lo + hi));
    double ms = 0, bareMs = 0;
    perSample(scene, repeats, &ms, &bareMs);
    const size_t n = scene.objects[0].meshObject->triangles.size();
    csv << n << ',' << ms << ',' << bareMs << '\n';
    std::printf("%8zu triangles  %8.1f ms/spp  bare %7.1f ms/spp\n", n, ms, bareMs);
    std::fflush(stdout);
  }
}

// The first light cut into `n` strips along its first edge (the same light in total).
std::vector<AreaLight> strips(const AreaLight& l, int n) {
  std::vector<AreaLight> out;
  const auto& c = l.cornersWorld;
  for (int k = 0; k < n; ++k) {
    const double a = double(k) / n, b = double(k + 1) / n;
    AreaLight s = l;
    s.cornersWorld = {c[0] + a * (c[1] - c[0]), c[0] + b * (c[1] - c[0]), c[3] + b * (c[2] - c[3]),
                      c[3] + a * (c[2] - c[3])};
    out.push_back(s);
  }
  return out;
}

void lights(const RenderScene& base, int repeats, std::ofstream& csv) {
  for (int n : {1, 2, 4, 8, 16, 32, 64}) {
    RenderScene scene = base;
    scene.lights = strips(base.lights.at(0), n);
    double ms = 0, bareMs = 0;
    perSample(scene, repeats, &ms, &bareMs);
    csv << n << ',' << ms << ',' << bareMs << '\n';
    std::printf("%3d lights  %8.1f ms/spp  bare %7.1f ms/spp\n", n, ms, bareMs);
    std::fflush(stdout);
  }
}

// The old focused wave on `threads` threads: 16 x 16 tiles taken in turn, one renderRect per
// pixel.
void pixelByPixelWave(const PathTracer& tracer, DifferentialBuffers& b, int threads) {
  const int tilesX = (b.width + 15) / 16, tiles = tilesX * ((b.height + 15) / 16);
  std::atomic<int> next{0};
  auto work = [&] {
    for (int t; (t = next.fetch_add(1)) < tiles;) {
      const int x0 = (t % tilesX) * 16, y0 = (t / tilesX) * 16;
      for (int y = y0; y < std::min(b.height, y0 + 16); ++y)
        for (int x = x0; x < std::min(b.width, x0 + 16); ++x)
          tracer.renderRect(b, x, y, x + 1, y + 1, b.samples[size_t(y) * b.width + x], 1, 7);
    }
  };
  std::vector<std::thread> pool;
  for (int k = 1; k < threads; ++k) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
}

// The session's focused and adaptive waves: one sample in every pixel as the waves used to
// render it (renderRect per pixel), as renderCounts() renders it (tile by tile) and as a uniform
// wave (render()): CPU seconds of the calling thread (one thread) and wall seconds on `threads`.
void waves(const RenderScene& scene, int repeats, int threads, std::ofstream& csv) {
  PathTracer tracer(scene);
  const int w = scene.camera.widthPx, h = scene.camera.heightPx;
  DifferentialBuffers b(w, h);
  const std::vector<int> ones(size_t(w) * h, 1);
  auto perPixel = [&](int t) { pixelByPixelWave(tracer, b, t); };
  auto tiles = [&](int t) { tracer.renderCounts(b, ones, 7, t); };
  auto uniform = [&](int t) { tracer.render(b, b.samples[0], 1, 7, t); };
  const std::pair<const char*, std::function<void(int)>> ways[] = {
      {"pixel_by_pixel", perPixel}, {"tiles", tiles}, {"uniform", uniform}};
  for (const auto& [name, run] : ways) {
    std::vector<double> cpu, wall;
    for (int r = 0; r < repeats; ++r) {
      const double t0 = threadSeconds();
      run(1);
      cpu.push_back(threadSeconds() - t0);
      const auto w0 = std::chrono::steady_clock::now();
      run(threads);
      wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count());
    }
    csv << name << ',' << median(cpu) << ',' << threads << ',' << median(wall) << '\n';
    std::printf("wave %-15s %.3f s CPU (1 thread)  %.3f s wall (%d threads)\n", name, median(cpu),
                median(wall), threads);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(
        stderr,
        "usage: bench_throughput SCENE.json OUT_DIR [--parts types,triangles,lights] [--repeats N]\n");
    return 2;
  }
  const std::string out = argv[2];
  std::string parts = "types,waves,triangles,lights";
  int repeats = 3;
  for (int i = 3; i + 1 < argc; i += 2) {
    if (std::string(argv[i]) == "--parts") parts = argv[i + 1];
    else if (std::string(argv[i]) == "--repeats") repeats = std::max(1, std::atoi(argv[i + 1]));
    else return std::fprintf(stderr, "bench_throughput: unknown option %s\n", argv[i]), 2;
  }
  auto loaded = loadSceneFile(argv[1]);
  if (!loaded) return std::fprintf(stderr, "%s\n", loaded.error().message().c_str()), 2;
  auto prepared = prepareScene(loaded->doc);
  if (!prepared) return std::fprintf(stderr, "%s\n", prepared.error().message().c_str()), 2;
  const RenderScene& scene = prepared->renderScene;
  if (scene.objects.empty() || !scene.objects[0].meshObject || scene.lights.empty())
    return std::fprintf(stderr, "%s: the scene needs an object and a light\n", argv[1]), 2;
  std::printf("%s: %d x %d, %zu lights, %zu objects\n", argv[1], scene.camera.widthPx,
              scene.camera.heightPx, scene.lights.size(), scene.objects.size());
  auto open = [&](const char* name, const char* header) {
    std::ofstream csv(out + "/" + name);
    if (!csv)
      std::fprintf(stderr, "bench_throughput: %s/%s cannot be written\n", out.c_str(), name),
          std::exit(2);
    csv << header << '\n';
    return csv;
  };
  if (parts.find("types") != std::string::npos) {
    auto csv = open("types.csv",
                    "type,rays,renderer_per_s_per_thread,bare_per_s_per_thread,ratio,"
                    "bare_single_per_s_per_thread,ratio_single");
    types(scene, repeats, csv);
  }
  if (parts.find("waves") != std::string::npos) {
    auto csv = open("waves.csv", "wave,cpu_s_1_thread,threads,wall_s");
    waves(scene, repeats, 2, csv);
  }
  if (parts.find("triangles") != std::string::npos) {
    auto csv = open("triangles.csv", "triangles,ms_per_spp,bare_ms_per_spp");
    triangles(scene, repeats, csv);
  }
  if (parts.find("lights") != std::string::npos) {
    auto csv = open("lights.csv", "lights,ms_per_spp,bare_ms_per_spp");
    lights(scene, repeats, csv);
  }
  return 0;
}
