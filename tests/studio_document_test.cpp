// The studio's non-visual parts with known answers: the sRGB conversion, the frame sink's
// version filter and hand-off, the document's undo merging, cancelling, and Save As path
// rewriting.
#include "document.h"
#include "frame_sink.h"
#include "image_convert.h"
#include "render_controller.h"

#include "inlay/engine/pipeline.h"
#include "inlay/modeling/scene_file.h"

#include <QDir>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <limits>

#include "studio_test_support.h"

using namespace inlay;
using inlay::test::waitMs;
using namespace inlay::studio;

namespace {

QString exampleDir() {
  const QString src = qEnvironmentVariable("INLAY_SOURCE_DIR");
  if (!src.isEmpty() && QFile::exists(src + QStringLiteral("/resources/example/scene.json")))
    return src + QStringLiteral("/resources/example");
  const std::string p = exampleScenePath();
  return p.empty() ? QString() : QFileInfo(QString::fromStdString(p)).absolutePath();
}

std::shared_ptr<RenderFrame> makeFrame(uint64_t version, const ImageF& with, const ImageF& without,
                                       float mask) {
  auto f = std::make_shared<RenderFrame>();
  f->sceneVersion = version;
  f->width = with.width;
  f->height = with.height;
  f->spp = 1;
  f->withObjects = with;
  f->withoutObjects = without;
  f->mask = ImageF(with.width, with.height, 1, mask);
  return f;
}

}  // namespace

class StudioDocumentTest : public QObject {
  Q_OBJECT

 private Q_SLOTS:
  void srgbEncodingHasKnownValues();
  void sinkDropsOldVersionsAndNotifiesOnce();
  void sinkCompositeOfUntouchedSceneIsThePhoto();
  void sinkShadowOnAClippedSunPatchIsTheRendersShadow();
  void dragMergesAndReturningIsObsolete();
  void cancelDropsTheResult();
  void saveAsRewritesRelativePaths();
  void rendererKeepsUpWithManyMoves();
  void sinkContextCompositesLikeTheFullScene();
  void insertAndDeleteAreUndoable();
  void markEditsValidateMergeAndRestartPreparation();
  void cameraResponseIsShownAndOneUndoStep();
};

void StudioDocumentTest::srgbEncodingHasKnownValues() {
  ImageF img(5, 1, 3);
  const float values[5] = {0.f, 0.0031308f, 0.5f, 1.f, 4.f};
  for (int x = 0; x < 5; ++x) img.setRgb(x, 0, Vec3::Constant(values[x]));
  const QImage q = srgb8FromLinear(img);
  QCOMPARE(q.size(), QSize(5, 1));
  QCOMPARE(qRed(q.pixel(0, 0)), 0);
  QCOMPARE(qRed(q.pixel(1, 0)), 10);   // 12.92 * 0.0031308 * 255 = 10.3
  QCOMPARE(qRed(q.pixel(2, 0)), 188);  // 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354
  QCOMPARE(qRed(q.pixel(3, 0)), 255);
  QCOMPARE(qRed(q.pixel(4, 0)), 255);  // clamped
  // One stop of exposure doubles the linear value: 0.25 -> 0.5.
  ImageF quarter(1, 1, 3, 0.25f);
  QCOMPARE(qGreen(srgb8FromLinear(quarter, 1.0).pixel(0, 0)), 188);
  // Every 8-bit code round-trips through linear.
  ImageF ramp(256, 1, 3);
  for (int x = 0; x < 256; ++x) ramp.setRgb(x, 0, Vec3::Constant(srgbToLinear(float(x) / 255.f)));
  const QImage r = srgb8FromLinear(ramp);
  for (int x = 0; x < 256; ++x) QCOMPARE(qBlue(r.pixel(x, 0)), x);
  // ... and back: linearFromSrgb8 gives every code's own linear value (layer export).
  QImage codes(256, 1, QImage::Format_RGB32);
  for (int x = 0; x < 256; ++x) codes.setPixel(x, 0, qRgb(x, 255 - x, x / 2));
  QCOMPARE(srgb8FromLinear(linearFromSrgb8(codes)), codes);
}

