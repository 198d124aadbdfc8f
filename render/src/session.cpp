// RenderSession: one long-lived render thread with the states wait / render / end, a delayed
// reset (edits bump the version and cancel; the thread applies them between waves, once the
// wave's tiles have stopped), and the pure schedule.
//
// Lock order: only Impl::mutex, never held while rendering or while calling the sink.
#include "inlay/render/session.h"

#include "inlay/render/denoise.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <limits>
#include <map>
#include <mutex>
#include <thread>
#include <utility>

namespace inlay {

std::vector<RenderWork> makeRenderSchedule(int targetSpp, int startDivider, int maxWave) {
  std::vector<RenderWork> work;
  for (int d = startDivider; d > 1; d /= 2) work.push_back({0, 1, d});
  maxWave = std::max(1, maxWave);
  int done = 0;
  while (done < targetSpp) {
    // 1, 1, 2, 4, ...: each wave doubles the samples so far, up to maxWave.
    const int n = std::min({std::max(1, done), maxWave, targetSpp - done});
    work.push_back({done, n, 1});
    done += n;
  }
  return work;
}

namespace {

using Clock = std::chrono::steady_clock;

// Standard error, in sRGB [0,1], of pixel i's composite from its own samples: the variance of
// the mean of the per-sample change (DifferentialBuffers::sumChange: the photo is a constant,
// so the composite's noise is the change's, the mask's included), averaged over RGB (unbiased
// with n >= 2, the raw second moment with n = 1), mapped to sRGB by the slope at the pixel's
// mean with-object value (the composite's value where the render matches the photo).
// Unsampled pixels: 0.
double pixelError(const DifferentialBuffers& b, size_t i) {
  const int n = b.samples[i];
  if (n <= 0) return 0;
  const float* ch = &b.sumChange.data[i * 3];
  const float* w = &b.sumWith.data[i * 3];
  const double m2 = b.sumChangeSq.data[i] / n;
  double meanSq = 0, meanWith = 0;
  for (int c = 0; c < 3; ++c) {
    const double mc = double(ch[c]) / n;
    meanSq += mc * mc / 3.0;
    meanWith += w[c] / (3.0 * n);
  }
  const double var = n >= 2 ? std::max(0.0, m2 - meanSq) * n / (n - 1.0) : m2;
  return srgbSlope(meanWith) * std::sqrt(var / n);
}

// Pixel i's composite differs from the photo in some sample (an object seen, or with != without).
bool changed(const DifferentialBuffers& b, size_t i) {
  const float* w = &b.sumWith.data[i * 3];
  const float* wo = &b.sumWithout.data[i * 3];
  return b.sumChangeSq.data[i] > 0 || b.sumMask.data[i] > 0 || w[0] != wo[0] || w[1] != wo[1] ||
         w[2] != wo[2];
}

// RenderFrame::samples and ::noise from the buffers.
void addSampleLayers(RenderFrame& frame, const DifferentialBuffers& b) {
  frame.samples = ImageF(b.width, b.height, 1);
  std::copy(b.samples.begin(), b.samples.end(), frame.samples.data.begin());
  frame.noise = ImageF(b.width, b.height, 1);
  for (size_t i = 0; i < b.samples.size(); ++i) frame.noise.data[i] = float(pixelError(b, i));
}

double meanSamples(const DifferentialBuffers& b) {
  double sum = 0;
  for (int n : b.samples) sum += n;
  return b.samples.empty() ? 0.0 : sum / double(b.samples.size());
}

// Estimated RMSE, in sRGB [0,1], of the composite over the pixels it changes (pixelError's
// root mean square over them).
double estimateError(const DifferentialBuffers& b) {
  double sum = 0;
  size_t count = 0;
  for (size_t i = 0; i < b.samples.size(); ++i)
    if (b.samples[i] > 0 && changed(b, i)) {
      const double e = pixelError(b, i);
      sum += e * e;
      ++count;
    }
  return count ? std::sqrt(sum / double(count)) : 0.0;
}

}  // namespace

namespace {

// Pixels where the composite may change: some sample met an object (a difference, or the
// object seen), and pixels within 2 of one that sees the object (its edge may not be sampled
// yet). Sparse indirect touches are not dilated: they say little about their neighbours.
std::vector<uint8_t> activePixels(const DifferentialBuffers& b) {
  const int w = b.width, h = b.height;
  std::vector<uint8_t> active(size_t(w) * h, 0);
  constexpr int r = 2;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float* a = b.sumWith.pixel(x, y);
      const float* c = b.sumWithout.pixel(x, y);
      if (b.sumDiffSq.at(x, y) > 0 || a[0] != c[0] || a[1] != c[1] || a[2] != c[2])
        active[size_t(y) * w + x] = 1;
      if (b.sumMask.at(x, y) > 0)
        for (int yy = std::max(0, y - r); yy <= std::min(h - 1, y + r); ++yy)
          for (int xx = std::max(0, x - r); xx <= std::min(w - 1, x + r); ++xx)
            active[size_t(yy) * w + xx] = 1;
    }
  return active;
}

// One focused wave: count[i] more samples in pixel i (each pixel continuing its own sample
// sequence), tile by tile in parallel; false when stopped.
bool renderFocused(const PathTracer& tracer, DifferentialBuffers& b, const std::vector<int>& count,
                   const SessionOptions& opt, const CancelToken& token) {
  return tracer.renderCounts(b, count, opt.seed, opt.threads, &token);
}

// focusOnChanges without a noise target: after two waves, `count` samples in the active pixels
// only, and in every pixel every 4th wave. Empty: the whole frame (all pixels have one count).
std::vector<int> focusedCounts(const DifferentialBuffers& b, int fullWaves, int count,
                               const SessionOptions& opt) {
  if (!opt.focusOnChanges || fullWaves < 2) return {};
  std::vector<int> counts(b.samples.size(), count);
  if (fullWaves % 4 == 0) return counts;
  const std::vector<uint8_t> active = activePixels(b);
  for (size_t i = 0; i < counts.size(); ++i) counts[i] = active[i] ? count : 0;
  return counts;
}

// Adaptive sampling toward the error `level` (sRGB standard error): the samples each pixel takes
// next. A pixel no sample has changed (the photo as it is) takes up to `quietSamples` (a few
// tell the room away from the objects apart from their shadows and bounce light), a changed
// one up to `minSamples` (enough for a variance); then a pixel whose error e, or a neighbour's
// (a converged pixel beside a noisy one may just not have been lucky yet; Cycles dilates the
// same way), is above the level takes what its variance says reaches it, n ((e / level)^2 - 1),
// at most doubling its samples (the estimate is rough) and never beyond targetSpp.
std::vector<int> adaptiveCounts(const DifferentialBuffers& b, double level, const SessionOptions& opt) {
  const int w = b.width, h = b.height;
  std::vector<double> ratio(b.samples.size(), 0.0);  // (e / level)^2 of changed pixels
  std::vector<uint8_t> isChanged(b.samples.size(), 0);
  for (size_t i = 0; i < ratio.size(); ++i) {
    isChanged[i] = changed(b, i);
    if (isChanged[i]) ratio[i] = std::pow(pixelError(b, i) / level, 2);
  }
  std::vector<int> counts(ratio.size(), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      const int n = b.samples[i];
      double r = 0;
      for (int yy = std::max(0, y - 1); yy <= std::min(h - 1, y + 1); ++yy)
        for (int xx = std::max(0, x - 1); xx <= std::min(w - 1, x + 1); ++xx)
          r = std::max(r, ratio[size_t(yy) * w + xx]);
      int c = std::max(0, (isChanged[i] ? opt.minSamples : opt.quietSamples) - n);
      if (r > 1 && n > 0) c = std::max(c, int(std::min(double(n), std::ceil(n * (r - 1)))));
      counts[i] = std::clamp(c, 0, std::max(0, opt.targetSpp - n));
    }
  return counts;
}

// The q-quantile (q in [0, 1]) of the changed pixels' errors; 0 when none changed.
double errorQuantile(const DifferentialBuffers& b, double q) {
  std::vector<double> e;
  for (size_t i = 0; i < b.samples.size(); ++i)
    if (changed(b, i)) e.push_back(pixelError(b, i));
  if (e.empty()) return 0;
  const size_t k = std::min(e.size() - 1, size_t(std::lround(q * double(e.size() - 1))));
  std::nth_element(e.begin(), e.begin() + std::ptrdiff_t(k), e.end());
  return e[k];
}

}  // namespace

