#include "render_controller.h"

#include "image_convert.h"
#include "inlay/modeling/image_io.h"

#include <QImageReader>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace inlay::studio {
namespace {

// `camera` seeing the same view on a grid of `width` x `height` pixels.
Camera scaledCamera(const Camera& camera, int width, int height) {
  Camera c = camera;
  const double sx = double(width) / camera.widthPx, sy = double(height) / camera.heightPx;
  c.widthPx = width;
  c.heightPx = height;
  c.focalPx = camera.focalPx * 0.5 * (sx + sy);  // sx and sy differ by the rounding only
  c.principalPx = Vec2(camera.principalPx.x() * sx, camera.principalPx.y() * sy);
  return c;
}

}  // namespace

QSize RenderController::previewSizeFor(int width, int height) {
  const double pixels = double(width) * height;
  if (width <= 0 || height <= 0 || pixels <= kPreviewMaxPixels) return {width, height};
  const double s = std::sqrt(kPreviewMaxPixels / pixels);
  return {std::max(1, int(std::lround(width * s))), std::max(1, int(std::lround(height * s)))};
}

RenderScene RenderController::previewScene(const PreparedScene& prepared) const {
  RenderScene scene = shownRenderScene(prepared);
  if (previewSize_.isValid() && previewSize_ != QSize(scene.camera.widthPx, scene.camera.heightPx))
    scene.camera = scaledCamera(scene.camera, previewSize_.width(), previewSize_.height());
  return scene;
}

RenderController::RenderController(Document* document, QObject* parent)
    : QObject(parent), document_(document) {
  sink_ = std::make_unique<CompositeSink>([this] {
    // Render thread: only post. The queued call is discarded if this object is gone. By name,
    // so the queued event holds nothing our code reads: Qt's hand-off of it is invisible to
    // ThreadSanitizer; the frame itself crosses under the sink's mutex.
    QMetaObject::invokeMethod(this, "takeFrame", Qt::QueuedConnection);
  });
  connect(document_, &Document::changed, this, &RenderController::onDocumentChanged);
}

RenderController::~RenderController() {
  session_.reset();  // joins the render thread: no onFrame() after this line
}

void RenderController::request(uint64_t version) {
  requestedVersion_ = version;
  sink_->setMinVersion(version);
}

void RenderController::requestScene(const PreparedScene& prepared) {
  hiddenSent_.clear();
  for (const ObjectKeys& o : prepared.doc.objects) hiddenSent_.push_back(o.hidden);
  request(session_->setScene(previewScene(prepared)));
}

uint64_t RenderController::tracerBuilds() const { return session_ ? session_->tracerBuilds() : 0; }

void RenderController::startScene() {
  const PreparedScene* prepared = document_->prepared();
  if (!prepared) return;
  SessionOptions options;
  options.targetSpp = std::max(1, prepared->doc.render.spp);
  options.seconds = prepared->doc.render.seconds.value_or(0.0);
  options.seed = prepared->doc.render.seed;
  options.tracer.clampRadiance = prepared->doc.render.clampIndirect;  // as the final render
  // Samples go where the objects change the photo (the part a user watches while dragging).
  options.focusOnChanges = true;
  // The first frame after an edit: one sample per 16 x 16 block (a quarter of the 8 x 8 wave's
  // paths, so it shows the edit sooner), then 8, 4, 2 and full resolution.
  options.startDivider = kFirstPreviewDivider;
  options.denoise = denoise_ ? SessionOptions::Denoise::All : SessionOptions::Denoise::Off;
  if (!session_) {
    session_ = std::make_unique<RenderSession>(sink_.get(), options);
  } else {
    session_->cancel();
    session_->setOptions(options);
  }
  // Before setScene: a frame of the new version must find the new context (with the photo at
  // the preview's size).
  previewSize_ = previewSizeFor(prepared->camera.widthPx, prepared->camera.heightPx);
  std::shared_ptr<const PreparedScene> context = CompositeSink::compositeContextOf(*prepared);
  if (previewSize_ != QSize(prepared->camera.widthPx, prepared->camera.heightPx)) {
    auto reduced = std::make_shared<PreparedScene>(*context);
    reduced->photo.linearRgb =
        resizeImage(context->photo.linearRgb, previewSize_.width(), previewSize_.height());
    reduced->camera = scaledCamera(context->camera, previewSize_.width(), previewSize_.height());
    ImageF& unclipped = reduced->renderScene.roomAlbedo.photoRadiance;
    if (!unclipped.empty())
      unclipped = resizeImage(unclipped, previewSize_.width(), previewSize_.height());
    context = std::move(reduced);
  }
  sink_->setContext(std::move(context), requestedVersion_ + 1);
  requestScene(*prepared);
  if (paused_) session_->cancel();
}

void RenderController::setPaused(bool paused) {
  if (paused_ == paused) return;
  paused_ = paused;
  if (!session_) return;
  if (paused_) {
    session_->cancel();
  } else if (const PreparedScene* prepared = document_->prepared(); prepared && document_->isReady()) {
    requestScene(*prepared);
  }
}

void RenderController::setDenoise(bool on) {
  if (denoise_ == on) return;
  denoise_ = on;
  if (session_ && document_->prepared()) startScene();
}

