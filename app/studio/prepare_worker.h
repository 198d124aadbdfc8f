// Runs prepareScene() off the GUI thread. A PrepareWorker is moved into the Document's QThread;
// the document submit()s a job (its data under the worker's mutex, then an argument-less queued
// call to runNext()) and, on the queued signal finished(), takes the result under the same
// mutex. The jobs and results cross threads through that std::mutex, not inside Qt's queued
// events: Debian's Qt is not built with ThreadSanitizer, which therefore cannot see the
// hand-off of data copied into a queued call and would report it as a race. Never throws
// across the thread: an exception becomes the job's error.
#pragma once

#include "inlay/engine/pipeline.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <deque>
#include <memory>
#include <mutex>

namespace inlay::studio {

struct PrepareResult {
  quint64 jobId = 0;
  std::shared_ptr<PreparedScene> scene;  // null on error or cancel
  bool cancelled = false;
  QString error;  // one line naming the file, key and reason
  QStringList warnings;
  double seconds = 0;
};

class PrepareWorker : public QObject {
  Q_OBJECT

 public:
  using QObject::QObject;
  // Worker thread (deleteLater when the thread finishes), after the GUI thread's last call.
  ~PrepareWorker() override;

  // GUI thread: queues a job; the worker runs jobs in order, one per submit().
  void submit(quint64 jobId, SceneDoc doc, std::shared_ptr<CancelToken> cancel);
  // GUI thread, on finished(): the oldest result not yet taken (one per finished()).
  PrepareResult takeResult();
  struct Progress {
    quint64 jobId = 0;
    QString stage;
    double fraction = 0;
  };
  // GUI thread, on progressed(): the latest progress report.
  Progress latestProgress() const;

 Q_SIGNALS:
  void progressed();  // a new progress report for latestProgress()
  void finished();    // a result is ready for takeResult()

 private:
  struct Job {
    quint64 id = 0;
    SceneDoc doc;
    std::shared_ptr<CancelToken> cancel;
  };
  // Worker thread (queued by submit()): runs the oldest job, stores its result, signals.
  Q_INVOKABLE void runNext();
  // Worker thread. `cancel` is polled by the engine; progress is throttled to ~20 per second.
  PrepareResult run(quint64 jobId, const SceneDoc& doc, const std::shared_ptr<CancelToken>& cancel);

  mutable std::mutex mutex_;  // guards jobs_, results_ and progress_
  Progress progress_;
  std::deque<Job> jobs_;
  std::deque<PrepareResult> results_;
};

}  // namespace inlay::studio
