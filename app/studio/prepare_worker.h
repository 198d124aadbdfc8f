// Runs prepareScene() off the GUI thread. A PrepareWorker is moved into the Document's QThread;
// the document starts a job with a queued call to run() and gets the result back by the queued
// signal finished(). Never throws across the thread: an exception becomes the job's error.
#pragma once

#include "inlay/engine/pipeline.h"

#include <QMetaType>
#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>

namespace inlay::studio {

struct PrepareResult {
  quint64 jobId = 0;
  std::shared_ptr<PreparedScene> scene;  // null on error or cancel
  bool cancelled = false;
  QString error;        // one line naming the file, key and reason
  QStringList warnings;
  double seconds = 0;
};

class PrepareWorker : public QObject {
  Q_OBJECT

 public:
  using QObject::QObject;

  // Worker thread. `cancel` is polled by the engine; progress is throttled to ~20 per second.
  void run(quint64 jobId, const SceneDoc& doc, std::shared_ptr<CancelToken> cancel);

 Q_SIGNALS:
  void progress(quint64 jobId, const QString& stage, double fraction);
  void finished(const inlay::studio::PrepareResult& result);
};

}  // namespace inlay::studio

Q_DECLARE_METATYPE(inlay::studio::PrepareResult)
