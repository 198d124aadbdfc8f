// The measurements behind docs/architecture.md's "Hand-written or library" rows that run in
// seconds: our resize against OpenImageIO's, the 8-bit sRGB encoder against a pow per value and
// a 65536-entry table, OpenCV's Otsu threshold against the exact optimum on sorted values, and
// subdivision (OpenMesh welding + OpenSubdiv face-varying UVs) against the std::map welding it
// replaced, on each MESH. One thread each (OIIO's own pool off), best of `repeats`, in the
// thread's CPU time. Writes
// OUT.csv with one row per method: what, method, ms, error (what the error means is in the
// row's `error_is`). PHOTO "-" skips the photo row; BENCH_ONLY=subdivide runs the subdivision
// rows alone (a trial, not the table).
//
//   build/tests/bench/bench_library_choices OUT.csv [repeats [PHOTO [MESH...]]]
//   /usr/bin/python3 tests/bench/benchlib.py table OUT.csv library_choices
#include "inlay/modeling/image.h"
#include "inlay/modeling/image_io.h"
#include "inlay/modeling/mesh.h"
#include "inlay/modeling/subdivide.h"
#include "inlay/lighting/shaft.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <algorithm>
#include <array>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <unordered_set>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace inlay;

int gRepeats = 3;

// The thread's CPU milliseconds (on a loaded machine the wall clock of anything longer than a
// scheduler slice mostly measures the other processes).
double cpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

double bestMs(const std::function<void()>& f) {
  double best = 1e300;
  for (int k = 0; k < gRepeats; ++k) {
    const double t0 = cpuMs();
    f();
    best = std::min(best, cpuMs() - t0);
  }
  return best;
}

struct Row {
  std::string what, method;
  double ms, error;
  std::string errorIs;
};

ImageF oiioResize(const ImageF& src, int w, int h, const char* filter, float width) {
  OIIO::ImageSpec in(src.width, src.height, src.channels, OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf a(in, const_cast<float*>(src.data.data()));
  OIIO::ImageBuf b(OIIO::ImageSpec(w, h, src.channels, OIIO::TypeDesc::FLOAT));
  OIIO::ImageBufAlgo::resize(b, a, filter, width);
  ImageF out(w, h, src.channels);
  b.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, out.data.data());
  return out;
}

// Resize a 12 MP photo to the studio's 1600 x 1200; error: the mean absolute difference from the
// exact area average of a 4:1 shrink (ours is exact there), on the 4032 x 3024 -> 1008 x 756 case.
void resizeRows(std::vector<Row>& rows) {
  ImageF big(4032, 3024, 3);
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0, 1);
  for (float& x : big.data) x = u(rng);
  ImageF exact(1008, 756, 3);
  for (int y = 0; y < 756; ++y)
    for (int x = 0; x < 1008; ++x)
      for (int c = 0; c < 3; ++c) {
        double s = 0;
        for (int j = 0; j < 4; ++j)
          for (int i = 0; i < 4; ++i) s += big.at(4 * x + i, 4 * y + j, c);
        exact.at(x, y, c) = float(s / 16);
      }
  auto meanAbs = [&](const ImageF& a) {
    double s = 0;
    for (size_t i = 0; i < a.data.size(); ++i) s += std::abs(a.data[i] - exact.data[i]);
    return s / double(a.data.size());
  };
  const char* what = "resize 4032x3024 -> 1600x1200";
  const char* errorIs = "mean |value - exact 4:1 area average| at 1008x756";
  ImageF out;
  rows.push_back({what, "ours (resizeImage)", bestMs([&] { out = resizeImage(big, 1600, 1200); }),
                  meanAbs(resizeImage(big, 1008, 756)), errorIs});
  rows.push_back({what, "OIIO resize, default filter",
                  bestMs([&] { out = oiioResize(big, 1600, 1200, "", 0); }),
                  meanAbs(oiioResize(big, 1008, 756, "", 0)), errorIs});
  rows.push_back({what, "OIIO resize, box",
                  bestMs([&] { out = oiioResize(big, 1600, 1200, "box", 4032.f / 1600); }),
                  meanAbs(oiioResize(big, 1008, 756, "box", 4)), errorIs});
}

