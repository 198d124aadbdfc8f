// Light refinement at 640 x 480 with two lights (refine.h): run time (median of several runs),
// light position and intensity error before and after, and the objective against time.
// Writes OUT/refine_time.csv and OUT/refine_objective.csv; bench_refine_plot.py plots them.
//
// usage: bench_refine [OUT_DIR] [RUNS] [PRIOR]   (PRIOR: LightRefineOptions::prior)
#include "../refine_room.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

using namespace inlay;

int main(int argc, char** argv) {
  const std::string out = argc > 1 ? argv[1] : "bench_out";
  const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 5;
  LightRefineOptions options;
  if (argc > 3) options.prior = std::atof(argv[3]);
  std::filesystem::create_directories(out);
  const auto t0 = std::chrono::steady_clock::now();
  const test::RefineRoom room = test::makeRefineRoom(640, 480, 16);
  const double makeSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::ofstream timeCsv(out + "/refine_time.csv"), objCsv(out + "/refine_objective.csv");
  timeCsv << "shift_m,run,seconds,iterations_report,evaluations,pixels,position_error_start_m,"
             "position_error_refined_m,intensity_error_start,intensity_error_refined,objective_start,"
             "objective_refined\n";
  objCsv << "shift_m,seconds,objective\n";
  auto worst = [&](const std::vector<AreaLight>& ls, bool position) {
    double e = 0;
    for (size_t j = 0; j < ls.size(); ++j)
      e = std::max(e, position ? (ls[j].centre() - room.truth[j].centre()).norm()
                               : (ls[j].radiance - room.truth[j].radiance).norm() /
                                     room.truth[j].radiance.norm());
    return e;
  };
  for (double shift : {0.1, 0.3}) {
    const auto start = test::perturbed(room.truth, shift, 1.3);
    std::vector<double> seconds;
    for (int run = 0; run < runs; ++run) {
      auto r =
          refineLights(room.camera, room.geometry, room.albedo, room.direct, {}, start, {}, {}, options);
      if (!r) {
        std::fprintf(stderr, "refinement failed: %s\n", r.error().message().c_str());
        return 1;
      }
      seconds.push_back(r->seconds);
      timeCsv << shift << "," << run << "," << r->seconds << ",\"" << r->report << "\","
              << r->evaluations << "," << r->pixels << "," << worst(start, true) << ","
              << worst(r->lights, true) << "," << worst(start, false) << "," << worst(r->lights, false)
              << "," << r->initialObjective << "," << r->finalObjective << "\n";
      if (run == 0)
        for (const auto& h : r->history)
          objCsv << shift << "," << h.seconds << "," << h.objective << "\n";
      if (run == 0)
        std::printf(
            "shift %.2f m: position error %.3f -> %.3f m, intensity error %.3f -> %.3f, objective %.4g -> %.4g\n",
            shift, worst(start, true), worst(r->lights, true), worst(start, false),
            worst(r->lights, false), r->initialObjective, r->finalObjective);
    }
    std::nth_element(seconds.begin(), seconds.begin() + long(seconds.size() / 2), seconds.end());
    std::printf(
        "shift %.2f m, prior %g: refinement of two lights at 640x480, median of %d runs: %.3f s "
        "(the 16-sample truth render of the whole frame took %.2f s)\n",
        shift, options.prior, runs, seconds[seconds.size() / 2], makeSeconds);
  }
  std::printf("wrote %s/refine_time.csv and %s/refine_objective.csv\n", out.c_str(), out.c_str());
  return 0;
}
