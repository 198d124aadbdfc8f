#include "embree_util.h"

#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>

namespace inlay::detail {

namespace {
void onEmbreeError(void*, RTCError code, const char* message) {
  if (code == RTC_ERROR_NONE) return;
  std::fprintf(stderr, "inlay: embree error %d: %s\n", int(code), message ? message : "");
}
}  // namespace

RTCDevice newDevice() {
  RTCDevice device = rtcNewDevice(nullptr);
  INLAY_CHECK(device != nullptr);
  rtcSetDeviceErrorFunction(device, onEmbreeError, nullptr);
  return device;
}

namespace {

// sharedObjectBvh's cache: per mesh address, the mesh it was built for (to tell a freed mesh's
// address reused by a new one) and its BVH.
struct ObjectBvhCache {
  std::mutex mutex;
  RTCDevice device = nullptr;
  struct Entry {
    std::weak_ptr<const TriangleMesh> mesh;
    RTCScene scene = nullptr;
  };
  std::map<const TriangleMesh*, Entry> entries;
  uint64_t builds = 0;

  RTCDevice deviceLocked() {
    if (!device) device = newDevice();
    return device;
  }
  // Drops the BVHs of meshes that are gone (a tracer that still instances one holds its own
  // reference).
  void purgeLocked() {
    for (auto it = entries.begin(); it != entries.end();) {
      if (!it->second.mesh.expired()) {
        ++it;
        continue;
      }
      if (it->second.scene) rtcReleaseScene(it->second.scene);
      it = entries.erase(it);
    }
  }
  RTCScene buildLocked(const TriangleMesh& mesh) {
    ++builds;
    RTCScene scene = rtcNewScene(deviceLocked());
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
    if (!attachTriangles(device, scene, 0, mesh)) {
      rtcReleaseScene(scene);
      return nullptr;
    }
    rtcCommitScene(scene);
    return scene;
  }
};

// Never destroyed: a tracer may be released during static destruction.
ObjectBvhCache& objectBvhCache() {
  static auto* cache = new ObjectBvhCache;
  return *cache;
}

}  // namespace

RTCDevice sharedTracerDevice() {
  ObjectBvhCache& c = objectBvhCache();
  std::lock_guard lock(c.mutex);
  RTCDevice device = c.deviceLocked();
  rtcRetainDevice(device);
  return device;
}

RTCScene sharedObjectBvh(const std::shared_ptr<const TriangleMesh>& mesh) {
  if (!mesh) return nullptr;
  ObjectBvhCache& c = objectBvhCache();
  std::lock_guard lock(c.mutex);
  c.purgeLocked();
  auto it = c.entries.find(mesh.get());
  if (it == c.entries.end())
    it = c.entries.emplace(mesh.get(), ObjectBvhCache::Entry{mesh, c.buildLocked(*mesh)}).first;
  if (it->second.scene) rtcRetainScene(it->second.scene);
  return it->second.scene;
}

uint64_t sharedObjectBvhBuilds() {
  ObjectBvhCache& c = objectBvhCache();
  std::lock_guard lock(c.mutex);
  return c.builds;
}

bool attachTriangles(RTCDevice device, RTCScene scene, unsigned geomId, const TriangleMesh& mesh) {
  if (mesh.triangles.empty() || mesh.positions.empty()) return false;
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.positions.size()));
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    // A non-finite vertex would poison the BVH bounds: zero it; its triangles are made
    // degenerate below.
    const Vec3f p = mesh.positions[i].allFinite() ? mesh.positions[i] : Vec3f::Zero();
    v[3 * i + 0] = p.x();
    v[3 * i + 1] = p.y();
    v[3 * i + 2] = p.z();
  }
  auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), mesh.triangles.size()));
  const auto n = uint32_t(mesh.positions.size());
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    bool usable = true;
    for (int k = 0; k < 3; ++k) {
      const uint32_t j = mesh.triangles[i][k];
      usable = usable && j < n && mesh.positions[j].allFinite();
    }
    // An unusable triangle (index out of range, non-finite vertex) becomes degenerate: never hit.
    for (int k = 0; k < 3; ++k) idx[3 * i + k] = usable ? mesh.triangles[i][k] : 0;
  }
  rtcCommitGeometry(geom);
  rtcAttachGeometryByID(scene, geom, geomId);
  rtcReleaseGeometry(geom);
  return true;
}

void attachQuad(RTCDevice device, RTCScene scene, unsigned geomId, const std::array<Vec3, 4>& c) {
  TriangleMesh quad;
  for (const auto& p : c) quad.positions.push_back(p.cast<float>());
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  attachTriangles(device, scene, geomId, quad);
}

}  // namespace inlay::detail
