#include "inlay/lighting/shaft.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace inlay {

namespace {

struct BoxPixel {
  int x, y;
  double logLum;
  int surface;
  Vec3 point;
  double area;  // world area of the pixel's footprint (relative)
};

// Pixels of a box with their surface hits. Returns an error when the box misses the photo.
Expected<std::vector<BoxPixel>> boxPixels(const std::array<double, 4>& box, const ImageF& photo,
                                          const Camera& camera, const SceneGeometry& geometry,
                                          const std::string& key) {
  for (double v : box)
    if (!std::isfinite(v)) return Error{"", key, "is not a finite number"};
  const int x0 = std::max(0, int(std::floor(box[0]))), y0 = std::max(0, int(std::floor(box[1])));
  const int x1 = std::min(photo.width, int(std::ceil(box[2]))),
            y1 = std::min(photo.height, int(std::ceil(box[3])));
  if (!(x1 - x0 >= 2 && y1 - y0 >= 2))
    return Error{"", key, "the box covers less than 2 x 2 pixels of the photo"};
  std::vector<BoxPixel> out;
  out.reserve(size_t(x1 - x0) * (y1 - y0));
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const Vec3 c = photo.rgb(x, y);
      if (!c.allFinite()) continue;
      const double lum = luminance(c);
      const Ray r = camera.rayThroughPixel(Vec2(x + 0.5, y + 0.5));
      const auto h = geometry.intersect(r);
      if (!h) continue;
      const double cosv = std::max(0.05, std::abs(h->normalWorld.dot(r.direction)));
      out.push_back(
          {x, y, std::log(std::max(lum, 1e-5)), h->surfaceId, h->pointWorld, h->t * h->t / cosv});
    }
  if (out.size() < 4)
    return Error{"", key,
                 "the box shows no surface of the room: draw it over the sunlit patch on the floor "
                 "or a wall, or " +
                     roomBoxAdvice(camera, geometry.box, SurfaceKind::WallBack)};
  return out;
}

}  // namespace

// Otsu's threshold on values: OpenCV's, on the values binned to 256 levels between their extremes;
// also returns the two class means (of the values themselves).
double detail::otsuThreshold(const std::vector<double>& v, double* meanLow, double* meanHigh) {
  const auto [mnIt, mxIt] = std::minmax_element(v.begin(), v.end());
  const double mn = *mnIt, mx = *mxIt;
  if (!(mx - mn > 1e-9)) {
    *meanLow = *meanHigh = mn;
    return mx;
  }
  cv::Mat1b levels(1, int(v.size()));
  for (size_t i = 0; i < v.size(); ++i)
    levels(0, int(i)) = uchar(std::clamp(int((v[i] - mn) / (mx - mn) * 255), 0, 255));
  cv::Mat unused;
  const int t = int(cv::threshold(levels, unused, 0, 255, cv::THRESH_BINARY | cv::THRESH_OTSU));
  double sum[2] = {0, 0}, count[2] = {0, 0};
  for (size_t i = 0; i < v.size(); ++i) {
    const int high = levels(0, int(i)) > t;
    sum[high] += v[i], count[high] += 1;
  }
  *meanLow = count[0] > 0 ? sum[0] / count[0] : mn;
  *meanHigh = count[1] > 0 ? sum[1] / count[1] : mx;
  return mn + (t + 0.5) / 255 * (mx - mn);
}

