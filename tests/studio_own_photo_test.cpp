// A new user's first composite on a photo of their own: no scene file, only a real photograph
// (a corridor with ceiling panels from the York Urban set in ../shared, read where it lies).
// Drop the photo on the window, see the estimated box, accept it, outline the ceiling panel with
// the Light tool, insert a built-in object on the floor, let the composite reach a few samples
// and export it. Each step's time since the drop and a screenshot go to
// studio_own_photo_artifacts/ in the build tree (figures.csv, NN_step.png, the exported PNG).
#include "document.h"
#include "main_window.h"
#include "render_controller.h"
#include "viewport.h"

#include "inlay/engine/pipeline.h"

#include <QAction>
#include <QDropEvent>
#include <QFile>
#include <QImage>
#include <QMimeData>
#include <QSettings>
#include <QStandardPaths>
#include <QUrl>
#include <QtTest>

#include <cmath>

#include "studio_test_support.h"
#include "studio_workflow_steps.h"

using namespace inlay;
using namespace inlay::studio;
using inlay::test::StepLog;
using inlay::test::waitMs;

namespace {

// The photo, read from ../shared (INLAY_SHARED_DIR) at run time, never copied into the repository.
QString ownPhoto() {
  const QString shared = qEnvironmentVariable("INLAY_SHARED_DIR");
  const QString path = shared + QStringLiteral("/york/P1020833.jpg");
  if (shared.isEmpty() || !QFile::exists(path)) return {};
  return QFileInfo(path).absoluteFilePath();
}

// Drops one local file on the widget the way a file manager does (enter, then drop).
void dropFile(QWidget* on, const QString& path) {
  QMimeData data;
  data.setUrls({QUrl::fromLocalFile(path)});
  const QPoint at = on->rect().center();
  QDragEnterEvent enter(at, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
  QCoreApplication::sendEvent(on, &enter);
  QVERIFY(enter.isAccepted());
  QDropEvent drop(QPointF(at), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
  QCoreApplication::sendEvent(on, &drop);
  QVERIFY(drop.isAccepted());
}

// Mean absolute difference (0..255) of two images over a square of half-size r around c.
double meanDifference(const QImage& a, const QImage& b, const QPoint& c, int r) {
  double sum = 0;
  int n = 0;
  for (int y = c.y() - r; y <= c.y() + r; ++y)
    for (int x = c.x() - r; x <= c.x() + r; ++x) {
      const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
      sum += std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q)) +
             std::abs(qBlue(p) - qBlue(q));
      n += 3;
    }
  return sum / n;
}

}  // namespace

class StudioOwnPhotoTest : public QObject {
  Q_OBJECT

 private Q_SLOTS:
  void initTestCase();
  void firstCompositeOnOwnPhoto();
};

void StudioOwnPhotoTest::initTestCase() {
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName(QStringLiteral("InlayTest"));
  QCoreApplication::setApplicationName(QStringLiteral("studio_own_photo_test"));
  QSettings().clear();
}

