// What the studio benchmarks (bench_studio, bench_big_photo) share: the application's set-up, the
// --out option, the window as they show it, the bundled example photo, the viewport's paint
// times and the wait for a composite of a given scene version. GUI thread only.
#pragma once

#include "main_window.h"
#include "render_controller.h"
#include "viewport.h"

#include "inlay/engine/pipeline.h"

#include <QCommandLineOption>
#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QStandardPaths>
#include <QTest>

#include <algorithm>
#include <vector>

namespace inlay::bench {

inline double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Settings in test mode under the organisation InlayBench: a benchmark never touches a user's.
inline void setUpBenchApplication(const char* name) {
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName(QStringLiteral("InlayBench"));
  QCoreApplication::setApplicationName(QString::fromLatin1(name));
}

// --out DIR, the output folder (default tests/bench/out).
inline QCommandLineOption outFolderOption() {
  return QCommandLineOption(QStringLiteral("out"), QStringLiteral("Output folder."),
                            QStringLiteral("dir"), QStringLiteral("tests/bench/out"));
}

// The bundled example's photo (beside exampleScenePath()); empty when the example is not found.
inline QString examplePhotoPath() {
  const std::string scene = exampleScenePath();
  if (scene.empty()) return {};
  return QFileInfo(QString::fromStdString(scene)).absoluteDir().filePath(QStringLiteral("photo.png"));
}

// The window at the benchmarks' size, non-interactive (no modal questions), shown.
inline void showBenchWindow(studio::MainWindow& w) {
  w.setInteractive(false);
  w.resize(1280, 800);
  w.show();
}

// Paint times (ms) of `count` synchronous repaints of the viewport, 5 ms apart.
inline std::vector<double> paintTimes(studio::MainWindow& w, int count) {
  studio::Viewport* view = w.viewport();
  view->clearPaintTimes();
  for (int k = 0; k < count; ++k) {
    view->repaint();
    QTest::qWait(5);
  }
  return view->paintTimesMs();
}

// Waits (processing events, polling every millisecond) until the renderer's current composite is
// of scene version `wanted` or later; false after `timeoutMs`.
inline bool waitForFrameOf(const studio::RenderController& r, quint64 wanted, int timeoutMs) {
  QElapsedTimer t;
  t.start();
  while (!(r.isCurrent() && r.frameInfo().sceneVersion >= wanted)) {
    if (t.elapsed() > timeoutMs) return false;
    QTest::qWait(1);
  }
  return true;
}

}  // namespace inlay::bench