void StudioDocumentTest::sinkDropsOldVersionsAndNotifiesOnce() {
  int notified = 0;
  CompositeSink sink([&] { ++notified; });
  PreparedScene scene;
  scene.photo.linearRgb = ImageF(4, 3, 3, 0.2f);
  sink.setContext(CompositeSink::compositeContextOf(scene), 5);
  const ImageF a(4, 3, 3, 0.2f);

  sink.onFrame(makeFrame(4, a, a, 0.f));  // older than the GUI asked for
  QCOMPARE(notified, 0);
  QVERIFY(!sink.take());

  sink.onFrame(makeFrame(5, a, a, 0.f));
  sink.onFrame(makeFrame(6, a, a, 0.f));  // not yet taken: replaces, no second post
  QCOMPARE(notified, 1);
  const std::optional<CompositeImage> got = sink.take();
  QVERIFY(got);
  QCOMPARE(got->sceneVersion, uint64_t(6));
  QVERIFY(!sink.take());

  sink.setMinVersion(8);
  sink.setMinVersion(7);  // never lowers
  sink.onFrame(makeFrame(7, a, a, 0.f));
  QVERIFY(!sink.take());
  ImageF wrongSize(2, 2, 3, 0.2f);
  sink.onFrame(makeFrame(9, wrongSize, wrongSize, 0.f));  // another scene's frame
  QVERIFY(!sink.take());
  QCOMPARE(notified, 1);
}

void StudioDocumentTest::sinkCompositeOfUntouchedSceneIsThePhoto() {
  CompositeSink sink([] {});
  PreparedScene scene;
  scene.photo.linearRgb = ImageF(8, 6, 3);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 8; ++x) scene.photo.linearRgb.setRgb(x, y, Vec3(x / 8.0, y / 6.0, 0.3));
  scene.doc.render.exposure = 0.5;
  sink.setContext(CompositeSink::compositeContextOf(scene), 1);
  // With and without objects equal, mask 0: the composite is the photo (times the exposure).
  const ImageF radiance(8, 6, 3, 0.7f);
  sink.onFrame(makeFrame(1, radiance, radiance, 0.f));
  const std::optional<CompositeImage> got = sink.take();
  QVERIFY(got);
  QCOMPARE(got->srgb8, srgb8FromLinear(scene.photo.linearRgb, 0.5));
  // A bright object covering everything (mask 1) shows the object instead.
  const ImageF white(8, 6, 3, 1.f);
  sink.onFrame(makeFrame(2, white, radiance, 1.f));
  const std::optional<CompositeImage> obj = sink.take();
  QVERIFY(obj);
  QCOMPARE(qRed(obj->srgb8.pixel(0, 0)), 255);
}

// A sun's patch clips in the photo (1.0, its radiance 6): an object's shadow there is the
// render's shadow (0.4) in the live frames as in the final render, not clip + 0.4 - 6 (black).
// The composite context carries the room's unclipped radiance only for a scene with a sun.
void StudioDocumentTest::sinkShadowOnAClippedSunPatchIsTheRendersShadow() {
  PreparedScene scene;
  scene.photo.linearRgb = ImageF(4, 3, 3, 1.f);
  scene.renderScene.roomAlbedo.photoRadiance = ImageF(4, 3, 3, 6.f);
  QVERIFY(CompositeSink::compositeContextOf(scene)->renderScene.roomAlbedo.photoRadiance.empty());
  scene.renderScene.suns.push_back(SunLight{});
  CompositeSink sink([] {});
  sink.setContext(CompositeSink::compositeContextOf(scene), 1);
  sink.onFrame(makeFrame(1, ImageF(4, 3, 3, 0.4f), ImageF(4, 3, 3, 6.f), 0.f));
  const std::optional<CompositeImage> got = sink.take();
  QVERIFY(got);
  QCOMPARE(got->linear->at(2, 1, 0), 0.4f);
  QCOMPARE(got->linear->at(2, 1, 2), 0.4f);
}

