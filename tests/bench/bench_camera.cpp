// Camera and layout benchmark: York Urban (real photos) and the ground-truth rooms.
//
// usage: bench_camera [--york DIR] [--scenes DIR] [--out DIR] [--budgets 5,15,30,60,120,240,480]
//                     [--default-budget 120] [--gt-segments] [--no-exif] [--principal-sigma S]
//                     [--known-principal] [--known-focal] [--reps N] [--dump DIR] [--seed K]
// Writes OUT/camera_bench.csv (one row per image and search budget) and
// OUT/camera_bench_summary.json; plot with bench_camera_plot.py. --known-principal gives the
// estimator the truth's principal point, --known-focal its focal length as a prior of 1e-4 log-sigma
// (diagnoses, not photo-alone figures: the horizon ceilings); --dump writes
// each estimate's segments, families, residuals and camera as JSON for looking at failures. Scores exactly as ../shared/tools/score_york.py does
// (orthogonalised truth, closest estimated axis per true direction, horizon error at the left and
// right borders over the image height, AUC up to 0.25). Photos are read with loadImage and the
// EXIF focal length is the prior, as `inlay-cli estimate` does (--no-exif: the 60 degree prior).
// Times: the estimator alone (not the JPEG decode), wall time of the fastest of --reps runs per
// budget (ms) and that run's CPU time (cpu_ms: what one idle core would take, however loaded the
// machine is); run with OPENCV_FOR_THREADS_NUM=1 (and taskset -c 0) for one core. --seed K: the
// hypothesis search's seed (EstimateOptions::seed); the York AUC moves by about +-0.005 with it,
// so compare settings over several seeds.
#include "inlay/modeling/estimate_camera.h"
#include "inlay/modeling/image.h"
#include "inlay/modeling/image_io.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace inlay;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// This thread's CPU time: what the estimator costs one idle core, whatever else loads the
// machine (wall time counts the waits for a core too).
double threadCpuMs() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

double median(std::vector<double> v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Horizon AUC as score_york.py: fraction with error <= x for x in [0, 0.25], trapezoid / 0.25.
double horizonAuc(const std::vector<double>& err) {
  if (err.empty()) return NAN;
  double area = 0, prev = 0;
  for (int i = 0; i <= 250; ++i) {
    const double x = 0.25 * i / 250;
    double frac = 0;
    for (double e : err) frac += (std::isfinite(e) ? e : 1.0) <= x ? 1 : 0;
    frac /= err.size();
    if (i > 0) area += 0.5 * (frac + prev) * (0.25 / 250);
    prev = frac;
  }
  return area / 0.25;
}

struct Truth {
  int W = 0, H = 0;
  double f = 0;
  Vec2 pp;
  std::vector<Vec3> dirs;  // camera frame: x right, y up, z forward (York's frame)
  std::optional<std::array<Vec2, 4>> backWall;
};

struct Scores {
  double focalRel = NAN, angMax = NAN, angMean = NAN, horizon = NAN, cornerMax = NAN, cornerMean = NAN;
};

Scores score(const Truth& t, const CameraEstimate& e) {
  Scores s;
  const double fe = e.camera.focalPx;
  s.focalRel = std::abs(fe - t.f) / t.f;
  const Mat3& R = e.camera.worldFromCamera;  // world from camera, camera looks down -z
  Vec3 est[3];
  for (int i = 0; i < 3; ++i) est[i] = Vec3(R(i, 0), R(i, 1), -R(i, 2));
  double mx = 0, sum = 0;
  for (const Vec3& d : t.dirs) {
    double best = 1e9;
    for (const Vec3& q : est)
      best = std::min(best, std::acos(std::min(1.0, std::abs(d.dot(q) / q.norm()))) * 180 / M_PI);
    mx = std::max(mx, best);
    sum += best;
  }
  s.angMax = mx;
  s.angMean = sum / t.dirs.size();
  // True horizon through the two horizontal true vanishing points.
  int vi = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(t.dirs[i].y()) > std::abs(t.dirs[vi].y())) vi = i;
  Mat3 K;
  K << t.f, 0, t.pp.x(), 0, -t.f, t.pp.y(), 0, 0, 1;
  std::vector<Vec3> hz;
  for (int i = 0; i < 3; ++i)
    if (i != vi) hz.push_back(K * t.dirs[i]);
  const Vec3 line = hz[0].cross(hz[1]);
  const Vec2 c = e.camera.principalPx;
  const Vec3 n = est[1];
  double herr = 0;
  for (double u : {0.0, double(t.W)}) {
    const double trueV = -(line.x() * u + line.z()) / line.y();
    const double estV = std::abs(n.y()) > 1e-12 ? c.y() + (n.x() * (u - c.x()) + n.z() * fe) / n.y()
                                                : INFINITY;
    herr = std::max(herr, std::abs(estV - trueV) / t.H);
  }
  s.horizon = herr;
  if (t.backWall) {
    double cm = 0, cs = 0;
    for (int i = 0; i < 4; ++i) {
      const double d = (e.backWallPx[i] - (*t.backWall)[i]).norm();
      cm = std::max(cm, d);
      cs += d;
    }
    s.cornerMax = cm;
    s.cornerMean = cs / 4;
  }
  return s;
}

