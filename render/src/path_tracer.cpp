// The differential Embree path tracer (see path_tracer.h for the contract).
//
// Scenes: `withScene` holds the room surfaces (geomID = surface id), the emitter quads of the
// area lights (geomID = surfaceCount + light index) and one instance per inserted object
// (geomID = surfaceCount + lightCount + object index), each instancing the object's own BVH.
// `withoutScene` holds the same room surfaces and emitters only. Moving an object rewrites its
// instance transform and recommits the top-level scene; the object's BVH is kept.
//
// Differential paths: tracePath() runs in Shared mode while the with-object path has met no
// object: every contribution is added to both sums with the same float value, so the sums
// stay bit-identical. A shadow ray blocked in the with-scene is retried in the without-scene
// (only then do the contributions differ). When the with-path hits an object, the same ray is
// traced on in the without-scene (WithoutOnly) and the with-path continues (WithOnly); both use
// the random dimensions of their depth, so they stay correlated.
//
// Light transport: unidirectional path tracing with next-event estimation to the area lights
// (one light picked by power over squared distance, or from a power table when there are many,
// TracerOptions::lightSelection; a point uniform in its solid angle, by area
// when that is tiny, a shadow ray) combined with BSDF sampling by the power heuristic (MIS). Camera rays and specular bounces see lights at
// full weight. Emissive objects are lights too: NEE picks them among the area lights by the same
// rule and samples a point uniformly by area on their triangles (MIS with BSDF hits likewise);
// they exist in the with-scene only, so their light reaches the with-sums alone.
// Materials (bsdf.h): room surfaces are Lambertian with the projected albedo, or Glossy over it
// or Mirror where the user marked them (RenderScene::roomMaterials, in both images); objects are
// Lambertian, Glossy (Fresnel-weighted GGX over a Lambertian base, energy <= 1), Conductor
// (GGX metal), Mirror, clear smooth Glass (Fresnel, Snell, no absorption, no eta^2 radiance
// scaling: it cancels on the way out), RoughGlass (Walter et al. 2007; NEE and MIS on both
// sides: lights behind the interface are reached through transmission), or Emissive (black
// otherwise). Russian roulette from russianRouletteDepth with survival min(0.95, max
// throughput). With TracerOptions::causticPhotons, smooth glass objects' caustics come from a
// photon map (the pass near the end of this file) at Lambertian vertices instead.
//
// Suns (parallel light through an opening, masked to their beam) are added at every
// non-specular vertex with a shadow ray against what stands inside the room (extrusions, cards,
// objects), never the box walls. When the host gives the photo's radiance, a bounce (never a
// camera ray) that lands on room the camera sees takes the photo's radiance there and ends; a
// with-only path adds what the objects change at that point (addObjectsEffect: their shadow).
//
// Random dimensions: 0, 1 the pixel jitter; vertex d uses 2 + 8 d + {0-1 light point, 2-3
// direction, 4 light pick, 5 lobe or Fresnel choice, 6 roulette, 7 occluder-card alpha test}
// (pairs are 2D-stratified).
//
// Occluder cards (SurfaceKind::OccluderCard, a matte standing in the room): a camera or bounce
// ray that meets one passes on with probability 1 - alpha there, and is otherwise room: a
// stochastic alpha test inside an Embree intersection filter, with the number of the vertex's
// dimension it looks for, carried in the ray's intersect context (with- and without-paths draw
// the same number; several cards on one ray share it, so their passes are correlated). Shadow rays get the same stochastic test inside an Embree occlusion filter,
// whose number is a hash of the ray and the hit distance (the filter has no sampler): shadows
// behind a matte's soft edge are soft, and the with- and without-scene tests of one shadow ray
// agree.
//
// Rays leave surfaces from the hit point offset along the geometric normal (rayEpsilon); the
// emitters sit 1 mm in front of their lights (kLightOffsetM).
#include "camera_directions.h"
#include "bsdf.h"
#include "caustic_map.h"
#include "embree_util.h"
#include "pixel_filter.h"
#include "simd_lanes.h"
#include "room_texture.h"
#include "sampling.h"
#include "sun_patch.h"

#include "inlay/render/path_tracer.h"

#include <tbb/blocked_range.h>
#include "inlay/modeling/parallel.h"
#include <tbb/task_arena.h>

#include <algorithm>
#include <bit>
#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <utility>

namespace inlay {

using namespace detail;

namespace {

constexpr int kTileSize = 16;
constexpr uint32_t kDimsPerVertex = 8;
constexpr uint32_t kFirstVertexDim = 2;  // dimensions 0, 1: the pixel jitter
// The sunlit patches' NEE (addSunPatchSample) draws its numbers from pairs far above the
// vertices' (kSunPatchPair + 2 depth and + 1): rooms without a patch keep their noise pattern.
constexpr uint32_t kSunPatchPair = 1u << 20;

enum class Mode { Shared, WithOnly, WithoutOnly };

struct ObjectData {
  RTCScene scene = nullptr;           // the object's own BVH (object space)
  RTCGeometry instance = nullptr;     // its instance in withScene (retained)
  RTCGeometry sunInstance = nullptr;  // its instance in sunWithScene (retained), if suns
  std::shared_ptr<const TriangleMesh> mesh;
  Mat4 worldFromObject = Mat4::Identity();
  Mat3 normalFromObject = Mat3::Identity();  // inverse transpose of the linear part
  bool mirrored = false;                     // negative determinant: winding flips
  bool shadingNormals = false;               // per-vertex normals usable
  Material material;
  int meshLight = -1;  // index into Impl::meshLights when emissive
  // A multi-material asset's per-part materials (InsertedObject::partMaterials) and, per part,
  // its index into Impl::meshLights (-1: not emissive). Empty: `material` everywhere.
  std::vector<Material> parts;
  std::vector<int> partMeshLight;

  // The part index of triangle `prim`, or -1 when `material` applies.
  int partOf(unsigned prim) const {
    if (parts.empty() || !mesh || prim >= mesh->triangleMaterial.size()) return -1;
    const uint32_t k = mesh->triangleMaterial[prim];
    return k < parts.size() ? int(k) : -1;
  }
  const Material& materialOf(unsigned prim) const {
    const int k = partOf(prim);
    return k < 0 ? material : parts[size_t(k)];
  }
  int meshLightOf(unsigned prim) const {
    const int k = partOf(prim);
    return k < 0 ? meshLight : partMeshLight[size_t(k)];
  }
};

struct LightData {
  std::array<Vec3, 4> emitter;  // corners of the emitter quad (offset from the light)
  bool rectangle = false;       // Urena's rectangle sampler (corner + edges below), else Arvo's
                                // triangles; both by solid angle
  Vec3 corner, edgeX, edgeY;
  Vec3 normal;
  double area = 0;
  Vec3 radiance;
  Vec3 centre;
  double radius = 0;              // the largest distance from the centre to a corner
  double firstTriangleShare = 0;  // sampleQuadUniform's split of the emitter by area
  double power = 0;               // area x mean radiance; 0: never picked
};

// An emissive object (or the emissive part of a multi-material one) as a light: its triangles
// in world space (refreshed when it moves), picked by area (one radiance per light, so by power
// too). Two-sided, as its hits are.
struct MeshLightData {
  size_t object = 0;
  int part = -1;                           // the object's part (-1: all its triangles)
  std::vector<Vec3> corner, edge1, edge2;  // triangle k = corner + b1 edge1 + b2 edge2
  std::vector<double> cumulativeArea;      // running sum; back() = area
  double area = 0;
  Vec3 radiance = Vec3::Zero();
  Vec3 centre = Vec3::Zero();
  std::array<Vec3, 8> boxCorners;  // world bounding box
  double power = 0;                // area x mean radiance; 0: never picked
};

struct SunData {
  const SunLight* sun = nullptr;  // beamAt(); points into Impl::scene.suns
  Vec3 toSun;                     // unit, against the travel direction
  Vec3 irradianceOverPi;
};

struct Hit {
  enum class Kind { None, Room, Light, Object } kind = Kind::None;
  int index = -1;     // surface id, light index or object index
  unsigned prim = 0;  // the object's triangle (its part's material)
  double t = 0;
  Vec3 point;
  Vec3 geometricNormal;  // unit, as the mesh winds it (outward for objects), world space
  Vec3 shadingNormal;    // unit, world space; equals geometricNormal without vertex normals
  // Float round-off of the hit triangle's intersection, metres: it grows with the size of the
  // triangle's coordinates (a 10 km object), so rays leave it at least this far off.
  double roundOffM = 0;
  const RoomTexture::Texel* texel = nullptr;  // room hits: the photo pixel that shows the point
  // A hit set up with its texel unchecked (a bounce cast ahead, PathTracer::Impl::tracePath):
  // the texel the point projects to, prefetched; checkTexel() then sets `texel`.
  const RoomTexture::Texel* texelUnchecked = nullptr;
};

// A bound on Embree's float intersection error for a triangle with these corners.
double triangleRoundOff(const Vec3& a, const Vec3& b, const Vec3& c) {
  return 32.0 * 1.1920929e-7 *
         std::max({a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff(), c.cwiseAbs().maxCoeff()});
}

// The intersect context of a camera or bounce ray: Embree's, then the number the occluder-card
// filter tests against the card's alpha (u < alpha: the card is hit; u < 0: every card is).
struct CardPassContext {
  RTCIntersectContext base;  // first: the filter gets a pointer to it
  double u = -1;
};

// A camera or bounce ray passes an occluder card where u >= alpha (probability 1 - alpha).
void cardIntersectFilter(const RTCFilterFunctionNArguments* args) {
  const auto* card = static_cast<const CardAlpha*>(args->geometryUserPtr);
  const double u = reinterpret_cast<const CardPassContext*>(args->context)->u;
  for (unsigned k = 0; k < args->N; ++k) {
    if (args->valid[k] != -1) continue;
    if (u >= card->alphaAt(filterRay(args, k).hitPoint())) args->valid[k] = 0;
  }
}

double powerHeuristic(double a, double b) {
  const double a2 = a * a, b2 = b * b;
  return a2 + b2 > 0 ? a2 / (a2 + b2) : 0.0;
}

}  // namespace

struct PathTracer::Impl {
  RenderScene scene;
  TracerOptions options;
  PixelFilter pixelFilter;  // where in and around its pixel a camera sample leaves
  RoomTexture room;         // scene.roomAlbedo as room hits read it
  RTCDevice device = nullptr;
  RTCScene withScene = nullptr;
  RTCScene withoutScene = nullptr;
  // Sun shadow rays see only what stands inside the room: extrusions, cards and (with) the
  // objects; the box's walls hold the opening the sun comes through, and emitters are left out.
  RTCScene sunWithScene = nullptr;
  RTCScene sunWithoutScene = nullptr;
  std::vector<SunData> suns;
  SunPatchLight sunPatches;  // the sunlit room the photo shows, a light for NEE (may be empty)
  CausticMap caustics;       // photons through smooth glass (TracerOptions::causticPhotons)
  unsigned surfaceCount = 0;
  bool hasCards = false;  // some room surface is an occluder card with a matte (its filters set)
  std::vector<LightData> lights;
  std::vector<MeshLightData> meshLights;  // NEE sources lights.size() + k
  std::vector<ObjectData> objects;
  mutable std::atomic<uint64_t> nonFiniteSamples{0};
  // Ray counts and times, summed per tile by renderRect (never per ray: no shared cache line
  // in the hot loop).
  struct AtomicCounters {
    std::atomic<uint64_t> cameraRays{0}, bounceRays{0}, shadowRays{0};
    std::atomic<int64_t> cameraNs{0}, bounceNs{0}, shadowNs{0}, neeNs{0};
    void add(const RayCounters& c) {
      neeNs.fetch_add(c.neeNs, std::memory_order_relaxed);
      cameraRays.fetch_add(c.cameraRays, std::memory_order_relaxed);
      bounceRays.fetch_add(c.bounceRays, std::memory_order_relaxed);
      shadowRays.fetch_add(c.shadowRays, std::memory_order_relaxed);
      cameraNs.fetch_add(c.cameraNs, std::memory_order_relaxed);
      bounceNs.fetch_add(c.bounceNs, std::memory_order_relaxed);
      shadowNs.fetch_add(c.shadowNs, std::memory_order_relaxed);
    }
  };
  mutable AtomicCounters counters;

  ~Impl() {
    for (auto& o : objects) {
      if (o.instance) rtcReleaseGeometry(o.instance);
      if (o.sunInstance) rtcReleaseGeometry(o.sunInstance);
      if (o.scene) rtcReleaseScene(o.scene);
    }
    if (withScene) rtcReleaseScene(withScene);
    if (withoutScene) rtcReleaseScene(withoutScene);
    if (sunWithScene) rtcReleaseScene(sunWithScene);
    if (sunWithoutScene) rtcReleaseScene(sunWithoutScene);
    if (device) rtcReleaseDevice(device);
  }

  unsigned objectGeomId(size_t i) const { return surfaceCount + unsigned(lights.size()) + unsigned(i); }

  // The photo's linear pixel under pixel (x, y) of the camera's frame, for the composite's
  // variance (a camera scaled to a smaller grid than the photo, as a big photo's preview is,
  // reads the photo pixel at the same place); zero when the scene carries no photo or the value
  // is not finite.
  Vec3 photoAt(int x, int y) const {
    const ImageF& p = scene.roomAlbedo.photoRadiance;
    if (p.channels < 3 || scene.camera.widthPx <= 0 || scene.camera.heightPx <= 0) return Vec3::Zero();
    if (p.width != scene.camera.widthPx || p.height != scene.camera.heightPx) {
      x = int((x + 0.5) * p.width / scene.camera.widthPx);
      y = int((y + 0.5) * p.height / scene.camera.heightPx);
    }
    const Vec3 v = p.rgb(std::clamp(x, 0, p.width - 1), std::clamp(y, 0, p.height - 1));
    return v.allFinite() ? v : Vec3::Zero();
  }

  void setTransform(ObjectData& o, const Mat4& worldFromObject) {
    o.worldFromObject = worldFromObject;
    const Mat3 linear = worldFromObject.topLeftCorner<3, 3>();
    const double det = linear.determinant();
    o.mirrored = det < 0;
    o.shadingNormals = o.mesh && o.mesh->normals.size() == o.mesh->positions.size() &&
                       std::isfinite(det) && std::abs(det) > 1e-300;
    o.normalFromObject = o.shadingNormals ? Mat3(linear.inverse().transpose()) : Mat3::Identity();
    if (!o.instance) return;
    float m[12];
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 3; ++r) m[c * 3 + r] = float(worldFromObject(r, c));
    rtcSetGeometryTransform(o.instance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, m);
    rtcCommitGeometry(o.instance);
    if (o.sunInstance) {
      rtcSetGeometryTransform(o.sunInstance, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, m);
      rtcCommitGeometry(o.sunInstance);
    }
  }

