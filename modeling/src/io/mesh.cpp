// Triangle meshes: helpers, builtins and importers.
//
// OBJ and PLY are read by the validating readers below rather than by OpenMesh: OpenMesh 9's
// PLY reader ignores `tristrips` elements (igea.ply loads with 0 faces), its TriMesh silently
// drops non-manifold faces ("complex edge"), and it trusts face indices and header counts, so
// every file would need a full validating pass first anyway. glTF/GLB go through Assimp after a
// structural pre-check of the buffers (Assimp 5.2 reads past short buffers in some paths), and
// the glTF JSON supplies the extensions Assimp 5.2 ignores (emissive strength, IOR). FBX,
// COLLADA and 3DS go to Assimp as they are (no reader of ours), and the result gets the same
// validation. OBJ polygons are ear-clipped on their best-fit plane (concave faces stay inside
// their outline).
#include "inlay/modeling/mesh.h"

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <unordered_map>

namespace inlay {

// ---------------------------------------------------------------------------------------------
// TriangleMesh

Eigen::AlignedBox3f TriangleMesh::bounds() const {
  Eigen::AlignedBox3f b;  // empty
  for (const Vec3f& p : positions) b.extend(p);
  return b;
}

void TriangleMesh::computeVertexNormals() {
  std::vector<Eigen::Vector3d> acc(positions.size(), Eigen::Vector3d::Zero());
  for (const auto& t : triangles) {
    const Eigen::Vector3d a = positions[t[0]].cast<double>(), b = positions[t[1]].cast<double>(),
                          c = positions[t[2]].cast<double>();
    const Eigen::Vector3d n = (b - a).cross(c - a);  // length = 2 x area: area weighting
    for (uint32_t v : t) acc[v] += n;
  }
  normals.resize(positions.size());
  for (size_t i = 0; i < acc.size(); ++i) {
    const double len = acc[i].norm();
    normals[i] = len > 0 ? Vec3f((acc[i] / len).cast<float>()) : Vec3f(0, 1, 0);
  }
}

void TriangleMesh::append(const TriangleMesh& other) {
  if (other.positions.empty() && other.triangles.empty()) return;
  const uint32_t offset = uint32_t(positions.size());
  const size_t oldTriangles = triangles.size();
  const bool wasEmpty = positions.empty();

  // Normals and UVs: kept when either side has them, filled in for the side that has none
  // (normals computed, UVs zero).
  if (wasEmpty) {
    normals = other.normals;
  } else if (!normals.empty() || !other.normals.empty()) {
    if (normals.empty()) computeVertexNormals();
    if (other.normals.empty()) {
      TriangleMesh copy = other;
      copy.computeVertexNormals();
      normals.insert(normals.end(), copy.normals.begin(), copy.normals.end());
    } else {
      normals.insert(normals.end(), other.normals.begin(), other.normals.end());
    }
  }
  if (wasEmpty) {
    uvs = other.uvs;
  } else if (!uvs.empty() || !other.uvs.empty()) {
    uvs.resize(positions.size(), Vec2f(0, 0));
    if (other.uvs.empty()) uvs.resize(positions.size() + other.positions.size(), Vec2f(0, 0));
    else uvs.insert(uvs.end(), other.uvs.begin(), other.uvs.end());
  }
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  for (const auto& t : other.triangles)
    triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});

  // Materials: when either side has per-triangle materials, every triangle gets one.
  if (triangleMaterial.empty() && other.triangleMaterial.empty()) return;
  auto defaultMaterial = [this]() {
    materials.push_back(AssetMaterial{"default"});
    return uint32_t(materials.size() - 1);
  };
  if (triangleMaterial.empty() && oldTriangles > 0)
    triangleMaterial.assign(oldTriangles, defaultMaterial());
  const uint32_t matOffset = uint32_t(materials.size());
  materials.insert(materials.end(), other.materials.begin(), other.materials.end());
  if (other.triangleMaterial.empty()) {
    const uint32_t d = defaultMaterial();
    triangleMaterial.resize(triangles.size(), d);
  } else {
    for (uint32_t m : other.triangleMaterial) triangleMaterial.push_back(m + matOffset);
  }
}

// ---------------------------------------------------------------------------------------------
// Polygon faces

namespace {

using Pt2 = Eigen::Vector2d;

double cross2(const Pt2& a, const Pt2& b, const Pt2& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

// The corners in the plane through them, counter-clockwise when seen against the Newell normal;
// empty when the polygon has no area to speak of.
std::vector<Pt2> projectToBestFitPlane(const std::vector<Vec3f>& corners) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  const size_t k = corners.size();
  for (size_t i = 0; i < k; ++i) {
    const Eigen::Vector3d a = corners[i].cast<double>(), b = corners[(i + 1) % k].cast<double>();
    n += Eigen::Vector3d((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                         (a.x() - b.x()) * (a.y() + b.y()));
  }
  double extent = 0;
  for (const Vec3f& c : corners) extent = std::max(extent, double((c - corners[0]).norm()));
  if (!(n.norm() > 1e-12 * extent * extent) || !n.allFinite()) return {};
  n.normalize();
  const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);  // u x v = n
  std::vector<Pt2> out;
  out.reserve(k);
  for (const Vec3f& c : corners) out.emplace_back(u.dot(c.cast<double>()), v.dot(c.cast<double>()));
  return out;
}

bool insideOrOnTriangle(const Pt2& p, const Pt2& a, const Pt2& b, const Pt2& c) {
  return cross2(a, b, p) >= 0 && cross2(b, c, p) >= 0 && cross2(c, a, p) >= 0;
}

// Ear clipping of a counter-clockwise polygon. A corner is an ear when it turns left and no
// other remaining reflex corner lies in its triangle (only reflex corners can). When none is
// found (a self-intersecting or degenerate remainder) the most convex corner is cut anyway, so
// the count of triangles is always n - 2.
std::vector<std::array<uint32_t, 3>> clipEars(const std::vector<Pt2>& p) {
  std::vector<uint32_t> ring(p.size());
  for (size_t i = 0; i < p.size(); ++i) ring[i] = uint32_t(i);
  std::vector<std::array<uint32_t, 3>> out;
  out.reserve(p.size() - 2);
  auto turn = [&](size_t i) {
    const size_t m = ring.size();
    return cross2(p[ring[(i + m - 1) % m]], p[ring[i]], p[ring[(i + 1) % m]]);
  };
  auto isEar = [&](size_t i) {
    const size_t m = ring.size();
    const uint32_t a = ring[(i + m - 1) % m], b = ring[i], c = ring[(i + 1) % m];
    if (!(cross2(p[a], p[b], p[c]) > 0)) return false;
    for (size_t j = 0; j < m; ++j) {
      const uint32_t q = ring[j];
      if (q == a || q == b || q == c || turn(j) > 0) continue;     // convex corners cannot block
      if (p[q] == p[a] || p[q] == p[b] || p[q] == p[c]) continue;  // a bridge's twin corner
      if (insideOrOnTriangle(p[q], p[a], p[b], p[c])) return false;
    }
    return true;
  };
  while (ring.size() > 3) {
    const size_t m = ring.size();
    size_t cut = m;
    for (size_t i = 0; i < m && cut == m; ++i)
      if (isEar(i)) cut = i;
    if (cut == m) {  // no proper ear: take the most convex corner
      cut = 0;
      for (size_t i = 1; i < m; ++i)
        if (turn(i) > turn(cut)) cut = i;
    }
    out.push_back({ring[(cut + m - 1) % m], ring[cut], ring[(cut + 1) % m]});
    ring.erase(ring.begin() + std::ptrdiff_t(cut));
  }
  out.push_back({ring[0], ring[1], ring[2]});
  return out;
}

}  // namespace