// The sink encodes the composite through the photo's camera response (untouched pixels show the
// photo's own codes), and choosing a response is one undo step that prepares again.
void StudioDocumentTest::cameraResponseIsShownAndOneUndoStep() {
  CompositeSink sink([] {});
  PreparedScene scene;
  scene.response = CameraResponse::toeShoulder({0.7, 0.3, 20});
  scene.photo.linearRgb = ImageF(8, 6, 3);
  for (size_t i = 0; i < scene.photo.linearRgb.data.size(); ++i)
    scene.photo.linearRgb.data[i] = scene.response.table8()[(i * 41) % 256];
  sink.setContext(CompositeSink::compositeContextOf(scene), 1);
  const ImageF radiance(8, 6, 3, 0.7f);
  sink.onFrame(makeFrame(1, radiance, radiance, 0.f));
  const std::optional<CompositeImage> got = sink.take();
  QVERIFY(got);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 8; ++x) {
      const size_t i = (size_t(y) * 8 + size_t(x)) * 3;
      QCOMPARE(qRed(got->srgb8.pixel(x, y)), int((i * 41) % 256));
      QCOMPARE(qBlue(got->srgb8.pixel(x, y)), int(((i + 2) * 41) % 256));
    }

  const QString dir = exampleDir();
  if (dir.isEmpty()) QSKIP("resources/example absent");
  Document doc;
  doc.newFromPhoto(dir + QStringLiteral("/photo.png"));
  QTRY_VERIFY_WITH_TIMEOUT(doc.state() != Document::State::Preparing, waitMs(120000));
  QVERIFY2(doc.isReady(), qPrintable(doc.prepareError()));
  doc.undoStack()->clear();
  QString reason;
  QVERIFY2(doc.setCameraResponse({ResponseKeys::Mode::Linear}, &reason), qPrintable(reason));
  QCOMPARE(doc.scene().camera.response.mode, ResponseKeys::Mode::Linear);
  QCOMPARE(doc.undoStack()->count(), 1);
  QTRY_VERIFY_WITH_TIMEOUT(doc.state() != Document::State::Preparing, waitMs(120000));
  QVERIFY(doc.prepared() && doc.prepared()->response == CameraResponse::linear());
  doc.undoStack()->undo();
  QCOMPARE(doc.scene().camera.response.mode, ResponseKeys::Mode::Auto);
}

void StudioDocumentTest::dragMergesAndReturningIsObsolete() {
  const QString dir = exampleDir();
  if (dir.isEmpty()) QSKIP("resources/example absent");
  Document doc;
  QString error;
  QVERIFY2(doc.openSceneFile(dir + QStringLiteral("/scene.json"), &error), qPrintable(error));
  QString reason;
  // While preparing, the document takes the move at once; the prepared scene catches up, and
  // a place where the object cannot stand fails the preparation naming the object.
  const Vec2 opened = doc.scene().objects[0].basePx;
  QVERIFY(doc.moveObject(0, Vec2(1, 1), 0, &reason));
  QVERIFY(doc.scene().objects[0].basePx == Vec2(1, 1));
  QTRY_VERIFY_WITH_TIMEOUT(doc.state() != Document::State::Preparing, waitMs(60000));
  QCOMPARE(doc.state(), Document::State::Failed);
  QVERIFY2(doc.prepareError().contains(QStringLiteral("objects[0]")), qPrintable(doc.prepareError()));
  doc.undoStack()->undo();
  QVERIFY(doc.scene().objects[0].basePx == opened);
  QTRY_VERIFY_WITH_TIMEOUT(doc.state() != Document::State::Preparing, waitMs(60000));
  QVERIFY2(doc.isReady(), qPrintable(doc.prepareError()));
  doc.undoStack()->clear();

  QSignalSpy changes(&doc, &Document::changed);
  const Vec2 start = doc.scene().objects[0].basePx;
  const int drag1 = Document::newDragId();
  for (int k = 1; k <= 5; ++k) QVERIFY(doc.moveObject(0, start + Vec2(-4.0 * k, -1.0 * k), drag1));
  QCOMPARE(doc.undoStack()->count(), 1);
  QCOMPARE(changes.count(), 5);  // one change per applied move
  QVERIFY(doc.scene().objects[0].basePx == start + Vec2(-20, -5));

  // A second drag is its own step, even of the same object.
  const int drag2 = Document::newDragId();
  QVERIFY(doc.moveObject(0, start + Vec2(-30, -5), drag2));
  QCOMPARE(doc.undoStack()->count(), 2);
  // Back to where that drag began: the step disappears.
  QVERIFY(doc.moveObject(0, start + Vec2(-20, -5), drag2));
  QCOMPARE(doc.undoStack()->count(), 1);

  // A move off every supporting surface changes nothing.
  QVERIFY(!doc.moveObject(0, Vec2(256, 5), drag2, &reason));
  QVERIFY(reason.contains(QStringLiteral("objects[0]")));
  QVERIFY(doc.scene().objects[0].basePx == start + Vec2(-20, -5));
  QVERIFY(!doc.setObjectHeight(0, -1.0, &reason));
  QVERIFY(!doc.moveObject(3, start, 0, &reason));

  doc.undoStack()->undo();
  QVERIFY(doc.scene().objects[0].basePx == start);
  QVERIFY(doc.undoStack()->isClean());
}

