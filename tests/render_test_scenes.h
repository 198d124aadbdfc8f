// Hand-built scenes for the render tests: box rooms of quads, rectangle lights, spheres, and a
// camera filled in field by field (no modeling solvers involved).
#pragma once

#include "inlay/render/path_tracer.h"
#include "inlay/render/scene.h"

#include <cmath>
#include <cstring>
#include <memory>

namespace inlay::test {

constexpr double kPi = 3.14159265358979323846;

// Corners C-U-V, C+U-V, C+U+V, C-U+V: a light made from them emits along U x V.
inline std::array<Vec3, 4> rectCorners(const Vec3& c, const Vec3& u, const Vec3& v) {
  return {c - u - v, c + u - v, c + u + v, c - u + v};
}

inline TriangleMesh quadMesh(const std::array<Vec3, 4>& c) {
  TriangleMesh m;
  for (const auto& p : c) m.positions.push_back(p.cast<float>());
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

inline AreaLight rectLight(const Vec3& c, const Vec3& u, const Vec3& v, const Vec3& radiance) {
  AreaLight l;
  l.cornersWorld = rectCorners(c, u, v);
  l.radiance = radiance;
  return l;
}

// The six inward-facing faces of a box as (centre, U, V) with U x V pointing into the box.
struct Face {
  Vec3 c, u, v;
};
inline std::array<Face, 6> boxFaces(const RoomBox& b) {
  const double cx = 0.5 * (b.xLeftM + b.xRightM), cy = 0.5 * b.ceilingM,
               cz = 0.5 * (b.zBackM + b.zRearM);
  const double hx = 0.5 * (b.xRightM - b.xLeftM), hy = 0.5 * b.ceilingM,
               hz = 0.5 * (b.zRearM - b.zBackM);
  return {{
      {Vec3(cx, 0, cz), Vec3(0, 0, hz), Vec3(hx, 0, 0)},           // floor, +y
      {Vec3(cx, b.ceilingM, cz), Vec3(hx, 0, 0), Vec3(0, 0, hz)},  // ceiling, -y
      {Vec3(b.xLeftM, cy, cz), Vec3(0, hy, 0), Vec3(0, 0, hz)},    // left, +x
      {Vec3(b.xRightM, cy, cz), Vec3(0, 0, hz), Vec3(0, hy, 0)},   // right, -x
      {Vec3(cx, cy, b.zBackM), Vec3(hx, 0, 0), Vec3(0, hy, 0)},    // back, +z
      {Vec3(cx, cy, b.zRearM), Vec3(0, hy, 0), Vec3(hx, 0, 0)},    // rear, -z
  }};
}

inline SceneGeometry boxRoom(const RoomBox& b = {}) {
  SceneGeometry g;
  g.box = b;
  const SurfaceKind kinds[6] = {SurfaceKind::Floor,     SurfaceKind::Ceiling,  SurfaceKind::WallLeft,
                                SurfaceKind::WallRight, SurfaceKind::WallBack, SurfaceKind::WallRear};
  const auto faces = boxFaces(b);
  for (int i = 0; i < 6; ++i) {
    Surface s;
    s.kind = kinds[i];
    s.name = surfaceKindName(kinds[i]);
    s.meshWorld = quadMesh(rectCorners(faces[i].c, faces[i].u, faces[i].v));
    s.supportsObjects = i == 0;
    g.surfaces.push_back(std::move(s));
  }
  return g;
}

// A pinhole camera at (0, heightM, 0) looking along -z, pitched by pitchDeg (negative: down).
inline Camera testCamera(int w, int h, double hfovDeg, double heightM = 1.3, double pitchDeg = 0) {
  Camera c;
  c.widthPx = w;
  c.heightPx = h;
  c.focalPx = 0.5 * w / std::tan(0.5 * hfovDeg * kPi / 180.0);
  c.principalPx = Vec2(0.5 * w, 0.5 * h);
  c.worldFromCamera = Eigen::AngleAxisd(pitchDeg * kPi / 180.0, Vec3::UnitX()).toRotationMatrix();
  c.heightM = heightM;
  return c;
}

// Room with uniform albedo per surface (no albedo image: every lookup takes the surface mean).
inline RenderScene roomScene(const Camera& cam, const RoomBox& box, double albedo) {
  RenderScene s;
  s.camera = cam;
  s.room = boxRoom(box);
  s.roomAlbedo.camera = cam;
  s.roomAlbedo.surfaceMean.assign(s.room.surfaces.size(), Vec3::Constant(albedo));
  return s;
}

// An empty box room lit by `count` small square lights in a grid under the ceiling: light 0
// shines with `brightLe`, the others with `dimLe` (grey). The camera looks down at the floor.
inline RenderScene manyLightsScene(int w, int h, int count, double brightLe, double dimLe) {
  const RoomBox box;
  RenderScene s = roomScene(testCamera(w, h, 70, 1.3, -30), box, 0.5);
  const int cols = int(std::ceil(std::sqrt(double(count))));
  const int rows = (count + cols - 1) / cols;
  const double half = 0.12, y = box.ceilingM - 0.01;
  for (int k = 0; k < count; ++k) {
    const int column = k % cols, row = k / cols;
    const double fx = (column + 0.5) / cols, fz = (row + 0.5) / rows;
    const Vec3 c(box.xLeftM + 0.2 + fx * (box.xRightM - box.xLeftM - 0.4), y,
                 box.zBackM + 0.2 + fz * (box.zRearM - box.zBackM - 0.4));
    // U x V = x x z = -y: the light shines down.
    s.lights.push_back(
        rectLight(c, Vec3(half, 0, 0), Vec3(0, 0, half), Vec3::Constant(k == 0 ? brightLe : dimLe)));
  }
  return s;
}

// UV sphere of radius r around the origin with outward vertex normals.
inline std::shared_ptr<TriangleMesh> sphereMesh(double r, int rings = 24, int segments = 48) {
  auto m = std::make_shared<TriangleMesh>();
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j <= segments; ++j) {
      const double th = kPi * i / rings, ph = 2 * kPi * j / segments;
      const Vec3 n(std::sin(th) * std::cos(ph), std::cos(th), std::sin(th) * std::sin(ph));
      m->positions.push_back((r * n).cast<float>());
      m->normals.push_back(n.cast<float>());
    }
  auto id = [&](int i, int j) { return uint32_t(i * (segments + 1) + j); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      // Counter-clockwise seen from outside: (b - a) x (c - a) points outward.
      m->triangles.push_back({id(i, j), id(i, j + 1), id(i + 1, j)});
      m->triangles.push_back({id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)});
    }
  return m;
}

