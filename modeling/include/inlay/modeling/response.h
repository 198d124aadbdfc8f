// The camera's response: how the file's encoded values relate to scene radiance.
//
// A camera maps relative linear radiance x >= 0 to an encoded value f(x) in [0,1] (an 8-bit
// code is round(255 f(x))). Inlay models f as one of three families:
//   - "srgb":   the IEC 61966-2-1 curve (what every 8-bit photo was read as before).
//   - "linear": the identity (EXR/HDR photos are already linear).
//   - "toe_shoulder": the sRGB curve after a warp of the radiance,
//        f(x) = srgb(S_s(T_t(x^p))),
//     p (power) > 0: the curve's overall gamma relative to sRGB (p < 1: a higher display
//       gamma's brighter mid-tones, p > 1: a lower one's);
//     T_t(u) = (1 + t) u^2 / (u + t), t (toe) >= 0: a darker, flatter toe (contrast in the
//       shadows); t = 0 is the identity;
//     S_s(u) = (1 + s) u / (1 + s u), s (shoulder) >= 0: a highlight roll-off; s = 0 is the
//       identity, large s a long shoulder where the top codes span many stops.
//     Each map takes [0,1] onto [0,1] with 0 -> 0 and 1 -> 1 and is strictly increasing, so f
//     is too; at p = 1, t = 0, s = 0 the family is sRGB exactly. Code 255 always decodes to
//     1.0: "1.0 is a pure white pixel" keeps its meaning in the scene file.
// Parameters are clamped to ResponseParams' bounds, where f stays finite and strictly
// monotone (f^-1 of every 8-bit code is a distinct finite float).
//
// estimateResponse() finds the toe_shoulder parameters from the photo's own edges or its noise
// level (see there).
// Thread-safe: a CameraResponse is an immutable value.
#pragma once

