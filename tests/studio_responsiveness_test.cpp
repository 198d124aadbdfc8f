// Issue #17's "first updated frame after any arranging gesture", the mechanism (the times are
// bench_gestures'), offscreen on the bundled example:
//   - a move is an instance update: the preview's tracer is not made again, and the first frame
//     delivered after it already shows the sphere at its new place and not at its old one;
//   - edits that keep the meshes (material, hide and show, duplicate, delete, undo) make a new
//     tracer that builds no object BVH again; a rename restarts nothing;
//   - a burst of edits (no wait between them, each cancelling the wave under way) never shows a
//     frame older than the newest edit asked for, and ends on a frame of the last one.
#include "document.h"
#include "main_window.h"
#include "render_controller.h"
#include "studio_test_support.h"

#include "inlay/engine/pipeline.h"
#include "inlay/render/path_tracer.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QUndoStack>
#include <QtTest>

using namespace inlay;
using namespace inlay::studio;
using inlay::test::waitMs;

namespace {

// Mean of |a - b| over the three 8-bit channels in the box [x0, x1) x [y0, y1).
double meanDiff(const QImage& a, const QImage& b, int x0, int y0, int x1, int y1) {
  double sum = 0;
  int n = 0;
  for (int y = std::max(0, y0); y < std::min(a.height(), y1); ++y)
    for (int x = std::max(0, x0); x < std::min(a.width(), x1); ++x, ++n) {
      const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
      sum += std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q)) +
             std::abs(qBlue(p) - qBlue(q));
    }
  return n ? sum / n : 0.0;
}

// Where the sphere's body is drawn above its base pixel: a box clear of its shadow on the floor.
struct Body {
  int x0, y0, x1, y1;
};
Body bodyAbove(const Vec2& base) {
  return {int(base.x()) - 14, int(base.y()) - 50, int(base.x()) + 14, int(base.y()) - 12};
}

// Every frame the controller shows, with the newest version requested when it was shown.
struct FrameLog {
  struct Entry {
    quint64 requested = 0, shown = 0;
    int divider = 1;
    QImage image;
  };
  std::vector<Entry> entries;
  QMetaObject::Connection connection;
  ~FrameLog() { QObject::disconnect(connection); }
  void attach(RenderController* r) {
    connection = QObject::connect(r, &RenderController::frameUpdated, r, [this, r] {
      if (r->hasFrame())
        entries.push_back({r->requestedVersion(), r->frameInfo().sceneVersion,
                           r->frameInfo().resolutionDivider, r->compositeImage()});
    });
  }
  // The first frame of version `v` or later, or null.
  const Entry* firstOf(quint64 v) const {
    for (const Entry& e : entries)
      if (e.shown >= v) return &e;
    return nullptr;
  }
};

}  // namespace

class StudioResponsivenessTest : public QObject {
  Q_OBJECT

 private Q_SLOTS:
  // One window for the whole test (the example is prepared once); each function leaves the
  // sphere where the next can move it.
  void initTestCase();
  void cleanupTestCase() { window_.reset(); }
  void moveIsAnInstanceUpdateAndItsFirstFrameShowsIt();
  void editsKeepTheObjectBvhs();
  void aBurstOfEditsShowsNoStaleFrame();

 private:
  // Waits (processing events) until the shown composite is of the newest request.
  bool waitCurrent() {
    RenderController* r = window_->renderer();
    QElapsedTimer t;
    t.start();
    while (!r->isCurrent() && t.elapsed() < waitMs(60000)) QTest::qWait(5);
    return r->isCurrent();
  }
  std::unique_ptr<MainWindow> window_;
};

void StudioResponsivenessTest::initTestCase() {
  const QString example = inlay::test::exampleScene();
  if (example.isEmpty() || !QFile::exists(example)) QSKIP("resources/example/scene.json absent");
  window_ = inlay::test::openStudio(example);
  QVERIFY(window_);
  Document* doc = window_->document();
  QTRY_VERIFY_WITH_TIMEOUT(doc->state() != Document::State::Preparing, waitMs(180000));
  QVERIFY2(doc->isReady(), qPrintable(doc->prepareError()));
  QVERIFY(waitCurrent());
}

