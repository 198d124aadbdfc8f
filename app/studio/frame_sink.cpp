#include "frame_sink.h"

#include "image_convert.h"

#include "inlay/render/grain.h"

namespace inlay::studio {

CompositeSink::CompositeSink(std::function<void()> notify) : notify_(std::move(notify)) {}

std::shared_ptr<const PreparedScene> CompositeSink::compositeContextOf(const PreparedScene& scene) {
  auto context = std::make_shared<PreparedScene>();
  context->doc.photo = scene.doc.photo;
  context->doc.photoResolved = scene.doc.photoResolved;
  context->doc.render = scene.doc.render;
  context->photo = scene.photo;
  context->response = scene.response;
  context->vignetting = scene.vignetting;
  context->photoNoise = scene.photoNoise;
  context->camera = scene.camera;
  context->box = scene.box;
  // The room's unclipped radiance, which the composite takes over a clipped sunlit patch: it
  // differs from the photo only where a sun's patch clips, so only a scene with a sun needs it.
  if (!scene.renderScene.suns.empty())
    context->renderScene.roomAlbedo.photoRadiance = scene.renderScene.roomAlbedo.photoRadiance;
  return context;
}

void CompositeSink::setContext(std::shared_ptr<const PreparedScene> context, uint64_t minVersion) {
  std::lock_guard lock(mutex_);
  context_ = std::move(context);
  grainField_.reset();
  minVersion_.store(minVersion);
  pending_.reset();
}

void CompositeSink::setMinVersion(uint64_t version) {
  uint64_t current = minVersion_.load();
  while (current < version && !minVersion_.compare_exchange_weak(current, version)) {
  }
}

std::optional<CompositeImage> CompositeSink::take() {
  std::lock_guard lock(mutex_);
  std::optional<CompositeImage> out = std::move(pending_);
  pending_.reset();
  return out;
}

void CompositeSink::onFrame(std::shared_ptr<const RenderFrame> frame) {
  if (!frame || frame->sceneVersion < minVersion_.load()) return;
  std::shared_ptr<const PreparedScene> context;
  std::shared_ptr<const ImageF> field;
  {
    std::lock_guard lock(mutex_);
    context = context_;
    field = grainField_;
  }
  if (!context || frame->width != context->photo.linearRgb.width ||
      frame->height != context->photo.linearRgb.height)
    return;  // a frame of a scene the GUI no longer shows
  // A coarse preview (blocks of d x d pixels, replaced within milliseconds) gets no grain: the
  // first frame after an edit comes sooner. Full-resolution frames get the grain compositeOf
  // gives, read from the context's field (drawn once per context, not per frame).
  const RenderKeys& keys = context->doc.render;
  const bool grain = frame->resolutionDivider == 1 && keys.grain && !context->photoNoise.empty();
  if (grain && !field) {
    field = std::make_shared<const ImageF>(
        grainField(context->photoNoise, frame->width, frame->height, keys.seed));
    std::lock_guard lock(mutex_);
    if (context == context_) grainField_ = field;
  }

  CompositeImage image;
  image.sceneVersion = frame->sceneVersion;
  image.spp = frame->spp;
  image.resolutionDivider = frame->resolutionDivider;
  image.seconds = frame->seconds;
  image.estimatedError = frame->estimatedError;
  image.final = frame->final;
  image.frame = frame;
  auto linear = std::make_shared<ImageF>(compositeOf(
      context->photo.linearRgb, keys.exposure, *frame, grain ? &context->photoNoise : nullptr, keys.seed,
      field.get(), &context->renderScene.roomAlbedo.photoRadiance, context->vignetting));
  // compositeOf already applied the scene's exposure. The room's unclipped radiance makes an
  // object's shadow on a clipped sunlit patch the same in the live frames as in the final render.
  image.srgb8 = encoded8FromLinear(*linear, context->response, 0.0);
  image.linear = std::move(linear);

  bool wasEmpty = false;
  {
    std::lock_guard lock(mutex_);
    if (frame->sceneVersion < minVersion_.load() || context != context_) return;
    wasEmpty = !pending_.has_value();
    pending_ = std::move(image);
  }
  if (wasEmpty && notify_) notify_();
}

}  // namespace inlay::studio