std::vector<std::array<uint32_t, 3>> triangulatePolygon(const std::vector<Vec3f>& corners) {
  const size_t k = corners.size();
  std::vector<std::array<uint32_t, 3>> fan;
  for (size_t i = 1; i + 1 < k; ++i) fan.push_back({0, uint32_t(i), uint32_t(i + 1)});
  if (k <= 3) return fan;
  const std::vector<Pt2> p = projectToBestFitPlane(corners);
  if (p.empty()) return fan;  // no area: any n - 2 triangles have none
  // Ear clipping is quadratic or worse in the corners: a face beyond a thousand is fanned.
  if (k > 1024) return fan;
  bool convex = true;
  for (size_t i = 0; i < k && convex; ++i)
    convex = cross2(p[(i + k - 1) % k], p[i], p[(i + 1) % k]) >= 0;
  if (convex) return fan;
  return clipEars(p);
}

// ---------------------------------------------------------------------------------------------
// Builtins

TriangleMesh makeSphere(int subdivisions) {
  subdivisions = std::clamp(subdivisions, 0, 7);
  const float t = (1.f + std::sqrt(5.f)) / 2.f;
  std::vector<Vec3f> v = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                          {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3f& p : v) p.normalize();
  std::vector<std::array<uint32_t, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                            {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                            {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                            {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
    auto midpoint = [&](uint32_t a, uint32_t b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back((v[a] + v[b]).normalized());
      return mid[key] = uint32_t(v.size() - 1);
    };
    std::vector<std::array<uint32_t, 3>> next;
    next.reserve(f.size() * 4);
    for (const auto& tri : f) {
      const uint32_t a = midpoint(tri[0], tri[1]), b = midpoint(tri[1], tri[2]),
                     c = midpoint(tri[2], tri[0]);
      next.push_back({tri[0], a, c});
      next.push_back({tri[1], b, a});
      next.push_back({tri[2], c, b});
      next.push_back({a, b, c});
    }
    f.swap(next);
  }
  TriangleMesh m;
  m.normals = v;
  m.positions.reserve(v.size());
  for (const Vec3f& p : v) m.positions.push_back(0.5f * p);
  m.triangles = std::move(f);
  return m;
}

TriangleMesh makeCube() {
  TriangleMesh m;
  // Per face: outward normal and two in-plane axes u, w with u x w = n (counter-clockwise).
  const Vec3f normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const Vec3f& n : normals) {
    const Vec3f u = std::fabs(n.y()) > 0.5f ? Vec3f(1, 0, 0) : Vec3f(0, 1, 0);
    const Vec3f w = n.cross(u);  // u x w = u x (n x u) = n
    const uint32_t base = uint32_t(m.positions.size());
    const float s[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const auto& st : s) {
      m.positions.push_back(0.5f * (n + st[0] * u + st[1] * w));
      m.normals.push_back(n);
      m.uvs.push_back(Vec2f(0.5f * (st[0] + 1), 0.5f * (st[1] + 1)));
    }
    m.triangles.push_back({base, base + 1, base + 2});
    m.triangles.push_back({base, base + 2, base + 3});
  }
  return m;
}

namespace {

namespace fs = std::filesystem;

// Internal only: thrown inside the readers, turned into Error at loadMesh.
struct MeshError {
  std::string element;
  std::string reason;
};
[[noreturn]] void fail(const std::string& element, const std::string& reason) {
  throw MeshError{element, reason};
}

std::string lowerExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

std::string readWholeFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("", "cannot open for reading");
  std::string s;
  in.seekg(0, std::ios::end);
  s.resize(size_t(in.tellg()));
  in.seekg(0);
  in.read(s.data(), std::streamsize(s.size()));
  if (!in) fail("", "read failed");
  return s;
}

// ---------------------------------------------------------------------------------------------
// OBJ

struct ObjCorner {
  int64_t v, vt, vn;  // 0-based, -1 = absent
};

bool parseDouble(std::string_view tok, double& out) {
  const auto r = std::from_chars(tok.data(), tok.data() + tok.size(), out);
  return r.ec == std::errc() && r.ptr == tok.data() + tok.size();
}
bool parseInt(std::string_view tok, int64_t& out) {
  const auto r = std::from_chars(tok.data(), tok.data() + tok.size(), out);
  return r.ec == std::errc() && r.ptr == tok.data() + tok.size();
}

void splitTokens(std::string_view line, std::vector<std::string_view>& toks) {
  toks.clear();
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const size_t b = i;
    while (i < line.size() && !(line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    if (i > b) toks.push_back(line.substr(b, i - b));
  }
}

// Clamps what a file may say to what the renderer can use.
void sanitize(AssetMaterial& mat) {
  auto clamp01 = [](double v) { return std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0; };
  for (int k = 0; k < 3; ++k) {
    mat.baseColor[k] = clamp01(mat.baseColor[k]);
    mat.emission[k] = std::isfinite(mat.emission[k]) ? std::max(0.0, mat.emission[k]) : 0.0;
  }
  mat.metallic = clamp01(mat.metallic);
  mat.roughness = clamp01(mat.roughness);
  mat.transmission = clamp01(mat.transmission);
  if (!(mat.ior >= 1.0 && mat.ior <= 5.0)) mat.ior = 1.5;
}

// Materials named by `usemtl`, in that order, filled from the MTL files. Lenient: a missing
// MTL file or a malformed line leaves the defaults (the geometry is still worth loading).
std::vector<AssetMaterial> readMtl(const std::vector<std::string>& files, const fs::path& dir,
                                   const std::vector<std::string>& names) {
  std::vector<AssetMaterial> out(names.size());
  std::map<std::string, size_t> index;
  for (size_t i = 0; i < names.size(); ++i) {
    out[i].name = names[i];
    index.emplace(names[i], i);
  }
  std::vector<std::string_view> toks;
  for (const std::string& f : files) {
    std::error_code ec;
    const fs::path p = dir / f;
    if (!fs::is_regular_file(p, ec) || fs::file_size(p, ec) > (64u << 20)) continue;
    std::ifstream in(p, std::ios::binary);
    std::string line;
    AssetMaterial* cur = nullptr;
    bool haveRoughness = false;
    while (std::getline(in, line)) {
      splitTokens(line, toks);
      if (toks.empty() || toks[0][0] == '#') continue;
      if (toks[0] == "newmtl") {
        auto it = toks.size() >= 2 ? index.find(std::string(toks[1])) : index.end();
        cur = it == index.end() ? nullptr : &out[it->second];
        haveRoughness = false;
        continue;
      }
      if (!cur) continue;
      double x[3] = {0, 0, 0};
      size_t n = 0;
      for (; n < 3 && n + 1 < toks.size() && parseDouble(toks[n + 1], x[n]); ++n) {
      }
      const std::string_view kw = toks[0];
      if (kw == "Kd" && n == 3) cur->baseColor = Vec3(x[0], x[1], x[2]);
      else if (kw == "Ke" && n == 3) cur->emission = Vec3(x[0], x[1], x[2]);
      else if (kw == "Ni" && n >= 1) cur->ior = x[0];
      else if (kw == "d" && n >= 1) cur->transmission = 1.0 - x[0];
      else if (kw == "Tr" && n >= 1) cur->transmission = x[0];
      else if (kw == "Pm" && n >= 1) cur->metallic = x[0];
      else if (kw == "Pr" && n >= 1) {
        cur->roughness = x[0];
        haveRoughness = true;
      } else if (kw == "Ns" && n >= 1 && !haveRoughness && x[0] >= 0) {
        cur->roughness = std::sqrt(2.0 / (x[0] + 2.0));  // Blinn-Phong exponent -> roughness
      }
    }
  }
  for (AssetMaterial& m : out) sanitize(m);
  return out;
}

// Appends one polygon face (vertex indices into m.positions): triangles (ids.size() - 2 of them)
// that follow the face's outline, concave ones included.
void addFace(TriangleMesh& m, const std::vector<uint32_t>& ids) {
  if (ids.size() == 3) {
    m.triangles.push_back({ids[0], ids[1], ids[2]});
    return;
  }
  std::vector<Vec3f> corners;
  corners.reserve(ids.size());
  for (uint32_t i : ids) corners.push_back(m.positions[i]);
  for (const auto& t : triangulatePolygon(corners))
    m.triangles.push_back({ids[t[0]], ids[t[1]], ids[t[2]]});
}

// What an OBJ file says, as read (indices 0-based, checked against the final counts later).
struct ObjData {
  std::vector<Vec3f> v, vn;
  std::vector<Vec2f> vt;
  std::vector<std::vector<ObjCorner>> faces;
  std::vector<size_t> faceLine;
  std::vector<int> faceMaterial;  // index into materialNames, -1 before any usemtl
  std::vector<std::string> materialNames, mtlFiles;
  std::map<std::string, int> materialIndex;
  int currentMaterial = -1;
  size_t triangleCount = 0;
};

// A 'v', 'vn' or 'vt' statement: finite numbers, at most limits.maxVertices vertices.
void readObjNumbers(ObjData& d, const std::vector<std::string_view>& toks, const std::string& where,
                    const MeshLimits& limits) {
  const std::string_view kw = toks[0];
  const size_t need = kw == "vt" ? 1 : 3;
  if (toks.size() < need + 1)
    fail(where, "'" + std::string(kw) + "' needs " + std::to_string(need) + " numbers");
  double x[3] = {0, 0, 0};
  for (size_t k = 0; k < std::min<size_t>(3, toks.size() - 1); ++k) {
    if (kw == "vt" && k == 2) break;
    if (!parseDouble(toks[k + 1], x[k]))
      fail(where, "malformed number '" + std::string(toks[k + 1]) + "'");
    if (!std::isfinite(x[k]) || std::fabs(x[k]) > 3e38)
      fail(where, "non-finite coordinate '" + std::string(toks[k + 1]) + "'");
  }
  if (kw == "v") {
    if (d.v.size() >= limits.maxVertices)
      fail(where, "more than " + std::to_string(limits.maxVertices) + " vertices");
    d.v.emplace_back(float(x[0]), float(x[1]), float(x[2]));
  } else if (kw == "vn") {
    d.vn.emplace_back(float(x[0]), float(x[1]), float(x[2]));
  } else {
    d.vt.emplace_back(float(x[0]), float(x[1]));
  }
}

// One face corner, "v", "v/vt", "v//vn" or "v/vt/vn". Negative indices count back from the last
// element read so far.
ObjCorner readObjCorner(std::string_view tok, const ObjData& d, const std::string& where) {
  int64_t idx[3] = {0, 0, 0};
  size_t s = 0;
  for (int part = 0; part < 3 && s <= tok.size(); ++part) {
    size_t e = tok.find('/', s);
    if (e == std::string_view::npos) e = tok.size();
    const std::string_view num = tok.substr(s, e - s);
    if (!num.empty() && !parseInt(num, idx[part]))
      fail(where, "malformed face index '" + std::string(tok) + "'");
    if (part == 0 && num.empty()) fail(where, "face corner without a vertex index");
    if (!num.empty() && idx[part] == 0) fail(where, "face index 0 (OBJ indices start at 1)");
    s = e + 1;
    if (e == tok.size()) break;
  }
  const size_t counts[3] = {d.v.size(), d.vt.size(), d.vn.size()};
  ObjCorner c{-1, -1, -1};
  int64_t* outs[3] = {&c.v, &c.vt, &c.vn};
  static const char* names[3] = {"vertex", "texture", "normal"};
  for (int part = 0; part < 3; ++part) {
    if (idx[part] == 0) continue;
    const int64_t r = idx[part] < 0 ? int64_t(counts[part]) + idx[part] : idx[part] - 1;
    if (r < 0)
      fail(where, std::string(names[part]) + " index " + std::to_string(idx[part]) +
                      " refers before the first " + names[part]);
    *outs[part] = r;
  }
  return c;
}

// An 'f' statement: at least 3 corners, at most limits.maxTriangles triangles in the file.
void readObjFace(ObjData& d, const std::vector<std::string_view>& toks, const std::string& where,
                 size_t lineNo, const MeshLimits& limits) {
  if (toks.size() < 4) fail(where, "a face needs at least 3 vertices");
  std::vector<ObjCorner> face;
  for (size_t k = 1; k < toks.size(); ++k) face.push_back(readObjCorner(toks[k], d, where));
  d.triangleCount += face.size() - 2;
  if (d.triangleCount > limits.maxTriangles)
    fail(where, "more than " + std::to_string(limits.maxTriangles) + " triangles");
  d.faces.push_back(std::move(face));
  d.faceLine.push_back(lineNo);
  d.faceMaterial.push_back(d.currentMaterial);
}

// The statements line by line: vertices, faces and materials; others (o, g, s, l, p) do not
// change what we keep.
ObjData parseObj(const std::string& text, const MeshLimits& limits) {
  ObjData d;
  std::vector<std::string_view> toks;
  size_t lineNo = 0, pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string_view line(text.data() + pos, end - pos);
    pos = end + 1;
    ++lineNo;
    if (line.empty() || line[0] == '#') continue;
    splitTokens(line, toks);
    if (toks.empty()) continue;
    const std::string where = "line " + std::to_string(lineNo);
    const std::string_view kw = toks[0];
    if (kw == "v" || kw == "vn" || kw == "vt") {
      readObjNumbers(d, toks, where, limits);
    } else if (kw == "f") {
      readObjFace(d, toks, where, lineNo, limits);
    } else if (kw == "usemtl" && toks.size() >= 2) {
      const std::string name(toks[1]);
      auto [it, added] = d.materialIndex.emplace(name, int(d.materialNames.size()));
      if (added) d.materialNames.push_back(name);
      d.currentMaterial = it->second;
    } else if (kw == "mtllib") {
      for (size_t k = 1; k < toks.size(); ++k) d.mtlFiles.emplace_back(toks[k]);
    }
  }
  return d;
}

// Which attributes every corner has.
struct ObjAttributes {
  bool allVt = true, allVn = true;
};

// Range checks against the final counts (forward references are tolerated).
ObjAttributes checkObjRanges(const ObjData& d) {
  ObjAttributes a;
  for (size_t fi = 0; fi < d.faces.size(); ++fi) {
    for (const ObjCorner& c : d.faces[fi]) {
      const std::string where = "line " + std::to_string(d.faceLine[fi]);
      if (c.v >= int64_t(d.v.size()))
        fail(where, "vertex index " + std::to_string(c.v + 1) + " out of range (file has " +
                        std::to_string(d.v.size()) + " vertices)");
      if (c.vt >= int64_t(d.vt.size()))
        fail(where, "texture index " + std::to_string(c.vt + 1) + " out of range (file has " +
                        std::to_string(d.vt.size()) + ")");
      if (c.vn >= int64_t(d.vn.size()))
        fail(where, "normal index " + std::to_string(c.vn + 1) + " out of range (file has " +
                        std::to_string(d.vn.size()) + ")");
      a.allVt = a.allVt && c.vt >= 0;
      a.allVn = a.allVn && c.vn >= 0;
    }
  }
  return a;
}

// The materials `usemtl` named, from the MTL files beside the OBJ, and one per triangle (a
// "default" material for faces before any usemtl).
void assignObjMaterials(TriangleMesh& m, const ObjData& d, const std::string& path) {
  if (d.materialNames.empty()) return;
  m.materials = readMtl(d.mtlFiles, fs::path(path).parent_path(), d.materialNames);
  uint32_t noMaterial = uint32_t(m.materials.size());
  if (std::find(d.faceMaterial.begin(), d.faceMaterial.end(), -1) != d.faceMaterial.end())
    m.materials.push_back(AssetMaterial{"default"});
  for (size_t fi = 0; fi < d.faces.size(); ++fi)
    m.triangleMaterial.insert(m.triangleMaterial.end(), d.faces[fi].size() - 2,
                              d.faceMaterial[fi] < 0 ? noMaterial : uint32_t(d.faceMaterial[fi]));
}

// The faces over one output vertex per distinct (v, vt, vn) corner; vt and vn are kept only
// when every corner has them.
void addObjFacesWithAttributes(TriangleMesh& m, const ObjData& d, ObjAttributes a) {
  std::unordered_map<uint64_t, uint32_t> corner;
  auto vertexOf = [&](const ObjCorner& c) {
    const uint64_t key = (uint64_t(c.v) * 0x9E3779B97F4A7C15ull) ^
                         (uint64_t(a.allVt ? c.vt : 0) * 0xC2B2AE3D27D4EB4Full) ^
                         (uint64_t(a.allVn ? c.vn : 0) + 0x165667B19E3779F9ull);
    // Collisions of the mixed key would merge different corners: verify and fall back.
    auto it = corner.find(key);
    if (it != corner.end()) {
      const uint32_t i = it->second;
      if (m.positions[i] == d.v[size_t(c.v)] && (!a.allVt || m.uvs[i] == d.vt[size_t(c.vt)]) &&
          (!a.allVn || m.normals[i] == d.vn[size_t(c.vn)]))
        return i;
    }
    const uint32_t i = uint32_t(m.positions.size());
    m.positions.push_back(d.v[size_t(c.v)]);
    if (a.allVt) m.uvs.push_back(d.vt[size_t(c.vt)]);
    if (a.allVn) m.normals.push_back(d.vn[size_t(c.vn)]);
    if (it == corner.end()) corner.emplace(key, i);
    return i;
  };
  for (const auto& face : d.faces) {
    std::vector<uint32_t> ids;
    ids.reserve(face.size());
    for (const ObjCorner& c : face) ids.push_back(vertexOf(c));
    addFace(m, ids);
  }
}

TriangleMesh readObj(const std::string& text, const std::string& path, const MeshLimits& limits) {
  ObjData d = parseObj(text, limits);
  const ObjAttributes a = checkObjRanges(d);
  TriangleMesh m;
  assignObjMaterials(m, d, path);
  if (!a.allVt && !a.allVn) {
    // Positions only: the file's vertices as they are.
    m.positions = std::move(d.v);
    for (const auto& face : d.faces) {
      std::vector<uint32_t> ids;
      ids.reserve(face.size());
      for (const ObjCorner& c : face) ids.push_back(uint32_t(c.v));
      addFace(m, ids);
    }
    return m;
  }
  addObjFacesWithAttributes(m, d, a);
  if (m.positions.size() > limits.maxVertices)
    fail("", "more than " + std::to_string(limits.maxVertices) + " vertices");
  return m;
}

// ---------------------------------------------------------------------------------------------
// PLY (ascii, binary little and big endian; elements vertex, face, tristrips; others skipped)

enum class PlyType { I8, U8, I16, U16, I32, U32, F32, F64 };

bool plyType(const std::string& s, PlyType& t) {
  static const std::pair<const char*, PlyType> names[] = {
      {"char", PlyType::I8},    {"int8", PlyType::I8},     {"uchar", PlyType::U8},
      {"uint8", PlyType::U8},   {"short", PlyType::I16},   {"int16", PlyType::I16},
      {"ushort", PlyType::U16}, {"uint16", PlyType::U16},  {"int", PlyType::I32},
      {"int32", PlyType::I32},  {"uint", PlyType::U32},    {"uint32", PlyType::U32},
      {"float", PlyType::F32},  {"float32", PlyType::F32}, {"double", PlyType::F64},
      {"float64", PlyType::F64}};
  for (const auto& [n, ty] : names)
    if (s == n) {
      t = ty;
      return true;
    }
  return false;
}
size_t plySize(PlyType t) {
  switch (t) {
    case PlyType::I8:
    case PlyType::U8: return 1;
    case PlyType::I16:
    case PlyType::U16: return 2;
    case PlyType::I32:
    case PlyType::U32:
    case PlyType::F32: return 4;
    default: return 8;
  }
}

struct PlyProperty {
  std::string name;
  bool isList = false;
  PlyType countType = PlyType::U8, type = PlyType::F32;
};
struct PlyElement {
  std::string name;
  uint64_t count = 0;
  int headerLine = 0;  // where the header declares it (for messages about lying counts)
  std::vector<PlyProperty> props;
};

// Reads values from the body with bounds checks; ascii or binary.
class PlyBody {
 public:
  enum class Format { Ascii, Le, Be };
  PlyBody(const std::string& data, size_t pos, Format f) : d_(data), pos_(pos), f_(f) {}

  double read(PlyType t, const std::string& where) {
    if (f_ == Format::Ascii) {
      while (pos_ < d_.size() && std::isspace((unsigned char)d_[pos_])) ++pos_;
      size_t e = pos_;
      while (e < d_.size() && !std::isspace((unsigned char)d_[e])) ++e;
      if (e == pos_) fail(where, endOfData());
      double v;
      const std::string_view tok(d_.data() + pos_, e - pos_);
      if (!parseDouble(tok, v)) fail(where, "malformed number '" + std::string(tok) + "'");
      pos_ = e;
      return v;
    }
    const size_t n = plySize(t);
    if (pos_ + n > d_.size()) fail(where, endOfData());
    unsigned char b[8];
    std::memcpy(b, d_.data() + pos_, n);
    pos_ += n;
    if (f_ == Format::Be) std::reverse(b, b + n);
    switch (t) {
      case PlyType::I8: return double(int8_t(b[0]));
      case PlyType::U8: return double(b[0]);
      case PlyType::I16: {
        int16_t x;
        std::memcpy(&x, b, 2);
        return x;
      }
      case PlyType::U16: {
        uint16_t x;
        std::memcpy(&x, b, 2);
        return x;
      }
      case PlyType::I32: {
        int32_t x;
        std::memcpy(&x, b, 4);
        return x;
      }
      case PlyType::U32: {
        uint32_t x;
        std::memcpy(&x, b, 4);
        return x;
      }
      case PlyType::F32: {
        float x;
        std::memcpy(&x, b, 4);
        return x;
      }
      default: {
        double x;
        std::memcpy(&x, b, 8);
        return x;
      }
    }
  }
  size_t remaining() const { return d_.size() - std::min(pos_, d_.size()); }
  // The element being read, so that running out of data says what the header claimed.
  void reading(const PlyElement& e) {
    claim_ = "header line " + std::to_string(e.headerLine) + " claims " + std::to_string(e.count) +
             " '" + e.name + "' entries";
  }

 private:
  std::string endOfData() const { return "unexpected end of data: the file ends here, but " + claim_; }

  const std::string& d_;
  size_t pos_;
  Format f_;
  std::string claim_ = "the header claims more";
};

// Lying headers: every element instance needs at least this many bytes; refuse counts the file
// cannot hold before allocating anything, naming the element line that claims too much.
void checkPlyCounts(const std::vector<PlyElement>& elements, PlyBody::Format format, size_t bodyBytes) {
  long double minBytes = 0;
  for (const PlyElement& e : elements) {
    size_t per = 0;
    for (const PlyProperty& p : e.props)
      per += format == PlyBody::Format::Ascii ? 2 : (p.isList ? plySize(p.countType) : plySize(p.type));
    minBytes += (long double)e.count * per;
    if (minBytes <= (long double)bodyBytes + 1) continue;
    fail("header line " + std::to_string(e.headerLine),
         "element counts promise more data than the file holds: '" + e.name + "' claims " +
             std::to_string(e.count) + " entries, so the data after end_header needs at least " +
             std::to_string((unsigned long long)std::min(minBytes, 1e19L)) +
             " bytes, but the file holds " + std::to_string(bodyBytes));
  }
}

// A PLY list's length, read as its count type (which may be float): a whole number from 0 to
// `max`. NaN fails too, before the conversion to an integer (fuzz_mesh_ply's float count).
int64_t plyListLength(double n, double max, const std::string& where) {
  if (!(n >= 0 && n <= max) || n != std::floor(n)) fail(where, "bad list length");
  return int64_t(n);
}

// A number read from a PLY body, for a message (it may be NaN or beyond any integer).
std::string plyNumber(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

// The header: the body's format, where it starts, and its elements in order.
struct PlyHeader {
  std::vector<PlyElement> elements;
  PlyBody::Format format = PlyBody::Format::Ascii;
  size_t bodyPos = 0;
};

// A 'property' line: a scalar ("property float x") or a list ("property list uchar int
// vertex_indices").
PlyProperty readPlyProperty(std::istringstream& ls, const std::string& where) {
  PlyProperty p;
  std::string t;
  ls >> t;
  if (t == "list") {
    std::string ct, it;
    ls >> ct >> it >> p.name;
    p.isList = true;
    if (!plyType(ct, p.countType) || !plyType(it, p.type)) fail(where, "unknown list type");
  } else {
    ls >> p.name;
    if (!plyType(t, p.type)) fail(where, "unknown property type '" + t + "'");
  }
  if (p.name.empty()) fail(where, "property without a name");
  return p;
}

// The header up to 'end_header' (at most 1 MB): format, elements and their properties; comment,
// obj_info and ply lines are ignored.
PlyHeader readPlyHeader(const std::string& data) {
  if (data.compare(0, 3, "ply") != 0 || data.size() < 4 || (data[3] != '\n' && data[3] != '\r'))
    fail("header", "not a PLY file (missing 'ply' magic)");
  const size_t endHeader = data.find("end_header");
  if (endHeader > (1 << 20)) fail("header", "no 'end_header' line");  // not found: npos
  PlyHeader h;
  h.bodyPos = data.find('\n', endHeader);
  if (h.bodyPos == std::string::npos) h.bodyPos = data.size();
  else ++h.bodyPos;
  std::istringstream header(data.substr(0, endHeader));
  std::string line;
  bool haveFormat = false;
  int lineNo = 0;
  while (std::getline(header, line)) {
    ++lineNo;
    const std::string where = "header line " + std::to_string(lineNo);
    std::istringstream ls(line);
    std::string kw;
    ls >> kw;
    if (kw == "format") {
      std::string f;
      ls >> f;
      if (f == "ascii") h.format = PlyBody::Format::Ascii;
      else if (f == "binary_little_endian") h.format = PlyBody::Format::Le;
      else if (f == "binary_big_endian") h.format = PlyBody::Format::Be;
      else fail(where, "unknown format '" + f + "'");
      haveFormat = true;
    } else if (kw == "element") {
      PlyElement e;
      std::string count;
      ls >> e.name >> count;
      int64_t c;
      if (e.name.empty() || !parseInt(count, c) || c < 0) fail(where, "malformed element line");
      e.count = uint64_t(c);
      e.headerLine = lineNo;
      h.elements.push_back(e);
    } else if (kw == "property") {
      if (h.elements.empty()) fail(where, "property before any element");
      h.elements.back().props.push_back(readPlyProperty(ls, where));
    }
  }
  if (!haveFormat) fail("header", "no 'format' line");
  return h;
}

// The vertex element: positions (x, y, z), and normals (nx, ny, nz) and texture coordinates
// (u v, s t or texture_u texture_v) when all of theirs are there; other properties are skipped.
void readPlyVertices(TriangleMesh& m, PlyBody& body, const PlyElement& e, const MeshLimits& limits) {
  const std::string ename = "element '" + e.name + "'";
  if (e.count > limits.maxVertices)
    fail(ename, std::to_string(e.count) + " vertices exceed the limit of " +
                    std::to_string(limits.maxVertices));
  int ix = -1, iy = -1, iz = -1, inx = -1, iny = -1, inz = -1, iu = -1, iv = -1;
  for (size_t k = 0; k < e.props.size(); ++k) {
    const std::string& n = e.props[k].name;
    const int ki = e.props[k].isList ? -1 : int(k);
    if (n == "x") ix = ki;
    else if (n == "y") iy = ki;
    else if (n == "z") iz = ki;
    else if (n == "nx") inx = ki;
    else if (n == "ny") iny = ki;
    else if (n == "nz") inz = ki;
    else if (n == "u" || n == "s" || n == "texture_u") iu = ki;
    else if (n == "v" || n == "t" || n == "texture_v") iv = ki;
  }
  if (ix < 0 || iy < 0 || iz < 0) fail(ename, "no x, y, z properties");
  const bool hasN = inx >= 0 && iny >= 0 && inz >= 0, hasUv = iu >= 0 && iv >= 0;
  m.positions.resize(size_t(e.count));
  if (hasN) m.normals.resize(size_t(e.count));
  if (hasUv) m.uvs.resize(size_t(e.count));
  std::vector<double> vals(e.props.size());
  for (uint64_t i = 0; i < e.count; ++i) {
    const std::string where = "vertex " + std::to_string(i);
    for (size_t k = 0; k < e.props.size(); ++k) {
      const PlyProperty& p = e.props[k];
      if (p.isList) {
        const int64_t n = plyListLength(body.read(p.countType, where), 1e6, where);
        for (int64_t q = 0; q < n; ++q) body.read(p.type, where);
      } else {
        vals[k] = body.read(p.type, where);
      }
    }
    const Vec3f pos = Vec3f(float(vals[size_t(ix)]), float(vals[size_t(iy)]), float(vals[size_t(iz)]));
    if (!pos.allFinite()) fail(where, "non-finite coordinate");
    m.positions[i] = pos;
    if (hasN)
      m.normals[i] = Vec3f(float(vals[size_t(inx)]), float(vals[size_t(iny)]), float(vals[size_t(inz)]));
    if (hasUv) m.uvs[i] = Vec2f(float(vals[size_t(iu)]), float(vals[size_t(iv)]));
  }
}

// One list of vertex indices as triangles: a face fanned from its first corner; a triangle
// strip, where -1 restarts the strip and odd triangles flip to keep the winding.
void addPlyIndices(TriangleMesh& m, const std::vector<int64_t>& idx, bool strips,
                   const std::string& where) {
  if (!strips) {
    if (idx.size() < 3) fail(where, "a face needs at least 3 vertices");
    for (size_t k = 1; k + 1 < idx.size(); ++k)
      m.triangles.push_back({uint32_t(idx[0]), uint32_t(idx[k]), uint32_t(idx[k + 1])});
    return;
  }
  size_t start = 0;
  for (size_t k = 0; k <= idx.size(); ++k) {
    if (k < idx.size() && idx[k] >= 0) continue;
    for (size_t q = start; q + 2 < k; ++q) {
      uint32_t a = uint32_t(idx[q]), b = uint32_t(idx[q + 1]), c = uint32_t(idx[q + 2]);
      if (a == b || b == c || a == c) continue;
      if ((q - start) % 2) std::swap(a, b);
      m.triangles.push_back({a, b, c});
    }
    start = k + 1;
  }
}

// A 'face' or 'tristrips' element: its vertex_indices (or vertex_index) lists, each index a
// whole number within the vertices read (-1 too in a strip); other properties are skipped.
void readPlyFaces(TriangleMesh& m, PlyBody& body, const PlyElement& e, const MeshLimits& limits) {
  const bool strips = e.name == "tristrips";
  for (uint64_t i = 0; i < e.count; ++i) {
    const std::string where = (strips ? "tristrip " : "face ") + std::to_string(i);
    for (const PlyProperty& p : e.props) {
      if (!p.isList) {
        body.read(p.type, where);
        continue;
      }
      const int64_t n = plyListLength(body.read(p.countType, where), 1e9, where);
      const bool isIndices = p.name == "vertex_indices" || p.name == "vertex_index";
      if (!isIndices) {
        for (int64_t q = 0; q < n; ++q) body.read(p.type, where);
        continue;
      }
      std::vector<int64_t> idx;
      idx.reserve(size_t(std::min<int64_t>(n, 1'000'000)));
      for (int64_t q = 0; q < n; ++q) {
        const double x = body.read(p.type, where);
        if (x != std::floor(x) || (strips ? x < -1 : x < 0) || x >= double(m.positions.size()))
          fail(where, "vertex index " + plyNumber(x) + " out of range (" +
                          std::to_string(m.positions.size()) + " vertices)");
        idx.push_back(int64_t(x));
      }
      addPlyIndices(m, idx, strips, where);
      if (m.triangles.size() > limits.maxTriangles)
        fail(where, "more than " + std::to_string(limits.maxTriangles) + " triangles");
    }
  }
}

// Any other element: read through, bounds-checked, and dropped.
void skipPlyElement(PlyBody& body, const PlyElement& e) {
  for (uint64_t i = 0; i < e.count; ++i)
    for (const PlyProperty& p : e.props) {
      const std::string where = e.name + " " + std::to_string(i);
      if (!p.isList) {
        body.read(p.type, where);
        continue;
      }
      const int64_t n = plyListLength(body.read(p.countType, where), 1e9, where);
      for (int64_t q = 0; q < n; ++q) body.read(p.type, where);
    }
}

TriangleMesh readPly(const std::string& data, const MeshLimits& limits) {
  const PlyHeader h = readPlyHeader(data);
  PlyBody body(data, h.bodyPos, h.format);
  checkPlyCounts(h.elements, h.format, body.remaining());

  TriangleMesh m;
  bool haveVertices = false;
  for (const PlyElement& e : h.elements) {
    body.reading(e);
    // An element without properties holds no bytes, whatever its count: nothing to read (a count
    // of 6e18 looped for ever, fuzz_mesh_ply's timeout). A vertex element still fails below.
    if (e.props.empty() && e.name != "vertex") continue;
    if (e.name == "vertex") {
      readPlyVertices(m, body, e, limits);
      haveVertices = true;
    } else if (e.name == "face" || e.name == "tristrips") {
      if (!haveVertices) fail("element '" + e.name + "'", "appears before the vertex element");
      readPlyFaces(m, body, e, limits);
    } else {
      skipPlyElement(body, e);
    }
  }
  if (!haveVertices) fail("header", "no vertex element");
  return m;
}

// ---------------------------------------------------------------------------------------------
// glTF / GLB

size_t base64DecodedSize(const std::string& uri) {
  const size_t comma = uri.find(',');
  if (comma == std::string::npos) return 0;
  size_t n = uri.size() - comma - 1;
  size_t pad = 0;
  while (n > 0 && pad < 2 && uri[comma + n] == '=') {
    --n;
    ++pad;
  }
  return (uri.size() - comma - 1) / 4 * 3 - pad;
}

// A non-negative integer (glTF indices, counts, offsets, lengths).
bool asIndex(const nlohmann::json& j, size_t& out) {
  if (j.is_number_unsigned()) {
    out = j.get<size_t>();
    return true;
  }
  if (j.is_number_integer() && j.get<long long>() >= 0) {
    out = size_t(j.get<long long>());
    return true;
  }
  return false;
}
size_t indexOr(const nlohmann::json& obj, const char* key, size_t fallback, bool& ok) {
  if (!obj.contains(key)) return fallback;
  size_t v = 0;
  ok = asIndex(obj[key], v) && ok;
  return v;
}

size_t componentSize(int componentType) {
  switch (componentType) {
    case 5120:
    case 5121: return 1;
    case 5122:
    case 5123: return 2;
    case 5125:
    case 5126: return 4;
    default: return 0;
  }
}
size_t componentCount(const std::string& type) {
  static const std::map<std::string, size_t> n = {{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4},
                                                  {"MAT2", 4},   {"MAT3", 9}, {"MAT4", 16}};
  auto it = n.find(type);
  return it == n.end() ? 0 : it->second;
}

// The glTF JSON (from .gltf text or the GLB JSON chunk) with buffers, views and accessors
// checked to lie inside the data they point to.
nlohmann::json checkGltf(const std::string& path, const std::string& data, bool glb) {
  using nlohmann::json;
  std::string jsonText;
  size_t binLength = 0;
  bool haveBin = false;
  if (glb) {
    auto u32 = [&](size_t at) {
      uint32_t x;
      std::memcpy(&x, data.data() + at, 4);
      return x;
    };
    if (data.size() < 20 || data.compare(0, 4, "glTF") != 0) fail("header", "not a GLB file");
    if (u32(8) > data.size()) fail("header", "declared length exceeds the file size");
    const uint32_t jsonLen = u32(12);
    if (u32(16) != 0x4E4F534Au || 20ull + jsonLen > data.size())
      fail("JSON chunk", "missing or truncated");
    jsonText = data.substr(20, jsonLen);
    const size_t binAt = 20 + size_t(jsonLen);
    if (binAt + 8 <= data.size() && u32(binAt + 4) == 0x004E4942u) {
      binLength = u32(binAt);
      if (binAt + 8 + binLength > data.size()) fail("BIN chunk", "truncated");
      haveBin = true;
    }
  } else {
    jsonText = data;
  }
  json j = json::parse(jsonText, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded() || !j.is_object()) fail("JSON", "invalid glTF JSON");

  std::vector<size_t> bufferSize;
  const json none;
  const json& buffers = j.contains("buffers") ? j["buffers"] : none;
  for (size_t i = 0; buffers.is_array() && i < buffers.size(); ++i) {
    const json& b = buffers[i];
    const std::string where = "buffers[" + std::to_string(i) + "]";
    bool ok = b.is_object() && b.contains("byteLength");
    const size_t declared = ok ? indexOr(b, "byteLength", 0, ok) : 0;
    if (!ok) fail(where, "missing or bad byteLength");
    size_t actual = 0;
    if (b.contains("uri") && b["uri"].is_string()) {
      const std::string uri = b["uri"].get<std::string>();
      if (uri.rfind("data:", 0) == 0) {
        actual = base64DecodedSize(uri);
      } else {
        std::error_code ec;
        const fs::path f = fs::path(path).parent_path() / uri;
        if (!fs::is_regular_file(f, ec)) fail(where, "buffer file not found: " + f.string());
        actual = size_t(fs::file_size(f, ec));
      }
    } else if (glb && i == 0 && haveBin) {
      actual = binLength;
    } else {
      fail(where, "no data (no uri and no GLB BIN chunk)");
    }
    if (declared > actual)
      fail(where, "byteLength " + std::to_string(declared) + " exceeds the " + std::to_string(actual) +
                      " bytes available");
    bufferSize.push_back(declared);
  }
  std::vector<size_t> viewSize, viewStride;
  const json& views = j.contains("bufferViews") ? j["bufferViews"] : none;
  for (size_t i = 0; views.is_array() && i < views.size(); ++i) {
    const json& v = views[i];
    const std::string where = "bufferViews[" + std::to_string(i) + "]";
    bool ok = v.is_object() && v.contains("buffer") && v.contains("byteLength");
    const size_t b = ok ? indexOr(v, "buffer", 0, ok) : 0;
    const size_t length = ok ? indexOr(v, "byteLength", 0, ok) : 0;
    const size_t offset = ok ? indexOr(v, "byteOffset", 0, ok) : 0;
    const size_t stride = ok ? indexOr(v, "byteStride", 0, ok) : 0;
    if (!ok) fail(where, "missing or bad buffer, byteLength, byteOffset or byteStride");
    if (b >= bufferSize.size()) fail(where, "buffer index out of range");
    if (offset > bufferSize[b] || length > bufferSize[b] - offset)
      fail(where, "points past the end of buffer " + std::to_string(b));
    viewSize.push_back(length);
    viewStride.push_back(stride);
  }
  const json& accessors = j.contains("accessors") ? j["accessors"] : none;
  for (size_t i = 0; accessors.is_array() && i < accessors.size(); ++i) {
    const json& a = accessors[i];
    const std::string where = "accessors[" + std::to_string(i) + "]";
    if (!a.is_object()) fail(where, "not an object");
    if (!a.contains("bufferView")) continue;  // all zeros (or sparse): nothing to read here
    bool ok = true;
    const size_t view = indexOr(a, "bufferView", 0, ok);
    const size_t count = indexOr(a, "count", 0, ok);
    const size_t offset = indexOr(a, "byteOffset", 0, ok);
    if (!ok || !a.contains("count")) fail(where, "missing or bad bufferView, count or byteOffset");
    if (view >= viewSize.size()) fail(where, "bufferView index out of range");
    const json ct = a.value("componentType", json());
    const json ty = a.value("type", json());
    const size_t elem = componentSize(ct.is_number_integer() ? ct.get<int>() : 0) *
                        componentCount(ty.is_string() ? ty.get<std::string>() : std::string());
    if (elem == 0) fail(where, "unknown componentType or type");
    const size_t stride = std::max(elem, viewStride[view]);
    if (count > (size_t(1) << 40) / stride) fail(where, "count too large");
    const size_t need = count == 0 ? 0 : offset + stride * (count - 1) + elem;
    if (need > viewSize[view]) fail(where, "reads past the end of bufferView " + std::to_string(view));
  }
  return j;
}

// The triangles of an imported scene (its node transforms applied by PreTransformVertices)
// with per-triangle materials.
TriangleMesh meshFromAssimp(const aiScene& sceneRef, const MeshLimits& limits,
                            const nlohmann::json* gltfMaterials) {
  const aiScene* scene = &sceneRef;
  TriangleMesh m;
  // Materials: Assimp's in the file's order (plus its default at the end); for glTF the
  // extensions Assimp 5.2 ignores come from the JSON.
  for (unsigned i = 0; i < scene->mNumMaterials; ++i) {
    const aiMaterial* am = scene->mMaterials[i];
    AssetMaterial mat;
    aiString name;
    if (am->Get(AI_MATKEY_NAME, name) == AI_SUCCESS) mat.name = name.C_Str();
    aiColor4D c;
    if (am->Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS ||
        am->Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS)
      mat.baseColor = Vec3(c.r, c.g, c.b);
    float x;
    if (am->Get(AI_MATKEY_METALLIC_FACTOR, x) == AI_SUCCESS) mat.metallic = x;
    if (am->Get(AI_MATKEY_ROUGHNESS_FACTOR, x) == AI_SUCCESS) mat.roughness = x;
    if (am->Get(AI_MATKEY_TRANSMISSION_FACTOR, x) == AI_SUCCESS) mat.transmission = x;
    aiColor3D e;
    if (am->Get(AI_MATKEY_COLOR_EMISSIVE, e) == AI_SUCCESS) mat.emission = Vec3(e.r, e.g, e.b);
    double strength = 1.0;
    if (am->Get(AI_MATKEY_EMISSIVE_INTENSITY, x) == AI_SUCCESS) strength = x;
    if (gltfMaterials && i < gltfMaterials->size()) {
      const nlohmann::json& gm = (*gltfMaterials)[i];
      const nlohmann::json ext = gm.is_object() ? gm.value("extensions", nlohmann::json::object())
                                                : nlohmann::json::object();
      if (ext.contains("KHR_materials_emissive_strength") &&
          ext["KHR_materials_emissive_strength"].value("emissiveStrength", nlohmann::json()).is_number())
        strength = ext["KHR_materials_emissive_strength"]["emissiveStrength"].get<double>();
      if (ext.contains("KHR_materials_ior") &&
          ext["KHR_materials_ior"].value("ior", nlohmann::json()).is_number())
        mat.ior = ext["KHR_materials_ior"]["ior"].get<double>();
      if (ext.contains("KHR_materials_transmission") &&
          ext["KHR_materials_transmission"].value("transmissionFactor", nlohmann::json()).is_number())
        mat.transmission = ext["KHR_materials_transmission"]["transmissionFactor"].get<double>();
    }
    mat.emission *= strength;
    sanitize(mat);
    m.materials.push_back(mat);
  }

  bool allNormals = true, allUvs = true;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    allNormals = allNormals && scene->mMeshes[i]->HasNormals();
    allUvs = allUvs && scene->mMeshes[i]->HasTextureCoords(0);
  }
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    const aiMesh* am = scene->mMeshes[i];
    const std::string where = "mesh " + std::to_string(i);
    if (m.positions.size() + am->mNumVertices > limits.maxVertices)
      fail(where, "more than " + std::to_string(limits.maxVertices) + " vertices");
    const uint32_t base = uint32_t(m.positions.size());
    for (unsigned v = 0; v < am->mNumVertices; ++v) {
      const aiVector3D& p = am->mVertices[v];
      m.positions.emplace_back(p.x, p.y, p.z);
      if (allNormals) {
        const aiVector3D& n = am->mNormals[v];
        m.normals.emplace_back(n.x, n.y, n.z);
      }
      if (allUvs) m.uvs.emplace_back(am->mTextureCoords[0][v].x, am->mTextureCoords[0][v].y);
    }
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
      const aiFace& face = am->mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines were sorted out
      for (unsigned k = 0; k < 3; ++k)
        if (face.mIndices[k] >= am->mNumVertices)
          fail(where, "face " + std::to_string(f) + " index out of range");
      m.triangles.push_back({base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
      m.triangleMaterial.push_back(am->mMaterialIndex < m.materials.size() ? am->mMaterialIndex : 0);
    }
    if (m.triangles.size() > limits.maxTriangles)
      fail(where, "more than " + std::to_string(limits.maxTriangles) + " triangles");
  }
  if (m.materials.empty()) {
    m.materials.push_back(AssetMaterial{"default"});
    std::fill(m.triangleMaterial.begin(), m.triangleMaterial.end(), 0u);
  }
  return m;
}

// Sets `importer` to drop points and lines; returns the post-processing every Assimp read here
// uses (triangles, welded vertices, normals, one flat mesh list, validated).
unsigned prepareAssimpImporter(Assimp::Importer& importer) {
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  return aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_GenNormals |
         aiProcess_PreTransformVertices | aiProcess_SortByPType | aiProcess_ValidateDataStructure;
}

TriangleMesh readGltf(const std::string& path, const MeshLimits& limits) {
  const std::string data = readWholeFile(path);
  const bool glb = data.size() >= 4 && data.compare(0, 4, "glTF") == 0;
  const nlohmann::json gltf = checkGltf(path, data, glb);

  Assimp::Importer importer;
  const unsigned flags = prepareAssimpImporter(importer);
  const aiScene* scene = nullptr;
  try {
    scene = importer.ReadFileFromMemory(data.data(), data.size(), flags, glb ? "glb" : "gltf");
    if (!glb && !scene) scene = importer.ReadFile(path, flags);  // external buffers by path
  } catch (const std::exception& e) {
    fail("", std::string("import failed: ") + e.what());
  }
  if (!scene) fail("", std::string("import failed: ") + importer.GetErrorString());
  if (!scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) fail("", "incomplete scene");

  const nlohmann::json* gltfMaterials =
      gltf.contains("materials") && gltf["materials"].is_array() ? &gltf["materials"] : nullptr;
  return meshFromAssimp(*scene, limits, gltfMaterials);
}

// A number from the scene's metadata (Assimp stores FBX settings as int, float or double).
std::optional<double> metadataNumber(const aiScene& scene, const char* key) {
  if (!scene.mMetaData) return std::nullopt;
  int32_t i;
  float f;
  double d;
  if (scene.mMetaData->Get(key, d)) return d;
  if (scene.mMetaData->Get(key, f)) return double(f);
  if (scene.mMetaData->Get(key, i)) return double(i);
  return std::nullopt;
}

// FBX, COLLADA and 3DS through Assimp. COLLADA's <unit> and up_axis are applied by Assimp; FBX
// says its unit (UnitScaleFactor, centimetres per unit) and up axis in its global settings; 3DS
// is z-up with no unit.
TriangleMesh readWithAssimp(const std::string& path, const std::string& ext, const MeshLimits& limits,
                            MeshFileInfo& info) {
  Assimp::Importer importer;
  const unsigned flags = prepareAssimpImporter(importer);
  const aiScene* scene = nullptr;
  try {
    scene = importer.ReadFile(path, flags);
  } catch (const std::exception& e) {
    fail("", std::string("import failed: ") + e.what());
  }
  if (!scene) fail("", std::string("import failed: ") + importer.GetErrorString());
  if (!scene->mRootNode || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || scene->mNumMeshes == 0)
    fail("", "no meshes in the file");
  TriangleMesh m = meshFromAssimp(*scene, limits, nullptr);
  // z-up: a quarter turn about x brings +z (or -z) to +y.
  auto turnZUp = [&m](double sign) {
    auto turn = [sign](Vec3f& v) { v = Vec3f(v.x(), float(sign) * v.z(), -float(sign) * v.y()); };
    for (Vec3f& p : m.positions) turn(p);
    for (Vec3f& n : m.normals) turn(n);
  };
  if (ext == ".dae") info.metresPerUnit = 1.0;
  // 3DS is z-up (3ds Max's axes), and Assimp 5.2 leaves it so: its own 3DS export of a y-up box
  // reads back lying on its side.
  if (ext == ".3ds") turnZUp(1.0);
  if (ext == ".fbx") {
    const std::optional<double> cmPerUnit = metadataNumber(*scene, "UnitScaleFactor");
    if (cmPerUnit && std::isfinite(*cmPerUnit) && *cmPerUnit > 0)
      info.metresPerUnit = *cmPerUnit / 100.0;
    const std::optional<double> up = metadataNumber(*scene, "UpAxis");
    if (up && *up == 2.0) turnZUp(metadataNumber(*scene, "UpAxisSign").value_or(1.0) < 0 ? -1.0 : 1.0);
  }
  return m;
}

// Common checks for every importer.
void validate(TriangleMesh& m, const MeshLimits& limits) {
  if (m.triangles.empty()) fail("", "no triangles");
  if (m.triangles.size() > limits.maxTriangles)
    fail("", std::to_string(m.triangles.size()) + " triangles exceed the limit of " +
                 std::to_string(limits.maxTriangles));
  if (m.positions.size() > limits.maxVertices)
    fail("", std::to_string(m.positions.size()) + " vertices exceed the limit of " +
                 std::to_string(limits.maxVertices));
  for (size_t i = 0; i < m.positions.size(); ++i)
    if (!m.positions[i].allFinite()) fail("vertex " + std::to_string(i), "non-finite coordinate");
  bool anyArea = false;
  for (size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& tri = m.triangles[t];
    for (uint32_t v : tri)
      if (v >= m.positions.size())
        fail("triangle " + std::to_string(t), "vertex index " + std::to_string(v) + " out of range");
    if (!anyArea) {
      const Vec3f a = m.positions[tri[0]], b = m.positions[tri[1]], c = m.positions[tri[2]];
      anyArea = (b - a).cross(c - a).squaredNorm() > 0.f;
    }
  }
  if (!anyArea) fail("", "every triangle has zero area");
  if (!m.normals.empty()) {
    bool ok = m.normals.size() == m.positions.size();
    for (Vec3f& n : m.normals) {
      const float len = n.norm();
      if (!std::isfinite(len) || len == 0.f) ok = false;
      else n /= len;
    }
    if (!ok) m.computeVertexNormals();  // the file's normals are unusable: recompute
  }
  if (!m.uvs.empty() && m.uvs.size() != m.positions.size()) m.uvs.clear();
  for (Vec2f& uv : m.uvs)
    if (!uv.allFinite()) uv = Vec2f(0, 0);
}

}  // namespace