// Encode 4.8 M linear values (a 1600 x 1000 RGB frame) to 8-bit sRGB; error: values whose code
// differs from lround(255 * linearToSrgb(v)).
void srgbRows(std::vector<Row>& rows) {
  std::vector<float> v(size_t(1600) * 1000 * 3);
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> u(0, 1.2f);
  for (float& x : v) x = u(rng) * u(rng);
  std::vector<unsigned char> exact(v.size()), out(v.size());
  for (size_t i = 0; i < v.size(); ++i)
    exact[i] = (unsigned char)std::lround(255.f * linearToSrgb(v[i]));
  static std::array<unsigned char, 65536> lut;
  for (int i = 0; i < 65536; ++i)
    lut[size_t(i)] = (unsigned char)std::lround(255.f * linearToSrgb(float(i) / 65535.f));
  auto wrong = [&] {
    double n = 0;
    for (size_t i = 0; i < v.size(); ++i) n += out[i] != exact[i];
    return n;
  };
  const char* what = "sRGB encode 4.8 M values";
  const char* errorIs = "codes differing from lround(255 linearToSrgb(v))";
  double ms = bestMs([&] {
    for (size_t i = 0; i < v.size(); ++i) out[i] = srgbCode8(v[i]);
  });
  rows.push_back({what, "srgbCode8 (boundaries + bucket table)", ms, wrong(), errorIs});
  ms = bestMs([&] {
    for (size_t i = 0; i < v.size(); ++i) {
      const float x = v[i];
      // x is in (0, 1) here: adding 0.5 and truncating rounds it (what the LUT variant costs).
      out[i] = !(x > 0.f) ? 0
               : x >= 1.f ? 255
                          : lut[size_t(x * 65535.f + 0.5f)];  // NOLINT(bugprone-incorrect-roundings)
    }
  });
  rows.push_back({what, "65536-entry table (the studio's before)", ms, wrong(), errorIs});
  ms = bestMs([&] {
    for (size_t i = 0; i < v.size(); ++i)
      out[i] = (unsigned char)std::lround(255.f * linearToSrgb(v[i]));
  });
  rows.push_back({what, "pow per value", ms, wrong(), errorIs});
}

// Between-class variance of splitting `v` above `t`.
double betweenClass(const std::vector<double>& v, double t) {
  double s[2] = {0, 0}, n[2] = {0, 0};
  for (double x : v) s[x > t] += x, n[x > t] += 1;
  if (n[0] == 0 || n[1] == 0) return 0;
  const double d = s[0] / n[0] - s[1] / n[1];
  return n[0] * n[1] * d * d;
}

// The best split of the sorted values (exact Otsu, no bins).
double bestBetweenClass(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  double total = 0, s = 0, best = 0;
  for (double x : v) total += x;
  for (size_t i = 0; i + 1 < v.size(); ++i) {
    s += v[i];
    const double n0 = double(i + 1), n1 = double(v.size()) - n0, d = s / n0 - (total - s) / n1;
    best = std::max(best, n0 * n1 * d * d);
  }
  return best;
}

// 500 random two-mode sets of log luminances (200 to 20 200 values); error: the mean fraction
// of the exact optimum's between-class variance the threshold misses.
void otsuRows(std::vector<Row>& rows) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  double loss = 0, ms = 0;
  const int sets = 500;
  for (int k = 0; k < sets; ++k) {
    const int n = 200 + int(u(rng) * 20000);
    const double lit = 0.05 + 0.9 * u(rng), lo = -3 + u(rng), hi = lo + 0.2 + 3 * u(rng);
    std::normal_distribution<double> a(lo, 0.05 + 0.5 * u(rng)), b(hi, 0.05 + 0.5 * u(rng));
    std::vector<double> v(size_t(n), 0.0);
    for (double& x : v) x = u(rng) < lit ? b(rng) : a(rng);
    double t = 0, mLow = 0, mHigh = 0;
    ms += bestMs([&] { t = detail::otsuThreshold(v, &mLow, &mHigh); });
    loss += 1 - betweenClass(v, t) / bestBetweenClass(v);
  }
  rows.push_back({"Otsu threshold, 500 two-mode sets", "cv::threshold(THRESH_OTSU) on 256 levels",
                  ms / sets, loss / sets,
                  "mean share of the exact optimum's between-class variance missed"});
}

// Loading a photo as the engine does (linear float, EXIF applied, checks) and encoding it for the
// screen: what the studio's quick preview would cost through image_io instead of QImageReader.
void photoRows(std::vector<Row>& rows, const std::string& path) {
  std::vector<unsigned char> codes;
  const double ms = bestMs([&] {
    const auto loaded = loadImage(path);
    if (!loaded) return;
    codes.resize(loaded->linearRgb.data.size());
    for (size_t i = 0; i < codes.size(); ++i) codes[i] = srgbCode8(loaded->linearRgb.data[i]);
  });
  rows.push_back({"photo preview " + path.substr(path.find_last_of('/') + 1), "loadImage + srgbCode8",
                  ms, 0, "(time only)"});
}

