// The tools for the scene's marks through the mouse and keys, offscreen: shaft boxes, occluder
// strokes, outline editing keys, deleting a mark from the scene tree, undoing an object edit
// while the marks are being re-prepared, and zoom and pan keeping the image under the cursor.
#include "docks.h"
#include "document.h"
#include "log_dock.h"
#include "main_window.h"
#include "render_controller.h"
#include "viewport.h"

#include "image_convert.h"
#include "inlay/engine/pipeline.h"
#include "inlay/modeling/image_io.h"
#include "inlay/modeling/image_resample.h"
#include "inlay/modeling/scene_file.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QStandardPaths>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QUndoStack>
#include <QtTest>

#include "studio_test_support.h"
#include "scene_scaling.h"

using namespace inlay;
using inlay::test::waitMs;
using namespace inlay::studio;

namespace {

void waitPrepared(Document* doc) {
  QElapsedTimer t;
  t.start();
  while (doc->state() == Document::State::Preparing && t.elapsed() < waitMs(180000)) QTest::qWait(20);
}

// The example photographed twice as large (1024 x 768, above the working copy's 0.5 MP): its
// photo enlarged into `dir`, its pixel keys scaled, saved as `dir`/big.json.
QString enlargedExample(const QTemporaryDir& dir) {
  auto loaded = loadSceneFile(inlay::test::exampleScene().toStdString());
  if (!loaded.ok()) return {};
  SceneDoc doc = loaded->doc;
  auto photo = loadImage(doc.photoResolved.empty() ? doc.photo : doc.photoResolved);
  if (!photo.ok()) return {};
  const double k = 2;
  const std::string image = dir.filePath(QStringLiteral("big.png")).toStdString();
  if (!saveImage(image, resizeImage(photo->linearRgb, 1024, 768)).ok()) return {};
  doc.photo = doc.photoResolved = image;
  inlay::test::scalePixelKeys(doc, k);
  const QString scene = dir.filePath(QStringLiteral("big.json"));
  return saveSceneFile(scene.toStdString(), doc).ok() ? scene : QString();
}

// A drag with `button` between two image points.
void dragImage(Viewport* view, Qt::MouseButton button, const Vec2& a, const Vec2& b, int steps = 6) {
  const QPoint from = view->widgetFromImage(a).toPoint(), to = view->widgetFromImage(b).toPoint();
  QTest::mousePress(view, button, Qt::NoModifier, from);
  for (int k = 1; k <= steps; ++k) QTest::mouseMove(view, from + (to - from) * k / steps);
  QTest::mouseRelease(view, button, Qt::NoModifier, to);
}

}  // namespace

class StudioToolsTest : public QObject {
  Q_OBJECT

 private Q_SLOTS:
  void initTestCase();
  void init();
  void cleanup();
  void shaftToolDrawsTwoBoxes();
  void occluderStrokesBecomeOneOccluderThenAppend();
  void outlineKeysAndDeletingAMark();
  void undoingAnObjectEditWhilePreparing();
  void zoomAndPanKeepTheImageUnderTheCursor();
  void exportShownLayer();
  void exportSceneAsGltf();
  void logListsEachPreparationsStages();
  void directLightOfABigPhotoAtThePhotosSize();

 private:
  void openPrepared(const QString& scene);
  std::unique_ptr<MainWindow> window_;
  Document* doc_ = nullptr;
  Viewport* view_ = nullptr;
};

void StudioToolsTest::initTestCase() {
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName(QStringLiteral("InlayTest"));
  QCoreApplication::setApplicationName(QStringLiteral("studio_tools_test"));
  qunsetenv("INLAY_LANG");
}

void StudioToolsTest::init() {
  const QString scene = inlay::test::exampleScene();
  if (scene.isEmpty() || !QFile::exists(scene)) QSKIP("resources/example/scene.json absent");
  openPrepared(scene);
}

// The studio on `scene`, prepared (the test fails when it is not).
void StudioToolsTest::openPrepared(const QString& scene) {
  window_ = inlay::test::openStudio(scene);
  QVERIFY(window_);
  doc_ = window_->document();
  view_ = window_->viewport();
  waitPrepared(doc_);
  QVERIFY2(doc_->isReady(), qPrintable(doc_->prepareError()));
}

void StudioToolsTest::cleanup() { window_.reset(); }