std::vector<int> parseList(const std::string& s) {
  std::vector<int> v;
  std::stringstream ss(s);
  std::string tok;
  while (std::getline(ss, tok, ',')) v.push_back(std::stoi(tok));
  return v;
}

struct Row {
  std::string set, image;
  int budget = 0;
  double ms = 0;
  double cpuMs = 0;        // the same run's CPU time (threadCpuMs)
  EstimateTimings stages;  // of the fastest run
  Scores s;
  double conf = 0, layoutScore = 0;
  Vec2 principal{0, 0};
  bool manhattan = false;
  int segments = 0;
};

// For looking at failures (tests/bench/bench_camera_plot.py --overlay draws them).
void dumpEstimate(const std::string& dir, const std::string& name, int budget, const CameraEstimate& e) {
  json j;
  j["focal_px"] = e.camera.focalPx;
  j["principal_px"] = {e.camera.principalPx.x(), e.camera.principalPx.y()};
  json rot = json::array();
  for (int r = 0; r < 3; ++r)
    rot.push_back({e.camera.worldFromCamera(r, 0), e.camera.worldFromCamera(r, 1),
                   e.camera.worldFromCamera(r, 2)});
  j["rotation"] = rot;
  json segs = json::array();
  for (const auto& s : e.segments)
    segs.push_back({s.aPx.x(), s.aPx.y(), s.bPx.x(), s.bPx.y(), s.family, s.residualPx});
  j["segments"] = segs;
  json bw = json::array();
  for (const auto& p : e.backWallPx) bw.push_back({p.x(), p.y()});
  j["back_wall_px"] = bw;
  j["confidence"] = {e.confidence[0], e.confidence[1], e.confidence[2]};
  j["warnings"] = e.warnings;
  fs::create_directories(dir);
  std::ofstream(fs::path(dir) /
                (fs::path(name).stem().string() + "_" + std::to_string(budget) + ".json"))
      << j.dump() << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::string york, scenes, out = ".";
  std::vector<int> budgets = {5, 15, 30, 60, 120, 240, 480};
  int defaultBudget = EstimateOptions{}.searchIterations;
  bool gtSegments = false, useExif = true;
  double principalSigma = EstimateOptions{}.principalSigma;
  bool knownPrincipal = false;  // diagnosis only: the truth's principal point given
  bool knownFocal = false;      // diagnosis only: the truth's focal length as a tight prior
  int reps = 3;
  uint32_t seed = EstimateOptions{}.seed;
  std::string dumpDir;  // per image and budget: the estimate's segments and camera (JSON)
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&] { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
    if (a == "--york") york = next();
    else if (a == "--scenes") scenes = next();
    else if (a == "--out") out = next();
    else if (a == "--budgets") budgets = parseList(next());
    else if (a == "--default-budget") defaultBudget = std::stoi(next());
    else if (a == "--gt-segments") gtSegments = true;
    else if (a == "--no-exif") useExif = false;
    else if (a == "--principal-sigma") principalSigma = std::stod(next());
    else if (a == "--known-principal") knownPrincipal = true;
    else if (a == "--known-focal") knownFocal = true;
    else if (a == "--reps") reps = std::max(1, std::stoi(next()));
    else if (a == "--dump") dumpDir = next();
    else if (a == "--seed") seed = uint32_t(std::stoul(next()));
    else {
      std::cerr << "usage: bench_camera [--york DIR] [--scenes DIR] [--out DIR] [--budgets a,b,c] "
                   "[--default-budget N] [--gt-segments] [--no-exif] [--principal-sigma S] "
                   "[--known-principal] [--known-focal] [--reps N] [--dump DIR] [--seed K]\n";
      return 2;
    }
  }
  if (std::find(budgets.begin(), budgets.end(), defaultBudget) == budgets.end())
    budgets.push_back(defaultBudget);
  std::sort(budgets.begin(), budgets.end());
  fs::create_directories(out);
  std::vector<Row> rows;

  auto run = [&](const std::string& set, const std::string& name, const LoadedImage& li, const Truth& t,
                 const std::vector<LineSegment>* segs) {
    const ImageF& im = li.linearRgb;
    for (int b : budgets) {
      EstimateOptions o;
      o.searchIterations = b;
      o.seed = seed;
      o.principalSigma = principalSigma;
      if (knownPrincipal) o.principalPx = t.pp;
      if (useExif) o.priorFocalPx = li.exif.focalPx(im.width, im.height);
      if (knownFocal) {
        o.priorFocalPx = t.f;
        o.priorLogSigmaExif = 1e-4;
      }
      // Best of 3 runs for the time (the machine is shared); results are deterministic.
      double bestMs = 1e300, bestCpuMs = 0;
      EstimateTimings bestStages;
      std::optional<CameraEstimate> est;
      for (int rep = 0; rep < reps; ++rep) {
        const double c0 = threadCpuMs();
        const auto t0 = std::chrono::steady_clock::now();
        auto e = segs ? estimateCameraFromSegments(im.width, im.height, *segs, o)
                      : estimateCamera(im, o);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        const double cpuMs = threadCpuMs() - c0;
        if (!e.ok()) {
          std::cerr << name << ": " << e.error().message() << "\n";
          break;
        }
        if (ms < bestMs) {
          bestStages = e->timings;
          bestCpuMs = cpuMs;
        }
        bestMs = std::min(bestMs, ms);
        est = *e;
      }
      if (!est) continue;
      if (!dumpDir.empty()) dumpEstimate(dumpDir, name, b, *est);
      Row r;
      r.set = set;
      r.image = name;
      r.budget = b;
      r.ms = bestMs;
      r.stages = bestStages;
      r.cpuMs = bestCpuMs;
      r.s = score(t, *est);
      r.conf = est->overallConfidence;
      r.principal = est->camera.principalPx;
      r.layoutScore = est->layoutScore;
      r.manhattan = est->manhattan;
      r.segments = int(est->segments.size());
      rows.push_back(r);
    }
  };

  if (!york.empty()) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(york))
      if (e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& jf : files) {
      std::ifstream f(jf);
      const json j = json::parse(f);
      Truth t;
      t.W = j["width"];
      t.H = j["height"];
      t.f = j["camera"]["focal_px"];
      t.pp = Vec2(j["camera"]["principal_px"][0], j["camera"]["principal_px"][1]);
      for (const auto& d : j["vanishing_directions_orthogonal_camera"])
        t.dirs.push_back(Vec3(d[0], d[1], d[2]).normalized());
      const std::string img = (fs::path(york) / j["image"].get<std::string>()).string();
      const auto im = loadImage(img);
      if (!im.ok()) {
        std::cerr << im.error().message() << "\n";
        continue;
      }
      std::vector<LineSegment> segs;
      if (gtSegments)
        for (const auto& s : j["segments_px"]) {
          LineSegment l;
          l.aPx = Vec2(s[0], s[1]);
          l.bPx = Vec2(s[2], s[3]);
          segs.push_back(l);
        }
      run("york", j["image"], *im, t, gtSegments ? &segs : nullptr);
    }
  }
  if (!scenes.empty()) {
    std::vector<fs::path> dirs;
    for (const auto& e : fs::directory_iterator(scenes))
      if (fs::exists(e.path() / "truth.json")) dirs.push_back(e.path());
    std::sort(dirs.begin(), dirs.end());
    for (const auto& d : dirs) {
      std::ifstream f(d / "truth.json");
      const json j = json::parse(f);
      Truth t;
      t.W = j["image"]["width"];
      t.H = j["image"]["height"];
      const json& c = j["camera"];
      t.f = c["focal_px"];
      t.pp = Vec2(c["principal_point_px"][0], c["principal_point_px"][1]);
      Mat3 R;
      for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 3; ++k) R(r, k) = c["R_cam_to_world_opengl"][r][k];
      // World axis i in the camera frame (y up), z flipped to York's z-forward frame.
      for (int i = 0; i < 3; ++i) t.dirs.push_back(Vec3(R(i, 0), R(i, 1), -R(i, 2)));
      const json& k = j["room"]["corners"];
      std::array<Vec2, 4> bw;
      bool ok = true;
      const char* names[4] = {"ceiling_front_left", "ceiling_front_right", "floor_front_right",
                              "floor_front_left"};
      for (int i = 0; i < 4; ++i) {
        if (k[names[i]]["pixel"].is_null()) ok = false;
        else bw[i] = Vec2(k[names[i]]["pixel"][0], k[names[i]]["pixel"][1]);
      }
      if (ok) t.backWall = bw;
      const auto im = loadImage((d / "photo.png").string());
      if (!im.ok()) {
        std::cerr << im.error().message() << "\n";
        continue;
      }
      run("scenes", d.filename().string(), *im, t, nullptr);
    }
  }

  {
    std::ofstream csv(fs::path(out) / "camera_bench.csv");
    csv << "set,image,budget,ms,focal_rel_err,vp_angle_deg_max,vp_angle_deg_mean,horizon_err,"
           "corner_err_px_max,corner_err_px_mean,confidence,manhattan,layout_score,segments,principal_x,principal_y,"
           "lines_ms,vanishing_ms,refine_ms,layout_ms,cpu_ms\n";
    for (const Row& r : rows)
      csv << r.set << "," << r.image << "," << r.budget << "," << r.ms << "," << r.s.focalRel << ","
          << r.s.angMax << "," << r.s.angMean << "," << r.s.horizon << "," << r.s.cornerMax << ","
          << r.s.cornerMean << "," << r.conf << "," << r.manhattan << "," << r.layoutScore << ","
          << r.segments << "," << r.principal.x() << "," << r.principal.y() << "," << r.stages.linesMs
          << "," << r.stages.vanishingMs << "," << r.stages.refineMs << "," << r.stages.layoutMs << ","
          << r.cpuMs << "\n";
  }
  json summary;
  for (const std::string set : {"york", "scenes"})
    for (int b : budgets) {
      std::vector<double> fr, am, hz, ms, cm, st[4], cpu;
      for (const Row& r : rows)
        if (r.set == set && r.budget == b) {
          fr.push_back(r.s.focalRel);
          am.push_back(r.s.angMax);
          hz.push_back(r.s.horizon);
          ms.push_back(r.ms);
          cm.push_back(r.s.cornerMax);
          st[0].push_back(r.stages.linesMs);
          st[1].push_back(r.stages.vanishingMs);
          st[2].push_back(r.stages.refineMs);
          st[3].push_back(r.stages.layoutMs);
          cpu.push_back(r.cpuMs);
        }
      if (fr.empty()) continue;
      json s = {{"images", fr.size()},
                {"focal_rel_err_median", median(fr)},
                {"vp_angle_deg_max_median", median(am)},
                {"horizon_auc", horizonAuc(hz)},
                {"ms_median", median(ms)},
                {"cpu_ms_median", median(cpu)},
                {"stage_ms_median",
                 {{"lines", median(st[0])},
                  {"vanishing", median(st[1])},
                  {"refine", median(st[2])},
                  {"layout", median(st[3])}}}};
      if (set == "scenes") s["corner_err_px_max_median"] = median(cm);
      summary[set][std::to_string(b)] = s;
    }
  summary["default_budget"] = defaultBudget;
  summary["exif_prior"] = useExif;
  summary["gt_segments"] = gtSegments;
  summary["seed"] = seed;
  std::ofstream(fs::path(out) / "camera_bench_summary.json") << summary.dump(1) << "\n";
  std::cout << summary.dump(1) << "\n";
  return 0;
}
