// Render Final Image on the bundled example (512 × 384, a few samples per pixel): the finished
// image is what the viewport shows (and the before/after split's right side) until the next
// edit, the status bar says it is the final render, Export Composite writes it, and the save
// dialog offers PNG, JPEG, TIFF and EXR. Screenshots in studio_final_image_artifacts/ of the
// build tree.
#include "document.h"
#include "final_render.h"
#include "main_window.h"
#include "render_controller.h"
#include "viewport.h"

#include <QAction>
#include <QMessageBox>
#include <QPushButton>
#include <QUndoStack>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cstdlib>
#include <memory>

#include "studio_test_support.h"
#include "studio_workflow_steps.h"

using namespace inlay;
using namespace inlay::studio;
using namespace inlay::test;

namespace {

// The largest difference of any channel between two images of one size (-1: sizes differ).
int maxCodeDifference(const QImage& a, const QImage& b) {
  if (a.size() != b.size()) return -1;
  const QImage x = a.convertToFormat(QImage::Format_RGB32), y = b.convertToFormat(QImage::Format_RGB32);
  int worst = 0;
  for (int j = 0; j < x.height(); ++j) {
    const QRgb* p = reinterpret_cast<const QRgb*>(x.constScanLine(j));
    const QRgb* q = reinterpret_cast<const QRgb*>(y.constScanLine(j));
    for (int i = 0; i < x.width(); ++i)
      worst = std::max({worst, std::abs(qRed(p[i]) - qRed(q[i])), std::abs(qGreen(p[i]) - qGreen(q[i])),
                        std::abs(qBlue(p[i]) - qBlue(q[i]))});
  }
  return worst;
}

}  // namespace

class StudioFinalImageTest : public QObject {
  Q_OBJECT

 private Q_SLOTS:
  void initTestCase();
  void finalImageIsShownUntilTheNextEdit();
  void splitShowsTheFinalImageRightOfTheDivider();
  void saveDialogOffersEveryFormat();
  void openingAnotherSceneAsksWhileFinalRenders();
  void closingAsksWhileFinalRenders();
  void closingWhilePreparingDoesNotHang();
  void cleanupTestCase() { window_.reset(); }

 private:
  std::unique_ptr<MainWindow> window_;  // the example, prepared once for every test
};

void StudioFinalImageTest::initTestCase() {
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName(QStringLiteral("InlayTest"));
  QCoreApplication::setApplicationName(QStringLiteral("studio_final_image_test"));
  QSettings().clear();
  window_ = openStudio(exampleScene());
  QVERIFY(window_);
  QVERIFY2(waitReady(window_->document(), waitMs(120000)),
           qPrintable(window_->document()->prepareError()));
}

