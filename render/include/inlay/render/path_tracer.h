// The Embree path tracer, differential by construction.
//
// One camera path is traced per (pixel, sample) in the scene WITH the inserted objects; the
// scene WITHOUT them shares the same random numbers (a pure function of pixel, sample,
// dimension and seed) and the same path prefix until the with-object path meets an object (a
// hit or a blocked shadow ray); only from there on is the without-object path traced on its
// own. So withObjects - withoutObjects is exactly zero wherever no path meets an object.
//
// Thread safety: after construction, render*() may run concurrently on disjoint pixel sets;
// setObjectTransform() must not overlap with rendering (the session serialises them).
#pragma once

#include "inlay/modeling/core.h"
#include "inlay/modeling/image.h"
#include "inlay/render/scene.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace inlay {

struct RayLog;

struct TracerOptions {
  int maxDepth = 8;  // path vertices after the camera (bounces), smooth glass apart
  // Smooth (clear) glass vertices a path may pass, counted apart from maxDepth: a refraction or
  // a reflection at a clear dielectric. A path inside a glass object with folds (an ear, a
  // handle) reflects internally several times before it leaves; cut at maxDepth it was black.
  // 12 is the truth renderer's (Cycles') transmission and total limit. With interpolated normals
  // a few paths stay trapped inside whatever the limit (the shading normal reflects them where
  // the facet would let them out): about 5 % on a 3 x 6 facet ball, 0.7 % with flat facets.
  int maxGlassDepth = 12;
  // At the camera's first smooth-glass vertex trace both the reflection (weight F) and the
  // refraction (1 - F) instead of picking one by F: one more path per glass pixel, none of the
  // Fresnel choice's noise there.
  bool splitGlassAtCamera = true;
  // Caustics of smooth glass objects by a photon pass (a light-traced caustic map): when the
  // scene holds a smooth glass object, about this many photons in all leave the area lights and
  // suns toward the glass objects' bounding spheres, pass the glass (Fresnel, Snell, up to
  // maxGlassDepth vertices) and are stored where they land on a Lambertian surface. Their
  // density, within causticRadius x the smallest glass object's bounding radius, lights every
  // Lambertian vertex of the with-objects render; those vertices' paths through smooth glass to
  // an area light are no longer counted (they are the same light). Built with the tracer and
  // again at every setObjectTransform (about a second for 2e5 photons on the loaded machine).
  // 0 (the default): off, the caustic found by BSDF sampling alone; scenes without smooth glass
  // render as with 0. Off by default because the benchmark's truth renderer (Cycles' MNEE) draws
  // far weaker caustics than this (docs/generalization.md, "Caustic photons"); the CLI's
  // --caustic-photons turns it on.
  int causticPhotons = 0;
  double causticRadius = 0.05;
  int russianRouletteDepth = 3;  // roulette starts at this depth
  double clampRadiance = 0;      // per-sample clamp of indirect radiance; 0 = off (unbiased)
  bool timeRays = false;         // time every ray by type (benchmarks: two clock reads per ray)
  bool timeNee = false;          // time next-event estimation alone (RayCounters::neeNs; two clock
                                 // reads per NEE vertex, none per ray): implied by timeRays
  bool roughGlassNee = true;     // next-event estimation (with MIS) at rough glass; false: found
                                 // by BSDF sampling alone (for comparison; suns then miss it)
  // The camera's pixel filter (render/src/pixel_filter.h): 0 the box of the pixel; w > 0 a
  // Blackman-Harris window reaching w pixels either side of the pixel's centre (Cycles'
  // filter_width). 1.5, Cycles' default and the benchmark truth's: chosen on half A over the
  // box (docs/generalization.md, "t06's object error, taken apart").
  double pixelFilterWidth = 1.5;
  // Next-event estimation (with MIS) toward the sunlit patches the photo shows (the texels of
  // a sun's lit mask that bounces read the photo's radiance at): without it a bounce finds such
  // a bright patch by BSDF sampling alone, as fireflies. Scenes without a sun are unaffected.
  bool sunPatchNee = true;
  // How next-event estimation picks one light (area light or emissive object) per vertex:
  // Spatial weighs every source by power over squared distance, skipping those behind the
  // vertex (O(n) per vertex, each weight computed once); Power draws from a table proportional
  // to power built once per scene (O(log n), whatever the vertex); Auto uses Spatial up to
  // spatialSelectionMax sources and Power above. All are unbiased (MIS uses the same pdf).
  // Measured (bench_light_selection, one bright and the rest dim, 1 to 256 lights): the table's
  // noise at equal samples is about twice the spatial rule's from 16 lights on; its lower cost
  // per sample repays that only from about 256 lights (equal noise^2 x time there, twice the
  // spatial rule's at 64 and 128); hence the spatial rule up to 256 sources.
  enum class LightSelection { Auto, Spatial, Power };
  LightSelection lightSelection = LightSelection::Auto;
  int spatialSelectionMax = 256;
  // Benchmarks: every ray the tracer casts is appended here as Embree receives it (one logical
  // ray each, before any occluder-card pass). Not thread-safe: render with one thread.
  RayLog* rayLog = nullptr;
};