struct RenderSession::Impl {
  FrameSink* sink = nullptr;
  mutable std::mutex mutex;
  std::condition_variable wake;    // the render thread waits on it
  std::condition_variable doneCv;  // waitUntilDone waits on it
  SessionOptions options;
  std::shared_ptr<const RenderScene> scene;  // as last set (transforms: see the moves)
  // Latest transform per object index (a drag sends many; only the last one matters).
  std::map<size_t, Mat4> movesSinceScene;  // applied after every rebuild
  std::map<size_t, Mat4> pendingMoves;     // not yet given to the tracer
  bool rebuild = false;
  uint64_t version = 0;
  uint64_t doneVersion = 0;  // last version finished (target, time limit or cancel())
  bool working = false;
  bool stop = false;
  uint64_t tracerBuilds = 0;
  CancelToken token;  // cancel and the per-version time limit, polled per pixel
  std::thread thread;

  void run();
  // Renders version v; returns when done, out of time or cancelled.
  // The time limit counts from `pickedUp`; the first wave always completes (unless cancelled),
  // so a version always gets a frame.
  void renderVersion(uint64_t v, const SessionOptions& opt, const PathTracer& tracer,
                     std::chrono::steady_clock::time_point pickedUp);
  void publish(uint64_t v, std::shared_ptr<const RenderFrame> frame) {
    {
      std::lock_guard<std::mutex> lock(mutex);
      if (version != v) return;  // stale: a newer version is on its way
    }
    if (sink) sink->onFrame(std::move(frame));
  }
};

