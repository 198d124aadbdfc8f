// The studio as a designer uses it with their own models: open a York photo (../shared/york,
// skipped without it), insert a glTF model through Insert Model…, drop an OBJ (with concave
// n-gon faces) on the floor and one on a wall (it lands on the floor below), turn and scale in
// Properties, duplicate, rename, hide, turn and raise with the on-canvas handles, drag it near a
// wall (its back snaps to the wall), render the final image, export, undo everything and redo it
// all (the guided start with the Steps panel is studio_guided_test). Each step's seconds since
// the photo was opened and a screenshot go to studio_designer_artifacts/ in the build tree
// (figures.csv, NN_step.png). Bad model files (empty, NaN, flat, over the triangle limit, absurd
// units, taller than the room) get a message naming the file or a sane default, never a crash; a
// model dropped on a table top while the scene is being prepared for that top waits and stands
// on it; the Properties dock labels every field, in German and French. The functions on the
// bundled example share one window and its preparation (preparedExample).
#include "docks.h"
#include "document.h"
#include "i18n.h"
#include "library_dock.h"
#include "main_window.h"
#include "model_import.h"
#include "render_controller.h"
#include "steps_dock.h"
#include "viewport.h"

#include "inlay/engine/pipeline.h"

#include <QAction>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QDropEvent>
#include <QFile>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMimeData>
#include <QPushButton>
#include <QSignalSpy>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QUrl>
#include <QtTest>

#include <cmath>
#include <numbers>

#include "studio_test_support.h"
#include "studio_workflow_steps.h"
#include "studio_designer_helpers.h"

using namespace inlay;
using namespace inlay::studio;
using namespace inlay::test;

// The helpers (sharedFile, dropUrl, floorPixel, ...) are shared with studio_guided_test.

class StudioDesignerTest : public QObject {
  Q_OBJECT

 private Q_SLOTS:
  void initTestCase();
  void modelsInsertDropArrangeUndoRedo();
  void badModelFilesGetMessagesOrSaneDefaults();
  void dropOnATableTopStandsOnIt();
  void propertiesLabelEveryFieldInEveryLanguage();
  void bigPhotosPreviewAtAboutOneMegapixel();

 private:
  // The bundled example, opened and prepared once for the functions that need it (each adds
  // its own objects and counts from what it finds); null when it is not installed or failed.
  MainWindow* preparedExample();

  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> example_;
};

MainWindow* StudioDesignerTest::preparedExample() {
  if (!example_) {
    const QString example = inlay::test::exampleScene();
    if (example.isEmpty()) return nullptr;
    example_ = inlay::test::openStudio(example);
    if (!example_) return nullptr;
  }
  if (!inlay::test::waitReady(example_->document(), waitMs(120000))) return nullptr;
  return example_.get();
}

void StudioDesignerTest::initTestCase() {
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName(QStringLiteral("InlayTest"));
  QCoreApplication::setApplicationName(QStringLiteral("studio_designer_test"));
  QSettings().clear();
  QVERIFY(dir_.isValid());
}

