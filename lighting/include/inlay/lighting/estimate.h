// The lighting stage: the room's albedo and its lights' intensities from one photo.
//
// Model (per pixel x on the room, per channel, all in the photo's linear units):
//   B(x) = rho(x) * ( sum_j L_j * E_j(x) + Gamma(x) )
// where E_j is the irradiance / pi that light j would give with unit radiance (shadowed, from
// the room geometry), Gamma the indirect irradiance / pi gathered from the photo itself (each
// gather ray's hit point is projected into the photo; what the photo does not show radiates
// its surface's fitted albedo times the fitted lights' direct light plus the light gathered at
// its patch, by radiosity sweeps over surface patches, gather.h), and rho the albedo. Light
// radiances L_j and per-surface reference albedos are found by a bounded robust least-squares
// fit (Ceres) that asks the albedo to be smooth within each surface; rho(x) = B / (sum L_j E_j
// + Gamma) then follows per pixel (physicalAlbedo).
// The albedo itself comes from the intrinsic decomposition (decompose.h): colour Retinex of that
// shading-free image, scaled per channel to it, minimised under the paper's objective with
// B = D + rho * Gamma. Saturated pixels and light outlines are left out of fit and data terms.
#pragma once

#include "inlay/lighting/decompose.h"
#include "inlay/modeling/camera.h"
#include "inlay/modeling/core.h"
#include "inlay/modeling/geometry.h"
#include "inlay/modeling/image.h"
#include "inlay/render/scene.h"

#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace inlay {

// The rays an estimate traced for its gather and for the light gathered at the room's patches
// (estimate.cpp): their hits, kept so that a second estimate of the same photo, camera, room and
// lights' mask (the refit after the lights' refinement) replays them instead of tracing them
// again (LightingOptions::reuseRays). The hits do not depend on the lights.
struct LightingRays;
struct PendingDecomposition;

// The decomposition of a working copy larger than a 640 x 480 photo runs on block means of at
// most this many pixels, its change to the start carried back bilinearly
// (DecomposeOptions::maxSolvePixels): 2 x 2 blocks at the 816 x 612 working copy of a 3 or 12 MP
// photo, a quarter of the solver's work; every photo up to 640 x 480 (dev rooms, York photos,
// the 0.3 MP example) is decomposed as before (docs/benchmarks.md, "The decomposition on block
// means").
inline constexpr long kLightingDecomposeMaxPixels = 640 * 480;

// The lighting's decomposition options: the defaults with kLightingDecomposeMaxPixels.
inline DecomposeOptions lightingDecomposeOptions() {
  DecomposeOptions d;
  d.maxSolvePixels = kLightingDecomposeMaxPixels;
  return d;
}

// The least albedo an unseen ceiling is given (neutral grey; its luminance): ceilings are painted
// white far more often than walls are, so the walls' mean is a poor guess for them in a room
// with dark or tiled walls. 0.77 is the median of half A's seven ceilings (scenes-train t01..t13:
// 0.71-0.86 against walls of 0.34-0.81); an object lit from above by a ceiling the photo does
// not show came out 6-9 % too dark in linear light with the walls' mean (docs/generalization.md,
// "The ~6 % darker diffuse object").
inline constexpr double kUnseenCeilingAlbedo = 0.77;