  // The closest hit; occluder cards are passed where cardU >= their alpha (cardU < 0: never).
  // With `prefetchTexel`, a room hit's texel is prefetched and left unchecked (checkTexel()).
  Hit intersect(RTCScene target, const Vec3& origin, const Vec3& dir, double tNear, double cardU = -1,
                bool prefetchTexel = false) const {
    RTCRayHit rh = makeRayHit(origin, dir, tNear, 3.4e38);
    CardPassContext ctx;
    rtcInitIntersectContext(&ctx.base);
    ctx.u = cardU;
    rtcIntersect1(target, &ctx.base, &rh);
    return hitFrom(rh.ray.tfar, rh.hit, origin, dir, prefetchTexel);
  }
  // The hit Embree found for the ray origin + t dir (tfar: its distance), set up for shading.
  Hit hitFrom(float tfar, const RTCHit& h, const Vec3& origin, const Vec3& dir,
              bool prefetchTexel = false) const {
    Hit hit;
    if (h.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
    hit.t = tfar;
    hit.point = origin + hit.t * dir;
    const unsigned inst = h.instID[0];
    const unsigned id = inst != RTC_INVALID_GEOMETRY_ID ? inst : h.geomID;
    if (id < surfaceCount) {
      hit.kind = Hit::Kind::Room;
      hit.index = int(id);
      const RoomTriangle& tri = roomTriangles[id][h.primID];
      hit.geometricNormal = tri.normalValid ? tri.normal : Vec3(-dir);  // safeNormal()
      hit.shadingNormal = hit.geometricNormal;
      hit.roundOffM = tri.roundOffM;
      const RoomTexture::Texel* t = room.texelAt(hit.point);
      if (!prefetchTexel) hit.texel = RoomTexture::shows(t, hit.index);
      else if ((hit.texelUnchecked = t)) __builtin_prefetch(t);
    } else if (id < surfaceCount + lights.size()) {
      hit.kind = Hit::Kind::Light;
      hit.index = int(id - surfaceCount);
      hit.geometricNormal = lights[size_t(hit.index)].normal;
      hit.shadingNormal = hit.geometricNormal;
    } else {
      hit.kind = Hit::Kind::Object;
      hit.index = int(id - surfaceCount - lights.size());
      hit.prim = h.primID;
      const ObjectData& o = objects[size_t(hit.index)];
      const TriangleMesh& m = *o.mesh;
      const auto& tri = m.triangles[h.primID];
      const Mat4& w = o.worldFromObject;
      auto toWorld = [&](const Vec3f& p) -> Vec3 {
        return w.topLeftCorner<3, 3>() * p.cast<double>() + w.topRightCorner<3, 1>();
      };
      const Vec3 a = toWorld(m.positions[tri[0]]), b = toWorld(m.positions[tri[1]]),
                 c = toWorld(m.positions[tri[2]]);
      Vec3 ng = safeNormal((b - a).cross(c - a), dir);
      hit.roundOffM = triangleRoundOff(a, b, c);
      if (o.mirrored) ng = -ng;
      hit.geometricNormal = ng;
      hit.shadingNormal = ng;
      if (o.shadingNormals) {
        const double u = h.u, v = h.v;
        const Vec3 nObj = (1.0 - u - v) * m.normals[tri[0]].cast<double>() +
                          u * m.normals[tri[1]].cast<double>() + v * m.normals[tri[2]].cast<double>();
        const Vec3 ns = o.normalFromObject * nObj;
        if (ns.squaredNorm() > 0 && ns.allFinite()) {
          hit.shadingNormal = ns.normalized();
          // Vertex normals define outward when the winding disagrees.
          if (hit.shadingNormal.dot(ng) < 0) hit.geometricNormal = -ng;
        }
      }
    }
    return hit;
  }

  // What intersect() needs of a room triangle, worked out once (the same arithmetic as per hit).
  struct RoomTriangle {
    Vec3 normal = Vec3::Zero();  // unit; see normalValid
    double roundOffM = 0;
    bool normalValid = false;  // false: a degenerate triangle, whose normal faces the ray
  };
  std::vector<std::vector<RoomTriangle>> roomTriangles;  // per surface, per triangle
  void buildRoomTriangles() {
    roomTriangles.resize(surfaceCount);
    for (unsigned id = 0; id < surfaceCount; ++id) {
      const TriangleMesh& m = scene.room.surfaces[id].meshWorld;
      roomTriangles[id].resize(m.triangles.size());
      for (size_t k = 0; k < m.triangles.size(); ++k) {
        const auto& tri = m.triangles[k];
        if (tri[0] >= m.positions.size() || tri[1] >= m.positions.size() || tri[2] >= m.positions.size())
          continue;  // never attached (attachTriangles skips it)
        const Vec3 a = m.positions[tri[0]].cast<double>(), b = m.positions[tri[1]].cast<double>(),
                   c = m.positions[tri[2]].cast<double>();
        const Vec3 n = (b - a).cross(c - a);
        const double len = n.norm();
        RoomTriangle& r = roomTriangles[id][k];
        r.normalValid = len > 0 && std::isfinite(len);
        if (r.normalValid) r.normal = n / len;
        r.roundOffM = triangleRoundOff(a, b, c);
      }
    }
  }

  // Sets the texel of a hit that hitFrom() left unchecked.
  static void checkTexel(Hit& hit) {
    if (hit.kind == Hit::Kind::Room) hit.texel = RoomTexture::shows(hit.texelUnchecked, hit.index);
  }

  static Vec3 safeNormal(const Vec3& n, const Vec3& dir) {
    const double len = n.norm();
    return len > 0 && std::isfinite(len) ? Vec3(n / len) : Vec3(-dir);
  }

  // Below this solid angle (sr) a light is sampled by area: the spherical angles lose
  // precision, and a far light has no 1/d^2 trouble anyway.
  static constexpr double kMinSolidAngle = 1e-6;
  // A light whose corners all lie within 1 / kFarLightRatio of its centre's distance from a
  // point (a bounding sphere seen under at most asin(1/kFarLightRatio)) is sampled by area
  // from there: across it 1/d^2 and the cosines vary by a few per cent, so the area pdf is
  // nearly proportional to the solid-angle one, and a point and its pdf cost a tenth of the
  // spherical quad's set-up and inversion. NEE and lightPdf() apply the same test.
  static constexpr double kFarLightRatio = 8.0;
  static bool sampledByArea(const LightData& l, const Vec3& from) {
    return (l.centre - from).squaredNorm() > (kFarLightRatio * kFarLightRatio) * (l.radius * l.radius);
  }
  // The solid-angle pdf of a point onLight that NEE from `from` drew uniformly by area on light
  // l, picked with probability selectProb; 0 when `from` lies behind the light.
  static double areaPdf(const LightData& l, double selectProb, const Vec3& from, const Vec3& onLight) {
    const Vec3 w = onLight - from;
    const double d2 = w.squaredNorm();
    const double cosL = -l.normal.dot(w) / std::sqrt(d2);
    if (!(cosL > 0)) return 0;
    return selectProb * d2 / (l.area * cosL);
  }

  // NEE sources: area lights 0 .. lights.size() - 1, then the emissive objects.
  size_t sourceCount() const { return lights.size() + meshLights.size(); }

  // How much NEE from point p (facing normal n) favours source j: power over squared distance
  // (capped next to the light), 0 when p is behind an area light or the source lies wholly
  // below p's tangent plane (it cannot contribute there: such directions are rejected).
  double selectionWeight(size_t j, const Vec3& p, const Vec3& n) const {
    if (j >= lights.size()) return meshSelectionWeight(meshLights[j - lights.size()], p, n);
    const LightData& l = lights[j];
    if (!(l.power > 0) || (p - l.emitter[0]).dot(l.normal) <= 0) return 0;
    bool above = n.squaredNorm() == 0;  // a zero normal: a two-sided (transmitting) BSDF
    for (const Vec3& c : l.emitter) above = above || (c - p).dot(n) > 0;
    if (!above) return 0;
    return l.power / std::max((l.centre - p).squaredNorm(), 0.25 * l.area);
  }
  static double meshSelectionWeight(const MeshLightData& m, const Vec3& p, const Vec3& n) {
    if (!(m.power > 0)) return 0;
    bool above = n.squaredNorm() == 0;
    for (const Vec3& c : m.boxCorners) above = above || (c - p).dot(n) > 0;
    if (!above) return 0;
    return m.power / std::max((m.centre - p).squaredNorm(), 0.25 * m.area);
  }
  double selectionTotal(const Vec3& p, const Vec3& n) const {
    double total = 0;
    for (size_t j = 0; j < sourceCount(); ++j) total += selectionWeight(j, p, n);
    return total;
  }
  // The power table (TracerOptions::LightSelection::Power): running sums of the sources'
  // power, built once per scene (again when an emissive object moves).
  bool powerSelection = false;
  std::vector<double> powerCdf;  // powerCdf[j] = power of sources 0..j; back() = total
  size_t lastPoweredSource = 0;  // the last source with power > 0 (round-off at u near 1)
  double sourcePower(size_t j) const {
    return j < lights.size() ? lights[j].power : meshLights[j - lights.size()].power;
  }
  void buildLightSelection() {
    powerCdf.assign(sourceCount(), 0.0);
    double run = 0;
    for (size_t j = 0; j < sourceCount(); ++j) {
      const double w = sourcePower(j);
      if (w > 0) run += w, lastPoweredSource = j;
      powerCdf[j] = run;
    }
    using Sel = TracerOptions::LightSelection;
    const Sel sel = options.lightSelection;
    powerSelection =
        sel == Sel::Power ||
        (sel == Sel::Auto && sourceCount() > size_t(std::max(0, options.spatialSelectionMax)));
  }
  // The probability that NEE from p (normal n) picks source j, as pickLight() draws it.
  double selectionProbability(size_t j, const Vec3& p, const Vec3& n) const {
    if (powerSelection)
      return powerCdf.empty() || !(powerCdf.back() > 0) ? 0.0 : sourcePower(j) / powerCdf.back();
    const double total = selectionTotal(p, n);
    return total > 0 ? selectionWeight(j, p, n) / total : 0.0;
  }
  // The source NEE picks with u in [0, 1); sourceCount() when none can contribute.
  size_t pickLight(const Vec3& p, const Vec3& n, double u, double* prob) const {
    if (powerSelection) {
      const double total = powerCdf.empty() ? 0.0 : powerCdf.back();
      if (!(total > 0)) return sourceCount();
      // The first source whose running sum exceeds u * total (sources of no power have an
      // empty interval and are never picked).
      const auto it = std::upper_bound(powerCdf.begin(), powerCdf.end(), u * total);
      const size_t j = it == powerCdf.end() ? lastPoweredSource : size_t(it - powerCdf.begin());
      *prob = sourcePower(j) / total;
      return j;
    }
    if (sourceCount() <= kBufferedWeights) return pickSpatialBuffered(p, n, u, prob);
    const double total = selectionTotal(p, n);
    if (!(total > 0)) return sourceCount();
    const double target = u * total;
    double run = 0;
    size_t last = sourceCount();
    for (size_t j = 0; j < sourceCount(); ++j) {
      const double w = selectionWeight(j, p, n);
      if (!(w > 0)) continue;
      last = j;
      run += w;
      if (target < run) {
        *prob = w / total;
        return j;
      }
    }
    *prob = selectionWeight(last, p, n) / total;  // round-off at u close to 1
    return last;
  }

  // pickLight()'s spatial rule for a few sources: every weight computed once (the same sums in
  // the same order, so the same pick and probability as the unbuffered loop).
  static constexpr size_t kBufferedWeights = 256;
  size_t pickSpatialBuffered(const Vec3& p, const Vec3& n, double u, double* prob) const {
    std::array<double, kBufferedWeights> weight;
    double total = 0;
    for (size_t j = 0; j < sourceCount(); ++j) total += (weight[j] = selectionWeight(j, p, n));
    if (!(total > 0)) return sourceCount();
    const double target = u * total;
    double run = 0;
    size_t last = sourceCount();
    for (size_t j = 0; j < sourceCount(); ++j) {
      if (!(weight[j] > 0)) continue;
      last = j;
      run += weight[j];
      if (target < run) {
        *prob = weight[j] / total;
        return j;
      }
    }
    *prob = weight[last] / total;  // round-off at u close to 1
    return last;
  }

  // Refreshes the world triangles of object i's mesh light (if it is one).
  void updateMeshLight(size_t i);  // every light of object i
  void updateMeshLightData(MeshLightData& m);
  // Makes `m` (its emission sanitised in place), the material of object i's part `part` (-1:
  // the whole object), a mesh light when it is emissive and bright; returns its index into
  // meshLights, or -1.
  int addMeshLight(const ObjectData& o, size_t i, Material& m, int part) {
    if (m.kind != Material::Kind::Emissive) return -1;
    const Vec3 e = m.emission;
    m.emission = e.allFinite() ? Vec3(e.cwiseMax(0.0)) : Vec3(Vec3::Zero());
    if (!o.instance || !(m.emission.maxCoeff() > 0)) return -1;
    meshLights.emplace_back();
    meshLights.back().object = i;
    meshLights.back().part = part;
    meshLights.back().radiance = m.emission;
    return int(meshLights.size()) - 1;
  }
  // A point on mesh light k uniform by area (u picks the triangle and is reused inside it);
  // its unit geometric normal into *normal.
  Vec3 sampleMeshLight(const MeshLightData& m, double u, double v, Vec3* normal) const;
  // Solid-angle pdf with which NEE from `from` picks the point `onLight` (geometric normal
  // lightNormal) on mesh light k; NEE and the MIS weight of BSDF hits both use it.
  double meshLightPdf(size_t k, const Vec3& from, const Vec3& fromNormal, const Vec3& onLight,
                      const Vec3& lightNormal) const {
    const MeshLightData& m = meshLights[k];
    const double selectProb = selectionProbability(lights.size() + k, from, fromNormal);
    const Vec3 w = onLight - from;
    const double d2 = w.squaredNorm();
    const double cosL = std::abs(lightNormal.dot(w)) / std::sqrt(d2);
    if (!(selectProb > 0) || !(cosL > 0) || !(m.area > 0)) return 0;
    return selectProb * d2 / (m.area * cosL);
  }

  // Solid-angle pdf with which NEE from `from` (facing normal fromNormal) picks the direction
  // to `onLight` on light i. NEE and the MIS weight of BSDF hits both use it.
  double lightPdf(int i, const Vec3& from, const Vec3& fromNormal, const Vec3& onLight) const {
    const LightData& l = lights[size_t(i)];
    if (!(l.area > 0)) return 0;
    const double selectProb = selectionProbability(size_t(i), from, fromNormal);
    if (!(selectProb > 0)) return 0;
    if (sampledByArea(l, from)) return areaPdf(l, selectProb, from, onLight);
    if (l.rectangle) {
      const SphericalRect sr(l.corner, l.edgeX, l.edgeY, from);
      if (sr.solidAngle > kMinSolidAngle) return selectProb / sr.solidAngle;
    } else {
      const SphericalQuad sq(l.emitter, from);
      if (sq.solidAngle > kMinSolidAngle) return selectProb / sq.solidAngle;
    }
    return areaPdf(l, selectProb, from, onLight);
  }

  // The material the user gave room surface `id` (Glossy or Mirror), or null: Lambertian.
  const Material* roomMaterial(int id) const {
    if (id < 0 || size_t(id) >= scene.roomMaterials.size() || !scene.roomMaterials[size_t(id)])
      return nullptr;
    const Material& m = *scene.roomMaterials[size_t(id)];
    return m.kind == Material::Kind::Glossy || m.kind == Material::Kind::Mirror ? &m : nullptr;
  }
  // A marked room surface's BSDF; a glossy one keeps the projected albedo already in `bsdf`.
  static void setRoomBsdf(const Material& m, SurfaceBsdf& bsdf) {
    bsdf.kind = m.kind;
    if (m.kind == Material::Kind::Mirror) bsdf.albedo = m.albedo.cwiseMax(0.0).cwiseMin(1.0);
    setLobeParameters(m, bsdf);
  }
  static void setLobeParameters(const Material& m, SurfaceBsdf& bsdf) {
    bsdf.alpha = std::max(1e-4, m.roughness * m.roughness);
    bsdf.ior = m.ior > 1e-3 && std::isfinite(m.ior) ? m.ior : 1.5;
  }

  Vec3 clampIndirect(const Vec3& c, bool indirect) const {
    if (!indirect || options.clampRadiance <= 0) return c;
    const double m = maxComponent(c);
    return m > options.clampRadiance ? Vec3(c * (options.clampRadiance / m)) : c;
  }

  struct Sums {
    Vec3 with = Vec3::Zero();
    Vec3 without = Vec3::Zero();
    RayCounters counters;
  };

  static int64_t clockNs() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
  }
  // Nanoseconds on the steady clock when TracerOptions::timeRays, else 0 (no clock read).
  int64_t rayClockNs() const { return options.timeRays ? clockNs() : 0; }
  // The same around next-event estimation: also when only TracerOptions::timeNee asks.
  int64_t neeClockNs() const { return options.timeRays || options.timeNee ? clockNs() : 0; }
  // Appends a ray to TracerOptions::rayLog (benchmarks only).
  void logRay(LoggedRay::Type type, RTCScene s, const Vec3& o, const Vec3& dir, double tNear,
              double tFar) const {
    LoggedRay r;
    r.type = type;
    r.target = s == withScene      ? LoggedRay::Target::With
               : s == withoutScene ? LoggedRay::Target::Without
               : s == sunWithScene ? LoggedRay::Target::SunWith
                                   : LoggedRay::Target::SunWithout;
    const RTCRayHit rh = makeRayHit(o, dir, tNear, tFar);
    r.org[0] = rh.ray.org_x, r.org[1] = rh.ray.org_y, r.org[2] = rh.ray.org_z;
    r.dir[0] = rh.ray.dir_x, r.dir[1] = rh.ray.dir_y, r.dir[2] = rh.ray.dir_z;
    r.tnear = rh.ray.tnear, r.tfar = rh.ray.tfar;
    options.rayLog->rays.push_back(r);
  }
  // A counted (and, if asked, timed) shadow ray: true when (0, tFar) is blocked in `s`.
  bool blocked(Sums& out, RTCScene s, const Vec3& o, const Vec3& dir, double tFar) const {
    if (options.rayLog) logRay(LoggedRay::Type::Shadow, s, o, dir, 0, tFar);
    const int64_t t0 = rayClockNs();
    const bool hit = occluded(s, o, dir, 0, tFar);
    ++out.counters.shadowRays;
    out.counters.shadowNs += rayClockNs() - t0;
    return hit;
  }
  // Adds light c reaching o from direction dir (up to tFar) to the sums of `mode`: with the
  // paths still shared, a ray the objects block is retried without them (only then do the
  // two sums differ).
  void addUnlessBlocked(Mode mode, RTCScene with, RTCScene without, const Vec3& o, const Vec3& dir,
                        double tFar, const Vec3& c, Sums& out) const {
    if (mode == Mode::Shared) {
      if (!blocked(out, with, o, dir, tFar)) out.with += c, out.without += c;
      else if (!blocked(out, without, o, dir, tFar)) out.without += c;  // only an object blocks it
    } else if (!blocked(out, mode == Mode::WithOnly ? with : without, o, dir, tFar)) {
      (mode == Mode::WithOnly ? out.with : out.without) += c;
    }
  }