// The finished final image replaces the preview in the viewport, the status bar names it, and
// Export Composite writes it; an edit returns to the live preview.
void StudioFinalImageTest::finalImageIsShownUntilTheNextEdit() {
  MainWindow* w = window_.get();
  Document* doc = w->document();
  QTRY_VERIFY_WITH_TIMEOUT(w->renderer()->hasFrame(), waitMs(60000));
  QVERIFY(!w->viewport()->showsFinalImage());

  QTemporaryDir dir;
  const QString finalPath = dir.filePath(QStringLiteral("final.png"));
  QSignalSpy finished(w, &MainWindow::finalImageFinished);
  QVERIFY(w->renderFinalImage(finalPath, 4));
  QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, waitMs(120000));
  QVERIFY2(finished.first()[0].toBool(), qPrintable(finished.first()[1].toString()));
  // The final frame is denoised (a few samples come out clean) and says so.
  QCOMPARE(FinalRender::optionsFor(*doc->prepared()).denoise, SessionOptions::Denoise::Final);
  QVERIFY2(finished.first()[1].toString().contains(QStringLiteral("before denoising")),
           qPrintable(finished.first()[1].toString()));

  // Shown at the photo's full size, the codes of the file written (the PNG's rounding aside).
  Viewport* view = w->viewport();
  QVERIFY(view->showsFinalImage());
  const QSize full(doc->prepared()->camera.widthPx, doc->prepared()->camera.heightPx);
  QCOMPARE(view->finalImage().size(), full);
  const int diff = maxCodeDifference(view->finalImage(), QImage(finalPath));
  QVERIFY2(diff >= 0 && diff <= 1, qPrintable(QString::number(diff)));
  const QString status = w->statusBar()->currentMessage();
  QVERIFY2(status.contains(QStringLiteral("Final render shown")) &&
               status.contains(QStringLiteral("final.png")),
           qPrintable(status));
  // Screenshots for the reader: the final image shown, then in the before/after split.
  StepLog shots(QStringLiteral("studio_final_image_artifacts"));
  QVERIFY(shots.shot(w, QStringLiteral("final_shown")));
  w->splitAction()->setChecked(true);
  QVERIFY(view->showsFinalImage());
  QVERIFY(shots.shot(w, QStringLiteral("final_split")));
  w->splitAction()->setChecked(false);
  // Preview frames still arriving do not replace it.
  QSignalSpy frames(w->renderer(), &RenderController::frameUpdated);
  QTRY_VERIFY_WITH_TIMEOUT(frames.count() > 0 || w->renderer()->frameInfo().final, waitMs(60000));
  QVERIFY(view->showsFinalImage());

  // Export Composite writes the final render, not the preview.
  const QString exported = dir.filePath(QStringLiteral("exported.png"));
  QVERIFY(w->exportComposite(exported));
  QCOMPARE(maxCodeDifference(QImage(exported), QImage(finalPath)), 0);

  // A selection is no edit; inserting a cube is: back to the live preview, the status cleared.
  doc->setSelectedObject(-1);
  QVERIFY(view->showsFinalImage());
  QVERIFY(w->insertBuiltin(QStringLiteral("builtin:cube")));
  QVERIFY(!view->showsFinalImage());
  QVERIFY(!w->statusBar()->currentMessage().contains(QStringLiteral("Final render shown")));
}

// With the split on, the final image is right of the divider and the photo left of it.
void StudioFinalImageTest::splitShowsTheFinalImageRightOfTheDivider() {
  MainWindow* w = window_.get();
  QVERIFY2(waitReady(w->document(), waitMs(120000)), qPrintable(w->document()->prepareError()));
  Viewport* view = w->viewport();
  const QSize full = w->renderer()->photoImage().size();
  QImage marker(full, QImage::Format_RGB32);
  marker.fill(QColor(255, 0, 255));  // a colour the photo does not have
  view->setFinalImage(marker, QStringLiteral("final"));
  w->splitAction()->setChecked(true);
  view->setSplitFraction(0.5);
  const QImage shot = view->grab().toImage();
  const int y = int(view->widgetFromImage(Vec2(0, 0.75 * full.height())).y());
  const QPoint right(int(view->splitWidgetX()) + 40, y), left(int(view->splitWidgetX()) - 40, y);
  QCOMPARE(QColor(shot.pixel(right)), QColor(255, 0, 255));
  QVERIFY(QColor(shot.pixel(left)) != QColor(255, 0, 255));
  view->setFinalImage(QImage());
  QVERIFY(!view->showsFinalImage());
}

void StudioFinalImageTest::saveDialogOffersEveryFormat() {
  const QString filters = MainWindow::compositeImageFilters().join(QStringLiteral(";;"));
  for (const char* ext : {"*.png", "*.jpg", "*.tif", "*.exr"})
    QVERIFY2(filters.contains(QLatin1String(ext)), ext);
}

namespace {

// The window's open "cancel the final render?" question's button `name`, or null.
QPushButton* questionButton(MainWindow* w, const char* name) {
  auto* box = w->findChild<QMessageBox*>(QStringLiteral("finalRenderQuestion"));
  return box && box->isVisible() ? box->findChild<QPushButton*>(QLatin1String(name)) : nullptr;
}

}  // namespace

