// inlay-cli: the Inlay engine without a window (../shared/spec/cli.md).
// Exit status: 0 success, 2 bad input or usage (one line naming file, key and reason),
// 1 internal failure or interruption.
#include "inlay/engine/pipeline.h"
#include "inlay/modeling/estimate_camera.h"
#include "inlay/modeling/image_io.h"
#include "inlay/modeling/scene_file.h"
#include "inlay/render/session.h"

#include <nlohmann/json.hpp>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace inlay;

constexpr const char* kUsage = R"(Usage:
  inlay-cli render SCENE.json -o OUT.png [options]   render the inserted objects into the photo
  inlay-cli demo -o OUT.png [options]                render the bundled example scene
  inlay-cli decompose SCENE.json --albedo ALBEDO.exr [--direct DIRECT.exr] [--method ours|retinex]
            [--seconds S] [--progress-csv F]         the room's albedo and direct light; S: the
                                                     solver's time limit, F: objective and
                                                     residuals against time
  inlay-cli estimate PHOTO -o CAMERA.json [--scene SCENE.json]
                                                     vanishing points, focal length, rotation,
                                                     back wall; --scene keeps what it fixes
  inlay-cli --help | --version

Render options:
  -o, --output FILE       composite; .png/.jpg/.tif as 8-bit sRGB, .exr as linear half
  --spp N                 stop at N samples per pixel (default: the scene's render.spp, 256)
  --seconds S             stop after S seconds of rendering (default: the scene's render.seconds)
  --seed K                random seed (default: the scene's render.seed)
  --threads T             threads (default: all cores)
  --layers FILE.exr       also write linear layers: composite, with_objects, without_objects, mask
  --progress-csv FILE     one row per progressive update: seconds, spp, estimated error
  --no-focus              sample every pixel equally (default: pixels the objects do not
                          change are revisited only every fourth wave)
  --quiet                 no progress on stderr

The scene file format is described in README.md (keys: photo, camera, layout, lights, shafts,
surfaces, occluders, objects, render). Outputs are written to a temporary file and renamed, so an interrupted run
never leaves a half-written file. Ctrl-C stops within a second.

Exit status: 0 success, 2 bad input or usage, 1 internal failure or interrupted.

A scene file without camera.vanishing_points_px or layout.back_wall_px gets them estimated from
the photo (as 'estimate' does), with a warning when the photo shows no clear room structure.
)";

CancelToken gCancel;
std::atomic<bool> gInterrupted{false};

void onSignal(int) {
  gInterrupted.store(true);
  gCancel.cancel();
}

int usageError(const std::string& msg) {
  std::fprintf(stderr, "inlay-cli: %s\n(run 'inlay-cli --help' for usage)\n", msg.c_str());
  return 2;
}

int inputError(const Error& e) {
  std::fprintf(stderr, "inlay-cli: %s\n", e.message().c_str());
  return 2;
}

struct Args {
  std::string command;
  std::vector<std::string> positional;
  std::string output, layers, progressCsv, albedo, direct, method = "ours", sceneForEstimate;
  std::optional<int> spp, seed, threads;
  std::optional<double> seconds;
  bool quiet = false;
  bool noFocus = false;
};

template <class T>
std::optional<T> parseNumber(const std::string& s) {
  try {
    size_t used = 0;
    if constexpr (std::is_same_v<T, int>) {
      const long v = std::stol(s, &used);
      if (used != s.size() || v < 0 || v > 1'000'000'000) return std::nullopt;
      return int(v);
    } else {
      const double v = std::stod(s, &used);
      if (used != s.size() || !std::isfinite(v) || v < 0) return std::nullopt;
      return v;
    }
  } catch (...) {
    return std::nullopt;
  }
}

// Returns an error message, or empty on success.
std::string parseArgs(int argc, char** argv, Args& a) {
  for (int i = 1; i < argc; ++i) {
    const std::string s = argv[i];
    auto value = [&](const char* flag) -> std::optional<std::string> {
      if (i + 1 >= argc) return std::nullopt;
      (void)flag;
      return std::string(argv[++i]);
    };
    if (s == "-o" || s == "--output" || s == "--layers" || s == "--progress-csv" ||
        s == "--albedo" || s == "--direct" || s == "--method" || s == "--scene" || s == "--spp" ||
        s == "--seconds" || s == "--seed" || s == "--threads") {
      const auto v = value(s.c_str());
      if (!v) return s + " needs a value";
      if (s == "-o" || s == "--output") a.output = *v;
      else if (s == "--layers") a.layers = *v;
      else if (s == "--progress-csv") a.progressCsv = *v;
      else if (s == "--albedo") a.albedo = *v;
      else if (s == "--direct") a.direct = *v;
      else if (s == "--method") a.method = *v;
      else if (s == "--scene") a.sceneForEstimate = *v;
      else if (s == "--seconds") {
        a.seconds = parseNumber<double>(*v);
        if (!a.seconds) return "--seconds: '" + *v + "' is not a non-negative number";
      } else {
        const auto n = parseNumber<int>(*v);
        if (!n) return s + ": '" + *v + "' is not a non-negative whole number";
        if (s == "--spp") {
          if (*n < 1) return "--spp must be at least 1";
          a.spp = n;
        } else if (s == "--seed") a.seed = n;
        else a.threads = n;
      }
    } else if (s == "--quiet" || s == "-q") {
      a.quiet = true;
    } else if (s == "--no-focus") {
      a.noFocus = true;
    } else if (!s.empty() && s[0] == '-' && s != "-") {
      return "unknown option '" + s + "'";
    } else if (a.command.empty()) {
      a.command = s;
    } else {
      a.positional.push_back(s);
    }
  }
  return {};
}

// Progress on stderr: a bar on a terminal, plain lines otherwise.
class Progress {
 public:
  explicit Progress(bool quiet) : quiet_(quiet), tty_(isatty(STDERR_FILENO)) {}
  void stage(const std::string& name, double fraction) {
    if (quiet_) return;
    if (tty_) {
      std::fprintf(stderr, "\r%-10s [%-30s] %3d%%", name.c_str(),
                   std::string(size_t(30 * std::clamp(fraction, 0.0, 1.0)), '#').c_str(),
                   int(100 * fraction));
      if (fraction >= 1) std::fprintf(stderr, "\n");
    } else if (name != last_) {
      std::fprintf(stderr, "inlay-cli: %s\n", name.c_str());
    }
    last_ = name;
  }
  void frame(const RenderFrame& f, double fraction) {
    if (quiet_) return;
    if (tty_) {
      std::fprintf(stderr, "\rrender     [%-30s] %3d%%  %d spp  %.1f s  err %.4f ",
                   std::string(size_t(30 * std::clamp(fraction, 0.0, 1.0)), '#').c_str(),
                   int(100 * fraction), f.spp, f.seconds, f.estimatedError);
    } else if (f.spp > 0 && (f.spp & (f.spp - 1)) == 0) {  // powers of two only
      std::fprintf(stderr, "inlay-cli: render %d spp, %.1f s, estimated error %.4f\n", f.spp,
                   f.seconds, f.estimatedError);
    }
  }
  void done() {
    if (!quiet_ && tty_) std::fprintf(stderr, "\n");
  }
  bool quiet() const { return quiet_; }

 private:
  bool quiet_, tty_;
  std::string last_;
};

class CollectingSink : public FrameSink {
 public:
  CollectingSink(Progress& progress, std::ofstream* csv, int targetSpp, double seconds)
      : progress_(progress), csv_(csv), targetSpp_(targetSpp), seconds_(seconds) {}
  void onFrame(std::shared_ptr<const RenderFrame> f) override {
    std::lock_guard<std::mutex> lock(m_);
    last_ = f;
    double fraction = double(f->spp) / std::max(1, targetSpp_);
    if (seconds_ > 0) fraction = std::max(fraction, f->seconds / seconds_);
    progress_.frame(*f, std::min(1.0, fraction));
    if (csv_ && f->spp > 0)
      *csv_ << f->seconds << "," << f->spp << "," << f->estimatedError << "\n" << std::flush;
  }
  std::shared_ptr<const RenderFrame> last() {
    std::lock_guard<std::mutex> lock(m_);
    return last_;
  }

 private:
  std::mutex m_;
  std::shared_ptr<const RenderFrame> last_;
  Progress& progress_;
  std::ofstream* csv_;
  int targetSpp_;
  double seconds_;
};

Expected<PreparedScene> loadAndPrepare(const std::string& scenePath, const Args& a, Progress& progress) {
  auto loaded = loadSceneFile(scenePath);
  if (!loaded) return loaded.error();
  for (const auto& w : loaded->warnings)
    if (!progress.quiet()) std::fprintf(stderr, "inlay-cli: warning: %s\n", w.c_str());
  PrepareOptions po;
  po.cancel = &gCancel;
  po.threads = a.threads.value_or(0);
  po.progress = [&](const std::string& stage, double f) { progress.stage(stage, f); };
  auto prepared = prepareScene(loaded->doc, po);
  if (!prepared) {
    Error e = prepared.error();
    if (e.file.empty()) e.file = scenePath;
    return e;
  }
  for (const auto& w : prepared->warnings)
    if (!progress.quiet()) std::fprintf(stderr, "inlay-cli: warning: %s\n", w.c_str());
  return prepared;
}

int commandRender(const std::string& scenePath, const Args& a) {
  if (a.output.empty()) return usageError("render needs -o OUT.png");
  Progress progress(a.quiet);
  auto prepared = loadAndPrepare(scenePath, a, progress);
  if (gInterrupted) return std::fprintf(stderr, "inlay-cli: interrupted\n"), 1;
  if (!prepared) return inputError(prepared.error());
  PreparedScene& ps = *prepared;

  SessionOptions so;
  so.targetSpp = a.spp.value_or(ps.doc.render.spp);
  so.seconds = a.seconds.value_or(ps.doc.render.seconds.value_or(0.0));
  so.seed = uint32_t(a.seed.value_or(int(ps.doc.render.seed)));
  so.threads = a.threads.value_or(0);
  so.startDivider = 1;  // no preview in batch mode
  // Samples go where the objects change the photo; untouched pixels are revisited every fourth
  // wave (render/session.h).
  so.focusOnChanges = !a.noFocus;
  std::ofstream csv;
  if (!a.progressCsv.empty()) {
    csv.open(a.progressCsv);
    if (!csv) return inputError(Error{a.progressCsv, "--progress-csv", "cannot be written"});
    csv << "seconds,spp,estimated_error\n";
  }
  CollectingSink sink(progress, a.progressCsv.empty() ? nullptr : &csv, so.targetSpp, so.seconds);
  {
    RenderSession session(&sink, so);
    session.setScene(ps.renderScene);
    while (!session.waitUntilDone(0.05)) {
      if (gInterrupted) {
        session.cancel();
        break;
      }
    }
  }
  progress.done();
  if (gInterrupted) return std::fprintf(stderr, "inlay-cli: interrupted; nothing written\n"), 1;
  const auto frame = sink.last();
  if (!frame || frame->spp == 0) {
    std::fprintf(stderr, "inlay-cli: the renderer produced no frame\n");
    return 1;
  }
  const ImageF composite = compositeOf(ps, *frame);
  if (auto st = saveImage(a.output, composite); !st) return inputError(st.error());
  if (!a.layers.empty()) {
    ImageF with = frame->withObjects, without = frame->withoutObjects;
    const std::vector<NamedLayer> layers = {{"composite", &composite}, {"with_objects", &with},
                                            {"without_objects", &without}, {"mask", &frame->mask}};
    if (auto st = saveLayersExr(a.layers, layers); !st) return inputError(st.error());
  }
  if (!a.quiet)
    std::fprintf(stderr, "inlay-cli: wrote %s (%d spp, %.1f s render, estimated error %.4f)\n",
                 a.output.c_str(), frame->spp, frame->seconds, frame->estimatedError);
  return 0;
}

// CAMERA.json: the scene file's `camera` and `layout` keys, plus `rotation` (world from camera,
// camera looking down its -z, y up), per-vanishing-point confidence and timings.
int commandEstimate(const std::string& photoPath, const Args& a) {
  if (a.output.empty()) return usageError("estimate needs -o CAMERA.json");
  Progress progress(a.quiet);
  progress.stage("photo", 0);
  auto photo = loadImage(photoPath, ImageLimits::photo());
  if (!photo) return inputError(photo.error());
  SceneDoc fixed;
  if (!a.sceneForEstimate.empty()) {
    auto loaded = loadSceneFile(a.sceneForEstimate);
    if (!loaded) return inputError(loaded.error());
    fixed = loaded->doc;
  }
  progress.stage("estimate", 0);
  // What the user already fixed in the scene is kept; the rest is estimated around it.
  auto cl = cameraAndLayoutOf(fixed.camera, fixed.layout, *photo, true, &gCancel);
  if (gInterrupted) return std::fprintf(stderr, "inlay-cli: interrupted; nothing written\n"), 1;
  if (!cl) return inputError(cl.error().inFile(a.sceneForEstimate.empty() ? photoPath : a.sceneForEstimate));
  const CameraEstimate& est = *cl->estimate;
  const Camera& cam = cl->camera;
  const std::array<Vec2, 3> vps = fixed.camera.vanishingPointsPx ? *fixed.camera.vanishingPointsPx
                                                                 : est.vanishingPointsPx;
  using nlohmann::json;
  auto pt = [](const Vec2& p) { return json::array({p.x(), p.y()}); };
  json j;
  j["camera"] = {{"height_m", cam.heightM}, {"focal_px", cam.focalPx},
                 {"principal_px", pt(cam.principalPx)},
                 {"vanishing_points_px", json::array({pt(vps[0]), pt(vps[1]), pt(vps[2])})}};
  j["layout"] = {{"back_wall_px", json::array({pt(cl->backWallPx[0]), pt(cl->backWallPx[1]),
                                               pt(cl->backWallPx[2]), pt(cl->backWallPx[3])})}};
  json rot = json::array();
  for (int r = 0; r < 3; ++r)
    rot.push_back(json::array({cam.worldFromCamera(r, 0), cam.worldFromCamera(r, 1), cam.worldFromCamera(r, 2)}));
  j["rotation"] = rot;
  j["confidence"] = {{"vanishing_points", json::array({est.confidence[0], est.confidence[1], est.confidence[2]})},
                     {"overall", est.overallConfidence}, {"manhattan", est.manhattan},
                     {"layout", est.layoutScore}};
  j["focal_interval_px"] = json::array({est.focalMinPx, est.focalMaxPx});
  j["focal_from_prior"] = est.focalFromPrior;
  j["warnings"] = est.warnings;
  j["timings_ms"] = {{"lines", est.timings.linesMs}, {"vanishing", est.timings.vanishingMs},
                     {"refine", est.timings.refineMs}, {"layout", est.timings.layoutMs},
                     {"total", est.timings.totalMs}};
  j["segments"] = est.segments.size();
  if (auto st = writeFileAtomically(a.output, j.dump(2) + "\n"); !st) return inputError(st.error());
  if (!a.quiet) {
    for (const auto& w : cl->warnings) std::fprintf(stderr, "inlay-cli: warning: %s\n", w.c_str());
    std::fprintf(stderr, "inlay-cli: wrote %s (focal %.1f px, confidence %.2f, %.0f ms)\n",
                 a.output.c_str(), cam.focalPx, est.overallConfidence, est.timings.totalMs);
  }
  return 0;
}

int commandDecompose(const std::string& scenePath, const Args& a) {
  if (a.albedo.empty()) return usageError("decompose needs --albedo ALBEDO.exr");
  if (a.method != "ours" && a.method != "retinex")
    return usageError("--method " + a.method + ": expected 'ours' or 'retinex'");
  Progress progress(a.quiet);
  auto prepared = loadAndPrepare(scenePath, a, progress);
  if (gInterrupted) return std::fprintf(stderr, "inlay-cli: interrupted\n"), 1;
  if (!prepared) return inputError(prepared.error());
  const LightingEstimate& le = prepared->lighting;
  const bool retinex = a.method == "retinex";
  // --seconds S: re-run the solver from its start with that time limit (error against time).
  std::optional<Decomposition> rerun;
  if (!retinex && a.seconds && !le.decomposeStart.empty()) {
    DecomposeOptions o;
    o.timeLimitSeconds = std::max(1e-6, *a.seconds);
    o.maxIterations = 100000;
    o.cancel = &gCancel;
    auto d = decomposeIntrinsic(prepared->photo.linearRgb, le.gathered, le.decomposeStart,
                                le.decomposeValid, le.decomposeClipped, o);
    if (!d) return inputError(d.error());
    rerun = std::move(*d);
  }
  const std::vector<DecomposeSample>& history = rerun ? rerun->history : le.decomposeHistory;
  if (!a.progressCsv.empty() && !retinex) {
    std::string csv = "seconds,iteration,objective,primal_residual,dual_residual\n";
    char row[160];
    for (const auto& h : history) {
      std::snprintf(row, sizeof row, "%.6f,%d,%.9g,%.6g,%.6g\n", h.seconds, h.iteration, h.objective,
                    h.primalResidual, h.dualResidual);
      csv += row;
    }
    if (auto st = writeFileAtomically(a.progressCsv, csv); !st) return inputError(st.error());
  }
  ImageF albedo = retinex ? le.retinexAlbedo : le.albedo;
  if (rerun)  // the room's pixels from the re-run
    for (size_t i = 0; i < albedo.data.size(); ++i)
      if (albedo.data[i] > 0 || le.decomposeValid[i / 3]) albedo.data[i] = rerun->albedo.data[i];
  if (auto st = saveImage(a.albedo, albedo, SaveOptions{false}); !st)
    return inputError(st.error());
  if (!a.direct.empty()) {
    ImageF direct = rerun ? rerun->direct : le.direct;
    if (retinex)  // D = B - rho Gamma for Retinex's rho
      for (size_t i = 0; i < direct.data.size() && i < le.gathered.data.size(); ++i)
        direct.data[i] = std::max(0.f, prepared->photo.linearRgb.data[i] -
                                           albedo.data[i] * le.gathered.data[i]);
    if (auto st = saveImage(a.direct, direct, SaveOptions{false}); !st)
      return inputError(st.error());
  }
  if (!a.quiet && !retinex && !le.decomposeReport.empty())
    std::fprintf(stderr, "inlay-cli: decomposition %s\n",
                 (rerun ? rerun->report : le.decomposeReport).c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  Args a;
  if (argc < 2) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (!std::strcmp(argv[i], "--version")) {
      std::printf("inlay-cli %s\n", versionString());
      return 0;
    }
  }
  if (const std::string err = parseArgs(argc, argv, a); !err.empty()) return usageError(err);
  try {
    if (a.command == "render") {
      if (a.positional.size() != 1) return usageError("render needs exactly one SCENE.json");
      return commandRender(a.positional[0], a);
    }
    if (a.command == "demo") {
      if (!a.positional.empty()) return usageError("demo takes no scene file");
      const std::string scene = exampleScenePath();
      if (scene.empty()) {
        std::fprintf(stderr, "inlay-cli: the bundled example scene was not found\n");
        return 1;
      }
      return commandRender(scene, a);
    }
    if (a.command == "decompose") {
      if (a.positional.size() != 1) return usageError("decompose needs exactly one SCENE.json");
      return commandDecompose(a.positional[0], a);
    }
    if (a.command == "estimate") {
      if (a.positional.size() != 1) return usageError("estimate needs exactly one PHOTO");
      return commandEstimate(a.positional[0], a);
    }
    return usageError(a.command.empty() ? "no command given" : "unknown command '" + a.command + "'");
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "inlay-cli: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "inlay-cli: internal error: %s\n", e.what());
    return 1;
  }
}
