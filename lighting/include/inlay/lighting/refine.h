// Light refinement: move the area lights and set their RGB intensities so that a direct-light
// render of the room matches the direct light the photo shows (Karsch et al. 2011, eq. 2).
//
//   minimise  sum_i alpha_i |R_i(L) - D_i|^2 / Z  +  prior * sum_j ( wPos_j |p_j - p0_j|^2
//                                                                + wInt_j |l_j - l0_j|^2
//                                                                + wSize_j |log s_j|^2 )
//
// over pixels i of a reduced grid, where R_i = rho_i * (sum_j L_j E_j(x_i; p_j) + sum_k S_k E_k)
// is the room's albedo times the direct irradiance / pi from the area lights and the suns (S_k:
// their strength; E_k: their direct light plus the bounce of their clipped sunlit patch, which
// the estimate gathered per unit strength and D left out: it is put back into the target, so
// that the unclipped walls and ceiling the patch lights tell the sun's strength), D the photo's
// direct component (decomposition), Z
// = sum_i alpha_i |D_i|^2 (so the data term is a relative error), alpha_i = 1 above the image's
// vertical midpoint falling quadratically to 0 at its bottom row. Positions p are the lights'
// centres normalised to the room box ([0,1] per axis), bounded so that the whole light stays
// inside the room; intensities l = L / (intensityRange * L0max) are in [0,1].
//
// E_j uses a fixed set of stratified points per light and pixel, so the objective is a smooth,
// deterministic function of the positions. Since R is linear in the intensities, they are
// solved in closed form (non-negative least squares) for every set of positions (variable
// projection); Ceres' bounded trust region moves the positions with forward-difference
// derivatives that recompute only the moved light's E. A light with refineSize also has its two
// edges' scale factors s_j (log, bounded) among Ceres' parameters.
#pragma once

