#include "embree_util.h"

#include <cstdio>
#include <cstdlib>

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