void StudioDesignerTest::modelsInsertDropArrangeUndoRedo() {
  const QString photo = sharedFile(QStringLiteral("york/P1020833.jpg"));
  if (photo.isEmpty()) QSKIP("skipped: ../shared/york not present (needs ../shared/york/P1020833.jpg)");
  // The glTF model: ../shared/models' spot when present, else a box this test writes.
  QString gltf = sharedFile(QStringLiteral("models/spot_red_plastic.glb"));
  if (gltf.isEmpty()) {
    gltf = dir_.filePath(QStringLiteral("cabinet.gltf"));
    QVERIFY(writeText(gltf, boxGltf(0.8, 1.1, 0.4)));
  }
  const QString shelf = dir_.filePath(QStringLiteral("shelf.obj"));
  QVERIFY(writeText(shelf, concaveShelfObj()));

  // --- 1. Open the photo: the scene is estimated ---
  DesignerWalk walk(QStringLiteral("studio_designer_artifacts"));
  const QString opened = walk.openPhoto(photo, waitMs(180000));
  QVERIFY2(opened.isEmpty(), qPrintable(opened));
  MainWindow& window = walk.window;
  Document* doc = window.document();
  Viewport* view = window.viewport();
  // Each step's screenshot once the preview shows its result (the time is taken before).
  auto step = [&](const QString& name) { QVERIFY(walk.step(name, waitMs(60000))); };

  // --- 2. Insert Model… with a glTF file: named after it, its own size (glTF is in metres) ---
  QVERIFY(window.insertModelAction()->isEnabled());
  QCOMPARE(window.insertModelAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_I));
  QElapsedTimer clock;
  clock.start();
  QVERIFY(window.insertModelFile(gltf));
  QVERIFY(waitNoPendingModels(window, waitMs(30000)));
  QVERIFY2(window.lastModelError().isEmpty(), qPrintable(window.lastModelError()));
  walk.timings << QStringLiteral("insert_gltf_ms,%1").arg(clock.elapsed());
  QCOMPARE(doc->objectCount(), 1);
  const ObjectKeys& inserted = doc->scene().objects[0];
  QCOMPARE(QString::fromStdString(inserted.name), QFileInfo(gltf).completeBaseName());
  QCOMPARE(doc->objectName(0), QFileInfo(gltf).completeBaseName());
  const double ownHeight = meshHeightUnits(*doc->prepared()->renderScene.objects[0].meshObject);
  QVERIFY2(std::abs(inserted.heightM - ownHeight) < 1e-6,
           qPrintable(QStringLiteral("height %1, the file's %2").arg(inserted.heightM).arg(ownHeight)));
  QVERIFY(std::abs(standsAtY(doc, 0)) < 1e-6);  // on the floor
  QCOMPARE(window.propertiesDock()->nameBox()->text(), QFileInfo(gltf).completeBaseName());
  QVERIFY(window.propertiesDock()->sizeLabel()->text().contains(QStringLiteral(" × ")));
  // Open Recent keeps it, under Models.
  QVERIFY(QSettings()
              .value(QStringLiteral("recentModels"))
              .toStringList()
              .contains(QFileInfo(gltf).absoluteFilePath()));
  {
    const QList<QAction*> recent = window.recentMenu()->actions();
    QVERIFY(std::any_of(recent.begin(), recent.end(), [&](QAction* a) {
      return a->data().toString() == QFileInfo(gltf).absoluteFilePath() && a->isEnabled();
    }));
  }
  step(QStringLiteral("gltf_inserted"));

  // --- 3. Drop an OBJ (concave faces, no unit) on the floor: it stands where it was dropped ---
  QTRY_VERIFY_WITH_TIMEOUT(window.renderer()->hasFrame(), waitMs(30000));
  const std::optional<Vec2> floorAt = floorPixel(doc, 0.3);
  QVERIFY(floorAt);
  clock.restart();
  QVERIFY(dropUrl(view, shelf, view->widgetFromImage(*floorAt).toPoint()));
  QTRY_COMPARE_WITH_TIMEOUT(doc->objectCount(), 2, waitMs(30000));
  walk.timings << QStringLiteral("drop_obj_ms,%1").arg(clock.elapsed());
  const ObjectKeys& dropped = doc->scene().objects[1];
  QCOMPARE(QString::fromStdString(dropped.name), QStringLiteral("shelf"));
  QVERIFY((dropped.basePx - *floorAt).norm() < 2.0);  // within the widget-to-image rounding
  QVERIFY(std::abs(standsAtY(doc, 1)) < 1e-6);
  QCOMPARE(dropped.heightM, defaultModelHeightM());  // OBJ states no unit
  // Every triangle of the shelf's U faces lies inside the U (no fan across the opening).
  {
    const TriangleMesh& m = *doc->prepared()->renderScene.objects[1].meshObject;
    QCOMPARE(int(m.triangles.size()), 2 * 6 + 8 * 2);
    for (const auto& t : m.triangles) {
      const Vec3f c = (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3.f;
      QVERIFY2(!(c.x() > 0.2f && c.x() < 0.8f && c.y() > 0.2f), "a triangle across the shelf's opening");
    }
  }
  step(QStringLiteral("obj_dropped_on_floor"));

  // A drop on the back wall: the model lands on the floor straight below the cursor.
  const std::array<Vec2, 4> wall = *doc->shownBackWallPx();
  const Vec2 onWall = 0.5 * (wall[0] + wall[2]);
  QVERIFY(dropUrl(view, shelf, view->widgetFromImage(onWall).toPoint()));
  QTRY_COMPARE_WITH_TIMEOUT(doc->objectCount(), 3, waitMs(30000));
  QVERIFY(std::abs(doc->scene().objects[2].basePx.x() - onWall.x()) < 2.0);
  QVERIFY(doc->scene().objects[2].basePx.y() > onWall.y());
  QVERIFY(std::abs(standsAtY(doc, 2)) < 1e-6);
  step(QStringLiteral("obj_dropped_on_wall_lands_on_floor"));

  // --- 4. Turn and scale the shelf in Properties (one undo step each) ---
  doc->setSelectedObject(1);
  const int beforeArrange = doc->undoStack()->count();
  clock.restart();
  window.propertiesDock()->yawBox()->setValue(35.0);
  window.propertiesDock()->heightBox()->setValue(1.2);
  walk.timings << QStringLiteral("turn_and_scale_ms,%1").arg(clock.elapsed());
  QCOMPARE(doc->scene().objects[1].yawDeg, 35.0);
  QCOMPARE(doc->scene().objects[1].heightM, 1.2);
  QCOMPARE(doc->undoStack()->count(), beforeArrange + 2);
  const std::optional<Vec3> size = doc->objectSizeM(1);
  QVERIFY(size);
  QVERIFY(std::abs(size->y() - 1.2) < 1e-9 && std::abs(size->x() / size->y() - 1.0 / 1.8) < 1e-4);
  QVERIFY(window.propertiesDock()->sizeLabel()->text().startsWith(QStringLiteral("0.67 × 0.20 × 1.20")));
  QTRY_VERIFY_WITH_TIMEOUT(window.renderer()->isCurrent(), waitMs(30000));
  step(QStringLiteral("turned_and_scaled"));

  // --- 5. Duplicate (Ctrl+D), rename and hide: one undo step each ---
  QCOMPARE(window.duplicateAction()->shortcut(), QKeySequence(Qt::CTRL | Qt::Key_D));
  window.duplicateAction()->trigger();
  QCOMPARE(doc->objectCount(), 4);
  QCOMPARE(doc->selectedObject(), 3);
  QCOMPARE(doc->objectName(3), QStringLiteral("shelf 2"));
  QCOMPARE(doc->scene().objects[3].heightM, 1.2);
  QCOMPARE(doc->scene().objects[3].yawDeg, 35.0);
  QVERIFY((doc->scene().objects[3].basePx - doc->scene().objects[1].basePx).norm() > 5.0);  // beside it
  QVERIFY(std::abs(standsAtY(doc, 3) - standsAtY(doc, 1)) < 0.02);
  QVERIFY(doc->renameObject(3, QStringLiteral("bookshelf")));
  QCOMPARE(doc->objectName(3), QStringLiteral("bookshelf"));
  window.hideAction()->trigger();
  QVERIFY(doc->scene().objects[3].hidden);
  QVERIFY(!window.propertiesDock()->shownBox()->isChecked());
  QCOMPARE(doc->undoStack()->count(), beforeArrange + 5);
  QTRY_VERIFY_WITH_TIMEOUT(window.renderer()->isCurrent(), waitMs(30000));
  step(QStringLiteral("duplicated_renamed_hidden"));
  window.hideAction()->trigger();  // shown again for the pictures
  QVERIFY(!doc->scene().objects[3].hidden);
  QTRY_VERIFY_WITH_TIMEOUT(window.renderer()->isCurrent() && window.renderer()->frameInfo().spp >= 2,
                           waitMs(60000));
  step(QStringLiteral("arranged"));

  // --- On-canvas handles: turn the shelf to 80° and raise it by a quarter, one undo step each ---
  doc->setSelectedObject(1);
  QTRY_VERIFY_WITH_TIMEOUT(window.renderer()->isCurrent(), waitMs(30000));
  const Vec3 shelfBase = doc->prepared()->placements[1].baseWorld;
  int beforeGesture = doc->undoStack()->count();
  const std::optional<QPointF> turnAt = view->handlePos(Viewport::Handle::Turn);
  QVERIFY(turnAt);
  QCOMPARE(view->handleAt(*turnAt), Viewport::Handle::Turn);
  const double yaw80 = 80.0 * std::numbers::pi / 180.0;
  clock.restart();
  inlay::test::dragLeft(
      view, turnAt->toPoint(),
      widgetOf(doc, view, shelfBase + 0.6 * Vec3(std::sin(yaw80), 0, std::cos(yaw80))));
  QVERIFY2(std::abs(doc->scene().objects[1].yawDeg - 80.0) < 2.0,
           qPrintable(QString::number(doc->scene().objects[1].yawDeg)));
  QCOMPARE(doc->undoStack()->count(), beforeGesture + 1);
  QTRY_VERIFY_WITH_TIMEOUT(window.renderer()->isCurrent(), waitMs(30000));
  walk.timings << QStringLiteral("turn_handle_to_frame_ms,%1").arg(clock.elapsed());
  const double h0 = doc->scene().objects[1].heightM;
  const std::optional<QPointF> heightAt = view->handlePos(Viewport::Handle::Height);
  QVERIFY(heightAt);
  clock.restart();
  inlay::test::dragLeft(view, heightAt->toPoint(),
                        widgetOf(doc, view, shelfBase + Vec3(0, 1.25 * h0, 0)));
  QVERIFY2(std::abs(doc->scene().objects[1].heightM - 1.25 * h0) < 0.03 * h0,
           qPrintable(QString::number(doc->scene().objects[1].heightM)));
  QCOMPARE(doc->undoStack()->count(), beforeGesture + 2);
  QTRY_VERIFY_WITH_TIMEOUT(window.renderer()->isCurrent(), waitMs(30000));
  walk.timings << QStringLiteral("height_handle_to_frame_ms,%1").arg(clock.elapsed());
  step(QStringLiteral("handles_turned_and_raised"));

  // --- Dragged near a wall, the shelf stands with its back against it, facing into the room ---
  {
    const RoomBox& box = doc->prepared()->geometry.box;
    const double halfDepth = 0.5 * doc->objectSizeM(1)->z();
    struct Wall {
      Vec3 nearIt, normal;
      double yawDeg;
      Vec3 onWall;
    };
    // 10 cm between the shelf's back and the wall (the snap takes up to 25 cm).
    const Wall walls[] = {{Vec3(box.xLeftM + halfDepth + 0.10, 0, shelfBase.z()), Vec3(1, 0, 0), 90.0,
                           Vec3(box.xLeftM, 0, 0)},
                          {Vec3(box.xRightM - halfDepth - 0.10, 0, shelfBase.z()), Vec3(-1, 0, 0), -90.0,
                           Vec3(box.xRightM, 0, 0)},
                          {Vec3(shelfBase.x(), 0, box.zBackM + halfDepth + 0.10), Vec3(0, 0, 1), 0.0,
                           Vec3(0, 0, box.zBackM)}};
    const Wall* chosen = nullptr;
    for (const Wall& w : walls) {
      const std::optional<Vec2> px = doc->prepared()->camera.project(w.nearIt);
      const std::optional<Vec2> stand = px ? doc->supportPointNear(*px) : std::nullopt;
      if (stand && (*stand - *px).norm() < 1.0 && doc->prepared()->camera.depthOf(w.nearIt) > 0.5) {
        chosen = &w;
        break;
      }
    }
    QVERIFY2(chosen, "no wall of the room has floor in view beside it");
    beforeGesture = doc->undoStack()->count();
    clock.restart();
    inlay::test::dragLeft(view, view->widgetFromImage(doc->scene().objects[1].basePx).toPoint(),
                          widgetOf(doc, view, chosen->nearIt), 20);
    QVERIFY2(std::abs(doc->scene().objects[1].yawDeg - chosen->yawDeg) < 1e-6,
             qPrintable(QString::number(doc->scene().objects[1].yawDeg)));
    const Vec3 snapped = doc->prepared()->placements[1].baseWorld;
    const double toWall = (snapped - chosen->onWall).dot(chosen->normal);
    QVERIFY2(std::abs(toWall - (halfDepth + 0.005)) < 0.01,
             qPrintable(
                 QStringLiteral("%1 m from the wall, the half depth is %2").arg(toWall).arg(halfDepth)));
    QCOMPARE(doc->undoStack()->count(), beforeGesture + 1);
    QTRY_VERIFY_WITH_TIMEOUT(window.renderer()->isCurrent(), waitMs(30000));
    walk.timings << QStringLiteral("snap_drag_to_frame_ms,%1").arg(clock.elapsed());
    step(QStringLiteral("snapped_to_wall"));
  }

  // --- Render the final image (full size, at most 2 samples per pixel here to keep the test
  // short; the final frame is denoised, so the shot is clean) and export the composite ---
  {
    const QString finalPath = walk.log.filePath(QStringLiteral("final.png"));
    QFile::remove(finalPath);
    QSignalSpy finished(&window, &MainWindow::finalImageFinished);
    clock.restart();
    QVERIFY(window.renderFinalImage(finalPath, 2));
    QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, waitMs(180000));
    walk.timings << QStringLiteral("render_final_ms,%1").arg(clock.elapsed());
    QVERIFY2(finished.first()[0].toBool(), qPrintable(finished.first()[1].toString()));
    QVERIFY2(finished.first()[1].toString().contains(QStringLiteral("before denoising")),
             qPrintable(finished.first()[1].toString()));
    QCOMPARE(QImage(finalPath).size(),
             QSize(doc->prepared()->camera.widthPx, doc->prepared()->camera.heightPx));
    step(QStringLiteral("final_rendered"));
    const QString exported = walk.log.filePath(QStringLiteral("composite.png"));
    QFile::remove(exported);
    QVERIFY(window.exportComposite(exported));
    QCOMPARE(QImage(exported).size(),
             QSize(doc->prepared()->camera.widthPx, doc->prepared()->camera.heightPx));
    step(QStringLiteral("exported"));
  }

  // --- 6. Undo everything, then redo it all: the same objects, key for key ---
  const std::string arranged = objectsJson(doc);
  clock.restart();
  int undone = 0;
  while (doc->undoStack()->canUndo()) {
    window.undoAction()->trigger();
    ++undone;
  }
  walk.timings << QStringLiteral("undo_all_ms,%1").arg(clock.elapsed());
  QCOMPARE(doc->objectCount(), 0);
  QTRY_VERIFY_WITH_TIMEOUT(window.renderer()->isCurrent(), waitMs(30000));
  step(QStringLiteral("all_undone"));
  clock.restart();
  for (int i = 0; i < undone; ++i) doc->undoStack()->redo();
  walk.timings << QStringLiteral("redo_all_ms,%1").arg(clock.elapsed());
  QVERIFY(inlay::test::waitReady(doc, waitMs(180000)));
  QCOMPARE(objectsJson(doc), arranged);
  QCOMPARE(int(doc->prepared()->placements.size()), 4);
  QTRY_VERIFY_WITH_TIMEOUT(window.renderer()->isCurrent() && window.renderer()->frameInfo().spp >= 2,
                           waitMs(60000));
  step(QStringLiteral("all_redone"));

  // (A drop while the scene is being prepared: dropOnATableTopStandsOnIt, on a preparation
  // that scene needs anyway.)
  QVERIFY(walk.report());
  qInfo("screenshots: %s", qPrintable(walk.log.shots().join(QStringLiteral(" "))));
}