  // Where a path stands: the next ray and what the vertices so far left it with.
  struct PathState {
    Vec3 origin, dir;
    double tNear = 0;
    Vec3 throughput = Vec3::Ones();
    int depth = 0;                   // index of the vertex the ray will find (0: the camera ray's hit)
    int glassVertices = 0;           // smooth glass vertices passed (TracerOptions::maxGlassDepth)
    bool lastSpecular = true;        // camera rays count as specular: lights seen directly count
    double lastPdf = 0;              // solid-angle pdf of the last non-specular bounce (MIS)
    Vec3 lastPoint = Vec3::Zero();   // the vertex of that bounce (MIS: the light pdf seen from it)
    Vec3 lastNormal = Vec3::Zero();  // its geometric normal on the side the path left from; zero
                                     // after a transmitting BSDF (light selection saw every side)
    bool noPhotoAtFirstHit = false;  // the first hit is path traced (addObjectsEffect)
    // The caustic map's part of the path: 1 when the last non-glass vertex was Lambertian and
    // took the map's light, 2 when smooth glass vertices alone followed it (an area light met
    // now is the map's light already), 0 otherwise.
    uint8_t causticChain = 0;
  };

  struct PixelSums;
  struct FirstVertex;
  void startPixel(const DifferentialBuffers& buffers, int x, int y, PixelSums& p) const;
  // The buffers' pixel size in the camera's pixels (a preview's buffers are smaller).
  struct PixelScale {
    double x, y;
  };
  PixelScale pixelScale(const DifferentialBuffers& buffers) const;
  Vec2 cameraPixel(int x, int y, const PixelScale& scale, const SampleRng& rng) const;
  Vec2 cameraPixelAt(int x, int y, const PixelScale& scale, const std::array<double, 2>& jitter) const;
  Vec3 cameraDirection(int x, int y, const PixelScale& scale, const SampleRng& rng) const;
  PathState cameraRay(const Vec3& dir) const;
  void addSample(PixelSums& p, bool wantGuide, const PathState& st, const SampleRng& rng,
                 const Hit* firstHit, const FirstVertex* first, RayCounters& tileCounters) const;
  void storePixel(DifferentialBuffers& buffers, int x, int y, int count, const PixelSums& p) const;
  void renderPixel(DifferentialBuffers& buffers, int x, int y, int firstSample, int count, uint32_t seed,
                   RayCounters& tileCounters) const;
  // Camera rays go in packets of kPacket pixels of a row, unless occluder cards are present
  // (their filter reads one pass number per intersect context, not one per ray).
  static constexpr int kPacket = 8;
  bool packetsSupported = false;  // the Embree build and the CPU run rtcIntersect8 natively (AVX)
  bool cameraPackets() const { return packetsSupported && !hasCards; }
  void renderPacket(DifferentialBuffers& buffers, int x0, int y, int n, const int* first,
                    const int* count, uint32_t seed, RayCounters& tileCounters) const;
  void castCameraPacket(int n, const Vec3& eye, const Vec3* dirs, Hit* hits,
                        RayCounters& tileCounters) const;
  void prefetchRun(const DifferentialBuffers& buffers, int x, int y, int n) const;
  template <class RenderRun>
  bool renderPixels(const DifferentialBuffers& buffers, int x0, int y0, int x1, int y1,
                    const CancelToken* cancel, RenderRun&& renderRun) const;
  mutable std::mutex arenaMutex;
  mutable std::shared_ptr<tbb::task_arena> arena;
  mutable int arenaThreads = -1;
  std::shared_ptr<tbb::task_arena> arenaFor(int threads) const;
  template <class RenderTile>
  bool forEachTile(int width, int height, int threads, const CancelToken* cancel,
                   RenderTile&& renderTile) const;

  // What one sample's camera path tells about its pixel besides radiance: whether its first hit
  // is an object (the mask), and, when wanted, the denoiser's guide: the first surface along the
  // camera's specular chain (smooth mirror and glass, near-smooth metal and frosted glass) that
  // is not specular, i.e. what the pixel shows.
  struct PrimaryRecord {
    bool objectFirst = false;
    bool wantGuide = false;     // DifferentialBuffers::hasGuides()
    bool guideOpen = true;      // still on the camera's specular chain
    Vec3 chain = Vec3::Ones();  // product of the specular reflectances met so far
    double length = 0;          // path length so far, metres
    Vec3 albedo = Vec3::Ones(), normal = Vec3::Zero(), point = Vec3::Zero();
    double distance = 1e6;  // no hit: far away
    bool specular = false;  // the chain met a specular surface before the guide's
  };
  struct GuideSums;
  // firstHit: the camera ray's hit in withScene, cast already (in a packet), or null.
  // first: that hit's vertex and NEE pick, worked out already (firstVertices), or null.
  void tracePath(Mode mode, PathState st, const SampleRng& rng, Sums& out, PrimaryRecord* rec,
                 const Hit* firstHit = nullptr, const FirstVertex* first = nullptr) const;
  void recordGuide(const PathState& st, const Hit& hit, PrimaryRecord& rec) const;
  bool guideReflectance(const Hit& hit, Vec3* albedo) const;
  void addObjectsEffect(PathState st, const SampleRng& rng, Sums& out) const;

  // tracePath's steps.
  // A surface vertex as the steps after its hit see it: the normals turned to the side the
  // path arrived from, the ray offset, the vertex's first random dimension and its four pairs
  // of random numbers, drawn at once (SampleRng::get2x4). Left unset on construction (a camera
  // packet keeps eight, FirstVertex): vertexFrom() sets all but u, vertexAt() all.
  struct Vertex {
    Vec3 point, wo, ngFacing, ns;
    bool frontSide;  // the path arrived on the side the geometric normal points to
    double eps;
    uint32_t dim;
    std::array<std::array<double, 2>, 4> u;  // pairs dim / 2 + 0 .. 3: the roles below
    const std::array<double, 2>& lightPoint() const { return u[0]; }   // NEE's point on the source
    const std::array<double, 2>& direction() const { return u[1]; }    // the BSDF's direction
    const std::array<double, 2>& pickAndLobe() const { return u[2]; }  // light pick, BSDF lobe
    double roulette() const { return u[3][0]; }                        // (dim + 7: occluder cards)
  };
  // A non-specular BSDF in its local frame at a vertex.
  struct Lobe {
    // The frame around `normal` and wo in it, made in place (Frame's three-argument
    // constructor: no store-forwarding stall on its axes).
    Lobe(const SurfaceBsdf& b, const Vec3& normal, const Vec3& wo, const Vec3& select)
        : bsdf(b), frame(normal, wo, &woLocal), selectNormal(select) {}
    const SurfaceBsdf& bsdf;
    Vec3 woLocal;  // (before `frame`, which sets it)
    Frame frame;
    Vec3 selectNormal;  // light selection's normal; zero after a transmitting BSDF (every side)
  };
  // A point NEE picked on a source.
  struct SourcePoint {
    Vec3 y, normal, radiance;
    double solidAngle = 0;  // > 0: sampled by solid angle (the same rule as lightPdf)
    bool mesh = false;      // on an emissive object
  };
  // NEE's source and the point on it (pickSource); li == sourceCount(): none.
  struct SourcePick {
    size_t li = 0;
    double selectProb = 0;
    SourcePoint p;
  };
  // A camera packet's lane worked out ahead of its path (firstVertices): the first hit's vertex
  // and, for a BSDF that does not transmit, NEE's source and point there.
  struct FirstVertex {
    bool set = false;     // v holds vertexAt() of the first hit
    bool picked = false;  // pick holds pickSource() for a reflecting BSDF at v
    Vertex v;
    SourcePick pick;
  };
  static void addTo(Mode mode, Sums& out, const Vec3& c) {
    if (mode != Mode::WithoutOnly) out.with += c;
    if (mode != Mode::WithOnly) out.without += c;
  }
  Hit castPathRay(Mode mode, const PathState& st, const SampleRng& rng, Sums& out,
                  bool prefetchTexel = false) const;
  void addLightSeen(Mode mode, const PathState& st, const Hit& hit, Sums& out) const;
  bool endsOnPhoto(Mode mode, PathState& st, const Hit& hit, const SampleRng& rng, Sums& out) const;
  bool surfaceBsdf(Mode mode, const PathState& st, const Hit& hit, Sums& out, SurfaceBsdf* bsdf) const;
  // Out of line: inlined, its hashes swell tracePath, which camera-only frames run too.
  [[gnu::noinline]] Vertex vertexAt(const PathState& st, const Hit& hit, const SampleRng& rng) const;
  static Vertex vertexFrom(const PathState& st, const Hit& hit);
  bool scatterNonSpecular(Mode mode, PathState& st, const Vertex& v, const SurfaceBsdf& bsdf,
                          const SampleRng& rng, Sums& out, Hit* next, const FirstVertex* first) const;
  bool bounceFrom(PathState& st, const Vertex& v, const Lobe& lobe, bool nee) const;
  SourcePoint sampleSource(size_t li, const Vec3& from, const std::array<double, 2>& u) const;
  static double sampleBySolidAngle(const LightData& l, const Vec3& from, const std::array<double, 2>& u,
                                   Vec3* y);
  SourcePick pickSource(const Vertex& v, const Lobe& lobe) const;
  SourcePick chooseSource(const Vertex& v, const Vec3& selectNormal) const;
  void finishAreaLightPoint(const LightData& l, const std::array<double, 2>& u, SourcePoint& p) const;
  // A camera packet's lanes in AVX2 (simd_lanes.h: the sampler's numbers, the near lights'
  // points): set by the constructor when the CPU runs AVX2 (simdLanesEnabled()).
  bool simdLanes = false;
  bool verticesAhead() const { return simdLanes && options.maxDepth > 0; }
  // Sample k of a camera packet (packetLanes).
  struct PacketLanes {
    int m = 0;                       // lanes
    std::array<int, kPacket> pixel;  // lane j: pixel x0 + pixel[j] of the packet's row
    std::array<SampleRng, kPacket> rngs;
    std::array<double, kPacket> px, py;
    SamplerLanes numbers;  // pairs 0 (the jitter) and, ahead, 1 .. 4 (the first vertex's)
  };
  void packetLanes(int x0, int y, int n, const int* first, const int* count, int k, uint32_t seed,
                   const PixelScale& scale, PacketLanes& p) const;
  void firstVertices(const PacketLanes& lanes, const Vec3* dirs, const Hit* hits, FirstVertex* out,
                     RayCounters& tileCounters) const;
  bool nearQuad(const SourcePick& pick, const Vec3& from) const;
  void pickNearQuads(int n, FirstVertex* const* lanes) const;
  void addSourceSample(Mode mode, const PathState& st, const Vertex& v, const Lobe& lobe,
                       const SourcePick& pick, Sums& out) const;
  void addSunLight(Mode mode, const PathState& st, const Vertex& v, const Lobe& lobe, Sums& out) const;
  void addSunPatchSample(Mode mode, const PathState& st, const Vertex& v, const Lobe& lobe,
                         const SampleRng& rng, Sums& out) const;
  double sunPatchWeight(const PathState& st, const Hit& hit) const;
  // Whether a non-specular vertex at `depth` makes NEE toward the sunlit patches: at the camera's
  // first hit, whose bounce lands unclamped; deeper, only with the clamp of indirect light off
  // (with it on, a landing two or more surfaces from the camera is clamped anyway, and the extra
  // shadow ray at every vertex doubled d4's render time for little).
  bool sunPatchNeeAt(int depth) const {
    return !sunPatches.empty() && (depth == 0 || options.clampRadiance <= 0);
  }
  void buildSunPatches();
  bool reflectMirror(PathState& st, const Vertex& v, const SurfaceBsdf& bsdf) const;
  bool scatterGlass(PathState& st, const Vertex& v, const SurfaceBsdf& bsdf) const;
  bool splitGlass(Mode mode, PathState& st, const Vertex& v, const SurfaceBsdf& bsdf,
                  const SampleRng& rng, Sums& out) const;
  bool survivesRoulette(PathState& st, const Vertex& v) const;

  // The caustic photon pass (TracerOptions::causticPhotons).
  struct GlassTarget {
    size_t object = 0;
    Vec3 centre = Vec3::Zero();
    double radius = 0;
  };
  struct PhotonBatch {
    size_t target = 0;  // into the glass targets
    size_t source = 0;  // area light, then suns
    uint32_t first = 0, count = 0, perPair = 1;
  };
  std::vector<GlassTarget> glassTargets() const;
  void buildCaustics();
  std::vector<CausticPhoton> emitPhotons(const GlassTarget& target, const PhotonBatch& batch) const;
  bool photonFromLight(const LightData& l, const GlassTarget& target, const SampleRng& rng,
                       uint32_t count, Vec3* origin, Vec3* dir, Vec3* flux) const;
  bool photonFromSun(const SunData& sun, const GlassTarget& target, const SampleRng& rng, uint32_t count,
                     Vec3* origin, Vec3* dir, Vec3* flux) const;
  void tracePhoton(const GlassTarget& target, Vec3 origin, Vec3 dir, const Vec3& flux,
                   const SampleRng& rng, std::vector<CausticPhoton>& out) const;
  Material::Kind photonSurface(const Hit& hit, double* ior) const;
  void addCausticLight(Mode mode, PathState& st, const Vertex& v, const SurfaceBsdf& bsdf,
                       Sums& out) const;
};

void PathTracer::Impl::updateMeshLight(size_t i) {
  const ObjectData& o = objects[i];
  if (o.meshLight >= 0) updateMeshLightData(meshLights[size_t(o.meshLight)]);
  for (int k : o.partMeshLight)
    if (k >= 0) updateMeshLightData(meshLights[size_t(k)]);
}

void PathTracer::Impl::updateMeshLightData(MeshLightData& m) {
  const ObjectData& o = objects[m.object];
  const Mat3 linear = o.worldFromObject.topLeftCorner<3, 3>();
  const Vec3 shift = o.worldFromObject.topRightCorner<3, 1>();
  m.corner.clear(), m.edge1.clear(), m.edge2.clear(), m.cumulativeArea.clear();
  m.area = 0;
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300), weighted = Vec3::Zero();
  const TriangleMesh& mesh = *o.mesh;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    if (m.part >= 0 && o.partOf(unsigned(t)) != m.part) continue;
    if (tri[0] >= mesh.positions.size() || tri[1] >= mesh.positions.size() ||
        tri[2] >= mesh.positions.size())
      continue;
    const Vec3 a = linear * mesh.positions[tri[0]].cast<double>() + shift;
    const Vec3 b = linear * mesh.positions[tri[1]].cast<double>() + shift;
    const Vec3 c = linear * mesh.positions[tri[2]].cast<double>() + shift;
    const double area = 0.5 * (b - a).cross(c - a).norm();
    if (!(area > 0) || !std::isfinite(area)) continue;  // needles and NaNs are never sampled
    m.corner.push_back(a), m.edge1.push_back(b - a), m.edge2.push_back(c - a);
    m.area += area;
    m.cumulativeArea.push_back(m.area);
    weighted += area * (a + b + c) / 3.0;
    for (const Vec3& p : {a, b, c}) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  }
  const double power = m.area * meanComponent(m.radiance);
  m.power = m.area > 0 && std::isfinite(power) ? power : 0.0;
  if (!(m.power > 0)) return;
  m.centre = weighted / m.area;
  for (int k = 0; k < 8; ++k)
    m.boxCorners[size_t(k)] =
        Vec3(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
}