// The subdivision before OpenMesh and face-varying UVs (modeling/src/geometry/subdivide.cpp up
// to November 2026), kept here as the baseline: std::map welding, a std::map of directed edges
// for the quad pairing, positions only (UVs dropped).
namespace before {

using namespace OpenSubdiv;

struct Point {
  Vec3 p = Vec3::Zero();
  void Clear(void* = nullptr) { p.setZero(); }
  void AddWithWeight(const Point& src, float weight) { p += double(weight) * src.p; }
};

struct Welded {
  std::vector<Vec3> positions;
  std::vector<std::array<int, 3>> triangles;
};

Welded weld(const TriangleMesh& mesh) {
  Welded w;
  std::map<std::array<float, 3>, int> index;
  std::vector<int> remap(mesh.positions.size(), -1);
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const Vec3f& p = mesh.positions[i];
    if (!p.allFinite()) continue;
    const auto [it, added] =
        index.emplace(std::array<float, 3>{p.x(), p.y(), p.z()}, int(w.positions.size()));
    if (added) w.positions.push_back(p.cast<double>());
    remap[i] = it->second;
  }
  for (const auto& t : mesh.triangles) {
    if (std::max({t[0], t[1], t[2]}) >= mesh.positions.size()) continue;
    const std::array<int, 3> r = {remap[t[0]], remap[t[1]], remap[t[2]]};
    if (r[0] < 0 || r[1] < 0 || r[2] < 0 || r[0] == r[1] || r[1] == r[2] || r[0] == r[2]) continue;
    w.triangles.push_back(r);
  }
  return w;
}

std::vector<std::array<int, 4>> pairIntoQuads(const Welded& w) {
  const size_t n = w.triangles.size();
  auto longestEdge = [&](size_t t) {
    int best = 0;
    double bestLen = -1;
    for (int k = 0; k < 3; ++k) {
      const double len =
          (w.positions[size_t(w.triangles[t][(k + 1) % 3])] - w.positions[size_t(w.triangles[t][k])])
              .squaredNorm();
      if (len > bestLen) bestLen = len, best = k;
    }
    return best;
  };
  auto normal = [&](size_t t) {
    const auto& v = w.triangles[t];
    return Vec3((w.positions[size_t(v[1])] - w.positions[size_t(v[0])])
                    .cross(w.positions[size_t(v[2])] - w.positions[size_t(v[0])])
                    .normalized());
  };
  std::map<std::pair<int, int>, size_t> directed;
  for (size_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k) directed[{w.triangles[t][k], w.triangles[t][(k + 1) % 3]}] = t;
  std::vector<std::array<int, 4>> quads;
  std::vector<bool> used(n, false);
  for (size_t t = 0; t < n; ++t) {
    if (used[t]) continue;
    const int k = longestEdge(t);
    const int a = w.triangles[t][k], b = w.triangles[t][(k + 1) % 3], c = w.triangles[t][(k + 2) % 3];
    const auto it = directed.find({b, a});
    if (it == directed.end() || used[it->second] || it->second == t) return {};
    const size_t u = it->second;
    const int ku = longestEdge(u);
    if (w.triangles[u][ku] != b || w.triangles[u][(ku + 1) % 3] != a) return {};
    if (!(normal(t).dot(normal(u)) > 0.999)) return {};
    used[t] = used[u] = true;
    quads.push_back({a, w.triangles[u][(ku + 2) % 3], b, c});
  }
  return quads;
}

std::optional<TriangleMesh> subdivide(const TriangleMesh& mesh, int levels) {
  const Welded w = weld(mesh);
  if (w.triangles.empty()) return std::nullopt;
  const std::vector<std::array<int, 4>> quads = pairIntoQuads(w);
  std::vector<int> counts, indices;
  if (quads.empty()) {
    counts.assign(w.triangles.size(), 3);
    for (const auto& t : w.triangles) indices.insert(indices.end(), t.begin(), t.end());
  } else {
    counts.assign(quads.size(), 4);
    for (const auto& q : quads) indices.insert(indices.end(), q.begin(), q.end());
  }
  Far::TopologyDescriptor desc;
  desc.numVertices = int(w.positions.size());
  desc.numFaces = int(counts.size());
  desc.numVertsPerFace = counts.data();
  desc.vertIndicesPerFace = indices.data();
  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(
      desc, Factory::Options(quads.empty() ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK, sdc)));
  if (!refiner) return std::nullopt;
  refiner->RefineUniform(Far::TopologyRefiner::UniformOptions(levels));
  std::vector<Point> points(size_t(refiner->GetNumVerticesTotal()));
  for (size_t i = 0; i < w.positions.size(); ++i) points[i].p = w.positions[i];
  Far::PrimvarRefiner primvar(*refiner);
  Point* src = points.data();
  for (int level = 1; level <= levels; ++level) {
    Point* dst = src + refiner->GetLevel(level - 1).GetNumVertices();
    primvar.Interpolate(level, src, dst);
    src = dst;
  }
  const Far::TopologyLevel& last = refiner->GetLevel(levels);
  TriangleMesh out;
  for (int i = 0; i < last.GetNumVertices(); ++i) out.positions.push_back(src[i].p.cast<float>());
  for (int f = 0; f < last.GetNumFaces(); ++f) {
    const Far::ConstIndexArray v = last.GetFaceVertices(f);
    for (int k = 1; k + 1 < v.size(); ++k)
      out.triangles.push_back({uint32_t(v[0]), uint32_t(v[k]), uint32_t(v[k + 1])});
  }
  out.computeVertexNormals();
  return out;
}

}  // namespace before