void RenderSession::Impl::run() {
  std::unique_ptr<PathTracer> tracer;
  for (;;) {
    std::unique_lock<std::mutex> lock(mutex);
    wake.wait(lock, [&] { return stop || (scene && version != doneVersion); });
    if (stop) return;
    const uint64_t v = version;
    const bool rebuildNow = rebuild || !tracer;
    rebuild = false;
    if (rebuildNow) ++tracerBuilds;
    std::map<size_t, Mat4> moves;
    if (rebuildNow) moves = movesSinceScene;
    else moves = pendingMoves;
    pendingMoves.clear();
    const std::shared_ptr<const RenderScene> sceneNow = scene;
    const SessionOptions opt = options;
    token.reset();
    token.setDeadlineFromNow(0);  // the time limit starts to apply after the first frame
    const auto pickedUp = Clock::now();
    working = true;
    lock.unlock();

    // The safe point: no wave is running, so the tracer may change.
    if (rebuildNow) tracer = std::make_unique<PathTracer>(*sceneNow, opt.tracer);
    for (const auto& [index, m] : moves) tracer->setObjectTransform(index, m);
    renderVersion(v, opt, *tracer, pickedUp);

    lock.lock();
    working = false;
    if (version == v) doneVersion = v;
    doneCv.notify_all();
  }
}

