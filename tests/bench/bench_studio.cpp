// The studio's interactivity, measured offscreen on the bundled example photo (camera and box
// estimated, so the vanishing-line overlay is drawn):
//   - viewport paint time while the renderer works (goal: under 16 ms), with every overlay, with
//     the vanishing lines off, and the baseline of the image alone (ratios to it are less noisy
//     than the times on a shared machine);
//   - time from an object move to the first composite of the new position on screen (goal:
//     under 100 ms).
// Each figure is the median over --runs runs. Writes bench_studio.csv (one row per sample) and
// bench_studio.png (the samples against their index) into --out.
//   QT_QPA_PLATFORM=offscreen build/tests/bench/bench_studio [--out DIR] [--runs 5] [--photo P]
#include "studio_bench.h"

#include "document.h"
#include "main_window.h"
#include "render_controller.h"
#include "viewport.h"

#include "inlay/engine/pipeline.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QPainter>
#include <QTest>
#include <QTextStream>

#include <algorithm>
#include <cstdio>
#include <map>

using namespace inlay;
using namespace inlay::studio;
using namespace inlay::bench;

namespace {

void waitPrepared(Document* doc) {
  QElapsedTimer t;
  t.start();
  while (doc->state() == Document::State::Preparing && t.elapsed() < 300000) QTest::qWait(20);
}

// Paint times (ms) of `count` synchronous repaints while the renderer is busy: an edit first so
// it renders.
std::vector<double> paintWhileRendering(MainWindow& w, int count) {
  Document* doc = w.document();
  const Vec2 base = doc->scene().objects[0].basePx;
  doc->moveObject(0, base + Vec2(1, 0));
  doc->moveObject(0, base);
  return paintTimes(w, count);
}

// Milliseconds from each move to the first composite of that move.
std::vector<double> firstFrameAfterMoves(MainWindow& w, int moves) {
  Document* doc = w.document();
  RenderController* r = w.renderer();
  const Vec2 base = doc->scene().objects[0].basePx;
  std::vector<double> ms;
  const int drag = Document::newDragId();
  for (int k = 1; k <= moves; ++k) {
    QElapsedTimer t;
    t.start();
    if (!doc->moveObject(0, base + Vec2(-3.0 * k, 0.5 * k), drag)) break;
    waitForFrameOf(*r, r->requestedVersion(), 10000);
    ms.push_back(double(t.nsecsElapsed()) * 1e-6);
    QTest::qWait(30);  // a user's mouse moves come every few tens of milliseconds
  }
  doc->undoStack()->undo();
  return ms;
}

void plot(const std::map<QString, std::vector<double>>& series, const QString& path) {
  QImage img(900, 500, QImage::Format_RGB32);
  img.fill(Qt::white);
  QPainter p(&img);
  p.setRenderHint(QPainter::Antialiasing);
  const QRectF area(70, 30, 800, 400);
  double maxY = 16 * 1.2;
  size_t maxN = 1;
  for (const auto& [name, v] : series) {
    for (double x : v) maxY = std::max(maxY, x);
    maxN = std::max(maxN, v.size());
  }
  maxY = std::min(maxY, 400.0);
  auto at = [&](size_t i, double y) {
    return QPointF(area.left() + area.width() * double(i) / std::max<size_t>(1, maxN - 1),
                   area.bottom() - area.height() * std::min(y, maxY) / maxY);
  };
  p.setPen(Qt::black);
  p.drawRect(area);
  for (double goal : {16.0, 100.0})
    if (goal < maxY) {
      p.setPen(QPen(Qt::gray, 1, Qt::DashLine));
      p.drawLine(at(0, goal), at(maxN - 1, goal));
      p.drawText(at(0, goal) + QPointF(-60, 4), QStringLiteral("%1 ms").arg(goal));
    }
  const QColor colours[] = {Qt::blue, Qt::darkGreen, Qt::red, Qt::darkMagenta};
  int c = 0;
  for (const auto& [name, v] : series) {
    p.setPen(QPen(colours[c % 4], 1.5));
    for (size_t i = 0; i + 1 < v.size(); ++i) p.drawLine(at(i, v[i]), at(i + 1, v[i + 1]));
    const int legendRow = c % 2, legendColumn = c / 2;  // the legend: two rows, then a new column
    p.drawText(QPointF(area.left() + 10 + 400 * legendColumn, area.bottom() + 25 + 15 * legendRow),
               QStringLiteral("%1 (median %2 ms)").arg(name).arg(median(v), 0, 'f', 2));
    ++c;
  }
  p.setPen(Qt::black);
  p.drawText(QPointF(area.left(), 20), QStringLiteral("studio: milliseconds per sample"));
  img.save(path);
}

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  setUpBenchApplication("bench_studio");
  QCommandLineParser parser;
  parser.addHelpOption();
  const QCommandLineOption outOpt = outFolderOption();
  const QCommandLineOption runsOpt(QStringLiteral("runs"), QStringLiteral("Runs."), QStringLiteral("n"),
                                   QStringLiteral("5"));
  const QCommandLineOption photoOpt(QStringLiteral("photo"), QStringLiteral("Photo."),
                                    QStringLiteral("file"));
  parser.addOptions({outOpt, runsOpt, photoOpt});
  parser.process(app);
  QString photo = parser.value(photoOpt);
  if (photo.isEmpty()) photo = examplePhotoPath();
  if (photo.isEmpty()) {
    std::fprintf(stderr, "bench_studio: the example is not found\n");
    return 2;
  }
  const int runs = std::max(1, parser.value(runsOpt).toInt());
  QDir().mkpath(parser.value(outOpt));
  const QDir out(parser.value(outOpt));