void StudioToolsTest::shaftToolDrawsTwoBoxes() {
  window_->toolAction(int(Viewport::Tool::Shaft))->trigger();
  dragImage(view_, Qt::LeftButton, Vec2(120, 300), Vec2(200, 340));
  QCOMPARE(int(doc_->scene().shafts.size()), 0);  // the source's box comes next
  dragImage(view_, Qt::LeftButton, Vec2(300, 90), Vec2(340, 150));
  QCOMPARE(int(doc_->scene().shafts.size()), 1);
  const ShaftKeys& s = doc_->scene().shafts[0];
  QVERIFY(s.shaftBoxPx && s.sourceBoxPx);
  QVERIFY(std::abs((*s.shaftBoxPx)[0] - 120) < 1.5 && std::abs((*s.shaftBoxPx)[3] - 340) < 1.5);
  QVERIFY(std::abs((*s.sourceBoxPx)[1] - 90) < 1.5 && std::abs((*s.sourceBoxPx)[2] - 340) < 1.5);
  QCOMPARE(doc_->undoStack()->count(), 1);
  QCOMPARE(doc_->state(), Document::State::Preparing);  // re-prepared with the shaft
  waitPrepared(doc_);
  // This photo has no sunlit patch there: the failure names the shaft, nothing crashes.
  if (doc_->state() == Document::State::Failed)
    QVERIFY2(doc_->prepareError().contains(QStringLiteral("shafts[0]")),
             qPrintable(doc_->prepareError()));
  doc_->undoStack()->undo();
  QCOMPARE(int(doc_->scene().shafts.size()), 0);
  waitPrepared(doc_);
  QVERIFY(doc_->isReady());
  // A box too small to mean anything is refused with a reason.
  dragImage(view_, Qt::LeftButton, Vec2(50, 300), Vec2(50.2, 300.2), 1);
  dragImage(view_, Qt::LeftButton, Vec2(300, 90), Vec2(340, 150));
  QCOMPARE(int(doc_->scene().shafts.size()), 0);
}

void StudioToolsTest::occluderStrokesBecomeOneOccluderThenAppend() {
  window_->toolAction(int(Viewport::Tool::Occluder))->trigger();
  const int steps0 = doc_->undoStack()->count();
  dragImage(view_, Qt::LeftButton, Vec2(180, 320), Vec2(230, 330));
  QCOMPARE(int(doc_->scene().occluders.size()), 0);  // no background stroke yet
  dragImage(view_, Qt::RightButton, Vec2(300, 200), Vec2(360, 210));
  QCOMPARE(int(doc_->scene().occluders.size()), 1);
  QCOMPARE(doc_->undoStack()->count(), steps0 + 1);
  const OccluderKeys& o = doc_->scene().occluders[0];
  QCOMPARE(int(o.foregroundScribblesPx.size()), 1);
  QCOMPARE(int(o.backgroundScribblesPx.size()), 1);
  QVERIFY(o.foregroundScribblesPx[0].size() >= 3);
  QVERIFY((o.foregroundScribblesPx[0].front() - Vec2(180, 320)).norm() < 1.5);
  // Another stroke goes to the same occluder, one undo step.
  dragImage(view_, Qt::LeftButton, Vec2(190, 340), Vec2(220, 345));
  QCOMPARE(int(doc_->scene().occluders.size()), 1);
  QCOMPARE(int(doc_->scene().occluders[0].foregroundScribblesPx.size()), 2);
  QCOMPARE(doc_->undoStack()->count(), steps0 + 2);
  // Enter: the next strokes start a new occluder.
  QTest::keyClick(view_, Qt::Key_Return);
  dragImage(view_, Qt::LeftButton, Vec2(60, 320), Vec2(80, 330));
  QCOMPARE(int(doc_->scene().occluders.size()), 1);
  waitPrepared(doc_);
  if (doc_->state() == Document::State::Failed)
    QVERIFY2(doc_->prepareError().contains(QStringLiteral("occluders[0]")),
             qPrintable(doc_->prepareError()));
  doc_->undoStack()->undo();
  doc_->undoStack()->undo();
  QCOMPARE(int(doc_->scene().occluders.size()), 0);
}

