// Run time of the decomposition alone (Retinex + the primal-dual solver) on synthetic layers
// (a checker reflectance under smooth direct light and indirect Gamma), per image size: Retinex
// seconds, solver milliseconds per iteration, seconds and iterations to reach the tolerance
// (or the iteration cap), the albedo MAE against the known reflectance at the start and end, and
// the process's peak resident memory after each size (sizes run smallest first). Two threads.
// Retinex's Poisson step alone, multigrid (what Retinex uses) against the DCT solve in the same
// process (its ratio is the figure that survives machine load), with the largest difference
// between their solutions (log reflectance).
// Writes the solver's objective and residuals against time to OUT/decompose_history_WxH.csv.
// usage: bench_decompose [--out DIR] [WxH ...]   (default 640x480 4000x3000 8660x5780)
#include "inlay/lighting/decompose.h"
#include "inlay/lighting/poisson.h"

#include "../decompose_layers.h"

#include <sys/resource.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

using namespace inlay;

// The Poisson step of Retinex on the log-luminance Laplacian of B, by multigrid and by the DCT:
// seconds of each and the largest difference of their (mean-zero) solutions.
std::tuple<double, double, double> timePoisson(const ImageF& B, int W, int H) {
  const size_t N = size_t(W) * H;
  std::vector<float> g(N), f(N, 0.f);
  for (size_t i = 0; i < N; ++i) g[i] = std::log(B.data[3 * i + 1]);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const size_t i = size_t(y) * W + x;
      if (x + 1 < W) f[i] += g[i + 1] - g[i], f[i + 1] -= g[i + 1] - g[i];
      if (y + 1 < H) f[i] += g[i + size_t(W)] - g[i], f[i + size_t(W)] -= g[i + size_t(W)] - g[i];
    }
  auto seconds = [](auto t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  auto t0 = std::chrono::steady_clock::now();
  const std::vector<float> mg = poissonNeumannMultigrid(f, W, H, 1e-4);
  const double mgS = seconds(t0);
  t0 = std::chrono::steady_clock::now();
  std::vector<float> dct = poissonNeumannDct(f, W, H);
  const double dctS = seconds(t0);
  double mean = 0, maxDiff = 0;
  for (float v : dct) mean += v;
  mean /= double(N);
  for (size_t i = 0; i < N; ++i) maxDiff = std::max(maxDiff, std::abs(mg[i] - (dct[i] - mean)));
  return {mgS, dctS, maxDiff};
}

int main(int argc, char** argv) {
  std::vector<std::pair<int, int>> sizes;
  std::string out = ".";
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 2);
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--out" && i + 1 < argc) {
      out = argv[++i];
      continue;
    }
    int w = 0, h = 0;
    if (std::sscanf(argv[i], "%dx%d", &w, &h) == 2 && w > 0 && h > 0) sizes.emplace_back(w, h);
  }
  if (sizes.empty()) sizes = {{640, 480}, {4000, 3000}, {8660, 5780}};
  std::printf(
      "size,retinex_s,solver_s,iterations,ms_per_iteration,converged,mae_start,mae_end,"
      "peak_rss_mb,poisson_mg_s,poisson_dct_s,poisson_max_diff\n");
  for (auto [W, H] : sizes) {
    const int cell = std::max(4, W / 16);
    const test::Layers l = test::makeLayers(W, H, cell);
    const ImageF &B = l.B, &G = l.gamma, &truth = l.rhoTrue;
    const std::vector<uint8_t>& valid = l.valid;
    const std::vector<uint8_t> clipped;  // none
    auto t0 = std::chrono::steady_clock::now();
    ImageF rho0 = retinexReflectance(B, valid);
    const double retinexS = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    // Anchor per channel to the truth's mean (the light fit's role in the pipeline).
    for (int c = 0; c < 3; ++c) {
      double st = 0, se = 0;
      for (size_t i = size_t(c); i < rho0.data.size(); i += 3) st += truth.data[i], se += rho0.data[i];
      for (size_t i = size_t(c); i < rho0.data.size(); i += 3)
        rho0.data[i] = std::clamp(float(rho0.data[i] * st / se), 0.f, 1.f);
    }
    auto mae = [&](const ImageF& a) {
      double s = 0;
      for (size_t i = 0; i < a.data.size(); ++i) s += std::abs(a.data[i] - truth.data[i]);
      return s / double(a.data.size());
    };
    const auto [mgS, dctS, maxDiff] = timePoisson(B, W, H);
    DecomposeOptions o;  // the pipeline's defaults: tolerance and iteration cap
    auto d = decomposeIntrinsic(B, G, rho0, valid, clipped, o);
    if (!d) return std::fprintf(stderr, "%s\n", d.error().message().c_str()), 1;
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    std::printf("%dx%d,%.3f,%.3f,%d,%.2f,%d,%.4f,%.4f,%.0f,%.3f,%.3f,%.2e\n", W, H, retinexS, d->seconds,
                d->iterations, 1000 * d->seconds / std::max(1, d->iterations), int(d->converged),
                mae(rho0), mae(d->albedo), ru.ru_maxrss / 1024.0, mgS, dctS, maxDiff);
    std::fprintf(stderr, "%dx%d: %s\n", W, H, d->report.c_str());
    const std::string path = out + "/decompose_history_" + std::to_string(W) + "x" + std::to_string(H) +
                             ".csv";
    if (FILE* f = std::fopen(path.c_str(), "w")) {
      std::fprintf(f, "seconds,iteration,objective,primal_residual,dual_residual\n");
      for (const auto& h : d->history)
        std::fprintf(f, "%.6f,%d,%.9g,%.6g,%.6g\n", h.seconds, h.iteration, h.objective,
                     h.primalResidual, h.dualResidual);
      std::fclose(f);
    }
    std::fflush(stdout);
  }
  return 0;
}
