// The denoised preview: an edge-aware à-trous wavelet filter (SVGF-style) of what the objects
// change, guided by what each pixel's camera ray meets first (albedo, normal, position) and by
// the object mask, with its strength set by each pixel's own estimated noise.
//
// What is filtered is the differential composite's delta, never the photo. The composite is
//   C = M * with + (1 - M) * (photo + with - without) = X + (1 - M) * photo,
//   X = with - (1 - M) * without,
// so X is the object's own radiance where the camera sees it (M = 1) and the with-minus-without
// difference elsewhere (M = 0). The filter smooths X (divided by the first hit's albedo, so a
// shadow on a tiled floor keeps its tiles) and writes the result back as a new with-object
// image: the usual composite of it is the photo plus the filtered delta.
//
// Guarantees:
// - Pixels no sample changed (with == without, mask 0, no change in any sample) and farther
//   than the filter's reach (denoiseReachPx) from every pixel a sample changed keep their
//   with-object value bit for bit, so they composite to the photo bit for bit; so does any
//   pixel whose filtered delta is exactly zero.
// - The change the filter makes to a pixel is at most DenoiseOptions::clampSigmas standard errors of
//   the pixel's own estimate (spatially pooled where a pixel has too few samples for its own),
//   so the filter's strength falls with the samples: a converged render comes out as it went in.
// - No NaN or Inf: non-finite inputs are treated as zero and weights are bounded.
#pragma once

#include "inlay/modeling/image.h"
#include "inlay/render/path_tracer.h"
#include "inlay/render/session.h"

#include <cstdint>
#include <vector>

namespace inlay {

// What each pixel centre's camera ray meets first, in the scene with the objects.
// (clang-tidy 14 reports the '__i0' of the implicitly defined copy of the array members below:
// the compiler's loop variable, not a name of ours.)
// NOLINTNEXTLINE(bugprone-reserved-identifier)
struct DenoiseGuides {
  int width = 0, height = 0;
  // Planes of W x H floats each (structure of arrays: the filter's loops vectorise).
  std::vector<float> albedo[3];    // reflectance of the first hit (1 for glass, lights, no hit)
  std::vector<float> normal[3];    // unit shading normal facing the camera (world)
  std::vector<float> position[3];  // world position of the hit, metres
  std::vector<float> distance;     // from the camera, metres (> 0)
  // Fraction of the pixel's samples that show it through a smooth mirror or glass (the tracer's
  // guides; empty: none, as from renderDenoiseGuides).
  std::vector<float> specular;
  bool empty() const { return width <= 0 || height <= 0; }
};

// The guides of a W x H frame (the camera's pixel frame scaled to W x H), one ray per pixel
// centre through `tracer`'s scene with the objects; parallel with `threads` (0 = all cores).
DenoiseGuides renderDenoiseGuides(const PathTracer& tracer, int width, int height, int threads = 0);

// The guides the path tracer recorded as it rendered (DifferentialBuffers::enableGuides): per
// pixel the mean over its samples of what the camera path shows past any smooth mirror or glass
// (normals renormalised). Pixels without samples get albedo 1, normal 0, distance 1e6. Empty
// when the buffers hold no guides.
DenoiseGuides denoiseGuidesFromBuffers(const DifferentialBuffers& buffers, int threads = 0);

struct DenoiseOptions {
  int levels = 5;  // à-trous levels (steps 1, 2, 4, ...): reach 2^levels - 1 px
  // Edge stop on the delta, in standard errors: on the room (shadows, bounce light) and on the
  // object's own pixels (mixed by the mask). Chosen on the unit test's sphere scene at 1-16 spp
  // (tests/render_denoise_test.cpp): the room's sparse changes want a tight stop, the object's
  // dense shading a looser one.
  float sigmaLuminance = 2.f;
  float sigmaLuminanceObject = 4.f;
  // ... and on pixels seen through a smooth mirror or glass (DenoiseGuides::specular): what they
  // show is a whole scene squeezed into few pixels, so a tight stop keeps its detail.
  float sigmaLuminanceSpecular = 1.f;
  float sigmaNormal = 16.f;  // edge stop on normals: exp(-sigma (1 - n_i . n_j))
  float sigmaPlane = 0.02f;  // edge stop on the distance from the pixel's tangent plane,
                             // relative to its distance from the camera
  float sigmaAlbedo = 0.1f;  // edge stop on the albedo (sum of |difference| over RGB)
  float sigmaMask = 0.1f;    // edge stop on the object mask (and on the specular fraction)
  float clampSigmas = 3.f;   // the change is at most this many standard errors
  int threads = 0;           // 0 = all cores
};

// How far (pixels) a change can spread: 2^levels - 1 (31 at the default 5 levels).
int denoiseReachPx(const DenoiseOptions& options);

// The statistics of a frame the filter needs, per pixel: samples, and the per-sample variance
// (mean over RGB) of what each sample changes (DifferentialBuffers::sumChange / sumChangeSq).
struct DenoiseInput {
  const ImageF* withObjects = nullptr;           // W x H x 3 means
  const ImageF* withoutObjects = nullptr;        // W x H x 3
  const ImageF* mask = nullptr;                  // W x H x 1
  const DifferentialBuffers* buffers = nullptr;  // the running sums the means came from
  const DenoiseGuides* guides = nullptr;
};

// The denoised with-object image (W x H x 3): composite it with the same without-object image
// and mask. Inputs of mismatched sizes are returned unchanged (a copy of withObjects).
ImageF denoiseWithObjects(const DenoiseInput& in, const DenoiseOptions& options = {});

// The render session's hook (SessionOptions::denoise): replaces frame.withObjects by its
// denoised version and sets frame.denoised. The guides are the buffers' own when they hold
// them (denoiseGuidesFromBuffers, renewed every frame); otherwise they are made from `tracer`
// on first use (or when the frame's size changed, one camera ray per pixel) and kept in *guides
// for the version's later frames.
void denoiseFrame(RenderFrame& frame, const DifferentialBuffers& buffers, const PathTracer& tracer,
                  DenoiseGuides* guides, const DenoiseOptions& options);
// The same with the default options on `threads` threads (the session's one-line hook).
inline void denoiseSessionFrame(RenderFrame& frame, const DifferentialBuffers& buffers,
                                const PathTracer& tracer, DenoiseGuides* guides, int threads) {
  DenoiseOptions options;
  options.threads = threads;
  denoiseFrame(frame, buffers, tracer, guides, options);
}

}  // namespace inlay
