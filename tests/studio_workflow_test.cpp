// A new user's whole workflow in the studio, offscreen, through the mouse wherever a user would
// use it: open the bundled example photo (the estimated box is shown first), accept the box, drag
// a corner (loupe shown), outline a light, insert an object, drag it across the floor, outline a
// table top with its height click and drag the object onto it, undo back to the start and redo,
// save, reopen and compare, switch to French. A screenshot of the window is saved at each step
// into the build tree (studio_workflow_artifacts/), with the figures measured on the way
// (viewport paint time while rendering, first updated frame after an edit) in figures.csv.
#include "docks.h"
#include "document.h"
#include "i18n.h"
#include "main_window.h"
#include "render_controller.h"
#include "viewport.h"

#include "inlay/engine/pipeline.h"
#include "inlay/modeling/scene_file.h"

#include <QAction>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QLabel>
#include <QLibraryInfo>
#include <QListWidget>
#include <QMenu>
#include <QStandardPaths>
#include <QSettings>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTextStream>
#include <QUndoStack>
#include <QtTest>

#include <algorithm>
#include <memory>

#include "studio_test_support.h"
#include "studio_workflow_steps.h"

using namespace inlay;
using inlay::test::StepLog;
using inlay::test::waitMs;
using namespace inlay::studio;

namespace {

QString examplePhoto() {
  const QString src = qEnvironmentVariable("INLAY_SOURCE_DIR");
  if (!src.isEmpty() && QFile::exists(src + QStringLiteral("/resources/example/photo.png")))
    return src + QStringLiteral("/resources/example/photo.png");
  const std::string scene = exampleScenePath();
  if (scene.empty()) return {};
  return QFileInfo(QString::fromStdString(scene)).absoluteDir().filePath(QStringLiteral("photo.png"));
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

class StudioWorkflowTest : public QObject {
  Q_OBJECT

 private Q_SLOTS:
  void initTestCase();
  void newUserWorkflow();
  void frenchFromTheLanguageMenu();

 private:
  static bool waitReady(Document* doc) { return inlay::test::waitReady(doc, waitMs(180000)); }
  std::unique_ptr<StepLog> log_;  // the screenshots and figures of both test functions
};

void StudioWorkflowTest::initTestCase() {
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName(QStringLiteral("InlayTest"));
  QCoreApplication::setApplicationName(QStringLiteral("studio_workflow_test"));
  qunsetenv("INLAY_LANG");
  QSettings().remove(QStringLiteral("language"));
  removeTranslators();
  log_ = std::make_unique<StepLog>(QStringLiteral("studio_workflow_artifacts"));
}

void StudioWorkflowTest::newUserWorkflow() {
  const QString photo = examplePhoto();
  if (photo.isEmpty() || !QFile::exists(photo)) QSKIP("resources/example/photo.png absent");

  MainWindow window;
  QVERIFY(inlay::test::showForWorkflow(window));
  Document* doc = window.document();
  Viewport* view = window.viewport();
  RenderController* renderer = window.renderer();
  QUndoStack* undo = doc->undoStack();
  log_->restart();
  auto step = [&](const QString& name) { QVERIFY(log_->step(&window, name)); };

  // --- 1. Open the photo: the automatic estimate is shown first ---
  QVERIFY(window.openPath(photo));
  QVERIFY2(waitReady(doc), qPrintable(doc->prepareError()));
  const std::string startJson = sceneToJson(doc->scene());
  QVERIFY(!doc->backWallIsUsers());
  QVERIFY(doc->shownBackWallPx().has_value());
  QVERIFY(doc->lastEstimate() && !doc->lastEstimate()->segments.empty());
  QVERIFY(view->showsVanishingLines());
  QTRY_VERIFY_WITH_TIMEOUT(renderer->hasFrame(), waitMs(30000));
  step(QStringLiteral("estimate_shown"));

  // --- 2. Accept the estimated box: it becomes the user's, unchanged ---
  const std::array<Vec2, 4> estimated = *doc->shownBackWallPx();
  QVERIFY(window.acceptBoxAction()->isEnabled());
  window.acceptBoxAction()->trigger();
  QCOMPARE(undo->count(), 1);
  QVERIFY(doc->backWallIsUsers());
  QVERIFY(*doc->scene().layout.backWallPx == estimated);
  QCOMPARE(doc->state(), Document::State::Preparing);  // re-prepared with the user's box
  QVERIFY2(waitReady(doc), qPrintable(doc->prepareError()));
  step(QStringLiteral("box_accepted"));

  // --- 3. Drag the bottom-left corner: one undo step, the loupe shows while dragging ---
  const Vec2& corner = estimated[3];
  const QPoint from = view->widgetFromImage(corner).toPoint();
  const Vec2 targetPx = corner + Vec2(6, -5);
  const QPoint to = view->widgetFromImage(targetPx).toPoint();
  QCOMPARE(view->cornerAt(from), 3);
  QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, from);
  for (int k = 1; k <= 6; ++k) QTest::mouseMove(view, from + (to - from) * k / 6);
  QVERIFY(view->loupeShown());
  step(QStringLiteral("corner_drag_loupe"));
  QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, to);
  QVERIFY(!view->loupeShown());
  QCOMPARE(undo->count(), 2);
  const Vec2 placedCorner = (*doc->scene().layout.backWallPx)[3];
  // Two roundings to whole widget pixels (the press, which sets the grab offset, and the release)
  // each move the corner by up to half a widget pixel per axis: at most 1.42 widget pixels.
  QVERIFY2((placedCorner - targetPx).norm() < 1.42 / view->zoom() + 1e-6,
           qPrintable(QStringLiteral("corner at %1, %2").arg(placedCorner.x()).arg(placedCorner.y())));
  for (int i = 0; i < 3; ++i)
    QVERIFY((*doc->scene().layout.backWallPx)[size_t(i)] == estimated[size_t(i)]);
  QVERIFY2(waitReady(doc), qPrintable(doc->prepareError()));
  // The user's fix is kept exactly; the camera was re-estimated around it.
  for (int i = 0; i < 4; ++i)
    QVERIFY(doc->prepared()->backWallPx[size_t(i)] == (*doc->scene().layout.backWallPx)[size_t(i)]);
  step(QStringLiteral("corner_moved"));