void StudioDocumentTest::markEditsValidateMergeAndRestartPreparation() {
  const QString dir = exampleDir();
  if (dir.isEmpty()) QSKIP("resources/example absent");
  Document doc;
  QString reason;
  // Nothing open: every mark edit is refused with a reason.
  QVERIFY(!doc.addLight({{1, 1}, {20, 1}, {20, 20}}, &reason));
  QVERIFY(!reason.isEmpty());
  QVERIFY(!doc.acceptEstimatedBox(&reason));

  doc.newFromPhoto(dir + QStringLiteral("/photo.png"));
  QTRY_VERIFY_WITH_TIMEOUT(doc.state() != Document::State::Preparing, waitMs(120000));
  QVERIFY2(doc.isReady(), qPrintable(doc.prepareError()));
  QVERIFY(!doc.backWallIsUsers());
  const std::array<Vec2, 4> estimated = *doc.shownBackWallPx();
  QVERIFY(doc.lastEstimate() != nullptr);

  // One drag of a corner: one undo step; each move restarts preparation, only the last job's
  // result is kept.
  QSignalSpy changes(&doc, &Document::changed);
  const int drag = Document::newDragId();
  for (int k = 1; k <= 4; ++k)
    QVERIFY(doc.setBackWallCorner(1, estimated[1] + Vec2(-2.0 * k, 1.0 * k), drag, &reason));
  QCOMPARE(doc.undoStack()->count(), 1);
  QVERIFY(doc.backWallIsUsers());
  QCOMPARE(doc.state(), Document::State::Preparing);
  int marks = 0, started = 0;
  for (const QList<QVariant>& c : changes) {
    const auto e = c.at(0).value<ChangeEvent>();
    marks += e.has(ChangeEvent::Marks);
    started += e.has(ChangeEvent::PrepareStarted);
  }
  QCOMPARE(marks, 4);
  QCOMPARE(started, 4);
  // The other corners kept the estimate's place.
  QVERIFY((*doc.scene().layout.backWallPx)[0] == estimated[0]);
  QVERIFY((*doc.scene().layout.backWallPx)[1] == estimated[1] + Vec2(-8, 4));
  QTRY_VERIFY_WITH_TIMEOUT(doc.state() != Document::State::Preparing, waitMs(120000));
  QVERIFY2(doc.isReady(), qPrintable(doc.prepareError()));
  QVERIFY(doc.prepared()->backWallPx == *doc.scene().layout.backWallPx);
  // Back to where the drag began within the same drag: still one step, for the corners became
  // the user's (the estimate, now kept); a second drag that returns leaves no step of its own.
  QVERIFY(doc.setBackWallCorner(1, estimated[1], drag));
  QCOMPARE(doc.undoStack()->count(), 1);
  QVERIFY(*doc.scene().layout.backWallPx == estimated);
  const int drag2 = Document::newDragId();
  QVERIFY(doc.setBackWallCorner(2, estimated[2] + Vec2(3, 3), drag2));
  QVERIFY(doc.setBackWallCorner(2, estimated[2], drag2));
  QCOMPARE(doc.undoStack()->count(), 1);
  doc.undoStack()->undo();
  QVERIFY(!doc.backWallIsUsers());
  QCOMPARE(doc.undoStack()->count(), 1);  // undone, not gone (redo is possible)
  QVERIFY(doc.undoStack()->isClean());

  // Bad input: refused, nothing pushed.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  QVERIFY(!doc.setBackWallCorner(4, Vec2(1, 1), 0, &reason));
  QVERIFY(!doc.setBackWallCorner(0, Vec2(nan, 1), 0, &reason));
  QVERIFY(!doc.addLight({{1, 1}, {20, 1}}, &reason));             // two points
  QVERIFY(!doc.addLight({{1, 1}, {20, 1}, {40, 1}}, &reason));    // no area
  QVERIFY(!doc.addLight({{1, 1}, {20, 1}, {nan, 20}}, &reason));  // NaN
  QVERIFY(!doc.addExtrusion({{1, 1}, {20, 1}}, Vec2(1, 30), &reason));
  QVERIFY(!doc.addShaft({10, 10, 10.5, 40}, {0, 0, 20, 20}, &reason));  // too thin
  QVERIFY(!doc.addOccluder(OccluderKeys{{{{5, 5}}}, {}}, &reason));     // no background stroke
  QVERIFY(!doc.addOccluderStroke(0, true, {{5, 5}}, &reason));          // no occluder 0
  QVERIFY(!doc.removeMark(MarkKind::Light, 0, &reason));
  QCOMPARE(doc.undoStack()->index(), 0);

  // Accept, then reset: the estimate comes back.
  QVERIFY(doc.acceptEstimatedBox(&reason));
  QVERIFY(*doc.scene().layout.backWallPx == estimated);
  QVERIFY(doc.resetBackWall(&reason));
  QVERIFY(!doc.backWallIsUsers());
  QCOMPARE(doc.undoStack()->count(), 2);  // the undone drag was dropped by the new pushes
  doc.undoStack()->undo();
  doc.undoStack()->undo();
  QVERIFY(doc.undoStack()->isClean());
  QVERIFY(!doc.scene().layout.backWallPx);
}

