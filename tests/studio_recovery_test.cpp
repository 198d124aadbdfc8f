// Never lose work: the studio runs as a child process (this executable with --studio-child,
// started with posix_spawn, offscreen, the real MainWindow), makes edits, autosaves, and is
// killed with SIGKILL while it holds its lock; then a new window finds the recovery file, offers
// it, and restores the edits.
#include "autosave.h"
#include "document.h"
#include "main_window.h"

#include "inlay/engine/pipeline.h"
#include "inlay/modeling/scene_file.h"

#include <QAbstractButton>
#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QMessageBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include <csignal>
#include <cstdio>

#include "child_process.h"

#include "studio_test_support.h"

using namespace inlay;
using inlay::test::exampleScene;
using inlay::test::waitMs;
using namespace inlay::studio;

namespace {

void sameSettingsAsTheChild() {
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName(QStringLiteral("InlayTest"));
  QCoreApplication::setApplicationName(QStringLiteral("studio_recovery_test"));
}

// The edits the child makes, so the parent knows what to expect.
const Vec2 kMove(-40, 6);
const std::vector<Vec2> kLight = {{380, 20}, {420, 22}, {420, 32}, {380, 30}};

// The child: open the scene, edit, wait for the autosave, say so, then wait to be killed.
int runChild(int argc, char** argv, const QString& scene) {
  QApplication app(argc, argv);
  sameSettingsAsTheChild();
  MainWindow window;
  window.setInteractive(false);
  window.show();
  if (!window.openPath(scene)) return 3;
  Document* doc = window.document();
  QElapsedTimer t;
  t.start();
  while (doc->state() == Document::State::Preparing && t.elapsed() < waitMs(120000)) QTest::qWait(20);
  if (!doc->isReady()) return 4;
  if (!doc->moveObject(0, doc->scene().objects[0].basePx + kMove)) return 5;
  if (!doc->addLight(kLight)) return 6;
  const int before = window.autosaver()->writes();
  while (window.autosaver()->writes() == before && t.elapsed() < waitMs(120000)) QTest::qWait(20);
  if (window.autosaver()->writes() == before) return 7;
  std::printf("AUTOSAVED %.6f %.6f\n", doc->scene().objects[0].basePx.x(),
              doc->scene().objects[0].basePx.y());
  std::fflush(stdout);
  return app.exec();  // until SIGKILL
}

}  // namespace

class StudioRecoveryTest : public QObject {
  Q_OBJECT

 private Q_SLOTS:
  void initTestCase() { sameSettingsAsTheChild(); }
  void killedStudioIsRestored();
};

void StudioRecoveryTest::killedStudioIsRestored() {
  const QString scene = exampleScene();
  if (scene.isEmpty() || !QFile::exists(scene)) QSKIP("resources/example/scene.json absent");
  Autosaver::discardAll();
  QVERIFY(!Autosaver::pending());

  // The child is a separate process (posix_spawn: fork and exec), so under ThreadSanitizer too.
  test::ChildProcess child;
  QVERIFY(child.start({"--studio-child", scene.toStdString()},
                      {"QT_QPA_PLATFORM=offscreen", "INLAY_AUTOSAVE_MS=200"}, true));
  const QByteArray said =
      QByteArray::fromStdString(child.readLine(std::chrono::milliseconds(waitMs(180000))));
  QVERIFY2(said.startsWith("AUTOSAVED"),
           qPrintable(
               QStringLiteral("child said '%1', %2")
                   .arg(QString::fromUtf8(said), QString::fromStdString(test::ChildProcess::describe(
                                                     child.waitFor(std::chrono::milliseconds(2000)))))));
  const QList<QByteArray> words = said.trimmed().split(' ');
  const Vec2 movedTo(words[1].toDouble(), words[2].toDouble());

  // --- Kill it hard: no close event, no cleanup, its lock still held ---
  QVERIFY(child.kill(SIGKILL));
  const std::optional<int> status = child.waitFor(std::chrono::milliseconds(waitMs(10000)));
  QVERIFY(status.has_value());
  QVERIFY(WIFSIGNALED(*status) && WTERMSIG(*status) == SIGKILL);

  // --- A new studio finds the work and offers it ---
  const std::optional<Autosaver::Recovery> pending = Autosaver::pending();
  QVERIFY(pending.has_value());
  QCOMPARE(QFileInfo(pending->originalPath).canonicalFilePath(), QFileInfo(scene).canonicalFilePath());
  MainWindow window;  // interactive: asks
  window.show();
  QVERIFY(window.offerRecovery());
  QMessageBox* box = nullptr;
  QTRY_VERIFY_WITH_TIMEOUT(
      (box = window.findChild<QMessageBox*>(QStringLiteral("recoveryQuestion"))) != nullptr &&
          box->isVisible(),
      waitMs(5000));
  QAbstractButton* restore = nullptr;
  for (QAbstractButton* b : box->buttons())
    if (box->buttonRole(b) == QMessageBox::AcceptRole) restore = b;
  QVERIFY(restore);
  restore->click();

  Document* doc = window.document();
  QCOMPARE(QFileInfo(doc->filePath()).canonicalFilePath(), QFileInfo(scene).canonicalFilePath());
  QVERIFY(!doc->undoStack()->isClean());  // the restored work is in no file yet
  QVERIFY(window.isWindowModified());
  QCOMPARE(doc->objectCount(), 1);
  QVERIFY((doc->scene().objects[0].basePx - movedTo).norm() < 1e-4);
  QCOMPARE(int(doc->scene().lights.size()), 3);  // the example's two and the child's
  QVERIFY(doc->scene().lights[2].pointsPx == kLight);
  QTRY_VERIFY_WITH_TIMEOUT(doc->state() != Document::State::Preparing, waitMs(120000));
  QVERIFY2(doc->isReady(), qPrintable(doc->prepareError()));

  // --- Saving puts the work in a file: the recovery file goes ---
  QTemporaryDir dir;
  window.setInteractive(false);
  QVERIFY(window.saveTo(dir.filePath(QStringLiteral("restored.json"))));
  QVERIFY(!Autosaver::pending());
}

int main(int argc, char** argv) {
  if (argc >= 3 && qstrcmp(argv[1], "--studio-child") == 0)
    return runChild(argc, argv, QString::fromLocal8Bit(argv[2]));
  QApplication app(argc, argv);
  StudioRecoveryTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "studio_recovery_test.moc"
