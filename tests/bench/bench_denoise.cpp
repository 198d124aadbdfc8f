// The denoiser's benchmark (bench_denoise.py plots it): on a prepared scene at W x H, per object
// material (diffuse, glossy, mirror, glass, glowing), the composite's RMSE against a converged
// reference of the same prepared scene (REF_SPP samples, another seed), raw and denoised, as the
// samples double from 1 to MAX_SPP on THREADS threads; and the filter's own time.
//
// - convergence.csv: material, mode (raw | denoised | opencv_guided: ximgproc's guided filter
//   as a baseline, opencvGuidedWith), spp, seconds (render wall time so far;
//   the denoised rows add that frame's filter time), cpu_seconds_per_thread (the same in process
//   CPU time over THREADS: what it would take on idle cores, robust on a shared machine),
//   object_rmse (pixels the reference mask covers
//   more than half), surroundings_rmse (pixels outside the object where the reference composite
//   differs from the photo by more than 2e-3: shadow and bounce light), their pixel counts.
// - timing.csv: per material, the camera-ray guides' milliseconds (renderDenoiseGuides, one ray
//   per pixel, what the session used to pay once per scene version; for comparison), the
//   median milliseconds of reading the render's own guides out of the buffers (per frame,
//   included in the denoised rows' time) and the filter's (median of 7 runs on the 4-spp frame) at W x H on THREADS threads,
//   wall and process CPU time over THREADS,
//   the baseline's (baselineMs, interleaved with the filter's runs: the ratio is robust to load),
//   and the reference's own estimated RMSE on the object and the surroundings (linear, from its
//   per-pixel variance): the floor under the curves.
//
// RMSE is over linear RGB of the composite, clamped to [0, 1] (what a display shows).
//
// usage: bench_denoise SCENE.json OUT_DIR WIDTH HEIGHT REF_SPP MAX_SPP THREADS [MATERIALS]
//   MATERIALS: comma-separated subset of diffuse,glossy,mirror,glass,glowing (default: all)
#include "material_cases.h"

#include "inlay/engine/pipeline.h"
#include "inlay/modeling/image_io.h"
#include "inlay/render/composite.h"
#include "inlay/render/denoise.h"
#include "inlay/render/path_tracer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <opencv2/core.hpp>
#include <opencv2/ximgproc/edge_filter.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>
#include <ctime>
#include <fstream>

using namespace inlay;
using inlay::bench::MaterialCase;
using inlay::bench::materialCases;

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// CPU seconds of the whole process (all threads): on a shared machine, what the work costs.
double processCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// The timing baseline, in the same process on the same threads: the filter's data flow without
// its edge stops (five levels of a 3 x 3 binomial blur of the three delta planes and the
// variance, rows in parallel). filter_ms / baseline_ms is comparable between loaded and idle runs.
double baselineMs(int w, int h, int threads) {
  const size_t n = size_t(w) * h;
  std::vector<std::vector<float>> in(4, std::vector<float>(n, 0.5f)), out = in;
  tbb::task_arena arena(threads > 0 ? threads : int(tbb::task_arena::automatic));
  const auto t0 = Clock::now();
  for (int level = 0; level < 5; ++level) {
    const int step = 1 << level;
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<int>(0, h, 8), [&](const tbb::blocked_range<int>& r) {
        for (int y = r.begin(); y < r.end(); ++y)
          for (size_t p = 0; p < in.size(); ++p) {
            float* o = out[p].data() + size_t(y) * w;
            for (int x = 0; x < w; ++x) {
              float sum = 0, ws = 0;
              for (int dy = -1; dy <= 1; ++dy) {
                const int yy = y + dy * step;
                if (yy < 0 || yy >= h) continue;
                const float* row = in[p].data() + size_t(yy) * w;
                for (int dx = -1; dx <= 1; ++dx) {
                  const int xx = x + dx * step;
                  if (xx < 0 || xx >= w) continue;
                  const float k = (dx ? 0.5f : 1.f) * (dy ? 0.5f : 1.f);
                  sum += k * row[xx], ws += k;
                }
              }
              o[x] = sum / ws;
            }
          }
      });
    });
    std::swap(in, out);
  }
  return secondsSince(t0) * 1e3 + 0.0 * in[0][0];
}

double rmse(const ImageF& a, const ImageF& b, const std::vector<size_t>& region) {
  double s = 0;
  for (size_t i : region)
    for (int c = 0; c < 3; ++c) {
      const double d = std::clamp(a.data[i * 3 + c], 0.f, 1.f) - std::clamp(b.data[i * 3 + c], 0.f, 1.f);
      s += d * d;
    }
  return std::sqrt(s / (3.0 * double(std::max<size_t>(1, region.size()))));
}

ImageF denoisedWith(const DifferentialBuffers& b, const ImageF& with, const ImageF& without,
                    const ImageF& mask, const DenoiseGuides& g, int threads) {
  DenoiseInput in;
  in.withObjects = &with, in.withoutObjects = &without, in.mask = &mask, in.buffers = &b, in.guides = &g;
  DenoiseOptions o;
  o.threads = threads;
  return denoiseWithObjects(in, o);
}