Vec3 PathTracer::Impl::sampleMeshLight(const MeshLightData& m, double u, double v, Vec3* normal) const {
  const double target = u * m.area;
  const size_t k =
      std::min(size_t(std::upper_bound(m.cumulativeArea.begin(), m.cumulativeArea.end(), target) -
                      m.cumulativeArea.begin()),
               m.cumulativeArea.size() - 1);
  const double before = k > 0 ? m.cumulativeArea[k - 1] : 0.0;
  const double span = m.cumulativeArea[k] - before;
  const double uu = std::clamp(span > 0 ? (target - before) / span : 0.0, 0.0, 1.0);
  const double su = std::sqrt(uu);
  *normal = m.edge1[k].cross(m.edge2[k]).normalized();
  return m.corner[k] + su * (1.0 - v) * m.edge1[k] + su * v * m.edge2[k];
}

// A path as named steps: cast the ray; part at an object; end at an emitter or on the photo;
// otherwise the surface's BSDF, next-event estimation, and the next direction. A non-specular
// vertex casts the next ray before its NEE (scatterNonSpecular), so the ray's hit waits here.
void PathTracer::Impl::tracePath(Mode mode, PathState st, const SampleRng& rng, Sums& out,
                                 PrimaryRecord* rec, const Hit* firstHit,
                                 const FirstVertex* first) const {
  // This vertex's hit, cast here or by the last vertex (castAhead), and the next one's, which a
  // non-specular vertex casts ahead: the two take turns, so a hit is never copied (its copy, a
  // tenth of tracePath's samples, waited on the loads of the record just written).
  std::array<Hit, 2> cast;
  int at = 0;
  bool castAhead = false;
  if (!firstHit) first = nullptr;
  for (;; ++st.depth, firstHit = nullptr, first = nullptr) {
    if (!firstHit && !castAhead) cast[size_t(at)] = castPathRay(mode, st, rng, out);
    if (std::exchange(castAhead, false)) checkTexel(cast[size_t(at)]);
    const Hit& hit = firstHit ? *firstHit : cast[size_t(at)];
    if (rec && rec->wantGuide && rec->guideOpen && mode != Mode::WithoutOnly) recordGuide(st, hit, *rec);
    if (mode == Mode::Shared && hit.kind == Hit::Kind::Object) {
      if (st.depth == 0 && rec) rec->objectFirst = true;
      // The paths part here: the same ray goes on through the room alone, from the same state
      // and with the same depth-indexed random dimensions; this path goes on with the objects.
      tracePath(Mode::WithoutOnly, st, rng, out, nullptr);
      mode = Mode::WithOnly;
    }
    if (hit.kind == Hit::Kind::None) return;
    if (hit.kind == Hit::Kind::Light) return addLightSeen(mode, st, hit, out);
    if (endsOnPhoto(mode, st, hit, rng, out)) return;
    SurfaceBsdf bsdf;
    if (!surfaceBsdf(mode, st, hit, out, &bsdf)) return;  // a glowing object ends the path
    const bool glass = bsdf.kind == Material::Kind::Glass;
    if (glass ? st.glassVertices >= options.maxGlassDepth
              : st.depth - st.glassVertices >= options.maxDepth)
      return;
    st.glassVertices += glass ? 1 : 0;
    st.causticChain = glass && st.causticChain != 0 ? 2 : 0;
    const Vertex v = first && first->set ? first->v : vertexAt(st, hit, rng);
    if (bsdf.kind == Material::Kind::RoughGlass) bsdf.eta = v.frontSide ? bsdf.ior : 1.0 / bsdf.ior;
    if (bsdf.nonSpecular()) {
      if (!scatterNonSpecular(mode, st, v, bsdf, rng, out, &cast[size_t(1 - at)], first)) return;
      at = 1 - at;
      castAhead = true;
      continue;
    }
    const bool split = glass && st.depth == 0 && options.splitGlassAtCamera;
    const bool goesOn = bsdf.kind == Material::Kind::Mirror ? reflectMirror(st, v, bsdf)
                        : split                             ? splitGlass(mode, st, v, bsdf, rng, out)
                                                            : scatterGlass(st, v, bsdf);
    if (!goesOn) return;
    st.tNear = 0;
    if (!survivesRoulette(st, v)) return;
  }
}

Hit PathTracer::Impl::castPathRay(Mode mode, const PathState& st, const SampleRng& rng, Sums& out,
                                  bool prefetchTexel) const {
  RTCScene s = mode == Mode::WithoutOnly ? withoutScene : withScene;  // (a pointer)
  const uint32_t cardDim = kFirstVertexDim + uint32_t(st.depth) * kDimsPerVertex + 7;
  if (options.rayLog)
    logRay(st.depth == 0 ? LoggedRay::Type::Camera : LoggedRay::Type::Bounce, s, st.origin, st.dir,
           st.tNear, 3.4e38);
  const int64_t t0 = rayClockNs();
  Hit hit = intersect(s, st.origin, st.dir, st.tNear, hasCards ? rng.get(cardDim) : -1.0, prefetchTexel);
  const int64_t spentNs = rayClockNs() - t0;
  if (st.depth == 0) ++out.counters.cameraRays, out.counters.cameraNs += spentNs;
  else ++out.counters.bounceRays, out.counters.bounceNs += spentNs;
  return hit;
}

// The camera rays eye + t dirs[k], k < n <= kPacket, in one rtcIntersect8 into withScene, their
// hits set up as intersect() sets them up; counted (and timed, if asked) as camera rays.
void PathTracer::Impl::castCameraPacket(int n, const Vec3& eye, const Vec3* dirs, Hit* hits,
                                        RayCounters& tileCounters) const {
  alignas(32) RTCRayHit8 rh;
  alignas(32) int valid[kPacket];
  for (int k = 0; k < kPacket; ++k) {
    valid[k] = k < n ? -1 : 0;
    const RTCRay one = makeRay(eye, dirs[std::min(k, n - 1)], 0, 3.4e38);
    rh.ray.org_x[k] = one.org_x, rh.ray.org_y[k] = one.org_y, rh.ray.org_z[k] = one.org_z;
    rh.ray.dir_x[k] = one.dir_x, rh.ray.dir_y[k] = one.dir_y, rh.ray.dir_z[k] = one.dir_z;
    rh.ray.tnear[k] = one.tnear, rh.ray.tfar[k] = one.tfar;
    rh.ray.time[k] = 0, rh.ray.mask[k] = one.mask, rh.ray.id[k] = unsigned(k), rh.ray.flags[k] = 0;
    rh.hit.geomID[k] = rh.hit.primID[k] = RTC_INVALID_GEOMETRY_ID;
    for (unsigned l = 0; l < RTC_MAX_INSTANCE_LEVEL_COUNT; ++l)
      rh.hit.instID[l][k] = RTC_INVALID_GEOMETRY_ID;
    if (options.rayLog && k < n) logRay(LoggedRay::Type::Camera, withScene, eye, dirs[k], 0, 3.4e38);
  }
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  const int64_t t0 = rayClockNs();
  rtcIntersect8(valid, withScene, &ctx, &rh);
  tileCounters.cameraNs += rayClockNs() - t0;
  tileCounters.cameraRays += uint64_t(n);
  for (int k = 0; k < n; ++k) {
    RTCHit h;
    h.geomID = rh.hit.geomID[k], h.primID = rh.hit.primID[k], h.instID[0] = rh.hit.instID[0][k];
    h.u = rh.hit.u[k], h.v = rh.hit.v[k];
    hits[k] = hitFrom(rh.ray.tfar[k], h, eye, dirs[k]);
  }
}

// An area light the path meets: its radiance, weighted by MIS against NEE after a
// non-specular bounce.
void PathTracer::Impl::addLightSeen(Mode mode, const PathState& st, const Hit& hit, Sums& out) const {
  const LightData& l = lights[size_t(hit.index)];
  const double cosL = -l.normal.dot(st.dir);
  if (cosL <= 0) return;             // the black back of the light
  if (st.causticChain == 2) return;  // the caustic map brought this light to the last vertex
  const double w = st.lastSpecular ? 1.0
                                   : powerHeuristic(st.lastPdf, lightPdf(hit.index, st.lastPoint,
                                                                         st.lastNormal, hit.point));
  if (w > 0)
    addTo(mode, out, clampIndirect(Vec3(st.throughput.cwiseProduct(l.radiance) * w), st.depth >= 2));
}

// The guide of a path vertex on the camera's specular chain (PrimaryRecord): a specular
// surface multiplies the chain's reflectance and leaves the chain open (its own values stay as
// the fallback should the path end there); anything else closes it.
void PathTracer::Impl::recordGuide(const PathState& st, const Hit& hit, PrimaryRecord& rec) const {
  if (hit.kind == Hit::Kind::None) {
    rec.guideOpen = false;
    if (st.depth == 0) return;  // nothing seen: the defaults (albedo 1, far away)
    rec.albedo = rec.chain;     // a reflection of nothing: keep the specular surface's place
    return;
  }
  rec.length += (hit.point - st.origin).norm();
  Vec3 reflectance = Vec3::Ones();
  const bool specular = guideReflectance(hit, &reflectance);
  const Vec3 n = hit.shadingNormal.dot(st.dir) > 0 ? Vec3(-hit.shadingNormal) : hit.shadingNormal;
  const Vec3 albedo = rec.chain.cwiseProduct(reflectance);
  if (albedo.allFinite() && n.allFinite() && hit.point.allFinite() && std::isfinite(rec.length)) {
    rec.albedo = albedo.cwiseMax(0.0).cwiseMin(1.0);
    rec.normal = n;
    rec.point = hit.point;
    rec.distance = std::max(rec.length, 1e-6);
  }
  if (specular) rec.chain = albedo;
  rec.specular = rec.specular || specular;
  rec.guideOpen = specular && st.depth < options.maxDepth;
}

// The reflectance the denoiser divides by at a hit (the projected photo albedo on the room, a
// material's colour; 1 for glass, lights and emitters); true when the surface is specular
// (smooth, or rough below kGuideSpecularRoughness): the pixel then shows what lies beyond it.
bool PathTracer::Impl::guideReflectance(const Hit& hit, Vec3* albedo) const {
  constexpr double kGuideSpecularRoughness = 0.1;
  using K = Material::Kind;
  if (hit.kind == Hit::Kind::Room) {
    const Material* m = roomMaterial(hit.index);  // glossy keeps the projected albedo
    const bool mirror = m && m->kind == K::Mirror;
    *albedo = mirror ? m->albedo : room.albedo(hit.index, hit.texel);
    return mirror;
  }
  if (hit.kind != Hit::Kind::Object) return false;
  const Material& m = objects[size_t(hit.index)].materialOf(hit.prim);
  const bool transparent = m.kind == K::Glass || m.kind == K::RoughGlass || m.kind == K::Emissive;
  if (!transparent) *albedo = m.albedo;
  return m.kind == K::Mirror || m.kind == K::Glass ||
         ((m.kind == K::Conductor || m.kind == K::RoughGlass) && m.roughness < kGuideSpecularRoughness);
}

// A bounce that lands on room the camera sees takes the photo's radiance there (all the light
// that point sends, so the path ends): true when it did. Camera rays never do: with and
// without must both be rendered there, or an object's shadow would vanish from the difference.
//
// Never on a surface marked mirror or glossy: the photo shows the radiance it sends toward the
// camera only, and its specular part depends on the direction (a mirror pixel shows whatever
// lies in the camera's mirror direction, not this bounce's). Taking it would give the bounce
// the wrong reflection and, where the path's own specular continuation is traced too, count
// the reflected light twice. Such a surface is path traced at every depth with its BSDF (NEE
// for its lobes, a bounce on), and its bounce ends on Lambertian room where the photo's
// radiance does hold for every direction. A Lambertian point the real mirror lights is
// unaffected: the photo there already holds that light.
bool PathTracer::Impl::endsOnPhoto(Mode mode, PathState& st, const Hit& hit, const SampleRng& rng,
                                   Sums& out) const {
  const bool photoAllowed = !std::exchange(st.noPhotoAtFirstHit, false);
  if (hit.kind != Hit::Kind::Room || st.depth < 1 || roomMaterial(hit.index) || !photoAllowed)
    return false;
  Vec3 photo;
  if (!RoomTexture::radiance(hit.texel, &photo)) return false;
  if (!sunPatches.empty()) photo *= sunPatchWeight(st, hit);
  addTo(mode, out, clampIndirect(Vec3(st.throughput.cwiseProduct(photo)), st.depth >= 2));
  // The objects' change at this point is found by this bounce alone (NEE to a sunlit patch
  // takes the photo's part only), so it keeps its full weight.
  if (mode == Mode::WithOnly) addObjectsEffect(st, rng, out);
  return true;
}

// The BSDF at a room or object hit; false (after adding its light) when the hit is a glowing
// object, which ends the path.
bool PathTracer::Impl::surfaceBsdf(Mode mode, const PathState& st, const Hit& hit, Sums& out,
                                   SurfaceBsdf* bsdf) const {
  if (hit.kind == Hit::Kind::Room) {
    bsdf->kind = Material::Kind::Diffuse;
    bsdf->albedo = room.albedo(hit.index, hit.texel).cwiseMax(0.0).cwiseMin(1.0);
    if (const Material* reassigned = roomMaterial(hit.index)) setRoomBsdf(*reassigned, *bsdf);
    return true;
  }
  const ObjectData& od = objects[size_t(hit.index)];
  const Material& m = od.materialOf(hit.prim);
  if (m.kind == Material::Kind::Emissive) {
    // Both sides emit. After a non-specular bounce NEE could have found this point too.
    const int k = od.meshLightOf(hit.prim);
    const double w =
        st.lastSpecular || k < 0
            ? 1.0
            : powerHeuristic(st.lastPdf, meshLightPdf(size_t(k), st.lastPoint, st.lastNormal, hit.point,
                                                      hit.geometricNormal));
    if (w > 0)
      addTo(mode, out, clampIndirect(Vec3(st.throughput.cwiseProduct(m.emission) * w), st.depth >= 2));
    return false;
  }
  bsdf->kind = m.kind;
  bsdf->albedo = m.albedo.cwiseMax(0.0).cwiseMin(1.0);
  setLobeParameters(m, *bsdf);
  return true;
}

PathTracer::Impl::Vertex PathTracer::Impl::vertexAt(const PathState& st, const Hit& hit,
                                                    const SampleRng& rng) const {
  Vertex v = vertexFrom(st, hit);
  v.u = rng.get2x4(v.dim / 2);
  return v;
}

// The vertex but its random numbers.
PathTracer::Impl::Vertex PathTracer::Impl::vertexFrom(const PathState& st, const Hit& hit) {
  Vertex v;
  v.point = hit.point;
  v.wo = -st.dir;
  const Vec3 ng = hit.geometricNormal;
  v.frontSide = v.wo.dot(ng) >= 0;
  v.ngFacing = v.frontSide ? ng : Vec3(-ng);
  v.ns = hit.shadingNormal;
  if (v.ns.dot(v.ngFacing) < 0) v.ns = -v.ns;
  v.eps = std::max(rayEpsilon(hit.point), hit.roundOffM);
  v.dim = kFirstVertexDim + uint32_t(st.depth) * kDimsPerVertex;
  return v;
}

