#include "prepare_worker.h"

#include <QElapsedTimer>
#include <QThread>

#include <exception>

namespace inlay::studio {

void PrepareWorker::run(quint64 jobId, const SceneDoc& doc, std::shared_ptr<CancelToken> cancel) {
  PrepareResult result;
  result.jobId = jobId;
  if (cancel->cancelled()) {
    // Superseded before it started (a drag queues one job per move): no photo loaded for it.
    result.cancelled = true;
    Q_EMIT finished(result);
    return;
  }
  QElapsedTimer clock;
  clock.start();

  QElapsedTimer sinceProgress;
  sinceProgress.start();
  std::string lastStage;
  PrepareOptions options;
  options.cancel = cancel.get();
  options.progress = [&](const std::string& stage, double fraction) {
    // The engine may report per tile; the dialog needs a few updates per second at most.
    if (QThread::currentThread()->isInterruptionRequested()) cancel->cancel();
    if (stage == lastStage && sinceProgress.elapsed() < 50 && fraction < 1.0) return;
    lastStage = stage;
    sinceProgress.restart();
    Q_EMIT progress(jobId, QString::fromStdString(stage), fraction);
  };

  try {
    Expected<PreparedScene> prepared = prepareScene(doc, options);
    if (prepared.ok()) {
      for (const std::string& w : prepared->warnings) result.warnings << QString::fromStdString(w);
      result.scene = std::make_shared<PreparedScene>(std::move(prepared.value()));
    } else if (cancel->cancelled()) {
      result.cancelled = true;
    } else {
      result.error = QString::fromStdString(prepared.error().message());
    }
  } catch (const std::exception& e) {
    result.error = QString::fromUtf8(e.what());
  } catch (...) {
    result.error = tr("Internal error while preparing the scene.");
  }
  if (cancel->cancelled() && !result.scene) result.cancelled = true;
  result.seconds = double(clock.nsecsElapsed()) * 1e-9;
  Q_EMIT finished(result);
}

}  // namespace inlay::studio
