// inlay-cli: the Inlay engine without a window (../shared/spec/cli.md).
// Exit status: 0 success, 2 bad input or usage (one line naming file, key and reason),
// 1 internal failure or interruption.
#include "batch.h"
#include "inlay/engine/pipeline.h"
#include "inlay/lighting/estimate.h"
#include "inlay/modeling/cpu_time.h"
#include "inlay/modeling/estimate_camera.h"
#include "inlay/modeling/image_io.h"
#include "inlay/modeling/scene_file.h"
#include "inlay/render/session.h"

#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace inlay;

constexpr const char* kUsage = R"(Usage:
  inlay-cli render SCENE.json -o OUT.png [options]   render the inserted objects into the photo
  inlay-cli demo -o OUT.png [options]                render the bundled example scene
  inlay-cli decompose SCENE.json --albedo ALBEDO.exr [--direct DIRECT.exr] [--method ours|retinex]
            [--gathered G.exr] [--physical P.exr] [--iterations N] [--solver default|scalar|diagonal|diagonal+hold] [--progress-csv F]
                                                     the room's albedo and direct light; G: the
                                                     gathered indirect light (irradiance / pi),
                                                     P: the light fit's albedo B / (its lights'
                                                     direct light + G) per pixel,
                                                     N: the solver's iteration cap, F: objective
                                                     and residuals against time
  inlay-cli estimate PHOTO -o CAMERA.json [--scene SCENE.json]
                                                     vanishing points, focal length, rotation,
                                                     back wall; --scene keeps what it fixes
  inlay-cli response SCENE.json|PHOTO -o RESPONSE.json
                   [--cue noise|noise-colour|colour|symmetry|both] [--prior W] [--edge-weight E]
                   [--min-improvement F] [--min-srgb-residual R] [--noise-quantile Q]
                   [--max-top-stops S] [--max-dark-fill D] [--evaluate-at P,T,S]
                                                     the camera response (camera.response, or
                                                     estimated from the photo): family,
                                                     parameters, warnings and the 256 codes'
                                                     linear values; --cue and --prior tune the
                                                     estimate (diagnostics)
  inlay-cli export SCENE.json -o SCENE.gltf|SCENE.glb
                                                     the reconstructed scene as glTF 2.0 (room
                                                     with albedo textures, lights as emissive
                                                     geometry, camera, objects and materials)
  inlay-cli batch MANIFEST.jsonl [--jobs N] [--shard K/N] [--verbose] [render options]
                                                     one render per manifest line (a scene, its
                                                     object overrides, an output); each scene
                                                     prepared once; existing outputs skipped
  inlay-cli --help | --version