// Opening another scene while a final render runs asks first: Keep Rendering leaves both as
// they were; Cancel the Render and Open stops it (nothing written) and opens the scene.
void StudioFinalImageTest::openingAnotherSceneAsksWhileFinalRenders() {
  MainWindow* w = window_.get();
  Document* doc = w->document();
  QVERIFY2(waitReady(doc, waitMs(120000)), qPrintable(doc->prepareError()));
  QVERIFY(doc->undoStack()->count() > 0);  // the cube of the first test
  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("open.png"));
  QSignalSpy finished(w, &MainWindow::finalImageFinished);
  QVERIFY(w->renderFinalImage(path));
  w->setInteractive(true);
  // No event loop runs between the start and the clicks: the render cannot have ended.
  QVERIFY(!w->openPath(exampleScene()));
  QPushButton* keep = questionButton(w, "keepRenderingButton");
  QVERIFY(keep && questionButton(w, "cancelRenderButton"));
  QCOMPARE(questionButton(w, "cancelRenderButton")->text(),
           QStringLiteral("Cancel the Render and Open"));
  keep->click();
  QVERIFY(w->finalRender() && w->finalRender()->running());
  QVERIFY(doc->undoStack()->count() > 0);  // the scene was not replaced
  QVERIFY(!w->openPath(exampleScene()));
  QPushButton* stop = questionButton(w, "cancelRenderButton");
  QVERIFY(stop);
  stop->click();
  QCOMPARE(finished.count(), 1);
  QVERIFY(!finished.first()[0].toBool());
  QVERIFY(!w->finalRender());
  QTRY_COMPARE_WITH_TIMEOUT(doc->undoStack()->count(), 0, waitMs(10000));  // opened afresh
  w->setInteractive(false);
  QVERIFY(!QFile::exists(path));
  QVERIFY2(waitReady(doc, waitMs(120000)), qPrintable(doc->prepareError()));
}

// Closing (the close button, File > Quit) while a final render runs asks: Keep Rendering keeps
// the window and the render; Cancel the Render and Close stops it and closes.
void StudioFinalImageTest::closingAsksWhileFinalRenders() {
  MainWindow* w = window_.get();
  QVERIFY2(waitReady(w->document(), waitMs(120000)), qPrintable(w->document()->prepareError()));
  QVERIFY(w->document()->undoStack()->isClean());  // no "save changes?" question on close
  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("close.png"));
  QSignalSpy finished(w, &MainWindow::finalImageFinished);
  QVERIFY(w->renderFinalImage(path));
  w->setInteractive(true);
  QVERIFY(!w->close());
  QPushButton* keep = questionButton(w, "keepRenderingButton");
  QVERIFY(keep);
  StepLog shots(QStringLiteral("studio_final_image_artifacts/close_question"));
  QVERIFY(shots.shot(keep->window(), QStringLiteral("close_question")));
  keep->click();
  QVERIFY(w->isVisible());
  QVERIFY(w->finalRender() && w->finalRender()->running());
  QCOMPARE(finished.count(), 0);
  w->quitAction()->trigger();
  QPushButton* stop = questionButton(w, "cancelRenderButton");
  QVERIFY(stop);
  QCOMPARE(stop->text(), QStringLiteral("Cancel the Render and Close"));
  stop->click();
  QCOMPARE(finished.count(), 1);
  QVERIFY(!finished.first()[0].toBool());
  QTRY_VERIFY_WITH_TIMEOUT(!w->isVisible(), waitMs(10000));
  QVERIFY(!QFile::exists(path));
  w->setInteractive(false);
}

// A window closed and destroyed while its scene prepares returns (the preparation is
// cancelled and joined), as one with a final render running does.
void StudioFinalImageTest::closingWhilePreparingDoesNotHang() {
  auto w = std::make_unique<MainWindow>();
  w->setInteractive(false);
  w->show();
  QVERIFY(QTest::qWaitForWindowExposed(w.get()));
  QVERIFY(w->openPath(exampleScene()));
  QCOMPARE(w->document()->state(), Document::State::Preparing);
  QElapsedTimer clock;
  clock.start();
  QVERIFY(w->close());
  w.reset();
  qInfo("closed and destroyed while preparing in %lld ms", clock.elapsed());
  QVERIFY2(clock.elapsed() < waitMs(30000), qPrintable(QString::number(clock.elapsed())));
}

QTEST_MAIN(StudioFinalImageTest)
#include "studio_final_image_test.moc"
