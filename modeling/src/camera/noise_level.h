// The photo's noise level against its codes, as a cue to the camera response (internal to
// modeling; see response.h).
//
// Sensor noise is signal-dependent in *linear* radiance: its variance is a + b x + c x^2 with
// a, b, c >= 0 (read noise, shot noise, and a renderer's sampling noise or gain noise). A
// response f bends that relation: measured in codes, sigma_code(c) = f'(x) sigma_x(x) at
// x = f^-1(c). Decoded with the right curve g = f^-1, the points (g(c), (g'(c) sigma_code(c))^2)
// lie on such a non-negative quadratic; a wrong curve bends them off it (Matsushita and Lin
// 2007, "Radiometric calibration from noise distributions", with their affine model widened by
// the quadratic term). A pure power change of the curve is nearly invisible to this cue (the
// fit's prior holds the power); toes and shoulders are not.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace inlay::detail {

struct NoiseBin {
  double code = 0;   // median code of the bin's blocks
  double sigma = 0;  // median noise standard deviation of its blocks, in codes
  int blocks = 0;
};

struct NoiseLevel {
  std::vector<NoiseBin> bins;  // increasing code
  int flatBlocks = 0;          // blocks (8 x 8 px, one channel) flat enough to measure
  std::string undetermined;    // why the noise cannot determine a curve, or empty
};

// Every channel's 8 x 8 blocks that are flat (apart from a linear gradient) and unclipped give
// one (mean code, noise) point: the RMS of the residual of each pixel against its four
// neighbours' mean. The points are split into up to 12 bins of equal count by code; each bin's
// median code and the `sigmaQuantile` quantile of its blocks' noise (0.5: the median; lower: the
// lower envelope, which texture and uneven lighting inflate less) form the noise level function.
// `codes`: W x H x 3 interleaved 8-bit codes; sigmaQuantile is clamped to [0, 1] (NaN: 0.5).
NoiseLevel measureNoiseLevel(const std::vector<unsigned char>& codes, int W, int H,
                             double sigmaQuantile = 0.5);

// How far the noise level, decoded by `g` (code -> linear, 256 strictly increasing values), is
// from a variance a + b x + c x^2 with a, b, c >= 0 (best fit, relative to each bin's
// variance): the RMS of log(fitted / measured). Quantisation's 1/12 code^2 is taken off first.
// Finite (10 when no admissible fit exists).
double noiseLevelResidual(const NoiseLevel& level, const std::array<double, 256>& g);

}  // namespace inlay::detail
