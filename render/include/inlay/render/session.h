// The progressive render session: one long-lived thread that renders a differential frame in
// waves (coarse first, then doubling), publishes each wave's result to a FrameSink, and
// restarts when the scene changes.
//
// Threads: every public method may be called from any thread (the studio's GUI thread, a
// test's threads). An edit bumps the scene version and raises the cancel flag; the render
// thread notices within one tile (a few ms) and applies the edit at a safe point (Cycles'
// delayed reset). Frames carry the version they were rendered for, and a frame of an older
// version is never published after one of a newer version. Lock order: none held while
// calling the sink.
#pragma once

#include "inlay/modeling/core.h"
#include "inlay/modeling/image.h"
#include "inlay/render/path_tracer.h"
#include "inlay/render/scene.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

namespace inlay {

// One wave of work: render `sampleCount` samples starting at `firstSample`, on a grid
// `resolutionDivider` times coarser than the frame in each direction (1 = full resolution).
struct RenderWork {
  int firstSample = 0;
  int sampleCount = 1;
  int resolutionDivider = 1;
  bool operator==(const RenderWork&) const = default;
};

// The schedule as a pure value: a coarse preview at `startDivider` (halving to 1, one sample
// each), then full resolution in waves of 1, 1, 2, 4, ... samples (at most `maxWave`) until
// `targetSpp` samples per pixel.
std::vector<RenderWork> makeRenderSchedule(int targetSpp, int startDivider = 8, int maxWave = 16);

struct RenderFrame {
  uint64_t sceneVersion = 0;
  int width = 0, height = 0;
  int spp = 0;                // full-resolution samples per pixel (0 during the preview);
                              // under a noise target the most any pixel has
  double meanSpp = 0;         // full-resolution samples per pixel, averaged over the frame
  int resolutionDivider = 1;  // > 1 for preview frames (upsampled to full size)
  double seconds = 0;         // since the version's render began
  ImageF withObjects;         // W x H x 3 means
  ImageF withoutObjects;      // W x H x 3
  ImageF mask;                // W x H x 1
  // W x H x 1: samples per pixel and each pixel's estimated standard error (sRGB [0,1]) in
  // final full-resolution frames, and in every full-resolution frame under a noise target;
  // empty otherwise.
  ImageF samples;
  ImageF noise;
  // Estimated RMSE (sRGB [0,1]) of the composite over the pixels it changes: per pixel the
  // variance of the mean of each sample's change to the composite (with - photo where the
  // camera ray meets an object, with - without elsewhere; so the mask's noise is included)
  // from the running sums, times the sRGB slope at the pixel's with-object value; exposure is
  // not included.
  double estimatedError = 0;
  // withObjects is the denoiser's (SessionOptions::denoise; render/denoise.h): its composite is
  // the photo plus the filtered delta. estimatedError, samples and noise stay the raw render's.
  bool denoised = false;
  bool final = false;      // target reached for this version
  bool converged = false;  // final because every pixel met SessionOptions::noiseTarget
};

// Implemented by the host (the CLI writes files, the studio converts to a QImage).
// Called on the render thread; must be quick and must not call back into the session.
class FrameSink {
 public:
  virtual ~FrameSink() = default;
  virtual void onFrame(std::shared_ptr<const RenderFrame> frame) = 0;
};

// Keeps the newest frame for a thread that waits for the render (inlay-cli's render and batch);
// `onEach`, when given, also sees every frame on the render thread, one at a time.
class LastFrameSink : public FrameSink {
 public:
  explicit LastFrameSink(std::function<void(const RenderFrame&)> onEach = {})
      : onEach_(std::move(onEach)) {}
  void onFrame(std::shared_ptr<const RenderFrame> frame) override {
    std::lock_guard<std::mutex> lock(m_);
    if (onEach_) onEach_(*frame);
    last_ = std::move(frame);
  }
  std::shared_ptr<const RenderFrame> last() const {
    std::lock_guard<std::mutex> lock(m_);
    return last_;
  }

 private:
  mutable std::mutex m_;
  std::shared_ptr<const RenderFrame> last_;
  std::function<void(const RenderFrame&)> onEach_;
};

struct SessionOptions {
  int targetSpp = 256;
  double seconds = 0;  // 0 = no time limit (per scene version; the first wave always
                       // completes, so every version gets a frame)
  uint32_t seed = 1;
  int threads = 0;  // 0 = all cores
  int startDivider = 8;
  // false: every full-resolution wave samples every pixel. true: after the first two waves,
  // pixels where no sample has yet met an object (with == without, and no pixel within 2
  // that sees the object) take part in every 4th wave only, so the samples go where the
  // composite changes. Each pixel still averages its own samples (no bias); quiet pixels just have
  // fewer of them, and a quiet pixel that meets an object becomes active again.
  bool focusOnChanges = false;
  // Adaptive sampling: > 0 samples a pixel only while the standard error of its composite
  // (sRGB [0,1], estimated from its own samples as in RenderFrame::estimatedError) is above
  // this, or a neighbour's is, or it has fewer than `minSamples`; the version ends (converged)
  // when no pixel needs more, else at targetSpp (per pixel) or the time limit. Pixels no
  // sample has changed (the photo as it is) stop at `quietSamples`, so the work goes to the
  // objects, their shadows and bounce light. Replaces focusOnChanges' schedule. Each pixel
  // still averages its own samples, and with == without stays exact wherever no path met an
  // object.
  double noiseTarget = 0;
  int minSamples = 16;
  int quietSamples = 4;
  TracerOptions tracer;
  // Denoise full-resolution frames (render/denoise.h; coarse previews are left as they are):
  // All of them (the studio's live preview), or only the version's final frame (a host that
  // keeps only the last frame, as the CLI). Costs one camera ray per pixel once per version
  // (the guides) and the filter per denoised frame.
  enum class Denoise { Off, Final, All };
  Denoise denoise = Denoise::Off;
};

class RenderSession {
 public:
  RenderSession(FrameSink* sink, const SessionOptions& options);
  ~RenderSession();  // stops the thread (cancels the current wave)
  RenderSession(const RenderSession&) = delete;
  RenderSession& operator=(const RenderSession&) = delete;

  // Replace the whole scene (rebuilds the BVHs). Returns the new scene version.
  uint64_t setScene(const RenderScene& scene);
  // Move one inserted object (an instance update only). Returns the new scene version.
  uint64_t setObjectTransform(size_t index, const Mat4& worldFromObject);
  void setOptions(const SessionOptions& options);  // restarts the current version
  // Blocks until the current version reached its target (or time limit), or was cancelled.
  // Returns false on timeout (seconds <= 0: wait forever).
  bool waitUntilDone(double timeoutSeconds = 0);
  void cancel();  // stop rendering the current version (state: idle)
  uint64_t version() const;
  bool busy() const;
  // PathTracers this session has made so far: one per setScene (or tracer option change) that the
  // render thread picked up; a move (setObjectTransform) makes none (tests count them).
  uint64_t tracerBuilds() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace inlay
