// Renderer benchmarks on a ../shared room (a scene file from harness.py), CSV on stdout-chosen
// files in OUT_DIR; bench_render.py plots them and derives the summary figures.
//
// - convergence.csv: composite RMSE in the objects' region (pixels where a converged
//   reference composite differs from the photo) against render seconds, per material (diffuse,
//   glossy, mirror, glass, glowing), thread count (1, 2) and mode: correlated (one differential
//   render) or independent (the scene with objects and the empty room rendered separately,
//   other seeds).
// - throughput.csv: rays per second per thread by type (camera, bounce, shadow: each type's
//   count over the thread time spent tracing it, TracerOptions::timeRays), and all rays over
//   wall time, for camera rays alone (maxDepth 0) and full paths, 1 and 2 threads (medians of
//   5 renders at 160 x 120, 4 spp), with the wall-time overhead of the timing.
// - bvh.csv: object BVH build seconds, instance update (move) seconds (median of 50) and the
//   resident memory the tracer adds, for spheres of 10k to 1M triangles.
//
// - session.csv: the progressive session at the photo's resolution (the studio's settings:
//   focus on changes, all cores): per object move, the milliseconds until the first frame of
//   the new version reaches the sink, its resolution divider, and the ratio to a baseline
//   measured in the same process (one 1-spp full-resolution render of the frame), for start
//   dividers 8 and 16; 15 moves each, 150 ms apart (landing mid-wave).
//
// usage: bench_render SCENE.json OUT_DIR [WIDTH HEIGHT REF_SPP MAX_SPP [PARTS]]
//   PARTS: comma-separated subset of bvh,throughput,convergence,session (default: all)
#include "material_cases.h"

#include "inlay/engine/pipeline.h"
#include "inlay/modeling/image_io.h"
#include "inlay/render/composite.h"
#include "inlay/render/path_tracer.h"
#include "inlay/render/session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <unistd.h>

using namespace inlay;
using inlay::bench::MaterialCase;
using inlay::bench::materialCases;

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

double residentMb() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return double(resident) * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

ImageF compositeFrom(const ImageF& photo, const DifferentialBuffers& withBuf,
                     const DifferentialBuffers& withoutBuf, bool correlated) {
  return differentialComposite(photo, withBuf.meanWith(),
                               correlated ? withBuf.meanWithout() : withoutBuf.meanWith(),
                               withBuf.meanMask());
}

double regionRmse(const ImageF& a, const ImageF& b, const std::vector<size_t>& region) {
  double s = 0;
  for (size_t i : region)
    for (int c = 0; c < 3; ++c) {
      const double d = a.data[i * 3 + c] - b.data[i * 3 + c];
      s += d * d;
    }
  return std::sqrt(s / (3.0 * std::max<size_t>(1, region.size())));
}

void convergence(const RenderScene& base, const ImageF& photo, int w, int h, int refSpp, int maxSpp,
                 std::ofstream& csv) {
  for (const MaterialCase& mc : materialCases()) {
    RenderScene scene = base;
    for (auto& o : scene.objects) o.material = mc.material;
    RenderScene empty = scene;
    empty.objects.clear();
    PathTracer tracer(scene), emptyTracer(empty);
    DifferentialBuffers ref(w, h);
    tracer.render(ref, 1 << 20, refSpp, 999);
    const ImageF reference = compositeFrom(photo, ref, ref, true);
    std::vector<size_t> region;
    for (size_t i = 0; i < reference.pixelCount(); ++i) {
      double d = 0;
      for (int c = 0; c < 3; ++c)
        d = std::max(d, double(std::abs(reference.data[i * 3 + c] - photo.data[i * 3 + c])));
      if (d > 2e-3) region.push_back(i);
    }
    std::fprintf(stderr, "%s: region %zu px\n", mc.name, region.size());
    for (int threads : {1, 2})
      for (bool correlated : {true, false}) {
        DifferentialBuffers with(w, h), without(w, h);
        double seconds = 0;
        int spp = 0;
        for (int step = 1; spp < maxSpp; step = spp) {  // doubling: 1, 2, 4, ...
          const auto t0 = Clock::now();
          tracer.render(with, spp, step, correlated ? 1 : 2, threads);
          if (!correlated) emptyTracer.render(without, spp, step, 3, threads);
          seconds += secondsSince(t0);
          spp += step;
          const double e =
              regionRmse(compositeFrom(photo, with, without, correlated), reference, region);
          csv << mc.name << ',' << (correlated ? "correlated" : "independent") << ',' << threads << ','
              << spp << ',' << seconds << ',' << e << ',' << region.size() << '\n';
        }
        csv.flush();
      }
  }
}