namespace {

Vec4 planeOf(const Surface& s) {
  const auto& m = s.meshWorld;
  const Vec3 a = m.positions[m.triangles[0][0]].cast<double>(),
             b = m.positions[m.triangles[0][1]].cast<double>(),
             c = m.positions[m.triangles[0][2]].cast<double>();
  Vec3 n = (b - a).cross(c - a).normalized();
  return Vec4(n.x(), n.y(), n.z(), -n.dot(a));
}

// The bright mode of a box as a soft mask on its dominant surface.
struct Patch {
  ImageF mask;
  int surface = -1;
  Vec3 centroid{0, 0, 0};
  double contrast = 0;
  int count = 0;
};

Patch brightPatch(const std::vector<BoxPixel>& px, int W, int H, size_t surfaceCount) {
  std::vector<double> v;
  v.reserve(px.size());
  for (const auto& p : px) v.push_back(p.logLum);
  double lo = 0, hi = 0;
  const double thr = detail::otsuThreshold(v, &lo, &hi);
  Patch out;
  out.contrast = std::exp(hi - lo);
  // Soft edge: a logistic of width 0.08 in log luminance around the threshold.
  auto soft = [&](double l) { return 1.0 / (1.0 + std::exp(-(l - thr) / 0.08)); };
  std::vector<double> weight(surfaceCount, 0.0);
  for (const auto& p : px) weight[size_t(p.surface)] += soft(p.logLum) * p.area;
  out.surface = int(std::max_element(weight.begin(), weight.end()) - weight.begin());
  out.mask = ImageF(W, H, 1, 0.f);
  double wsum = 0;
  for (const auto& p : px) {
    if (p.surface != out.surface) continue;
    const double m = soft(p.logLum);
    out.mask.at(p.x, p.y) = float(m);
    out.centroid += m * p.area * p.point;
    wsum += m * p.area;
    out.count += m > 0.5;
  }
  if (wsum > 0) out.centroid /= wsum;
  return out;
}

}  // namespace

Expected<ShaftEstimate> sunFromShaft(const ShaftKeys& shaft, const ImageF& photo, const Camera& camera,
                                     const SceneGeometry& geometry, const std::string& key) {
  ShaftEstimate out;
  const int W = photo.width, H = photo.height;
  const size_t S = geometry.surfaces.size();
  std::optional<Patch> patch, source;
  if (shaft.shaftBoxPx) {
    auto px = boxPixels(*shaft.shaftBoxPx, photo, camera, geometry, key + ".shaft_box_px");
    if (!px) return px.error();
    Patch p = brightPatch(*px, W, H, S);
    if (!(p.contrast > 1.4) || p.count < 4)
      return Error{"", key + ".shaft_box_px",
                   "no sunlit patch found in the box (its bright part is only " +
                       std::to_string(p.contrast) + " times its dark part)"};
    patch = std::move(p);
  }
  if (shaft.sourceBoxPx) {
    auto px = boxPixels(*shaft.sourceBoxPx, photo, camera, geometry, key + ".source_box_px");
    if (!px) return px.error();
    source = brightPatch(*px, W, H, S);
  }
  Vec3 dir;
  if (shaft.direction) {
    dir = *shaft.direction;
    out.directionGiven = true;
  } else if (patch && source) {
    dir = patch->centroid - source->centroid;
  } else {
    return Error{"", key + ".direction", "is needed when only one box is given"};
  }
  if (!dir.allFinite() || dir.norm() < 1e-9)
    return Error{"", key + ".direction", "is not a usable direction (zero or not finite)"};
  dir.normalize();
  const Patch& receiver = patch ? *patch : *source;
  if (receiver.surface < 0 || size_t(receiver.surface) >= S)
    return Error{"", key,
                 "the lit region is not on any surface of the room: " +
                     roomBoxAdvice(camera, geometry.box, SurfaceKind::WallBack)};
  const Vec4 plane = planeOf(geometry.surfaces[size_t(receiver.surface)]);
  // The patch must face the light: light arrives on the room side of its surface.
  Vec3 n = plane.head<3>();
  const Vec3 towardCamera = camera.centreWorld() - receiver.centroid;
  if (n.dot(towardCamera) < 0) n = -n;
  if (patch && !(n.dot(dir) < -1e-3))
    return Error{
        "", key,
        "the light's direction does not reach the lit patch (on the " +
            geometry.surfaces[size_t(receiver.surface)].name +
            ") from inside the room: the window box and the patch box must be on the room's "
            "sides the sunlight passes between (the patch lit, the window it comes "
            "through), or " +
            roomBoxAdvice(camera, geometry.box, geometry.surfaces[size_t(receiver.surface)].kind)};
  out.sun.travelDirection = dir;
  out.sun.irradianceOverPi = Vec3(1, 1, 1);
  out.sun.receiverPlane = plane;
  out.sun.camera = camera;
  out.sun.litMask = receiver.mask;
  out.litMaskPx = receiver.mask;
  out.patchCentroidWorld = patch ? patch->centroid : Vec3::Zero();
  out.sourceCentroidWorld = source ? source->centroid : Vec3::Zero();
  out.contrast = receiver.contrast;
  out.litPixels = receiver.count;
  return out;
}

