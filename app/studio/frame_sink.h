// The studio's FrameSink: turns each RenderFrame into the displayable composite on the render
// thread and hands the newest one to the GUI thread.
//
// Threads: onFrame() runs on the render thread (RenderSession's); setContext() and
// setMinVersion() on the GUI thread; take() on the GUI thread. One small mutex guards the slot
// holding the newest image; it is never held while compositing, so the GUI never waits for
// the renderer. Frames of a scene version older than the newest one the GUI asked for are
// dropped before any work is done. `notify` is called (on the render thread) once per new
// image until the GUI took it; it must only post (QMetaObject::invokeMethod, queued).
#pragma once

#include "inlay/engine/pipeline.h"

#include <QImage>

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>

namespace inlay::studio {

// One displayable frame.
struct CompositeImage {
  uint64_t sceneVersion = 0;
  int spp = 0;
  int resolutionDivider = 1;
  double seconds = 0;
  double estimatedError = 0;
  bool final = false;
  QImage srgb8;                              // the composite, 8-bit (the photo's response)
  std::shared_ptr<const ImageF> linear;      // the composite, linear (for export)
  std::shared_ptr<const RenderFrame> frame;  // the renderer's frame (the layers' source)
};

class CompositeSink : public FrameSink {
 public:
  explicit CompositeSink(std::function<void()> notify);

  // What compositeOf needs of the prepared scene; the sink keeps its own immutable copy so the
  // GUI may edit the document's PreparedScene without locking. `minVersion`: see below.
  void setContext(std::shared_ptr<const PreparedScene> context, uint64_t minVersion);
  // Frames older than this scene version are dropped.
  void setMinVersion(uint64_t version);
  // The newest image not yet taken (GUI thread).
  std::optional<CompositeImage> take();

  void onFrame(std::shared_ptr<const RenderFrame> frame) override;

  // A copy of the parts of `scene` that compositeOf reads: the photo, its measured noise (the
  // grain), the camera response and the document's render keys (exposure, grain, seed), plus the
  // camera and room for completeness.
  static std::shared_ptr<const PreparedScene> compositeContextOf(const PreparedScene& scene);

 private:
  std::function<void()> notify_;
  std::atomic<uint64_t> minVersion_{0};
  std::mutex mutex_;  // guards context_, pending_
  std::shared_ptr<const PreparedScene> context_;
  // The grain fields of context_ (render/grain.h grainField), made on its first full-resolution
  // frame; null until then.
  std::shared_ptr<const ImageF> grainField_;
  std::optional<CompositeImage> pending_;
};

}  // namespace inlay::studio
