// The workflow tests' record of a user's steps: each step's time since the start and a numbered
// screenshot of the window, written into a folder of the build tree (beside the test binary),
// with the figures in a CSV. GUI thread only.
#pragma once

#include "document.h"
#include "main_window.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QStringList>
#include <QTest>
#include <QTextStream>
#include <QWidget>

#include <functional>

namespace inlay::test {

// Shows the window at the workflow tests' size, non-interactive (no modal questions); true once
// it is exposed.
inline bool showForWorkflow(studio::MainWindow& window) {
  window.setInteractive(false);
  window.resize(1280, 800);
  window.show();
  return QTest::qWaitForWindowExposed(&window);
}

// Waits while the document prepares; true when it ended Ready.
inline bool waitReady(studio::Document* doc, int timeoutMs) {
  QElapsedTimer t;
  t.start();
  while (doc->state() == studio::Document::State::Preparing && t.elapsed() < timeoutMs) QTest::qWait(20);
  return doc->state() == studio::Document::State::Ready;
}

class StepLog {
 public:
  // folder: created under the test binary's folder (the build tree's tests/).
  // Screenshots of an earlier run (NN_step.png) are removed: the folder shows this run only.
  explicit StepLog(const QString& folder) : dir_(QCoreApplication::applicationDirPath()) {
    dir_.mkpath(folder);
    dir_.cd(folder);
    for (const QString& old : dir_.entryList({QStringLiteral("[0-9][0-9]_*.png")}, QDir::Files))
      dir_.remove(old);
    clock_.start();
  }

  QString filePath(const QString& name) const { return dir_.filePath(name); }
  // The steps' times count from here.
  void restart() { clock_.restart(); }
  // Saves the window as NN_name.png; false when it could not be written.
  bool shot(QWidget* w, const QString& name) {
    const QString path =
        dir_.filePath(QStringLiteral("%1_%2.png").arg(++shotNumber_, 2, 10, QLatin1Char('0')).arg(name));
    shots_ << path;
    return w->grab().save(path);
  }
  // Records the step's seconds since restart() and its screenshot; `settle` (when given) runs
  // in between, so that the time is the step's own and the shot shows its result.
  bool step(QWidget* w, const QString& name, const std::function<void()>& settle = {}) {
    steps_ << QStringLiteral("%1,%2").arg(name).arg(clock_.elapsed() / 1000.0, 0, 'f', 2);
    if (settle) settle();
    return shot(w, name);
  }
  const QStringList& steps() const { return steps_; }
  const QStringList& shots() const { return shots_; }
  // Writes "figure,value" rows: `figures` first, then one step_seconds_<step> row per step.
  bool writeFigures(const QString& fileName, const QStringList& figures = {}) const {
    QFile csv(dir_.filePath(fileName));
    if (!csv.open(QIODevice::WriteOnly | QIODevice::Text)) return false;
    QTextStream out(&csv);
    out << "figure,value\n";
    for (const QString& f : figures) out << f << "\n";
    for (const QString& s : steps_) out << "step_seconds_" << s << "\n";
    return true;
  }

 private:
  QDir dir_;
  QElapsedTimer clock_;
  int shotNumber_ = 0;
  QStringList steps_, shots_;
};

}  // namespace inlay::test
