// Internal: small RAII and conversion helpers around the Embree 3 C API.
#pragma once

#include "inlay/modeling/core.h"
#include "inlay/modeling/mesh.h"

#include <embree3/rtcore.h>
#include <pmmintrin.h>  // _MM_SET_DENORMALS_ZERO_MODE
#include <xmmintrin.h>

#include <array>
#include <cstdint>
#include <limits>
#include <memory>

namespace inlay::detail {

// Sets flush-to-zero and denormals-are-zero for the scope (Embree's advice for tracing
// threads) and restores the caller's MXCSR, so TBB workers shared with other libraries are
// left as they were.
class DenormalsOffScope {
 public:
  DenormalsOffScope() : saved_(_mm_getcsr()) {
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
  }
  ~DenormalsOffScope() { _mm_setcsr(saved_); }
  DenormalsOffScope(const DenormalsOffScope&) = delete;
  DenormalsOffScope& operator=(const DenormalsOffScope&) = delete;

 private:
  unsigned int saved_;
};

// A new Embree device; aborts (a bug or a broken install) when Embree cannot start.
RTCDevice newDevice();

// The Embree device every PathTracer of the process builds in (retained for the caller: release
// it), so that they can share the object BVHs below.
RTCDevice sharedTracerDevice();
// The committed object-space BVH of `mesh` in sharedTracerDevice(), retained for the caller
// (release it); null when the mesh has nothing to attach. Built once per mesh while the mesh
// lives (the cache holds it by address and checks the mesh is still the one it built): a tracer
// rebuilt after an edit that kept an object's mesh (a material, hide, insert, delete or undo)
// instances the BVH it had. Meshes are immutable (shared_ptr<const>). Thread-safe.
RTCScene sharedObjectBvh(const std::shared_ptr<const TriangleMesh>& mesh);
// Object BVHs sharedObjectBvh() built so far in this process.
uint64_t sharedObjectBvhBuilds();

// Adds triangles (positions in the scene's frame) as geometry `geomId` of `scene`.
// Skips empty meshes. Returns false when the mesh had nothing to add.
bool attachTriangles(RTCDevice device, RTCScene scene, unsigned geomId, const TriangleMesh& mesh);
// Adds a two-triangle quad as geometry `geomId`.
void attachQuad(RTCDevice device, RTCScene scene, unsigned geomId, const std::array<Vec3, 4>& c);

// Ray k of a filter function's packet: its origin, direction and the candidate hit's distance.
struct FilterRay {
  Vec3 org, dir;
  float t;
  Vec3 hitPoint() const { return org + double(t) * dir; }
};
inline FilterRay filterRay(const RTCFilterFunctionNArguments* args, unsigned k) {
  const unsigned n = args->N;
  return {Vec3(RTCRayN_org_x(args->ray, n, k), RTCRayN_org_y(args->ray, n, k),
               RTCRayN_org_z(args->ray, n, k)),
          Vec3(RTCRayN_dir_x(args->ray, n, k), RTCRayN_dir_y(args->ray, n, k),
               RTCRayN_dir_z(args->ray, n, k)),
          RTCRayN_tfar(args->ray, n, k)};
}

inline RTCRay makeRay(const Vec3& origin, const Vec3& dir, double tNear, double tFar) {
  RTCRay r;
  r.org_x = float(origin.x());
  r.org_y = float(origin.y());
  r.org_z = float(origin.z());
  r.dir_x = float(dir.x());
  r.dir_y = float(dir.y());
  r.dir_z = float(dir.z());
  r.tnear = float(tNear);
  r.tfar = tFar >= 3e38 ? std::numeric_limits<float>::infinity() : float(tFar);
  r.time = 0;
  r.mask = 0xFFFFFFFFu;
  r.id = 0;
  r.flags = 0;
  return r;
}

inline RTCRayHit makeRayHit(const Vec3& origin, const Vec3& dir, double tNear, double tFar) {
  RTCRayHit rh;
  rh.ray = makeRay(origin, dir, tNear, tFar);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  for (unsigned l = 0; l < RTC_MAX_INSTANCE_LEVEL_COUNT; ++l) rh.hit.instID[l] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

// True when the ray segment (tNear, tFar) is blocked in `scene`.
inline bool occluded(RTCScene scene, const Vec3& origin, const Vec3& dir, double tNear, double tFar) {
  RTCRay ray = makeRay(origin, dir, tNear, tFar);  // an occlusion test reads no hit record
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  rtcOccluded1(scene, &ctx, &ray);
  return ray.tfar < 0;  // Embree sets tfar = -inf on a hit
}

// Offset for a ray leaving a surface point: enough to clear float round-off of the hit point
// (Embree intersects in float) at room scale, small against any modelled gap.
inline double rayEpsilon(const Vec3& p) { return 1e-4 * (1.0 + p.cwiseAbs().maxCoeff() * 0.1); }

}  // namespace inlay::detail