// A non-specular vertex: a direction from the BSDF and the roulette; the ray in that direction
// cast at once into *next (its room texel prefetched, not yet read), then next-event estimation
// (a light source, the suns), whose work hides the texel's cache miss. The same rays and sums as
// NEE first: the direction and the roulette draw their own dimensions. False when the path ends
// here.
bool PathTracer::Impl::scatterNonSpecular(Mode mode, PathState& st, const Vertex& v,
                                          const SurfaceBsdf& bsdf, const SampleRng& rng, Sums& out,
                                          Hit* next, const FirstVertex* first) const {
  // Light selection and its pdfs skip sources below the tangent plane, unless the BSDF
  // transmits (rough glass): then every side counts (a zero normal says so).
  const Lobe lobe(bsdf, bsdf.transmits() && v.wo.dot(v.ns) <= 0 ? v.ngFacing : v.ns, v.wo,
                  bsdf.transmits() ? Vec3(Vec3::Zero()) : v.ngFacing);
  const bool nee = !bsdf.transmits() || options.roughGlassNee;
  // The caustic map's light here marks the path (PathState::causticChain) before the bounce
  // copies its state.
  if (bsdf.kind == Material::Kind::Diffuse && !caustics.empty()) addCausticLight(mode, st, v, bsdf, out);
  // NEE's source and point first: their chain of square roots and divisions (the spherical
  // quad) does not depend on the bounce's, so the core overlaps the two. A camera packet's first
  // vertex may have it already (firstVertices: a BSDF that does not transmit).
  const int64_t pickStart = neeClockNs();
  const SourcePick pick = !nee ? SourcePick{sourceCount(), 0, {}}
                          : first && first->picked && !bsdf.transmits() ? first->pick
                                                                        : pickSource(v, lobe);
  out.counters.neeNs += neeClockNs() - pickStart;
  PathState after = st;
  const bool goesOn = bounceFrom(after, v, lobe, nee) && survivesRoulette(after, v);
  if (goesOn) {
    PathState ray = after;
    ++ray.depth;
    *next = castPathRay(mode, ray, rng, out, true);
  }
  if (nee) {
    const int64_t neeStart = neeClockNs();
    addSourceSample(mode, st, v, lobe, pick, out);
    addSunLight(mode, st, v, lobe, out);
    if (sunPatchNeeAt(st.depth)) addSunPatchSample(mode, st, v, lobe, rng, out);
    out.counters.neeNs += neeClockNs() - neeStart;
  }
  if (goesOn) st = after;
  return goesOn;
}

// The next ray from a non-specular vertex, sampled from its BSDF, into `st`; false when the
// path ends here.
bool PathTracer::Impl::bounceFrom(PathState& st, const Vertex& v, const Lobe& lobe, bool nee) const {
  const auto& uDir = v.direction();
  const BsdfSample s = lobe.bsdf.sample(lobe.woLocal, v.pickAndLobe()[1], uDir[0], uDir[1]);
  if (!s.valid) return false;
  st.dir = lobe.frame.toWorld(s.dir).normalized();
  const bool reflected = s.dir.z() > 0;
  // A shading normal may send it to the wrong side of the real surface: end the path.
  if ((st.dir.dot(v.ngFacing) > 0) != reflected) return false;
  st.throughput = st.throughput.cwiseProduct(s.weight);
  st.lastSpecular = !nee;  // without NEE here, a light the bounce finds counts in full
  st.lastPdf = s.pdf;
  st.lastPoint = v.point;
  st.lastNormal = lobe.selectNormal;
  st.origin = v.point + (reflected ? v.eps : -v.eps) * v.ngFacing;
  st.tNear = 0;
  return true;
}

// A point on NEE source `li` seen from `from`: on an area light uniform in its solid angle
// (rectangles and quads; by area when the light is far, sampledByArea, or its solid angle tiny),
// on an emissive object uniform by area.
PathTracer::Impl::SourcePoint PathTracer::Impl::sampleSource(size_t li, const Vec3& from,
                                                             const std::array<double, 2>& u) const {
  SourcePoint p;
  p.mesh = li >= lights.size();
  if (p.mesh) {
    const MeshLightData& m = meshLights[li - lights.size()];
    p.y = sampleMeshLight(m, u[0], u[1], &p.normal);
    p.radiance = m.radiance;
    return p;
  }
  const LightData& l = lights[li];
  if (!sampledByArea(l, from)) p.solidAngle = sampleBySolidAngle(l, from, u, &p.y);
  finishAreaLightPoint(l, u, p);
  return p;
}

// The rest of an area light's point once its solid-angle sample is known (p.solidAngle > 0, p.y
// set) or not (p.solidAngle 0): by area, a rectangle through its edges (one smooth map, so
// stratified u stay stratified over it), any other quad through its two triangles.
void PathTracer::Impl::finishAreaLightPoint(const LightData& l, const std::array<double, 2>& u,
                                            SourcePoint& p) const {
  if (p.solidAngle == 0)
    p.y = l.rectangle ? Vec3(l.corner + u[0] * l.edgeX + u[1] * l.edgeY)
                      : sampleQuadUniform(l.emitter, l.firstTriangleShare, u[0], u[1]);
  p.normal = l.normal;
  p.radiance = l.radiance;
}

// A point on area light l uniform in the solid angle it subtends from `from` into *y; returns
// that solid angle, or 0 (y untouched) when it is below kMinSolidAngle.
double PathTracer::Impl::sampleBySolidAngle(const LightData& l, const Vec3& from,
                                            const std::array<double, 2>& u, Vec3* y) {
  if (l.rectangle) {
    const SphericalRect sr(l.corner, l.edgeX, l.edgeY, from);
    if (!(sr.solidAngle > kMinSolidAngle)) return 0;
    *y = sr.sample(u[0], u[1]);
    return sr.solidAngle;
  }
  const SphericalQuad sq(l.emitter, from);
  if (!(sq.solidAngle > kMinSolidAngle)) return 0;
  *y = sq.sample(u[0], u[1]);
  return sq.solidAngle;
}

// Next-event estimation to one source (area light or emissive object) picked by power over
// squared distance (or by power alone, TracerOptions::lightSelection), MIS-weighted against
// the BSDF, with a shadow ray.
PathTracer::Impl::SourcePick PathTracer::Impl::pickSource(const Vertex& v, const Lobe& lobe) const {
  SourcePick pick = chooseSource(v, lobe.selectNormal);
  if (pick.li < sourceCount()) pick.p = sampleSource(pick.li, v.point, v.lightPoint());
  return pick;
}

// The source alone (pick.p left unset).
PathTracer::Impl::SourcePick PathTracer::Impl::chooseSource(const Vertex& v,
                                                            const Vec3& selectNormal) const {
  SourcePick pick;
  pick.li = sourceCount() == 0 ? sourceCount()
                               : pickLight(v.point, selectNormal, v.pickAndLobe()[0], &pick.selectProb);
  if (pick.li >= sourceCount() || !(pick.selectProb > 0)) pick.li = sourceCount();
  return pick;
}

// A camera packet's first vertices, worked out before each lane's path goes on alone: every room
// or object hit's vertex (vertexAt) and NEE's source and point there as a BSDF that does not
// transmit picks them, the near lights' spherical quads (NEE's slowest part, a chain of dependent
// square roots and divisions each) four at a time in AVX2 lanes, whose chains overlap. The same
// vertices and points, bit for bit, as the paths would find alone (a transmitting BSDF, whose
// light selection sees every side, picks again). Only with the lanes, and paths that go on
// (verticesAhead()).
void PathTracer::Impl::firstVertices(const PacketLanes& lanes, const Vec3* dirs, const Hit* hits,
                                     FirstVertex* out, RayCounters& tileCounters) const {
  const int n = lanes.m;
  for (int j = 0; j < n; ++j) {
    out[j].set = out[j].picked = false;
    if (hits[j].kind != Hit::Kind::Room && hits[j].kind != Hit::Kind::Object) continue;
    out[j].v = vertexFrom(cameraRay(dirs[j]), hits[j]);
    for (size_t k = 0; k < 4; ++k)  // pairs 1 .. 4 of the packet's numbers (packetLanes)
      out[j].v.u[k] = {lanes.numbers.u[k + 1][0][j], lanes.numbers.u[k + 1][1][j]};
    out[j].set = true;
  }
  const int64_t start = neeClockNs();
  std::array<FirstVertex*, kPacket> near;
  int m = 0;
  for (int j = 0; j < n; ++j) {
    FirstVertex& f = out[j];
    if (!f.set) continue;
    f.pick = chooseSource(f.v, f.v.ngFacing);
    f.picked = true;
    if (f.pick.li >= sourceCount()) continue;
    if (nearQuad(f.pick, f.v.point)) near[size_t(m++)] = &f;
    else f.pick.p = sampleSource(f.pick.li, f.v.point, f.v.lightPoint());
  }
  for (int j = 0; j < m; j += kQuadLanes) pickNearQuads(std::min(kQuadLanes, m - j), &near[size_t(j)]);
  tileCounters.neeNs += neeClockNs() - start;
}

// True when NEE's point on the picked source is a spherical quad's: an area light that is not a
// rectangle, near enough to be sampled by solid angle (sampleSource).
bool PathTracer::Impl::nearQuad(const SourcePick& pick, const Vec3& from) const {
  if (pick.li >= lights.size()) return false;
  const LightData& l = lights[pick.li];
  return !l.rectangle && !sampledByArea(l, from);
}

// sampleSource() for n <= kQuadLanes picks of near quads, in the lanes of one kernel call (lanes
// past n repeat the last pick); a lane the kernel leaves to the scalar code takes it.
void PathTracer::Impl::pickNearQuads(int n, FirstVertex* const* lanes) const {
  QuadLanes q;
  for (int l = 0; l < kQuadLanes; ++l) {
    const FirstVertex& f = *lanes[std::min(l, n - 1)];
    const std::array<Vec3, 4>& c = lights[f.pick.li].emitter;
    for (int a = 0; a < 3; ++a) {
      for (int k = 0; k < 4; ++k) q.corner[k][a][l] = c[size_t(k)][a];
      q.origin[a][l] = f.v.point[a];
    }
    q.u0[l] = f.v.lightPoint()[0], q.u1[l] = f.v.lightPoint()[1];
  }
  const int scalarLanes = sphericalQuadLanesAvx2(q);
  for (int l = 0; l < n; ++l) {
    SourcePick& pick = lanes[l]->pick;
    const std::array<double, 2>& u = lanes[l]->v.lightPoint();
    if (scalarLanes & (1 << l)) {
      pick.p = sampleSource(pick.li, lanes[l]->v.point, u);
      continue;
    }
    if (q.solidAngle[l] > kMinSolidAngle)
      pick.p.solidAngle = q.solidAngle[l], pick.p.y = Vec3(q.y[0][l], q.y[1][l], q.y[2][l]);
    finishAreaLightPoint(lights[pick.li], u, pick.p);
  }
}

// The rest of it, for the source and point `pick` drew.
void PathTracer::Impl::addSourceSample(Mode mode, const PathState& st, const Vertex& v, const Lobe& lobe,
                                       const SourcePick& pick, Sums& out) const {
  if (pick.li >= sourceCount()) return;
  const size_t li = pick.li;
  const double selectProb = pick.selectProb;
  const SourcePoint& p = pick.p;
  Vec3 w = p.y - v.point;
  const double d = std::sqrt(w.squaredNorm());
  if (d > 0) w /= d;
  // Area lights emit on their front only; emissive objects on both sides.
  const double cosL = p.mesh ? std::abs(p.normal.dot(w)) : -p.normal.dot(w);
  const bool above = w.dot(v.ngFacing) > 0;
  const Vec3 wLocal = lobe.frame.toLocal(w);
  if (!(d > 2 * v.eps && cosL > 0 && (above || lobe.bsdf.transmits()) && (wLocal.z() > 0) == above))
    return;
  double pdfBsdf = 0;
  const Vec3 fcos = lobe.bsdf.eval(lobe.woLocal, wLocal, &pdfBsdf);
  if (!(fcos.maxCoeff() > 0)) return;
  const double pdfLight =
      p.mesh             ? meshLightPdf(li - lights.size(), v.point, lobe.selectNormal, p.y, p.normal)
      : p.solidAngle > 0 ? selectProb / p.solidAngle
                         : areaPdf(lights[li], selectProb, v.point, p.y);
  const Vec3 c = pdfLight > 0
                     ? clampIndirect(Vec3(st.throughput.cwiseProduct(fcos).cwiseProduct(p.radiance) *
                                          (powerHeuristic(pdfLight, pdfBsdf) / pdfLight)),
                                     st.depth >= 1)
                     : Vec3(Vec3::Zero());
  // The shadow ray runs from the offset origin to the sampled point itself, stopping just
  // short of the emitter (which would otherwise block its own light): its direction is the
  // segment itself, not normalised (Embree's t is then the fraction of it).
  const Vec3 o = v.point + (above ? v.eps : -v.eps) * v.ngFacing;
  const Vec3 ws = p.y - o;
  const double tFar = 1.0 - 1e-4;
  if (p.mesh) {
    // An emissive object exists in the with-scene only.
    if (mode != Mode::WithoutOnly && c.maxCoeff() > 0 && !blocked(out, withScene, o, ws, tFar))
      out.with += c;
  } else {
    addUnlessBlocked(mode, withScene, withoutScene, o, ws, tFar, c, out);
  }
}

// The sunlit patches the photo shows (sun_patch.h): a point picked on them by power, its photo
// radiance as a bounce landing there would read it, MIS-weighted against the BSDF (whose landing
// on a patch texel sunPatchWeight weighs), with a shadow ray. What the objects change on the patch
// (their shadow on it) is left to the bounce (endsOnPhoto, addObjectsEffect).
void PathTracer::Impl::addSunPatchSample(Mode mode, const PathState& st, const Vertex& v,
                                         const Lobe& lobe, const SampleRng& rng, Sums& out) const {
  const uint32_t pair = kSunPatchPair + 2 * uint32_t(st.depth);
  const auto u = rng.get2(pair);
  const SunPatchLight::Sample p = sunPatches.sample(u[0], u[1], rng.get2(pair + 1)[0]);
  if (!(p.pdfArea > 0)) return;
  Vec3 w = p.y - v.point;
  const double d2 = w.squaredNorm(), d = std::sqrt(d2);
  if (d > 0) w /= d;
  const double cosY = -p.normal.dot(w);
  const bool above = w.dot(v.ngFacing) > 0;
  const Vec3 wLocal = lobe.frame.toLocal(w);
  if (!(d > 2 * v.eps && cosY > 0 && (above || lobe.bsdf.transmits()) && (wLocal.z() > 0) == above))
    return;
  double pdfBsdf = 0;
  const Vec3 fcos = lobe.bsdf.eval(lobe.woLocal, wLocal, &pdfBsdf);
  if (!(fcos.maxCoeff() > 0)) return;
  const double pdfLight = p.pdfArea * d2 / cosY;
  if (!(pdfLight > 0) || !std::isfinite(pdfLight)) return;
  const Vec3 c = clampIndirect(Vec3(st.throughput.cwiseProduct(fcos).cwiseProduct(p.radiance) *
                                    (powerHeuristic(pdfLight, pdfBsdf) / pdfLight)),
                               st.depth >= 1);
  const Vec3 o = v.point + (above ? v.eps : -v.eps) * v.ngFacing;
  Vec3 ws = p.y - o;
  const double ds = ws.norm();
  ws /= ds;
  addUnlessBlocked(mode, withScene, withoutScene, o, ws, ds * (1.0 - 1e-4), c, out);
}

// The MIS weight of a bounce's landing on room the photo shows, against NEE to the sunlit
// patches: 1 off the patches and after a specular vertex (which made no NEE).
double PathTracer::Impl::sunPatchWeight(const PathState& st, const Hit& hit) const {
  if (st.lastSpecular || !hit.texel || !sunPatchNeeAt(st.depth - 1)) return 1.0;
  const double pdfArea = sunPatches.pdfArea(room.indexOf(hit.texel));
  if (!(pdfArea > 0)) return 1.0;
  const Vec3 w = hit.point - st.lastPoint;
  const double d2 = w.squaredNorm();
  const double cosY = std::abs(hit.geometricNormal.dot(st.dir));
  if (!(cosY > 0) || !(d2 > 0)) return 1.0;
  return powerHeuristic(st.lastPdf, pdfArea * d2 / cosY);
}

