// Never lose work: the document is written to a recovery file beside the settings every few
// seconds while it has unsaved changes, and removed when it is saved, closed or discarded. A
// recovery file found at start means the studio did not close properly (a crash, a kill, power
// loss): the window offers to restore it.
//
// Files (both written atomically, so a kill mid-write leaves the previous pair):
//   <settings folder>/<application>-recovery.json  the scene file, paths absolute
//   <settings folder>/<application>-recovery.info  JSON: {"original": the document's file or "", "saved": ISO time}
// One studio per user is assumed: a second running studio shares the files.
//
// GUI thread only.
#pragma once

#include <QDateTime>
#include <QObject>
#include <QString>
#include <QTimer>

#include <optional>

namespace inlay::studio {

class Document;

class Autosaver : public QObject {
  Q_OBJECT

 public:
  // The interval: the setting "autosaveSeconds" (default 30, at least 5), or the environment
  // variable INLAY_AUTOSAVE_MS (tests).
  explicit Autosaver(Document* document, QObject* parent = nullptr);

  static QString recoveryScenePath();
  static QString recoveryInfoPath();

  // What a previous run left behind, if anything.
  struct Recovery {
    QString scenePath;     // the recovery scene file
    QString originalPath;  // the file the work belonged to ("" for a new scene)
    QDateTime saved;
  };
  static std::optional<Recovery> pending();
  static void discard();

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
  Document* document_;
  QTimer timer_;
  bool dirty_ = false;
  int writes_ = 0;
  QString error_;
};

}  // namespace inlay::studio
