// Closed procedural shapes (see shapes.h).
#include "shapes.h"

#include <algorithm>
#include <cmath>

namespace inlay::library {

namespace {

constexpr float kPi = 3.14159265358979f;

uint32_t addVertex(TriangleMesh& m, const Vec3f& p, const Vec3f& n, const Vec2f& uv) {
  m.positions.push_back(p);
  m.normals.push_back(n.normalized());
  m.uvs.push_back(uv);
  return uint32_t(m.positions.size() - 1);
}

// Adds triangle (a, b, c) unless it has no area (a collapsed ring meeting an apex).
void addTriangle(TriangleMesh& m, uint32_t a, uint32_t b, uint32_t c) {
  const Vec3f& pa = m.positions[a];
  if ((m.positions[b] - pa).cross(m.positions[c] - pa).squaredNorm() <= 1e-18f) return;
  m.triangles.push_back({a, b, c});
}

// Winds every triangle so that its geometric normal agrees with its vertex normals: the
// builders below state the outward normal analytically, which fixes the winding.
void orientToNormals(TriangleMesh& m) {
  for (auto& t : m.triangles) {
    const Vec3f g = (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]);
    const Vec3f n = m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]];
    if (g.dot(n) < 0) std::swap(t[1], t[2]);
  }
}

// Grid coordinates along one axis of a rounded box: the flat middle's two ends plus `segments`
// steps into each rounded end, spaced by equal angles (tan, since the grid point is projected
// onto the rounding's circle from the inner box).
std::vector<float> roundedAxis(float half, float radius, int segments) {
  if (radius <= 0.f) return {-half, half};
  const float inner = half - radius;
  std::vector<float> c;
  for (int k = segments; k >= 1; --k)
    c.push_back(-(inner + radius * std::tan(0.25f * kPi * float(k) / float(segments))));
  if (inner > 1e-6f) c.push_back(-inner);
  c.push_back(inner > 1e-6f ? inner : 0.f);
  for (int k = 1; k <= segments; ++k)
    c.push_back(inner + radius * std::tan(0.25f * kPi * float(k) / float(segments)));
  c.front() = -half, c.back() = half;  // exactly, so the edges of neighbouring faces weld
  return c;
}

// One face of a rounded box: the grid on the cube face whose outward axis is `axis` (sign
// `sign`), each point pushed onto the rounded surface around the inner box.
void roundedBoxFace(TriangleMesh& m, const Vec3f& half, float radius, int segments, int axis,
                    float sign) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const std::vector<float> cu = roundedAxis(half[u], radius, segments);
  const std::vector<float> cv = roundedAxis(half[v], radius, segments);
  const Vec3f inner = (half - Vec3f::Constant(radius)).cwiseMax(0.f);
  const uint32_t base = uint32_t(m.positions.size());
  for (float b : cv)
    for (float a : cu) {
      Vec3f p;
      p[axis] = sign * half[axis], p[u] = a, p[v] = b;
      Vec3f n = Vec3f::Zero();
      n[axis] = sign;
      if (radius > 0.f) {
        const Vec3f core = p.cwiseMax(-inner).cwiseMin(inner);
        n = (p - core).normalized();
        p = core + radius * n;
      }
      addVertex(m, p, n, Vec2f(p[u], p[v]));
    }
  const uint32_t nu = uint32_t(cu.size());
  for (uint32_t j = 0; j + 1 < cv.size(); ++j)
    for (uint32_t i = 0; i + 1 < nu; ++i) {
      const uint32_t a = base + j * nu + i, b = a + 1, c = a + nu + 1, d = a + nu;
      addTriangle(m, a, b, c);
      addTriangle(m, a, c, d);
    }
}

// The outward normal (r, y) of profile edge e.
Eigen::Vector2f edgeNormal(const std::vector<Eigen::Vector2f>& profile, size_t e) {
  const Eigen::Vector2f d = profile[e + 1] - profile[e];
  return Eigen::Vector2f(d.y(), -d.x()).normalized();
}
// The normal (r, y) at `point` (an end of `edge`): smooth with the neighbouring edge, or the
// edge's own at a crease.
Eigen::Vector2f profileNormal(const std::vector<Eigen::Vector2f>& profile, size_t edge, size_t point,
                              float creaseCos) {
  Eigen::Vector2f own = edgeNormal(profile, edge);           // not const: returned by move
  const size_t other = point == edge ? edge - 1 : edge + 1;  // the neighbouring edge at `point`
  if ((point == edge && edge == 0) || (point != edge && edge + 2 >= profile.size())) return own;
  if ((profile[other + 1] - profile[other]).squaredNorm() <= 0.f) return own;
  const Eigen::Vector2f n2 = edgeNormal(profile, other);
  return own.dot(n2) >= creaseCos ? Eigen::Vector2f((own + n2).normalized()) : own;
}

}  // namespace