// The texels that show a sunlit patch (inside a sun's lit mask, on a Lambertian room surface
// the sun faces, with a usable photo radiance) become the patch light. One camera ray per
// texel of the lit masks finds the surface each shows.
void PathTracer::Impl::buildSunPatches() {
  const int w = room.width(), h = room.height();
  const Camera& cam = scene.roomAlbedo.camera;
  if (suns.empty() || w <= 0 || h <= 0 || cam.widthPx <= 0 || cam.heightPx <= 0) return;
  auto inSomeMask = [&](const Vec2& px) {
    for (const SunData& sd : suns) {
      const ImageF& m = sd.sun->litMask;
      if (m.empty()) return true;
      const int mx = int(px.x() * m.width / cam.widthPx), my = int(px.y() * m.height / cam.heightPx);
      if (mx >= 0 && my >= 0 && mx < m.width && my < m.height && m.at(mx, my, 0) > 0) return true;
    }
    return false;
  };
  std::vector<SunPatchLight::Footprint> footprints;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * size_t(w) + size_t(x);
      const RoomTexture::Texel& t = room.texel(i);
      const Vec2 px((x + 0.5) * cam.widthPx / w, (y + 0.5) * cam.heightPx / h);
      if (!t.radianceUsable() || t.surface() < 0 || roomMaterial(t.surface()) || !inSomeMask(px))
        continue;
      const Hit hit = intersect(withoutScene, cam.centreWorld(), cam.directionThroughPixel(px), 0);
      if (hit.kind != Hit::Kind::Room || hit.texel != &t) continue;
      const Vec3 n = hit.geometricNormal.dot(hit.point - cam.centreWorld()) > 0
                         ? Vec3(-hit.geometricNormal)
                         : hit.geometricNormal;
      const bool lit = std::any_of(suns.begin(), suns.end(), [&](const SunData& sd) {
        return sd.toSun.dot(n) > 0 && sd.sun->beamAt(hit.point) > 0;
      });
      if (!lit) continue;
      auto f = texelFootprint(cam, w, h, x, y, hit.point, n);
      if (!f) continue;
      f->radiance = Vec3(t.radiance[0], t.radiance[1], t.radiance[2]);
      footprints.push_back(*f);
    }
  sunPatches = SunPatchLight(std::move(footprints), room.texelCount());
}

// Suns: parallel light, a delta direction (never found by BSDF sampling, so no MIS).
void PathTracer::Impl::addSunLight(Mode mode, const PathState& st, const Vertex& v, const Lobe& lobe,
                                   Sums& out) const {
  for (const SunData& sun : suns) {
    const bool sunAbove = sun.toSun.dot(v.ngFacing) > 0;
    if (!sunAbove && !(lobe.bsdf.transmits() && sun.toSun.dot(v.ngFacing) < 0)) continue;
    const double beam = sun.sun->beamAt(v.point);
    if (!(beam > 0)) continue;
    double pdfBsdf = 0;
    const Vec3 sunLocal = lobe.frame.toLocal(sun.toSun);
    if ((sunLocal.z() > 0) != sunAbove) continue;
    const Vec3 fcos = lobe.bsdf.eval(lobe.woLocal, sunLocal, &pdfBsdf);
    if (!(fcos.maxCoeff() > 0)) continue;
    // L = f cos E_perp with E_perp = pi * irradianceOverPi.
    const Vec3 c = clampIndirect(
        Vec3(st.throughput.cwiseProduct(fcos).cwiseProduct(sun.irradianceOverPi) * (kPi * beam)),
        st.depth >= 1);
    const Vec3 o = v.point + (sunAbove ? v.eps : -v.eps) * v.ngFacing;
    addUnlessBlocked(mode, sunWithScene, sunWithoutScene, o, sun.toSun, 3.4e38, c, out);
  }
}

bool PathTracer::Impl::reflectMirror(PathState& st, const Vertex& v, const SurfaceBsdf& bsdf) const {
  st.dir = reflect(v.wo, v.ns).normalized();
  if (st.dir.dot(v.ngFacing) <= 0) st.dir = reflect(v.wo, v.ngFacing).normalized();
  st.throughput = st.throughput.cwiseProduct(bsdf.albedo);
  st.lastSpecular = true;
  st.lastPdf = 0;
  st.origin = v.point + v.eps * v.ngFacing;
  return true;
}

// Smooth dielectric, clear (no absorption): reflect or refract by the Fresnel weight
// (sampleSmoothGlass: never lost at a shading normal's silhouette).
bool PathTracer::Impl::scatterGlass(PathState& st, const Vertex& v, const SurfaceBsdf& bsdf) const {
  // Entering when the ray comes from the outward side.
  const double eta = v.frontSide ? bsdf.ior : 1.0 / bsdf.ior;
  const SmoothGlassSample s = sampleSmoothGlass(v.wo, v.ngFacing, v.ns, eta, v.pickAndLobe()[1]);
  st.dir = s.dir;
  st.origin = v.point + (s.reflected ? v.eps : -v.eps) * v.ngFacing;
  st.lastSpecular = true;
  st.lastPdf = 0;
  return true;
}

// The camera's first smooth-glass vertex, split (TracerOptions::splitGlassAtCamera): the
// reflection is traced as a branch of weight F and this path goes on refracted with weight
// 1 - F, instead of one of them picked with those probabilities (whose choice was half of a
// glass object's noise at 16 samples). Total internal reflection, or F = 0, has nothing to
// split.
bool PathTracer::Impl::splitGlass(Mode mode, PathState& st, const Vertex& v, const SurfaceBsdf& bsdf,
                                  const SampleRng& rng, Sums& out) const {
  const double eta = v.frontSide ? bsdf.ior : 1.0 / bsdf.ior;
  const SmoothGlassSample r = sampleSmoothGlass(v.wo, v.ngFacing, v.ns, eta, 0.0);
  const SmoothGlassSample t = sampleSmoothGlass(v.wo, v.ngFacing, v.ns, eta, std::nextafter(1.0, 0.0));
  if (!r.reflected || t.reflected) return scatterGlass(st, v, bsdf);
  PathState branch = st;
  branch.dir = r.dir;
  branch.origin = v.point + v.eps * v.ngFacing;
  branch.throughput *= r.fresnel;
  branch.lastSpecular = true;
  branch.lastPdf = 0;
  branch.tNear = 0;
  ++branch.depth;
  tracePath(mode, branch, rng, out, nullptr);
  st.dir = t.dir;
  st.origin = v.point - v.eps * v.ngFacing;
  st.throughput *= 1.0 - t.fresnel;
  st.lastSpecular = true;
  st.lastPdf = 0;
  return true;
}

// Russian roulette from russianRouletteDepth: survival min(0.95, max throughput).
bool PathTracer::Impl::survivesRoulette(PathState& st, const Vertex& v) const {
  if (st.depth + 1 < options.russianRouletteDepth) return true;
  const double q = std::min(0.95, maxComponent(st.throughput));
  if (!(q > 0) || v.roulette() >= q) return false;
  st.throughput /= q;
  return true;
}

// The caustic photon pass (TracerOptions::causticPhotons). Light reaches a Lambertian point
// through a smooth glass object along paths light -> glass ... glass -> point that the path
// tracer finds only by BSDF sampling (next-event estimation's shadow ray is blocked by the
// glass): rare hits on a small light, the caustic missing or fireflies. Photons from every area
// light and sun, aimed at each glass object's bounding sphere, follow those paths from the
// light's end; their density at a Lambertian vertex replaces the vertex's own paths through the
// glass to an area light (PathState::causticChain), so each light path is counted once.

// The inserted objects with a smooth glass material (any part), with their world bounding
// spheres (the box's centre, the farthest vertex).
std::vector<PathTracer::Impl::GlassTarget> PathTracer::Impl::glassTargets() const {
  std::vector<GlassTarget> targets;
  auto isGlass = [](const Material& m) { return m.kind == Material::Kind::Glass; };
  for (size_t i = 0; i < objects.size(); ++i) {
    const ObjectData& o = objects[i];
    if (!o.instance || !o.mesh ||
        !(isGlass(o.material) || std::any_of(o.parts.begin(), o.parts.end(), isGlass)))
      continue;
    const Mat3 linear = o.worldFromObject.topLeftCorner<3, 3>();
    const Vec3 shift = o.worldFromObject.topRightCorner<3, 1>();
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (const Vec3f& p : o.mesh->positions) {
      const Vec3 w = linear * p.cast<double>() + shift;
      lo = lo.cwiseMin(w), hi = hi.cwiseMax(w);
    }
    GlassTarget t{i, 0.5 * (lo + hi), 0.0};
    for (const Vec3f& p : o.mesh->positions)
      t.radius = std::max(t.radius, (linear * p.cast<double>() + shift - t.centre).norm());
    if (t.centre.allFinite() && t.radius > 0 && std::isfinite(t.radius)) targets.push_back(t);
  }
  return targets;
}

// Emits options.causticPhotons photons in all, an equal share per (source, glass object), in
// parallel batches whose photons are concatenated in order (the map is the same whatever the
// threads), and builds the map with a radius of causticRadius x the smallest bounding radius.
void PathTracer::Impl::buildCaustics() {
  caustics = CausticMap();
  const size_t sources = lights.size() + suns.size();
  if (options.causticPhotons <= 0 || sources == 0 || !(options.causticRadius > 0)) return;
  const std::vector<GlassTarget> targets = glassTargets();
  if (targets.empty()) return;
  const uint32_t perPair =
      uint32_t(std::max<size_t>(1, size_t(options.causticPhotons) / (sources * targets.size())));
  std::vector<PhotonBatch> batches;
  constexpr uint32_t kBatch = 4096;
  for (size_t t = 0; t < targets.size(); ++t)
    for (size_t src = 0; src < sources; ++src)
      for (uint32_t first = 0; first < perPair; first += kBatch)
        batches.push_back({t, src, first, std::min(kBatch, perPair - first), perPair});
  std::vector<std::vector<CausticPhoton>> landed(batches.size());
  parallelFor(tbb::blocked_range<size_t>(0, batches.size()), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t b = r.begin(); b < r.end(); ++b)
      landed[b] = emitPhotons(targets[batches[b].target], batches[b]);
  });
  std::vector<CausticPhoton> photons;
  for (const auto& l : landed) photons.insert(photons.end(), l.begin(), l.end());
  double radius = 1e300;
  for (const GlassTarget& t : targets) radius = std::min(radius, options.causticRadius * t.radius);
  caustics = CausticMap(std::move(photons), radius);
}

// One batch: photon k of the pair (source, target) draws its numbers from SampleRng(k, target,
// source, a fixed seed) and carries 1 / perPair of the flux the source sends into the sphere.
std::vector<CausticPhoton> PathTracer::Impl::emitPhotons(const GlassTarget& target,
                                                         const PhotonBatch& batch) const {
  std::vector<CausticPhoton> out;
  for (uint32_t k = batch.first; k < batch.first + batch.count; ++k) {
    const SampleRng rng(k, uint32_t(batch.target), uint32_t(batch.source), 0x9e3779b9u);
    Vec3 origin, dir, flux;
    const bool emitted =
        batch.source < lights.size()
            ? photonFromLight(lights[batch.source], target, rng, batch.perPair, &origin, &dir, &flux)
            : photonFromSun(suns[batch.source - lights.size()], target, rng, batch.perPair, &origin,
                            &dir, &flux);
    if (emitted) tracePhoton(target, origin, dir, flux, rng, out);
  }
  return out;
}

// A photon from area light l toward the target's sphere: a point uniform on the emitter, a
// direction uniform in the cone the sphere fills from there (the whole front hemisphere, by
// the cosine, when the point lies inside the sphere). Flux: L cos A Omega / count.
bool PathTracer::Impl::photonFromLight(const LightData& l, const GlassTarget& target,
                                       const SampleRng& rng, uint32_t count, Vec3* origin, Vec3* dir,
                                       Vec3* flux) const {
  if (!(l.power > 0)) return false;
  const auto uPoint = rng.get2(0), uDir = rng.get2(1);
  *origin = sampleQuadUniform(l.emitter, uPoint[0], uPoint[1]);
  const Vec3 toCentre = target.centre - *origin;
  const double dist = toCentre.norm();
  double weight = 0;  // cos Omega, or pi for the cosine-weighted hemisphere
  if (!(dist > target.radius)) {
    *dir = Frame(l.normal).toWorld(sampleCosineHemisphere(uDir[0], uDir[1]));
    weight = kPi;
  } else {
    const double sinMax2 = std::min(1.0, target.radius * target.radius / (dist * dist));
    const double cosMax = std::sqrt(1.0 - sinMax2);
    const double cosT = 1.0 - uDir[0] * (1.0 - cosMax),
                 sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT));
    const double phi = 2.0 * kPi * uDir[1];
    *dir = Frame(toCentre / dist).toWorld(Vec3(sinT * std::cos(phi), sinT * std::sin(phi), cosT));
    weight = l.normal.dot(*dir) * 2.0 * kPi * (1.0 - cosMax);
  }
  *flux = l.radiance * (weight * l.area / count);
  return weight > 0 && dir->allFinite() && flux->allFinite();
}

// A photon from a sun: a point uniform on the sphere's disc across the beam, started just
// outside the sphere on the sun's side; none where the beam does not reach or something inside
// the room stands between it and the opening. Flux: E_perp beam pi R^2 / count.
bool PathTracer::Impl::photonFromSun(const SunData& sun, const GlassTarget& target, const SampleRng& rng,
                                     uint32_t count, Vec3* origin, Vec3* dir, Vec3* flux) const {
  const auto u = rng.get2(0);
  const double r = target.radius * std::sqrt(u[0]), phi = 2.0 * kPi * u[1];
  const Frame frame(sun.toSun);
  *origin = target.centre +
            frame.toWorld(Vec3(r * std::cos(phi), r * std::sin(phi), 1.01 * target.radius));
  *dir = -sun.toSun;
  const double beam = sun.sun->beamAt(*origin);
  if (!(beam > 0) || occluded(sunWithScene, *origin, sun.toSun, 0, 3.4e38)) return false;
  *flux = sun.irradianceOverPi * (kPi * beam * kPi * target.radius * target.radius / count);
  return flux->allFinite();
}

// What a photon meets: Glass (with its IOR), Diffuse (a Lambertian room surface or object),
// or anything else (a light, a marked room surface, another material), which ends it.
Material::Kind PathTracer::Impl::photonSurface(const Hit& hit, double* ior) const {
  if (hit.kind == Hit::Kind::Room)
    return roomMaterial(hit.index) ? Material::Kind::Mirror : Material::Kind::Diffuse;
  if (hit.kind != Hit::Kind::Object) return Material::Kind::Emissive;
  const Material& m = objects[size_t(hit.index)].materialOf(hit.prim);
  SurfaceBsdf bsdf;
  setLobeParameters(m, bsdf);
  *ior = bsdf.ior;
  return m.kind;
}

// A photon's path: it must meet the target first (a photon aimed at another object's sphere
// that meets this one first is that object's), then smooth glass (reflected or refracted by
// the Fresnel weight, as scatterGlass) up to maxGlassDepth vertices, and is stored where it
// lands on a Lambertian surface.
void PathTracer::Impl::tracePhoton(const GlassTarget& target, Vec3 origin, Vec3 dir, const Vec3& flux,
                                   const SampleRng& rng, std::vector<CausticPhoton>& out) const {
  Hit hit = intersect(withScene, origin, dir, rayEpsilon(origin));
  if (hit.kind != Hit::Kind::Object || size_t(hit.index) != target.object) return;
  for (int vertex = 0;; ++vertex) {
    double ior = 1.5;
    const Material::Kind kind = photonSurface(hit, &ior);
    const Vec3 wo = -dir, ng = hit.geometricNormal;
    const bool front = wo.dot(ng) >= 0;
    const Vec3 ngFacing = front ? ng : Vec3(-ng);
    if (kind == Material::Kind::Diffuse && vertex > 0) return out.push_back({hit.point, ngFacing, flux});
    if (kind != Material::Kind::Glass || vertex >= options.maxGlassDepth) return;
    const Vec3 ns = hit.shadingNormal.dot(ngFacing) < 0 ? Vec3(-hit.shadingNormal) : hit.shadingNormal;
    const SmoothGlassSample s =
        sampleSmoothGlass(wo, ngFacing, ns, front ? ior : 1.0 / ior, rng.get(4 + uint32_t(vertex)));
    const double eps = std::max(rayEpsilon(hit.point), hit.roundOffM);
    origin = hit.point + (s.reflected ? eps : -eps) * ngFacing;
    dir = s.dir;
    hit = intersect(withScene, origin, dir, 0);
  }
}

// The caustic map's light at a Lambertian vertex (with-objects sums only: the glass exists
// there alone), as direct light is clamped: f = albedo / pi times the photons' irradiance.
void PathTracer::Impl::addCausticLight(Mode mode, PathState& st, const Vertex& v,
                                       const SurfaceBsdf& bsdf, Sums& out) const {
  st.causticChain = 1;
  if (mode == Mode::WithoutOnly) return;
  const Vec3 e = caustics.irradiance(v.point, v.ngFacing);
  if (!(e.maxCoeff() > 0)) return;
  out.with +=
      clampIndirect(Vec3(st.throughput.cwiseProduct(bsdf.albedo).cwiseProduct(e) / kPi), st.depth >= 1);
}

