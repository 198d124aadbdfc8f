#include "final_render.h"

#include "frame_sink.h"
#include "image_convert.h"

#include <QDir>
#include <QFileInfo>
#include <QThread>

#include <algorithm>
#include <cmath>
#include <mutex>

namespace inlay::studio {

// Keeps the newest frame for the GUI thread (render thread: store and post only).
class FinalRender::Sink : public FrameSink {
 public:
  explicit Sink(FinalRender* owner) : owner_(owner) {}
  void onFrame(std::shared_ptr<const RenderFrame> frame) override {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      newest_ = std::move(frame);
    }
    QMetaObject::invokeMethod(owner_, "takeFrame", Qt::QueuedConnection);
  }
  std::shared_ptr<const RenderFrame> take() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return std::exchange(newest_, nullptr);
  }

 private:
  FinalRender* owner_;
  std::mutex mutex_;
  std::shared_ptr<const RenderFrame> newest_;
};

SessionOptions FinalRender::optionsFor(const PreparedScene& scene, int maxSpp) {
  SessionOptions so;  // as `inlay-cli render` sets them
  so.targetSpp = std::max(1, scene.doc.render.spp);
  if (maxSpp > 0) so.targetSpp = std::min(so.targetSpp, maxSpp);
  so.seconds = scene.doc.render.seconds.value_or(0.0);
  so.seed = scene.doc.render.seed;
  so.startDivider = 1;  // no preview: every wave counts
  so.focusOnChanges = true;
  so.noiseTarget = scene.doc.render.noise;
  so.tracer.clampRadiance = scene.doc.render.clampIndirect;  // as the preview
  // The final frame is denoised (render/denoise.h): a capped or timed render comes out clean,
  // and the filter's strength falls with the samples, so one that reached the noise target is
  // the render's own. Pixels the objects do not change stay the photo's bits.
  so.denoise = SessionOptions::Denoise::Final;
  return so;
}

FinalRender::FinalRender(const PreparedScene& scene, const QString& path, int maxSpp, QObject* parent)
    : QObject(parent),
      path_(path),
      context_(CompositeSink::compositeContextOf(scene)),
      options_(optionsFor(scene, maxSpp)) {
  qRegisterMetaType<inlay::studio::FinalRender::Progress>();
  progress_.noiseTarget = options_.noiseTarget;
  sink_ = std::make_unique<Sink>(this);
  session_ = std::make_unique<RenderSession>(sink_.get(), options_);
  session_->setScene(shownRenderScene(scene));
}

FinalRender::~FinalRender() {
  session_.reset();  // joins the render thread
  if (saver_) {
    QObject::disconnect(saver_, nullptr, this, nullptr);
    saver_->wait();
    delete saver_;
  }
}

void FinalRender::cancel() {
  if (finished_ || cancelled_) return;
  cancelled_ = true;
  if (saver_) return;  // the file is being written: it finishes (atomically) and is reported
  session_->cancel();
  finish(false, tr("Render Final Image cancelled; nothing was written."));
}

void FinalRender::takeFrame() {
  const std::shared_ptr<const RenderFrame> frame = sink_->take();
  if (!frame || finished_ || cancelled_ || saver_) return;
  Progress& p = progress_;
  p.spp = frame->spp;
  p.meanSpp = frame->meanSpp;
  p.estimatedError = frame->estimatedError;
  p.seconds = frame->seconds;
  // The samples still needed grow with the square of the error over the target.
  double f = double(frame->spp) / double(options_.targetSpp);
  if (options_.noiseTarget > 0 && frame->estimatedError > 0)
    f = std::max(f, std::pow(options_.noiseTarget / frame->estimatedError, 2.0));
  if (options_.seconds > 0) f = std::max(f, frame->seconds / options_.seconds);
  p.fraction = frame->final ? 1.0 : std::max(p.fraction, std::clamp(f, 0.0, 0.99));
  Q_EMIT progressed(p);
  if (frame->final) startSaving(frame);
}

void FinalRender::startSaving(const std::shared_ptr<const RenderFrame>& frame) {
  struct Result {
    Status status;
    std::shared_ptr<const ImageF> image;
    QImage shown;
  };
  auto result = std::make_shared<Result>();
  const std::shared_ptr<const PreparedScene> context = context_;
  const std::string file = QDir::toNativeSeparators(path_).toStdString();
  saver_ = QThread::create([result, context, frame, file] {
    auto composite = std::make_shared<ImageF>(compositeOf(*context, *frame));
    SaveOptions save;  // 8-bit files through the photo's camera response (its codes kept)
    save.response = outputResponseOf(*context);
    result->status = saveImage(file, *composite, save);  // atomic: temporary file and rename
    if (result->status.ok())  // what the viewport shows of it: the codes of an 8-bit file
      result->shown = save.response ? encoded8FromLinear(*composite, *save.response)
                                    : srgb8FromLinear(*composite);
    result->image = std::move(composite);
  });
  connect(saver_, &QThread::finished, this, [this, result, frame] {
    saver_->deleteLater();
    saver_ = nullptr;
    if (!result->status.ok())
      return finish(false, QString::fromStdString(result->status.error().message()));
    composite_ = result->image;
    shown_ = result->shown;
    finish(true, (frame->denoised
                      ? tr("Wrote %1: %2 × %3, %4 samples per pixel at most (%5 on average), estimated "
                           "error %6 before denoising, %7 s")
                      : tr("Wrote %1: %2 × %3, %4 samples per pixel at most (%5 on average), estimated "
                           "error %6, %7 s"))
                     .arg(QDir::toNativeSeparators(path_))
                     .arg(frame->width)
                     .arg(frame->height)
                     .arg(frame->spp)
                     .arg(frame->meanSpp, 0, 'f', 1)
                     .arg(frame->estimatedError, 0, 'f', 4)
                     .arg(frame->seconds, 0, 'f', 1));
  });
  saver_->start();
}

void FinalRender::finish(bool ok, const QString& message) {
  if (finished_) return;
  finished_ = true;
  Q_EMIT finished(ok, message);
}

}  // namespace inlay::studio
