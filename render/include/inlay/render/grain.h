// The photo's grain: measured once from the photo (a noise level function per channel, the
// grain's spatial and cross-channel correlation), then given to the pixels the inserted objects
// change, so an object is as grainy as the photo around it.
//
// Units: whatever linear units the photo is given in (ps.photo.linearRgb: sRGB-decoded, or the
// camera response's linearisation); the noise is measured and added in those units, before the
// composite's exposure and encoding.
//
// Threads: measurePhotoNoise() and addGrain() are pure functions of their inputs (no global
// state, no random number generator: the grain is a hash of pixel, field and seed), safe to call
// from any thread.
#pragma once

#include "inlay/modeling/image.h"
#include "inlay/render/session.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace inlay {

// What measurePhotoNoise() found. Empty (no knots, or every sigma 0): the photo shows no noise
// and gets no grain.
struct PhotoNoise {
  // One point of a channel's noise level function: the noise's standard deviation at a mean
  // intensity, both in the photo's linear units.
  struct Knot {
    double intensity = 0;
    double sigma = 0;
  };
  // Per channel (R, G, B), by increasing intensity; sigma(I) is piecewise linear between the
  // knots and constant beyond the first and the last.
  std::array<std::vector<Knot>, 3> levels;
  // The grain's spatial correlation: white noise filtered by a Gaussian this wide (pixels; 0:
  // white, one pixel fine), found from the photo's high-frequency noise against its total
  // noise (JPEG and demosaicing make grain coarser than a pixel).
  double grainWidthPx = 0;
  // Correlation of the noise between channels in [0, 1): the part of the variance the three
  // channels share (1 would be grey grain, 0 independent colour grain).
  double channelCorrelation = 0;
  // Diagnostics: flat patches measured per channel, and why a part could not be measured.
  std::array<int, 3> patchesUsed{};
  std::vector<std::string> notes;

  bool empty() const;
  // sigma_c(intensity); 0 for an empty channel; finite for every finite input.
  double sigma(int channel, double intensity) const;
};

struct NoiseMeasureOptions {
  int patchPx = 8;                 // square patches this wide, a plane fitted to each
  double envelopeQuantile = 0.25;  // per intensity bin, this quantile of the patches' residual
                                   // variance (the lower envelope: texture only adds variance),
                                   // corrected by the chi-square quantile of a noise-only patch
  int maxBins = 16;                // intensity bins per channel (equal patch counts)
  int minPatchesPerBin = 24;       // fewer valid patches: fewer bins; < this in all: no model
  long maxPatches = 200'000;       // per image: the patch stride grows for large photos
};

// The noise of `linear` (W x H x >= 3, linear units) against intensity, per channel, from the
// flattest patches: per patch a plane is fitted (shading and gradients removed) and the residual
// variance and the high-frequency (Immerkaer's 3 x 3 second difference) variance measured;
// patches touching a clipped pixel (the channel's minimum or maximum value) or a non-finite one
// are left out. Never fails: a photo too small, flat, clipped or noise-free gives an empty model
// (with a note saying why).
PhotoNoise measurePhotoNoise(const ImageF& linear, const NoiseMeasureOptions& options = {});

// Grain for the pixels the objects change, in place on `composite` (the differential composite
// of photoLinear and the frame's withObjects, withoutObjects and mask, in the photo's linear
// units, before exposure). A channel of a pixel is changed where the mask is not 0 or
// withObjects differs from withoutObjects (differentialComposite's rule); untouched channels
// keep their value bit for bit. A changed channel of mask m and composite value v gets the noise
// it lacks there:
//   sqrt(max(0, sigma^2(v) - (1 - m)^2 sigma^2(photo) - s_render^2))
// times a unit-variance grain field shaped like the photo's (PhotoNoise::grainWidthPx and
// channelCorrelation): object pixels (m = 1) the full sigma(v), pixels only shadowed or lit by
// bounce light keep the photo's own noise and get only the part missing at their new value.
// s_render is the render's own noise, from frame.noise (the session's standard error in sRGB,
// taken back to linear by the same sRGB slope; 0 when the frame has none): a render not yet
// converged already carries part of the grain. The result is clamped at 0 like the composite
// and is finite wherever the composite is. An empty model changes nothing. `seed` picks the
// grain field: the same seed gives the same grain bit for bit, on any thread count.
// `field`, when given and of the composite's size, is grainField(noise, W, H, seed): the grain is
// read from it instead of being drawn again (the same bits).
void addGrain(ImageF& composite, const ImageF& photoLinear, const RenderFrame& frame,
              const PhotoNoise& noise, uint32_t seed, const ImageF* field = nullptr);

// The unit-variance grain fields addGrain() scales, for a whole width x height frame (W x H x 3):
// a pure function of the model's grain width and channel correlation, the size and the seed. A
// host that composites many frames of one scene (the studio's live preview) computes it once
// instead of per frame (about 30 ms at 512 x 384); empty for an empty model.
ImageF grainField(const PhotoNoise& noise, int width, int height, uint32_t seed);

// One line for a user: the noise at the photo's middle intensity, the grain's width and colour
// share, or why there is none.
std::string describeNoise(const PhotoNoise& noise);

// The unit-variance grain field of `noise`'s correlation at pixel (x, y), channel c (0..2): what
// addGrain() scales. Exposed for tests and benchmarks; any integer coordinates.
float grainAt(const PhotoNoise& noise, int x, int y, int c, uint32_t seed);

}  // namespace inlay
