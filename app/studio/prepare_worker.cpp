#include "prepare_worker.h"

#include <QElapsedTimer>
#include <QThread>

#include <exception>

namespace inlay::studio {

void PrepareWorker::submit(quint64 jobId, SceneDoc doc, std::shared_ptr<CancelToken> cancel) {
  std::lock_guard lock(mutex_);
  jobs_.push_back({jobId, std::move(doc), std::move(cancel)});
  // By name: the queued call then carries no data our (instrumented) code touches. Under the
  // lock, so the GUI thread's last touch of this object precedes the destructor's lock.
  QMetaObject::invokeMethod(this, "runNext", Qt::QueuedConnection);
}

PrepareWorker::~PrepareWorker() {
  // The lock is the hand-off from the GUI thread's last takeResult() that TSan can see (Qt's,
  // through quit() and QThread::finished, is not instrumented).
  std::lock_guard lock(mutex_);
  jobs_.clear();
  results_.clear();
}

PrepareResult PrepareWorker::takeResult() {
  std::lock_guard lock(mutex_);
  INLAY_CHECK(!results_.empty());
  PrepareResult result = std::move(results_.front());
  results_.pop_front();
  return result;
}

PrepareWorker::Progress PrepareWorker::latestProgress() const {
  std::lock_guard lock(mutex_);
  return progress_;
}

void PrepareWorker::runNext() {
  Job job;
  {
    std::lock_guard lock(mutex_);
    INLAY_CHECK(!jobs_.empty());
    job = std::move(jobs_.front());
    jobs_.pop_front();
  }
  PrepareResult result = run(job.id, job.doc, job.cancel);
  {
    std::lock_guard lock(mutex_);
    results_.push_back(std::move(result));
  }
  Q_EMIT finished();
}

PrepareResult PrepareWorker::run(quint64 jobId, const SceneDoc& doc,
                                 const std::shared_ptr<CancelToken>& cancel) {
  PrepareResult result;
  result.jobId = jobId;
  if (cancel->cancelled()) {
    // Superseded before it started (a drag queues one job per move): no photo loaded for it.
    result.cancelled = true;
    return result;
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
    {
      std::lock_guard lock(mutex_);
      progress_ = {jobId, QString::fromStdString(stage), fraction};
    }
    Q_EMIT progressed();
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
  return result;
}

}  // namespace inlay::studio