struct LightingOptions {
  // Cosine-weighted rays per gathered pixel (gather.h); 0: chosen from a pilot so that Gamma's
  // relative standard error per gathered pixel is about gatherNoise.
  int gatherSamples = 0;
  double gatherNoise = 0.05;
  int gatherStride = 4;  // gather on every n-th pixel, interpolate between
  // The gather's grid (and E_j's) has at most this many points: a larger photo (or working copy)
  // gathers on a sparser grid, as many points over the room as a 640 x 480 photo's at stride 4
  // (gatherStrideFor). The gathered light is smooth within a surface, so more points over the
  // same room only cost time (a 0.5 MP working copy: 31 k points at stride 4, 1.6 times the
  // gather of a 0.3 MP photo). 0: no cap.
  int gatherMaxPoints = 160 * 120;
  // What the photo does not show radiates its albedo times the light gathered at its patch:
  // patches about room size / patchesAcrossRoom wide, patchSamples rays each, patchSweeps
  // radiosity sweeps (gather.h, SurfacePatches).
  double patchesAcrossRoom = 20;
  int patchSamples = 64;
  int patchSweeps = 3;
  int directSamples = 16;  // points per light for E_j
  // The fit and the gathered light depend on each other through what the camera does not see
  // (its radiance is predicted from the fitted albedo and lights). The first pass guesses it
  // from the mean of what the camera sees; later passes predict it from the previous fit, each
  // pass's Gamma mixed with the previous one's (Gamma <- r Gamma_new + (1 - r) Gamma_old): a
  // light behind the camera makes the plain iteration overshoot and swing (Gamma too low, then
  // far too high), and stopping after the second pass kept the overshoot (albedo too dark, the
  // light too bright). Passes stop when the mean Gamma changes by less than passTolerance
  // (relative), after at most maxPasses. Rooms with a sun: sunRoomToFixedPoint.
  int maxPasses = 5;
  // A room with a sun: its pass 2 gathers the sunlit patch apart; from pass 3 on the passes are
  // relaxed and stop as the plain ones do (at most maxPasses, at least 3). False: the scheme
  // before, sunRoomPasses plain passes (2: not a fixed point of the passes, the sky of a window
  // out of view in a side wall low; docs/generalization.md, "The sun room's passes to a fixed
  // point").
  bool sunRoomToFixedPoint = true;
  int sunRoomPasses = 2;
  double passRelaxation = 0.5;
  double passTolerance = 0.03;
  int fitPixels = 6000;  // pixels sampled for the fit
  // The light fit's solver stops when its cost changes by less than this fraction in an
  // iteration (Ceres' function_tolerance; its default). A coarser one ends the fit sooner: the
  // pipeline's response check compares two responses on small copies with 1e-3
  // (ResponseQuickCheck in app/engine/pipeline.h). Outside (0, 1) (NaN too): Ceres' default.
  double fitFunctionTolerance = 1e-6;
  // The fit reads each pixel as the mean of the photo over the (2 fitWindow + 1)^2 pixels around
  // it on the same surface (0: the pixel alone): the log of a noisy or finely textured pixel is
  // biased low, which made the albedo too dark and the lights too bright (estimate.cpp; chosen on
  // half A of the training rooms, docs/generalization.md).
  int fitWindow = 4;
  double saturatedAbove = 0.98;  // linear value treated as clipped
  // Luminance below which a photo pixel is black (no measurement): the light fit leaves it out,
  // the decomposition's data terms below a tenth of it, the fit's log floors at a hundredth. 1e-4
  // is below sRGB's code 1 (3e-4); a camera response with a long highlight shoulder decodes far
  // more of the codes below it (shoulder 1000: code 85), so the pipeline scales it with the
  // response's code 1 (blackLevelOf in pipeline.cpp; docs/camera-response.md).
  double blackBelow = 1e-4;
  // A pixel whose photo over the modelled shading exceeds this in a channel is not explained by
  // the model (a light or opening it lacks, wrong geometry): its albedo comes from the photo's
  // Retinex and the decomposition's data terms leave it out.
  double unexplainedAbove = 1.25;
  uint32_t seed = 7;
  int threads = 0;
  // The albedo: Retinex anchored to the fitted lights (the start), then the geometry-aware
  // objective (decompose.h) unless `objective` is false.
  RetinexOptions retinex;
  DecomposeOptions decompose = lightingDecomposeOptions();
  bool objective = true;
  // Several estimated lights whose centres are out of the photo's view share one radiance (the
  // first's): the photo shows only the sum of their light on the walls, and a free split drifts
  // (scenes-train t11, docs/generalization.md). False: each gets its own.
  bool tieLightsOutOfView = true;
  // Diagnostics (an oracle): when every channel is >= 0, the albedo the fit's own model of the
  // room gives a ceiling the camera does not see (its passes' unseen patches), instead of the
  // walls' mean (albedoOfUnseen). The fitted lights follow it (docs/generalization.md, "The
  // lights' intensity and the unseen ceiling"). Negative: the product's rule.
  // One sun: also gather its light that reaches the seen room by way of the surfaces the camera
  // does not see, per unit strength (LightingEstimate::sunBounceUnseen), for the bounce fit of a
  // clipped sun (PrepareOptions::sunsFromBounce). Off: not computed (the fit never uses it).
  bool gatherSunBounceUnseen = false;
  Vec3 fitUnseenCeilingAlbedo = Vec3::Constant(-1);
  // From the second pass on, the light the walls the camera does not see bounce from each area
  // light's direct light (their albedo x that light's unit irradiance, gathered per unit
  // radiance) enters the fit as a term proportional to that light, E_j + U_j, instead of a fixed
  // part of Gamma at the previous pass's radiance: the fit then sees that this part of Gamma has
  // no scale of its own (docs/generalization.md, "The unseen room's bounce in the light fit").
  // False: the fixed part, as before (diagnostics).
  bool unseenBounceScalesWithLights = true;
  // The same for a light whose centre is out of the photo's view (false: its unseen bounce stays
  // a fixed part of Gamma).
  bool unseenBounceOfLightsOutOfView = false;
  // With that term: the albedo of a ceiling the camera does not see is an unknown of the fit (per
  // channel, bounded to [0.05, 1]), told by the light it bounces onto the seen room, with a weak
  // prior toward the fitted walls' mean: a residual unseenCeilingPriorWeight x log(ceiling /
  // walls' mean) beside the pixels' log residuals (0.3: the fit's robust scale, 0.15, over a prior
  // standard deviation of 0.5 in log albedo). Where the photo tells it less than the prior does,
  // it falls back to the walls' mean and a note says so (docs/generalization.md, "The unseen
  // ceiling's albedo as an unknown of the light fit"). False: the walls' mean, as before.
  bool fitUnseenCeiling = true;
  double unseenCeilingPriorWeight = 0.3;
  // The render's unseen ceiling (LightingEstimate::surfaceMeanAlbedo): true, the fit's estimate
  // where the photo told it (each channel); false (or not told), albedoOfUnseen's rule with
  // kUnseenCeilingAlbedo.
  bool renderFittedCeiling = false;
  // In a room with a sun, the least albedo (grey, in luminance) the fit's own model of the
  // unseen room gives a ceiling it makes no estimate of (no unknown for it: no in-view light
  // whose bounce is apart), as the render does (kUnseenCeilingAlbedo); the walls' mean when they
  // are brighter. The sunlit patch lights the ceiling straight on, and its bounce off the ceiling
  // is much of the light on the seen walls, so the walls' mean (t04: 0.45 against 0.89) left
  // Gamma short and the albedo 1.3 to 1.5 times too bright everywhere. Chosen on synthetic sun
  // rooms; a room without a sun keeps the walls' mean (there half A's t13 came out worse with
  // the floor). docs/generalization.md, "The sun rooms' albedo: the unseen ceiling". 0: the
  // walls' mean (the rule before).
  double sunRoomUnseenCeilingAtLeast = kUnseenCeilingAlbedo;
  // Room surfaces (by surface id) the user marked glossy or mirror: their pixels show a
  // reflection, not rho * (sum L E + Gamma), so the light fit leaves them out.
  std::vector<bool> nonMatteSurfaces;
  // An earlier estimate's rays (LightingEstimate::rays). Used only when they were traced for the
  // same photo, lights' mask, camera, room, gather grid and samples, patches and seed (checked by
  // a fingerprint of all of them; otherwise the estimate traces its own): the estimate is then
  // the one it would compute tracing them, up to the order of its sums.
  std::shared_ptr<const LightingRays> reuseRays;
  // With reuseRays replayed (and no sun): start from where that estimate's passes stopped (its
  // room model of what the camera does not see, its Gamma and clipped gain) instead of from the
  // surfaces' mean radiance: its first pass is the earlier estimate's next one, so the passes
  // stop one to three sooner (a refit after the refinement moved the lights by a few percent).
  // False: every estimate starts cold.
  bool warmStart = true;
  // The decomposition (the albedo after the light fit, the estimate's last and, at 0.3 MP, a
  // sixth of its CPU) is left for finishDecomposition: the estimate returns after the light
  // fit's residuals (fitRmsLog, fitResidualRelative) with the light fit's per-pixel albedo in
  // `albedo` and `pendingDecomposition` set. A caller that compares residuals first (the
  // pipeline's refit and its camera response check) decomposes only the estimate it keeps, and
  // gets what the estimate would have given without this.
  bool deferDecomposition = false;
  const CancelToken* cancel = nullptr;
};