void StudioDocumentTest::cancelDropsTheResult() {
  const QString dir = exampleDir();
  if (dir.isEmpty()) QSKIP("resources/example absent");
  Document doc;
  QString error;
  QVERIFY(doc.openSceneFile(dir + QStringLiteral("/scene.json"), &error));
  QCOMPARE(doc.state(), Document::State::Preparing);
  doc.cancelPrepare();
  QCOMPARE(doc.state(), Document::State::Empty);
  QVERIFY(!doc.prepareError().isEmpty());
  QTest::qWait(waitMs(1500));  // whatever the worker still delivers is dropped
  QCOMPARE(doc.state(), Document::State::Empty);
  QVERIFY(!doc.prepared());
  // Prepared again on request.
  doc.prepare();
  QTRY_VERIFY_WITH_TIMEOUT(doc.state() != Document::State::Preparing, waitMs(60000));
  QVERIFY(doc.isReady());
}

void StudioDocumentTest::saveAsRewritesRelativePaths() {
  const QString dir = exampleDir();
  if (dir.isEmpty()) QSKIP("resources/example absent");
  QTemporaryDir tmp;
  QVERIFY(QFile::copy(dir + QStringLiteral("/scene.json"), tmp.filePath(QStringLiteral("scene.json"))));
  QVERIFY(QFile::copy(dir + QStringLiteral("/photo.png"), tmp.filePath(QStringLiteral("photo.png"))));
  QVERIFY(QDir(tmp.path()).mkdir(QStringLiteral("sub")));

  Document doc;
  QString error;
  QVERIFY(doc.openSceneFile(tmp.filePath(QStringLiteral("scene.json")), &error));
  doc.cancelPrepare();  // saving needs no prepared scene
  const std::string photo = doc.scene().photoResolved;

  // Beside the photo: stays relative.
  QVERIFY2(doc.saveAs(tmp.filePath(QStringLiteral("copy.json")), &error), qPrintable(error));
  QCOMPARE(QString::fromStdString(doc.scene().photo), QStringLiteral("photo.png"));
  // In a subfolder: the photo is outside it, so the path becomes absolute.
  const QString deeper = tmp.filePath(QStringLiteral("sub/deeper.json"));
  QVERIFY(doc.saveAs(deeper, &error));
  QCOMPARE(doc.filePath(), QFileInfo(deeper).absoluteFilePath());
  QVERIFY(QFileInfo(QString::fromStdString(doc.scene().photo)).isAbsolute());
  const Expected<SceneLoadResult> back = loadSceneFile(deeper.toStdString());
  QVERIFY(back.ok());
  QCOMPARE(QString::fromStdString(back->doc.photoResolved), QString::fromStdString(photo));
  QCOMPARE(QString::fromStdString(sceneToJson(back->doc)),
           QString::fromStdString(sceneToJson(doc.scene())));

  // A folder that cannot be written: an error, and the document keeps its file.
  QVERIFY(!doc.saveAs(QStringLiteral("/proc/inlay-no/x.json"), &error));
  QVERIFY(!error.isEmpty());
  QCOMPARE(doc.filePath(), QFileInfo(deeper).absoluteFilePath());
}

