// The scene file (spec/scene-file.md): parse with validation, serialise in spec order.
//
// Parsing goes through nlohmann's SAX interface so that (1) nesting depth is checked while
// reading, before any recursion can happen, and (2) a lexer error such as a number overflow
// (1e999) names the key where it happened. The DOM is then walked with a key path.
#include "inlay/modeling/scene_file.h"

#include "inlay/modeling/response.h"

#include "inlay/modeling/image_io.h"
#include "inlay/modeling/mesh.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace inlay {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using ojson = nlohmann::ordered_json;

constexpr int kVersion = 1;

// Internal only: thrown inside this unit, turned into Error at the API boundary.
struct SceneError {
  Error error;
};

[[noreturn]] void fail(const std::string& key, const std::string& reason) {
  throw SceneError{Error{"", key, reason}};
}

std::string child(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}
std::string child(const std::string& path, size_t index) {
  return path + "[" + std::to_string(index) + "]";
}

// ---------------------------------------------------------------------------------------------
// SAX DOM builder with a depth limit and key paths for errors.
class PathSax : public nlohmann::json_sax<json> {
 public:
  explicit PathSax(int maxDepth) : maxDepth_(maxDepth) {}

  json root;
  std::optional<Error> error;

  bool null() override { return value(nullptr); }
  bool boolean(bool v) override { return value(v); }
  bool number_integer(number_integer_t v) override { return value(v); }
  bool number_unsigned(number_unsigned_t v) override { return value(v); }
  bool number_float(number_float_t v, const string_t&) override {
    if (!std::isfinite(v)) return failHere("non-finite number");
    return value(v);
  }
  bool string(string_t& v) override { return value(v); }
  bool binary(binary_t&) override { return failHere("binary values are not JSON"); }
  bool start_object(std::size_t) override { return open(json::object()); }
  bool key(string_t& k) override {
    frames_.back().key = k;
    if (frames_.back().node->contains(k)) duplicateKeys.push_back(currentPath());
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(json::array()); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t byte, const std::string& token,
                   const nlohmann::detail::exception& ex) override {
    std::string what = ex.what();
    if (ex.id == 406) {
      what = "number out of range (" + token + ")";
    } else {
      // nlohmann's text is "[json.exception.parse_error.101] parse error at line 1, ...".
      const auto pos = what.find("] ");
      if (pos != std::string::npos) what = what.substr(pos + 2);
      what = "invalid JSON at byte " + std::to_string(byte) + ": " + what;
    }
    if (!error) error = Error{"", currentPath(), what};
    return false;
  }

  std::vector<std::string> duplicateKeys;

 private:
  struct Frame {
    json* node;
    std::string key;  // objects: the key being read
  };

  std::string currentPath() const {
    // An array's open child is its last element; at the innermost level the next value
    // (about to be added) is the one being read.
    std::string p;
    for (size_t i = 0; i < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      const bool innermost = i + 1 == frames_.size();
      if (f.node->is_array()) p = child(p, f.node->size() - (innermost ? 0 : 1));
      else if (!f.key.empty()) p = child(p, f.key);
    }
    return p;
  }
  bool failHere(const std::string& reason) {
    if (!error) error = Error{"", currentPath(), reason};
    return false;
  }
  json* slot() {
    if (frames_.empty()) return &root;
    Frame& f = frames_.back();
    if (f.node->is_array()) {
      f.node->push_back(nullptr);
      return &f.node->back();
    }
    return &(*f.node)[f.key];
  }
  bool value(json v) {
    *slot() = std::move(v);
    if (!frames_.empty() && frames_.back().node->is_object()) frames_.back().key.clear();
    return true;
  }
  bool open(json empty) {
    if (int(frames_.size()) >= maxDepth_)
      return failHere("nesting deeper than " + std::to_string(maxDepth_) + " levels");
    json* s = slot();
    *s = std::move(empty);
    frames_.push_back(Frame{s, {}});
    return true;
  }
  bool close() {
    frames_.pop_back();
    if (!frames_.empty() && frames_.back().node->is_object()) frames_.back().key.clear();
    return true;
  }

  int maxDepth_;
  std::vector<Frame> frames_;
};

// ---------------------------------------------------------------------------------------------
// Typed readers. Each takes the value and its key path and fails with the path.

const char* typeName(const json& j) {
  if (j.is_string()) return "a string";
  if (j.is_boolean()) return "a boolean";
  if (j.is_null()) return "null";
  if (j.is_array()) return "an array";
  if (j.is_object()) return "an object";
  return "a number";
}