void StudioToolsTest::outlineKeysAndDeletingAMark() {
  window_->toolAction(int(Viewport::Tool::Light))->trigger();
  for (const Vec2& q : {Vec2(380, 20), Vec2(420, 22), Vec2(500, 200)})
    QTest::mouseClick(view_, Qt::LeftButton, Qt::NoModifier, view_->widgetFromImage(q).toPoint());
  QCOMPARE(int(view_->pendingPoints().size()), 3);
  QTest::keyClick(view_, Qt::Key_Backspace);  // the stray point goes
  QCOMPARE(int(view_->pendingPoints().size()), 2);
  QTest::keyClick(view_, Qt::Key_Return);  // two points: refused, kept for more
  QCOMPARE(int(doc_->scene().lights.size()), 2);
  for (const Vec2& q : {Vec2(420, 32), Vec2(380, 30)})
    QTest::mouseClick(view_, Qt::LeftButton, Qt::NoModifier, view_->widgetFromImage(q).toPoint());
  QTest::keyClick(view_, Qt::Key_Return);
  QCOMPARE(int(doc_->scene().lights.size()), 3);
  QVERIFY(view_->pendingPoints().empty());
  // A double click on the last point closes the outline (the point stays).
  for (const Vec2& q : {Vec2(440, 20), Vec2(480, 24), Vec2(490, 30)})
    QTest::mouseClick(view_, Qt::LeftButton, Qt::NoModifier, view_->widgetFromImage(q).toPoint());
  const QPoint last = view_->widgetFromImage(Vec2(470, 34)).toPoint();
  // As Qt delivers a double click: press, release, double click, release.
  QTest::mouseClick(view_, Qt::LeftButton, Qt::NoModifier, last);
  QMouseEvent dbl(QEvent::MouseButtonDblClick, QPointF(last), view_->mapToGlobal(QPointF(last)),
                  Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
  QCoreApplication::sendEvent(view_, &dbl);
  QTest::mouseRelease(view_, Qt::LeftButton, Qt::NoModifier, last);
  QCOMPARE(int(doc_->scene().lights.size()), 4);
  QCOMPARE(int(doc_->scene().lights[3].pointsPx.size()), 4);
  doc_->undoStack()->undo();
  // Escape drops an outline half drawn.
  QTest::mouseClick(view_, Qt::LeftButton, Qt::NoModifier,
                    view_->widgetFromImage(Vec2(10, 10)).toPoint());
  QTest::keyClick(view_, Qt::Key_Escape);
  QVERIFY(view_->pendingPoints().empty());
  waitPrepared(doc_);

  // A click inside a light's outline selects it (and its scene tree item); Delete removes it.
  window_->toolAction(int(Viewport::Tool::Select))->trigger();
  const QPoint inside = view_->widgetFromImage(Vec2(400, 26)).toPoint();
  QVERIFY(view_->markAt(inside) == (MarkRef{MarkKind::Light, 2}));
  QTest::mouseClick(view_, Qt::LeftButton, Qt::NoModifier, inside);
  QVERIFY(doc_->selectedMark() == (MarkRef{MarkKind::Light, 2}));
  QCOMPARE(doc_->selectedObject(), -1);
  QCOMPARE(window_->sceneDock()->tree()->currentItem()->text(0), QStringLiteral("Light 3"));
  window_->deleteSelected();
  QCOMPARE(int(doc_->scene().lights.size()), 2);
  QVERIFY(!doc_->selectedMark());
  doc_->undoStack()->undo();
  QCOMPARE(int(doc_->scene().lights.size()), 3);
  // A click on nothing deselects.
  QTest::mouseClick(view_, Qt::LeftButton, Qt::NoModifier,
                    view_->widgetFromImage(Vec2(250, 200)).toPoint());
  QVERIFY(!doc_->selectedMark());

  // Delete light 1 from the scene tree: undoable.
  QTreeWidget* tree = window_->sceneDock()->tree();
  QTreeWidgetItem* light1 = nullptr;
  for (QTreeWidgetItemIterator it(tree); *it; ++it)
    if ((*it)->text(0) == QStringLiteral("Light 1")) light1 = *it;
  QVERIFY(light1);
  tree->setCurrentItem(light1);
  QVERIFY(doc_->selectedMark() == (MarkRef{MarkKind::Light, 0}));
  const std::vector<Vec2> second = doc_->scene().lights[1].pointsPx;
  window_->deleteSelected();
  QCOMPARE(int(doc_->scene().lights.size()), 2);
  QVERIFY(doc_->scene().lights[0].pointsPx == second);
  doc_->undoStack()->undo();
  QCOMPARE(int(doc_->scene().lights.size()), 3);
}

void StudioToolsTest::undoingAnObjectEditWhilePreparing() {
  const Vec2 base0 = doc_->scene().objects[0].basePx;
  QVERIFY(doc_->moveObject(0, base0 + Vec2(-30, 4)));
  QVERIFY(doc_->addLight({{380, 20}, {420, 22}, {420, 32}, {380, 30}}));
  QCOMPARE(doc_->state(), Document::State::Preparing);
  doc_->undoStack()->undo();  // the light (re-prepares)
  QCOMPARE(doc_->state(), Document::State::Preparing);
  doc_->undoStack()->undo();  // the move, with nothing prepared
  QVERIFY(doc_->scene().objects[0].basePx == base0);
  QVERIFY(doc_->undoStack()->isClean());
  waitPrepared(doc_);
  QVERIFY2(doc_->isReady(), qPrintable(doc_->prepareError()));
  // The prepared scene is of the undone document.
  const Placement& pl = doc_->prepared()->placements[0];
  QVERIFY((*doc_->prepared()->camera.project(pl.baseWorld) - base0).norm() < 1e-3);
  doc_->undoStack()->redo();
  doc_->undoStack()->redo();
  QCOMPARE(int(doc_->scene().lights.size()), 3);
  QVERIFY(doc_->scene().objects[0].basePx == base0 + Vec2(-30, 4));
  waitPrepared(doc_);
  QVERIFY(doc_->isReady());
  QVERIFY((*doc_->prepared()->camera.project(doc_->prepared()->placements[0].baseWorld) -
           (base0 + Vec2(-30, 4)))
              .norm() < 1e-3);
}

void StudioToolsTest::zoomAndPanKeepTheImageUnderTheCursor() {
  const QPoint at(view_->width() / 3, view_->height() / 2);
  const Vec2 under = view_->imageFromWidget(at);
  const double zoom0 = view_->zoom();
  QWheelEvent wheel(at, view_->mapToGlobal(at), QPoint(), QPoint(0, 240), Qt::NoButton, Qt::NoModifier,
                    Qt::NoScrollPhase, false);
  QCoreApplication::sendEvent(view_, &wheel);
  QVERIFY(view_->zoom() > zoom0 * 1.2);
  QVERIFY((view_->imageFromWidget(at) - under).norm() < 1e-6);
  // Middle drag pans by the drag.
  const QPointF before = view_->widgetFromImage(Vec2(100, 100));
  QTest::mousePress(view_, Qt::MiddleButton, Qt::NoModifier, at);
  QTest::mouseMove(view_, at + QPoint(40, -25));
  QTest::mouseRelease(view_, Qt::MiddleButton, Qt::NoModifier, at + QPoint(40, -25));
  const QPointF moved = view_->widgetFromImage(Vec2(100, 100)) - before;
  QVERIFY(std::abs(moved.x() - 40) < 1e-6 && std::abs(moved.y() + 25) < 1e-6);
  view_->zoomToFit();
  QVERIFY(std::abs(view_->zoom() - zoom0) < 1e-9);
}

// The same size and RGB values (alpha and colour space aside).
static bool samePixels(const QImage& a, const QImage& b) {
  if (a.size() != b.size()) return false;
  const QImage x = a.convertToFormat(QImage::Format_RGB32), y = b.convertToFormat(QImage::Format_RGB32);
  for (int row = 0; row < x.height(); ++row)
    for (int col = 0; col < x.width(); ++col)
      if (qRed(x.pixel(col, row)) != qRed(y.pixel(col, row)) ||
          qGreen(x.pixel(col, row)) != qGreen(y.pixel(col, row)) ||
          qBlue(x.pixel(col, row)) != qBlue(y.pixel(col, row)))
        return false;
  return true;
}

void StudioToolsTest::exportShownLayer() {
  QTemporaryDir dir;
  view_->setLayer(Layer::Albedo);
  const QString path = dir.filePath(QStringLiteral("albedo.png"));
  QVERIFY(window_->exportShownLayer(path));
  const QImage back(path);
  QCOMPARE(back.width(), doc_->prepared()->photo.linearRgb.width);
  // Code for code (the file is tagged sRGB, the shown image carries no colour space: compare pixels).
  QVERIFY(samePixels(back, window_->renderer()->layerImage(Layer::Albedo)));
  // TIFF too (written by image_io; Qt has no TIFF plugin here), read back code for code.
  const QString tif = dir.filePath(QStringLiteral("albedo.tif"));
  QVERIFY(window_->exportShownLayer(tif));
  const auto tifBack = loadImage(tif.toStdString());
  QVERIFY(tifBack.ok());
  QVERIFY(samePixels(srgb8FromLinear(tifBack->linearRgb), back));
  // A folder that does not exist: refused, nothing half-written.
  QVERIFY(!window_->exportShownLayer(dir.filePath(QStringLiteral("no/such/albedo.png"))));
}

void StudioToolsTest::exportSceneAsGltf() {
  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("room.gltf"));
  QVERIFY(window_->exportSceneGltf(path));
  QFile file(path);
  QVERIFY(file.open(QIODevice::ReadOnly));
  const QJsonObject root = QJsonDocument::fromJson(file.readAll()).object();
  QCOMPARE(root.value(QStringLiteral("asset")).toObject().value(QStringLiteral("version")).toString(),
           QStringLiteral("2.0"));
  QVERIFY(root.value(QStringLiteral("cameras")).toArray().size() == 1);
  // Room surfaces, lights as emissive quads, and the example's objects.
  QVERIFY(root.value(QStringLiteral("meshes")).toArray().size() >
          int(doc_->prepared()->renderScene.objects.size()));
  // A folder that does not exist: refused with a message, nothing written.
  QVERIFY(!window_->exportSceneGltf(dir.filePath(QStringLiteral("no/such/room.gltf"))));
}

