// Big photos in the studio, measured offscreen: a photo upscaled at run time to each size asked
// for (default 0.3, 3 and 12 megapixels; written to a temporary folder, never kept), opened as a
// new scene with one sphere inserted. Per size:
//   open_ms           openPath() until the photo is painted (the preview before preparation);
//   prepare_ms        until the document is Ready (camera, room, lighting at the photo's size);
//   first_frame_ms    from Ready until the first composite is on screen;
//   paint_ms          one viewport repaint while the renderer works (median);
//   gesture_frame_ms  an arranging gesture (a move, a turn or a height change of the sphere,
//                     one per round) until the first composite of it is on screen (median);
//   gesture_frame_cpu_ms  the process's CPU time (all threads) over the same span;
// and the preview's size (RenderController::previewSizeFor). The same gesture figure on the
// bundled example (512 x 384) is the target (<= 33 ms).
// Writes bench_big_photo.csv (megapixels,width,height,figure,value: milliseconds, or megapixels
// for preview_megapixels; one row per sample) into --out;
// tests/bench/bench_big_photo.py runs this and plots it.
//   QT_QPA_PLATFORM=offscreen build/tests/bench/bench_big_photo [--out DIR] [--mp 0.3,3,12]
//       [--gestures 15] [--photo P]
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
#include <QImageReader>
#include <QImageWriter>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTextStream>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>

using namespace inlay;
using namespace inlay::studio;
using namespace inlay::bench;