// Rays as the tracer handed them to Embree (TracerOptions::rayLog), so a benchmark can cast the
// same rays through a bare Embree loop.
struct LoggedRay {
  enum class Type : uint8_t { Camera, Bounce, Shadow };
  // The scene it was cast into: the room with or without the objects, or what a sun's shadow
  // ray sees (no box walls, no emitters) with or without them.
  enum class Target : uint8_t { With, Without, SunWith, SunWithout };
  Type type = Type::Camera;
  Target target = Target::With;
  float org[3] = {0, 0, 0}, dir[3] = {0, 0, 0};
  float tnear = 0, tfar = 0;  // tfar: infinity for camera and bounce rays
};
struct RayLog {
  std::vector<LoggedRay> rays;
};

// Rays traced by type, and the thread time spent in them (nanoseconds, summed over threads;
// 0 unless TracerOptions::timeRays). count / (ns * 1e-9) is rays per second per thread.
struct RayCounters {
  uint64_t cameraRays = 0;  // the first ray of a path (again without the objects, once it
                            // met one)
  uint64_t bounceRays = 0;  // every later path segment
  uint64_t shadowRays = 0;  // NEE and sun shadow rays
  int64_t cameraNs = 0, bounceNs = 0, shadowNs = 0;
  // Thread time in next-event estimation as a whole (light pick, point on the light, BSDF
  // evaluation, shadow rays; suns included), when timeRays or timeNee: what a shadow ray costs
  // the renderer.
  int64_t neeNs = 0;
  RayCounters& operator+=(const RayCounters& o) {
    cameraRays += o.cameraRays, bounceRays += o.bounceRays, shadowRays += o.shadowRays;
    cameraNs += o.cameraNs, bounceNs += o.bounceNs, shadowNs += o.shadowNs, neeNs += o.neeNs;
    return *this;
  }
};

// Running sums of a differential render at full resolution. mean = sum / samples[pixel].
struct DifferentialBuffers {
  int width = 0, height = 0;
  ImageF sumWith;     // W x H x 3, radiance of the scene with objects
  ImageF sumWithout;  // W x H x 3, radiance of the scene without objects
  ImageF sumMask;     // W x H x 1, fraction of camera samples whose first hit is an object
  ImageF sumDiffSq;   // W x H x 1, sum over samples of |with - without|^2 (mean over RGB)
  // What each sample makes of the composite, less the photo: with - photo where the camera
  // ray's first hit is an object, with - without elsewhere (the photo pixel is a constant, so
  // these sums give the composite's per-pixel variance, mask noise included; with no photo in
  // the scene, photo = 0).
  ImageF sumChange;          // W x H x 3
  ImageF sumChangeSq;        // W x H x 1, sum of |change|^2 (mean over RGB)
  std::vector<int> samples;  // per pixel
  // The denoiser's guides (render/denoise.h), summed over samples; empty (0 x 0) unless
  // enableGuides() was called, and then the radiance sums above are the same bits as without.
  // Each sample's camera path records the first surface along its specular chain (smooth
  // mirror and glass, metal and frosted glass of roughness below 0.1) that is not specular,
  // i.e. what the pixel shows: its albedo (times the chain's reflectances; 1 for glass, lights
  // and emitters, and where the path meets nothing), its shading normal facing the path, its
  // world position, and the path's length to it (1e6 for no hit); and whether it was seen
  // through a specular surface.
  ImageF sumGuideAlbedo;    // W x H x 3
  ImageF sumGuideNormal;    // W x H x 3 (a sum of unit vectors)
  ImageF sumGuidePosition;  // W x H x 3, metres
  ImageF sumGuideDistance;  // W x H x 3: path length (metres), records, records that met a
                            // specular surface first

  DifferentialBuffers() = default;
  DifferentialBuffers(int w, int h);
  void clear();
  void enableGuides();
  bool hasGuides() const {
    return sumGuideDistance.width == width && width > 0 && !sumGuideDistance.data.empty();
  }
  // Means (W x H x 3, x 3, x 1) with unsampled pixels left 0.
  ImageF meanWith() const;
  ImageF meanWithout() const;
  ImageF meanMask() const;
};

class PathTracer {
 public:
  explicit PathTracer(const RenderScene& scene, const TracerOptions& options = {});
  ~PathTracer();
  PathTracer(const PathTracer&) = delete;
  PathTracer& operator=(const PathTracer&) = delete;

