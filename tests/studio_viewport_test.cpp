// The studio end to end, offscreen: open the bundled example, drag the object's marker with the
// mouse, and check the document, the undo stack (one step per drag), the rendered viewport, the
// saved file and the German translation.
#include "docks.h"
#include "document.h"
#include "i18n.h"
#include "main_window.h"
#include "render_controller.h"
#include "viewport.h"

#include "inlay/engine/pipeline.h"
#include "inlay/modeling/image_io.h"
#include "inlay/modeling/scene_file.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QMenu>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include "studio_test_support.h"

using namespace inlay;
using inlay::test::waitMs;
using namespace inlay::studio;

namespace {

QString exampleScene() {
  QString fromSource = qEnvironmentVariable("INLAY_SOURCE_DIR") +
                       QStringLiteral("/resources/example/scene.json");
  if (!qEnvironmentVariable("INLAY_SOURCE_DIR").isEmpty() && QFile::exists(fromSource))
    return fromSource;
  return QString::fromStdString(exampleScenePath());
}

// Number of pixels whose colour differs by more than `tolerance` in any channel.
int differingPixels(const QImage& a, const QImage& b, int tolerance = 8) {
  if (a.size() != b.size()) return a.width() * a.height();
  const QImage x = a.convertToFormat(QImage::Format_RGB32);
  const QImage y = b.convertToFormat(QImage::Format_RGB32);
  int n = 0;
  for (int r = 0; r < x.height(); ++r) {
    const auto* p = reinterpret_cast<const QRgb*>(x.constScanLine(r));
    const auto* q = reinterpret_cast<const QRgb*>(y.constScanLine(r));
    for (int c = 0; c < x.width(); ++c)
      if (std::abs(qRed(p[c]) - qRed(q[c])) > tolerance ||
          std::abs(qGreen(p[c]) - qGreen(q[c])) > tolerance ||
          std::abs(qBlue(p[c]) - qBlue(q[c])) > tolerance)
        ++n;
  }
  return n;
}

}  // namespace

class StudioViewportTest : public QObject {
  Q_OBJECT

 private Q_SLOTS:
  void initTestCase();
  void dragMovesObjectAsOneUndoStep();
  void germanTranslation();
  void badPhotoReportsErrorWithoutCrash();
  void embeddedExampleOpens();
  void progressDialogCancels();
};

void StudioViewportTest::initTestCase() {
  QStandardPaths::setTestModeEnabled(true);  // QSettings go to a test location
  QCoreApplication::setOrganizationName(QStringLiteral("InlayTest"));
  QCoreApplication::setApplicationName(QStringLiteral("studio_viewport_test"));
  qunsetenv("INLAY_LANG");
  removeTranslators();
}