void StudioDocumentTest::rendererKeepsUpWithManyMoves() {
  const QString dir = exampleDir();
  if (dir.isEmpty()) QSKIP("resources/example absent");
  Document doc;
  RenderController renderer(&doc);
  QString error;
  QVERIFY(doc.openSceneFile(dir + QStringLiteral("/scene.json"), &error));
  QTRY_VERIFY_WITH_TIMEOUT(doc.state() != Document::State::Preparing, waitMs(60000));
  QVERIFY(doc.isReady());
  QTRY_VERIFY_WITH_TIMEOUT(renderer.hasFrame(), waitMs(30000));
  QVERIFY(!renderer.photoImage().isNull());
  QCOMPARE(renderer.compositeImage().size(), renderer.photoImage().size());

  // A fast drag: every move restarts the render; stale frames never replace newer ones.
  const Vec2 start = doc.scene().objects[0].basePx;
  const int dragId = Document::newDragId();
  quint64 lastShown = 0;
  connect(&renderer, &RenderController::frameUpdated, this, [&] {
    QVERIFY(renderer.frameInfo().sceneVersion >= lastShown);
    lastShown = renderer.frameInfo().sceneVersion;
  });
  for (int k = 1; k <= 200; ++k) {
    QVERIFY(doc.moveObject(0, start + Vec2(-0.3 * k, -0.05 * k), dragId));
    if (k % 10 == 0) QCoreApplication::processEvents();
  }
  QCOMPARE(doc.undoStack()->count(), 1);
  const quint64 wanted = renderer.requestedVersion();
  QTRY_VERIFY_WITH_TIMEOUT(renderer.isCurrent(), waitMs(30000));
  QCOMPARE(quint64(renderer.frameInfo().sceneVersion), wanted);
  doc.undoStack()->undo();
  QTRY_VERIFY_WITH_TIMEOUT(renderer.isCurrent() && renderer.requestedVersion() > wanted, waitMs(30000));
}

// The sink composites with a slim copy of the prepared scene; it must give what compositeOf
// gives with the whole one (this fails if compositeOf starts reading something not copied).
void StudioDocumentTest::sinkContextCompositesLikeTheFullScene() {
  const QString dir = exampleDir();
  if (dir.isEmpty()) QSKIP("resources/example absent");
  Expected<SceneLoadResult> loaded = loadSceneFile((dir + QStringLiteral("/scene.json")).toStdString());
  QVERIFY(loaded.ok());
  loaded->doc.render.exposure = 0.7;
  const Expected<PreparedScene> full = prepareScene(loaded->doc);
  QVERIFY2(full.ok(), full.ok() ? "" : full.error().message().c_str());
  const int w = full->photo.linearRgb.width, h = full->photo.linearRgb.height;
  ImageF with(w, h, 3), without(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      with.setRgb(x, y, Vec3(0.001 * x, 0.002 * y, 0.5));
      without.setRgb(x, y, Vec3(0.3, 0.001 * (x + y), 0.25));
    }
  auto frame = makeFrame(1, with, without, 0.f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) frame->mask.at(x, y) = float((x * 7 + y * 3) % 11) / 10.f;
  const ImageF expected = compositeOf(*full, *frame);
  const ImageF got = compositeOf(*CompositeSink::compositeContextOf(*full), *frame);
  QCOMPARE(got.width, expected.width);
  QCOMPARE(got.height, expected.height);
  QVERIFY(got.data == expected.data);
}

