#include "batch.h"

#include "inlay/engine/pipeline.h"
#include "inlay/modeling/image_io.h"
#include "inlay/modeling/scene_file.h"
#include "inlay/render/session.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace inlay::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// The command line of `batch`.
struct BatchArgs {
  std::string manifest;
  int jobs = 1;
  int shard = 0, shards = 1;  // --shard K/N: this process takes scene groups g with g % N == K
  std::optional<int> spp, seed, threads;
  std::optional<double> seconds, noise;
  bool quiet = false;
  bool verbose = false;  // each scene's preparation stages on stderr
  bool denoise = false;  // --denoise (render/denoise.h)
};

// One manifest line, parsed.
struct BatchLine {
  int lineNumber = 0;            // 1-based, as an editor shows it
  std::string scene;             // absolute
  std::string output;            // absolute
  json objects = json::array();  // per-object overrides, merged into the scene's objects[i]
  json render = json::object();  // merged into the scene's render keys
};

// Lines sharing one scene file: prepared once.
struct SceneGroup {
  std::string scene;
  std::vector<size_t> lines;  // indices into the manifest's lines
};

struct Failure {
  int lineNumber = 0;
  std::string message;
  bool badInput = true;  // else an internal failure
};

std::optional<double> parseNonNegative(const std::string& s) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0' || !std::isfinite(v) || v < 0) return std::nullopt;
  return v;
}

std::optional<int> parseCount(const std::string& s) {
  const auto v = parseNonNegative(s);
  if (!v || *v != std::floor(*v) || *v > 1e9) return std::nullopt;
  return int(*v);
}

// Returns an error message, or empty.
std::string parseBatchArgs(int argc, char** argv, BatchArgs& a) {
  for (int i = 1; i < argc; ++i) {
    const std::string s = argv[i];
    if (s == "--quiet" || s == "-q") {
      a.quiet = true;
      continue;
    }
    if (s == "--verbose" || s == "-v") {
      a.verbose = true;
      continue;
    }
    if (s == "--denoise") {
      a.denoise = true;
      continue;
    }
    if (s.size() > 1 && s[0] == '-') {
      if (i + 1 >= argc) return s + " needs a value";
      const std::string v = argv[++i];
      if (s == "--jobs") {
        const auto n = parseCount(v);
        if (!n || *n < 1) return "--jobs: '" + v + "' is not a whole number >= 1";
        a.jobs = *n;
      } else if (s == "--shard") {
        const size_t slash = v.find('/');
        const auto k = parseCount(v.substr(0, slash));
        const auto n = slash == std::string::npos ? std::nullopt : parseCount(v.substr(slash + 1));
        if (!k || !n || *n < 1 || *k >= *n) return "--shard: '" + v + "' is not K/N with 0 <= K < N";
        a.shard = *k;
        a.shards = *n;
      } else if (s == "--spp" || s == "--seed" || s == "--threads") {
        const auto n = parseCount(v);
        if (!n || (s == "--spp" && *n < 1)) return s + ": '" + v + "' is not a valid whole number";
        (s == "--spp" ? a.spp : s == "--seed" ? a.seed : a.threads) = n;
      } else if (s == "--seconds" || s == "--noise") {
        const auto x = parseNonNegative(v);
        if (!x || (s == "--noise" && *x >= 1)) return s + ": '" + v + "' is not a valid number";
        (s == "--seconds" ? a.seconds : a.noise) = x;
      } else {
        return "batch: unknown option '" + s + "'";
      }
      continue;
    }
    if (!a.manifest.empty()) return "batch takes one MANIFEST.jsonl";
    a.manifest = s;
  }
  if (a.manifest.empty()) return "batch needs a MANIFEST.jsonl";
  return {};
}

fs::path absoluteFrom(const fs::path& base, const std::string& p) {
  return fs::path(p).is_absolute() ? fs::path(p) : (base / p).lexically_normal();
}