Render options:
  -o, --output FILE       composite; .png/.jpg/.tif as 8-bit through the photo's camera
                          response (camera.response; sRGB for a linear photo), so pixels the
                          objects do not change keep the photo's codes; .exr as linear half
  --spp N                 stop at N samples per pixel (default: the scene's render.spp, 256)
  --seconds S             stop after S seconds of rendering (default: the scene's render.seconds)
  --seed K                random seed (default: the scene's render.seed)
  --threads T             threads (default: all cores)
  --layers FILE.exr       also write linear layers: composite (without grain), with_objects,
                          without_objects, mask
  --progress-csv FILE     one row per progressive update: seconds, spp, estimated error
  --noise E               adaptive sampling: stop sampling a pixel once its composite's
                          estimated standard error (sRGB [0,1]) is below E, and the render
                          once every pixel is (default: the scene's render.noise, 0.004;
                          0: sample until --spp or --seconds)
  --no-focus              sample every pixel equally (with --noise 0; default: pixels the
                          objects do not change are revisited only every fourth wave)
  --no-grain              leave the inserted objects clean (default: the scene's render.grain,
                          true: the pixels the objects change get the photo's own grain)
  --denoise               denoise the composite: an edge-aware filter of what the objects
                          change, guided by albedo, normals, depth and the object mask, whose
                          strength falls as the samples grow (pixels the objects do not change
                          stay the photo bit for bit; default for demo, off for render)
  --no-denoise            the raw render (demo's default is --denoise)
  --initial-lights        render with the lights as estimated, before their refinement
  --suns-from-bounce      diagnostics: a sun whose lit patch clips takes its strength from the
                          light the patch bounces onto the room (off by default: it fails on
                          held-out rooms, docs/generalization.md)
  --lights-json FILE      the lights before and after refinement (corners in metres, rgb in
                          the photo's linear units), the refinement's objective against time
                          and the seconds of each stage of the preparation
  --replace-lights FILE   diagnostics: render with the area lights of FILE (its "refined" list,
                          or "lights"; the format --lights-json writes) instead of the estimate's
  --replace-albedo FILE   diagnostics: render the room with this albedo (linear EXR, the
                          photo's size) instead of the estimate's; the surfaces the camera
                          does not see take its walls' mean (the product's rule)
  --replace-radiance FILE diagnostics: where the photo clips, the render's bounces read this
                          radiance (linear EXR, the photo's size and units) instead of the
                          light model's (a sunlit patch: albedo x the fitted sun)
  --surface-albedo FILE   diagnostics: {"ceiling": [r, g, b], ...}: the albedo of each named
                          room surface where the camera does not see it
  --clamp-indirect R      clamp each sample's light after the first bounce to R times white (the
                          photo's linear units, as Cycles' "clamp indirect"); 0 or "off": no
                          clamp (default: the scene's render.clamp_indirect)
  --caustic-photons N     photons of the caustic pass for smooth glass objects: the bright
                          light a glass object focuses onto the room (200000 is the measured
                          setting; default 0: off, caustics by path tracing alone)
  --caustic-radius F      diagnostics: the caustic photons' gather radius as a fraction of the
                          glass object's bounding radius (default 0.05)
  --pixel-filter W        diagnostics: the camera's pixel filter, a Blackman-Harris window
                          reaching W pixels either side of a pixel's centre (Cycles'
                          filter width); 0 or "box": the box of the pixel (default 1.5)
  --report FILE           the preparation's report as JSON: every stage with its seconds or why
                          this scene skipped it, and the warnings (also with decompose, export)
  --prepare-seed K        diagnostics: the preparation's own randomness (the lighting fit's
                          gather, the refinement's samples), added to each stage's seed
                          (default 0); --seed is the render's only
  --keep-better-fit-tolerance F
                          diagnostics: the refit after the light refinement is kept unless its
                          log residual is larger than the first estimate's by more than F of it
                          (default 0.016: twice the residual's spread over seeds)
  --refit-min-move F      diagnostics: the lighting is fitted again after the light refinement
                          only when a light's corner moved by at least F of the light's size,
                          else the first estimate's lights are kept (default 0.05; 0: any move
                          over a millimetre refits)
  --window-reveal M       diagnostics: the depth (m) of the reveal of a sun's window the photo
                          does not show; its sky's opening is the beam's section widened by it
                          on the side the light comes from (default 0.2; 0: the beam's section)
  --fit-unseen-ceiling R,G,B
                          diagnostics: the albedo the light fit's model gives a ceiling the
                          photo does not show (default: the seen walls' mean)
  --unseen-ceiling MODE    diagnostics: the albedo of a ceiling the photo does not show. fit
                          (default): an unknown of the light fit, told by the light it bounces
                          onto the seen room (the walls' mean where the photo does not tell it),
                          the render's ceiling at least white grey as before; fit-render: the
                          render takes the fit's estimate too; walls: the fit takes the seen
                          walls' mean (the rule before)
  --working-mp M          the image stages of the preparation (occluder mattes, lights' mask,
                          shafts, lighting, refinement) work on the photo reduced to at most M
                          megapixels (default 0.5; 0: the photo's own size); their maps are
                          brought back to the photo's size, the render and composite stay at
                          it (decompose always works at the photo's size)
  --response-quick-margin M
                          diagnostics: the camera response check's copies decide when the log
                          of their residuals' ratio is beyond M (default 0.1); "inf": the full
                          check always (the copies' ratio is still reported)
  --response-quick-copy N,F,P[,T[,R]]
                          diagnostics: the check's copies have at most N pixels (0: no copies),
                          F light fit pixels, P gather-and-fit passes, the light fit's
                          function tolerance T and R 1 to refine and refit their lights, 0 not
                          (its defaults: ResponseQuickCheck)
  --no-response-check     diagnostics: an estimated curve is kept without the light fit's
                          check against sRGB (default: checked; docs/benchmarks.md measures
                          what the check adds by it)
  --min-srgb-residual R, --min-improvement F
                          diagnostics: the "auto" response estimate's evidence gate, as for
                          inlay-cli response (0 and 0: every fitted curve goes to the check)
  --verbose               list every stage of the preparation on stderr: its seconds, or why it
                          was skipped ("shafts: skipped, no sun marked")
  --quiet                 no progress on stderr

The scene file format is described in docs/scene-file.md (installed: PREFIX/share/doc/inlay;
keys: photo, camera, layout, lights, shafts, surfaces, occluders, objects, render). Outputs are
written to a temporary file and renamed, so an interrupted run never leaves a half-written file.
Ctrl-C stops within a second.

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
  std::string output, layers, progressCsv, albedo, direct, gathered, physical, method = "ours",
                                                                               sceneForEstimate;
  std::string lightsJson, replaceLights, replaceAlbedo, replaceRadiance, surfaceAlbedo, cue,
      report;          // cue: empty = the default
  std::string solver;  // decompose --solver: empty = the lighting's own decomposition
  std::optional<double> prior, minImprovement, minSrgbResidual, noiseQuantile, maxTopStops, maxDarkFill;
  std::optional<double> edgeWeight;
  std::string evaluateAt;  // response diagnostics: "power,toe,shoulder"
  bool initialLights = false;
  bool sunsFromBounce = false;  // --suns-from-bounce
  std::optional<int> spp, seed, threads, iterations, prepareSeed;
  std::optional<double> keepBetterFitTolerance;  // --keep-better-fit-tolerance
  std::optional<double> refitMinMove;            // --refit-min-move
  std::optional<double> windowReveal;            // --window-reveal
  std::optional<Vec3> fitUnseenCeiling;          // --fit-unseen-ceiling R,G,B
  std::string unseenCeiling = "fit";             // --unseen-ceiling walls|fit|fit-render
  std::optional<double> seconds, noise;
  std::optional<double> workingMp;              // --working-mp
  std::optional<double> quickMargin;            // --response-quick-margin (inf: the full check always)
  std::optional<ResponseQuickCheck> quickCopy;  // --response-quick-copy N,F,P[,T]
  std::optional<double> clampIndirect;          // --clamp-indirect (0: off); else render.clamp_indirect
  std::optional<int> causticPhotons;            // --caustic-photons
  std::optional<double> causticRadius;          // --caustic-radius
  std::optional<double> pixelFilter;            // --pixel-filter (0: the box)
  bool quiet = false;
  bool verbose = false;
  bool noFocus = false;
  bool noGrain = false;
  bool noResponseCheck = false;  // --no-response-check
  std::optional<bool> denoise;   // --denoise / --no-denoise; unset: the command's default
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

// The options followed by a value.
bool takesValue(const std::string& option) {
  static const std::string options =
      "-o --output --layers --progress-csv --albedo --direct --gathered --physical --method "
      "--scene --spp --seconds --noise --seed --threads --iterations --lights-json "
      "--replace-lights --replace-albedo --cue --replace-radiance --surface-albedo --prior "
      "--evaluate-at --min-improvement --report --min-srgb-residual --noise-quantile "
      "--working-mp --max-top-stops --response-quick-margin --response-quick-copy "
      "--clamp-indirect --max-dark-fill --edge-weight --prepare-seed "
      "--keep-better-fit-tolerance --refit-min-move --fit-unseen-ceiling --caustic-photons --window-reveal "
      "--unseen-ceiling --caustic-radius --pixel-filter --solver ";
  if (option.empty() || option.find(' ') != std::string::npos) return false;
  return (" " + options).find(" " + option + " ") != std::string::npos;
}

// The light fit's diagnostics that take a value (--unseen-ceiling, --fit-unseen-ceiling,
// --keep-better-fit-tolerance, --window-reveal, --refit-min-move): nullopt when `s` is none of
// them, else an error message (empty: parsed into `a`).
std::optional<std::string> parseLightFitDiagnostic(const std::string& s, const std::string& v, Args& a) {
  if (s == "--unseen-ceiling") {
    if (v != "walls" && v != "fit" && v != "fit-render")
      return "--unseen-ceiling: '" + v + "' is not walls, fit or fit-render";
    a.unseenCeiling = v;
  } else if (s == "--fit-unseen-ceiling") {
    double r = -1, g = -1, b = -1;
    char tail = 0;
    if (std::sscanf(v.c_str(), "%lf,%lf,%lf%c", &r, &g, &b, &tail) != 3 ||
        !(r >= 0 && g >= 0 && b >= 0) || !std::isfinite(r + g + b))
      return "--fit-unseen-ceiling: '" + v + "' is not three non-negative numbers R,G,B";
    a.fitUnseenCeiling = Vec3(r, g, b);
  } else if (s == "--keep-better-fit-tolerance") {
    a.keepBetterFitTolerance = parseNumber<double>(v);
    if (!a.keepBetterFitTolerance)
      return "--keep-better-fit-tolerance: '" + v + "' is not a non-negative fraction";
  } else if (s == "--window-reveal") {
    a.windowReveal = parseNumber<double>(v);
    if (!a.windowReveal || !(*a.windowReveal <= 10))
      return "--window-reveal: '" + v + "' is not a depth in metres from 0 to 10";
  } else if (s == "--refit-min-move") {
    a.refitMinMove = parseNumber<double>(v);
    if (!a.refitMinMove) return "--refit-min-move: '" + v + "' is not a non-negative fraction";
  } else {
    return std::nullopt;
  }
  return std::string();
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
    if (takesValue(s)) {
      const auto v = value(s.c_str());
      if (!v) return s + " needs a value";
      if (s == "-o" || s == "--output") a.output = *v;
      else if (s == "--layers") a.layers = *v;
      else if (s == "--progress-csv") a.progressCsv = *v;
      else if (s == "--albedo") a.albedo = *v;
      else if (s == "--direct") a.direct = *v;
      else if (s == "--gathered") a.gathered = *v;
      else if (s == "--physical") a.physical = *v;
      else if (s == "--method") a.method = *v;
      else if (s == "--solver") a.solver = *v;
      else if (s == "--scene") a.sceneForEstimate = *v;
      else if (s == "--lights-json") a.lightsJson = *v;
      else if (s == "--report") a.report = *v;
      else if (s == "--replace-lights") a.replaceLights = *v;
      else if (s == "--replace-albedo") a.replaceAlbedo = *v;
      else if (s == "--replace-radiance") a.replaceRadiance = *v;
      else if (s == "--surface-albedo") a.surfaceAlbedo = *v;
      else if (s == "--cue") a.cue = *v;
      else if (s == "--evaluate-at") a.evaluateAt = *v;
      else if (const auto e = parseLightFitDiagnostic(s, *v, a)) {
        if (!e->empty()) return *e;
      } else if (s == "--response-quick-margin") {
        a.quickMargin = *v == "inf" ? std::optional<double>(std::numeric_limits<double>::infinity())
                                    : parseNumber<double>(*v);
        if (!a.quickMargin || !(*a.quickMargin >= 0))
          return "--response-quick-margin: '" + *v + "' is not a non-negative number or \"inf\"";
      } else if (s == "--response-quick-copy") {
        ResponseQuickCheck q;
        char tail = 0;
        int refine = int(q.refineLights);
        const int n = std::sscanf(v->c_str(), "%lf,%d,%d,%lf,%d%c", &q.maxPixels, &q.fitPixels,
                                  &q.maxPasses, &q.fitTolerance, &refine, &tail);
        q.refineLights = refine == 1;
        if (n < 3 || n > 5 || !(q.maxPixels >= 0) || q.fitPixels < 1 || q.maxPasses < 1 ||
            !(q.fitTolerance > 0 && q.fitTolerance < 1) || (refine != 0 && refine != 1))
          return "--response-quick-copy: '" + *v +
                 "' is not PIXELS,FIT_PIXELS,PASSES[,TOLERANCE[,REFINE]]";
        a.quickCopy = q;
      } else if (s == "--working-mp") {
        a.workingMp = parseNumber<double>(*v);
        if (!a.workingMp) return "--working-mp: '" + *v + "' is not a non-negative number of megapixels";
      } else if (s == "--min-improvement") {
        a.minImprovement = parseNumber<double>(*v);
        if (!a.minImprovement || *a.minImprovement >= 1)
          return "--min-improvement: '" + *v + "' is not a number in [0, 1)";
      } else if (s == "--min-srgb-residual") {
        a.minSrgbResidual = parseNumber<double>(*v);
        if (!a.minSrgbResidual) return "--min-srgb-residual: '" + *v + "' is not a non-negative number";
      } else if (s == "--max-top-stops") {
        a.maxTopStops = parseNumber<double>(*v);
        if (!a.maxTopStops) return "--max-top-stops: '" + *v + "' is not a non-negative number of stops";
      } else if (s == "--max-dark-fill") {
        a.maxDarkFill = parseNumber<double>(*v);
        if (!a.maxDarkFill || *a.maxDarkFill > 1)
          return "--max-dark-fill: '" + *v + "' is not a number in [0, 1] (0: off)";
      } else if (s == "--edge-weight") {
        a.edgeWeight = parseNumber<double>(*v);
        if (!a.edgeWeight) return "--edge-weight: '" + *v + "' is not a non-negative number";
      } else if (s == "--noise-quantile") {
        a.noiseQuantile = parseNumber<double>(*v);
        if (!a.noiseQuantile || *a.noiseQuantile <= 0 || *a.noiseQuantile > 1)
          return "--noise-quantile: '" + *v + "' is not a number in (0, 1]";
      } else if (s == "--clamp-indirect") {
        const auto c = *v == "off" ? std::optional<double>(0.0) : parseNumber<double>(*v);
        if (!c) return "--clamp-indirect: '" + *v + "' is not a non-negative number or \"off\"";
        a.clampIndirect = *c;
      } else if (s == "--pixel-filter") {
        a.pixelFilter = *v == "box" ? std::optional<double>(0.0) : parseNumber<double>(*v);
        if (!a.pixelFilter || !(*a.pixelFilter >= 0) || !(*a.pixelFilter <= 8))
          return "--pixel-filter: '" + *v + "' is not a width in pixels in [0, 8] or \"box\"";
      } else if (s == "--caustic-radius") {
        a.causticRadius = parseNumber<double>(*v);
        if (!a.causticRadius || !(*a.causticRadius > 0))
          return "--caustic-radius: '" + *v + "' is not a positive fraction";
      } else if (s == "--prior") {
        a.prior = parseNumber<double>(*v);
        if (!a.prior) return "--prior: '" + *v + "' is not a non-negative number";
      } else if (s == "--seconds") {
        a.seconds = parseNumber<double>(*v);
        if (!a.seconds) return "--seconds: '" + *v + "' is not a non-negative number";
      } else if (s == "--noise") {
        a.noise = parseNumber<double>(*v);
        if (!a.noise || *a.noise >= 1) return "--noise: '" + *v + "' is not a number in [0, 1)";
      } else {
        const auto n = parseNumber<int>(*v);
        if (!n) return s + ": '" + *v + "' is not a non-negative whole number";
        if (s == "--spp") {
          if (*n < 1) return "--spp must be at least 1";
          a.spp = n;
        } else if (s == "--seed") a.seed = n;
        else if (s == "--prepare-seed") a.prepareSeed = n;
        else if (s == "--caustic-photons") a.causticPhotons = n;
        else if (s == "--iterations") {
          if (*n < 1) return "--iterations must be at least 1";
          a.iterations = n;
        } else a.threads = n;
      }
    } else if (s == "--quiet" || s == "-q") {
      a.quiet = true;
    } else if (s == "--verbose" || s == "-v") {
      a.verbose = true;
    } else if (s == "--no-focus") {
      a.noFocus = true;
    } else if (s == "--no-grain") {
      a.noGrain = true;
    } else if (s == "--no-response-check") {
      a.noResponseCheck = true;
    } else if (s == "--denoise" || s == "--no-denoise") {
      a.denoise = s == "--denoise";
    } else if (s == "--initial-lights") {
      a.initialLights = true;
    } else if (s == "--suns-from-bounce") {
      a.sunsFromBounce = true;
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
      std::fprintf(stderr, "inlay-cli: render %d spp, %.1f s, estimated error %.4f\n", f.spp, f.seconds,
                   f.estimatedError);
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

// Progress on the terminal and the optional progress CSV, for each frame of a render.
std::function<void(const RenderFrame&)> reportFrames(Progress& progress, std::ofstream* csv,
                                                     int targetSpp, double seconds) {
  return [&progress, csv, targetSpp, seconds](const RenderFrame& f) {
    double fraction = double(f.spp) / std::max(1, targetSpp);
    if (seconds > 0) fraction = std::max(fraction, f.seconds / seconds);
    progress.frame(f, std::min(1.0, fraction));
    if (csv && f.spp > 0)
      *csv << f.seconds << "," << f.spp << "," << f.estimatedError << "\n" << std::flush;
  };
}

// The preparation's stages: each with its seconds, or the reason this scene skipped it.
nlohmann::json stagesJson(const std::vector<StageRecord>& stages) {
  nlohmann::json out = nlohmann::json::array();
  for (const StageRecord& s : stages) {
    nlohmann::json j = {{"name", s.name}, {"ran", s.ran}};
    if (s.ran) {
      j["seconds"] = s.seconds;
      j["cpu_seconds"] = s.cpuSeconds;
    } else {
      j["skipped"] = s.reason;
    }
    if (s.workingWidth > 0) j["working_px"] = {s.workingWidth, s.workingHeight};
    if (!s.detail.empty()) j["detail"] = s.detail;
    for (const StageStep& step : s.steps)
      j["steps"].push_back(
          {{"name", step.name}, {"seconds", step.seconds}, {"cpu_seconds", step.cpuSeconds}});
    out.push_back(std::move(j));
  }
  return out;
}

// The [name, seconds] pairs of the stages that ran (--lights-json's "stage_seconds").
nlohmann::json stageSecondsJson(const std::vector<StageRecord>& stages) {
  nlohmann::json out = nlohmann::json::array();
  for (const StageRecord& s : stages)
    if (s.ran) out.push_back({s.name, s.seconds});
  return out;
}

// --report: what the preparation did, stage by stage, and its warnings.
nlohmann::json prepareReport(const PreparedScene& ps) {
  double total = 0;
  for (const StageRecord& s : ps.stages) total += s.seconds;
  return {{"stages", stagesJson(ps.stages)},
          {"seconds", total},
          {"photo_px", {ps.photo.linearRgb.width, ps.photo.linearRgb.height}},
          {"working_px", {ps.workingPx[0], ps.workingPx[1]}},
          {"warnings", ps.warnings}};
}

Expected<PreparedScene> loadAndPrepare(const std::string& scenePath, const Args& a, Progress& progress) {
  // Before the long preparation: a report that cannot be written is known now.
  if (!a.report.empty()) {
    const std::filesystem::path folder = std::filesystem::absolute(a.report).parent_path();
    std::error_code ec;
    if (!std::filesystem::is_directory(folder, ec))
      return Error{a.report, "--report", "its folder does not exist"};
  }
  auto loaded = loadSceneFile(scenePath);
  if (!loaded) return loaded.error();
  for (const auto& w : loaded->warnings)
    if (!progress.quiet()) std::fprintf(stderr, "inlay-cli: warning: %s\n", w.c_str());
  PrepareOptions po;
  po.cancel = &gCancel;
  po.threads = a.threads.value_or(0);
  po.progress = [&](const std::string& stage, double f) { progress.stage(stage, f); };
  po.refineLights = !a.initialLights;
  po.sunsFromBounce = a.sunsFromBounce;
  if (a.prepareSeed) po.seed = uint32_t(*a.prepareSeed);
  if (a.keepBetterFitTolerance) po.keepBetterFitTolerance = *a.keepBetterFitTolerance;
  if (a.refitMinMove) po.refitMinLightMove = *a.refitMinMove;
  if (a.windowReveal) po.windowRevealDepthM = *a.windowReveal;
  if (a.fitUnseenCeiling) po.fitUnseenCeilingAlbedo = *a.fitUnseenCeiling;
  po.fitUnseenCeiling = a.unseenCeiling != "walls";
  po.renderFittedCeiling = a.unseenCeiling == "fit-render";
  if (a.noResponseCheck) po.checkResponseByLightFit = false;
  if (a.quickMargin) po.responseQuick.margin = *a.quickMargin;
  if (a.quickCopy) {
    const double margin = po.responseQuick.margin;
    po.responseQuick = *a.quickCopy;
    po.responseQuick.margin = margin;
  }
  // The response estimate's evidence gate (diagnostics, as for inlay-cli response).
  if (a.minImprovement) po.responseEstimate.minImprovement = *a.minImprovement;
  if (a.minSrgbResidual) po.responseEstimate.minSrgbResidual = *a.minSrgbResidual;
  // decompose writes the decomposition itself: at the photo's own size.
  po.workingMaxPixels = a.command == "decompose" ? 0.0
                        : a.workingMp            ? *a.workingMp * 1e6
                                                 : kWorkingMaxPixels;
  auto prepared = prepareScene(loaded->doc, po);
  if (!prepared) {
    Error e = prepared.error();
    if (e.file.empty()) e.file = scenePath;
    return e;
  }
  for (const auto& w : prepared->warnings)
    if (!progress.quiet()) std::fprintf(stderr, "inlay-cli: warning: %s\n", w.c_str());
  // --verbose: the stages even with --quiet (it was asked for).
  if (a.verbose)
    for (const StageRecord& s : prepared->stages)
      std::fprintf(stderr, "inlay-cli: stage %s\n", describeStage(s).c_str());
  if (!a.report.empty())
    if (auto st = writeFileAtomically(a.report, prepareReport(*prepared).dump(1) + "\n"); !st)
      return st.error();
  if (!progress.quiet()) {
    const auto& e = prepared->responseEstimate;
    std::fprintf(
        stderr, "inlay-cli: camera response: %s%s\n", prepared->response.describe().c_str(),
        e ? (" (estimated from " +
             (e->noiseBins > 0 ? "the photo's noise at " + std::to_string(e->noiseBins) + " levels"
                               : std::to_string(e->edgesUsed) + " edges") +
             " in " + std::to_string(int(std::lround(1000 * e->seconds))) + " ms)")
                .c_str()
          : " (camera.response)");
  }
  return prepared;
}

nlohmann::json lightsJsonOf(const std::vector<AreaLight>& lights) {
  using nlohmann::json;
  json a = json::array();
  for (const AreaLight& L : lights) {
    json corners = json::array();
    for (const Vec3& c : L.cornersWorld) corners.push_back({c.x(), c.y(), c.z()});
    const Vec3 c = L.centre();
    a.push_back({{"corners", corners},
                 {"centre", {c.x(), c.y(), c.z()}},
                 {"rgb", {L.radiance.x(), L.radiance.y(), L.radiance.z()}}});
  }
  return a;
}

// --lights-json's "unseen_ceiling": the light fit's estimate of an unseen ceiling's albedo (null
// where it made none), per channel whether the photo told it, and the albedo the render gives
// the ceiling.
nlohmann::json unseenCeilingJson(const PreparedScene& ps) {
  const LightingEstimate& l = ps.lighting;
  const Vec3& a = l.unseenCeilingAlbedo;
  nlohmann::json rendered = nullptr;
  for (size_t s = 0; s < ps.geometry.surfaces.size() && s < l.surfaceMeanAlbedo.size(); ++s)
    if (ps.geometry.surfaces[s].kind == SurfaceKind::Ceiling) {
      const Vec3& r = l.surfaceMeanAlbedo[s];
      rendered = {r.x(), r.y(), r.z()};
      break;
    }
  return {{"fitted", a.allFinite() ? nlohmann::json{a.x(), a.y(), a.z()} : nlohmann::json(nullptr)},
          {"told", {l.unseenCeilingTold[0], l.unseenCeilingTold[1], l.unseenCeilingTold[2]}},
          {"rendered", rendered}};
}

// --lights-json: the lights before and after refinement and what the refinement did.
nlohmann::json lightsReport(const PreparedScene& ps) {
  using nlohmann::json;
  const LightRefineResult& r = ps.refinement;
  json history = json::array();
  for (const auto& h : r.history) history.push_back({h.seconds, h.objective});
  auto sunsJson = [](const std::vector<SunLight>& suns) {
    json a = json::array();
    for (const auto& s : suns)
      a.push_back({{"rgb", {s.irradianceOverPi.x(), s.irradianceOverPi.y(), s.irradianceOverPi.z()}}});
    return a;
  };
  return {{"initial", lightsJsonOf(ps.initialLights)},
          {"refined", lightsJsonOf(ps.lighting.lights)},
          {"stage_seconds", stageSecondsJson(ps.stages)},
          {"stages", stagesJson(ps.stages)},
          {"suns_initial", sunsJson(ps.initialSuns)},
          {"suns_refined", sunsJson(ps.lighting.suns)},
          {"unseen_ceiling", unseenCeilingJson(ps)},
          {"fit",  // the last light fit's residual (LightingEstimate::fitResidualRelative, fitRmsLog)
           {{"residual_relative", ps.lighting.fitResidualRelative}, {"rms_log", ps.lighting.fitRmsLog}}},
          {"vignetting",  // the last light fit's residual read as 1 - v r^2; camera.vignetting's choice
           {{"v", ps.lighting.vignetting},
            {"residual_ratio", ps.lighting.vignettingResidualRatio},
            {"estimated_before_devignetting", ps.vignettingEstimated},  // camera.vignetting
            {"applied", ps.vignetting}}},
          {"refinement",
           {{"ran", !r.history.empty()},
            {"seconds", r.seconds},
            {"pixels", r.pixels},
            {"evaluations", r.evaluations},
            {"stopped_by_budget", r.stoppedByBudget},  // LightRefineOptions::maxEvaluations
            {"stopped_by_time_guard", r.stoppedByGuard},
            {"initial_objective", r.initialObjective},
            {"final_objective", r.finalObjective},
            {"initial_data_term", r.initialDataTerm},
            {"final_data_term", r.finalDataTerm},
            {"history", history},
            {"report", r.report},
            {"notes", r.notes}}}};
}

// --surface-albedo FILE.json (diagnostics): {"ceiling": [r, g, b], ...}, the albedo the render
// gives each named room surface where the camera does not see it.
Status applySurfaceAlbedo(RenderScene& rs, const std::string& path) {
  std::ifstream in(path);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object())
    return Error{path, "--surface-albedo", "expected a JSON object {\"ceiling\": [r, g, b], ...}"};
  for (const auto& [name, v] : j.items()) {
    const auto it = std::find_if(rs.room.surfaces.begin(), rs.room.surfaces.end(),
                                 [&](const Surface& sf) { return sf.name == name; });
    if (it == rs.room.surfaces.end())
      return Error{path, name, "no room surface of this name (floor, ceiling, wall_left, ...)"};
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
      return Error{path, name, "expected three numbers in [0, 1]"};
    const Vec3 rgb(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
    if (!(rgb.minCoeff() >= 0 && rgb.maxCoeff() <= 1))
      return Error{path, name, "expected three numbers in [0, 1]"};
    rs.roomAlbedo.surfaceMean[size_t(it - rs.room.surfaces.begin())] = rgb;
  }
  return {};
}

// --replace-radiance FILE.exr (diagnostics): where the photo clips (a channel at 0.98 or more),
// the radiance the render's bounces read is the file's (at least the photo's), not the light
// model's: the truth's sunlit patch in place of the fitted sun's.
Status applyRadiance(RenderScene& rs, const ImageF& photo, const std::string& path) {
  auto img = loadImage(path);
  if (!img) return img.error().underKey("--replace-radiance");
  const ImageF& r = img->linearRgb;
  ImageF& out = rs.roomAlbedo.photoRadiance;
  if (r.width != photo.width || r.height != photo.height || out.width != photo.width ||
      out.height != photo.height)
    return Error{path, "--replace-radiance", "not the photo's size"};
  for (int y = 0; y < photo.height; ++y)
    for (int x = 0; x < photo.width; ++x) {
      const Vec3 v = r.rgb(x, y);
      if (photo.rgb(x, y).maxCoeff() >= 0.98 && v.allFinite())
        out.setRgb(x, y, v.cwiseMax(photo.rgb(x, y)));
    }
  return {};
}

// --replace-lights / --replace-albedo (diagnostics: which of lights and albedo limits the error).
Status applyReplacements(PreparedScene& ps, const Args& a) {
  RenderScene& rs = ps.renderScene;
  if (!a.replaceLights.empty()) {
    std::ifstream in(a.replaceLights);
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    const char* list = j.is_object() && j.contains("refined") ? "refined" : "lights";
    if (!j.is_object() || !j.contains(list) || !j[list].is_array())
      return Error{a.replaceLights, "--replace-lights",
                   "expected a JSON object with a \"lights\" array"};
    rs.lights.clear();
    for (size_t i = 0; i < j[list].size(); ++i) {
      const auto& l = j[list][i];
      const std::string key = std::string(list) + "[" + std::to_string(i) + "]";
      AreaLight L;
      try {
        for (size_t k = 0; k < 4; ++k)
          L.cornersWorld[k] = Vec3(l.at("corners").at(k).at(0), l.at("corners").at(k).at(1),
                                   l.at("corners").at(k).at(2));
        L.radiance = Vec3(l.at("rgb").at(0), l.at("rgb").at(1), l.at("rgb").at(2));
      } catch (const std::exception&) {
        return Error{a.replaceLights, key,
                     "expected \"corners\" (4 x 3 numbers) and \"rgb\" (3 numbers)"};
      }
      if (!L.radiance.allFinite() || !(L.area() > 0))
        return Error{a.replaceLights, key, "not a finite light with an area"};
      rs.lights.push_back(L);
    }
  }
  if (!a.replaceAlbedo.empty()) {
    auto img = loadImage(a.replaceAlbedo);
    if (!img) return img.error().underKey("--replace-albedo");
    const ImageF& alb = img->linearRgb;
    if (alb.width != rs.roomAlbedo.albedo.width || alb.height != rs.roomAlbedo.albedo.height)
      return Error{a.replaceAlbedo, "--replace-albedo", "not the photo's size"};
    rs.roomAlbedo.albedo = alb;
    // The surfaces' means (for what the camera does not see) from the new albedo.
    std::vector<Vec3> sum(rs.roomAlbedo.surfaceMean.size(), Vec3::Zero());
    std::vector<double> n(sum.size(), 0);
    for (size_t i = 0; i < rs.roomAlbedo.firstSurfacePerPixel.size(); ++i) {
      const int s = rs.roomAlbedo.firstSurfacePerPixel[i];
      if (s < 0 || size_t(s) >= sum.size()) continue;
      sum[size_t(s)] += alb.rgb(int(i % size_t(alb.width)), int(i / size_t(alb.width)));
      n[size_t(s)] += 1;
    }
    for (size_t s = 0; s < sum.size(); ++s)
      if (n[s] > 0) sum[s] /= n[s];
    // What the camera does not see takes the product's rule, applied to the new albedo (not
    // the estimate's guess: an all-true oracle must not keep the estimated unseen ceiling).
    rs.roomAlbedo.surfaceMean = albedoOfUnseen(rs.room, sum, n, kUnseenCeilingAlbedo);
  }
  if (!a.replaceRadiance.empty())
    if (auto st = applyRadiance(rs, ps.photo.linearRgb, a.replaceRadiance); !st) return st;
  if (!a.surfaceAlbedo.empty()) return applySurfaceAlbedo(rs, a.surfaceAlbedo);
  return {};
}

// The path tracer's settings: the scene's clamp of indirect light, and the command line's caustic
// photons (off unless asked).
TracerOptions tracerOptions(const Args& a, double clampIndirect) {
  TracerOptions t;
  t.clampRadiance = clampIndirect;
  if (a.causticPhotons) t.causticPhotons = *a.causticPhotons;
  if (a.causticRadius) t.causticRadius = *a.causticRadius;
  if (a.pixelFilter) t.pixelFilterWidth = *a.pixelFilter;
  return t;
}

int commandRender(const std::string& scenePath, const Args& a, bool denoiseByDefault = false) {
  if (a.output.empty()) return usageError("render needs -o OUT.png");
  Progress progress(a.quiet);
  auto prepared = loadAndPrepare(scenePath, a, progress);
  if (gInterrupted) return std::fprintf(stderr, "inlay-cli: interrupted\n"), 1;
  if (!prepared) return inputError(prepared.error());
  PreparedScene& ps = *prepared;

  if (auto st = applyReplacements(ps, a); !st) return inputError(st.error());
  if (a.noGrain) ps.doc.render.grain = false;
  if (!a.quiet && ps.doc.render.grain)
    std::fprintf(stderr, "inlay-cli: %s\n", describeNoise(ps.photoNoise).c_str());
  if (!a.lightsJson.empty())
    if (auto st = writeFileAtomically(a.lightsJson, lightsReport(ps).dump(1) + "\n"); !st)
      return inputError(st.error());

  SessionOptions so;
  so.targetSpp = a.spp.value_or(ps.doc.render.spp);
  so.seconds = a.seconds.value_or(ps.doc.render.seconds.value_or(0.0));
  so.seed = uint32_t(a.seed.value_or(int(ps.doc.render.seed)));
  so.threads = a.threads.value_or(0);
  so.startDivider = 1;  // no preview in batch mode
  if (a.clampIndirect) ps.doc.render.clampIndirect = *a.clampIndirect;
  so.tracer = tracerOptions(a, ps.doc.render.clampIndirect);
  // Samples go where the objects change the photo; untouched pixels are revisited every fourth
  // wave (render/session.h).
  so.focusOnChanges = !a.noFocus;
  // Adaptive sampling to the scene's noise target (render/session.h); --no-focus alone keeps
  // the uniform schedule it always meant.
  so.noiseTarget = a.noise.value_or(a.noFocus ? 0.0 : ps.doc.render.noise);
  // render/denoise.h; only the final frame is written, so only it is denoised.
  so.denoise = a.denoise.value_or(denoiseByDefault) ? SessionOptions::Denoise::Final
                                                    : SessionOptions::Denoise::Off;
  std::ofstream csv;
  if (!a.progressCsv.empty()) {
    csv.open(a.progressCsv);
    if (!csv) return inputError(Error{a.progressCsv, "--progress-csv", "cannot be written"});
    csv << "seconds,spp,estimated_error\n";
  }
  LastFrameSink sink(
      reportFrames(progress, a.progressCsv.empty() ? nullptr : &csv, so.targetSpp, so.seconds));
  {
    RenderSession session(&sink, so);
    session.setScene(shownRenderScene(ps));
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
  SaveOptions save;
  save.response = outputResponseOf(ps);
  if (auto st = saveImage(a.output, composite, save); !st) return inputError(st.error());
  if (!a.layers.empty()) {
    ImageF with = frame->withObjects, without = frame->withoutObjects;
    const ImageF clean = compositeOf(ps, *frame, /*withGrain=*/false);  // the layers stay clean
    std::vector<NamedLayer> layers = {{"composite", &clean},
                                      {"with_objects", &with},
                                      {"without_objects", &without},
                                      {"mask", &frame->mask}};
    if (!frame->samples.empty()) layers.push_back({"samples", &frame->samples});
    if (!frame->noise.empty()) layers.push_back({"noise", &frame->noise});
    if (auto st = saveLayersExr(a.layers, layers); !st) return inputError(st.error());
  }
  if (!a.quiet)
    std::fprintf(
        stderr,
        "inlay-cli: wrote %s (%d spp at most, %.1f on average, %.1f s render, estimated error %.4f%s%s)\n",
        a.output.c_str(), frame->spp, frame->meanSpp, frame->seconds, frame->estimatedError,
        frame->converged ? ", converged" : "", frame->denoised ? ", denoised" : "");
  return 0;
}

int commandExport(const std::string& scenePath, const Args& a) {
  if (a.output.empty()) return usageError("export needs -o SCENE.gltf or SCENE.glb");
  const std::string ext = std::filesystem::path(a.output).extension().string();
  if (ext != ".gltf" && ext != ".glb" && ext != ".GLTF" && ext != ".GLB")
    return inputError(Error{a.output, "-o", "the export file must end in .gltf or .glb"});
  Progress progress(a.quiet);
  auto prepared = loadAndPrepare(scenePath, a, progress);
  if (gInterrupted) return std::fprintf(stderr, "inlay-cli: interrupted\n"), 1;
  if (!prepared) return inputError(prepared.error());
  std::vector<std::string> warnings;
  if (auto st = exportSceneGltf(*prepared, a.output, &warnings); !st) return inputError(st.error());
  progress.done();
  for (const auto& w : warnings)
    if (!a.quiet) std::fprintf(stderr, "inlay-cli: warning: %s\n", w.c_str());
  if (!a.quiet) std::fprintf(stderr, "inlay-cli: wrote %s\n", a.output.c_str());
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
  if (!cl)
    return inputError(cl.error().inFile(a.sceneForEstimate.empty() ? photoPath : a.sceneForEstimate));
  const CameraEstimate& est = *cl->estimate;
  const Camera& cam = cl->camera;
  const std::array<Vec2, 3> vps = fixed.camera.vanishingPointsPx ? *fixed.camera.vanishingPointsPx
                                                                 : est.vanishingPointsPx;
  using nlohmann::json;
  auto pt = [](const Vec2& p) { return json::array({p.x(), p.y()}); };
  json j;
  j["camera"] = {{"height_m", cam.heightM},
                 {"focal_px", cam.focalPx},
                 {"principal_px", pt(cam.principalPx)},
                 {"vanishing_points_px", json::array({pt(vps[0]), pt(vps[1]), pt(vps[2])})}};
  j["layout"] = {{"back_wall_px", json::array({pt(cl->backWallPx[0]), pt(cl->backWallPx[1]),
                                               pt(cl->backWallPx[2]), pt(cl->backWallPx[3])})}};
  json rot = json::array();
  for (int r = 0; r < 3; ++r)
    rot.push_back(
        json::array({cam.worldFromCamera(r, 0), cam.worldFromCamera(r, 1), cam.worldFromCamera(r, 2)}));
  j["rotation"] = rot;
  j["confidence"] = {
      {"vanishing_points", json::array({est.confidence[0], est.confidence[1], est.confidence[2]})},
      {"overall", est.overallConfidence},
      {"manhattan", est.manhattan},
      {"layout", est.layoutScore}};
  // What each vanishing point rests on (the studio shows the same from CameraEstimate).
  json vpInfo = json::array();
  for (const VanishingPointInfo& v : est.vanishingPoints)
    vpInfo.push_back(
        {{"homogeneous_px", {v.homogeneousPx.x(), v.homogeneousPx.y(), v.homogeneousPx.z()}},
         {"at_infinity", v.atInfinity},
         {"segments", v.segmentCount},
         {"support_length_px", v.supportLengthPx},
         {"rms_residual_px", v.rmsResidualPx},
         {"angular_sigma_deg", v.angularSigmaDeg},
         {"confidence", v.confidence},
         {"nearly_parallel", v.nearlyParallel}});
  j["vanishing_point_support"] = vpInfo;
  j["focal_interval_px"] = json::array({est.focalMinPx, est.focalMaxPx});
  j["focal_from_prior"] = est.focalFromPrior;
  j["principal_sigma_px"] = pt(est.principalSigmaPx);
  j["principal_from_prior"] = est.principalFromPrior;
  j["warnings"] = est.warnings;
  j["timings_ms"] = {{"lines", est.timings.linesMs},
                     {"vanishing", est.timings.vanishingMs},
                     {"refine", est.timings.refineMs},
                     {"layout", est.timings.layoutMs},
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

const char* cueName(ResponseEstimateOptions::Cue cue) {
  using Cue = ResponseEstimateOptions::Cue;
  return cue == Cue::Noise         ? "noise"
         : cue == Cue::NoiseColour ? "noise-colour"
         : cue == Cue::Symmetry    ? "symmetry"
         : cue == Cue::Colour      ? "colour"
                                   : "both";
}

// The cue `name` (as cueName writes it), or none.
std::optional<ResponseEstimateOptions::Cue> cueNamed(const std::string& name) {
  using Cue = ResponseEstimateOptions::Cue;
  for (const Cue cue : {Cue::Noise, Cue::NoiseColour, Cue::Symmetry, Cue::Colour, Cue::Both})
    if (name == cueName(cue)) return cue;
  return std::nullopt;
}

// RESPONSE.json: the camera response of a scene's photo (its camera.response, estimated when
// "auto") or of a bare photo (estimated), with the 256 codes' linear values.
int commandResponse(const std::string& input, const Args& a) {
  if (a.output.empty()) return usageError("response needs -o RESPONSE.json");
  ResponseEstimateOptions o;
  o.cancel = &gCancel;
  if (!a.cue.empty()) {
    const auto cue = cueNamed(a.cue);
    if (!cue)
      return usageError("--cue " + a.cue +
                        ": expected 'noise', 'noise-colour', 'symmetry', 'colour' or 'both'");
    o.cue = *cue;
  }
  if (a.edgeWeight) o.edgeWeight = *a.edgeWeight;
  if (a.prior) o.priorWeight = *a.prior;
  if (a.minImprovement) o.minImprovement = *a.minImprovement;
  if (a.minSrgbResidual) o.minSrgbResidual = *a.minSrgbResidual;
  if (a.noiseQuantile) o.noiseQuantile = *a.noiseQuantile;
  if (a.maxTopStops) o.maxTopStops = *a.maxTopStops;
  if (a.maxDarkFill) o.maxDarkFill = *a.maxDarkFill;
  if (!a.evaluateAt.empty()) {
    ResponseParams q;
    if (std::sscanf(a.evaluateAt.c_str(), "%lf,%lf,%lf", &q.power, &q.toe, &q.shoulder) != 3)
      return usageError("--evaluate-at: expected POWER,TOE,SHOULDER");
    o.evaluateAt = q;
  }
  ResponseKeys keys;
  std::string photoPath = input;
  std::string ext = std::filesystem::path(input).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  const bool scene = ext == ".json";
  if (scene) {
    auto loaded = loadSceneFile(input);
    if (!loaded) return inputError(loaded.error());
    for (const auto& w : loaded->warnings)
      if (!a.quiet) std::fprintf(stderr, "inlay-cli: warning: %s\n", w.c_str());
    keys = loaded->doc.camera.response;
    photoPath = loaded->doc.photoResolved.empty() ? loaded->doc.photo : loaded->doc.photoResolved;
  }
  auto photo = loadImage(photoPath, ImageLimits::photo());
  if (!photo) return inputError(scene ? photo.error().underKey("photo").inFile(input) : photo.error());
  const ChosenResponse c = responseOf(keys, *photo, o);
  if (gInterrupted) return std::fprintf(stderr, "inlay-cli: interrupted; nothing written\n"), 1;
  using nlohmann::json;
  const CameraResponse& r = c.response;
  json j;
  j["family"] = r.familyName();
  j["description"] = r.describe();
  j["parameters"] = {
      {"power", r.params().power}, {"toe", r.params().toe}, {"shoulder", r.params().shoulder}};
  j["source"] = !photo->wasSrgbEncoded ? "linear photo" : c.estimate ? "estimated" : "camera.response";
  j["warnings"] = c.warnings;
  json table = json::array();
  for (float v : r.table8()) table.push_back(v);
  j["table"] = table;  // code k (0..255) -> linear radiance, code 255 -> 1
  if (c.estimate) {
    const ResponseEstimate& e = *c.estimate;
    json history = json::array();
    for (const auto& [sec, obj] : e.history) history.push_back({sec, obj});
    j["estimate"] = {{"determined", e.determined},
                     {"decision", e.decision},
                     {"cue", cueName(o.cue)},
                     {"prior_weight", o.priorWeightOrDefault()},
                     {"shape_prior_weight", o.shapePriorWeightOrDefault()},
                     {"min_improvement", o.minImprovementOrDefault()},
                     {"min_srgb_residual", o.minSrgbResidualOrDefault()},
                     {"noise_quantile", o.noiseQuantileOrDefault()},
                     {"max_top_stops", o.maxTopStops},
                     {"min_top_levels", o.minTopLevels},
                     {"max_dark_fill", o.maxDarkFill.value_or(0.0)},
                     {"dark_fill_min_improvement", o.darkFillMinImprovement},
                     {"dark_fill", e.darkFill},
                     {"dark_fill_evidence", e.darkFillEvidence},
                     {"edges_used", e.edgesUsed},
                     {"noise_bins", e.noiseBins},
                     {"segments_found", e.segmentsFound},
                     {"objective", e.objective},
                     {"srgb_objective", e.srgbObjective},
                     {"evidence", e.evidence},
                     {"srgb_evidence", e.srgbEvidence},
                     {"edge_weight", o.edgeWeightOrDefault()},
                     {"edge_note", e.edgeNote},
                     {"seconds", e.seconds},
                     {"cpu_seconds", e.cpuSeconds},
                     {"history", history}};
    json level = json::array();
    for (const auto& [code, sigma] : e.noiseLevel) level.push_back({code, sigma});
    j["estimate"]["noise_level"] = level;
  }
  if (auto st = writeFileAtomically(a.output, j.dump(1) + "\n"); !st) return inputError(st.error());
  if (!a.quiet) {
    for (const auto& w : c.warnings) std::fprintf(stderr, "inlay-cli: warning: %s\n", w.c_str());
    std::fprintf(stderr, "inlay-cli: wrote %s (%s)\n", a.output.c_str(), r.describe().c_str());
  }
  return 0;
}

// decompose --solver: the product's solver (default, DecomposeOptions' defaults), the one before
// issue #16 (scalar: one scalar step, cap 30), and the previous opt-in ones (diagonal steps with
// the coarse start, without and with the held pixels), those three stopping only on their
// residuals or a flat objective as before.
DecomposeOptions solverOptions(const std::string& solver) {
  DecomposeOptions o;
  if (solver.empty() || solver == "default") return o;
  o.gapTolerance = 0;
  o.holdInvalid = solver == "diagonal+hold";
  if (solver == "scalar") o.diagonalSteps = false, o.pyramidLevels = 0, o.maxIterations = 30;
  return o;
}

int commandDecompose(const std::string& scenePath, const Args& a) {
  if (a.albedo.empty()) return usageError("decompose needs --albedo ALBEDO.exr");
  if (a.seconds)  // the solver stops on convergence or an iteration cap, never on the clock
    return usageError("--seconds applies to render; decompose takes --iterations N");
  if (a.method != "ours" && a.method != "retinex")
    return usageError("--method " + a.method + ": expected 'ours' or 'retinex'");
  if (!a.solver.empty() && a.solver != "default" && a.solver != "scalar" && a.solver != "diagonal" &&
      a.solver != "diagonal+hold")
    return usageError("--solver " + a.solver +
                      ": expected 'default', 'scalar', 'diagonal' or 'diagonal+hold'");
  Progress progress(a.quiet);
  auto prepared = loadAndPrepare(scenePath, a, progress);
  if (gInterrupted) return std::fprintf(stderr, "inlay-cli: interrupted\n"), 1;
  if (!prepared) return inputError(prepared.error());
  const LightingEstimate& le = prepared->lighting;
  const bool retinex = a.method == "retinex";
  // --iterations N, --solver: re-run the solver from its start with that iteration cap (error
  // against solver time at a reproducible budget) and steps.
  std::optional<Decomposition> rerun;
  if (!retinex && (a.iterations || !a.solver.empty()) && !le.decomposeStart.empty()) {
    DecomposeOptions o = solverOptions(a.solver);
    if (a.iterations) o.maxIterations = *a.iterations;
    o.cancel = &gCancel;
    const double cpu0 = processCpuSeconds();
    auto d = decomposeIntrinsic(prepared->photo.linearRgb, le.gathered, le.decomposeStart,
                                le.decomposeValid, le.decomposeClipped, o);
    if (!d) return inputError(d.error());
    if (!a.quiet)  // the process is idle but for the solver now: its CPU time
      std::fprintf(stderr, "inlay-cli: decomposition re-run: %.3f s of CPU\n",
                   processCpuSeconds() - cpu0);
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
  if (auto st = saveImage(a.albedo, albedo, SaveOptions{false}); !st) return inputError(st.error());
  if (!a.direct.empty()) {
    ImageF direct = rerun ? rerun->direct : le.direct;
    if (retinex)  // D = B - rho Gamma for Retinex's rho
      for (size_t i = 0; i < direct.data.size() && i < le.gathered.data.size(); ++i)
        direct.data[i] =
            std::max(0.f, prepared->photo.linearRgb.data[i] - albedo.data[i] * le.gathered.data[i]);
    if (auto st = saveImage(a.direct, direct, SaveOptions{false}); !st) return inputError(st.error());
  }
  if (!a.gathered.empty())
    if (auto st = saveImage(a.gathered, le.gathered, SaveOptions{false}); !st)
      return inputError(st.error());
  if (!a.physical.empty())
    if (auto st = saveImage(a.physical, le.physicalAlbedo, SaveOptions{false}); !st)
      return inputError(st.error());
  // The solver's report goes to stderr even with --quiet when it stopped before converging.
  const bool converged = rerun ? rerun->converged : le.decomposeConverged;
  if (!retinex && !converged)
    std::fprintf(stderr, "inlay-cli: warning: decomposition %s\n",
                 (rerun ? rerun->report : le.decomposeReport).c_str());
  else if (!a.quiet && !retinex && !le.decomposeReport.empty())
    std::fprintf(stderr, "inlay-cli: decomposition %s\n",
                 (rerun ? rerun->report : le.decomposeReport).c_str());
  if (!a.quiet && std::isfinite(le.fitResidualRelative))
    std::fprintf(stderr,
                 "inlay-cli: light fit: relative residual %.5f (rms log %.5f); vignetting as the "
                 "residual shows it %.2f (residual x %.3f)\n",
                 le.fitResidualRelative, le.fitRmsLog, le.vignetting, le.vignettingResidualRatio);
  return 0;
}

// `batch` parses its own options (app/cli/batch.h).
int batchCommand(int argc, char** argv) {
  try {
    return inlay::cli::runBatch(argc, argv, gCancel, gInterrupted);
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "inlay-cli: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "inlay-cli: internal error: %s\n", e.what());
    return 1;
  }
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
  if (!std::strcmp(argv[1], "batch")) return batchCommand(argc - 1, argv + 1);
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
      return commandRender(scene, a, /*denoiseByDefault=*/true);
    }
    if (a.command == "decompose") {
      if (a.positional.size() != 1) return usageError("decompose needs exactly one SCENE.json");
      return commandDecompose(a.positional[0], a);
    }
    if (a.command == "export") {
      if (a.positional.size() != 1) return usageError("export needs exactly one SCENE.json");
      return commandExport(a.positional[0], a);
    }
    if (a.command == "response") {
      if (a.positional.size() != 1) return usageError("response needs exactly one SCENE.json or PHOTO");
      return commandResponse(a.positional[0], a);
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