// The baseline OpenCV offers (ximgproc's guided filter, He et al.): the same delta X filtered
// with a three-channel guide (the first hit's mean albedo, the mask, the normal's y: floor
// against walls), radius 5, eps 1e-3, no noise level and no clamp; written back as our filter's.
ImageF opencvGuidedWith(const ImageF& with, const ImageF& without, const ImageF& mask,
                        const DenoiseGuides& g) {
  const int w = with.width, h = with.height;
  cv::Mat guide(h, w, CV_32FC3), src(h, w, CV_32FC3), dst;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      const float m = std::clamp(mask.data[i], 0.f, 1.f);
      guide.at<cv::Vec3f>(y, x) =
          cv::Vec3f((g.albedo[0][i] + g.albedo[1][i] + g.albedo[2][i]) / 3.f, m, g.normal[1][i]);
      for (int c = 0; c < 3; ++c)
        src.at<cv::Vec3f>(y, x)[c] = with.data[i * 3 + c] - (1.f - m) * without.data[i * 3 + c];
    }
  cv::ximgproc::guidedFilter(guide, src, dst, 5, 1e-3);
  ImageF out = with;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      const float m = std::clamp(mask.data[i], 0.f, 1.f);
      for (int c = 0; c < 3; ++c)
        out.data[i * 3 + c] = dst.at<cv::Vec3f>(y, x)[c] + (1.f - m) * without.data[i * 3 + c];
    }
  return out;
}