namespace {

// The lit pixels of the beam carried back against the light: per box surface reached, the
// points where they cross it.
std::map<int, std::vector<Vec3>> beamCrossings(const SunLight& sun, const Camera& camera,
                                               const SceneGeometry& geometry) {
  std::map<int, std::vector<Vec3>> out;
  const ImageF& mask = sun.litMask;
  const Vec3 toSun = -sun.travelDirection.normalized();
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x) {
      if (!(mask.at(x, y) > 0.5f)) continue;
      const Vec2 px((x + 0.5) * camera.widthPx / mask.width, (y + 0.5) * camera.heightPx / mask.height);
      const auto h = geometry.intersect(camera.rayThroughPixel(px));
      if (!h) continue;
      const auto back = geometry.intersect(Ray{h->pointWorld + 1e-5 * h->normalWorld, toSun});
      if (!back || !isBoxSurface(geometry.surfaces[size_t(back->surfaceId)].kind)) continue;
      out[back->surfaceId].push_back(back->pointWorld);
    }
  return out;
}

// The q-quantile of v (reordered).
double quantileOf(std::vector<double>& v, double q) {
  const size_t k = std::min(v.size() - 1, size_t(q * double(v.size())));
  std::nth_element(v.begin(), v.begin() + long(k), v.end());
  return v[k];
}

// Of 8 x 8 points on the light, the share the camera sees (the first surface along its ray).
double visibleShareOf(const AreaLight& light, int surface, const Camera& camera,
                      const SceneGeometry& geometry) {
  int seen = 0;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      const double a = (i + 0.5) / 8, b = (j + 0.5) / 8;
      const auto& c = light.cornersWorld;
      const Vec3 q = (1 - a) * (1 - b) * c[0] + a * (1 - b) * c[1] + a * b * c[2] + (1 - a) * b * c[3];
      const auto px = camera.project(q);
      if (!px || px->x() < 0 || px->y() < 0 || px->x() >= camera.widthPx || px->y() >= camera.heightPx)
        continue;
      const auto h = geometry.intersect(camera.rayThroughPixel(*px));
      seen += h && h->surfaceId == surface && (h->pointWorld - q).norm() < 0.02;
    }
  return seen / 64.0;
}

// The beam's section [a0, a1] x [b0, b1] (along u, v in the wall's plane, inward normal n)
// widened to the inner opening of a wall `depth` thick (openingOfBeam): the outer opening, seen
// along the beam, is the inner one shifted by depth x the beam's slope across the wall, so the
// section is the inner opening less that shift on the side the shift leaves. Each side grows by
// at most the section's extent (a beam grazing the wall); nothing for depth <= 0, not finite, or
// a beam that does not cross the wall into the room.
void widenByReveal(const Vec3& travel, const Vec3& n, const Vec3& u, const Vec3& v, double depth,
                   double& a0, double& a1, double& b0, double& b1) {
  const double across = travel.dot(n);
  if (!(depth > 0) || !std::isfinite(depth) || !(across > 1e-6) || !travel.allFinite()) return;
  auto widen = [&](double along, double& lo, double& hi) {
    const double shift = std::clamp(depth * along / across, -(hi - lo), hi - lo);
    if (shift > 0) lo -= shift;
    else hi -= shift;
  };
  widen(travel.dot(u), a0, a1);
  widen(travel.dot(v), b0, b1);
}