// The seconds one step of estimateLighting took (LightingEstimate::steps): wall and the process's
// CPU seconds (every thread) summed over its calls.
struct LightingStepTime {
  std::string name;  // "surfaces", "direct light", "gather", "unseen patches", "light fit", ...
  double seconds = 0;
  double cpuSeconds = 0;
  int calls = 0;
};

struct LightingEstimate {
  ImageF albedo;          // W x H x 3, reflectance in [0,1] (the decomposition's)
  ImageF retinexAlbedo;   // W x H x 3, colour Retinex scaled per channel to the fitted lights
  ImageF physicalAlbedo;  // W x H x 3, B / (sum L_j E_j + Gamma) per pixel (the light fit's)
  // The decomposition's inputs besides the photo and `gathered` (to re-run it with other
  // options): its start rho0 (W x H x 3) and masks (W x H: data terms apply / B is clipped).
  ImageF decomposeStart;
  std::vector<uint8_t> decomposeValid, decomposeClipped;
  std::vector<DecomposeSample> decomposeHistory;  // objective and residuals against time
  std::string decomposeReport;                    // converged, or why the solver stopped
  bool decomposeConverged = true;                 // false: stopped at its iteration cap
  // Gamma: W x H x 3, indirect irradiance / pi. D = B - rho * Gamma: W x H x 3, >= 0. W x H: the
  // photo the estimate ran on; the preparation (pipeline.h) brings a working copy's albedo to the
  // photo's size, `gathered` only with a sun, `direct` never (the composite does not read it).
  ImageF gathered;
  ImageF direct;
  std::vector<AreaLight> lights;        // with fitted radiance
  std::vector<SunLight> suns;           // with fitted strength
  std::vector<Vec3> surfaceMeanAlbedo;  // per surface id of the geometry
  // The light fit's estimate of the albedo of a ceiling the camera does not see
  // (LightingOptions::fitUnseenCeiling), in the fit's albedo scale; NaN when it made none (the
  // photo shows the ceiling, no light's bounce is apart, or the option is off). Per channel:
  // whether the photo told it (false: the walls' mean, the prior, was used).
  Vec3 unseenCeilingAlbedo = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  std::array<bool, 3> unseenCeilingTold = {false, false, false};
  std::vector<int> firstSurfacePerPixel;  // W x H: the surface id each pixel centre shows (-1: none)
  double fitRmsLog = 0;                   // robust fit residual (log space)
  // How much of the photo the fitted model leaves unexplained, free of the photo's scale and
  // gamma: over the fit's pixels and channels, the median |log(B / (rho_s (sum L_j E_j +
  // Gamma)))| (rho_s the fit's albedo of the pixel's surface) over the median |log B - median
  // log B|. A response that decodes the photo to the room's true radiance should lower it (the
  // camera-response benchmark compares curves by it); NaN when no pixel tells.
  double fitResidualRelative = std::numeric_limits<double>::quiet_NaN();
  // The photo's vignetting as the model's residual shows it (a diagnostic, not applied): the
  // strength v of a radial fall-off 1 - v r^2 (r^2: the squared distance from the image centre
  // over the corner's) that best explains log(B / model) beside one offset per surface (least
  // absolute deviations, v on a 0.01 grid in [0, 0.6]); and the residual with v over without.
  double vignetting = 0;
  double vignettingResidualRatio = 1;
  int gatherSamples = 0;  // rays per gathered pixel used
  int gatherStride = 0;   // the gather's stride used (gatherStrideFor) and its grid's points
  int gatherPoints = 0;
  int passes = 0;         // gather-and-fit passes run (LightingOptions::maxPasses)
  int fitIterations = 0;  // the light fit's solver iterations, over its passes and channels
  // The rays this estimate traced or replayed (for LightingOptions::reuseRays of a refit; about
  // 70 bytes per ray that lands where the camera does not see, 4 per ray that it does: tens of
  // MB, dropped by the preparation once the refit ran). raysReused: replayed, not traced.
  std::shared_ptr<const LightingRays> rays;
  bool raysReused = false;
  bool warmStarted = false;  // its passes went on from the replayed rays' (warmStart)
  // LightingOptions::deferDecomposition: what the decomposition needs (null: none pending).
  std::shared_ptr<const PendingDecomposition> pendingDecomposition;
  // Extra gain the fit gave the light gathered from clipped photo pixels (their radiance is only
  // a lower bound); already folded into `gathered`. Zero when the photo has few clipped pixels.
  Vec3 clippedGain = Vec3::Zero();
  // Per sun: W x H x 3, the irradiance / pi its clipped sunlit pixels (a patch too bright for
  // the photo) send to each pixel under the sun at unit strength (irradianceOverPi = 1): their
  // radiance is albedo times the sun's irradiance, so it scales with the sun. Already in
  // `gathered` at the fitted strength. Empty when no sunlit pixel is clipped.
  std::vector<ImageF> sunBounce;
  // Per sun (one sun only; empty otherwise or without sunBounce): W x H x 3, the irradiance / pi
  // the sun's light sends to each pixel at unit strength by way of the surfaces the camera does
  // not see, after bouncing there (their predicted radiance's part that the sun brought: its
  // clipped patch's light and its direct light on them, through the room model's radiosity).
  // `gathered` holds it at the strength sunBounceUnseenAt (the first pass's), not the fitted
  // one: the light fit keeps it fixed; sun_ratio.h's bounce fit scales it.
  std::vector<ImageF> sunBounceUnseen;
  std::vector<Vec3> sunBounceUnseenAt;
  double seconds = 0;
  std::vector<LightingStepTime> steps;  // where `seconds` went, in the order the steps first ran
  std::vector<std::string> notes;
};