// One line of the manifest. Paths (scene, output, objects[].mesh) are relative to the
// manifest's folder.
Expected<BatchLine> parseLine(const std::string& text, int lineNumber, const fs::path& base,
                              const std::string& manifest) {
  const std::string where = manifest + ":" + std::to_string(lineNumber);
  json j = json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return Error{where, "", "not a JSON object"};
  BatchLine line;
  line.lineNumber = lineNumber;
  for (const char* key : {"scene", "output"})
    if (!j.contains(key) || !j[key].is_string() || j[key].get<std::string>().empty())
      return Error{where, key, "must be a non-empty string (a path)"};
  line.scene = absoluteFrom(base, j["scene"]).string();
  line.output = absoluteFrom(base, j["output"]).string();
  if (j.contains("objects")) {
    if (!j["objects"].is_array()) return Error{where, "objects", "must be an array of objects"};
    line.objects = j["objects"];
    for (size_t i = 0; i < line.objects.size(); ++i) {
      json& o = line.objects[i];
      if (!o.is_object())
        return Error{where, "objects[" + std::to_string(i) + "]", "must be a JSON object"};
      if (o.contains("mesh") && o["mesh"].is_string()) {
        const std::string mesh = o["mesh"];
        if (mesh.rfind("builtin:", 0) != 0) o["mesh"] = absoluteFrom(base, mesh).string();
      }
    }
  }
  if (j.contains("render")) {
    if (!j["render"].is_object()) return Error{where, "render", "must be a JSON object"};
    line.render = j["render"];
  }
  for (const auto& [key, value] : j.items()) {
    (void)value;
    if (key != "scene" && key != "output" && key != "objects" && key != "render")
      return Error{where, key, "unknown key (expected scene, output, objects, render)"};
  }
  return line;
}

Expected<std::vector<BatchLine>> readManifest(const std::string& path) {
  std::ifstream in(path);
  if (!in) return Error{path, "", "cannot be read"};
  const fs::path base = fs::absolute(path).parent_path();
  std::vector<BatchLine> lines;
  std::string text;
  for (int n = 1; std::getline(in, text); ++n) {
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    auto line = parseLine(text, n, base, path);
    if (!line) return line.error();
    lines.push_back(std::move(*line));
  }
  if (lines.empty()) return Error{path, "", "holds no lines"};
  // Two lines writing one file would race and the resume could not tell them apart.
  std::map<std::string, int> byOutput;
  for (const BatchLine& l : lines)
    if (auto [it, added] = byOutput.emplace(l.output, l.lineNumber); !added)
      return Error{path + ":" + std::to_string(l.lineNumber), "output",
                   "the same file as line " + std::to_string(it->second) + " (" + l.output + ")"};
  return lines;
}

// Scene groups in the order their scenes first appear; shard K of N takes groups g % N == K.
std::vector<SceneGroup> groupsOfShard(const std::vector<BatchLine>& lines, int shard, int shards) {
  std::vector<SceneGroup> groups;
  std::map<std::string, size_t> index;
  for (size_t i = 0; i < lines.size(); ++i) {
    auto [it, added] = index.emplace(lines[i].scene, groups.size());
    if (added) groups.push_back({lines[i].scene, {}});
    groups[it->second].lines.push_back(i);
  }
  std::vector<SceneGroup> mine;
  for (size_t g = 0; g < groups.size(); ++g)
    if (int(g % size_t(shards)) == shard) mine.push_back(std::move(groups[g]));
  return mine;
}

// The scene as this line wants it: its objects merged into the scene's objects[i] key by key
// (a new object past the scene's list), its render keys into the scene's.
Expected<SceneDoc> lineScene(const json& sceneJson, const BatchLine& line) {
  json j = sceneJson;
  if (!j.contains("objects") || !j["objects"].is_array()) j["objects"] = json::array();
  for (size_t i = 0; i < line.objects.size(); ++i) {
    if (i < j["objects"].size()) j["objects"][i].merge_patch(line.objects[i]);
    else j["objects"].push_back(line.objects[i]);
  }
  if (!line.render.empty()) {
    if (!j.contains("render") || !j["render"].is_object()) j["render"] = json::object();
    j["render"].merge_patch(line.render);
  }
  const std::string where = "line " + std::to_string(line.lineNumber) + " on " + line.scene;
  auto parsed = parseSceneJson(j.dump(), fs::path(line.scene).parent_path().string(), where);
  if (!parsed) return parsed.error();
  return parsed->doc;
}

// What every line of a prepared scene shares, read-only while its lines render.
struct PreparedGroup {
  const PreparedScene* scene = nullptr;
  json sceneJson;
  MeshCache meshes;  // guarded by meshMutex
  std::mutex meshMutex;
};

class BatchRunner {
 public:
  BatchRunner(const BatchArgs& args, CancelToken& cancel, const std::atomic<bool>& interrupted)
      : args_(args), cancel_(cancel), interrupted_(interrupted) {}