// Rays per second per thread by type: each type's count over the thread time spent tracing it
// (TracerOptions::timeRays), the median of kRuns renders; plus all rays over wall time x
// threads, and the wall-time cost of the timing itself (timed / untimed render, medians).
void throughput(const RenderScene& scene, int w, int h, std::ofstream& csv) {
  constexpr int kRuns = 5;
  auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  auto perSecond = [](uint64_t n, int64_t ns) { return ns > 0 ? double(n) / (double(ns) * 1e-9) : 0.0; };
  for (int threads : {1, 2}) {
    for (int maxDepth : {0, 8}) {
      TracerOptions timed, untimed;
      timed.maxDepth = untimed.maxDepth = maxDepth;
      timed.timeRays = true;
      PathTracer tracer(scene, timed), plain(scene, untimed);
      DifferentialBuffers b(w, h);
      tracer.render(b, 0, 1, 7, threads);  // warm-up
      plain.render(b, 0, 1, 7, threads);
      std::vector<double> cam, bounce, shadow, all, wall, wallPlain;
      RayCounters n;
      for (int run = 0; run < kRuns; ++run) {
        const RayCounters c0 = tracer.stats().byType;
        auto t0 = Clock::now();
        tracer.render(b, 1 + 4 * run, 4, 7, threads);
        wall.push_back(secondsSince(t0));
        RayCounters c = tracer.stats().byType;
        c.cameraRays -= c0.cameraRays, c.bounceRays -= c0.bounceRays, c.shadowRays -= c0.shadowRays;
        c.cameraNs -= c0.cameraNs, c.bounceNs -= c0.bounceNs, c.shadowNs -= c0.shadowNs;
        cam.push_back(perSecond(c.cameraRays, c.cameraNs));
        bounce.push_back(perSecond(c.bounceRays, c.bounceNs));
        shadow.push_back(perSecond(c.shadowRays, c.shadowNs));
        n = c;
        t0 = Clock::now();
        plain.render(b, 1 + 4 * run, 4, 7, threads);
        wallPlain.push_back(secondsSince(t0));
        all.push_back(double(c.cameraRays + c.bounceRays + c.shadowRays) / wallPlain.back() / threads);
      }
      csv << threads << ',' << maxDepth << ',' << median(wallPlain) << ',' << n.cameraRays << ','
          << n.bounceRays << ',' << n.shadowRays << ',' << median(cam) << ',' << median(bounce) << ','
          << median(shadow) << ',' << median(all) << ',' << median(wall) / median(wallPlain) << '\n';
      csv.flush();
    }
  }
}

std::shared_ptr<TriangleMesh> sphere(int rings) {
  auto m = std::make_shared<TriangleMesh>();
  const int segments = 2 * rings;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j <= segments; ++j) {
      const double th = M_PI * i / rings, ph = 2 * M_PI * j / segments;
      const Vec3 n(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph));
      m->positions.push_back((0.3 * n).cast<float>());
      m->normals.push_back(n.cast<float>());
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

void bvh(const RenderScene& base, std::ofstream& csv) {
  for (int rings : {50, 158, 500}) {  // 4 rings^2 triangles: 10k, 100k, 1M
    RenderScene scene = base;
    const auto mesh = sphere(rings);
    const double meshMb =
        double(mesh->positions.size() * 2 * sizeof(Vec3f) + mesh->triangles.size() * 12) / (1 << 20);
    InsertedObject o = scene.objects.at(0);
    o.meshObject = mesh;
    scene.objects = {o};
    const double before = residentMb();
    const auto t0 = Clock::now();
    auto tracer = std::make_unique<PathTracer>(scene);
    const double build = secondsSince(t0);
    const double after = residentMb();
    std::vector<double> moves;
    for (int k = 0; k < 50; ++k) {
      Mat4 m = o.worldFromObject;
      m(0, 3) += 0.001 * (k + 1);
      const auto t1 = Clock::now();
      tracer->setObjectTransform(0, m);
      moves.push_back(secondsSince(t1));
    }
    std::nth_element(moves.begin(), moves.begin() + 25, moves.end());
    csv << mesh->triangles.size() << ',' << build << ',' << moves[25] << ',' << after - before << ','
        << meshMb << '\n';
    csv.flush();
  }
}

// Records when the first frame of each scene version arrives.
class FirstFrameSink : public FrameSink {
 public:
  void onFrame(std::shared_ptr<const RenderFrame> frame) override {
    std::lock_guard<std::mutex> lock(mutex_);
    first_.try_emplace(frame->sceneVersion, Clock::now(), frame->resolutionDivider);
  }
  bool firstOf(uint64_t version, Clock::time_point* at, int* divider) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = first_.find(version);
    if (it == first_.end()) return false;
    *at = it->second.first, *divider = it->second.second;
    return true;
  }

 private:
  std::mutex mutex_;
  std::map<uint64_t, std::pair<Clock::time_point, int>> first_;
};

