// Intrinsic decomposition of a photo into albedo and light layers: colour Retinex (Grosse et al.
// 2009) as the baseline and starting point, and the geometry-aware objective of Karsch et al.
// 2011 (Sec. 4) solved by a primal-dual method.
//
// Model per pixel and channel (linear photo units): B = D + rho * Gamma, where Gamma is the
// indirect irradiance / pi gathered from the photo (gather.h), rho the albedo in [0,1] and D the
// direct layer (>= 0). The objective, with D eliminated through the equality:
//   sum |Lap rho|_1 + g1 * m * |grad rho|^2 + g2 * (Gamma (rho - rho0))^2
//       + g3 * |grad (B - rho Gamma)|^2,        0 <= rho <= min(1, B / Gamma)
// (g2 (D - D0)^2 with D0 = B - rho0 Gamma is g2 Gamma^2 (rho - rho0)^2). The mask
// m = 1 - 1/(1 + exp(-s(|grad B|^2 - c))) frees rho to change where the photo has an edge.
// The absolute scale of rho is anchored by Gamma: the data terms tie rho * Gamma to the photo,
// and D >= 0 caps rho at B / Gamma.
//
// All functions are pure and thread-safe; they use TBB for the per-row loops.
#pragma once

#include "inlay/modeling/core.h"
#include "inlay/modeling/image.h"

#include <cstdint>
#include <string>
#include <vector>