double number(const json& j, const std::string& path) {
  if (!j.is_number()) fail(path, std::string("expected a number, got ") + typeName(j));
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(path, "not a finite number");
  return v;
}
double positive(const json& j, const std::string& path) {
  const double v = number(j, path);
  if (!(v > 0)) fail(path, "must be > 0 (got " + j.dump() + ")");
  return v;
}
double indexOfRefraction(const json& j, const std::string& path) {
  const double v = number(j, path);
  if (!(v >= 1.0 && v <= 5.0)) fail(path, "must be in [1, 5] (got " + j.dump() + ")");
  return v;
}
double inUnitRange(const json& j, const std::string& path) {
  const double v = number(j, path);
  if (v < 0 || v > 1) fail(path, "must be in [0, 1] (got " + j.dump() + ")");
  return v;
}
long long integer(const json& j, const std::string& path) {
  if (j.is_number_integer()) {
    if (j.is_number_unsigned() && j.get<unsigned long long>() > (1ull << 62))
      fail(path, "integer out of range");
    return j.get<long long>();
  }
  if (j.is_number_float()) {
    const double v = j.get<double>();
    if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 1e15) return (long long)v;
    fail(path, "expected an integer, got " + j.dump());
  }
  fail(path, std::string("expected an integer, got ") + typeName(j));
}
// render.clamp_indirect: multiples of white (>= 0; 0 is off) or the string "off".
double clampIndirect(const json& j, const std::string& path) {
  const char* what = "a number of times white (0 or \"off\": no clamp; e.g. 4)";
  if (j.is_string() && j.get<std::string>() == "off") return 0.0;
  if (!j.is_number()) fail(path, std::string("expected ") + what + ", got " + j.dump());
  const double v = j.get<double>();
  if (!std::isfinite(v) || v < 0) fail(path, std::string("expected ") + what + ", got " + j.dump());
  return v;
}
bool boolean(const json& j, const std::string& path) {
  if (!j.is_boolean()) fail(path, std::string("expected true or false, got ") + typeName(j));
  return j.get<bool>();
}
std::string string(const json& j, const std::string& path) {
  if (!j.is_string()) fail(path, std::string("expected a string, got ") + typeName(j));
  return j.get<std::string>();
}
const json& array(const json& j, const std::string& path, size_t minSize = 0,
                  size_t maxSize = size_t(-1)) {
  if (!j.is_array()) fail(path, std::string("expected an array, got ") + typeName(j));
  const std::string got = ", got " + std::to_string(j.size());
  if (minSize == maxSize && j.size() != minSize)
    fail(path, "expected " + std::to_string(minSize) + " elements" + got);
  if (j.size() < minSize) fail(path, "expected at least " + std::to_string(minSize) + " elements" + got);
  if (j.size() > maxSize) fail(path, "expected at most " + std::to_string(maxSize) + " elements" + got);
  return j;
}
template <int N>
Eigen::Matrix<double, N, 1> vec(const json& j, const std::string& path) {
  array(j, path, N, N);
  Eigen::Matrix<double, N, 1> v;
  for (int i = 0; i < N; ++i) v[i] = number(j[size_t(i)], child(path, size_t(i)));
  return v;
}
Vec3 nonNegativeRgb(const json& j, const std::string& path) {
  Vec3 v = vec<3>(j, path);
  for (int i = 0; i < 3; ++i)
    if (v[i] < 0) fail(child(path, size_t(i)), "must be >= 0");
  return v;
}
Vec3 albedo(const json& j, const std::string& path) {
  array(j, path, 3, 3);
  Vec3 v;
  for (int i = 0; i < 3; ++i) v[i] = inUnitRange(j[size_t(i)], child(path, size_t(i)));
  return v;
}
std::vector<Vec2> polyline(const json& j, const std::string& path, size_t minPoints,
                           const SceneLimits& limits) {
  array(j, path, minPoints, limits.maxPointsPerPolyline);
  std::vector<Vec2> pts;
  pts.reserve(j.size());
  for (size_t i = 0; i < j.size(); ++i) pts.push_back(vec<2>(j[i], child(path, i)));
  return pts;
}
std::array<double, 4> box(const json& j, const std::string& path) {
  const Vec4 b = vec<4>(j, path);
  if (!(b[0] < b[2]) || !(b[1] < b[3])) fail(path, "expected [x0, y0, x1, y1] with x0 < x1 and y0 < y1");
  return {b[0], b[1], b[2], b[3]};
}
const json& object(const json& j, const std::string& path) {
  if (!j.is_object()) fail(path, std::string("expected an object, got ") + typeName(j));
  return j;
}

// ---------------------------------------------------------------------------------------------
// Outlines.

double signedArea(const std::vector<Vec2>& p) {
  double a = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec2& u = p[i];
    const Vec2& v = p[(i + 1) % p.size()];
    a += u.x() * v.y() - v.x() * u.y();
  }
  return 0.5 * a;
}

double orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}
bool onSegment(const Vec2& a, const Vec2& b, const Vec2& p) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
}
// Closed segments [a,b] and [c,d] share a point (exact predicates on doubles are enough for
// user clicks; collinear overlap counts as an intersection).
bool segmentsIntersect(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double d1 = orient(c, d, a), d2 = orient(c, d, b);
  const double d3 = orient(a, b, c), d4 = orient(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  if (d1 == 0 && onSegment(c, d, a)) return true;
  if (d2 == 0 && onSegment(c, d, b)) return true;
  if (d3 == 0 && onSegment(a, b, c)) return true;
  if (d4 == 0 && onSegment(a, b, d)) return true;
  return false;
}

// A closed outline must have >= 3 points, non-zero area and no self-intersection. O(n^2) on
// polylines a user drew (<= SceneLimits::maxPointsPerPolyline, checked before).
void checkSimplePolygon(const std::vector<Vec2>& p, const std::string& path) {
  if (p.size() < 3) fail(path, "a closed outline needs at least 3 points");
  // All points on one line (or one point): zero area, whatever the order.
  size_t far = 0;
  for (size_t i = 1; i < p.size(); ++i)
    if ((p[i] - p[0]).squaredNorm() > (p[far] - p[0]).squaredNorm()) far = i;
  const double extent2 = (p[far] - p[0]).squaredNorm();
  bool collinear = true;
  for (const Vec2& q : p)
    collinear = collinear && std::fabs(orient(p[0], p[far], q)) <= 1e-12 * std::max(1.0, extent2);
  if (collinear) fail(path, "outline has zero area (all points on one line)");
  const size_t n = p.size();
  for (size_t i = 0; i < n; ++i) {
    if (p[i] == p[(i + 1) % n]) fail(child(path, (i + 1) % n), "repeats the previous point");
  }
  for (size_t i = 0; i < n; ++i) {
    const Vec2 &a = p[i], &b = p[(i + 1) % n];
    for (size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      const Vec2 &c = p[j], &d = p[(j + 1) % n];
      if (adjacent) {
        // Neighbours share one endpoint; they intersect further only when folding back.
        const Vec2& shared = (j == i + 1) ? b : a;
        const Vec2& other1 = (j == i + 1) ? a : b;
        const Vec2& other2 = (j == i + 1) ? d : c;
        if (orient(shared, other1, other2) == 0 && (other1 - shared).dot(other2 - shared) > 0)
          fail(path, "outline is self-intersecting (segments " + std::to_string(i) + " and " +
                         std::to_string(j) + " overlap)");
        continue;
      }
      if (segmentsIntersect(a, b, c, d))
        fail(path, "outline is self-intersecting (segments " + std::to_string(i) + " and " +
                       std::to_string(j) + " cross)");
    }
  }
  if (std::fabs(signedArea(p)) <= 1e-12 * std::max(1.0, extent2)) fail(path, "outline has zero area");
}

// ---------------------------------------------------------------------------------------------
// Keys.

class Reader {
 public:
  Reader(std::string fileName, fs::path baseDir, const SceneLimits& limits,
         std::vector<std::string>& warnings)
      : file_(std::move(fileName)), base_(std::move(baseDir)), limits_(limits), warnings_(warnings) {}

  // Warns about keys of `obj` outside `known`.
  void knownKeys(const json& obj, const std::string& path, std::initializer_list<const char*> known) {
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      if (std::find_if(known.begin(), known.end(), [&](const char* k) { return it.key() == k; }) ==
          known.end())
        warnings_.push_back(file_ + ": unknown key '" + child(path, it.key()) + "' ignored");
    }
  }

  // Paths may lead anywhere (absolute, or out of the scene's folder: scripts write them), but
  // they must name a regular file: never a folder, a device or a pipe.
  static std::string whyNotAFile(const std::string& resolved) {
    std::error_code ec;
    if (!fs::exists(resolved, ec)) return "file not found: " + resolved;
    return "not a regular file: " + resolved;
  }

  std::string resolve(const std::string& p) const {
    fs::path q(p);
    if (q.is_relative()) q = base_ / q;
    std::error_code ec;
    fs::path abs = fs::absolute(q, ec);
    return (ec ? q : abs).lexically_normal().string();
  }

  SceneDoc read(const json& root) {
    object(root, "");
    knownKeys(root, "",
              {"format", "version", "photo", "camera", "layout", "lights", "shafts", "surfaces",
               "occluders", "objects", "room", "render"});
    SceneDoc doc;
    if (!root.contains("format")) fail("format", "missing (expected \"inlay-scene\")");
    if (string(root["format"], "format") != "inlay-scene")
      fail("format", "expected \"inlay-scene\", got " + root["format"].dump());
    if (!root.contains("version")) fail("version", "missing (expected 1)");
    const long long version = integer(root["version"], "version");
    if (version != kVersion)
      fail("version", "unsupported version " + std::to_string(version) +
                          " (this program reads version " + std::to_string(kVersion) + ")");
    if (!root.contains("photo")) fail("photo", "missing (the photo to insert objects into)");
    doc.photo = string(root["photo"], "photo");
    if (doc.photo.empty()) fail("photo", "empty path");
    doc.photoResolved = resolve(doc.photo);
    std::error_code ec;
    if (!fs::is_regular_file(doc.photoResolved, ec)) fail("photo", whyNotAFile(doc.photoResolved));

    if (root.contains("camera")) readCamera(root["camera"], doc.camera);
    if (root.contains("layout")) readLayout(root["layout"], doc.layout);
    if (root.contains("lights")) {
      const json& a = array(root["lights"], "lights", 0, limits_.maxObjects);
      for (size_t i = 0; i < a.size(); ++i) doc.lights.push_back(readLight(a[i], child("lights", i)));
    }
    if (root.contains("shafts")) {
      const json& a = array(root["shafts"], "shafts", 0, limits_.maxObjects);
      for (size_t i = 0; i < a.size(); ++i) doc.shafts.push_back(readShaft(a[i], child("shafts", i)));
    }
    if (root.contains("surfaces")) {
      const json& a = array(root["surfaces"], "surfaces", 0, limits_.maxObjects);
      for (size_t i = 0; i < a.size(); ++i)
        doc.surfaces.push_back(readSurface(a[i], child("surfaces", i)));
    }
    if (root.contains("occluders")) {
      const json& a = array(root["occluders"], "occluders", 0, limits_.maxObjects);
      for (size_t i = 0; i < a.size(); ++i)
        doc.occluders.push_back(readOccluder(a[i], child("occluders", i)));
    }
    if (root.contains("objects")) {
      const json& a = root["objects"];
      if (a.is_array() && a.size() > limits_.maxObjects)
        fail("objects", std::to_string(a.size()) + " objects exceed the limit of " +
                            std::to_string(limits_.maxObjects));
      array(a, "objects");
      for (size_t i = 0; i < a.size(); ++i) doc.objects.push_back(readObject(a[i], child("objects", i)));
    }
    if (root.contains("room")) readRoom(root["room"], doc.room);
    if (root.contains("render")) readRender(root["render"], doc.render);
    return doc;
  }

 private:
  void readCamera(const json& j, CameraKeys& c) {
    const std::string p = "camera";
    object(j, p);
    knownKeys(j, p,
              {"height_m", "focal_px", "principal_px", "vanishing_points_px", "vanishing_lines_px",
               "response", "vignetting"});
    if (j.contains("height_m")) c.heightM = positive(j["height_m"], child(p, "height_m"));
    if (j.contains("focal_px")) c.focalPx = positive(j["focal_px"], child(p, "focal_px"));
    if (j.contains("principal_px")) c.principalPx = vec<2>(j["principal_px"], child(p, "principal_px"));
    if (j.contains("vanishing_points_px")) {
      const std::string vp = child(p, "vanishing_points_px");
      const json& a = array(j["vanishing_points_px"], vp, 3, 3);
      std::array<Vec2, 3> v;
      for (size_t i = 0; i < 3; ++i) v[i] = vec<2>(a[i], child(vp, i));  // huge values allowed
      c.vanishingPointsPx = v;
    }
    if (j.contains("vanishing_lines_px")) readVanishingLines(j["vanishing_lines_px"], c);
    if (j.contains("response")) c.response = readResponse(j["response"]);
    if (j.contains("vignetting")) c.vignetting = readVignetting(j["vignetting"]);
  }

  // camera.vignetting: "none", "auto" or a strength v in [0, VignettingKeys::kMax].
  VignettingKeys readVignetting(const json& j) {
    const std::string p = "camera.vignetting";
    VignettingKeys k;
    if (j.is_string()) {
      const std::string v = j.get<std::string>();
      if (v == "auto") k.mode = VignettingKeys::Mode::Auto;
      else if (v == "none") k.mode = VignettingKeys::Mode::None;
      else
        fail(p, "unknown vignetting '" + v + "' (expected \"auto\", \"none\" or a number in [0, 0.9])");
      return k;
    }
    if (!j.is_number())
      fail(p, std::string("expected \"auto\", \"none\" or a number in [0, 0.9], got ") + typeName(j));
    k.mode = VignettingKeys::Mode::Given;
    k.v = number(j, p);
    if (!(k.v >= 0 && k.v <= VignettingKeys::kMax)) {
      char buf[120];
      std::snprintf(buf, sizeof buf, "must be in [0, %g] (got %s)", VignettingKeys::kMax,
                    j.dump().c_str());
      fail(p, buf);
    }
    return k;
  }

  // camera.response: "auto", "srgb", "linear" or {"family": ..., parameters}.
  ResponseKeys readResponse(const json& j) {
    const std::string p = "camera.response";
    ResponseKeys r;
    if (j.is_string()) {
      const std::string v = j.get<std::string>();
      if (v == "auto") r.mode = ResponseKeys::Mode::Auto;
      else if (v == "srgb") r.mode = ResponseKeys::Mode::Srgb;
      else if (v == "linear") r.mode = ResponseKeys::Mode::Linear;
      else
        fail(p, "unknown response '" + v +
                    "' (expected \"auto\", \"srgb\", \"linear\" or an object "
                    "{\"family\": \"toe_shoulder\", \"power\", \"toe\", \"shoulder\"})");
      return r;
    }
    if (!j.is_object())
      fail(p, std::string("expected \"auto\", \"srgb\", \"linear\" or an object, got ") + typeName(j));
    knownKeys(j, p, {"family", "power", "toe", "shoulder"});
    if (!j.contains("family"))
      fail(child(p, "family"), "missing (\"toe_shoulder\", \"srgb\" or \"linear\")");
    const std::string family = string(j["family"], child(p, "family"));
    if (family == "srgb") r.mode = ResponseKeys::Mode::Srgb;
    else if (family == "linear") r.mode = ResponseKeys::Mode::Linear;
    else if (family == "toe_shoulder") r.mode = ResponseKeys::Mode::ToeShoulder;
    else
      fail(child(p, "family"),
           "unknown family '" + family + "' (expected \"toe_shoulder\", \"srgb\" or \"linear\")");
    auto bounded = [&](const char* key, double lo, double hi, double fallback) {
      if (!j.contains(key)) return fallback;
      const double v = number(j[key], child(p, key));
      if (v < lo || v > hi) {
        char buf[120];
        std::snprintf(buf, sizeof buf, "must be in [%g, %g] (got %s)", lo, hi, j[key].dump().c_str());
        fail(child(p, key), buf);
      }
      return v;
    };
    if (r.mode == ResponseKeys::Mode::ToeShoulder) {
      r.power = bounded("power", ResponseParams::kMinPower, ResponseParams::kMaxPower, 1.0);
      r.toe = bounded("toe", 0.0, ResponseParams::kMaxToe, 0.0);
      r.shoulder = bounded("shoulder", 0.0, ResponseParams::kMaxShoulder, 0.0);
    } else {
      for (const char* k : {"power", "toe", "shoulder"})
        if (j.contains(k)) fail(child(p, k), "only the toe_shoulder family takes parameters");
    }
    return r;
  }

  // camera.vanishing_lines_px: {"x": [[a0, b0], [a1, b1]], ...}, any of the three axes.
  void readVanishingLines(const json& j, CameraKeys& c) {
    const std::string p = "camera.vanishing_lines_px";
    object(j, p);
    knownKeys(j, p, {"x", "y", "z"});
    static const char* const kAxes[3] = {"x", "y", "z"};
    for (size_t k = 0; k < 3; ++k) {
      if (!j.contains(kAxes[k])) continue;
      const std::string ap = child(p, kAxes[k]);
      const json& pair = array(j[kAxes[k]], ap, 2, 2);
      std::array<Vec2, 4> pts;
      for (size_t s = 0; s < 2; ++s) {
        const std::string sp = child(ap, s);
        const json& seg = array(pair[s], sp, 2, 2);
        pts[2 * s] = vec<2>(seg[0], child(sp, 0));
        pts[2 * s + 1] = vec<2>(seg[1], child(sp, 1));
        if ((pts[2 * s + 1] - pts[2 * s]).norm() < 2)
          fail(sp, "a degenerate segment (its ends are less than 2 pixels apart)");
      }
      // The second segment's ends both on the first one's line: no direction can be read.
      const Vec2 d = (pts[1] - pts[0]).normalized();
      auto offLine = [&](const Vec2& q) {
        const Vec2 r = q - pts[0];
        return std::abs(d.x() * r.y() - d.y() * r.x());
      };
      if (offLine(pts[2]) < 1 && offLine(pts[3]) < 1)
        fail(ap, "the two segments lie on one line (draw two different edges)");
      c.vanishingLinesPx[k] = pts;
    }
  }

  void readLayout(const json& j, LayoutKeys& l) {
    object(j, "layout");
    knownKeys(j, "layout", {"back_wall_px", "rear_m"});
    if (j.contains("back_wall_px")) {
      const std::string p = "layout.back_wall_px";
      const json& a = array(j["back_wall_px"], p, 4, 4);
      std::array<Vec2, 4> v;
      for (size_t i = 0; i < 4; ++i) v[i] = vec<2>(a[i], child(p, i));
      l.backWallPx = v;
    }
    if (j.contains("rear_m")) {
      const double v = positive(j["rear_m"], "layout.rear_m");
      if (v > 100) fail("layout.rear_m", "must be at most 100 m (got " + j["rear_m"].dump() + ")");
      l.rearM = v;
    }
  }

  LightKeys readLight(const json& j, const std::string& p) {
    object(j, p);
    LightKeys l;
    l.cornersM.fill(Vec3::Zero());  // Eigen does not zero on value-initialisation
    if (!j.contains("kind")) fail(child(p, "kind"), "missing (\"polygon_px\" or \"rect_m\")");
    const std::string kind = string(j["kind"], child(p, "kind"));
    if (kind == "polygon_px") {
      l.kind = LightKeys::Kind::PolygonPx;
      knownKeys(j, p, {"kind", "points", "rgb", "refine", "lock", "weights", "refine_size"});
      if (!j.contains("points")) fail(child(p, "points"), "missing");
      const std::string pp = child(p, "points");
      array(j["points"], pp, 0, limits_.maxPointsPerPolyline);
      if (j["points"].size() < 3)
        fail(pp,
             "a light polygon needs at least 3 points (got " + std::to_string(j["points"].size()) + ")");
      l.pointsPx = polyline(j["points"], pp, 3, limits_);
      checkSimplePolygon(l.pointsPx, pp);
    } else if (kind == "rect_m") {
      l.kind = LightKeys::Kind::RectM;
      knownKeys(j, p, {"kind", "corners", "rgb", "refine", "lock", "weights", "refine_size"});
      if (!j.contains("corners")) fail(child(p, "corners"), "missing");
      const std::string cp = child(p, "corners");
      const json& a = array(j["corners"], cp, 4, 4);
      for (size_t i = 0; i < 4; ++i) l.cornersM[i] = vec<3>(a[i], child(cp, i));
      const Vec3& c0 = l.cornersM[0];
      const double area = 0.5 * ((l.cornersM[1] - c0).cross(l.cornersM[2] - c0).norm() +
                                 (l.cornersM[2] - c0).cross(l.cornersM[3] - c0).norm());
      if (!(area > 1e-12)) fail(cp, "light rectangle has zero area");
    } else {
      fail(child(p, "kind"), "unknown light kind '" + kind + "' (expected polygon_px or rect_m)");
    }
    if (j.contains("rgb")) l.rgb = nonNegativeRgb(j["rgb"], child(p, "rgb"));
    if (j.contains("refine")) l.refine = boolean(j["refine"], child(p, "refine"));
    if (j.contains("lock")) l.lock = boolean(j["lock"], child(p, "lock"));
    if (j.contains("refine_size")) l.refineSize = boolean(j["refine_size"], child(p, "refine_size"));
    if (j.contains("weights")) {
      const std::string wp = child(p, "weights");
      object(j["weights"], wp);
      knownKeys(j["weights"], wp, {"position", "intensity", "size"});
      auto weight = [&](const char* k, double* w) {
        if (!j["weights"].contains(k)) return;
        *w = number(j["weights"][k], child(wp, k));
        if (*w < 0) fail(child(wp, k), "must be >= 0 (got " + j["weights"][k].dump() + ")");
      };
      weight("position", &l.positionWeight);
      weight("intensity", &l.intensityWeight);
      weight("size", &l.sizeWeight);
    }
    return l;
  }

  ShaftKeys readShaft(const json& j, const std::string& p) {
    object(j, p);
    knownKeys(j, p, {"shaft_box_px", "source_box_px", "direction"});
    ShaftKeys s;
    if (j.contains("shaft_box_px")) s.shaftBoxPx = box(j["shaft_box_px"], child(p, "shaft_box_px"));
    if (j.contains("source_box_px")) s.sourceBoxPx = box(j["source_box_px"], child(p, "source_box_px"));
    if (j.contains("direction")) {
      s.direction = vec<3>(j["direction"], child(p, "direction"));
      if (!(s.direction->norm() > 0)) fail(child(p, "direction"), "must be a non-zero vector");
    }
    if ((!s.shaftBoxPx || !s.sourceBoxPx) && !s.direction)
      fail(child(p, "direction"), std::string("required when ") +
                                      (s.shaftBoxPx ? "source_box_px" : "shaft_box_px") + " is missing");
    return s;
  }

  // Stairs drawn as a side profile on a wall: the polygon, the wall (optional), the width
  // (optional: to the opposite wall).
  SurfaceKeys readStairsProfile(const json& j, const std::string& p, SurfaceKeys s) {
    knownKeys(j, p, {"kind", "profile_px", "wall", "width_m"});
    for (const char* k : {"base_px", "steps", "rise_m", "run_m", "climb_axis"})
      if (j.contains(k)) fail(child(p, k), "not used with profile_px (give one or the other)");
    s.profilePx = polyline(j["profile_px"], child(p, "profile_px"), 3, limits_);
    checkSimplePolygon(s.profilePx, child(p, "profile_px"));
    if (j.contains("wall")) {
      s.wall = string(j["wall"], child(p, "wall"));
      if (s.wall != "left" && s.wall != "right" && s.wall != "back")
        fail(child(p, "wall"), "must be one of \"left\", \"right\", \"back\"");
    }
    if (j.contains("width_m") && !j["width_m"].is_null())
      s.widthM = positive(j["width_m"], child(p, "width_m"));
    return s;
  }

  SurfaceKeys readSurface(const json& j, const std::string& p) {
    object(j, p);
    SurfaceKeys s;
    if (j.contains("kind")) s.kind = string(j["kind"], child(p, "kind"));
    if (s.kind == "stairs" && j.contains("profile_px")) return readStairsProfile(j, p, s);
    if (s.kind == "stairs") {
      knownKeys(j, p, {"kind", "base_px", "steps", "rise_m", "run_m", "width_m", "climb_axis"});
      for (const char* k : {"base_px", "steps", "rise_m", "run_m", "width_m"})
        if (!j.contains(k)) fail(child(p, k), "missing");
      s.basePx = vec<2>(j["base_px"], child(p, "base_px"));
      const long long steps = integer(j["steps"], child(p, "steps"));
      if (steps < 1 || steps > 1000) fail(child(p, "steps"), "must be from 1 to 1000");
      s.steps = int(steps);
      s.riseM = positive(j["rise_m"], child(p, "rise_m"));
      s.runM = positive(j["run_m"], child(p, "run_m"));
      s.widthM = positive(j["width_m"], child(p, "width_m"));
      if (j.contains("climb_axis")) {
        s.climbAxis = string(j["climb_axis"], child(p, "climb_axis"));
        if (s.climbAxis != "+x" && s.climbAxis != "-x" && s.climbAxis != "+z" && s.climbAxis != "-z")
          fail(child(p, "climb_axis"), "must be one of \"+x\", \"-x\", \"+z\", \"-z\"");
      }
      return s;
    }
    if (s.kind != "extrusion" && s.kind != "box")
      fail(child(p, "kind"),
           "unknown surface kind '" + s.kind + "' (expected extrusion, box or stairs)");
    knownKeys(j, p, {"kind", "outline_px", "height_click_px", "thickness_m"});
    if (!j.contains("outline_px")) fail(child(p, "outline_px"), "missing");
    s.outlinePx = polyline(j["outline_px"], child(p, "outline_px"), 0, limits_);
    checkSimplePolygon(s.outlinePx, child(p, "outline_px"));
    if (!j.contains("height_click_px")) fail(child(p, "height_click_px"), "missing");
    s.heightClickPx = vec<2>(j["height_click_px"], child(p, "height_click_px"));
    if (j.contains("thickness_m") && !j["thickness_m"].is_null()) {
      s.thicknessM = number(j["thickness_m"], child(p, "thickness_m"));
      if (*s.thicknessM < 0) fail(child(p, "thickness_m"), "must be >= 0 (0: solid to the floor)");
    }
    return s;
  }

  std::vector<std::vector<Vec2>> scribbles(const json& j, const std::string& p) {
    const json& a = array(j, p, 0, limits_.maxPointsPerPolyline);
    std::vector<std::vector<Vec2>> out;
    for (size_t i = 0; i < a.size(); ++i) out.push_back(polyline(a[i], child(p, i), 1, limits_));
    return out;
  }

  OccluderKeys readOccluder(const json& j, const std::string& p) {
    object(j, p);
    knownKeys(j, p, {"foreground_scribbles_px", "background_scribbles_px"});
    OccluderKeys o;
    if (j.contains("foreground_scribbles_px"))
      o.foregroundScribblesPx =
          scribbles(j["foreground_scribbles_px"], child(p, "foreground_scribbles_px"));
    if (j.contains("background_scribbles_px"))
      o.backgroundScribblesPx =
          scribbles(j["background_scribbles_px"], child(p, "background_scribbles_px"));
    return o;
  }

  MaterialKeys readMaterial(const json& j, const std::string& p) {
    object(j, p);
    knownKeys(j, p, {"preset", "albedo", "roughness", "ior", "rgb"});
    MaterialKeys m;
    if (j.contains("preset")) m.preset = string(j["preset"], child(p, "preset"));
    static const std::set<std::string> presets = {"diffuse",  "glossy", "mirror", "glass",
                                                  "emissive", "asset",  "metal",  "rough_glass"};
    if (!presets.count(m.preset))
      fail(child(p, "preset"),
           "unknown material preset '" + m.preset +
               "' (expected diffuse, glossy, metal, mirror, glass, rough_glass, emissive or asset)");
    if (j.contains("albedo")) m.albedo = albedo(j["albedo"], child(p, "albedo"));
    if (j.contains("roughness")) m.roughness = inUnitRange(j["roughness"], child(p, "roughness"));
    if (j.contains("ior")) m.ior = indexOfRefraction(j["ior"], child(p, "ior"));
    if (j.contains("rgb")) m.rgb = nonNegativeRgb(j["rgb"], child(p, "rgb"));
    return m;
  }

  void readRoom(const json& j, RoomKeys& room) {
    object(j, "room");
    knownKeys(j, "room", {"materials"});
    if (!j.contains("materials")) return;
    const std::string p = "room.materials";
    object(j["materials"], p);
    // The spelling of every name SceneGeometry gives a surface; whether this room has it is
    // the engine's check (it knows how many surfaces and occluders there are).
    static const std::regex names(
        "floor|ceiling|wall_left|wall_right|wall_back|wall_rear|surface_[0-9]+_(top|side)|occluder_[0-9]+_card");
    for (auto it = j["materials"].begin(); it != j["materials"].end(); ++it) {
      const std::string key = child(p, it.key());
      if (!std::regex_match(it.key(), names))
        fail(key, "unknown room surface '" + it.key() +
                      "' (expected floor, ceiling, wall_left, wall_right, wall_back, wall_rear, "
                      "surface_<i>_top, surface_<i>_side or occluder_<i>_card)");
      room.materials[it.key()] = readRoomMaterial(it.value(), key);
    }
  }

  RoomMaterialKeys readRoomMaterial(const json& j, const std::string& p) {
    object(j, p);
    knownKeys(j, p, {"preset", "roughness", "ior", "reflectance"});
    RoomMaterialKeys m;
    if (j.contains("preset")) m.preset = string(j["preset"], child(p, "preset"));
    if (m.preset != "glossy" && m.preset != "mirror" && m.preset != "diffuse")
      fail(child(p, "preset"),
           "unknown room material preset '" + m.preset + "' (expected glossy, mirror or diffuse)");
    if (j.contains("roughness")) m.roughness = inUnitRange(j["roughness"], child(p, "roughness"));
    if (j.contains("ior")) m.ior = indexOfRefraction(j["ior"], child(p, "ior"));
    if (j.contains("reflectance")) m.reflectance = albedo(j["reflectance"], child(p, "reflectance"));
    return m;
  }

  ObjectKeys readObject(const json& j, const std::string& p) {
    object(j, p);
    knownKeys(j, p,
              {"mesh", "base_px", "height_m", "yaw_deg", "subdivide", "material", "name", "hidden"});
    ObjectKeys o;
    const std::string mp = child(p, "mesh");
    if (!j.contains("mesh")) fail(mp, "missing (builtin:sphere, builtin:cube or a mesh file)");
    o.mesh = string(j["mesh"], mp);
    if (o.mesh.rfind("builtin:", 0) == 0) {
      if (o.mesh != "builtin:sphere" && o.mesh != "builtin:cube")
        fail(mp, "unknown builtin mesh '" + o.mesh + "' (expected builtin:sphere or builtin:cube)");
    } else {
      if (o.mesh.empty()) fail(mp, "empty path");
      std::string ext = fs::path(o.mesh).extension().string();
      std::transform(ext.begin(), ext.end(), ext.begin(),
                     [](unsigned char c) { return char(std::tolower(c)); });
      const std::vector<std::string>& known = meshFileExtensions();
      if (std::find(known.begin(), known.end(), ext) == known.end())
        fail(mp, "unsupported mesh format '" + ext +
                     "' (expected .obj, .ply, .gltf, .glb, .fbx, .dae or .3ds)");
      o.meshResolved = resolve(o.mesh);
      std::error_code ec;
      if (!fs::is_regular_file(o.meshResolved, ec)) fail(mp, whyNotAFile(o.meshResolved));
    }
    if (!j.contains("base_px")) fail(child(p, "base_px"), "missing");
    o.basePx = vec<2>(j["base_px"], child(p, "base_px"));
    if (j.contains("height_m")) o.heightM = positive(j["height_m"], child(p, "height_m"));
    if (j.contains("yaw_deg")) o.yawDeg = number(j["yaw_deg"], child(p, "yaw_deg"));
    if (j.contains("subdivide")) {
      const double levels = number(j["subdivide"], child(p, "subdivide"));
      if (!(levels >= 0 && levels <= 5 && levels == std::floor(levels)))
        fail(child(p, "subdivide"), "must be a whole number of levels in [0, 5]");
      o.subdivideLevels = int(levels);
    }
    if (j.contains("material")) o.material = readMaterial(j["material"], child(p, "material"));
    if (j.contains("name")) o.name = string(j["name"], child(p, "name"));
    if (j.contains("hidden")) {
      if (!j["hidden"].is_boolean()) fail(child(p, "hidden"), "must be true or false");
      o.hidden = j["hidden"].get<bool>();
    }
    return o;
  }

  void readRender(const json& j, RenderKeys& r) {
    const std::string p = "render";
    object(j, p);
    knownKeys(j, p, {"spp", "seconds", "noise", "exposure", "seed", "grain", "clamp_indirect"});
    if (j.contains("spp")) {
      const long long spp = integer(j["spp"], child(p, "spp"));
      if (spp < 1) fail(child(p, "spp"), "must be >= 1 (got " + std::to_string(spp) + ")");
      if (spp > (1 << 24)) fail(child(p, "spp"), "must be <= 16777216");
      r.spp = int(spp);
    }
    if (j.contains("seconds") && !j["seconds"].is_null())
      r.seconds = positive(j["seconds"], child(p, "seconds"));
    if (j.contains("noise")) {
      r.noise = number(j["noise"], child(p, "noise"));
      if (!(r.noise >= 0 && r.noise < 1))
        fail(child(p, "noise"), "must be in [0, 1) (sRGB standard error)");
    }
    if (j.contains("exposure")) {
      r.exposure = number(j["exposure"], child(p, "exposure"));
      if (std::fabs(r.exposure) > 64) fail(child(p, "exposure"), "must be in [-64, 64] stops");
    }
    if (j.contains("seed")) {
      const long long seed = integer(j["seed"], child(p, "seed"));
      if (seed < 0 || seed > 0xffffffffLL) fail(child(p, "seed"), "must be in [0, 4294967295]");
      r.seed = unsigned(seed);
    }
    if (j.contains("grain")) r.grain = boolean(j["grain"], child(p, "grain"));
    if (j.contains("clamp_indirect"))
      r.clampIndirect = clampIndirect(j["clamp_indirect"], child(p, "clamp_indirect"));
  }

  std::string file_;
  fs::path base_;
  const SceneLimits& limits_;
  std::vector<std::string>& warnings_;
};