void StudioDesignerTest::badModelFilesGetMessagesOrSaneDefaults() {
  auto write = [&](const QString& name, const QByteArray& bytes) {
    const QString p = dir_.filePath(name);
    return writeText(p, bytes) ? p : QString();
  };
  auto refusedNaming = [](const ModelLoadResult& r, const QString& file, const QString& what) {
    if (r.model) return QStringLiteral("%1 was accepted").arg(file);
    if (!r.error.contains(file) || !r.error.contains(what, Qt::CaseInsensitive))
      return QStringLiteral("message '%1' does not name %2 and '%3'").arg(r.error, file, what);
    return QString();
  };
  const double h = 0.75;
  // Empty, NaN, flat, not a model, over the limit: refused with the file and the reason.
  QString why = refusedNaming(loadModelForInsert(write(QStringLiteral("empty.obj"), QByteArray()), h),
                              QStringLiteral("empty.obj"), QStringLiteral("empty"));
  QVERIFY2(why.isEmpty(), qPrintable(why));
  why = refusedNaming(
      loadModelForInsert(write(QStringLiteral("nan.obj"), "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n"), h),
      QStringLiteral("nan.obj"), QStringLiteral("non-finite"));
  QVERIFY2(why.isEmpty(), qPrintable(why));
  why = refusedNaming(
      loadModelForInsert(
          write(QStringLiteral("rug.obj"), "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nf 1 2 3 4\n"), h),
      QStringLiteral("rug.obj"), QStringLiteral("flat"));
  QVERIFY2(why.isEmpty(), qPrintable(why));
  why = refusedNaming(loadModelForInsert(write(QStringLiteral("notes.txt"), "hello"), h),
                      QStringLiteral("notes.txt"), QStringLiteral("not a model file"));
  QVERIFY2(why.isEmpty(), qPrintable(why));
  why = refusedNaming(loadModelForInsert(write(QStringLiteral("junk.fbx"), "no FBX in here"), h),
                      QStringLiteral("junk.fbx"), QStringLiteral("import failed"));
  QVERIFY2(why.isEmpty(), qPrintable(why));
  // The triangle limit, stated in the message (a small limit stands in for 5 million).
  ModelImportLimits tiny;
  tiny.maxTriangles = 10;
  const ModelLoadResult big =
      loadModelForInsert(write(QStringLiteral("shelf_big.obj"), concaveShelfObj()), h, tiny);
  why = refusedNaming(big, QStringLiteral("shelf_big.obj"), QStringLiteral("10"));
  QVERIFY2(why.isEmpty(), qPrintable(why));
  QVERIFY2(big.error.contains(QStringLiteral("up to 10 triangles")), qPrintable(big.error));
  QCOMPARE(ModelImportLimits{}.maxTriangles, size_t(5'000'000));

  // Absurd units: a glTF box 1 km or 1 µm high gets the default height and a note.
  for (const double metres : {1000.0, 1e-6}) {
    const ModelLoadResult r =
        loadModelForInsert(write(QStringLiteral("absurd.gltf"), boxGltf(metres, metres, metres)), h);
    QVERIFY2(r.model, qPrintable(r.error));
    QCOMPARE(r.model->heightM, h);
    QVERIFY(!r.model->ownSize);
    QVERIFY(!r.model->notes.isEmpty() &&
            r.model->notes.join(QString()).contains(QStringLiteral("absurd")));
  }
  // A plausible one keeps its own size; one without normals gets a note and flat shading.
  const ModelLoadResult cabinet =
      loadModelForInsert(write(QStringLiteral("cabinet.gltf"), boxGltf(0.8, 1.1, 0.4)), h);
  QVERIFY2(cabinet.model, qPrintable(cabinet.error));
  QVERIFY(cabinet.model->ownSize);
  QVERIFY(std::abs(cabinet.model->heightM - 1.1) < 1e-6);
  QCOMPARE(cabinet.model->name, QStringLiteral("cabinet"));
  const ModelLoadResult bare =
      loadModelForInsert(write(QStringLiteral("bare.obj"), concaveShelfObj()), h);
  QVERIFY2(bare.model, qPrintable(bare.error));
  QVERIFY(bare.model->notes.join(QString()).contains(QStringLiteral("no normals")));
  // A missing MTL file (its textures with it): the model still comes in, with the default material.
  const ModelLoadResult lost = loadModelForInsert(
      write(QStringLiteral("lost.obj"), "mtllib nowhere.mtl\nusemtl wood\n" + concaveShelfObj()), h);
  QVERIFY2(lost.model, qPrintable(lost.error));

  // Through the window: a refusal is a message naming the file, and nothing changes.
  if (inlay::test::exampleScene().isEmpty()) QSKIP("the bundled example is not installed");
  MainWindow* window = preparedExample();
  QVERIFY(window);
  const int objects = window->document()->objectCount();
  const int steps = window->document()->undoStack()->count();
  QVERIFY(window->insertModelFile(dir_.filePath(QStringLiteral("nan.obj"))));
  QVERIFY(waitNoPendingModels(*window, waitMs(10000)));
  QVERIFY2(window->lastModelError().contains(QStringLiteral("nan.obj")),
           qPrintable(window->lastModelError()));
  QVERIFY(!window->insertModelFile(dir_.filePath(QStringLiteral("notes.txt"))));
  QVERIFY(window->lastModelError().contains(QStringLiteral("notes.txt")));
  QCOMPARE(window->document()->objectCount(), objects);
  QCOMPARE(window->document()->undoStack()->count(), steps);
  // A plausible size the room cannot hold (15 m, in metres as glTF says): the default height.
  const QString tower = write(QStringLiteral("tower.gltf"), boxGltf(1, 15, 1));
  QVERIFY(window->document()->prepared()->box.ceilingM < 15);
  QVERIFY(window->insertModelFile(tower));
  QVERIFY(waitNoPendingModels(*window, waitMs(10000)));
  QVERIFY2(window->lastModelError().isEmpty(), qPrintable(window->lastModelError()));
  QCOMPARE(window->document()->objectCount(), objects + 1);
  QCOMPARE(window->document()->scene().objects.back().heightM, defaultModelHeightM());
  QCOMPARE(window->document()->undoStack()->count(), steps + 1);
  // Lower than the ceiling but wider than the whole room (a 40 m x 2 m slab, as a teapot that
  // says 6 m is): the default height too, and its own height keeps a model the room holds.
  const QString slab = write(QStringLiteral("slab.gltf"), boxGltf(40, 2, 1));
  QVERIFY(window->insertModelFile(slab));
  QVERIFY(waitNoPendingModels(*window, waitMs(10000)));
  QCOMPARE(window->document()->objectCount(), objects + 2);
  QCOMPARE(window->document()->scene().objects.back().heightM, defaultModelHeightM());
  const QString stool = write(QStringLiteral("stool.gltf"), boxGltf(0.4, 0.45, 0.4));
  QVERIFY(window->insertModelFile(stool));
  QVERIFY(waitNoPendingModels(*window, waitMs(10000)));
  QCOMPARE(window->document()->objectCount(), objects + 3);
  QVERIFY(std::abs(window->document()->scene().objects.back().heightM - 0.45) < 1e-6);
}