void StudioDocumentTest::insertAndDeleteAreUndoable() {
  const QString dir = exampleDir();
  if (dir.isEmpty()) QSKIP("resources/example absent");
  Document doc;
  RenderController renderer(&doc);
  QString error;
  QVERIFY(doc.openSceneFile(dir + QStringLiteral("/scene.json"), &error));
  QTRY_VERIFY_WITH_TIMEOUT(doc.state() != Document::State::Preparing, waitMs(60000));
  QVERIFY(doc.isReady());
  const ObjectKeys sphere = doc.scene().objects[0];

  const std::optional<Vec2> at = doc.freeStandingPointPx();
  QVERIFY(at);
  ObjectKeys cube;
  cube.mesh = "builtin:cube";
  cube.basePx = *at;
  cube.heightM = 0.4;
  QVERIFY(doc.insertObject(cube));
  QCOMPARE(doc.objectCount(), 2);
  QCOMPARE(doc.selectedObject(), 1);
  QCOMPARE(doc.prepared()->renderScene.objects.size(), size_t(2));
  QCOMPARE(doc.prepared()->placements.size(), size_t(2));
  QTRY_VERIFY_WITH_TIMEOUT(renderer.isCurrent(), waitMs(30000));

  QString reason;
  ObjectKeys unknown = cube;
  unknown.mesh = "builtin:teapot-that-is-not";
  QVERIFY(!doc.insertObject(unknown, &reason));
  QVERIFY(!reason.isEmpty());
  ObjectKeys onCeiling = cube;
  onCeiling.basePx = Vec2(256, 5);
  QVERIFY(!doc.insertObject(onCeiling, &reason));
  QCOMPARE(doc.objectCount(), 2);
  QCOMPARE(doc.undoStack()->count(), 1);

  QVERIFY(doc.removeObject(0));
  QCOMPARE(doc.objectCount(), 1);
  QCOMPARE(QString::fromStdString(doc.scene().objects[0].mesh), QStringLiteral("builtin:cube"));
  QVERIFY(doc.moveObject(0, *at + Vec2(-15, 0)));  // indices of what is left are consistent
  const std::optional<Vec2> reprojected =
      doc.prepared()->camera.project(doc.prepared()->placements[0].baseWorld);
  QVERIFY(reprojected && (*reprojected - (*at + Vec2(-15, 0))).norm() < 1e-3);
  doc.undoStack()->undo();  // the move
  doc.undoStack()->undo();  // the delete: the sphere is back where it was, in its place
  QCOMPARE(doc.objectCount(), 2);
  QVERIFY(doc.scene().objects[0].basePx == sphere.basePx);
  QCOMPARE(QString::fromStdString(doc.scene().objects[0].mesh), QStringLiteral("builtin:sphere"));
  QVERIFY(doc.scene().objects[1].basePx == *at);
  doc.undoStack()->undo();  // the insert
  QCOMPARE(doc.objectCount(), 1);
  QVERIFY(doc.undoStack()->isClean());
  QTRY_VERIFY_WITH_TIMEOUT(renderer.isCurrent(), waitMs(30000));
  doc.undoStack()->redo();
  doc.undoStack()->redo();
  QCOMPARE(doc.objectCount(), 1);
  QCOMPARE(QString::fromStdString(doc.scene().objects[0].mesh), QStringLiteral("builtin:cube"));
  QVERIFY(!doc.removeObject(5, &reason));
}

QTEST_GUILESS_MAIN(StudioDocumentTest)
#include "studio_document_test.moc"