void StudioResponsivenessTest::moveIsAnInstanceUpdateAndItsFirstFrameShowsIt() {
  Document* doc = window_->document();
  RenderController* r = window_->renderer();
  // Let the preview refine a little, so the move cancels a wave under way.
  QTRY_VERIFY_WITH_TIMEOUT(r->frameInfo().spp >= 1, waitMs(60000));
  const QImage photo = r->photoImage().convertToFormat(QImage::Format_RGB32);
  const QImage before = r->compositeImage().convertToFormat(QImage::Format_RGB32);
  const Vec2 home = doc->scene().objects[0].basePx, away = home + Vec2(-70, 0);
  const Body oldBody = bodyAbove(home), newBody = bodyAbove(away);
  const double shownBefore = meanDiff(before, photo, oldBody.x0, oldBody.y0, oldBody.x1, oldBody.y1);
  QVERIFY2(shownBefore > 20, qPrintable(QString::number(shownBefore)));

  const uint64_t tracers = r->tracerBuilds(), bvhs = PathTracer::objectBvhBuilds();
  FrameLog log;
  log.attach(r);
  QVERIFY(doc->moveObject(0, away, Document::newDragId()));
  const quint64 v = r->requestedVersion();
  QVERIFY(waitCurrent());
  const FrameLog::Entry* first = log.firstOf(v);
  QVERIFY(first);
  for (const FrameLog::Entry& e : log.entries)
    QVERIFY2(e.shown >= v, "a frame older than the move was shown");
  const QImage img = first->image.convertToFormat(QImage::Format_RGB32);
  const double oldPlace = meanDiff(img, photo, oldBody.x0, oldBody.y0, oldBody.x1, oldBody.y1);
  const double newPlace = meanDiff(img, photo, newBody.x0, newBody.y0, newBody.x1, newBody.y1);
  qInfo("first frame after the move (1/%d resolution): old place %.1f, new place %.1f (before %.1f)",
        first->divider, oldPlace, newPlace, shownBefore);
  QVERIFY2(newPlace > 0.5 * shownBefore, "the first frame does not show the sphere at its new place");
  QVERIFY2(oldPlace < 0.3 * shownBefore, "the first frame still shows the sphere at its old place");
  QCOMPARE(r->tracerBuilds(), tracers);
  QCOMPARE(PathTracer::objectBvhBuilds(), bvhs);
}

void StudioResponsivenessTest::editsKeepTheObjectBvhs() {
  Document* doc = window_->document();
  RenderController* r = window_->renderer();
  const uint64_t bvhs = PathTracer::objectBvhBuilds();
  const uint64_t tracers = r->tracerBuilds();
  QVERIFY(tracers >= 1);
  // Each edit: a new scene version whose first frame comes, from a new tracer.
  auto edit = [&](const char* what, const std::function<bool()>& apply) {
    const quint64 before = r->requestedVersion();
    const uint64_t made = r->tracerBuilds();
    QVERIFY2(apply(), what);
    QVERIFY2(r->requestedVersion() > before, what);
    QVERIFY(waitCurrent());
    QVERIFY2(r->tracerBuilds() == made + 1, what);
  };
  MaterialKeys red;
  red.albedo = Vec3(0.8, 0.1, 0.1);
  edit("material", [&] { return doc->setMaterial(0, red); });
  edit("hide", [&] { return doc->setObjectHidden(0, true); });
  edit("show", [&] { return doc->setObjectHidden(0, false); });
  edit("duplicate", [&] { return doc->duplicateObject(0); });
  QCOMPARE(doc->objectCount(), 2);
  edit("delete", [&] { return doc->removeObject(1); });
  edit("undo", [&] {
    doc->undoStack()->undo();
    return doc->objectCount() == 2;
  });
  QCOMPARE(PathTracer::objectBvhBuilds(), bvhs);

  // A rename changes nothing the renderer sees: no new version, no new tracer.
  const quint64 version = r->requestedVersion();
  const uint64_t made = r->tracerBuilds();
  QVERIFY(doc->renameObject(0, QStringLiteral("ball")));
  QCOMPARE(r->requestedVersion(), version);
  QCOMPARE(r->tracerBuilds(), made);
}

void StudioResponsivenessTest::aBurstOfEditsShowsNoStaleFrame() {
  Document* doc = window_->document();
  RenderController* r = window_->renderer();
  const Vec2 home = doc->scene().objects[0].basePx;
  FrameLog log;
  log.attach(r);
  const int drag = Document::newDragId();
  for (int k = 1; k <= 12; ++k) {
    QVERIFY(doc->moveObject(0, home + Vec2(-5.0 * k, 0), drag));
    if (k % 4 == 0) {
      MaterialKeys m;
      m.albedo = Vec3(0.2 + 0.05 * k, 0.5, 0.5);
      QVERIFY(doc->setMaterial(0, m));
    }
    QCoreApplication::processEvents();  // frames may arrive between the edits
  }
  const quint64 last = r->requestedVersion();
  QVERIFY(waitCurrent());
  QVERIFY(log.firstOf(last));
  for (const FrameLog::Entry& e : log.entries)
    QVERIFY2(
        e.shown >= e.requested,
        qPrintable(
            QStringLiteral("version %1 shown after %2 was asked for").arg(e.shown).arg(e.requested)));
  QCOMPARE(r->frameInfo().sceneVersion, last);
}

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  StudioResponsivenessTest test;
  return QTest::qExec(&test, argc, argv);
}
#include "studio_responsiveness_test.moc"