// Share of `a`'s distinct positions that are not, bit for bit, among `b`'s (0: the same
// surface; subdivide splits seam vertices, so positions are compared as sets).
double positionsNotIn(const TriangleMesh& a, const TriangleMesh& b) {
  auto key = [](const Vec3f& p) {
    return std::string(reinterpret_cast<const char*>(p.data()), sizeof(float) * 3);
  };
  std::unordered_set<std::string> inB, inA;
  for (const Vec3f& p : b.positions) inB.insert(key(p));
  size_t missing = 0;
  for (const Vec3f& p : a.positions)
    if (inA.insert(key(p)).second && !inB.count(key(p))) ++missing;
  return inA.empty() ? 1.0 : double(missing) / double(inA.size());
}

// Each mesh subdivided (2 levels; 1 above 50 000 triangles) by the code before and by
// subdivide(); what each kept: vertices, triangles, UVs. Error of the new row: positions not in
// the old result (0 = the same surface); of the old row: the share of the input's UVs lost.
void subdivideRows(std::vector<Row>& rows, const std::vector<std::string>& meshes) {
  for (const std::string& path : meshes) {
    const auto mesh = loadMesh(path);
    if (!mesh) {
      std::fprintf(stderr, "skipping %s: %s\n", path.c_str(), mesh.error().message().c_str());
      continue;
    }
    const int levels = mesh->triangles.size() > 50'000 ? 1 : 2;
    const std::string what = "subdivide " + path.substr(path.find_last_of('/') + 1) + " (" +
                             std::to_string(mesh->triangles.size()) + " triangles, " +
                             (mesh->uvs.empty() ? "no UVs" : "UVs") + "), " + std::to_string(levels) +
                             " levels";
    auto counts = [](const TriangleMesh& m) {
      return std::to_string(m.positions.size()) + " vertices, " + std::to_string(m.triangles.size()) +
             " triangles, " + (m.uvs.empty() ? "no UVs" : "UVs");
    };
    std::optional<TriangleMesh> old;
    const double oldMs = bestMs([&] { old = before::subdivide(*mesh, levels); });
    Expected<SubdivisionResult> now = Error{};
    const double nowMs = bestMs([&] { now = subdivide(*mesh, levels); });
    if (!old || !now) {
      std::fprintf(stderr, "skipping %s: a subdivision failed\n", path.c_str());
      continue;
    }
    rows.push_back({what, "std::map weld, OpenSubdiv, UVs dropped (before): " + counts(*old), oldMs,
                    mesh->uvs.empty() ? 0.0 : 1.0, "share of the input's UVs lost"});
    rows.push_back({what,
                    "OpenMesh weld, OpenSubdiv face-varying UVs: " + counts(now->mesh) + ", " +
                        std::to_string(now->nonManifoldTriangles) + " non-manifold",
                    nowMs, positionsNotIn(now->mesh, *old),
                    "share of positions not in the before's result (0 = same surface)"});
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_library_choices OUT.csv [repeats [PHOTO [MESH...]]]\n");
    return 2;
  }
  if (argc > 2) gRepeats = std::max(1, std::atoi(argv[2]));
  const std::string photo = argc > 3 && std::string(argv[3]) != "-" ? argv[3] : "";
  const std::vector<std::string> meshes(argv + std::min(argc, 4), argv + argc);
  OIIO::attribute("threads", 1);
  std::vector<Row> rows;
  const char* only = std::getenv("BENCH_ONLY");  // "subdivide": the subdivision rows alone
  const bool all = only == nullptr || std::string(only).empty();
  if (all) {
    srgbRows(rows);
    otsuRows(rows);
    resizeRows(rows);
    if (!photo.empty()) photoRows(rows, photo);
  }
  subdivideRows(rows, meshes);
  std::ofstream csv(argv[1]);
  csv << "what,method,ms,error,error_is\n";
  for (const Row& r : rows) {
    csv << '"' << r.what << "\",\"" << r.method << "\"," << r.ms << ',' << r.error << ",\"" << r.errorIs
        << "\"\n";
    std::printf("%-36s %-42s %10.2f ms  error %.4g (%s)\n", r.what.c_str(), r.method.c_str(), r.ms,
                r.error, r.errorIs.c_str());
  }
  return csv ? 0 : 1;
}