// Whether surface `id` is flagged in `nonMatte` (LightingOptions::nonMatteSurfaces).
inline bool isNonMatte(const std::vector<bool>& nonMatte, int id) {
  return id >= 0 && size_t(id) < nonMatte.size() && nonMatte[size_t(id)];
}

// An area light for a light the user outlined on the photo: the outline's pixels are cast onto
// the room; the light is the best-fitting rectangle on the surface they land on (usually the
// ceiling), offset 1 mm into the room and facing it. Errors name `keyForMessages`.
Expected<AreaLight> lightFromOutline(const Camera& camera, const SceneGeometry& geometry,
                                     const std::vector<Vec2>& outlinePx,
                                     const std::string& keyForMessages);

// The albedo of the surfaces the camera does not see (`weight[s]` = 0, e.g. their seen pixel
// count): walls take the weighted mean of the walls it sees (the room's mean when it sees none),
// the ceiling the same or, when that is darker (luminance), `ceilingAtLeast` grey; any other
// surface the room's mean (0.5 grey when nothing is seen); a seen surface keeps `albedo[s]`.
// One entry per surface of `geometry`. The render's room takes kUnseenCeilingAlbedo
// (LightingEstimate::surfaceMeanAlbedo); the light fit's own model of the unseen room passes 0
// in a room without a sun (its per-surface albedos are its passes' intermediate scale: an
// absolute floor there moved the fitted lights, e.g. a sky through an unseen window 2.0 times its
// radiance instead of 1.4) and LightingOptions::sunRoomUnseenCeilingAtLeast with a sun.
std::vector<Vec3> albedoOfUnseen(const SceneGeometry& geometry, const std::vector<Vec3>& albedo,
                                 const std::vector<double>& weight, double ceilingAtLeast = 0);