// The Log dock: after each preparation, every stage with its seconds or why the scene skipped it
// (the lines of inlay-cli --verbose), and why a preparation failed.
void StudioToolsTest::logListsEachPreparationsStages() {
  LogDock* log = window_->logDock();
  QVERIFY(log);
  const QString first = log->text();
  QVERIFY2(first.contains(QStringLiteral("Prepared the scene in")), qPrintable(first));
  for (const char* line : {"  photo: ", "  refine: ", "  shafts: skipped, no sun marked",
                           "  occluders: skipped, none marked", "  surfaces: skipped, none marked"})
    QVERIFY2(first.contains(QString::fromLatin1(line)), line);
  // An occluder: the next preparation's block runs its stage (or says why it failed).
  window_->toolAction(int(Viewport::Tool::Occluder))->trigger();
  dragImage(view_, Qt::LeftButton, Vec2(180, 320), Vec2(230, 330));
  dragImage(view_, Qt::RightButton, Vec2(300, 200), Vec2(360, 210));
  QCOMPARE(int(doc_->scene().occluders.size()), 1);
  waitPrepared(doc_);
  const QString added = log->text().mid(first.size());
  if (doc_->state() == Document::State::Failed)
    QVERIFY2(added.contains(QStringLiteral("could not be prepared")), qPrintable(added));
  else
    QVERIFY2(added.contains(QStringLiteral("  occluders: ")) &&
                 added.contains(QStringLiteral(" s (1 matte)")),
             qPrintable(added));
  // A picture of it for the docs (beside the test binary).
  log->raise();
  QTest::qWait(50);
  QDir dir(QCoreApplication::applicationDirPath());
  dir.mkpath(QStringLiteral("studio_tools_artifacts"));
  QVERIFY(window_->grab().save(dir.filePath(QStringLiteral("studio_tools_artifacts/log_dock.png"))));
}