void StudioOwnPhotoTest::firstCompositeOnOwnPhoto() {
  const QString photo = ownPhoto();
  if (photo.isEmpty()) QSKIP("skipped: ../shared/york not present (needs ../shared/york/P1020833.jpg)");

  StepLog log(QStringLiteral("studio_own_photo_artifacts"));
  MainWindow window;
  QVERIFY(inlay::test::showForWorkflow(window));
  Document* doc = window.document();
  Viewport* view = window.viewport();
  RenderController* renderer = window.renderer();
  log.restart();
  auto step = [&](const QString& name) { QVERIFY(log.step(&window, name)); };

  // --- 1. Drop the bare photo on the window: a new scene, the estimated box shown ---
  dropFile(&window, photo);
  QTRY_VERIFY_WITH_TIMEOUT(doc->scene().photoResolved == photo.toStdString(), waitMs(5000));
  QVERIFY(doc->filePath().isEmpty());  // no scene file yet
  QVERIFY2(inlay::test::waitReady(doc, waitMs(180000)), qPrintable(doc->prepareError()));
  QVERIFY(!doc->backWallIsUsers());
  QVERIFY(doc->shownBackWallPx().has_value());
  QVERIFY(view->showsVanishingLines());
  QVERIFY(doc->scene().lights.empty());
  QTRY_VERIFY_WITH_TIMEOUT(renderer->hasFrame(), waitMs(30000));
  step(QStringLiteral("estimate_shown"));

  // --- 2. Accept the estimated box ---
  const std::array<Vec2, 4> estimated = *doc->shownBackWallPx();
  QVERIFY(window.acceptBoxAction()->isEnabled());
  window.acceptBoxAction()->trigger();
  QVERIFY(doc->backWallIsUsers());
  QVERIFY(*doc->scene().layout.backWallPx == estimated);
  QVERIFY2(inlay::test::waitReady(doc, waitMs(180000)), qPrintable(doc->prepareError()));
  step(QStringLiteral("box_accepted"));

  // --- 3. Outline the middle ceiling panel with the Light tool (clicks, closed on the first) ---
  window.toolAction(int(Viewport::Tool::Light))->trigger();
  const Vec2 panel[4] = {{324, 49}, {398, 47}, {411, 92}, {339, 93}};
  for (const Vec2& q : panel)
    QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, view->widgetFromImage(q).toPoint());
  QTest::mouseClick(view, Qt::LeftButton, Qt::NoModifier, view->widgetFromImage(panel[0]).toPoint());
  QVERIFY(view->pendingPoints().empty());
  QCOMPARE(int(doc->scene().lights.size()), 1);
  QVERIFY2(inlay::test::waitReady(doc, waitMs(180000)), qPrintable(doc->prepareError()));
  QCOMPARE(int(doc->prepared()->lighting.lights.size()), 1);
  window.toolAction(int(Viewport::Tool::Select))->trigger();
  step(QStringLiteral("light_outlined"));

  // --- 4. Insert a built-in object: it stands on the floor ---
  QVERIFY(window.insertBuiltin(QStringLiteral("builtin:sphere")));
  QCOMPARE(doc->objectCount(), 1);
  QCOMPARE(int(doc->prepared()->placements.size()), 1);
  QVERIFY(std::abs(doc->prepared()->placements[0].baseWorld.y()) < 1e-6);
  step(QStringLiteral("object_inserted"));

  // --- 5. The composite reaches a few samples per pixel ---
  const int wantedSpp = 4;
  QTRY_VERIFY_WITH_TIMEOUT(renderer->isCurrent() && renderer->frameInfo().spp >= wantedSpp,
                           waitMs(120000));
  step(QStringLiteral("composite_rendered"));

  // --- 6. Export the composite (what File > Export Composite writes after its dialog) ---
  const QString exported = log.filePath(QStringLiteral("own_photo_composite.png"));
  QFile::remove(exported);
  QVERIFY(window.exportComposite(exported));
  QVERIFY(QFile::exists(exported));
  step(QStringLiteral("composite_exported"));

  // The object's pixels differ from the photo's; a far corner of the ceiling barely does.
  const QImage out = QImage(exported).convertToFormat(QImage::Format_RGB32);
  const QImage original = QImage(photo).convertToFormat(QImage::Format_RGB32);
  QCOMPARE(out.size(), original.size());
  const Camera& cam = doc->prepared()->camera;
  const Vec3 base = doc->prepared()->placements[0].baseWorld;
  const std::optional<Vec2> centre =
      cam.project(base + Vec3(0, 0.5 * doc->scene().objects[0].heightM, 0));
  QVERIFY(centre);
  const QPoint objectPx(int(std::lround(centre->x())), int(std::lround(centre->y())));
  QVERIFY(out.rect().adjusted(3, 3, -3, -3).contains(objectPx));
  const double onObject = meanDifference(out, original, objectPx, 3);
  const double farAway = meanDifference(out, original, QPoint(8, 8), 3);
  qInfo("mean |composite - photo| (0..255): %.1f on the object at (%d, %d), %.1f in the far corner",
        onObject, objectPx.x(), objectPx.y(), farAway);
  QVERIFY2(onObject > 10 && onObject > 4 * farAway,
           qPrintable(QStringLiteral("object %1, far corner %2").arg(onObject).arg(farAway)));

  QVERIFY(log.writeFigures(QStringLiteral("figures.csv"),
                           {QStringLiteral("composite_spp,%1").arg(renderer->frameInfo().spp),
                            QStringLiteral("object_mean_abs_difference_8bit,%1").arg(onObject),
                            QStringLiteral("far_corner_mean_abs_difference_8bit,%1").arg(farAway)}));
  qInfo("steps (name, seconds since the drop): %s", qPrintable(log.steps().join(QStringLiteral("; "))));
  qInfo("screenshots: %s", qPrintable(log.shots().join(QStringLiteral(" "))));
}

QTEST_MAIN(StudioOwnPhotoTest)
#include "studio_own_photo_test.moc"