  MainWindow w;
  showBenchWindow(w);
  if (!w.openPath(photo)) return 2;
  waitPrepared(w.document());
  if (!w.document()->isReady() || !w.insertBuiltin(QStringLiteral("builtin:sphere"))) {
    std::fprintf(stderr, "bench_studio: %s\n", qPrintable(w.document()->prepareError()));
    return 2;
  }
  QTest::qWait(500);

  std::map<QString, std::vector<double>> samples;
  std::map<QString, std::vector<double>> medians;
  Viewport* view = w.viewport();
  for (int run = 0; run < runs; ++run) {
    view->setShowVanishingLines(true);
    view->setLayer(Layer::Composite);
    const auto all = paintWhileRendering(w, 40);
    view->setShowVanishingLines(false);
    const auto noLines = paintWhileRendering(w, 40);
    view->setLayer(Layer::Photo);
    const auto image = paintWhileRendering(w, 40);
    view->setLayer(Layer::Composite);
    view->setShowVanishingLines(true);
    const auto frames = firstFrameAfterMoves(w, 20);
    const std::pair<QString, const std::vector<double>*> named[] = {
        {QStringLiteral("paint_all_overlays_ms"), &all},
        {QStringLiteral("paint_without_vanishing_lines_ms"), &noLines},
        {QStringLiteral("paint_image_only_ms"), &image},
        {QStringLiteral("first_frame_after_move_ms"), &frames}};
    for (const auto& [name, v] : named) {
      samples[name].insert(samples[name].end(), v->begin(), v->end());
      medians[name].push_back(median(*v));
    }
  }

  QFile csv(out.filePath(QStringLiteral("bench_studio.csv")));
  if (!csv.open(QIODevice::WriteOnly | QIODevice::Text)) return 1;
  QTextStream s(&csv);
  s << "figure,index,ms\n";
  for (const auto& [name, v] : samples)
    for (size_t i = 0; i < v.size(); ++i) s << name << ',' << i << ',' << v[i] << '\n';
  plot(samples, out.filePath(QStringLiteral("bench_studio.png")));

  const double base = median(medians[QStringLiteral("paint_image_only_ms")]);
  std::printf("figure,median_of_run_medians_ms,ratio_to_image_only\n");
  for (const auto& [name, m] : medians)
    std::printf("%s,%.2f,%.2f\n", qPrintable(name), median(m), base > 0 ? median(m) / base : 0.0);
  return 0;
}