  // --- 4. Outline the left ceiling light with the Light tool (clicks, closed on the first) ---
  window.toolAction(int(Viewport::Tool::Light))->trigger();
  QCOMPARE(view->tool(), Viewport::Tool::Light);
  const Vec2 outline[4] = {{89.3, 37.0}, {149.7, 39.7}, {153.3, 53.1}, {100.2, 51.0}};
  for (const Vec2& q : outline)
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, view->widgetFromImage(q).toPoint());
  QCOMPARE(int(view->pendingPoints().size()), 4);
  QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, view->widgetFromImage(outline[0]).toPoint());
  QVERIFY(view->pendingPoints().empty());
  QCOMPARE(int(doc->scene().lights.size()), 1);
  QCOMPARE(undo->count(), 3);
  QVERIFY2(waitReady(doc), qPrintable(doc->prepareError()));
  QCOMPARE(int(doc->prepared()->lighting.lights.size()), 1);
  window.toolAction(int(Viewport::Tool::Select))->trigger();
  step(QStringLiteral("light_outlined"));

  // --- 5. Insert an object: it stands on the floor ---
  QVERIFY(window.insertBuiltin(QStringLiteral("builtin:sphere")));
  QCOMPARE(doc->objectCount(), 1);
  QCOMPARE(undo->count(), 4);
  QTRY_VERIFY_WITH_TIMEOUT(renderer->isCurrent() && renderer->frameInfo().spp >= 1, waitMs(60000));
  step(QStringLiteral("object_inserted"));

  // --- 6. Drag it across the floor (one undo step), measuring the first frame after each move ---
  const Vec2 base0 = doc->scene().objects[0].basePx;
  const Vec2 floorTarget = base0 + Vec2(-70, 12);
  QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, view->widgetFromImage(base0).toPoint());
  std::vector<double> firstFrameMs;
  for (int k = 1; k <= 8; ++k) {
    const Vec2 at = base0 + (floorTarget - base0) * (k / 8.0);
    QElapsedTimer sinceEdit;
    sinceEdit.start();
    QTest::mouseMove(view, view->widgetFromImage(at).toPoint());
    const quint64 wanted = renderer->requestedVersion();
    while (!(renderer->isCurrent() && renderer->frameInfo().sceneVersion >= wanted) &&
           sinceEdit.elapsed() < waitMs(10000))
      QTest::qWait(1);
    firstFrameMs.push_back(double(sinceEdit.nsecsElapsed()) * 1e-6);
  }
  QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier,
                      view->widgetFromImage(floorTarget).toPoint());
  QCOMPARE(undo->count(), 5);
  QVERIFY((doc->scene().objects[0].basePx - floorTarget).norm() < 1.0);
  QVERIFY(std::abs(doc->prepared()->placements[0].baseWorld.y()) < 1e-6);  // on the floor
  QTRY_VERIFY_WITH_TIMEOUT(renderer->isCurrent() && renderer->frameInfo().spp >= 2, waitMs(60000));
  step(QStringLiteral("object_on_floor"));

  // --- Viewport paint time while the renderer works (after an edit, so it renders) ---
  doc->moveObject(0, floorTarget + Vec2(2, 0));
  doc->undoStack()->undo();
  view->clearPaintTimes();
  for (int k = 0; k < 40; ++k) {
    view->repaint();
    QTest::qWait(10);
  }
  const std::vector<double> paintMs = view->paintTimesMs();

  // --- 7. Outline a table top (0.5 m high) with the Surface tool, then its height click ---
  const Camera cam = doc->prepared()->camera;
  const Vec3 onFloor = doc->prepared()->placements[0].baseWorld;
  const Vec3 centre = onFloor + Vec3(0.9, 0, -0.4);
  const double topM = 0.5;
  const Vec3 corners3[4] = {centre + Vec3(-0.35, topM, 0.3), centre + Vec3(0.35, topM, 0.3),
                            centre + Vec3(0.35, topM, -0.3), centre + Vec3(-0.35, topM, -0.3)};
  std::vector<Vec2> tableOutline;
  for (const Vec3& c : corners3) tableOutline.push_back(*cam.project(c));
  const Vec2 heightClick = *cam.project(Vec3(corners3[0].x(), 0, corners3[0].z()));
  window.toolAction(int(Viewport::Tool::Surface))->trigger();
  for (const Vec2& q : tableOutline)
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, view->widgetFromImage(q).toPoint());
  QTest::keyClick(view, Qt::Key_Return);  // closes the outline; the height click comes next
  QCOMPARE(int(doc->scene().surfaces.size()), 0);
  QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, view->widgetFromImage(heightClick).toPoint());
  QCOMPARE(int(doc->scene().surfaces.size()), 1);
  QCOMPARE(undo->count(), 6);
  QVERIFY2(waitReady(doc), qPrintable(doc->prepareError()));
  QCOMPARE(int(doc->prepared()->extrusions.size()), 1);
  QVERIFY(std::abs(doc->prepared()->extrusions[0].heightM - topM) < 0.05);
  window.toolAction(int(Viewport::Tool::Select))->trigger();
  step(QStringLiteral("table_outlined"));

  // --- 8. Drag the object onto the table: it stands on the top ---
  const Vec2 onTable = *cam.project(centre + Vec3(0, topM, 0));
  const Vec2 objectNow = doc->scene().objects[0].basePx;
  const QPoint grab = view->widgetFromImage(objectNow).toPoint();
  QCOMPARE(view->objectAt(grab), 0);
  QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, grab);
  for (int k = 1; k <= 10; ++k)
    QTest::mouseMove(view,
                     view->widgetFromImage(objectNow + (onTable - objectNow) * (k / 10.0)).toPoint());
  QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, view->widgetFromImage(onTable).toPoint());
  QCOMPARE(undo->count(), 7);
  const double standsAt = doc->prepared()->placements[0].baseWorld.y();
  QVERIFY2(std::abs(standsAt - doc->prepared()->extrusions[0].heightM) < 1e-3,
           qPrintable(QStringLiteral("stands at y = %1 m").arg(standsAt)));
  QTRY_VERIFY_WITH_TIMEOUT(renderer->isCurrent() && renderer->frameInfo().spp >= 2, waitMs(60000));
  // The status bar shows the render's figures.
  QStringList figures;
  for (QLabel* l : window.statusBar()->findChildren<QLabel*>()) figures << l->text();
  const QString joined = figures.join(QLatin1Char(' '));
  QVERIFY2(joined.contains(QStringLiteral("spp")) && joined.contains(QStringLiteral("samples/s")) &&
               joined.contains(QStringLiteral("error")),
           qPrintable(joined));
  step(QStringLiteral("object_on_table"));
  const std::string finalJson = sceneToJson(doc->scene());

  // --- Layers: each shows its own image ---
  for (int l = 0; l < kLayerCount; ++l) {
    window.layersDock()->list()->setCurrentRow(l);
    QCOMPARE(int(view->layer()), l);
    const QImage img = renderer->layerImage(Layer(l));
    QVERIFY2(!img.isNull(), qPrintable(QStringLiteral("layer %1 is empty").arg(l)));
    QCOMPARE(img.width(), doc->prepared()->photo.linearRgb.width);
  }
  QVERIFY(log_->shot(&window, QStringLiteral("layer_difference")));
  window.layersDock()->list()->setCurrentRow(int(Layer::Composite));

  // --- 9. Undo back to the start, then redo to the end ---
  while (undo->canUndo()) undo->undo();
  QVERIFY(undo->isClean());
  QCOMPARE(sceneToJson(doc->scene()), startJson);
  QVERIFY2(waitReady(doc), qPrintable(doc->prepareError()));
  QCOMPARE(doc->objectCount(), 0);
  QVERIFY(!doc->backWallIsUsers());
  step(QStringLiteral("undone_to_start"));
  while (undo->canRedo()) undo->redo();
  QCOMPARE(sceneToJson(doc->scene()), finalJson);
  QVERIFY2(waitReady(doc), qPrintable(doc->prepareError()));
  QVERIFY(std::abs(doc->prepared()->placements[0].baseWorld.y() - topM) < 0.05);
  QTRY_VERIFY_WITH_TIMEOUT(renderer->isCurrent() && renderer->frameInfo().spp >= 2, waitMs(60000));
  step(QStringLiteral("redone_to_end"));

  // --- 10. Save, reopen in a new window, compare ---
  QTemporaryDir dir;
  const QString saved = dir.filePath(QStringLiteral("my_room.json"));
  QVERIFY(window.saveTo(saved));
  QVERIFY(undo->isClean());
  MainWindow reopened;
  reopened.setInteractive(false);
  reopened.resize(1280, 800);
  reopened.show();
  QVERIFY(reopened.openPath(saved));
  QVERIFY2(waitReady(reopened.document()), qPrintable(reopened.document()->prepareError()));
  QCOMPARE(sceneToJson(reopened.document()->scene()), sceneToJson(doc->scene()));
  QVERIFY((reopened.document()->prepared()->placements[0].baseWorld -
           doc->prepared()->placements[0].baseWorld)
              .norm() < 1e-9);
  QTRY_VERIFY_WITH_TIMEOUT(reopened.renderer()->hasFrame(), waitMs(60000));
  step(QStringLiteral("reopened"));

  // --- Figures ---
  QVERIFY(log_->writeFigures(
      QStringLiteral("figures.csv"),
      {QStringLiteral("viewport_paint_ms_median,%1").arg(median(paintMs)),
       QStringLiteral("viewport_paint_ms_max,%1").arg(*std::max_element(paintMs.begin(), paintMs.end())),
       QStringLiteral("first_frame_after_edit_ms_median,%1").arg(median(firstFrameMs)),
       QStringLiteral("first_frame_after_edit_ms_max,%1")
           .arg(*std::max_element(firstFrameMs.begin(), firstFrameMs.end()))}));
  qInfo("viewport paint while rendering: median %.2f ms, max %.2f ms (%zu paints)", median(paintMs),
        *std::max_element(paintMs.begin(), paintMs.end()), paintMs.size());
  qInfo("first updated frame after an object move: median %.1f ms, max %.1f ms (%zu moves)",
        median(firstFrameMs), *std::max_element(firstFrameMs.begin(), firstFrameMs.end()),
        firstFrameMs.size());
  qInfo("steps (name, seconds since start): %s", qPrintable(log_->steps().join(QStringLiteral("; "))));
}