void StudioDesignerTest::dropOnATableTopStandsOnIt() {
  if (inlay::test::exampleScene().isEmpty()) QSKIP("the bundled example is not installed");
  const QString shelf = dir_.filePath(QStringLiteral("small_shelf.obj"));
  QVERIFY(writeText(shelf, concaveShelfObj()));
  MainWindow* window = preparedExample();  // with badModelFiles...'s objects when it ran first
  QVERIFY(window);
  Document* doc = window->document();
  // A table top outlined on the example's floor (as the Table Top tool makes it). The model is
  // dropped on it while the scene is being prepared for it: the drop waits and goes in once the
  // scene is ready, onto the new top.
  QVERIFY(doc->addExtrusion({{60, 250}, {150, 250}, {160, 280}, {50, 280}}, {60, 330}));
  QCOMPARE(doc->state(), Document::State::Preparing);
  const int objects = doc->objectCount();
  const int steps = doc->undoStack()->count();
  const Vec2 onTop(105, 265);
  QVERIFY(dropUrl(window->viewport(), shelf, window->viewport()->widgetFromImage(onTop).toPoint()));
  QVERIFY2(inlay::test::waitReady(doc, waitMs(120000)), qPrintable(doc->prepareError()));
  QVERIFY(waitNoPendingModels(*window, waitMs(30000)));
  QCOMPARE(doc->undoStack()->count(), steps + 1);  // the drop is one undo step
  QVERIFY2(window->lastModelError().isEmpty(), qPrintable(window->lastModelError()));
  QCOMPARE(doc->objectCount(), objects + 1);
  const int i = objects;
  QVERIFY((doc->scene().objects[size_t(i)].basePx - onTop).norm() < 2.0);
  // On the top, above the floor, on the surface the drop pointed at.
  const Placement& pl = doc->prepared()->placements[size_t(i)];
  QVERIFY2(pl.baseWorld.y() > 0.05, qPrintable(QString::number(pl.baseWorld.y())));
  const auto& surfaces = doc->prepared()->geometry.surfaces;
  QVERIFY(pl.supportSurfaceId >= 0 && size_t(pl.supportSurfaceId) < surfaces.size());
  QVERIFY2(QString::fromStdString(surfaces[size_t(pl.supportSurfaceId)].name)
               .endsWith(QStringLiteral("_top")),
           surfaces[size_t(pl.supportSurfaceId)].name.c_str());
  // Its duplicate stays on the table top (not on the floor beside it), or on the same spot.
  QVERIFY(doc->duplicateObject(i));
  QVERIFY(std::abs(doc->prepared()->placements[size_t(i + 1)].baseWorld.y() - pl.baseWorld.y()) < 0.02);
}