ojson toJson(const Vec2& v) { return ojson::array({v.x(), v.y()}); }
ojson toJson(const Vec3& v) { return ojson::array({v.x(), v.y(), v.z()}); }
ojson toJson(const std::vector<Vec2>& pts) {
  ojson a = ojson::array();
  for (const Vec2& p : pts) a.push_back(toJson(p));
  return a;
}

}  // namespace

Expected<SceneLoadResult> parseSceneJson(const std::string& text, const std::string& baseDir,
                                         const std::string& fileNameForMessages,
                                         const SceneLimits& limits) {
  const std::string& file = fileNameForMessages;
  if (text.size() > limits.maxFileBytes)
    return Error{file, "",
                 "scene file of " + std::to_string(text.size()) + " bytes exceeds the limit of " +
                     std::to_string(limits.maxFileBytes) + " bytes"};
  PathSax sax(std::max(1, limits.maxNesting));
  try {
    const bool ok = json::sax_parse(text, &sax, json::input_format_t::json, /*strict=*/true);
    if (!ok || sax.error) {
      Error e = sax.error.value_or(Error{"", "", "invalid JSON"});
      e.file = file;
      return e;
    }
  } catch (const std::exception& ex) {  // allocation failures and the like
    return Error{file, "", std::string("cannot parse: ") + ex.what()};
  }
  SceneLoadResult result;
  for (const std::string& k : sax.duplicateKeys)
    result.warnings.push_back(file + ": duplicate key '" + k + "', the last value is used");
  try {
    Reader reader(file, fs::path(baseDir.empty() ? "." : baseDir), limits, result.warnings);
    result.doc = reader.read(sax.root);
  } catch (const SceneError& e) {
    return e.error.inFile(file);
  } catch (const std::exception& ex) {
    return Error{file, "", std::string("cannot read: ") + ex.what()};
  }
  return result;
}