void StudioWorkflowTest::frenchFromTheLanguageMenu() {
  {
    MainWindow window;
    window.setInteractive(false);
    QAction* french = nullptr;
    for (QAction* a : window.findChildren<QAction*>())
      if (a->text() == QStringLiteral("Français")) french = a;
    QVERIFY(french);
    french->trigger();  // stored in the settings, translators installed
  }
  QCOMPARE(QSettings().value(QStringLiteral("language")).toString(), QStringLiteral("fr"));
  QCOMPARE(chosenLanguage(), QStringLiteral("fr"));
  {
    MainWindow window;
    window.resize(1280, 800);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QCOMPARE(window.fileMenu()->title().remove(QLatin1Char('&')), QStringLiteral("Fichier"));
    QCOMPARE(window.toolsMenu()->title().remove(QLatin1Char('&')), QStringLiteral("Outils"));
    QCOMPARE(window.layersDock()->windowTitle(), QStringLiteral("Calques"));
    // Qt's own strings come from qtbase_fr (when the system has it).
    if (QFile::exists(QLibraryInfo::path(QLibraryInfo::TranslationsPath) +
                      QStringLiteral("/qtbase_fr.qm")))
      QCOMPARE(QCoreApplication::translate("QPlatformTheme", "Cancel"), QStringLiteral("Annuler"));
    QVERIFY(log_->shot(&window, QStringLiteral("french")));
  }
  // Back to the system's language (English here).
  QSettings().remove(QStringLiteral("language"));
  removeTranslators();
  MainWindow english;
  QCOMPARE(english.fileMenu()->title().remove(QLatin1Char('&')), QStringLiteral("File"));
}

QTEST_MAIN(StudioWorkflowTest)
#include "studio_workflow_test.moc"