void StudioDesignerTest::propertiesLabelEveryFieldInEveryLanguage() {
  MainWindow window;
  window.setInteractive(false);
  window.show();
  QVERIFY(QTest::qWaitForWindowExposed(&window));
  PropertiesDock* dock = window.propertiesDock();
  auto* form = dock->findChild<QFormLayout*>();  // inside the dock's scroll area
  QVERIFY(form);
  auto labels = [&] {
    QStringList out;
    for (int row = 0; row < form->rowCount(); ++row) {
      if (form->itemAt(row, QFormLayout::SpanningRole)) continue;  // a section title
      QLayoutItem* field = form->itemAt(row, QFormLayout::FieldRole);
      if (!field || !field->widget()) continue;
      auto* label = qobject_cast<QLabel*>(form->labelForField(field->widget()));
      out << (label ? label->text() : QString());
    }
    return out;
  };
  const QStringList english = labels();
  QVERIFY(english.size() >= 12);
  for (const QString& l : english)
    QVERIFY2(!l.isEmpty(),
             qPrintable(QStringLiteral("a field without a label: ") + english.join(QLatin1Char('|'))));
  QVERIFY(english.contains(QStringLiteral("Size (W × D × H):")));
  for (const QString& lang : {QStringLiteral("de"), QStringLiteral("fr")}) {
    window.setLanguage(lang);
    QCoreApplication::processEvents();
    const QStringList translated = labels();
    QCOMPARE(translated.size(), english.size());
    for (int i = 0; i < english.size(); ++i) {
      QVERIFY2(!translated[i].isEmpty(), qPrintable(lang));
      if (english[i] != QLatin1String("Name:") &&
          english[i] != QLatin1String("Material:"))  // German too
        QVERIFY2(translated[i] != english[i], qPrintable(lang + QStringLiteral(": ") + english[i]));
    }
    QVERIFY(window.insertModelAction()->text() != QStringLiteral("Insert &Model…"));
  }
  window.setLanguage(QStringLiteral("en"));
  QSettings().remove(QStringLiteral("language"));
  removeTranslators();
}