TriangleMesh roundedBox(const Vec3f& size, float radiusM, int segments) {
  const Vec3f half = 0.5f * size.cwiseAbs();
  const float radius = std::clamp(radiusM, 0.f, half.minCoeff());
  TriangleMesh m;
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {-1.f, 1.f}) roundedBoxFace(m, half, radius, std::max(1, segments), axis, sign);
  orientToNormals(m);
  return m;
}

TriangleMesh lathe(const std::vector<Eigen::Vector2f>& profile, int sides, float creaseDeg) {
  TriangleMesh m;
  const float creaseCos = std::cos(creaseDeg * kPi / 180.f);
  float rMax = 0.f;
  for (const auto& p : profile) rMax = std::max(rMax, p.x());
  float along = 0.f;  // arc length up the profile: the v texture coordinate
  for (size_t e = 0; e + 1 < profile.size(); ++e) {
    const Eigen::Vector2f &p0 = profile[e], &p1 = profile[e + 1];
    const float length = (p1 - p0).norm();
    if (length <= 0.f || (p0.x() <= 0.f && p1.x() <= 0.f)) continue;
    // One ring per end of this edge (its own normals: creases stay sharp, smooth ones agree).
    uint32_t ring[2];
    const Eigen::Vector2f pts[2] = {p0, p1};
    for (int end = 0; end < 2; ++end) {
      const Eigen::Vector2f n = profileNormal(profile, e, e + size_t(end), creaseCos);
      const float v = along + (end ? length : 0.f);
      ring[end] = uint32_t(m.positions.size());
      if (pts[end].x() <= 0.f) {  // on the axis: one apex
        addVertex(m, Vec3f(0, pts[end].y(), 0), Vec3f(0, n.y() >= 0 ? 1.f : -1.f, 0), Vec2f(0, v));
        continue;
      }
      for (int k = 0; k <= sides; ++k) {
        const float phi = 2.f * kPi * float(k) / float(sides);
        const float geometric = 2.f * kPi * float(k % sides) / float(sides);  // the seam welds exactly
        const float c = std::cos(geometric), s = std::sin(geometric);
        addVertex(m, Vec3f(pts[end].x() * c, pts[end].y(), pts[end].x() * s),
                  Vec3f(n.x() * c, n.y(), n.x() * s), Vec2f(rMax * phi, v));
      }
    }
    for (uint32_t k = 0; k < uint32_t(sides); ++k) {
      const bool apex0 = p0.x() <= 0.f, apex1 = p1.x() <= 0.f;
      const uint32_t a0 = apex0 ? ring[0] : ring[0] + k, a1 = apex0 ? ring[0] : ring[0] + k + 1;
      const uint32_t b0 = apex1 ? ring[1] : ring[1] + k, b1 = apex1 ? ring[1] : ring[1] + k + 1;
      if (apex0) {
        addTriangle(m, a0, b1, b0);  // a fan from the bottom apex
      } else if (apex1) {
        addTriangle(m, a0, a1, b1);  // a fan to the top apex
      } else {
        addTriangle(m, a0, a1, b1);
        addTriangle(m, a0, b1, b0);
      }
    }
    along += length;
  }
  orientToNormals(m);
  return m;
}

TriangleMesh rod(const Vec3f& a, const Vec3f& b, float ra, float rb, int sides) {
  const float length = (b - a).norm();
  TriangleMesh m = lathe({{0, 0}, {ra, 0}, {rb, length}, {0, length}}, sides);
  Affine t = Affine::Identity();
  t.translate(a);
  t.rotate(Eigen::Quaternionf::FromTwoVectors(Vec3f::UnitY(), (b - a).normalized()));
  return transformed(m, t);
}