namespace inlay {

struct RetinexOptions {
  // A log-intensity step between neighbours larger than this is a reflectance edge (shading
  // varies slowly on a diffuse room except at shadow boundaries). Natural-log units per pixel.
  double intensityThreshold = 0.12;
  // A step in chromaticity (r, g, b) / (r + g + b) larger than this is a reflectance edge
  // whatever the intensity does (white light does not change chromaticity).
  double chromaThreshold = 0.012;
};

// Colour Retinex: reflectance up to one scale per channel. `linearRgb`: W x H x 3 (photo units).
// `valid`: W x H, nonzero where the pixel may be used (room, not a lamp, not clipped); gradients
// touching an invalid pixel are zero, so invalid pixels take the value reconstructed around them.
// Returns W x H x 3, positive, geometric mean 1 over valid pixels (per channel up to
// chromaticity). Poisson reconstruction by a DCT (Neumann boundary).
ImageF retinexReflectance(const ImageF& linearRgb, const std::vector<uint8_t>& valid,
                          const RetinexOptions& options = {});

struct DecomposeOptions {
  double g1 = 0.2;  // weight of the masked smoothness of rho
  double g2 = 0.9;  // weight of (D - D0)^2
  double g3 = 0.1;  // weight of |grad D|^2
  double s = 10;    // mask steepness
  double c = 0.15;  // mask threshold on |grad B|^2, B in the photo's linear units (white 1)
  // Units of B and Gamma in the objective: the L1 term is scale-free in rho, the quadratic ones
  // grow with the square of the photo's units, so the units set how much the prior may
  // override the data. With `unitsFromNoise`, B is counted in standard deviations of the
  // photo's own pixel noise (pixelNoiseSigma over the valid, unclipped pixels), at most
  // `unitsPerWhite` per white: the data terms then weigh a change of the layers by how far it
  // stands above the noise, so the noise of a grainy photo is not pushed into rho by the
  // smoothness of D (what made more iterations worse), while a clean photo keeps the
  // quantisation level as its unit. Default cap: 8-bit code units (white = 255).
  // normaliseByMeanGamma: divide by the mean gathered irradiance first (exposure-invariant).
  double unitsPerWhite = 255;
  bool unitsFromNoise = true;
  bool normaliseByMeanGamma = false;
  // The solver stops on convergence or at the iteration cap, never on the clock, so a photo
  // and geometry give the same albedo bit for bit on every run and machine load. With the
  // defaults below (diagonal steps, coarse start, held pixels, gapTolerance) the example and the
  // training rooms converge after 30 to 110 iterations at the photo's level (docs/benchmarks.md,
  // "A converged decomposition at the old one's cost"); the cap is a guard. The scalar solver
  // with the old cap of 30 stopped before converging on every room (1430 iterations to converge
  // on the example).
  int maxIterations = 200;
  int minIterations = 10;
  // Converged when the RMS primal and dual residuals (Goldstein et al. 2013 for primal-dual),
  // each times its step (so in units of rho and of the dual variable in [-1,1]), both fall
  // below `tolerance`, or when the objective changed by less than `objectiveTolerance`
  // (relative) over the last `historyEvery` iterations.
  double tolerance = 1e-4;
  double objectiveTolerance = 1e-6;
  // Or when the objective's gap to its minimum, per pixel and channel, is below `gapTolerance`:
  // the gap estimated from the last two decreases over `historyEvery` iterations as a geometric
  // series, times 2 (the ratio of the decreases grows on a grainy photo: the estimate was a fifth
  // short on t09). In the objective's units (B in standard deviations of the photo's noise, or
  // 8-bit codes on a clean photo), 1e-3 is a change of D by about 1/30 of the noise at one pixel
  // and channel, or of the albedo's Laplacian by 1e-3, below what the photo and the renders can
  // show (chosen on half A: the same albedo error as 1e-4 and 3e-4 in fewer iterations). 0: off.
  double gapTolerance = 1e-3;
  // Photos with more pixels are solved on block means of at most this many pixels; the
  // solver's change to the start is carried back to full resolution (memory and time bounded
  // for 50 MP photos). <= 0: always full resolution.
  long maxSolvePixels = 2'000'000;
  // Per-pixel primal steps (diagonal preconditioning, decompose.cpp) instead of one scalar step
  // set by the brightest pixel (false: that scalar step, the solver before issue #16). With
  // pyramidLevels they reach the objective's minimum many times sooner; without holdInvalid
  // that minimum's albedo was worse than 30 scalar iterations' on half B and the dev rooms
  // (docs/benchmarks.md, "The decomposition's steps and coarse-to-fine start").
  bool diagonalSteps = true;
  // Pixels outside `valid` keep their start (the lighting gives them the photo's own Retinex:
  // the model does not explain them). Off: only the smoothness and g3 terms hold them, and a
  // converged solve moves them, which made its albedo worse than 30 scalar iterations' on half B
  // (on: better on both halves; docs/benchmarks.md, same section).
  bool holdInvalid = true;
  // Coarse-to-fine start: the objective is first solved on up to this many coarser levels (2 x 2
  // block means each, down to a short side of 32 pixels, g2 x 4 per level so that each level
  // discretises the same continuous objective), each level's albedo change and dual variable
  // interpolated as the next finer level's start. The coarse levels take the smooth, slow part
  // of the solution (what the fine level's local steps spread over hundreds of iterations) for
  // a quarter of the cost per level. 0: the photo's level alone. A coarser level is only a
  // start: it stops at coarseIterations (or converged); more did not shorten the photo's level
  // on the example, t03 and t07 (a synthetic checker needed its coarse levels converged).
  int pyramidLevels = 2;
  int coarseIterations = 30;
  int historyEvery = 10;  // record objective and residuals every n iterations (and the last)
  const CancelToken* cancel = nullptr;
};

// Standard deviation of the pixel noise of `image` (linear units, its first three channels
// pooled): the median absolute response of the 3 x 3 second-difference operator of Immerkaer
// (1996, "Fast noise variance estimation") over pixels whose 3 x 3 neighbourhood is all in
// `use`, as a Gaussian's (the median keeps reflectance edges, a minority, out of it). 0 when
// fewer than 16 such pixels.
double pixelNoiseSigma(const ImageF& image, const std::vector<uint8_t>& use);

struct DecomposeSample {
  double seconds = 0;
  int iteration = 0;
  double objective = 0;
  double primalResidual = 0;  // RMS per pixel and channel
  double dualResidual = 0;
};

struct Decomposition {
  ImageF albedo;  // W x H x 3, reflectance in [0,1] and <= B / Gamma where B is not clipped
  ImageF direct;  // W x H x 3, D = B - rho * Gamma, >= 0 (clipped pixels: clamped at 0)
  std::vector<DecomposeSample> history;
  int iterations = 0;
  bool converged = false;  // false: stopped at the iteration cap, by cancellation or NaN
  std::string report;      // one line: converged or why it stopped, with the residuals reached
  double seconds = 0;
};

// How many times decomposeIntrinsic has run in this process (all threads): tests use it to show
// that moving an object never redoes the decomposition.
uint64_t decompositionRuns();

// Minimises the objective above from `rho0` (W x H x 3, typically anchored Retinex). `photo`:
// B, W x H x 3 linear; `gathered`: Gamma, W x H x 3 >= 0. `valid`: W x H, nonzero where the
// data terms apply; `clipped`: W x H (may be empty), nonzero where B is only a lower bound (the
// cap B / Gamma is lifted there). Bad input (sizes, non-finite weights) is an error.
Expected<Decomposition> decomposeIntrinsic(const ImageF& photo, const ImageF& gathered,
                                           const ImageF& rho0, const std::vector<uint8_t>& valid,
                                           const std::vector<uint8_t>& clipped,
                                           const DecomposeOptions& options = {});

}  // namespace inlay