void sessionLatency(const RenderScene& scene, std::ofstream& csv) {
  const int w = scene.camera.widthPx, h = scene.camera.heightPx;
  double baseline = 0;
  {
    PathTracer tracer(scene);
    DifferentialBuffers b(w, h);
    tracer.render(b, 0, 1, 5);  // warm-up
    std::vector<double> t;
    for (int k = 0; k < 3; ++k) {
      const auto t0 = Clock::now();
      tracer.render(b, 1 + k, 1, 5);
      t.push_back(secondsSince(t0) * 1e3);
    }
    std::sort(t.begin(), t.end());
    baseline = t[1];
  }
  for (int startDivider : {8, 16}) {
    FirstFrameSink sink;
    SessionOptions opt;
    opt.targetSpp = 1 << 20;
    opt.focusOnChanges = true;
    opt.startDivider = startDivider;
    RenderSession session(&sink, opt);
    session.setScene(scene);
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // long waves are running
    const Mat4 start = scene.objects.at(0).worldFromObject;
    for (int k = 0; k < 15; ++k) {
      Mat4 m = start;
      m(0, 3) += 0.02 * ((k % 5) - 2);
      const auto t0 = Clock::now();
      const uint64_t v = session.setObjectTransform(0, m);
      Clock::time_point at;
      int divider = 0;
      while (!sink.firstOf(v, &at, &divider) && secondsSince(t0) < 10)
        std::this_thread::sleep_for(std::chrono::microseconds(200));
      const double ms = std::chrono::duration<double, std::milli>(at - t0).count();
      csv << w << 'x' << h << ',' << startDivider << ',' << k << ',' << ms << ',' << divider << ','
          << baseline << ',' << ms / baseline << '\n';
      std::this_thread::sleep_for(std::chrono::milliseconds(150));
    }
    csv.flush();
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: bench_render SCENE.json OUT_DIR [WIDTH HEIGHT REF_SPP MAX_SPP]\n");
    return 2;
  }
  const std::string out = argv[2];
  const int w = argc > 4 ? std::atoi(argv[3]) : 96, h = argc > 4 ? std::atoi(argv[4]) : 72;
  const int refSpp = argc > 5 ? std::atoi(argv[5]) : 256, maxSpp = argc > 6 ? std::atoi(argv[6]) : 64;
  const std::string parts = argc > 7 ? argv[7] : "bvh,throughput,convergence,session";
  auto wanted = [&](const char* part) { return parts.find(part) != std::string::npos; };
  auto loaded = loadSceneFile(argv[1]);
  if (!loaded) return std::fprintf(stderr, "%s\n", loaded.error().message().c_str()), 2;
  auto prepared = prepareScene(loaded->doc);
  if (!prepared) return std::fprintf(stderr, "%s\n", prepared.error().message().c_str()), 2;
  if (prepared->renderScene.objects.empty()) return std::fprintf(stderr, "the scene has no object\n"), 2;
  const ImageF photo = resizeImage(prepared->photo.linearRgb, w, h);

  if (wanted("bvh")) {
    std::ofstream csv(out + "/bvh.csv");
    csv << "triangles,build_s,move_s,tracer_rss_mb,mesh_mb\n";
    bvh(prepared->renderScene, csv);
  }
  if (wanted("throughput")) {
    std::ofstream csv(out + "/throughput.csv");
    csv << "threads,max_depth,seconds,camera_rays,bounce_rays,shadow_rays,camera_per_s_per_thread,"
           "bounce_per_s_per_thread,shadow_per_s_per_thread,rays_per_s_per_thread,timing_overhead\n";
    throughput(prepared->renderScene, 160, 120, csv);
  }
  if (wanted("session")) {
    std::ofstream csv(out + "/session.csv");
    csv << "frame,start_divider,edit,first_frame_ms,first_frame_divider,baseline_1spp_ms,ratio_to_baseline\n";
    sessionLatency(prepared->renderScene, csv);
  }
  if (wanted("convergence")) {
    std::ofstream csv(out + "/convergence.csv");
    if (!csv) return std::fprintf(stderr, "%s: cannot write\n", out.c_str()), 2;
    csv << "material,mode,threads,spp,seconds,rmse,region_px\n";
    convergence(prepared->renderScene, photo, w, h, refSpp, maxSpp, csv);
  }
  return 0;
}