// The rectangle [a0, a1] x [b0, b1] (from `origin` along u, v: a box surface's axes) cut to the
// room box (a window cannot reach past its wall's edges).
void clampToBox(const RoomBox& box, const Vec3& origin, const Vec3& u, const Vec3& v, double& a0,
                double& a1, double& b0, double& b1) {
  const Vec3 lo(std::min(box.xLeftM, box.xRightM), 0.0, std::min(box.zBackM, box.zRearM));
  const Vec3 hi(std::max(box.xLeftM, box.xRightM), box.ceilingM, std::max(box.zBackM, box.zRearM));
  auto limits = [&](const Vec3& axis, double& l0, double& l1) {
    // The range of t with origin + t axis inside the box along the axis' main coordinate.
    int k = 0;
    axis.cwiseAbs().maxCoeff(&k);
    if (std::abs(axis[k]) < 0.5) return;
    double t0 = (lo[k] - origin[k]) / axis[k], t1 = (hi[k] - origin[k]) / axis[k];
    if (t0 > t1) std::swap(t0, t1);
    const double n0 = std::max(l0, t0), n1 = std::min(l1, t1);
    if (n1 - n0 > 1e-3) l0 = n0, l1 = n1;
  };
  limits(u, a0, a1);
  limits(v, b0, b1);
}

}  // namespace

std::optional<BeamOpening> openingOfBeam(const SunLight& sun, const Camera& camera,
                                         const SceneGeometry& geometry, int minPixels,
                                         double revealDepthM) {
  const auto crossings = beamCrossings(sun, camera, geometry);
  const auto most = std::max_element(crossings.begin(), crossings.end(),
                                     [](auto& a, auto& b) { return a.second.size() < b.second.size(); });
  if (most == crossings.end() || int(most->second.size()) < std::max(minPixels, 4)) return std::nullopt;
  const std::vector<Vec3>& pts = most->second;
  // The surface's normal into the room and two axes in its plane (a box surface: axis-aligned).
  const Vec4 plane = planeOf(geometry.surfaces[size_t(most->first)]);
  Vec3 n = plane.head<3>().normalized();
  const RoomBox& box = geometry.box;
  const Vec3 centre(0.5 * (box.xLeftM + box.xRightM), 0.5 * box.ceilingM,
                    0.5 * (box.zBackM + box.zRearM));
  if (n.dot(centre - pts[0]) < 0) n = -n;
  // u horizontal (width), v up the wall (height); on the ceiling u along x.
  const Vec3 up = std::abs(n.y()) > 0.9 ? Vec3::UnitZ() : Vec3::UnitY();
  const Vec3 u = up.cross(n).normalized(), v = n.cross(u).normalized();
  std::vector<double> a(pts.size()), b(pts.size());
  for (size_t i = 0; i < pts.size(); ++i)
    a[i] = (pts[i] - pts[0]).dot(u), b[i] = (pts[i] - pts[0]).dot(v);
  double a0 = quantileOf(a, 0.02), a1 = quantileOf(a, 0.98), b0 = quantileOf(b, 0.02),
         b1 = quantileOf(b, 0.98);
  if (!(a1 - a0 > 1e-3 && b1 - b0 > 1e-3)) return std::nullopt;
  widenByReveal(sun.travelDirection, n, u, v, revealDepthM, a0, a1, b0, b1);
  clampToBox(box, pts[0], u, v, a0, a1, b0, b1);
  BeamOpening out;
  const Vec3 o = pts[0] + 1e-3 * n;
  out.light.cornersWorld = {o + a0 * u + b0 * v, o + a1 * u + b0 * v, o + a1 * u + b1 * v,
                            o + a0 * u + b1 * v};
  if (out.light.normal().dot(n) < 0) std::swap(out.light.cornersWorld[1], out.light.cornersWorld[3]);
  out.light.radiance = Vec3(1, 1, 1);
  out.surface = most->first;
  out.widthM = a1 - a0;
  out.heightM = b1 - b0;
  out.pixels = int(pts.size());
  out.visibleShare = visibleShareOf(out.light, out.surface, camera, geometry);
  return out;
}

}  // namespace inlay