  int run(const std::vector<BatchLine>& lines, const std::vector<SceneGroup>& groups);

 private:
  void runGroup(const std::vector<BatchLine>& lines, const SceneGroup& group);
  void renderLine(PreparedGroup& g, const BatchLine& line);
  Status renderAndSave(PreparedGroup& g, const BatchLine& line, const SceneDoc& doc);
  void fail(const BatchLine& line, const Error& e, bool badInput);
  void note(const std::string& text);
  int threadsPerJob() const;

  const BatchArgs& args_;
  CancelToken& cancel_;
  const std::atomic<bool>& interrupted_;
  std::mutex m_;  // guards the counters, the failures and stderr
  std::vector<Failure> failures_;
  int rendered_ = 0, skipped_ = 0, total_ = 0, done_ = 0;
};

void BatchRunner::note(const std::string& text) {
  if (args_.quiet) return;
  std::lock_guard<std::mutex> lock(m_);
  std::fprintf(stderr, "inlay-cli: batch: %s\n", text.c_str());
}

void BatchRunner::fail(const BatchLine& line, const Error& e, bool badInput) {
  std::lock_guard<std::mutex> lock(m_);
  ++done_;
  failures_.push_back({line.lineNumber, e.message(), badInput});
  // Failures are shown even with --quiet.
  std::fprintf(stderr, "inlay-cli: batch: line %d failed: %s\n", line.lineNumber, e.message().c_str());
}

int BatchRunner::threadsPerJob() const {
  if (args_.threads) return *args_.threads;
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  return std::max(1, cores / args_.jobs);
}

Status BatchRunner::renderAndSave(PreparedGroup& g, const BatchLine& line, const SceneDoc& doc) {
  const PreparedScene& ps = *g.scene;
  RenderScene rs = ps.renderScene;
  {
    std::lock_guard<std::mutex> lock(g.meshMutex);
    auto placed = placeObjects(doc.objects, ps.geometry, ps.camera, &g.meshes);
    if (!placed) return placed.error().inFile(line.scene);
    rs.objects = std::move(placed->objects);
  }
  SessionOptions so;  // as `inlay-cli render` sets them
  so.targetSpp = args_.spp.value_or(doc.render.spp);
  so.seconds = args_.seconds.value_or(doc.render.seconds.value_or(0.0));
  so.seed = uint32_t(args_.seed.value_or(int(doc.render.seed)));
  so.threads = threadsPerJob();
  so.startDivider = 1;
  so.focusOnChanges = true;
  so.noiseTarget = args_.noise.value_or(doc.render.noise);
  so.tracer.clampRadiance = doc.render.clampIndirect;
  so.denoise = args_.denoise ? SessionOptions::Denoise::Final : SessionOptions::Denoise::Off;
  LastFrameSink sink;
  {
    RenderSession session(&sink, so);
    session.setScene(rs);
    while (!session.waitUntilDone(0.05))
      if (interrupted_) {
        session.cancel();
        break;
      }
  }
  if (interrupted_) return Error{line.output, "", "interrupted; nothing written"};
  const auto frame = sink.last();
  if (!frame || frame->spp == 0) return Error{line.output, "", "the renderer produced no frame"};
  // As `inlay-cli render` writes it: the line's grain and exposure, the photo's response.
  const ImageF composite = compositeOf(ps.photo.linearRgb, doc.render.exposure, *frame,
                                       doc.render.grain ? &ps.photoNoise : nullptr, doc.render.seed,
                                       nullptr, &ps.renderScene.roomAlbedo.photoRadiance, ps.vignetting);
  SaveOptions save;
  save.response = outputResponseOf(ps);
  std::error_code ec;
  fs::create_directories(fs::path(line.output).parent_path(), ec);
  return saveImage(line.output, composite, save);
}

void BatchRunner::renderLine(PreparedGroup& g, const BatchLine& line) {
  if (interrupted_) return;
  const auto start = Clock::now();
  auto doc = lineScene(g.sceneJson, line);
  if (!doc) return fail(line, doc.error(), true);
  if (auto st = renderAndSave(g, line, *doc); !st) {
    if (!interrupted_) fail(line, st.error(), false);
    return;
  }
  int done = 0;
  {
    std::lock_guard<std::mutex> lock(m_);
    done = ++done_;
    ++rendered_;
  }
  char msg[96];
  std::snprintf(msg, sizeof msg, "[%d/%d] line %d: ", done, total_, line.lineNumber);
  note(msg + line.output + " (" + std::to_string(int(std::lround(secondsSince(start)))) + " s)");
}