void runCase(const MaterialCase& mc, const RenderScene& base, const ImageF& photo, int w, int h,
             int refSpp, int maxSpp, int threads, std::ofstream& csv, std::ofstream& timing) {
  RenderScene scene = base;
  for (auto& o : scene.objects) o.material = mc.material, o.partMaterials.clear();
  PathTracer tracer(scene);
  DifferentialBuffers ref(w, h);
  tracer.render(ref, 1 << 20, refSpp, 999, threads);
  const ImageF refMask = ref.meanMask();
  const ImageF reference = differentialComposite(photo, ref.meanWith(), ref.meanWithout(), refMask);
  std::vector<size_t> object, around;
  for (size_t i = 0; i < reference.pixelCount(); ++i) {
    double d = 0;
    for (int c = 0; c < 3; ++c)
      d = std::max(d, double(std::abs(reference.data[i * 3 + c] - photo.data[i * 3 + c])));
    if (refMask.data[i] > 0.5f) object.push_back(i);
    else if (refMask.data[i] == 0 && d > 2e-3) around.push_back(i);
  }
  // The reference's own estimated error (its per-pixel variance of the mean change): the floor
  // under every curve measured against it.
  auto refError = [&](const std::vector<size_t>& region) {
    double sum = 0;
    for (size_t i : region) {
      const int n = std::max(1, ref.samples[i]);
      double meanSq = 0;
      for (int c = 0; c < 3; ++c) meanSq += std::pow(double(ref.sumChange.data[i * 3 + c]) / n, 2) / 3.0;
      sum += std::max(0.0, double(ref.sumChangeSq.data[i]) / n - meanSq) / std::max(1, n - 1);
    }
    return std::sqrt(sum / double(std::max<size_t>(1, region.size())));
  };
  auto t0 = Clock::now();
  (void)renderDenoiseGuides(tracer, w, h, threads);  // the camera-ray guides, timed for comparison
  const double rayGuidesMs = secondsSince(t0) * 1e3;
  DifferentialBuffers b(w, h);
  b.enableGuides();  // the guides come from the render's own paths
  std::vector<double> guidesMs;
  double seconds = 0, cpu = 0;
  std::vector<double> filterMs, filterCpuMs, baseMs;
  for (int spp = 0, step = 1; spp < maxSpp; step = spp) {
    t0 = Clock::now();
    double c0 = processCpuSeconds();
    tracer.render(b, spp, step, 1, threads);
    seconds += secondsSince(t0);
    cpu += (processCpuSeconds() - c0) / std::max(1, threads);
    spp += step;
    const ImageF with = b.meanWith(), without = b.meanWithout(), mask = b.meanMask();
    const ImageF raw = differentialComposite(photo, with, without, mask);
    t0 = Clock::now();
    c0 = processCpuSeconds();
    const DenoiseGuides guides = denoiseGuidesFromBuffers(b, threads);
    guidesMs.push_back(secondsSince(t0) * 1e3);
    const ImageF dw = denoisedWith(b, with, without, mask, guides, threads);
    const double ms = secondsSince(t0) * 1e3,
                 filterCpu = (processCpuSeconds() - c0) / std::max(1, threads);
    if (spp == 4)
      for (int k = 0; k < 7; ++k) {
        t0 = Clock::now();
        const double c1 = processCpuSeconds();
        (void)denoisedWith(b, with, without, mask, guides, threads);
        filterMs.push_back(secondsSince(t0) * 1e3);
        filterCpuMs.push_back((processCpuSeconds() - c1) * 1e3 / std::max(1, threads));
        baseMs.push_back(baselineMs(w, h, threads));
      }
    const ImageF den = differentialComposite(photo, dw, without, mask);
    t0 = Clock::now();
    const double c2 = processCpuSeconds();
    const ImageF gw = opencvGuidedWith(with, without, mask, guides);
    const double cvMs = secondsSince(t0) * 1e3,
                 cvCpu = (processCpuSeconds() - c2) / std::max(1, threads);
    const ImageF cvd = differentialComposite(photo, gw, without, mask);
    csv << mc.name << ",opencv_guided," << spp << ',' << seconds + cvMs * 1e-3 << ',' << cpu + cvCpu
        << ',' << rmse(cvd, reference, object) << ',' << rmse(cvd, reference, around) << ','
        << object.size() << ',' << around.size() << '\n';
    csv << mc.name << ",raw," << spp << ',' << seconds << ',' << cpu << ','
        << rmse(raw, reference, object) << ',' << rmse(raw, reference, around) << ',' << object.size()
        << ',' << around.size() << '\n';
    csv << mc.name << ",denoised," << spp << ',' << seconds + ms * 1e-3 << ',' << cpu + filterCpu << ','
        << rmse(den, reference, object) << ',' << rmse(den, reference, around) << ',' << object.size()
        << ',' << around.size() << '\n';
    csv.flush();
  }
  std::sort(filterMs.begin(), filterMs.end());
  std::sort(filterCpuMs.begin(), filterCpuMs.end());
  std::sort(guidesMs.begin(), guidesMs.end());
  std::sort(baseMs.begin(), baseMs.end());
  timing << mc.name << ',' << w << ',' << h << ',' << threads << ',' << rayGuidesMs << ','
         << guidesMs[guidesMs.size() / 2] << ','
         << (filterMs.empty() ? 0.0 : filterMs[filterMs.size() / 2]) << ','
         << (filterCpuMs.empty() ? 0.0 : filterCpuMs[filterCpuMs.size() / 2]) << ','
         << (baseMs.empty() ? 0.0 : baseMs[baseMs.size() / 2]) << ',' << refError(object) << ','
         << refError(around) << '\n';
  timing.flush();
  std::fprintf(
      stderr, "%s: object %zu px, surroundings %zu px, filter %.1f ms (median), baseline %.1f ms\n",
      mc.name, object.size(), around.size(), filterMs.empty() ? 0.0 : filterMs[filterMs.size() / 2],
      baseMs.empty() ? 0.0 : baseMs[baseMs.size() / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 8) {
    std::fprintf(stderr,
                 "usage: bench_denoise SCENE.json OUT_DIR WIDTH HEIGHT REF_SPP MAX_SPP THREADS\n");
    return 2;
  }
  const std::string out = argv[2];
  const int w = std::atoi(argv[3]), h = std::atoi(argv[4]), refSpp = std::atoi(argv[5]);
  const int maxSpp = std::atoi(argv[6]), threads = std::atoi(argv[7]);
  if (w <= 0 || h <= 0 || refSpp <= 0 || maxSpp <= 0 || threads < 0)
    return std::fprintf(stderr, "bench_denoise: bad size or sample counts\n"), 2;
  auto loaded = loadSceneFile(argv[1]);
  if (!loaded) return std::fprintf(stderr, "%s\n", loaded.error().message().c_str()), 2;
  auto prepared = prepareScene(loaded->doc);
  if (!prepared) return std::fprintf(stderr, "%s\n", prepared.error().message().c_str()), 2;
  if (prepared->renderScene.objects.empty()) return std::fprintf(stderr, "the scene has no object\n"), 2;
  const ImageF photo = resizeImage(prepared->photo.linearRgb, w, h);
  std::ofstream csv(out + "/convergence.csv"), timing(out + "/timing.csv");
  if (!csv || !timing) return std::fprintf(stderr, "%s: cannot write\n", out.c_str()), 2;
  csv << "material,mode,spp,seconds,cpu_seconds_per_thread,object_rmse,surroundings_rmse,object_px,surroundings_px\n";
  timing
      << "material,width,height,threads,ray_guides_ms,buffer_guides_ms,filter_ms,filter_cpu_ms_per_thread,baseline_ms,reference_object_error,reference_surroundings_error\n";
  // The materials to run, as ",a,b,": built by append (GCC 12 warns falsely on "," + string).
  std::string only;
  if (argc > 8) only.append(",").append(argv[8]).append(",");
  auto wanted = [&only](const char* name) {
    return only.empty() || only.find(std::string(",").append(name).append(",")) != std::string::npos;
  };
  for (const MaterialCase& mc : materialCases())
    if (wanted(mc.name))
      runCase(mc, prepared->renderScene, photo, w, h, refSpp, maxSpp, threads, csv, timing);
  return 0;
}