// A closed box of the given extent (x, y, z ranges as a RoomBox: ceilingM is its top, its
// bottom at y = 0), faces wound outward, no vertex normals.
inline std::shared_ptr<TriangleMesh> boxMesh(const RoomBox& extent) {
  auto box = std::make_shared<TriangleMesh>();
  for (const auto& f : boxFaces(extent)) {
    TriangleMesh q = quadMesh(rectCorners(f.c, f.u, f.v));
    std::swap(q.triangles[0][1], q.triangles[0][2]);  // box faces wind inward: turn them outward
    std::swap(q.triangles[1][1], q.triangles[1][2]);
    box->append(q);
  }
  return box;
}

inline Mat4 translation(const Vec3& t) {
  Mat4 m = Mat4::Identity();
  m.topRightCorner<3, 1>() = t;
  return m;
}

// An inserted object of `mesh` moved to `at`, of material `kind` (the material's other defaults).
inline InsertedObject placedObject(std::shared_ptr<TriangleMesh> mesh, const Vec3& at,
                                   Material::Kind kind) {
  InsertedObject o;
  o.meshObject = std::move(mesh);
  o.worldFromObject = translation(at);
  o.material.kind = kind;
  return o;
}

// Bit-for-bit equality of two images (the differential render's zero-difference tests).
inline bool sameBits(const ImageF& a, const ImageF& b) {
  return a.data.size() == b.data.size() &&
         std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}

inline bool allFinite(const ImageF& im) {
  for (float v : im.data)
    if (!std::isfinite(v)) return false;
  return true;
}

// Relative error of rendered pixels against an analytic value: its mean (the bias) and its RMS.
struct RelativeError {
  double sum = 0, sum2 = 0;
  int n = 0;
  void add(double got, double expected) {
    const double rel = got / expected - 1;
    sum += rel, sum2 += rel * rel, ++n;
  }
  double mean() const { return sum / n; }
  double rms() const { return std::sqrt(sum2 / n); }
};

}  // namespace inlay::test