// The photo shows the room without the objects. A path that left an object and lands on room
// the camera sees needs that point's radiance in the scene WITH the objects: the photo's, plus
// what the objects change there (the shadow they cast on it, the light they bounce onto it).
// That change is what a Shared path from the point estimates as with - without: it is path
// traced from there (NEE with the with/without shadow test, a bounce that parts at an object)
// and only the difference is kept, so it is exactly zero where the objects play no part. Without
// it the bottom of an object standing on the floor saw the floor's unshadowed photo radiance.
// Only with-only paths do it (they are few: an object pixel's or a ray's that met an object); a
// Shared path landing on room in an object's shadow misses that second-order darkening.
void PathTracer::Impl::addObjectsEffect(PathState st, const SampleRng& rng, Sums& out) const {
  Sums change;
  st.noPhotoAtFirstHit = true;
  tracePath(Mode::Shared, st, rng, change, nullptr);
  out.with += change.with - change.without;
  out.counters += change.counters;
}

// ---------------------------------------------------------------------------------------------

DifferentialBuffers::DifferentialBuffers(int w, int h)
    : width(w),
      height(h),
      sumWith(w, h, 3),
      sumWithout(w, h, 3),
      sumMask(w, h, 1),
      sumDiffSq(w, h, 1),
      sumChange(w, h, 3),
      sumChangeSq(w, h, 1),
      samples(size_t(w) * size_t(h), 0) {}

void DifferentialBuffers::clear() {
  std::fill(sumWith.data.begin(), sumWith.data.end(), 0.f);
  std::fill(sumWithout.data.begin(), sumWithout.data.end(), 0.f);
  std::fill(sumMask.data.begin(), sumMask.data.end(), 0.f);
  std::fill(sumDiffSq.data.begin(), sumDiffSq.data.end(), 0.f);
  std::fill(sumChange.data.begin(), sumChange.data.end(), 0.f);
  std::fill(sumChangeSq.data.begin(), sumChangeSq.data.end(), 0.f);
  std::fill(samples.begin(), samples.end(), 0);
  for (ImageF* g : {&sumGuideAlbedo, &sumGuideNormal, &sumGuidePosition, &sumGuideDistance})
    std::fill(g->data.begin(), g->data.end(), 0.f);
}

void DifferentialBuffers::enableGuides() {
  if (hasGuides()) return;
  sumGuideAlbedo = ImageF(width, height, 3);
  sumGuideNormal = ImageF(width, height, 3);
  sumGuidePosition = ImageF(width, height, 3);
  sumGuideDistance = ImageF(width, height, 3);
}

namespace {
ImageF meanOf(const ImageF& sum, const std::vector<int>& samples) {
  ImageF out(sum.width, sum.height, sum.channels);
  for (size_t i = 0; i < sum.pixelCount(); ++i) {
    if (samples[i] <= 0) continue;
    const float inv = 1.f / float(samples[i]);
    for (int c = 0; c < sum.channels; ++c)
      out.data[i * sum.channels + c] = sum.data[i * sum.channels + c] * inv;
  }
  return out;
}
}  // namespace

ImageF DifferentialBuffers::meanWith() const { return meanOf(sumWith, samples); }
ImageF DifferentialBuffers::meanWithout() const { return meanOf(sumWithout, samples); }
ImageF DifferentialBuffers::meanMask() const { return meanOf(sumMask, samples); }

// ---------------------------------------------------------------------------------------------

namespace {
// A number in [0, 1) fixed by a shadow ray and its candidate hit on a card: a pure function of
// the ray (so of pixel, sample and seed), the same in the with- and without-object scenes, and
// independent between two cards on one ray (their distances differ).
double shadowAlphaNumber(const float org[3], const float dir[3], float t) {
  uint32_t h = 0x9e3779b9u;
  auto mix = [&h](float f) { h = pcgHash(h ^ std::bit_cast<uint32_t>(f)); };
  for (int i = 0; i < 3; ++i) mix(org[i]), mix(dir[i]);
  mix(t);
  return double(h >> 8) * (1.0 / 16777216.0);
}

// Shadow rays pass an occluder card with probability 1 - alpha (a stochastic alpha test): in
// expectation the card's shadow has the matte's strength, soft edge included.
void cardShadowFilter(const RTCFilterFunctionNArguments* args) {
  const auto* card = static_cast<const CardAlpha*>(args->geometryUserPtr);
  for (unsigned k = 0; k < args->N; ++k) {
    if (args->valid[k] != -1) continue;
    const FilterRay r = filterRay(args, k);
    const float org[3] = {float(r.org.x()), float(r.org.y()), float(r.org.z())};
    const float dir[3] = {float(r.dir.x()), float(r.dir.y()), float(r.dir.z())};
    if (shadowAlphaNumber(org, dir, r.t) >= card->alphaAt(r.hitPoint())) args->valid[k] = 0;
  }
}
}  // namespace

PathTracer::PathTracer(const RenderScene& scene, const TracerOptions& options)
    : impl_(std::make_unique<Impl>()) {
  Impl& d = *impl_;
  auto attachCardShadowFilters = [&](RTCScene s) {
    for (unsigned i = 0; i < d.surfaceCount; ++i) {
      const Surface& surf = d.scene.room.surfaces[i];
      if (surf.kind != SurfaceKind::OccluderCard || !surf.cardAlpha) continue;
      RTCGeometry g = rtcGetGeometry(s, i);
      if (!g) continue;
      rtcSetGeometryUserData(g, const_cast<CardAlpha*>(surf.cardAlpha.get()));
      rtcSetGeometryOccludedFilterFunction(g, cardShadowFilter);
      rtcSetGeometryIntersectFilterFunction(g, cardIntersectFilter);
      d.hasCards = true;
      rtcCommitGeometry(g);
    }
  };
  d.scene = scene;
  d.options = options;
  d.pixelFilter = PixelFilter(options.pixelFilterWidth);
  d.room = RoomTexture(scene.roomAlbedo);
  // The texture holds what room hits read of these (so the tracer's copy of the scene, which
  // scene() returns, keeps of roomAlbedo the camera, the surface means and the photo for
  // photoAt(): 17 bytes a pixel fewer, against the texture's 32).
  ProjectedAlbedo& copied = d.scene.roomAlbedo;
  copied.albedo = ImageF();
  std::vector<int>().swap(copied.firstSurfacePerPixel);
  std::vector<uint8_t>().swap(copied.photoRadianceUsable);
  GgxAlbedoTable::instance();       // built here (~30 ms, once per process), never mid-frame
  d.device = sharedTracerDevice();  // the object BVHs are shared between tracers
  d.packetsSupported = rtcGetDeviceProperty(d.device, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED) != 0;
  d.simdLanes = simdLanesEnabled();
  d.withScene = rtcNewScene(d.device);
  d.withoutScene = rtcNewScene(d.device);
  d.surfaceCount = unsigned(scene.room.surfaces.size());
  d.buildRoomTriangles();
  for (unsigned i = 0; i < d.surfaceCount; ++i) {
    attachTriangles(d.device, d.withScene, i, scene.room.surfaces[i].meshWorld);
    attachTriangles(d.device, d.withoutScene, i, scene.room.surfaces[i].meshWorld);
  }
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const AreaLight& light = scene.lights[i];
    LightData l;
    l.emitter = emitterCorners(light);
    l.normal = light.normal();
    l.area = light.area();
    l.radiance = light.radiance.allFinite() ? Vec3(light.radiance.cwiseMax(0.0)) : Vec3(Vec3::Zero());
    const bool valid = l.normal.allFinite() && l.area > 0 && std::isfinite(l.area);
    l.rectangle = valid && asRectangle(l.emitter, &l.corner, &l.edgeX, &l.edgeY);
    if (!valid) l.area = 0, l.normal = Vec3(0, -1, 0);
    const double power = valid ? l.area * meanComponent(l.radiance) : 0.0;
    l.power = std::isfinite(power) ? power : 0.0;
    l.centre = 0.25 * (l.emitter[0] + l.emitter[1] + l.emitter[2] + l.emitter[3]);
    for (const Vec3& c : l.emitter) l.radius = std::max(l.radius, (c - l.centre).norm());
    l.firstTriangleShare = firstTriangleShare(l.emitter);
    d.lights.push_back(l);
    const unsigned geomId = d.surfaceCount + unsigned(i);
    if (valid) {
      attachQuad(d.device, d.withScene, geomId, l.emitter);
      attachQuad(d.device, d.withoutScene, geomId, l.emitter);
    }
  }
  d.objects.resize(scene.objects.size());
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const InsertedObject& src = scene.objects[i];
    ObjectData& o = d.objects[i];
    o.mesh = src.meshObject;
    o.material = src.material;
    if (o.mesh && !o.mesh->empty()) {
      // Built once per mesh: a tracer rebuilt after an edit instances the BVH it had.
      o.scene = sharedObjectBvh(o.mesh);
      if (o.scene) {
        o.instance = rtcNewGeometry(d.device, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(o.instance, o.scene);
      }
    }
    if (o.instance && !scene.suns.empty()) {
      o.sunInstance = rtcNewGeometry(d.device, RTC_GEOMETRY_TYPE_INSTANCE);
      rtcSetGeometryInstancedScene(o.sunInstance, o.scene);
    }
    // A multi-material asset lights by its emissive parts; any other object by its material.
    if (o.mesh && !src.partMaterials.empty() &&
        o.mesh->triangleMaterial.size() == o.mesh->triangles.size()) {
      o.parts = src.partMaterials;
      for (size_t k = 0; k < o.parts.size(); ++k)
        o.partMeshLight.push_back(d.addMeshLight(o, i, o.parts[k], int(k)));
    } else {
      o.meshLight = d.addMeshLight(o, i, o.material, -1);
    }
    d.setTransform(o, src.worldFromObject);
    d.updateMeshLight(i);
    if (o.instance) rtcAttachGeometryByID(d.withScene, o.instance, d.objectGeomId(i));
  }
  d.buildLightSelection();
  attachCardShadowFilters(d.withScene);
  attachCardShadowFilters(d.withoutScene);
  rtcCommitScene(d.withScene);
  rtcCommitScene(d.withoutScene);

  for (const SunLight& sun : d.scene.suns) {
    SunData sd;
    sd.sun = &sun;
    sd.toSun = -sun.travelDirection.normalized();
    sd.irradianceOverPi = sun.irradianceOverPi.allFinite() ? Vec3(sun.irradianceOverPi.cwiseMax(0.0))
                                                           : Vec3(Vec3::Zero());
    if (sd.toSun.allFinite() && sd.irradianceOverPi.maxCoeff() > 0) d.suns.push_back(sd);
  }
  if (!d.suns.empty()) {
    d.sunWithScene = rtcNewScene(d.device);
    d.sunWithoutScene = rtcNewScene(d.device);
    for (unsigned i = 0; i < d.surfaceCount; ++i) {
      if (isBoxSurface(scene.room.surfaces[i].kind)) continue;
      attachTriangles(d.device, d.sunWithScene, i, scene.room.surfaces[i].meshWorld);
      attachTriangles(d.device, d.sunWithoutScene, i, scene.room.surfaces[i].meshWorld);
    }
    for (size_t i = 0; i < d.objects.size(); ++i)
      if (d.objects[i].sunInstance)
        rtcAttachGeometryByID(d.sunWithScene, d.objects[i].sunInstance, d.objectGeomId(i));
    attachCardShadowFilters(d.sunWithScene);
    attachCardShadowFilters(d.sunWithoutScene);
    rtcCommitScene(d.sunWithScene);
    rtcCommitScene(d.sunWithoutScene);
  }
  if (d.options.sunPatchNee) d.buildSunPatches();
  d.buildCaustics();
}

PathTracer::~PathTracer() = default;

const RenderScene& PathTracer::scene() const { return impl_->scene; }

uint64_t PathTracer::objectBvhBuilds() { return sharedObjectBvhBuilds(); }

PathTracer::Stats PathTracer::stats() const {
  Stats s;
  const Impl::AtomicCounters& c = impl_->counters;
  s.nonFiniteSamples = impl_->nonFiniteSamples.load(std::memory_order_relaxed);
  s.byType.cameraRays = c.cameraRays.load(std::memory_order_relaxed);
  s.byType.bounceRays = c.bounceRays.load(std::memory_order_relaxed);
  s.byType.shadowRays = c.shadowRays.load(std::memory_order_relaxed);
  s.byType.cameraNs = c.cameraNs.load(std::memory_order_relaxed);
  s.byType.bounceNs = c.bounceNs.load(std::memory_order_relaxed);
  s.byType.shadowNs = c.shadowNs.load(std::memory_order_relaxed);
  s.byType.neeNs = c.neeNs.load(std::memory_order_relaxed);
  s.rays = s.byType.cameraRays + s.byType.bounceRays + s.byType.shadowRays;
  s.cameraRays = s.byType.cameraRays;
  s.shadowRays = s.byType.shadowRays;
  return s;
}

void PathTracer::setObjectTransform(size_t index, const Mat4& worldFromObject) {
  Impl& d = *impl_;
  if (index >= d.objects.size()) return;
  d.scene.objects[index].worldFromObject = worldFromObject;
  d.setTransform(d.objects[index], worldFromObject);
  d.updateMeshLight(index);
  if (d.objects[index].meshLight >= 0) d.buildLightSelection();  // its area may have changed
  rtcCommitScene(d.withScene);
  if (d.sunWithScene) rtcCommitScene(d.sunWithScene);
  d.buildCaustics();  // the glass moved, or what its caustic falls on
}

PathTracer::CausticStats PathTracer::causticStats() const {
  CausticStats c;
  c.photons = impl_->caustics.size();
  c.radius = impl_->caustics.radius();
  c.flux = impl_->caustics.totalFlux();
  return c;
}

// One pixel's guide records, summed in double (DifferentialBuffers' guide sums).
// Set to zero by clear(), not on construction (see PixelSums).
struct PathTracer::Impl::GuideSums {
  Vec3 albedo, normal, point;
  double distance, count, specular;
  void clear() {
    albedo.setZero(), normal.setZero(), point.setZero();
    distance = count = specular = 0;
  }
  void add(const PrimaryRecord& r) {
    albedo += r.albedo, normal += r.normal, point += r.point;
    distance += r.distance, count += 1, specular += r.specular ? 1 : 0;
  }
  void addTo(DifferentialBuffers& b, int x, int y) const {
    float* a = b.sumGuideAlbedo.pixel(x, y);
    float* n = b.sumGuideNormal.pixel(x, y);
    float* p = b.sumGuidePosition.pixel(x, y);
    for (int c = 0; c < 3; ++c)
      a[c] += float(albedo[c]), n[c] += float(normal[c]), p[c] += float(point[c]);
    float* d = b.sumGuideDistance.pixel(x, y);
    d[0] += float(distance), d[1] += float(count), d[2] += float(specular);
  }
};

// One pixel's samples, summed in double and added to the buffers once (so a pixel's sums do not
// depend on how its samples were grouped into tiles or packets).
// Left unset on construction and set by startPixel(): a packet keeps eight of them, which the
// compiler would otherwise clear with eight `rep stos` (a tenth of a camera ray's time outside
// Embree).
struct PathTracer::Impl::PixelSums {
  Vec3 with, without, change;
  double mask, diffSq, changeSq;
  GuideSums guide;
  Vec3 photo;  // the photo under the pixel (the change of an object pixel)
};

PathTracer::Impl::PixelScale PathTracer::Impl::pixelScale(const DifferentialBuffers& buffers) const {
  const Camera& cam = scene.camera;
  return {double(cam.widthPx) / buffers.width, double(cam.heightPx) / buffers.height};
}

// Where in the camera's pixel frame the camera ray of sample `rng` through pixel (x, y) of the
// buffers (scaled into that frame by `scale`) leaves.
Vec2 PathTracer::Impl::cameraPixel(int x, int y, const PixelScale& scale, const SampleRng& rng) const {
  return cameraPixelAt(x, y, scale, rng.get2(0));
}

