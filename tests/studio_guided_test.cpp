// The guided start on a York photo (../shared/york, skipped without it), as a new user meets it:
// the Steps panel's states, the box accepted with the step's own button, one light outlined, a
// library chair dragged in, Render Final Image (and a cancelled one that leaves the earlier file
// alone), the before/after split and the export; the panel hides once all four steps are done
// and View > Steps brings it back. A binary of its own: QtTest's time limit is per binary here.
#include "document.h"
#include "library_dock.h"
#include "main_window.h"
#include "render_controller.h"
#include "steps_dock.h"
#include "viewport.h"

#include <QAction>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QtTest>

#include <memory>

#include "studio_test_support.h"
#include "studio_workflow_steps.h"
#include "studio_designer_helpers.h"

using namespace inlay;
using namespace inlay::studio;
using namespace inlay::test;

class StudioGuidedTest : public QObject {
  Q_OBJECT

 private Q_SLOTS:
  void initTestCase();
  void guidedFirstCompositeOnAYorkPhoto();
};

void StudioGuidedTest::initTestCase() {
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName(QStringLiteral("InlayTest"));
  QCoreApplication::setApplicationName(QStringLiteral("studio_guided_test"));
  QSettings().clear();
}

// The guided start on a York photo: the Steps panel's states, the box accepted with the step's
// own button, one light outlined, a library chair dragged in, Render Final Image (and a
// cancelled one), the before/after split and the export; the panel hides once all four steps
// are done and View > Steps brings it back. Screenshots and times in
// studio_guided_artifacts/ in the build tree.
void StudioGuidedTest::guidedFirstCompositeOnAYorkPhoto() {
  const QString photo = sharedFile(QStringLiteral("york/P1020833.jpg"));
  if (photo.isEmpty()) QSKIP("skipped: ../shared/york not present (needs ../shared/york/P1020833.jpg)");
  QSettings().remove(QStringLiteral("guide/done"));
  DesignerWalk walk(QStringLiteral("studio_guided_artifacts"));
  const QString opened = walk.openPhoto(photo, waitMs(180000));
  QVERIFY2(opened.isEmpty(), qPrintable(opened));
  MainWindow& window = walk.window;
  Document* doc = window.document();
  Viewport* view = window.viewport();
  // Each step's screenshot once the preview shows its result (the time is taken before).
  auto step = [&](const QString& name) { QVERIFY(walk.step(name, waitMs(60000))); };

  // --- The Steps panel: the box estimated, no lights, no objects, nothing exported ---
  StepsDock* steps = window.stepsDock();
  QVERIFY(steps->isVisible());
  QCOMPARE(steps->currentStep(), int(StepsDock::Room));
  QVERIFY(steps->button(StepsDock::Room)->isVisible() && steps->button(StepsDock::Room)->isEnabled());
  QVERIFY2(steps->stateText(StepsDock::Lights).contains(QStringLiteral("gathered light only")),
           qPrintable(steps->stateText(StepsDock::Lights)));
  QVERIFY(!steps->isDone(StepsDock::Objects) && !steps->isDone(StepsDock::Export));

  // --- Accept the box (the step's own button), then outline one light (Light tool clicks) ---
  QElapsedTimer clock;
  clock.start();
  steps->button(StepsDock::Room)->click();
  QVERIFY(doc->backWallIsUsers());
  QVERIFY(steps->isDone(StepsDock::Room));
  QCOMPARE(steps->currentStep(), int(StepsDock::Lights));
  steps->button(StepsDock::Lights)->click();  // picks the Light tool
  QCOMPARE(view->tool(), Viewport::Tool::Light);
  const QRectF lamp = brightestPatch(window.renderer()->photoImage());
  for (const QPointF& c : {lamp.topLeft(), lamp.topRight(), lamp.bottomRight(), lamp.bottomLeft()})
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier,
                      view->widgetFromImage(Vec2(c.x(), c.y())).toPoint());
  QTest::keyClick(view, Qt::Key_Return);
  QCOMPARE(int(doc->scene().lights.size()), 1);
  QVERIFY(steps->isDone(StepsDock::Lights));
  QCOMPARE(steps->currentStep(), int(StepsDock::Objects));
  window.toolAction(int(Viewport::Tool::Select))->trigger();
  QVERIFY2(inlay::test::waitReady(doc, waitMs(180000)), qPrintable(doc->prepareError()));
  walk.timings << QStringLiteral("accept_box_and_light_prepared_ms,%1").arg(clock.elapsed());
  step(QStringLiteral("box_accepted_light_outlined"));

  // --- A library chair dragged onto the floor ---
  auto* library = window.findChild<LibraryDock*>();
  QVERIFY(library);
  QListWidgetItem* chair = nullptr;
  for (int i = 0; i < library->list()->count(); ++i)
    if (library->list()->item(i)->text() == QStringLiteral("Chair")) chair = library->list()->item(i);
  if (!chair) QSKIP("the model library is not installed");
  const std::unique_ptr<QMimeData> mime(library->list()->mimeData({chair}));
  QVERIFY(mime && mime->hasUrls());
  QTRY_VERIFY_WITH_TIMEOUT(window.renderer()->hasFrame(), waitMs(60000));
  const std::optional<Vec2> floorAt = floorPixel(doc, 0.5);
  QVERIFY(floorAt);
  clock.restart();
  QVERIFY(dropUrl(view, mime->urls().first().toLocalFile(), view->widgetFromImage(*floorAt).toPoint()));
  QVERIFY(waitNoPendingModels(window, waitMs(30000)));
  QVERIFY2(window.lastModelError().isEmpty(), qPrintable(window.lastModelError()));
  QCOMPARE(doc->objectCount(), 1);
  walk.timings << QStringLiteral("library_chair_drop_ms,%1").arg(clock.elapsed());
  QVERIFY(steps->isDone(StepsDock::Objects));
  QCOMPARE(steps->currentStep(), int(StepsDock::Export));
  QTRY_VERIFY_WITH_TIMEOUT(window.renderer()->isCurrent() && window.renderer()->frameInfo().spp >= 2,
                           waitMs(60000));
  step(QStringLiteral("library_chair_dropped"));

  // --- Render Final Image: the photo's full size, written atomically; then all steps are done ---
  {
    const QString finalPath = walk.log.filePath(QStringLiteral("final.png"));
    QFile::remove(finalPath);
    QSignalSpy finished(&window, &MainWindow::finalImageFinished);
    clock.restart();
    QVERIFY(window.renderFinalImage(finalPath, 8));
    QVERIFY(window.renderer()->paused());
    QVERIFY(!window.renderFinalAction()->isEnabled());
    QVERIFY(!window.renderFinalImage(finalPath, 8));  // one at a time
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, waitMs(180000));
    walk.timings << QStringLiteral("render_final_ms,%1").arg(clock.elapsed());
    QVERIFY2(finished.first()[0].toBool(), qPrintable(finished.first()[1].toString()));
    const QImage written(finalPath);
    QCOMPARE(written.size(), QSize(doc->prepared()->camera.widthPx, doc->prepared()->camera.heightPx));
    QVERIFY(!window.renderer()->paused());
    QVERIFY(window.renderFinalAction()->isEnabled());
    QVERIFY(steps->isDone(StepsDock::Export));
    // All four done: the panel hides for good, and View > Steps brings it back.
    QVERIFY(!steps->isVisible());
    QVERIFY(QSettings().value(QStringLiteral("guide/done")).toBool());
    step(QStringLiteral("final_rendered"));
    steps->toggleViewAction()->trigger();
    QVERIFY(steps->isVisible());
    // A cancelled render leaves the earlier file as it was, and no temporary beside it.
    const QByteArray earlier = readAll(finalPath);
    QVERIFY(window.renderFinalImage(finalPath, 8));
    window.finalRender()->cancel();
    QCOMPARE(finished.count(), 2);
    QVERIFY(!finished.last()[0].toBool());
    QCOMPARE(readAll(finalPath), earlier);
    QCOMPARE(QFileInfo(finalPath).absoluteDir().entryList({QStringLiteral("*final.png*")}, QDir::Files),
             QStringList{QStringLiteral("final.png")});
    QVERIFY(!window.renderer()->paused());
  }

  // --- The before/after split: the divider follows a drag ---
  window.splitAction()->trigger();
  QVERIFY(view->splitView());
  {
    const int y = view->height() / 2;
    const int x0 = int(view->splitWidgetX());
    const double f0 = view->splitFraction();
    inlay::test::dragLeft(view, QPoint(x0, y), QPoint(x0 - 120, y));
    QVERIFY2(view->splitFraction() < f0 - 0.1, qPrintable(QString::number(view->splitFraction())));
    QTRY_VERIFY_WITH_TIMEOUT(window.renderer()->isCurrent() && window.renderer()->frameInfo().spp >= 2,
                             waitMs(60000));
    step(QStringLiteral("before_after_split"));
  }
  window.splitAction()->trigger();
  QVERIFY(!view->splitView());

  // --- Export the composite ---
  {
    const QString exported = walk.log.filePath(QStringLiteral("composite.jpg"));
    QFile::remove(exported);
    QVERIFY(window.exportComposite(exported));
    QCOMPARE(QImage(exported).size(),
             QSize(doc->prepared()->camera.widthPx, doc->prepared()->camera.heightPx));
    step(QStringLiteral("exported"));
  }

  QVERIFY(walk.report());
}

QTEST_MAIN(StudioGuidedTest)
#include "studio_guided_test.moc"