void RenderSession::Impl::renderVersion(uint64_t v, const SessionOptions& opt, const PathTracer& tracer,
                                        Clock::time_point pickedUp) {
  const auto start = Clock::now();
  const Camera& cam = tracer.scene().camera;
  const int w = cam.widthPx, h = cam.heightPx;
  if (w <= 0 || h <= 0) return;
  auto seconds = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  DifferentialBuffers full;  // allocated at the first full-resolution wave (previews stay cheap)
  int spp = 0;
  int fullWaves = 0;
  bool converged = false;                   // every pixel met the noise target before the sample cap
  bool pendingFrame = false;                // samples added since the last frame published
  std::shared_ptr<const RenderFrame> last;  // the last frame published for this version
  DenoiseGuides guides;  // SessionOptions::denoise: from `full`'s guide sums, per frame
  auto send = [&](std::shared_ptr<const RenderFrame> frame) {
    if (!last && opt.seconds > 0) {
      const double left = opt.seconds - std::chrono::duration<double>(Clock::now() - pickedUp).count();
      token.setDeadlineFromNow(std::max(1e-9, left));
    }
    last = frame;
    publish(v, std::move(frame));
  };
  // The full-resolution buffers as a frame (final: the version's last).
  auto publishFull = [&](bool final) {
    // An edit (or cancel()) came during the wave: its frame would be dropped as stale, and the
    // means, the denoiser and the sink's composite would only delay the new version's first frame.
    if (token.cancelled()) return;
    auto frame = std::make_shared<RenderFrame>();
    frame->sceneVersion = v;
    frame->width = w, frame->height = h;
    frame->spp = spp;
    frame->resolutionDivider = 1;
    frame->withObjects = full.meanWith();
    frame->withoutObjects = full.meanWithout();
    frame->mask = full.meanMask();
    frame->estimatedError = estimateError(full);
    frame->meanSpp = meanSamples(full);
    // The per-pixel layers cost a frame's worth of work: final frames, and adaptive ones, only.
    if (final || opt.noiseTarget > 0) addSampleLayers(*frame, full);
    frame->final = final;
    if (opt.denoise == SessionOptions::Denoise::All ||
        (final && opt.denoise == SessionOptions::Denoise::Final))
      denoiseSessionFrame(*frame, full, tracer, &guides, opt.threads);
    frame->seconds = seconds();
    pendingFrame = false;
    send(std::move(frame));
  };
  // Adaptive sampling after the first uniform waves: error levels falling by sqrt(2) from the
  // noisiest pixel's down to the target, each wave bringing the pixels above the level to it
  // (so a time limit leaves the errors even, not the samples). False when cancelled.
  auto renderAdaptive = [&] {
    double level = std::numeric_limits<double>::infinity();  // first: the minimum samples only
    for (;;) {
      if (token.shouldStop()) return true;
      const std::vector<int> counts = adaptiveCounts(full, level, opt);
      if (std::none_of(counts.begin(), counts.end(), [](int c) { return c > 0; })) {
        if (level <= opt.noiseTarget) {
          converged = errorQuantile(full, 1.0) <= opt.noiseTarget;  // else some pixel is at targetSpp
          return true;
        }
        // The first level: the 99th percentile (the few pixels above it double their samples
        // in every wave anyway; starting at the largest would spend waves on fireflies alone).
        level = std::max(opt.noiseTarget,
                         std::isinf(level) ? errorQuantile(full, 0.99) : level / std::sqrt(2.0));
        continue;
      }
      const bool complete = renderFocused(tracer, full, counts, opt, token);
      if (!complete && token.cancelled()) return false;
      spp = *std::max_element(full.samples.begin(), full.samples.end());
      // Waves get short near the end; a frame at most every 0.25 s (and the last one).
      if (!complete || !last || seconds() - last->seconds >= 0.25) publishFull(!complete);
      else pendingFrame = true;
      if (!complete) return true;
    }
  };
  for (const RenderWork& work : makeRenderSchedule(opt.targetSpp, opt.startDivider)) {
    if (token.shouldStop()) break;
    if (work.resolutionDivider > 1) {
      // Coarse preview: a grid d times coarser (each coarse pixel samples its d x d cell),
      // shown nearest-upsampled at full size.
      const int d = work.resolutionDivider;
      const int cw = (w + d - 1) / d, ch = (h + d - 1) / d;
      DifferentialBuffers preview(cw, ch);
      if (!tracer.render(preview, work.firstSample, work.sampleCount, opt.seed ^ 0x9E3779B9u,
                         opt.threads, &token))
        break;
      auto frame = std::make_shared<RenderFrame>();
      frame->sceneVersion = v;
      frame->width = w, frame->height = h;
      frame->spp = 0;
      frame->resolutionDivider = d;
      const ImageF mw = preview.meanWith(), mwo = preview.meanWithout(), mm = preview.meanMask();
      frame->withObjects = ImageF(w, h, 3);
      frame->withoutObjects = ImageF(w, h, 3);
      frame->mask = ImageF(w, h, 1);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const int sx = std::min(cw - 1, x / d), sy = std::min(ch - 1, y / d);
          frame->withObjects.setRgb(x, y, mw.rgb(sx, sy));
          frame->withoutObjects.setRgb(x, y, mwo.rgb(sx, sy));
          frame->mask.at(x, y) = mm.at(sx, sy);
        }
      frame->estimatedError = estimateError(preview);
      frame->seconds = seconds();
      send(std::move(frame));
      continue;
    }
    if (full.width != w) {
      full = DifferentialBuffers(w, h);
      // The denoiser's guides come from the render's own camera paths (render/denoise.h).
      if (opt.denoise != SessionOptions::Denoise::Off) full.enableGuides();
    }
    if (opt.noiseTarget > 0 && spp >= std::min(opt.quietSamples, opt.targetSpp))
      break;  // adaptive from here
    const std::vector<int> counts = focusedCounts(full, fullWaves, work.sampleCount, opt);
    // With no counts every pixel has the same count: the wave's first sample is each pixel's next.
    const bool complete = counts.empty() ? tracer.render(full, work.firstSample, work.sampleCount,
                                                         opt.seed, opt.threads, &token)
                                         : renderFocused(tracer, full, counts, opt, token);
    ++fullWaves;
    if (complete) spp += work.sampleCount;
    if (!complete && token.cancelled()) return;  // an edit or cancel(): publish nothing
    const bool outOfTime = !complete;
    // Out of time inside the first full-resolution wave: its buffer holds no whole sample
    // (some tiles none at all), so the last preview stays the final frame (below).
    if (outOfTime && spp == 0 && last) break;
    publishFull(outOfTime || spp >= opt.targetSpp);
    if (outOfTime) return;
  }
  if (opt.noiseTarget > 0 && spp > 0 && last && !last->final && !renderAdaptive()) return;
  if (pendingFrame && !token.cancelled()) publishFull(false);  // the adaptive waves' latest
  // Out of time between waves or during the preview: the last frame becomes the final one.
  if (!token.cancelled() && last && !last->final) {
    auto frame = std::make_shared<RenderFrame>(*last);
    frame->final = true;
    frame->converged = converged;
    if (frame->samples.empty() && frame->resolutionDivider == 1 && full.width == w)
      addSampleLayers(*frame, full);
    if (opt.denoise != SessionOptions::Denoise::Off && !frame->denoised &&
        frame->resolutionDivider == 1 && full.width == w)
      denoiseSessionFrame(*frame, full, tracer, &guides, opt.threads);
    frame->seconds = seconds();
    send(std::move(frame));
  }
}