// A 12-megapixel photo's preview renders at about 1 MP with the photo's aspect; photos up to
// 1 MP render their preview at their own size (Render Final Image is always the photo's).
void StudioDesignerTest::bigPhotosPreviewAtAboutOneMegapixel() {
  QCOMPARE(RenderController::previewSizeFor(640, 480), QSize(640, 480));
  QCOMPARE(RenderController::previewSizeFor(1000, 1000), QSize(1000, 1000));
  for (const QSize photo :
       {QSize(4000, 3000), QSize(3000, 4000), QSize(9248, 6936), QSize(1001, 1000)}) {
    const QSize p = RenderController::previewSizeFor(photo.width(), photo.height());
    const double pixels = double(p.width()) * p.height();
    QVERIFY2(pixels <= RenderController::kPreviewMaxPixels * 1.003 &&
                 pixels > 0.99 * RenderController::kPreviewMaxPixels,
             qPrintable(QStringLiteral("%1 x %2").arg(p.width()).arg(p.height())));
    QVERIFY(std::abs(double(p.width()) / p.height() - double(photo.width()) / photo.height()) < 0.003);
  }
  QCOMPARE(RenderController::previewSizeFor(0, 0), QSize(0, 0));
}

QTEST_MAIN(StudioDesignerTest)
#include "studio_designer_test.moc"
