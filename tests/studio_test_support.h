// Helpers shared by the studio QtTests.
#pragma once

#include "main_window.h"

#include "inlay/engine/pipeline.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QString>
#include <QtTest>

#include <memory>

namespace inlay::test {

// Sanitizer builds run several times slower (TSan 5-15x, ASan about 2-3x), so every wait a
// studio test makes for a worker, a frame or a child process is scaled by the factor that
// cmake/Sanitizers.cmake chooses (1 in an ordinary build). Only the deadline grows: each test
// still waits for the same condition.
constexpr int kWaitScale = INLAY_TEST_WAIT_SCALE;

constexpr int waitMs(int ms) { return ms * kWaitScale; }

// The bundled example's scene: the source tree's copy, else the one the studio finds itself.
inline QString exampleScene() {
  const QString src = qEnvironmentVariable("INLAY_SOURCE_DIR");
  if (!src.isEmpty() && QFile::exists(src + QStringLiteral("/resources/example/scene.json")))
    return src + QStringLiteral("/resources/example/scene.json");
  return QString::fromStdString(exampleScenePath());
}

// The bundled example's photo, beside its scene (empty when the example is not found): opened
// as a photo, the studio estimates the camera and the box itself.
inline QString examplePhoto() {
  const QString scene = exampleScene();
  return scene.isEmpty() ? QString()
                         : QFileInfo(scene).absoluteDir().filePath(QStringLiteral("photo.png"));
}

// A drag with the left button along a straight line, in `steps` moves.
inline void dragLeft(QWidget* w, QPoint from, QPoint to, int steps = 10) {
  QTest::mousePress(w, Qt::LeftButton, Qt::NoModifier, from);
  for (int k = 1; k <= steps; ++k) QTest::mouseMove(w, from + (to - from) * k / steps);
  QTest::mouseRelease(w, Qt::LeftButton, Qt::NoModifier, to);
}

// A studio window as the tests use it (offscreen, no dialogs, a fixed size), shown and opening
// `path`; nullptr when it could not be exposed or refused the file.
inline std::unique_ptr<studio::MainWindow> openStudio(const QString& path) {
  auto w = std::make_unique<studio::MainWindow>();
  w->setInteractive(false);
  w->resize(1100, 750);
  w->show();
  if (!QTest::qWaitForWindowExposed(w.get()) || !w->openPath(path)) return nullptr;
  return w;
}

}  // namespace inlay::test