TriangleMesh torus(float majorM, float minorM, int ringSides, int tubeSides) {
  TriangleMesh m;
  for (int i = 0; i <= ringSides; ++i) {
    const float phi = 2.f * kPi * float(i) / float(ringSides);
    const float phiSeam = 2.f * kPi * float(i % ringSides) / float(ringSides);  // the seam welds exactly
    const Vec3f radial(std::cos(phiSeam), 0, std::sin(phiSeam));
    for (int j = 0; j <= tubeSides; ++j) {
      const float theta = 2.f * kPi * float(j) / float(tubeSides);
      const float thetaSeam = 2.f * kPi * float(j % tubeSides) / float(tubeSides);
      const Vec3f n = std::cos(thetaSeam) * radial + std::sin(thetaSeam) * Vec3f::UnitY();
      addVertex(m, majorM * radial + minorM * n, n, Vec2f(majorM * phi, minorM * theta));
    }
  }
  const uint32_t stride = uint32_t(tubeSides + 1);
  for (uint32_t i = 0; i < uint32_t(ringSides); ++i)
    for (uint32_t j = 0; j < uint32_t(tubeSides); ++j) {
      const uint32_t a = i * stride + j, b = a + stride, c = b + 1, d = a + 1;
      addTriangle(m, a, b, c);
      addTriangle(m, a, c, d);
    }
  orientToNormals(m);
  return m;
}

TriangleMesh sweep(const std::vector<Vec3f>& path, const std::vector<Vec3f>& up,
                   const std::vector<float>& halfWidth, const std::vector<float>& halfThick, int sides) {
  TriangleMesh m;
  const size_t n = path.size();
  std::vector<uint32_t> ringStart(n);
  std::vector<bool> apex(n);
  std::vector<Vec3f> tangent(n);
  float along = 0.f;
  for (size_t i = 0; i < n; ++i) {
    tangent[i] = (path[std::min(i + 1, n - 1)] - path[i > 0 ? i - 1 : 0]).normalized();
    const Vec3f side = tangent[i].cross(up[i]).normalized();
    const Vec3f upPerp = side.cross(tangent[i]).normalized();
    if (i > 0) along += (path[i] - path[i - 1]).norm();
    ringStart[i] = uint32_t(m.positions.size());
    apex[i] = halfWidth[i] <= 0.f || halfThick[i] <= 0.f;
    if (apex[i]) {
      addVertex(m, path[i], i == 0 ? Vec3f(-tangent[i]) : tangent[i], Vec2f(0, along));
      continue;
    }
    for (int k = 0; k < sides; ++k) {
      const float theta = 2.f * kPi * float(k) / float(sides);
      const float c = std::cos(theta), s = std::sin(theta);
      const Vec3f p = path[i] + halfWidth[i] * c * side + halfThick[i] * s * upPerp;
      const Vec3f nrm = (c / halfWidth[i]) * side + (s / halfThick[i]) * upPerp;
      addVertex(m, p, nrm, Vec2f(theta * halfWidth[i], along));
    }
  }
  auto at = [&](size_t i, int k) { return apex[i] ? ringStart[i] : ringStart[i] + uint32_t(k % sides); };
  for (size_t i = 0; i + 1 < n; ++i)
    for (int k = 0; k < sides; ++k) {
      addTriangle(m, at(i, k), at(i, k + 1), at(i + 1, k + 1));
      addTriangle(m, at(i, k), at(i + 1, k + 1), at(i + 1, k));
    }
  // Flat caps where an end is open.
  for (size_t i : {size_t(0), n - 1}) {
    if (apex[i]) continue;
    const Vec3f capNormal = i == 0 ? Vec3f(-tangent[i]) : tangent[i];
    const uint32_t centre = addVertex(m, path[i], capNormal, Vec2f(0, 0));
    const uint32_t first = uint32_t(m.positions.size());
    for (int k = 0; k < sides; ++k) {
      const Vec3f p = m.positions[ringStart[i] + uint32_t(k)];
      addVertex(m, p, capNormal, Vec2f(p.x(), p.z()));
    }
    for (int k = 0; k < sides; ++k)
      addTriangle(m, centre, first + uint32_t(k), first + uint32_t((k + 1) % sides));
  }
  orientToNormals(m);
  return m;
}

TriangleMesh transformed(const TriangleMesh& mesh, const Affine& t) {
  TriangleMesh m = mesh;
  const Eigen::Matrix3f normalFrom = t.linear().inverse().transpose();
  for (Vec3f& p : m.positions) p = t * p;
  for (Vec3f& n : m.normals) n = (normalFrom * n).normalized();
  if (t.linear().determinant() < 0)
    for (auto& tri : m.triangles) std::swap(tri[1], tri[2]);
  return m;
}

}  // namespace inlay::library