void RenderController::onDocumentChanged(const ChangeEvent& event) {
  if (event.has(ChangeEvent::SceneReplaced) || event.has(ChangeEvent::PrepareStarted) ||
      event.has(ChangeEvent::PrepareFinished))
    for (CachedLayer& c : layerCache_) c = {};
  if (event.has(ChangeEvent::SceneReplaced)) {
    if (session_) session_->cancel();
    sink_->setContext(nullptr, requestedVersion_ + 1);
    composite_ = {};
    // A quick preview so the user sees the photo while the engine prepares it.
    QImageReader reader(QString::fromStdString(document_->scene().photoResolved));
    reader.setAutoTransform(true);
    photo_ = reader.read();
    Q_EMIT frameUpdated();
  }
  if (event.has(ChangeEvent::PrepareStarted) && session_) session_->cancel();
  if (event.has(ChangeEvent::PrepareFinished)) {
    if (const PreparedScene* prepared = document_->prepared()) {
      photo_ = encoded8FromLinear(prepared->photo.linearRgb, prepared->response,
                                  prepared->doc.render.exposure);
      composite_ = {};
      startScene();
      Q_EMIT frameUpdated();
    }
  }
  const PreparedScene* prepared = document_->prepared();
  if (session_ && prepared && event.has(ChangeEvent::ObjectsAddedOrRemoved)) {
    if (!paused_) requestScene(*prepared);
    return;
  }
  if (!session_ || !prepared || event.objectIndex < 0 ||
      size_t(event.objectIndex) >= prepared->renderScene.objects.size())
    return;
  if (paused_) return;  // setPaused(false) renders the scene as it is then
  const size_t i = size_t(event.objectIndex);
  const bool hiddenChanged = event.has(ChangeEvent::ObjectShown) &&
                             (i >= hiddenSent_.size() || i >= prepared->doc.objects.size() ||
                              hiddenSent_[i] != prepared->doc.objects[i].hidden);
  if (event.has(ChangeEvent::ObjectMaterial) || hiddenChanged) {
    requestScene(*prepared);  // carries the new transform too
  } else if (event.has(ChangeEvent::ObjectPlacement)) {
    request(session_->setObjectTransform(
        size_t(event.objectIndex),
        prepared->renderScene.objects[size_t(event.objectIndex)].worldFromObject));
  }
}

namespace {

// |a - b| per channel, times `gain`, of two images of one size (8-bit).
QImage differenceOf(const QImage& a, const QImage& b, int gain) {
  if (a.size() != b.size() || a.isNull()) return {};
  const QImage x = a.convertToFormat(QImage::Format_RGB32);
  const QImage y = b.convertToFormat(QImage::Format_RGB32);
  QImage out(x.size(), QImage::Format_RGB32);
  for (int r = 0; r < x.height(); ++r) {
    const auto* p = reinterpret_cast<const QRgb*>(x.constScanLine(r));
    const auto* q = reinterpret_cast<const QRgb*>(y.constScanLine(r));
    auto* o = reinterpret_cast<QRgb*>(out.scanLine(r));
    for (int c = 0; c < x.width(); ++c) {
      auto d = [&](int u, int v) { return std::min(255, gain * std::abs(u - v)); };
      o[c] = qRgb(d(qRed(p[c]), qRed(q[c])), d(qGreen(p[c]), qGreen(q[c])), d(qBlue(p[c]), qBlue(q[c])));
    }
  }
  return out;
}

}  // namespace

QImage RenderController::layerImage(Layer layer) {
  const PreparedScene* prepared = document_->prepared();
  const RenderFrame* frame = composite_.frame.get();
  const double exposure = prepared ? prepared->doc.render.exposure : 0.0;
  // Radiance layers are shown through the photo's camera response, as the composite is.
  const CameraResponse response = prepared ? prepared->response : CameraResponse::srgb();
  // The source each layer is made from; its address is the cache key (a new prepared scene
  // or frame is a new object).
  const void* source = nullptr;
  switch (layer) {
    case Layer::Composite: return compositeImage();
    case Layer::Photo: return photoImage();
    case Layer::Albedo:
    case Layer::DirectLight: source = prepared ? &prepared->lighting : nullptr; break;
    case Layer::WithObjects:
    case Layer::WithoutObjects:
    case Layer::Mask:
    case Layer::Difference: source = frame; break;
  }
  if (!source) return {};
  CachedLayer& cached = layerCache_[int(layer)];
  if (cached.source == source && !cached.image.isNull()) return cached.image;
  QImage image;
  switch (layer) {
    case Layer::Albedo:
      // Reflectance is shown as is (exposure does not apply to it).
      image = srgb8FromLinear(prepared->lighting.albedo, 0.0);
      break;
    case Layer::DirectLight:
      // The preparation keeps the direct light at its working copy's size.
      image = encoded8FromLinear(resizeImage(prepared->lighting.direct, prepared->photo.linearRgb.width,
                                             prepared->photo.linearRgb.height),
                                 response, exposure);
      break;
    case Layer::WithObjects: image = encoded8FromLinear(frame->withObjects, response, exposure); break;
    case Layer::WithoutObjects:
      image = encoded8FromLinear(frame->withoutObjects, response, exposure);
      break;
    case Layer::Mask: image = srgb8FromLinear(frame->mask, 0.0); break;
    case Layer::Difference:
      // Against the photo at the composite's size (a big photo's preview is smaller).
      image = differenceOf(compositeImage(),
                           photoImage().size() == compositeImage().size()
                               ? photoImage()
                               : photoImage().scaled(compositeImage().size(), Qt::IgnoreAspectRatio,
                                                     Qt::SmoothTransformation),
                           4);
      break;
    default: break;
  }
  cached = {source, image};
  return image;
}

void RenderController::takeFrame() {
  std::optional<CompositeImage> image = sink_->take();
  if (!image || image->sceneVersion < requestedVersion_) return;
  composite_ = std::move(*image);
  // A freed frame's address may come back for a new one: the cache forgets frame layers here.
  for (Layer l : {Layer::WithObjects, Layer::WithoutObjects, Layer::Mask, Layer::Difference})
    layerCache_[int(l)] = {};
  Q_EMIT frameUpdated();
}

}  // namespace inlay::studio
