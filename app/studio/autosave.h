// Never lose work: the document is written to a recovery file beside the settings every few
// seconds while it has unsaved changes, and removed when it is saved, closed or discarded. A
// recovery file whose studio is gone (a crash, a kill, power loss) is offered at the next start.
//
// Files of one studio (each written atomically, so a kill mid-write leaves the previous pair),
// <id> = "<pid>-<n>" (n counts the studios of one process):
//   <settings folder>/<application>-recovery-<id>.json  the scene file, paths absolute
//   <settings folder>/<application>-recovery-<id>.info  JSON: {"original": the document's file or "", "saved": ISO time}
//   <settings folder>/<application>-recovery-<id>.lock  a QLockFile held while that studio lives
// Two studios never share files. A recovery is offered only when its lock is stale (the process
// that held it is dead) or gone: never the work of a studio that is still running.
//
// GUI thread only.
#pragma once

#include <QDateTime>
#include <QLockFile>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <optional>
#include <vector>

namespace inlay::studio {

class Document;

class Autosaver : public QObject {
  Q_OBJECT

 public:
  // The interval: the setting "autosaveSeconds" (default 30, at least 5), or the environment
  // variable INLAY_AUTOSAVE_MS (tests). Takes this studio's lock.
  explicit Autosaver(Document* document, QObject* parent = nullptr);
  ~Autosaver() override;  // releases the lock; unsaved work stays recoverable

  // This studio's files.
  QString scenePath() const;
  QString infoPath() const;

  // What a studio that is no longer running left behind.
  struct Recovery {
    QString scenePath;     // the recovery scene file
    QString originalPath;  // the file the work belonged to ("" for a new scene)
    QDateTime saved;
  };
  // All of them, newest first.
  static std::vector<Recovery> pendingAll();
  // The newest, if any.
  static std::optional<Recovery> pending();
  // Removes one (after restoring it, or when the user declines it).
  static void discard(const Recovery& recovery);
  // Removes every one of them.
  static void discardAll();
  // Removes this studio's own files (saved or closed).
  void discardOwn();

  // Writes the recovery files now when there are unsaved changes since the last write; removes
  // them when the document is clean. Returns false when writing failed (error() says why).
  bool saveNow();
  // The document holds changes not in any file (a restored recovery): write at the next tick.
  void markDirty() { dirty_ = true; }
  QString error() const { return error_; }
  int intervalMs() const { return timer_.interval(); }
  // A write happened (tests wait for it).
  int writes() const { return writes_; }

 Q_SIGNALS:
  void autosaved();

 private:
  QString pathWith(const char* suffix) const;

  Document* document_;
  QString id_;
  std::unique_ptr<QLockFile> lock_;
  QTimer timer_;
  bool dirty_ = false;
  int writes_ = 0;
  QString error_;
};

}  // namespace inlay::studio