#include "inlay/modeling/camera.h"
#include "inlay/modeling/core.h"
#include "inlay/modeling/geometry.h"
#include "inlay/modeling/image.h"
#include "inlay/render/scene.h"

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace inlay {

// Per area light: what the user fixed. Defaults are the weights.
struct LightRefineSpec {
  bool lock = false;           // keep position and intensity as they come in
  double positionWeight = 10;  // w of the position prior (normalised room units)
  double intensityWeight = 1;  // w of the intensity prior (normalised intensity)
  // Also fit the light's two edge lengths (each scaled by a factor within
  // [1 / sizeRange, sizeRange] of LightRefineOptions), pulled toward the start by
  // sizeWeight |log factor|^2. Off by default: an outline drawn on the photo gives the size.
  bool refineSize = false;
  double sizeWeight = 10;
  // The farthest its centre may move from where it came in along each world axis, in metres
  // (infinity: anywhere in the room). An outlined light gets outlineDisplacementBoundM: the
  // outline is the user's evidence of where the light is. An axis whose range is below the
  // finite-difference step is pinned.
  double maxDisplacementM = std::numeric_limits<double>::infinity();
};

struct LightRefineOptions {
  int gridPixels = 3000;    // the render's reduced resolution: at most about this many pixels
  int samplesPerLight = 9;  // fixed stratified points per light and pixel
  int maxIterations = 25;   // Ceres trust-region iterations
  // The solve's deterministic budget, in direct-light evaluations of one light on the grid
  // (LightRefineResult::evaluations): the solve stops after the iteration that reaches it, so
  // the refined lights are the same on every machine and under any load. At the default grid
  // one evaluation takes about 5 ms of one core here, so 2000 is the 10 s the wall-clock
  // limit before it allowed on an idle core; the scenes measured use at most 70
  // (docs/benchmarks.md, "Reproducible preparation"). At least 1.
  int maxEvaluations = 2000;
  // Last-resort guard against a hang, in wall-clock seconds (infinity: none). It is read only
  // between iterations, far beyond what the budget takes; when it stops the solve, a note says
  // that the lights may differ on another machine. Positive.
  double guardSeconds = 300;
  // Seconds on a monotonic clock for the guard and the history; empty: std::chrono's steady
  // clock. Tests inject a slow one.
  std::function<double()> clock;
  double prior = 2e-3;           // scale of the priors against the relative data term
  double intensityRange = 8;     // normalised intensity 1 = this many times the start's largest channel
  double stepNormalised = 2e-3;  // finite-difference step on the normalised position
  double marginM = 1e-3;         // lights keep this far inside the room's walls
  double sizeRange = 2;          // a refined size stays within [1/sizeRange, sizeRange] of the start
  // Outlined lights stay within their outline's uncertainty (LightRefineSpec::maxDisplacementM
  // from outlineDisplacementBoundM; the pipeline sets it); false: they move as freely as the
  // lights placed in 3D. The uncertainty: this many pixels (of the image the refinement reads,
  // the working copy), or this fraction of the outline's diagonal when that is more. Chosen on
  // scenes-train half A (docs/generalization.md): t03's sconce, 1.15 times its true power when
  // free, 1.13 with a quarter of its diagonal, 1.11 with a tenth, 1.09 with 3 px alone.
  bool holdOutlinedLights = true;
  double outlineUncertaintyPx = 3;
  double outlineUncertaintyFraction = 0;
  uint32_t seed = 11;
  // Suns: with refineSuns their strengths (RGB irradianceOverPi) are unknowns solved with the
  // area lights' intensities, pulled toward the start with sunIntensityWeight (directions and
  // beams stay as given). Off by default: against D the strength inherits the decomposition's
  // albedo error (d4: 17% from the truth against the estimate's 13%, object RMSE +0.002; README),
  // while the estimate's fit ties albedo, sun and its patch's bounce together. Off, the suns are
  // a fixed part of the render.
  bool refineSuns = false;
  double sunIntensityWeight = 1;
  // Per sun (may be empty or shorter): W x H x 3, its clipped sunlit patch's bounce per unit
  // strength (LightingEstimate::sunBounce), included in the direct image's gathered light.
  std::vector<ImageF> sunBounce;
  // Room surfaces (by surface id) marked glossy or mirror: they do not follow rho * E, so their
  // pixels are left out of the data term (LightingOptions::nonMatteSurfaces likewise).
  std::vector<bool> nonMatteSurfaces;
  const CancelToken* cancel = nullptr;
};

struct LightRefineSample {
  double seconds = 0;
  double objective = 0;  // the full objective (data + priors) after that iteration
};

struct LightRefineResult {
  std::vector<AreaLight> lights;  // refined (locked ones as given)
  std::vector<SunLight> suns;     // with refined strengths (as given unless refineSuns)
  double initialObjective = 0;    // at the start positions, intensities solved
  double finalObjective = 0;
  double initialDataTerm = 0, finalDataTerm = 0;  // the relative data term alone
  std::vector<LightRefineSample> history;
  int pixels = 0;       // grid pixels that took part
  int evaluations = 0;  // direct-light renders of one light
  double seconds = 0;
  bool stoppedByBudget = false;    // LightRefineOptions::maxEvaluations ended the solve
  bool stoppedByGuard = false;     // LightRefineOptions::guardSeconds did (a note says so)
  std::string report;              // why the solver stopped
  std::vector<std::string> notes;  // lights moved into the room, lights that light nothing, ...
};

// How many times refineLights has run in this process (all threads): tests use it to show that
// a scene whose lights are all locked skips the refinement.
uint64_t lightRefinementRuns();

// `albedo` and `direct`: W x H x 3, linear, the photo's pixel frame (the decomposition's rho
// and D); `usable`: W x H, 1 where D is data (not a light outline, not clipped, on the room),
// empty = every pixel on the room. `specs` has one entry per light (missing: defaults).
// Errors: empty or mismatched images, non-finite light corners or specs (keys "lights[j]").
Expected<LightRefineResult> refineLights(const Camera& camera, const SceneGeometry& geometry,
                                         const ImageF& albedo, const ImageF& direct,
                                         const std::vector<uint8_t>& usable,
                                         const std::vector<AreaLight>& lights,
                                         const std::vector<LightRefineSpec>& specs,
                                         const std::vector<SunLight>& suns = {},
                                         const LightRefineOptions& options = {});

// How far (metres, per world axis) the centre of `light`, outlined on the photo by `outlinePx`
// (the camera's pixels), may move in the refinement: the outline's uncertainty in pixels,
// max(outlineUncertaintyPx, outlineUncertaintyFraction x the outline's bounding-box diagonal),
// times the metres one pixel spans at the light (its distance from the camera over the focal
// length). Infinity (free) when there is no outline or it or the light is not finite; never NaN.
double outlineDisplacementBoundM(const Camera& camera, const AreaLight& light,
                                 const std::vector<Vec2>& outlinePx, const LightRefineOptions& options);

// The weight alpha of image row y (pixel centre y + 0.5) in an image of `height` rows.
double refineRowWeight(double y, int height);

// Non-negative least squares of a small dense problem: x >= 0 minimising |A x - b|^2 given as
// its normal equations (M = A^T A, symmetric positive semi-definite, q = A^T b). Lawson-Hanson
// active set; returns zeros when nothing positive helps.
std::vector<double> nonNegativeLeastSquares(const std::vector<double>& M, const std::vector<double>& q,
                                            int n);

}  // namespace inlay