// The same for the sample's numbers `jitter` (its pair 0).
Vec2 PathTracer::Impl::cameraPixelAt(int x, int y, const PixelScale& scale,
                                     const std::array<double, 2>& jitter) const {
  // The filter's width is in the camera's pixels: a coarse buffer's pixel (a preview, scale > 1)
  // covers several of them and samples its own cell, the box.
  if (scale.x > 1 || scale.y > 1) return Vec2((x + jitter[0]) * scale.x, (y + jitter[1]) * scale.y);
  return Vec2((x + pixelFilter.position(jitter[0])) * scale.x,
              (y + pixelFilter.position(jitter[1])) * scale.y);
}

// The direction of that camera ray.
Vec3 PathTracer::Impl::cameraDirection(int x, int y, const PixelScale& scale,
                                       const SampleRng& rng) const {
  return scene.camera.directionThroughPixel(cameraPixel(x, y, scale, rng));
}

// The camera ray in direction `dir`.
PathTracer::Impl::PathState PathTracer::Impl::cameraRay(const Vec3& dir) const {
  PathState st;
  st.origin = scene.camera.centreWorld();
  st.dir = dir;
  return st;
}

// Traces one sample's path from `st` (its first hit given, or cast here) and adds it to `p`.
void PathTracer::Impl::addSample(PixelSums& p, bool wantGuide, const PathState& st, const SampleRng& rng,
                                 const Hit* firstHit, const FirstVertex* first,
                                 RayCounters& tileCounters) const {
  Sums sums;
  PrimaryRecord rec;
  rec.wantGuide = wantGuide;
  tracePath(Mode::Shared, st, rng, sums, &rec, firstHit, first);
  tileCounters += sums.counters;
  if (rec.wantGuide) p.guide.add(rec);
  if (!sums.with.allFinite() || !sums.without.allFinite()) {
    nonFiniteSamples.fetch_add(1, std::memory_order_relaxed);
    return;  // dropped: counts as a sample of zero in both renders
  }
  p.with += sums.with;
  p.without += sums.without;
  p.mask += rec.objectFirst ? 1.0 : 0.0;
  p.diffSq += (sums.with - sums.without).squaredNorm() / 3.0;
  const Vec3 change = rec.objectFirst ? Vec3(sums.with - p.photo) : Vec3(sums.with - sums.without);
  p.change += change;
  p.changeSq += change.squaredNorm() / 3.0;
}

void PathTracer::Impl::storePixel(DifferentialBuffers& buffers, int x, int y, int count,
                                  const PixelSums& p) const {
  float* w = buffers.sumWith.pixel(x, y);
  float* wo = buffers.sumWithout.pixel(x, y);
  float* ch = buffers.sumChange.pixel(x, y);
  for (int c = 0; c < 3; ++c) {
    w[c] += float(p.with[c]);
    wo[c] += float(p.without[c]);
    ch[c] += float(p.change[c]);
  }
  buffers.sumChangeSq.at(x, y) += float(p.changeSq);
  buffers.sumMask.at(x, y) += float(p.mask);
  buffers.sumDiffSq.at(x, y) += float(p.diffSq);
  buffers.samples[size_t(y) * buffers.width + x] += count;
  if (buffers.hasGuides()) p.guide.addTo(buffers, x, y);
}

// Sets up the sums `p` of pixel (x, y) of the buffers: zero, and the photo under the pixel.
void PathTracer::Impl::startPixel(const DifferentialBuffers& buffers, int x, int y, PixelSums& p) const {
  p.with.setZero(), p.without.setZero(), p.change.setZero();
  p.mask = p.diffSq = p.changeSq = 0;
  p.guide.clear();
  const PixelScale scale = pixelScale(buffers);
  p.photo = photoAt(int((x + 0.5) * scale.x), int((y + 0.5) * scale.y));
}

// One pixel's samples [firstSample, firstSample + count), one ray at a time.
void PathTracer::Impl::renderPixel(DifferentialBuffers& buffers, int x, int y, int firstSample,
                                   int count, uint32_t seed, RayCounters& tileCounters) const {
  PixelSums p;
  startPixel(buffers, x, y, p);
  const PixelScale scale = pixelScale(buffers);
  for (int k = 0; k < count; ++k) {
    const SampleRng rng(uint32_t(x), uint32_t(y), uint32_t(firstSample + k), seed);
    addSample(p, buffers.hasGuides(), cameraRay(cameraDirection(x, y, scale, rng)), rng, nullptr,
              nullptr, tileCounters);
  }
  storePixel(buffers, x, y, count, p);
}

// Sample k of a packet's pixels x0 + i of row y, those with k < count[i] (lane j: pixel
// x0 + pixel[j]): each lane's SampleRng and the position its camera ray leaves from. With the
// lanes (simd_lanes.h), the rngs' keys, the jitter and, when verticesAhead(), the first vertex's
// four pairs come from one samplerLanesAvx2 call: the same numbers as the rngs draw.
void PathTracer::Impl::packetLanes(int x0, int y, int n, const int* first, const int* count, int k,
                                   uint32_t seed, const PixelScale& scale, PacketLanes& p) const {
  static_assert(kSamplerLanes == kPacket && kFirstVertexDim / 2 + 4 <= kSamplerPairs);
  p.m = 0;
  for (int i = 0; i < n; ++i)
    if (k < count[i]) p.pixel[size_t(p.m++)] = i;
  SamplerLanes& s = p.numbers;
  if (simdLanes && p.m > 0) {
    s.seed = seed, s.pairs = verticesAhead() ? int(kFirstVertexDim / 2 + 4) : 1;
    for (int q = 0; q < s.pairs; ++q) s.pairHash[q] = SampleRng::pairHash(uint32_t(q));
    s.sobol1Reversed = &kSobol1Reversed.byByte[0][0];
    for (int l = 0; l < kSamplerLanes; ++l) {
      const int i = p.pixel[size_t(std::min(l, p.m - 1))];
      s.x[l] = uint32_t(x0 + i), s.y[l] = uint32_t(y), s.sample[l] = uint32_t(first[i] + k);
    }
    samplerLanesAvx2(s);
  }
  for (int j = 0; j < p.m; ++j) {
    const int x = x0 + p.pixel[size_t(j)];
    const uint32_t sample = uint32_t(first[p.pixel[size_t(j)]] + k);
    Vec2 at;
    if (simdLanes) {
      p.rngs[size_t(j)] = SampleRng::fromKey(s.pixelKey[j], sample, s.reversedSample[j]);
      at = cameraPixelAt(x, y, scale, {s.u[0][0][j], s.u[0][1][j]});
    } else {
      p.rngs[size_t(j)] = SampleRng(uint32_t(x), uint32_t(y), sample, seed);
      at = cameraPixel(x, y, scale, p.rngs[size_t(j)]);
    }
    p.px[size_t(j)] = at.x(), p.py[size_t(j)] = at.y();
  }
}

// Pixels x0 .. x0 + n - 1 (n <= kPacket) of row y, pixel i's samples [first[i], first[i] +
// count[i]): sample k of every pixel that has it leaves the camera in one packet, then each path
// goes on alone. A pixel's sums are those renderPixel() gives when the packet finds the same hits.
void PathTracer::Impl::renderPacket(DifferentialBuffers& buffers, int x0, int y, int n, const int* first,
                                    const int* count, uint32_t seed, RayCounters& tileCounters) const {
  std::array<PixelSums, kPacket> sums;
  std::array<FirstVertex, kPacket> firsts;
  const bool ahead = verticesAhead();
  int most = 0;
  for (int i = 0; i < n; ++i)
    startPixel(buffers, x0 + i, y, sums[size_t(i)]), most = std::max(most, count[i]);
  const PixelScale scale = pixelScale(buffers);
  PacketLanes lanes;
  for (int k = 0; k < most; ++k) {
    // The lanes' numbers and pixel positions, then their directions two at a time.
    packetLanes(x0, y, n, first, count, k, seed, scale, lanes);
    const int m = lanes.m;
    std::array<Vec3, kPacket> dirs;
    directionsThroughPixels(scene.camera, m, lanes.px.data(), lanes.py.data(), dirs.data());
    std::array<Hit, kPacket> hits;
    castCameraPacket(m, scene.camera.centreWorld(), dirs.data(), hits.data(), tileCounters);
    if (ahead) firstVertices(lanes, dirs.data(), hits.data(), firsts.data(), tileCounters);
    for (int j = 0; j < m; ++j)
      addSample(sums[size_t(lanes.pixel[size_t(j)])], buffers.hasGuides(), cameraRay(dirs[size_t(j)]),
                lanes.rngs[size_t(j)], &hits[size_t(j)], ahead ? &firsts[size_t(j)] : nullptr,
                tileCounters);
  }
  for (int i = 0; i < n; ++i)
    if (count[i] > 0) storePixel(buffers, x0 + i, y, count[i], sums[size_t(i)]);
}

// Renders the pixels of [x0,x1) x [y0,y1) (clipped to the buffers) by `renderOne(x, y, counters)`
// with flush-to-zero on and the ray counters published once at the end; false when `cancel`
// stopped it (checked per pixel).
template <class RenderRun>
bool PathTracer::Impl::renderPixels(const DifferentialBuffers& buffers, int x0, int y0, int x1, int y1,
                                    const CancelToken* cancel, RenderRun&& renderRun) const {
  INLAY_CHECK(buffers.width > 0 && buffers.height > 0 &&
              buffers.samples.size() == size_t(buffers.width) * buffers.height);
  x0 = std::max(0, x0), y0 = std::max(0, y0);
  x1 = std::min(buffers.width, x1), y1 = std::min(buffers.height, y1);
  if (scene.camera.widthPx <= 0 || scene.camera.heightPx <= 0) return true;
  DenormalsOffScope ftz;
  RayCounters rectCounters;  // published once, when the rect ends or is cancelled
  struct Publish {
    const Impl& d;
    const RayCounters& c;
    ~Publish() { d.counters.add(c); }
  } publish{*this, rectCounters};
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; x += kPacket) {
      if (cancel && cancel->shouldStop()) return false;
      // The next run's first reads (its camera hits' texels and albedo, cache misses at one
      // sample a pixel) are fetched while this run renders.
      const bool sameRow = x + kPacket < x1;
      if (sameRow || y + 1 < y1)
        prefetchRun(buffers, sameRow ? x + kPacket : x0, sameRow ? y : y + 1,
                    std::min(kPacket, x1 - (sameRow ? x + kPacket : x0)));
      renderRun(x, y, std::min(kPacket, x1 - x), rectCounters);
    }
  return true;
}

// Prefetches the room records camera hits through pixels x .. x + n - 1 of row y of the buffers
// read first (RoomTexture::prefetchRun).
void PathTracer::Impl::prefetchRun(const DifferentialBuffers& buffers, int x, int y, int n) const {
  const double w = buffers.width, h = buffers.height;
  room.prefetchRun((x + 0.5) / w, (x + n - 0.5) / w, (y + 0.5) / h);
}

// The arena render() and renderCounts() run their tiles in, kept from one call to the next
// (the session's waves) and made again only when the thread count changes.
std::shared_ptr<tbb::task_arena> PathTracer::Impl::arenaFor(int threads) const {
  std::lock_guard<std::mutex> lock(arenaMutex);
  if (!arena || arenaThreads != threads) {
    const int concurrency = threads > 0 ? threads : int(tbb::task_arena::automatic);
    arena = std::make_shared<tbb::task_arena>(concurrency);
    arenaThreads = threads;
  }
  return arena;
}

// Calls renderTile(x0, y0, x1, y1) for every kTileSize tile of a width x height frame in
// parallel; false when a tile returned false or `cancel` stopped the wave.
template <class RenderTile>
bool PathTracer::Impl::forEachTile(int width, int height, int threads, const CancelToken* cancel,
                                   RenderTile&& renderTile) const {
  const int tilesX = (width + kTileSize - 1) / kTileSize;
  const int tilesY = (height + kTileSize - 1) / kTileSize;
  std::atomic<bool> stopped{false};
  const std::shared_ptr<tbb::task_arena> a = arenaFor(threads);
  a->execute([&] {
    parallelFor(tbb::blocked_range<int>(0, tilesX * tilesY, 1), [&](const tbb::blocked_range<int>& r) {
      for (int t = r.begin(); t != r.end(); ++t) {
        if (stopped.load(std::memory_order_relaxed) || (cancel && cancel->shouldStop())) {
          stopped = true;
          return;
        }
        const int tx = t % tilesX, ty = t / tilesX;
        if (!renderTile(tx * kTileSize, ty * kTileSize, (tx + 1) * kTileSize, (ty + 1) * kTileSize))
          stopped = true;
      }
    });
  });
  return !stopped.load();
}

bool PathTracer::renderRect(DifferentialBuffers& buffers, int x0, int y0, int x1, int y1,
                            int firstSample, int count, uint32_t seed, const CancelToken* cancel) const {
  const Impl& d = *impl_;
  std::array<int, Impl::kPacket> firsts, counts;
  firsts.fill(firstSample), counts.fill(count);
  return d.renderPixels(
      buffers, x0, y0, x1, y1, cancel, [&](int x, int y, int n, RayCounters& counters) {
        if (d.cameraPackets())
          return d.renderPacket(buffers, x, y, n, firsts.data(), counts.data(), seed, counters);
        for (int i = 0; i < n; ++i) d.renderPixel(buffers, x + i, y, firstSample, count, seed, counters);
      });
}

bool PathTracer::render(DifferentialBuffers& buffers, int firstSample, int count, uint32_t seed,
                        int threads, const CancelToken* cancel) const {
  return impl_->forEachTile(
      buffers.width, buffers.height, threads, cancel, [&](int x0, int y0, int x1, int y1) {
        return renderRect(buffers, x0, y0, x1, y1, firstSample, count, seed, cancel);
      });
}

bool PathTracer::renderCounts(DifferentialBuffers& buffers, const std::vector<int>& counts,
                              uint32_t seed, int threads, const CancelToken* cancel) const {
  const Impl& d = *impl_;
  INLAY_CHECK(counts.size() == buffers.samples.size());
  return d.forEachTile(
      buffers.width, buffers.height, threads, cancel, [&](int x0, int y0, int x1, int y1) {
        return d.renderPixels(
            buffers, x0, y0, x1, y1, cancel, [&](int x, int y, int n, RayCounters& counters) {
              const size_t at = size_t(y) * buffers.width + x;
              std::array<int, Impl::kPacket> firsts{}, runCounts{};
              for (int i = 0; i < n; ++i)
                firsts[size_t(i)] = buffers.samples[at + size_t(i)],
                runCounts[size_t(i)] = std::max(0, counts[at + size_t(i)]);
              if (d.cameraPackets())
                return d.renderPacket(buffers, x, y, n, firsts.data(), runCounts.data(), seed, counters);
              for (int i = 0; i < n; ++i)
                if (runCounts[size_t(i)] > 0)
                  d.renderPixel(buffers, x + i, y, firsts[size_t(i)], runCounts[size_t(i)], seed,
                                counters);
            });
      });
}

PathTracer::FirstHit PathTracer::firstHit(const Vec2& pixel) const {
  const Impl& d = *impl_;
  FirstHit out;
  const Vec3 eye = d.scene.camera.centreWorld();
  const Vec3 dir = d.scene.camera.directionThroughPixel(pixel).normalized();
  const Hit hit = d.intersect(d.withScene, eye, dir, 0, 0.5);
  if (hit.kind == Hit::Kind::None || !dir.allFinite()) return out;
  out.hit = true;
  out.object = hit.kind == Hit::Kind::Object;
  out.distance = hit.t;
  out.point = hit.point;
  out.normal = hit.shadingNormal.dot(dir) > 0 ? Vec3(-hit.shadingNormal) : hit.shadingNormal;
  if (hit.kind == Hit::Kind::Room) {
    const Material* m = d.roomMaterial(hit.index);
    out.albedo = m && m->kind == Material::Kind::Mirror ? m->albedo
                                                        : d.room.albedo(hit.index, hit.texel);
  } else if (hit.kind == Hit::Kind::Object) {
    const Material& m = d.objects[size_t(hit.index)].materialOf(hit.prim);
    const bool coloured = m.kind != Material::Kind::Glass && m.kind != Material::Kind::RoughGlass &&
                          m.kind != Material::Kind::Emissive;
    if (coloured) out.albedo = m.albedo;
  }
  out.albedo = out.albedo.allFinite() ? Vec3(out.albedo.cwiseMax(0.0).cwiseMin(1.0))
                                      : Vec3(Vec3::Ones());
  return out;
}

}  // namespace inlay