#include "inlay/modeling/core.h"
#include "inlay/modeling/image.h"

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace inlay {

enum class ResponseFamily { Srgb, Linear, ToeShoulder };

struct ResponseParams {
  double power = 1.0;     // [kMinPower, kMaxPower]
  double toe = 0.0;       // [0, kMaxToe]
  double shoulder = 0.0;  // [0, kMaxShoulder]
  static constexpr double kMinPower = 0.4, kMaxPower = 2.5;
  static constexpr double kMaxToe = 2.0;
  static constexpr double kMaxShoulder = 1000.0;
  ResponseParams clamped() const;  // NaN -> the neutral value
};

class CameraResponse {
 public:
  CameraResponse();  // sRGB
  static CameraResponse srgb();
  static CameraResponse linear();
  static CameraResponse toeShoulder(const ResponseParams& params);  // clamped to the bounds

  ResponseFamily family() const { return family_; }
  const ResponseParams& params() const { return params_; }
  std::string familyName() const;  // "srgb", "linear", "toe_shoulder"
  // e.g. "toe_shoulder (power 0.82, toe 0.10, shoulder 3.1)"
  std::string describe() const;

  // f: linear radiance -> encoded [0,1] (clamped; NaN -> 0).
  double encode(double linear) const;
  // f^-1: encoded [0,1] (clamped) -> linear radiance in [0,1].
  double decode(double encoded) const;

  // f^-1 of the 8-bit codes: 256 strictly increasing finite floats, table8()[0] = 0,
  // table8()[255] = 1. For "srgb" these are exactly srgbToLinear(k / 255.f).
  const std::array<float, 256>& table8() const { return table8_; }
  // round(255 f(linear)), such that encodeCode8(table8()[k]) == k for every code k.
  unsigned char encodeCode8(float linear) const;

  bool operator==(const CameraResponse& o) const {
    return family_ == o.family_ && (family_ != ResponseFamily::ToeShoulder ||
                                    (params_.power == o.params_.power && params_.toe == o.params_.toe &&
                                     params_.shoulder == o.params_.shoulder));
  }

 private:
  void buildTables();
  ResponseFamily family_ = ResponseFamily::Srgb;
  ResponseParams params_;
  std::array<float, 256> table8_{};
  std::array<float, 255> thresholds8_{};  // f^-1((k + 0.5) / 255): code k below, k + 1 above
};

// The file's encoded values of a photo read as sRGB (LoadedImage::linearRgb of an 8- or 16-bit
// file) decoded again with `response`: every value v becomes response.decode(srgb(v)), with the
// sRGB code recovered exactly for 8-bit files (`bitsPerChannel` 8) so a photo's pixel with code
// k becomes exactly table8()[k]. In place; a linear response of an sRGB-read image is its
// encoded values as they are.
void redecodePhoto(ImageF& srgbDecodedRgb, int bitsPerChannel, const CameraResponse& response);

// The 8-bit codes (W x H x 3, interleaved) of an image read as sRGB, recovered exactly for
// 8-bit files and rounded for deeper ones.
std::vector<unsigned char> srgbCodesOf(const ImageF& srgbDecodedRgb);

struct ResponseEstimateOptions {
  // What the estimate measures at the photo's straight edges between two flat regions:
  //   Symmetry: the edge's profile in linear radiance is point-symmetric about its middle (a
  //     symmetric lens/pixel blur of a step), which a wrong curve bends (works for grey edges);
  //   Colour: the pixels across an edge are mixtures of its two colours, on a line in linear
  //     RGB, which a wrong curve bends (Lin, Gu, Yamazaki, Shum 2004; needs coloured edges);
  //   Both: the sum of the two;
  //   Noise: the photo's noise variance, decoded, is a non-negative quadratic a + b x + c x^2
  //     of the linear radiance (read, shot and gain or sampling noise), which a wrong curve
  //     bends (Matsushita and Lin 2007); needs flat regions over a range of codes and
  //     measurable noise;
  //   NoiseColour: the noise level plus edgeWeight times the colour edges' residual, in one fit
  //     (the noise sees toes and shoulders but hardly a power; the colour mixtures see the
  //     power where there are edges). Without minEdges clean edges it is the noise level
  //     alone. The noise cue's acceptance, evidence gate and shoulder rule apply to the fit's
  //     noise part. Opt-in diagnostic: on the camera variants it does not beat Noise and it
  //     gives real photos implausible curves (docs/camera-response.md, "The noise and the
  //     edge mixtures in one fit").
  enum class Cue { Symmetry, Colour, Both, Noise, NoiseColour };
  // The noise level is (part of) the cue.
  bool noiseCue() const { return cue == Cue::Noise || cue == Cue::NoiseColour; }
  // The noise level with its evidence gate (minSrgbResidual): it keeps sRGB on every plain
  // render and lowers half A's object RMSE under random cameras, where the colour edges (the
  // old default) keep sRGB on every photo (docs/camera-response.md).
  Cue cue = Cue::Noise;
  // Weight of the pull toward sRGB's power (a Gaussian prior on (power - 1) / 0.25), relative
  // to the cue's residual. Unset: the cue's own default (edge cues 2, noise 0.1; chosen on
  // half A by bench_response.py; noise-colour 0.02, the colour cue's light pull, not tuned).
  std::optional<double> priorWeight;
  // The same for toe and shoulder (a Gaussian prior on toe / 0.25 and log(1 + shoulder) / 1.5).
  // Unset: edge cues as priorWeight, noise cues 0 (the noise sees toes and shoulders; the power
  // hardly).
  std::optional<double> shapePriorWeight;
  int minEdges = 8;  // fewer clean edges: sRGB with a warning
  // The fitted curve is kept only when it lowers the cue's residual by at least this fraction
  // of sRGB's; otherwise sRGB (the photo shows no curve clearly different from it). Unset: the
  // cue's default (edge cues 0.1, noise cues 0.5 of the noise part: ResponseEstimate::evidence).
  std::optional<double> minImprovement;
  // The three numbers above with the cue's defaults filled in.
  double priorWeightOrDefault() const {
    return priorWeight.value_or(cue == Cue::NoiseColour ? 0.02 : noiseCue() ? 0.1 : 2.0);
  }
  double shapePriorWeightOrDefault() const {
    return shapePriorWeight.value_or(noiseCue() ? 0.0 : priorWeightOrDefault());
  }
  double minImprovementOrDefault() const { return minImprovement.value_or(noiseCue() ? 0.5 : 0.1); }
  // NoiseColour: the weight of the colour edges' mean robust residual (0 to 1 per edge) against
  // the noise level's residual (an RMS log deviation). Unset: 1.
  std::optional<double> edgeWeight;
  double edgeWeightOrDefault() const { return std::max(0.0, edgeWeight.value_or(1.0)); }
  // Noise cue: a curve is fitted only when sRGB's residual is at least this (the RMS log
  // deviation of the decoded noise variance from a quadratic), i.e. when the noise contradicts
  // sRGB more than it does on any photo that is sRGB (half A's plain photos and the dev rooms
  // leave up to 0.48: a rendered photo's noise depends on how each pixel is lit, not on its
  // brightness alone, which a long shoulder mimics). Unset: 0.5 for the noise cue
  // (docs/camera-response.md), 0 (no check) for the edge cues.
  std::optional<double> minSrgbResidual;
  double minSrgbResidualOrDefault() const { return minSrgbResidual.value_or(noiseCue() ? 0.5 : 0.0); }
  // A fitted curve must show what it claims about the bright half of the codes: one that spans
  // more than maxTopStops stops between codes 128 and 254 (sRGB spans 2.2; a real camera's
  // shoulder adds two to three) is kept only when the photo's noise was measured at no fewer
  // than minTopLevels code bins in that half (three points show a bend, two only a slope).
  // Otherwise the long shoulder is an extrapolation from the dark half (a blown sky beside dark
  // ground: York P1030004 got 7.8 stops from one bright bin): sRGB, with a warning saying why.
  // 6 stops is the plausibility bound of bench_response_york.py; random cameras' S-curves span
  // up to 8.6 stops and are kept where their noise reaches the top half (chosen on half A of
  // the camera variants, docs/camera-response.md).
  double maxTopStops = 6;
  int minTopLevels = 3;
  // Noise cue, opt-in: the contrast evidence of the photo's shadows. darkFill (see
  // ResponseEstimate) is the 1st percentile of the pixels' sRGB-decoded luminance over its
  // median: in a closed room the light reflected by its walls fills the shadows, so a photo
  // whose shadows read darker than maxDarkFill of the median under sRGB has been through a
  // contrast curve. Such a photo gets the noise cue's curve without the evidence gate
  // (minSrgbResidual) when it lowers the residual by darkFillMinImprovement (instead of
  // minImprovement); the shoulder rule above still applies. Unset or 0: off (the default).
  // Measured (docs/camera-response.md): every plain render of the training rooms and every
  // dev room is above 0.14, so 0.12 keeps them sRGB and gives the sigmoid cameras their curve;
  // but every York photo is below 0.09 (real rooms have dark things in them), so on real
  // photos it would take the gate away, which is why it is off by default.
  std::optional<double> maxDarkFill;
  double darkFillMinImprovement = 0.2;
  bool darkFillOn() const { return maxDarkFill.value_or(0.0) > 0; }
  // Noise cue: the quantile of the flat blocks' noise that stands for each code bin (0.5: the
  // median). Texture and a rendered photo's uneven lighting only add variance to a block, so a
  // lower quantile follows the sensor's noise more closely. Unset: kDefaultNoiseQuantile.
  std::optional<double> noiseQuantile;
  static constexpr double kDefaultNoiseQuantile = 0.5;
  double noiseQuantileOrDefault() const { return noiseQuantile.value_or(kDefaultNoiseQuantile); }
  int maxSegments = 300;        // line segments considered (the longest)
  double minEdgeLengthPx = 20;  // shorter segments are skipped
  const CancelToken* cancel = nullptr;
  // Diagnostics: skip the search and report the objective at these parameters.
  std::optional<ResponseParams> evaluateAt;
};

struct ResponseEstimate {
  CameraResponse response;  // sRGB when undetermined
  bool determined = false;  // false: the photo could not determine it (see warnings)
  std::vector<std::string> warnings;
  int edgesUsed = 0;  // clean edges the fit used (edge cues)
  int noiseBins = 0;  // code bins of the measured noise level (noise cue)
  int segmentsFound = 0;
  double objective = 0;      // the fit's mean edge residual at the result (without prior)
  double srgbObjective = 0;  // the same for plain sRGB
  // What the acceptance (minImprovement) and the evidence gate (minSrgbResidual) compare: the
  // noise level's residual at the result and for sRGB for the noise cues (objective and
  // srgbObjective without the edges for NoiseColour), objective and srgbObjective otherwise.
  double evidence = 0;
  double srgbEvidence = 0;
  // NoiseColour without enough clean edges: why the fit used the noise level alone.
  std::string edgeNote;
  // Noise cue: the measured noise level (code, sigma in codes) per bin, increasing code.
  std::vector<std::array<double, 2>> noiseLevel;
  // The photo's 1st percentile of sRGB-decoded luminance over its median, in [0, 1] (1 when
  // the median is black); ResponseEstimateOptions::maxDarkFill.
  double darkFill = 1;
  // The curve was accepted on the shadows' contrast evidence (darkFill below maxDarkFill)
  // rather than on the noise residual's evidence gate.
  bool darkFillEvidence = false;
  std::string decision;  // why this curve: "fitted", or why sRGB was kept
  double seconds = 0;
  double cpuSeconds = 0;  // this thread's CPU time (what an idle core would take)
  // The fit's objective (with prior) against seconds: one row per improvement.
  std::vector<std::pair<double, double>> history;
};

// The response of an 8/16-bit photo read as sRGB (`srgbDecodedRgb`: LoadedImage::linearRgb of
// such a file), from the photo alone. Edge cues: line segments are found (lines.h), each
// segment's pixels within 4 px are kept when both sides are flat, unclipped and differ. Noise
// cue: the noise level of flat 8 x 8 blocks against their codes (noise_level.h). The
// toe_shoulder parameters minimise the chosen cue's residual plus the prior (a grid, then
// Nelder-Mead). Undetermined (returns sRGB, determined false, a warning saying why): a nearly
// flat or nearly binary photo, one mostly clipped, fewer than minEdges clean edges (edge cues),
// or too few flat regions or no measurable noise (noise cue).
ResponseEstimate estimateResponse(const ImageF& srgbDecodedRgb,
                                  const ResponseEstimateOptions& options = {});

}  // namespace inlay