RenderSession::RenderSession(FrameSink* sink, const SessionOptions& options)
    : impl_(std::make_unique<Impl>()) {
  impl_->sink = sink;
  impl_->options = options;
  impl_->thread = std::thread([this] { impl_->run(); });
}

RenderSession::~RenderSession() {
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    impl_->stop = true;
    impl_->token.cancel();
  }
  impl_->wake.notify_all();
  impl_->thread.join();
}

uint64_t RenderSession::setScene(const RenderScene& scene) {
  auto copy = std::make_shared<const RenderScene>(scene);  // the copy outside the lock
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->scene = std::move(copy);
  impl_->movesSinceScene.clear();
  impl_->pendingMoves.clear();
  impl_->rebuild = true;
  impl_->token.cancel();
  const uint64_t v = ++impl_->version;
  impl_->wake.notify_all();
  return v;
}

uint64_t RenderSession::setObjectTransform(size_t index, const Mat4& worldFromObject) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->movesSinceScene[index] = worldFromObject;
  impl_->pendingMoves[index] = worldFromObject;
  impl_->token.cancel();
  const uint64_t v = ++impl_->version;
  impl_->wake.notify_all();
  return v;
}

void RenderSession::setOptions(const SessionOptions& options) {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  const TracerOptions& a = impl_->options.tracer;
  const TracerOptions& b = options.tracer;
  if (a.maxDepth != b.maxDepth || a.maxGlassDepth != b.maxGlassDepth ||
      a.splitGlassAtCamera != b.splitGlassAtCamera || a.russianRouletteDepth != b.russianRouletteDepth ||
      a.clampRadiance != b.clampRadiance || a.causticPhotons != b.causticPhotons ||
      a.causticRadius != b.causticRadius)
    impl_->rebuild = true;
  impl_->options = options;
  impl_->token.cancel();
  ++impl_->version;
  impl_->wake.notify_all();
}

bool RenderSession::waitUntilDone(double timeoutSeconds) {
  std::unique_lock<std::mutex> lock(impl_->mutex);
  auto done = [&] { return !impl_->scene || (impl_->doneVersion == impl_->version && !impl_->working); };
  if (timeoutSeconds <= 0) {
    impl_->doneCv.wait(lock, done);
    return true;
  }
  return impl_->doneCv.wait_for(lock, std::chrono::duration<double>(timeoutSeconds), done);
}

void RenderSession::cancel() {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  impl_->token.cancel();
  if (!impl_->working) impl_->doneVersion = impl_->version;  // not started: nothing to stop
  impl_->doneCv.notify_all();
}

uint64_t RenderSession::version() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->version;
}

uint64_t RenderSession::tracerBuilds() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->tracerBuilds;
}

bool RenderSession::busy() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->scene && (impl_->working || impl_->doneVersion != impl_->version);
}

}  // namespace inlay
