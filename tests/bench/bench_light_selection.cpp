// Next-event estimation's choice of a light against the number of lights (1 to 256), in one
// process: the spatial selection (power over squared distance, every light weighed at every
// vertex) against the power table (TracerOptions::LightSelection), on an empty box room lit by
// a ceiling grid of small lights, one bright and the rest dim (test::manyLightsScene), two
// bounces. Per light count and mode: seconds per sample (median of REPEATS renders on the
// calling thread, its CPU time: the shared machine's load hardly moves it, unlike wall time) and the noise: the RMS difference of two renders with other seeds over sqrt 2,
// relative to the image's mean (equal samples), and the time-to-equal-noise product
// (noise^2 x seconds per sample: lower is better).
//
// usage: bench_light_selection OUT.csv [WIDTH HEIGHT SPP REPEATS]
#include "../render_test_scenes.h"

#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <vector>

using namespace inlay;

namespace {

double threadSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

struct Result {
  double secondsPerSample = 0;
  double relativeNoise = 0;
  double mean = 0;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

Result measure(const RenderScene& scene, TracerOptions::LightSelection mode, int w, int h, int spp,
               int repeats) {
  TracerOptions opt;
  opt.maxDepth = 2;
  opt.lightSelection = mode;
  PathTracer tracer(scene, opt);
  std::vector<double> times;
  ImageF first, second;
  for (int r = 0; r < std::max(2, repeats); ++r) {
    DifferentialBuffers b(w, h);
    const double t = threadSeconds();
    tracer.renderRect(b, 0, 0, w, h, 0, spp, uint32_t(17 + r));
    times.push_back((threadSeconds() - t) / spp);
    if (r == 0) first = b.meanWith();
    if (r == 1) second = b.meanWith();
  }
  double diff2 = 0, sum = 0;
  for (size_t i = 0; i < first.data.size(); ++i) {
    const double d = double(first.data[i]) - second.data[i];
    diff2 += d * d, sum += 0.5 * (double(first.data[i]) + second.data[i]);
  }
  const double n = double(first.data.size());
  Result res;
  res.secondsPerSample = median(times);
  res.mean = sum / n;
  res.relativeNoise = std::sqrt(diff2 / n / 2) / res.mean;
  return res;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_light_selection OUT.csv [WIDTH HEIGHT SPP REPEATS]\n");
    return 2;
  }
  const int w = argc > 3 ? std::atoi(argv[2]) : 96, h = argc > 3 ? std::atoi(argv[3]) : 72;
  const int spp = argc > 4 ? std::atoi(argv[4]) : 16, repeats = argc > 5 ? std::atoi(argv[5]) : 3;
  if (w <= 0 || h <= 0 || spp <= 0 || repeats <= 0) {
    std::fprintf(stderr, "bench_light_selection: WIDTH HEIGHT SPP REPEATS must be positive\n");
    return 2;
  }
  std::ofstream csv(argv[1]);
  if (!csv) {
    std::fprintf(stderr, "bench_light_selection: %s cannot be written\n", argv[1]);
    return 2;
  }
  csv << "lights,mode,seconds_per_spp,relative_noise,mean,noise2_x_seconds\n";
  using Sel = TracerOptions::LightSelection;
  const std::pair<Sel, const char*> modes[] = {
      {Sel::Spatial, "spatial"}, {Sel::Power, "power"}, {Sel::Auto, "auto"}};
  for (int count : {1, 2, 4, 8, 16, 32, 64, 128, 256}) {
    const RenderScene scene = test::manyLightsScene(w, h, count, 40.0, 2.0);
    for (const auto& [mode, name] : modes) {
      const Result r = measure(scene, mode, w, h, spp, repeats);
      csv << count << ',' << name << ',' << r.secondsPerSample << ',' << r.relativeNoise << ',' << r.mean
          << ',' << r.relativeNoise * r.relativeNoise * r.secondsPerSample << '\n';
      std::printf("%2d lights %-8s %8.2f ms/spp  noise %.4f  mean %.4f\n", count, name,
                  1e3 * r.secondsPerSample, r.relativeNoise, r.mean);
      std::fflush(stdout);
    }
  }
  return 0;
}