Expected<SceneLoadResult> loadSceneFile(const std::string& path, const SceneLimits& limits) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return Error{path, "", "file not found"};
  const auto size = fs::file_size(path, ec);
  if (ec) return Error{path, "", "cannot read: " + ec.message()};
  if (size > limits.maxFileBytes)
    return Error{path, "",
                 "scene file of " + std::to_string(size) + " bytes exceeds the limit of " +
                     std::to_string(limits.maxFileBytes) + " bytes"};
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{path, "", "cannot open for reading"};
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) return Error{path, "", "read failed"};
  const fs::path abs = fs::absolute(path, ec);
  return parseSceneJson(ss.str(), (ec ? fs::path(path) : abs).parent_path().string(), path, limits);
}

namespace {

// camera: only the keys given ("auto" response is the default and not written).
ojson cameraJson(const CameraKeys& c, bool anyLines) {
  ojson cam = ojson::object();
  if (c.heightM) cam["height_m"] = *c.heightM;
  if (c.focalPx) cam["focal_px"] = *c.focalPx;
  if (c.principalPx) cam["principal_px"] = toJson(*c.principalPx);
  if (c.vanishingPointsPx) {
    ojson a = ojson::array();
    for (const Vec2& v : *c.vanishingPointsPx) a.push_back(toJson(v));
    cam["vanishing_points_px"] = a;
  }
  if (anyLines) {
    ojson lines = ojson::object();
    static const char* const kAxes[3] = {"x", "y", "z"};
    for (size_t k = 0; k < 3; ++k) {
      if (!c.vanishingLinesPx[k]) continue;
      const auto& q = *c.vanishingLinesPx[k];
      lines[kAxes[k]] = ojson::array(
          {ojson::array({toJson(q[0]), toJson(q[1])}), ojson::array({toJson(q[2]), toJson(q[3])})});
    }
    cam["vanishing_lines_px"] = lines;
  }
  if (c.response.mode == ResponseKeys::Mode::Srgb) cam["response"] = "srgb";
  if (c.response.mode == ResponseKeys::Mode::Linear) cam["response"] = "linear";
  if (c.response.mode == ResponseKeys::Mode::ToeShoulder)
    cam["response"] = {{"family", "toe_shoulder"},
                       {"power", c.response.power},
                       {"toe", c.response.toe},
                       {"shoulder", c.response.shoulder}};
  if (c.vignetting.mode == VignettingKeys::Mode::Auto) cam["vignetting"] = "auto";
  if (c.vignetting.mode == VignettingKeys::Mode::Given) cam["vignetting"] = c.vignetting.v;
  return cam;
}

ojson lightJson(const LightKeys& l) {
  ojson o;
  if (l.kind == LightKeys::Kind::PolygonPx) {
    o["kind"] = "polygon_px";
    o["points"] = toJson(l.pointsPx);
  } else {
    o["kind"] = "rect_m";
    ojson corners = ojson::array();
    for (const Vec3& v : l.cornersM) corners.push_back(toJson(v));
    o["corners"] = corners;
  }
  if (l.rgb) o["rgb"] = toJson(*l.rgb);
  o["refine"] = l.refine;
  if (l.lock) o["lock"] = true;
  if (l.refineSize) o["refine_size"] = true;
  if (l.positionWeight != LightKeys{}.positionWeight ||
      l.intensityWeight != LightKeys{}.intensityWeight || l.sizeWeight != LightKeys{}.sizeWeight)
    o["weights"] =
        ojson{{"position", l.positionWeight}, {"intensity", l.intensityWeight}, {"size", l.sizeWeight}};
  return o;
}

ojson shaftJson(const ShaftKeys& s) {
  ojson o = ojson::object();
  if (s.shaftBoxPx) o["shaft_box_px"] = *s.shaftBoxPx;
  if (s.sourceBoxPx) o["source_box_px"] = *s.sourceBoxPx;
  if (s.direction) o["direction"] = toJson(*s.direction);
  return o;
}

// A surface in its kind's form: stairs from a profile, stairs from a spec, or an extrusion.
ojson surfaceJson(const SurfaceKeys& s) {
  if (s.kind == "stairs" && !s.profilePx.empty()) {
    ojson o{{"kind", s.kind}, {"profile_px", toJson(s.profilePx)}};
    if (!s.wall.empty()) o["wall"] = s.wall;
    if (s.widthM > 0) o["width_m"] = s.widthM;
    return o;
  }
  if (s.kind == "stairs")
    return ojson{{"kind", s.kind},           {"base_px", toJson(s.basePx)},
                 {"steps", s.steps},         {"rise_m", s.riseM},
                 {"run_m", s.runM},          {"width_m", s.widthM},
                 {"climb_axis", s.climbAxis}};
  ojson o{{"kind", s.kind},
          {"outline_px", toJson(s.outlinePx)},
          {"height_click_px", toJson(s.heightClickPx)}};
  if (s.thicknessM) o["thickness_m"] = *s.thicknessM;
  return o;
}

ojson occluderJson(const OccluderKeys& o) {
  ojson fg = ojson::array(), bg = ojson::array();
  for (const auto& s : o.foregroundScribblesPx) fg.push_back(toJson(s));
  for (const auto& s : o.backgroundScribblesPx) bg.push_back(toJson(s));
  return ojson{{"foreground_scribbles_px", fg}, {"background_scribbles_px", bg}};
}

ojson objectJson(const ObjectKeys& o) {
  const MaterialKeys& m = o.material;
  ojson mat{{"preset", m.preset},
            {"albedo", toJson(m.albedo)},
            {"roughness", m.roughness},
            {"ior", m.ior},
            {"rgb", toJson(m.rgb)}};
  ojson obj{{"mesh", o.mesh},
            {"base_px", toJson(o.basePx)},
            {"height_m", o.heightM},
            {"yaw_deg", o.yawDeg},
            {"material", mat}};
  if (o.subdivideLevels > 0) obj["subdivide"] = o.subdivideLevels;
  if (!o.name.empty()) obj["name"] = o.name;
  if (o.hidden) obj["hidden"] = true;
  return obj;
}

ojson renderJson(const RenderKeys& render) {
  ojson r;
  r["spp"] = render.spp;
  r["seconds"] = render.seconds ? ojson(*render.seconds) : ojson(nullptr);
  r["noise"] = render.noise;
  r["exposure"] = render.exposure;
  r["seed"] = render.seed;
  r["grain"] = render.grain;
  r["clamp_indirect"] = render.clampIndirect > 0 ? ojson(render.clampIndirect) : ojson("off");
  return r;
}

// A JSON array of one entry per item, or nothing when there are none.
template <class T, class ToJson>
void putList(ojson& j, const char* key, const std::vector<T>& items, ToJson toJsonOf) {
  if (items.empty()) return;
  ojson a = ojson::array();
  for (const T& item : items) a.push_back(toJsonOf(item));
  j[key] = a;
}

// The document in the spec's key order; optional sections only when they hold something.
ojson buildJson(const SceneDoc& doc) {
  ojson j;
  j["format"] = "inlay-scene";
  j["version"] = kVersion;
  j["photo"] = doc.photo;

  const CameraKeys& c = doc.camera;
  const bool anyLines = std::any_of(c.vanishingLinesPx.begin(), c.vanishingLinesPx.end(),
                                    [](const auto& l) { return l.has_value(); });
  const bool anyResponse = c.response.mode != ResponseKeys::Mode::Auto;
  const bool anyVignetting = c.vignetting.mode != VignettingKeys::Mode::None;
  if (c.heightM || c.focalPx || c.principalPx || c.vanishingPointsPx || anyLines || anyResponse ||
      anyVignetting)
    j["camera"] = cameraJson(c, anyLines);
  if (doc.layout.backWallPx || doc.layout.rearM) {
    ojson layout = ojson::object();
    if (doc.layout.backWallPx) {
      ojson a = ojson::array();
      for (const Vec2& v : *doc.layout.backWallPx) a.push_back(toJson(v));
      layout["back_wall_px"] = a;
    }
    if (doc.layout.rearM) layout["rear_m"] = *doc.layout.rearM;
    j["layout"] = layout;
  }
  putList(j, "lights", doc.lights, lightJson);
  putList(j, "shafts", doc.shafts, shaftJson);
  putList(j, "surfaces", doc.surfaces, surfaceJson);
  putList(j, "occluders", doc.occluders, occluderJson);
  putList(j, "objects", doc.objects, objectJson);
  if (!doc.room.materials.empty()) {
    ojson mats = ojson::object();
    for (const auto& [name, m] : doc.room.materials)
      mats[name] = ojson{{"preset", m.preset},
                         {"roughness", m.roughness},
                         {"ior", m.ior},
                         {"reflectance", toJson(m.reflectance)}};
    j["room"] = ojson{{"materials", mats}};
  }
  j["render"] = renderJson(doc.render);
  return j;
}

// The key path of the first non-finite number (JSON cannot hold it: nlohmann writes null).
std::optional<std::string> firstNonFinite(const ojson& j, const std::string& path) {
  if (j.is_number_float() && !std::isfinite(j.get<double>())) return path;
  if (j.is_object())
    for (auto it = j.begin(); it != j.end(); ++it)
      if (auto p = firstNonFinite(it.value(), child(path, it.key()))) return p;
  if (j.is_array())
    for (size_t i = 0; i < j.size(); ++i)
      if (auto p = firstNonFinite(j[i], child(path, i))) return p;
  return std::nullopt;
}

}  // namespace

std::string sceneToJson(const SceneDoc& doc) {
  // Invalid UTF-8 in a path is replaced (U+FFFD) rather than thrown; saveSceneFile refuses it.
  return buildJson(doc).dump(2, ' ', false, ojson::error_handler_t::replace) + "\n";
}

Status saveSceneFile(const std::string& path, const SceneDoc& doc) {
  const ojson j = buildJson(doc);
  // Never write a file that would not read back.
  if (auto key = firstNonFinite(j, ""))
    return Error{path, *key, "not a finite number; nothing was written"};
  std::string text;
  try {
    text = j.dump(2) + "\n";
  } catch (const nlohmann::json::exception&) {
    return Error{path, "", "a path or name is not valid UTF-8; nothing was written"};
  }
  return writeFileAtomically(path, text);
}

}  // namespace inlay