// The decomposition an estimate left (LightingOptions::deferDecomposition): `estimate`'s albedo,
// direct light, decomposition fields, notes and surfaceMeanAlbedo become what estimateLighting
// would have given, value for value; `geometry` is the room it was estimated in. Nothing pending:
// nothing changes. An error is the decomposition's (its key "decomposition"), the one
// estimateLighting would have returned instead of the estimate.
std::optional<Error> finishDecomposition(LightingEstimate& estimate, const SceneGeometry& geometry);

// The gather's stride on a width x height photo: `stride` (LightingOptions::gatherStride, at
// least 1), or the smallest larger one whose grid, ceil(width / s) x ceil(height / s), has at
// most `maxPoints` points (LightingOptions::gatherMaxPoints; <= 0: no cap).
int gatherStrideFor(int width, int height, int stride, int maxPoints);

// `lightMaskPx`: W x H x 1, 1 where a light is visible in the photo (excluded from gathering
// and fitting); may be empty. `suns`: sunlight beams whose strength is fitted alongside the
// lights (their masks and directions as given).
Expected<LightingEstimate> estimateLighting(const ImageF& photoLinear, const Camera& camera,
                                            const SceneGeometry& geometry,
                                            const std::vector<AreaLight>& lights,
                                            const std::vector<bool>& refine, const ImageF& lightMaskPx,
                                            const std::vector<SunLight>& suns = {},
                                            const LightingOptions& options = {});

// The photo's radiance for the render's bounces off the room (ProjectedAlbedo::photoRadiance):
// `photoLinear` (W x H x 3) with its clipped pixels inside a sun's beam replaced by the model's
// radiance there, albedo x (gathered light + the area lights' and suns' direct light), at least
// the photo's value; the albedo is the light fit's (physicalAlbedo: at a clipped pixel its
// surface's, fitted together with the suns' strengths). A sunlit patch the photo clips would otherwise light an object standing in
// it at the clip level only. `lighting` holds the lights and suns to use (refined or not).
ImageF radianceForBounces(const ImageF& photoLinear, const Camera& camera, const SceneGeometry& geometry,
                          const LightingEstimate& lighting, double saturatedAbove = 0.98);

}  // namespace inlay