// The preparation keeps a big photo's direct light at its working copy's size: the View menu's
// "Direct light" shows it at the photo's size, under the other layers' pixels (a picture of it
// beside the test binary).
void StudioToolsTest::directLightOfABigPhotoAtThePhotosSize() {
  QTemporaryDir dir;
  const QString scene = enlargedExample(dir);
  QVERIFY(!scene.isEmpty());
  openPrepared(scene);
  if (QTest::currentTestFailed()) return;
  const PreparedScene* prepared = doc_->prepared();
  QCOMPARE(prepared->photo.linearRgb.width, 1024);
  QVERIFY(prepared->lighting.direct.width < 1024);  // the working copy's
  view_->setLayer(Layer::DirectLight);
  const QImage direct = window_->renderer()->layerImage(Layer::DirectLight);
  QCOMPARE(direct.size(), QSize(1024, 768));
  QCOMPARE(window_->renderer()->layerImage(Layer::Albedo).size(), direct.size());
  // Not black and not one flat colour: the lights' fall-off is there.
  const QImage grey = direct.convertToFormat(QImage::Format_Grayscale8);
  int lo = 255, hi = 0;
  for (int y = 0; y < grey.height(); y += 8)
    for (int x = 0; x < grey.width(); x += 8) {
      lo = std::min(lo, qGray(grey.pixel(x, y)));
      hi = std::max(hi, qGray(grey.pixel(x, y)));
    }
  QVERIFY2(hi - lo > 40, qPrintable(QStringLiteral("codes %1..%2").arg(lo).arg(hi)));
  QTest::qWait(50);
  QDir out(QCoreApplication::applicationDirPath());
  out.mkpath(QStringLiteral("studio_tools_artifacts"));
  QVERIFY(
      window_->grab().save(out.filePath(QStringLiteral("studio_tools_artifacts/direct_light_big.png"))));
}

QTEST_MAIN(StudioToolsTest)
#include "studio_tools_test.moc"