namespace {

double msSince(const QElapsedTimer& t) { return double(t.nsecsElapsed()) * 1e-6; }

// CPU time of the whole process (every thread) in milliseconds: on a shared machine the wall
// time of a gesture grows with the load, its CPU time does not.
double processCpuMs() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

// Waits (processing events) until `done` or `timeoutMs`; false on timeout.
template <class F>
bool waitFor(F done, int timeoutMs) {
  QElapsedTimer t;
  t.start();
  while (!done()) {
    if (t.elapsed() > timeoutMs) return false;
    QTest::qWait(1);
  }
  return true;
}

// `source` scaled (smoothly, aspect kept) to about `megapixels`, written as a JPEG into `dir`.
QString upscaled(const QImage& source, double megapixels, const QDir& dir) {
  const double s = std::sqrt(megapixels * 1e6 / (double(source.width()) * source.height()));
  const QSize size(int(std::lround(source.width() * s)), int(std::lround(source.height() * s)));
  const QString path = dir.filePath(QStringLiteral("photo_%1mp.jpg").arg(megapixels));
  QImageWriter writer(path, "jpeg");
  writer.setQuality(92);
  return writer.write(source.scaled(size, Qt::IgnoreAspectRatio, Qt::SmoothTransformation)) ? path
                                                                                            : QString();
}

// Milliseconds from each arranging gesture (move, turn, height, in turn) to its first composite
// on screen; `cpuMs` gets the process's CPU time over the same span.
std::vector<double> gestureToFrame(MainWindow& w, int gestures, std::vector<double>& cpuMs) {
  Document* doc = w.document();
  RenderController* r = w.renderer();
  const ObjectKeys start = doc->scene().objects[0];
  std::vector<double> ms;
  for (int k = 1; k <= gestures; ++k) {
    const int drag = Document::newDragId();
    QElapsedTimer t;
    t.start();
    const double cpu0 = processCpuMs();
    bool ok = false;
    switch (k % 3) {
      case 0: ok = doc->moveObject(0, start.basePx + Vec2(-2.0 * k, 0.5 * k), drag); break;
      case 1: ok = doc->setObjectYaw(0, start.yawDeg + 7.0 * k, nullptr, drag); break;
      default: ok = doc->setObjectHeight(0, start.heightM * (1.0 + 0.02 * k), nullptr, drag); break;
    }
    if (!ok) continue;
    if (!waitForFrameOf(*r, r->requestedVersion(), 20000)) continue;
    w.viewport()->repaint();  // on screen
    ms.push_back(msSince(t));
    cpuMs.push_back(processCpuMs() - cpu0);
    QTest::qWait(40);  // a user's gestures come tens of milliseconds apart
  }
  return ms;
}

struct Row {
  double megapixels;
  QSize size;
  QString figure;
  double ms;
};

bool fail(const QString& photo, const char* why) {
  std::fprintf(stderr, "bench_big_photo: %s: %s\n", qPrintable(photo), why);
  return false;
}

// One photo: open, prepare, first frame, paints, gestures. False when it could not be prepared.
bool measure(const QString& photo, double megapixels, int gestures, std::vector<Row>& rows) {
  MainWindow w;
  showBenchWindow(w);
  if (!QTest::qWaitForWindowExposed(&w)) return fail(photo, "the window was not exposed");
  Document* doc = w.document();
  QElapsedTimer t;
  t.start();
  if (!w.openPath(photo)) return fail(photo, "openPath refused it");
  w.viewport()->repaint();
  const QSize size = w.renderer()->photoImage().size();
  auto add = [&](const QString& figure, double ms) { rows.push_back({megapixels, size, figure, ms}); };
  add(QStringLiteral("open_ms"), msSince(t));
  t.restart();
  if (!waitFor([&] { return doc->state() != Document::State::Preparing; }, 3600000) || !doc->isReady()) {
    std::fprintf(stderr, "bench_big_photo: %s: %s\n", qPrintable(photo),
                 qPrintable(doc->prepareError()));
    return false;
  }
  add(QStringLiteral("prepare_ms"), msSince(t));
  t.restart();
  if (!waitFor([&] { return w.renderer()->hasFrame(); }, 600000))
    return fail(photo, "no first frame in 10 min");
  w.viewport()->repaint();
  add(QStringLiteral("first_frame_ms"), msSince(t));
  const QSize preview = w.renderer()->previewSize();
  add(QStringLiteral("preview_megapixels"), double(preview.width()) * preview.height() * 1e-6);
  if (!w.insertBuiltin(QStringLiteral("builtin:sphere"))) {
    // Open, prepare and first frame stand; the arranging figures need an object.
    std::fprintf(stderr, "bench_big_photo: %s: no sphere inserted (%s): no paint or gesture figures\n",
                 qPrintable(photo), qPrintable(w.statusBar()->currentMessage()));
    return true;
  }
  waitFor([&] { return w.renderer()->isCurrent(); }, 60000);
  for (double ms : paintTimes(w, 30)) add(QStringLiteral("paint_ms"), ms);
  std::vector<double> cpu;
  for (double ms : gestureToFrame(w, gestures, cpu)) add(QStringLiteral("gesture_frame_ms"), ms);
  for (double ms : cpu) add(QStringLiteral("gesture_frame_cpu_ms"), ms);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  setUpBenchApplication("bench_big_photo");
  QCommandLineParser parser;
  parser.addHelpOption();
  const QCommandLineOption outOpt = outFolderOption();
  const QCommandLineOption mpOpt(QStringLiteral("mp"), QStringLiteral("Megapixels, comma-separated."),
                                 QStringLiteral("list"), QStringLiteral("0.3,3,12"));
  const QCommandLineOption gesturesOpt(QStringLiteral("gestures"), QStringLiteral("Gestures per photo."),
                                       QStringLiteral("n"), QStringLiteral("15"));
  const QCommandLineOption photoOpt(QStringLiteral("photo"), QStringLiteral("The photo to upscale."),
                                    QStringLiteral("file"));
  parser.addOptions({outOpt, mpOpt, gesturesOpt, photoOpt});
  parser.process(app);

  const QString example = examplePhotoPath();
  if (example.isEmpty()) {
    std::fprintf(stderr, "bench_big_photo: the example is not found\n");
    return 2;
  }
  QString photo = parser.value(photoOpt);
  if (photo.isEmpty()) {
    const QString york = qEnvironmentVariable("INLAY_SHARED_DIR", QStringLiteral("../shared")) +
                         QStringLiteral("/york/P1020833.jpg");
    photo = QFile::exists(york) ? york : example;
  }
  QImageReader reader(photo);
  reader.setAutoTransform(true);
  const QImage source = reader.read();
  if (source.isNull()) {
    std::fprintf(stderr, "bench_big_photo: %s: cannot read (%s)\n", qPrintable(photo),
                 qPrintable(reader.errorString()));
    return 2;
  }
  QDir().mkpath(parser.value(outOpt));
  const QDir out(parser.value(outOpt));
  QTemporaryDir tmp;
  const int gestures = std::max(3, parser.value(gesturesOpt).toInt());

  std::vector<Row> rows;
  // Rewritten after each photo, so a long run that is stopped keeps what it measured.
  auto writeCsv = [&] {
    QFile csv(out.filePath(QStringLiteral("bench_big_photo.csv")));
    if (!csv.open(QIODevice::WriteOnly | QIODevice::Text)) return false;
    QTextStream s(&csv);
    s << "megapixels,width,height,figure,value\n";
    for (const Row& r : rows)
      s << r.megapixels << ',' << r.size.width() << ',' << r.size.height() << ',' << r.figure << ','
        << r.ms << '\n';
    return true;
  };
  // The target size first: the bundled example as it is (512 x 384).
  if (!measure(example, 0.0, gestures, rows) || !writeCsv()) return 1;
  for (const QString& item : parser.value(mpOpt).split(QLatin1Char(','), Qt::SkipEmptyParts)) {
    const double mp = item.toDouble();
    const QString path = upscaled(source, mp, QDir(tmp.path()));
    if (path.isEmpty())
      std::fprintf(stderr, "bench_big_photo: the %.1f MP photo could not be written\n", mp);
    if (path.isEmpty() || !measure(path, mp, gestures, rows)) {
      std::fprintf(stderr, "bench_big_photo: %.1f MP failed\n", mp);
      return 1;
    }
    if (!writeCsv()) return 1;
    std::fprintf(stderr, "bench_big_photo: %.1f MP done\n", mp);
  }
  // The medians, one line per photo and figure (megapixels 0: the example at 512 x 384).
  std::printf("photo,width,height,figure,median\n");
  std::vector<std::pair<QString, QString>> seen;
  for (const Row& r : rows) {
    const QString photoKey = QStringLiteral("%1").arg(r.megapixels);
    if (std::find(seen.begin(), seen.end(), std::make_pair(photoKey, r.figure)) != seen.end()) continue;
    seen.emplace_back(photoKey, r.figure);
    std::vector<double> v;
    for (const Row& q : rows)
      if (q.megapixels == r.megapixels && q.figure == r.figure) v.push_back(q.ms);
    std::printf("%s,%d,%d,%s,%.2f\n",
                r.megapixels == 0 ? "example" : qPrintable(photoKey + QStringLiteral("MP")),
                r.size.width(), r.size.height(), qPrintable(r.figure), median(v));
  }
  return 0;
}