void BatchRunner::runGroup(const std::vector<BatchLine>& lines, const SceneGroup& group) {
  // Resumable: an existing output is a finished line (outputs are written atomically).
  std::vector<const BatchLine*> todo;
  for (size_t i : group.lines) {
    std::error_code ec;
    if (fs::exists(lines[i].output, ec)) {
      std::lock_guard<std::mutex> lock(m_);
      ++skipped_;
      ++done_;
    } else {
      todo.push_back(&lines[i]);
    }
  }
  if (todo.empty() || interrupted_) return;
  const auto start = Clock::now();
  auto failAll = [&](const Error& e, bool badInput) {
    for (const BatchLine* l : todo) fail(*l, e, badInput);
  };
  auto loaded = loadSceneFile(group.scene);
  if (!loaded) return failAll(loaded.error(), true);
  PreparedGroup g;
  {
    std::ifstream in(group.scene);
    std::stringstream text;
    text << in.rdbuf();
    g.sceneJson = json::parse(text.str(), nullptr, false);
  }
  SceneDoc room = loaded->doc;
  room.objects.clear();  // each line places its own
  PrepareOptions po;
  po.cancel = &cancel_;
  po.threads = args_.threads.value_or(0);
  auto prepared = prepareScene(room, po);
  if (interrupted_) return;
  if (!prepared) return failAll(prepared.error().inFile(group.scene), true);
  g.scene = &*prepared;
  char msg[64];
  std::snprintf(msg, sizeof msg, " (%.1f s, %zu lines to render)", secondsSince(start), todo.size());
  note("prepared " + group.scene + msg);
  if (args_.verbose) {
    std::lock_guard<std::mutex> lock(m_);
    for (const StageRecord& s : prepared->stages)
      std::fprintf(stderr, "inlay-cli: batch: stage %s\n", describeStage(s).c_str());
  }

  // --jobs N lines at a time, each on its share of the cores; the outputs do not depend on it.
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i = next++; i < todo.size() && !interrupted_; i = next++) renderLine(g, *todo[i]);
  };
  std::vector<std::thread> pool;
  for (int j = 1; j < std::min<int>(args_.jobs, int(todo.size())); ++j) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
}

int BatchRunner::run(const std::vector<BatchLine>& lines, const std::vector<SceneGroup>& groups) {
  for (const auto& g : groups) total_ += int(g.lines.size());
  const auto start = Clock::now();
  for (const auto& g : groups) {
    if (interrupted_) break;
    runGroup(lines, g);
  }
  std::lock_guard<std::mutex> lock(m_);
  const int missing = total_ - rendered_ - skipped_;
  std::fprintf(stderr,
               "inlay-cli: batch: %d lines in %zu scenes: %d rendered, %d already there, %zu failed"
               "%s (%.1f s)\n",
               total_, groups.size(), rendered_, skipped_, failures_.size(),
               interrupted_ ? ", interrupted" : "", secondsSince(start));
  if (interrupted_) return 1;
  if (missing == 0) return 0;
  std::sort(failures_.begin(), failures_.end(),
            [](const Failure& a, const Failure& b) { return a.lineNumber < b.lineNumber; });
  std::fprintf(stderr, "inlay-cli: batch: failed lines of %s:", args_.manifest.c_str());
  for (const auto& f : failures_) std::fprintf(stderr, " %d", f.lineNumber);
  std::fprintf(stderr, "\n");
  const bool internal =
      std::any_of(failures_.begin(), failures_.end(), [](const Failure& f) { return !f.badInput; });
  return internal ? 1 : 2;
}

}  // namespace

int runBatch(int argc, char** argv, CancelToken& cancel, const std::atomic<bool>& interrupted) {
  BatchArgs args;
  if (const std::string err = parseBatchArgs(argc, argv, args); !err.empty()) {
    std::fprintf(stderr, "inlay-cli: %s\n(run 'inlay-cli --help' for usage)\n", err.c_str());
    return 2;
  }
  auto lines = readManifest(args.manifest);
  if (!lines) {
    std::fprintf(stderr, "inlay-cli: %s\n", lines.error().message().c_str());
    return 2;
  }
  const auto groups = groupsOfShard(*lines, args.shard, args.shards);
  BatchRunner runner(args, cancel, interrupted);
  return runner.run(*lines, groups);
}

}  // namespace inlay::cli
