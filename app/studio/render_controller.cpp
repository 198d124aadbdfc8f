#include "render_controller.h"

#include "image_convert.h"

#include <QImageReader>

namespace inlay::studio {

RenderController::RenderController(Document* document, QObject* parent)
    : QObject(parent), document_(document) {
  sink_ = std::make_unique<CompositeSink>([this] {
    // Render thread: only post. The queued call is discarded if this object is gone.
    QMetaObject::invokeMethod(this, &RenderController::takeFrame, Qt::QueuedConnection);
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

void RenderController::startScene() {
  const PreparedScene* prepared = document_->prepared();
  if (!prepared) return;
  SessionOptions options;
  options.targetSpp = std::max(1, prepared->doc.render.spp);
  options.seconds = prepared->doc.render.seconds.value_or(0.0);
  options.seed = prepared->doc.render.seed;
  // Samples go where the objects change the photo (the part a user watches while dragging).
  options.focusOnChanges = true;
  if (!session_) {
    session_ = std::make_unique<RenderSession>(sink_.get(), options);
  } else {
    session_->cancel();
    session_->setOptions(options);
  }
  // Before setScene: a frame of the new version must find the new context.
  sink_->setContext(CompositeSink::compositeContextOf(*prepared), requestedVersion_ + 1);
  request(session_->setScene(prepared->renderScene));
}

void RenderController::onDocumentChanged(const ChangeEvent& event) {
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
      photo_ = srgb8FromLinear(prepared->photo.linearRgb, prepared->doc.render.exposure);
      composite_ = {};
      startScene();
      Q_EMIT frameUpdated();
    }
  }
  const PreparedScene* prepared = document_->prepared();
  if (session_ && prepared && event.has(ChangeEvent::ObjectsAddedOrRemoved)) {
    request(session_->setScene(prepared->renderScene));
    return;
  }
  if (!session_ || !prepared || event.objectIndex < 0 ||
      size_t(event.objectIndex) >= prepared->renderScene.objects.size())
    return;
  if (event.has(ChangeEvent::ObjectMaterial)) {
    request(session_->setScene(prepared->renderScene));  // carries the new transform too
  } else if (event.has(ChangeEvent::ObjectPlacement)) {
    request(session_->setObjectTransform(
        size_t(event.objectIndex),
        prepared->renderScene.objects[size_t(event.objectIndex)].worldFromObject));
  }
}

void RenderController::takeFrame() {
  std::optional<CompositeImage> image = sink_->take();
  if (!image || image->sceneVersion < requestedVersion_) return;
  composite_ = std::move(*image);
  Q_EMIT frameUpdated();
}

}  // namespace inlay::studio
