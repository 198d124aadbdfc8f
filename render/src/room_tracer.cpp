// RoomTracer: Embree queries on the empty room for the lighting stage, and the projected albedo
// lookup that the path tracer uses for room surfaces.
#include "embree_util.h"
#include "sampling.h"

#include "inlay/render/path_tracer.h"
#include "inlay/render/scene.h"

#include <tbb/blocked_range.h>
#include "inlay/modeling/parallel.h"

#include <cmath>

namespace inlay {

using namespace detail;

struct RoomTracer::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<TriangleMesh> meshes;                     // per surface id, world space (for normals)
  std::vector<std::shared_ptr<const CardAlpha>> cards;  // the mattes the filters read

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

namespace {

// An occluder card stops a ray where its matte covers at least half (alpha >= 0.5) and lets it
// pass elsewhere, as SceneGeometry::intersect does: the card stands for the object's silhouette,
// not for its bounding box (the floor seen between a table's legs is floor, and lit as floor).
// Deterministic, unlike the renderer's stochastic test: the lighting stage must give the same
// result on every run.
void cardMatteFilter(const RTCFilterFunctionNArguments* args) {
  const auto* card = static_cast<const CardAlpha*>(args->geometryUserPtr);
  for (unsigned k = 0; k < args->N; ++k) {
    if (args->valid[k] != -1) continue;
    if (card->alphaAt(filterRay(args, k).hitPoint()) < 0.5) args->valid[k] = 0;
  }
}

}  // namespace

RoomTracer::RoomTracer(const SceneGeometry& room) : impl_(std::make_unique<Impl>()) {
  impl_->device = newDevice();
  impl_->scene = rtcNewScene(impl_->device);
  for (size_t i = 0; i < room.surfaces.size(); ++i) {
    const Surface& surf = room.surfaces[i];
    impl_->meshes.push_back(surf.meshWorld);
    if (!attachTriangles(impl_->device, impl_->scene, unsigned(i), surf.meshWorld)) continue;
    if (surf.kind != SurfaceKind::OccluderCard || !surf.cardAlpha) continue;
    impl_->cards.push_back(surf.cardAlpha);
    RTCGeometry g = rtcGetGeometry(impl_->scene, unsigned(i));
    rtcSetGeometryUserData(g, const_cast<CardAlpha*>(surf.cardAlpha.get()));
    rtcSetGeometryIntersectFilterFunction(g, cardMatteFilter);
    rtcSetGeometryOccludedFilterFunction(g, cardMatteFilter);
    rtcCommitGeometry(g);
  }
  rtcCommitScene(impl_->scene);
}

RoomTracer::~RoomTracer() = default;

std::optional<SurfaceHit> RoomTracer::intersect(const Ray& ray, double tMin) const {
  DenormalsOffScope ftz;
  RTCRayHit rh = makeRayHit(ray.origin, ray.direction, tMin, 3.4e38);
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  rtcIntersect1(impl_->scene, &ctx, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  SurfaceHit hit;
  hit.surfaceId = int(rh.hit.geomID);
  hit.t = rh.ray.tfar;
  hit.pointWorld = ray.at(hit.t);
  const TriangleMesh& m = impl_->meshes[rh.hit.geomID];
  const auto& tri = m.triangles[rh.hit.primID];
  const Vec3 a = m.positions[tri[0]].cast<double>(), b = m.positions[tri[1]].cast<double>(),
             c = m.positions[tri[2]].cast<double>();
  Vec3 n = (b - a).cross(c - a);
  n = n.squaredNorm() > 0 ? n.normalized() : Vec3(-ray.direction);
  hit.normalWorld = n.dot(ray.direction) > 0 ? Vec3(-n) : n;
  return hit;
}

bool RoomTracer::visible(const Vec3& a, const Vec3& b) const {
  const Vec3 d = b - a;
  const double len = d.norm();
  if (!(len > 0)) return true;
  const double eps = std::min(rayEpsilon(a), 0.25 * len);
  DenormalsOffScope ftz;
  return !occluded(impl_->scene, a, d / len, eps, len - std::min(rayEpsilon(b), 0.25 * len));
}

double RoomTracer::unitLightIrradianceOverPi(const AreaLight& light, const Vec3& p, const Vec3& n,
                                             int samples, uint32_t seed) const {
  const Vec3 nl = light.normal();
  const double area = light.area();
  if (samples <= 0 || !(area > 0) || !nl.allFinite()) return 0;
  const std::array<Vec3, 4> corners = emitterCorners(light);
  if ((p - corners[0]).dot(nl) <= 0) return 0;  // behind the light
  const int nx = std::max(1, int(std::sqrt(double(samples))));
  const int ny = std::max(1, samples / nx);
  const uint32_t key = pcgHash(seed ^ 0x5bd1e995u);
  // Stratified in the solid angle the light subtends (bounded next to the light, as in the
  // path tracer): Urena's map for rectangles, Arvo's triangles otherwise; by area when tiny.
  Vec3 s, ex, ey;
  std::optional<SphericalRect> sr;
  std::optional<SphericalQuad> sq;
  if (asRectangle(corners, &s, &ex, &ey)) {
    sr.emplace(s, ex, ey, p);
    if (!(sr->solidAngle > 1e-6)) sr.reset();
  } else {
    sq.emplace(corners, p);
    if (!(sq->solidAngle > 1e-6)) sq.reset();
  }
  DenormalsOffScope ftz;
  double sum = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const uint32_t h = pcgHash(key + pcgHash(uint32_t(j * nx + i)));
      const double u = (i + double(h & 0xFFFF) / 65536.0) / nx, v = (j + double(h >> 16) / 65536.0) / ny;
      const Vec3 y = sr ? sr->sample(u, v) : sq ? sq->sample(u, v) : sampleQuadUniform(corners, u, v);
      Vec3 w = y - p;
      const double d2 = w.squaredNorm();
      if (!(d2 > 0)) continue;
      const double d = std::sqrt(d2);
      w /= d;
      const double cosR = n.dot(w), cosL = -nl.dot(w);
      if (cosR <= 0 || cosL <= 0) continue;
      const double eps = std::min(rayEpsilon(p), 0.25 * d);
      if (occluded(impl_->scene, p, w, eps, d * (1.0 - 1e-5))) continue;
      // E / pi = (1/pi) * integral of L cosR over the light's solid angle, with L = 1.
      sum += sr || sq ? cosR : cosR * cosL / d2 * area;
    }
  const double measure = sr ? sr->solidAngle : sq ? sq->solidAngle : 1.0;
  return sum * measure / (double(nx) * ny) / kPi;
}

Vec3 ProjectedAlbedo::lookup(int surfaceId, const Vec3& pointWorld) const {
  return albedoAtPixel(surfaceId,
                       albedo.channels < 1 ? std::nullopt : pixelShowing(surfaceId, pointWorld));
}

Vec3 ProjectedAlbedo::albedoAtPixel(int surfaceId, std::optional<size_t> i) const {
  const bool haveMean = surfaceId >= 0 && size_t(surfaceId) < surfaceMean.size();
  // No mean for this id (the host gave none): a neutral grey rather than black or white.
  Vec3 fallback = haveMean ? surfaceMean[size_t(surfaceId)] : Vec3(0.5, 0.5, 0.5);
  if (albedo.channels < 1 || !i) return fallback;
  return albedo.rgb(int(*i % size_t(albedo.width)), int(*i / size_t(albedo.width)));
}

std::optional<size_t> ProjectedAlbedo::pixelShowing(int surfaceId, const Vec3& pointWorld) const {
  const int w = albedo.width, h = albedo.height;
  if (albedo.empty() || firstSurfacePerPixel.size() != size_t(w) * h || camera.widthPx <= 0 ||
      camera.heightPx <= 0)
    return std::nullopt;
  const auto px = camera.project(pointWorld);
  if (!px) return std::nullopt;
  // The albedo image may differ in size from the camera's pixel frame: scale.
  const double x = px->x() * double(w) / camera.widthPx, y = px->y() * double(h) / camera.heightPx;
  if (!(x >= 0 && y >= 0 && x < w && y < h)) return std::nullopt;
  const size_t i = size_t(std::min(h - 1, int(y))) * w + size_t(std::min(w - 1, int(x)));
  if (firstSurfacePerPixel[i] != surfaceId) return std::nullopt;
  return i;
}

void ProjectedAlbedo::computeFirstSurfaces(const SceneGeometry& geometry) {
  const int w = albedo.empty() ? camera.widthPx : albedo.width;
  const int h = albedo.empty() ? camera.heightPx : albedo.height;
  firstSurfacePerPixel.assign(size_t(std::max(0, w)) * std::max(0, h), -1);
  if (w <= 0 || h <= 0 || camera.widthPx <= 0 || camera.heightPx <= 0) return;
  const RoomTracer tracer(geometry);
  parallelFor(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y != rows.end(); ++y)
      for (int x = 0; x < w; ++x) {
        const Vec2 px((x + 0.5) * camera.widthPx / w, (y + 0.5) * camera.heightPx / h);
        const auto hit = tracer.intersect(camera.rayThroughPixel(px), 1e-6);
        if (hit) firstSurfacePerPixel[size_t(y) * w + x] = hit->surfaceId;
      }
  });
}

}  // namespace inlay