  // The tracer's copy of the scene. Its roomAlbedo keeps the camera, the surface means and the
  // photo only: the albedo, first-surface and usable tables live in the tracer's room texture
  // (read them from the RenderScene the tracer was made from).
  const RenderScene& scene() const;
  // Object BVHs built so far by every tracer of the process. An object's BVH (object space) is
  // built once per mesh while the mesh lives and shared by the tracers that instance it, so a
  // tracer made again after an edit that kept the meshes (a material, hide, insert or delete of
  // another object, undo) builds none (tests count them).
  static uint64_t objectBvhBuilds();
  // Moves object `index` (an instance transform update; its BVH is not rebuilt).
  void setObjectTransform(size_t index, const Mat4& worldFromObject);

  // Adds samples [firstSample, firstSample + count) for every pixel in [x0,x1) x [y0,y1).
  // Returns false when `cancel` stopped it (the buffers then hold whole samples only for the
  // pixels completed).
  bool renderRect(DifferentialBuffers& buffers, int x0, int y0, int x1, int y1, int firstSample,
                  int count, uint32_t seed, const CancelToken* cancel = nullptr) const;
  // The whole frame, parallel over tiles with `threads` threads (0 = all cores).
  bool render(DifferentialBuffers& buffers, int firstSample, int count, uint32_t seed, int threads = 0,
              const CancelToken* cancel = nullptr) const;
  // Adds counts[y * width + x] samples to every pixel, each pixel continuing its own sequence
  // from buffers.samples (the session's focused and adaptive waves), parallel over tiles as
  // render(). counts holds one entry per pixel of the buffers.
  bool renderCounts(DifferentialBuffers& buffers, const std::vector<int>& counts, uint32_t seed,
                    int threads = 0, const CancelToken* cancel = nullptr) const;
  // Counters since construction (all threads): rays traced (camera, bounce and shadow rays in
  // either scene), and samples dropped because a value was not finite (they count as zero in
  // both renders).
  struct Stats {
    uint64_t rays = 0;
    uint64_t nonFiniteSamples = 0;
    uint64_t cameraRays = 0;  // of `rays`: camera rays, and shadow rays (NEE, suns); the rest
    uint64_t shadowRays = 0;  // are bounce rays
    RayCounters byType;       // the same counts by type, with their times
  };
  Stats stats() const;

  // What the camera ray through `pixel` (the camera's pixel frame) meets first in the scene
  // with the objects (an occluder card is passed where its alpha is below one half): the
  // denoiser's guides (denoise.h). albedo: the surface's reflectance (the projected albedo on
  // the room, a mirror's reflectance), 1 for glass, lights and emissive objects.
  struct FirstHit {
    bool hit = false;
    bool object = false;
    double distance = 0;
    Vec3 point = Vec3::Zero(), normal = Vec3::Zero(), albedo = Vec3::Ones();
  };
  FirstHit firstHit(const Vec2& pixel) const;

  // The caustic map (TracerOptions::causticPhotons) as built for the objects' current place:
  // photons stored, their radius (metres) and total flux (W, summed over RGB / 3); zero when the
  // scene has no smooth glass or the pass is off.
  struct CausticStats {
    size_t photons = 0;
    double radius = 0;
    double flux = 0;
  };
  CausticStats causticStats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Queries on the empty room for the lighting stage (gather rays, direct light), through Embree.
class RoomTracer {
 public:
  explicit RoomTracer(const SceneGeometry& room);
  ~RoomTracer();
  RoomTracer(const RoomTracer&) = delete;
  RoomTracer& operator=(const RoomTracer&) = delete;

  std::optional<SurfaceHit> intersect(const Ray& ray, double tMin = 1e-5) const;
  // True when the open segment a-b crosses no surface.
  bool visible(const Vec3& a, const Vec3& b) const;
  // Irradiance over pi at point p (normal n) due to `light` if its radiance were 1 in every
  // channel, with shadows, from `samples` stratified points on the light (deterministic in
  // `seed`). Points behind the light or facing away get 0.
  double unitLightIrradianceOverPi(const AreaLight& light, const Vec3& p, const Vec3& n, int samples,
                                   uint32_t seed) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Irradiance over pi at p (normal n) that `sun` would give with strength 1 in every channel:
// its beam mask at p, times the cosine, times whether anything inside the room (an extrusion, an
// occluder card) stands between p and the opening. The box's own walls never block: the
// opening is in them.
double unitSunIrradianceOverPi(const RoomTracer& tracer, const SceneGeometry& room, const SunLight& sun,
                               const Vec3& p, const Vec3& n);

}  // namespace inlay