void StudioViewportTest::dragMovesObjectAsOneUndoStep() {
  const QString example = exampleScene();
  if (example.isEmpty() || !QFile::exists(example)) QSKIP("resources/example/scene.json absent");

  MainWindow window;
  window.setInteractive(false);
  window.resize(1100, 750);
  window.show();
  QVERIFY(QTest::qWaitForWindowExposed(&window));
  Document* doc = window.document();
  RenderController* renderer = window.renderer();
  Viewport* view = window.viewport();

  QVERIFY(window.openPath(example));
  QTRY_VERIFY_WITH_TIMEOUT(doc->state() != Document::State::Preparing, waitMs(60000));
  QVERIFY2(doc->state() == Document::State::Ready, qPrintable(doc->prepareError()));
  QVERIFY(doc->objectCount() >= 1);
  QTRY_VERIFY_WITH_TIMEOUT(renderer->isCurrent() && renderer->frameInfo().spp >= 2, waitMs(30000));
  const QImage before = view->grab().toImage();

  // --- Drag the marker of object 0 by (-60, -12) image pixels (staying on the floor) ---
  const Vec2 base0 = doc->scene().objects[0].basePx;
  const Vec2 target = base0 + Vec2(-60, -12);
  const QPoint from = view->widgetFromImage(base0).toPoint();
  const QPoint to = view->widgetFromImage(target).toPoint();
  QCOMPARE(view->objectAt(from), 0);
  QCOMPARE(doc->undoStack()->count(), 0);
  inlay::test::dragLeft(view, from, to);

  const Vec2 moved = doc->scene().objects[0].basePx;
  QVERIFY2((moved - base0).norm() > 50, "the drag did not move the object");
  // The grab offset keeps the marker under the cursor: it ends within a pixel of the target.
  QVERIFY2((moved - target).norm() < 1.0,
           qPrintable(QStringLiteral("ended at %1, %2").arg(moved.x()).arg(moved.y())));
  QCOMPARE(doc->undoStack()->count(), 1);  // ten moves, one undo step
  QVERIFY(!doc->undoStack()->isClean());
  QVERIFY(window.isWindowModified());
  // The prepared scene follows: the placement's base is where the new pixel's ray meets the floor.
  const Placement& placed = doc->prepared()->placements[0];
  QVERIFY(std::abs(placed.baseWorld.y()) < 1e-6);
  const std::optional<Vec2> reprojected = doc->prepared()->camera.project(placed.baseWorld);
  QVERIFY(reprojected && (*reprojected - moved).norm() < 1e-3);

  // --- The composite is re-rendered for the new position and differs ---
  QTRY_VERIFY_WITH_TIMEOUT(renderer->isCurrent() && renderer->frameInfo().spp >= 2, waitMs(30000));
  const QImage after = view->grab().toImage();
  QCOMPARE(after.size(), before.size());
  const int changed = differingPixels(before, after);
  QVERIFY2(changed > 1000, qPrintable(QStringLiteral("only %1 pixels changed").arg(changed)));

  // --- Undo restores exactly, redo re-applies ---
  doc->undoStack()->undo();
  QVERIFY(doc->scene().objects[0].basePx == base0);
  QVERIFY(doc->prepared()->doc.objects[0].basePx == base0);
  QVERIFY(doc->undoStack()->isClean());
  doc->undoStack()->redo();
  QVERIFY(doc->scene().objects[0].basePx == moved);

  // --- A drag that ends where it started leaves no undo step ---
  const QPoint movedAt = view->widgetFromImage(moved).toPoint();
  QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, movedAt);
  QTest::mouseMove(view, movedAt + QPoint(40, 5));
  QTest::mouseMove(view, movedAt + QPoint(20, -5));
  QTest::mouseMove(view, movedAt);
  QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, movedAt);
  QCOMPARE(doc->undoStack()->count(), 1);
  QVERIFY((doc->scene().objects[0].basePx - moved).norm() < 1.0);
  const Vec2 settled = doc->scene().objects[0].basePx;

  // --- A pixel on no supporting surface (the ceiling) keeps the last valid position ---
  const Vec2 ceiling(256.0, 8.0);
  inlay::test::dragLeft(view, view->widgetFromImage(settled).toPoint(),
                        view->widgetFromImage(ceiling).toPoint(), 1);
  QVERIFY(doc->scene().objects[0].basePx == settled);
  QCOMPARE(doc->undoStack()->count(), 1);
  QVERIFY2(!window.statusBar()->currentMessage().isEmpty(), "no reason shown");

  // --- Arrow keys nudge the selected object, one undo step per press ---
  view->setFocus();
  QTest::keyClick(view, Qt::Key_Left, Qt::ShiftModifier);
  QVERIFY(doc->scene().objects[0].basePx == settled + Vec2(-10, 0));
  QCOMPARE(doc->undoStack()->count(), 2);
  doc->undoStack()->undo();
  QVERIFY(doc->scene().objects[0].basePx == settled);

  // --- Edits from the properties dock are undoable commands too ---
  PropertiesDock* props = window.propertiesDock();
  QCOMPARE(doc->selectedObject(), 0);
  const double height0 = doc->scene().objects[0].heightM;
  props->heightBox()->setValue(height0 + 0.25);
  QCOMPARE(doc->scene().objects[0].heightM, height0 + 0.25);
  QCOMPARE(doc->undoStack()->count(), 2);
  const int glossy = props->presetBox()->findData(QStringLiteral("glossy"));
  QVERIFY(glossy >= 0);
  props->presetBox()->setCurrentIndex(glossy);
  Q_EMIT props->presetBox()->activated(glossy);  // as a user's choice does
  QCOMPARE(QString::fromStdString(doc->scene().objects[0].material.preset), QStringLiteral("glossy"));
  QCOMPARE(doc->undoStack()->count(), 3);
  QVERIFY(doc->prepared()->renderScene.objects[0].material.kind == Material::Kind::Glossy);
  // A material change re-sends the scene; the renderer catches up with it.
  QTRY_VERIFY_WITH_TIMEOUT(renderer->isCurrent() && renderer->frameInfo().spp >= 1, waitMs(30000));
  doc->undoStack()->undo();
  doc->undoStack()->undo();
  QCOMPARE(doc->scene().objects[0].heightM, height0);
  QCOMPARE(QString::fromStdString(doc->scene().objects[0].material.preset), QStringLiteral("diffuse"));
  QCOMPARE(props->heightBox()->value(), height0);  // the dock follows the document

  // --- Export the composite (8-bit PNG and linear EXR) ---
  QTemporaryDir dir;
  QVERIFY(dir.isValid());
  QTRY_VERIFY_WITH_TIMEOUT(renderer->isCurrent() && renderer->frameInfo().spp >= 1, waitMs(30000));
  for (const char* name : {"composite.png", "composite.exr"}) {
    const QString out = dir.filePath(QString::fromLatin1(name));
    QVERIFY(window.exportComposite(out));
    const Expected<LoadedImage> back = loadImage(out.toStdString());
    QVERIFY2(back.ok(), back.ok() ? "" : back.error().message().c_str());
    QCOMPARE(back->linearRgb.width, doc->prepared()->photo.linearRgb.width);
    QCOMPARE(back->linearRgb.height, doc->prepared()->photo.linearRgb.height);
  }

  // --- Save, and read back what was saved ---
  const QString path = dir.filePath(QStringLiteral("moved.json"));
  QVERIFY(window.saveTo(path));
  QVERIFY(doc->undoStack()->isClean());
  QVERIFY(!window.isWindowModified());
  QCOMPARE(doc->filePath(), path);
  const Expected<SceneLoadResult> reloaded = loadSceneFile(path.toStdString());
  QVERIFY2(reloaded.ok(), reloaded.ok() ? "" : reloaded.error().message().c_str());
  QCOMPARE(QString::fromStdString(sceneToJson(reloaded->doc)),
           QString::fromStdString(sceneToJson(doc->scene())));
  QVERIFY(reloaded->doc.objects[0].basePx == settled);
  QCOMPARE(QFileInfo(QString::fromStdString(reloaded->doc.photoResolved)).canonicalFilePath(),
           QFileInfo(QString::fromStdString(doc->scene().photoResolved)).canonicalFilePath());
}