const std::vector<std::string>& meshFileExtensions() {
  static const std::vector<std::string> exts = {".obj", ".ply", ".gltf", ".glb", ".fbx", ".dae", ".3ds"};
  return exts;
}

Expected<TriangleMesh> loadMesh(const std::string& pathOrBuiltin, const MeshLimits& limits,
                                MeshFileInfo* infoOut) {
  const std::string& path = pathOrBuiltin;
  MeshFileInfo scratch;
  MeshFileInfo& info = infoOut ? *infoOut : scratch;
  info = {};
  if (path.rfind("builtin:", 0) == 0) info.format = "builtin";
  if (path == "builtin:sphere") return makeSphere();
  if (path == "builtin:cube") return makeCube();
  if (path.rfind("builtin:", 0) == 0)
    return Error{path, "", "unknown builtin mesh (expected builtin:sphere or builtin:cube)"};
  std::error_code ec;
  if (!fs::exists(path, ec)) return Error{path, "", "file not found"};
  if (!fs::is_regular_file(path, ec)) return Error{path, "", "not a regular file"};
  const auto size = fs::file_size(path, ec);
  if (ec) return Error{path, "", "cannot read: " + ec.message()};
  if (size == 0) return Error{path, "", "empty file"};
  if ((long long)size > limits.maxFileBytes)
    return Error{path, "",
                 "file of " + std::to_string(size) + " bytes exceeds the limit of " +
                     std::to_string(limits.maxFileBytes) + " bytes"};
  const std::string ext = lowerExtension(path);
  try {
    TriangleMesh m;
    if (ext == ".obj") m = readObj(readWholeFile(path), path, limits);
    else if (ext == ".ply") m = readPly(readWholeFile(path), limits);
    else if (ext == ".gltf" || ext == ".glb") m = readGltf(path, limits);
    else if (ext == ".fbx" || ext == ".dae" || ext == ".3ds")
      m = readWithAssimp(path, ext, limits, info);
    else
      return Error{path, "",
                   "unsupported mesh format '" + ext +
                       "' (expected .obj, .ply, .gltf, .glb, .fbx, .dae or .3ds)"};
    if (ext == ".gltf" || ext == ".glb") info.metresPerUnit = 1.0;  // the glTF spec's unit
    info.format = ext == ".glb" ? "gltf" : ext.substr(1);
    validate(m, limits);
    return m;
  } catch (const MeshError& e) {
    return Error{path, e.element, e.reason};
  } catch (const std::bad_alloc&) {
    return Error{path, "", "not enough memory"};
  } catch (const std::exception& e) {
    return Error{path, "", std::string("cannot read: ") + e.what()};
  }
}

}  // namespace inlay