void StudioViewportTest::germanTranslation() {
  qputenv("INLAY_LANG", "de");
  QCOMPARE(chosenLanguage(), QStringLiteral("de"));
  QVERIFY2(installTranslators(), "no German catalogue at :/i18n/inlay_de.qm");
  {
    MainWindow window;
    QCOMPARE(window.fileMenu()->title().remove(QLatin1Char('&')), QStringLiteral("Datei"));
    QCOMPARE(window.propertiesDock()->windowTitle(), QStringLiteral("Eigenschaften"));
  }
  removeTranslators();
  qunsetenv("INLAY_LANG");
  MainWindow english;
  QCOMPARE(english.fileMenu()->title().remove(QLatin1Char('&')), QStringLiteral("File"));
}

void StudioViewportTest::badPhotoReportsErrorWithoutCrash() {
  QTemporaryDir dir;
  const QString bogus = dir.filePath(QStringLiteral("not-a-photo.jpg"));
  {
    QFile f(bogus);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("this is text, not a JPEG");
  }
  MainWindow window;
  window.show();
  QVERIFY(QTest::qWaitForWindowExposed(&window));
  QVERIFY(window.openPath(bogus));
  QTRY_VERIFY_WITH_TIMEOUT(window.document()->state() != Document::State::Preparing, waitMs(30000));
  QCOMPARE(window.document()->state(), Document::State::Failed);
  QVERIFY(!window.document()->prepareError().isEmpty());
  // The error is shown in a dialog that does not block.
  QMessageBox* box = nullptr;
  QTRY_VERIFY_WITH_TIMEOUT((box = window.findChild<QMessageBox*>()) != nullptr && box->isVisible(),
                           waitMs(5000));
  QVERIFY(box->text().contains(QStringLiteral("not-a-photo.jpg")));
  box->close();
  // Edits are refused with a reason instead of crashing.
  QString reason;
  QVERIFY(!window.document()->moveObject(0, Vec2(10, 10), 0, &reason));
  QVERIFY(!reason.isEmpty());
}

void StudioViewportTest::embeddedExampleOpens() {
  if (!QFile::exists(QStringLiteral(":/example/scene.json")))
    QSKIP("the example was not embedded (resources/example absent at configure time)");
  QVERIFY(QFile::exists(QStringLiteral(":/icons/inlay.svg")));
  MainWindow window;
  window.setInteractive(false);
  QVERIFY(window.openEmbeddedExample());
  const QString path = window.document()->filePath();
  QVERIFY(!path.startsWith(QLatin1String(":")));
  QVERIFY(QFile::exists(path));
  QTRY_VERIFY_WITH_TIMEOUT(window.document()->state() != Document::State::Preparing, waitMs(60000));
  QVERIFY2(window.document()->isReady(), qPrintable(window.document()->prepareError()));
  QCOMPARE(window.document()->objectCount(), 1);
}

void StudioViewportTest::progressDialogCancels() {
  const QString example = exampleScene();
  if (example.isEmpty() || !QFile::exists(example)) QSKIP("resources/example/scene.json absent");
  MainWindow window;
  window.show();
  QVERIFY(window.openPath(example));
  // The result comes back by queued signal: until the event loop runs, it is still preparing.
  QCOMPARE(window.document()->state(), Document::State::Preparing);
  auto* dialog = window.findChild<QProgressDialog*>();
  QVERIFY(dialog);
  auto* cancelButton = dialog->findChild<QPushButton*>();
  QVERIFY(cancelButton);
  cancelButton->click();  // as the user does
  QCOMPARE(window.document()->state(), Document::State::Empty);
  QTRY_VERIFY_WITH_TIMEOUT(window.findChild<QProgressDialog*>() == nullptr, waitMs(5000));
  QTest::qWait(waitMs(500));
  QCOMPARE(window.document()->state(), Document::State::Empty);  // the late result is dropped
  QVERIFY(!window.renderer()->hasFrame());
}

QTEST_MAIN(StudioViewportTest)
#include "studio_viewport_test.moc"
