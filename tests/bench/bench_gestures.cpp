// Issue #17's target, measured: the time from each arranging gesture to the first repainted
// viewport frame that shows it (goal: 33 ms at 512x384), on the bundled example (its sphere, and
// the library chair inserted beside it; the gestures work on the chair), with the denoised
// preview off and on. Gestures, each --reps times (a user's edits come tens of milliseconds apart,
// so every edit lands while the previous one is still rendering):
//   move (one drag step), yaw, height (one step of the turn and height handles), duplicate,
//   delete, hide (hide and show in turn), material (albedo of the chair), insert (the library's
//   chair, already read: a drag from the Library dock), undo (of each duplicate, delete, material
//   change and insert).
// A gesture starts at the Document call the viewport makes for it (validation included) and ends
// when the renderer's composite is of the edit's scene version (or newer) and the viewport has
// painted it (its own paint in the event loop, or one made here). Writes DIR/gestures.csv (gesture,
// denoise, index, ms, cpu_ms: the process's CPU time over the same span, frame_taken_ms: when the
// GUI thread took the frame, before painting it) and prints gesture, denoise, median and p90.
//   QT_QPA_PLATFORM=offscreen build/tests/bench/bench_gestures [--out DIR] [--reps 20]
//       [--only move,yaw,...] [--denoise off|on|both]
// tests/bench/bench_gestures.py runs it and plots the figure.
#include "studio_bench.h"

#include "document.h"
#include "main_window.h"
#include "model_import.h"
#include "render_controller.h"
#include "viewport.h"

#include "inlay/engine/model_library.h"
#include "inlay/engine/pipeline.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QTest>
#include <QTextStream>

#include <cstdio>
#include <ctime>
#include <functional>
#include <map>

using namespace inlay;
using namespace inlay::studio;
using namespace inlay::bench;

namespace {

double processCpuMs() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) * 1e3 + double(ts.tv_nsec) * 1e-6;
}

struct Sample {
  QString gesture;
  bool denoise = false;
  double ms = 0, cpuMs = 0;
  double frameMs = 0;  // to the GUI thread taking the frame (before its paint)
};

class GestureBench {
 public:
  GestureBench(MainWindow& w, std::shared_ptr<const TriangleMesh> chair, ObjectKeys chairKeys)
      : w_(w), doc_(*w.document()), chair_(std::move(chair)), chairKeys_(std::move(chairKeys)) {}

  // Every gesture `reps` times with the denoiser `denoise`.
  void run(bool denoise, int reps) {
    denoise_ = denoise;
    w_.renderer()->setDenoise(denoise);
    waitForFrameOf(*w_.renderer(), w_.renderer()->requestedVersion(), 60000);
    const int o = chairIndex();
    const ObjectKeys start = doc_.scene().objects[size_t(o)];
    const int drag = Document::newDragId();
    for (int k = 0; k < reps && wants("move"); ++k)
      time("move",
           [&] { return doc_.moveObject(o, start.basePx + Vec2(-3.0 * (k % 6 + 1), 1.0), drag); });
    if (doc_.undoStack()->canUndo()) doc_.undoStack()->undo();
    const int turn = Document::newDragId();
    for (int k = 0; k < reps && wants("yaw"); ++k)
      time("yaw", [&] { return doc_.setObjectYaw(o, start.yawDeg + 7.0 * (k + 1), nullptr, turn); });
    if (doc_.undoStack()->canUndo()) doc_.undoStack()->undo();
    const int scale = Document::newDragId();
    for (int k = 0; k < reps && wants("height"); ++k)
      time("height", [&] {
        return doc_.setObjectHeight(o, start.heightM * (1.0 + 0.02 * (k % 6 + 1)), nullptr, scale);
      });
    if (doc_.undoStack()->canUndo()) doc_.undoStack()->undo();
    for (int k = 0; k < reps; ++k) {
      if (wants("duplicate") && time("duplicate", [&] { return doc_.duplicateObject(o); })) undo();
      if (wants("delete") && time("delete", [&] { return doc_.removeObject(o); })) undo();
      if (wants("hide") && time("hide", [&] { return doc_.setObjectHidden(o, true); }))
        time("hide", [&] { return doc_.setObjectHidden(o, false); });
      MaterialKeys m;
      m.albedo = Vec3(0.2 + 0.03 * k, 0.5, 0.7);
      if (wants("material") && time("material", [&] { return doc_.setMaterial(o, m); })) undo();
      if (wants("insert") && time("insert", [&] { return doc_.insertObject(insertKeys(k), chair_); }))
        undo();
    }
  }
  const std::vector<Sample>& samples() const { return samples_; }
  // Only these gestures are made (empty: all); a left-out undo leaves its edit in place.
  void setOnly(const QStringList& only) { only_ = only; }

 private:
  // The move, yaw and height drags each end with an untimed undo; every other gesture's undo is
  // timed as "undo" when undo is wanted (and made, untimed, when not).
  bool wants(const char* gesture) const {
    return only_.isEmpty() || only_.contains(QString::fromLatin1(gesture));
  }
  int chairIndex() const { return doc_.objectCount() - 1; }
  ObjectKeys insertKeys(int k) const {
    ObjectKeys keys = chairKeys_;
    keys.basePx += Vec2(8.0 * (k % 4), 0.0);
    return keys;
  }
  void undo() {
    time("undo", [&] {
      if (doc_.undoStack()->canUndo()) doc_.undoStack()->undo();
      return true;
    });
  }
  // Times one edit to its frame on screen; an edit refused or a frame that never came is left out
  // (false when refused).
  bool time(const char* gesture, const std::function<bool()>& edit) {
    RenderController& r = *w_.renderer();
    Viewport& view = *w_.viewport();
    QElapsedTimer t;
    t.start();
    const double cpu0 = processCpuMs();
    const bool ok = edit();
    // When the GUI thread takes the edit's first frame, and how many paints the viewport had made.
    const quint64 wanted = r.requestedVersion();
    double frameMs = -1;
    size_t paintsAtFrame = 0;
    const QMetaObject::Connection taken = QObject::connect(&r, &RenderController::frameUpdated, [&] {
      if (frameMs < 0 && r.isCurrent() && r.frameInfo().sceneVersion >= wanted) {
        frameMs = double(t.nsecsElapsed()) * 1e-6;
        paintsAtFrame = view.paintTimesMs().size();
      }
    });
    if (ok && waitForFrameOf(r, wanted, 20000)) {
      // On screen: the viewport's own paint after the frame, else one made here.
      if (frameMs < 0 || view.paintTimesMs().size() <= paintsAtFrame) view.repaint();
      samples_.push_back({QString::fromLatin1(gesture), denoise_, double(t.nsecsElapsed()) * 1e-6,
                          processCpuMs() - cpu0, frameMs});
    } else {
      std::fprintf(stderr, "bench_gestures: %s %s\n", gesture, ok ? "gave no frame" : "was refused");
    }
    QObject::disconnect(taken);
    QTest::qWait(40);  // a user's gestures come tens of milliseconds apart
    return ok;
  }

  MainWindow& w_;
  Document& doc_;
  std::shared_ptr<const TriangleMesh> chair_;
  ObjectKeys chairKeys_;
  bool denoise_ = false;
  QStringList only_;
  std::vector<Sample> samples_;
};

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, size_t(q * double(v.size() - 1) + 0.5))];
}

// The library's chair, read as a drop from the Library dock reads it, standing on the floor.
bool insertChair(MainWindow& w, std::shared_ptr<const TriangleMesh>* mesh, ObjectKeys* keys) {
  const QString path =
      QDir(QString::fromStdString(modelLibraryDir())).filePath(QStringLiteral("chair.glb"));
  const ModelLoadResult loaded = loadModelForInsert(path, kDefaultModelHeightM);
  const std::optional<Vec2> at = w.document()->supportPointNear(Vec2(330, 300));
  if (!loaded.model || !at) {
    std::fprintf(stderr, "bench_gestures: %s\n",
                 loaded.model ? "no floor at (330, 300)" : qPrintable(loaded.error));
    return false;
  }
  keys->mesh = keys->meshResolved = path.toStdString();
  keys->name = "chair";
  keys->basePx = *at;
  keys->heightM = loaded.model->heightM;
  keys->material.preset = "asset";
  *mesh = loaded.model->mesh;
  QString reason;
  if (!w.document()->insertObject(*keys, *mesh, &reason)) {
    std::fprintf(stderr, "bench_gestures: %s\n", qPrintable(reason));
    return false;
  }
  return true;
}

bool writeCsv(const QString& path, const std::vector<Sample>& samples) {
  QFile csv(path);
  if (!csv.open(QIODevice::WriteOnly | QIODevice::Text)) return false;
  QTextStream s(&csv);
  s << "gesture,denoise,index,ms,cpu_ms,frame_taken_ms\n";
  std::map<std::pair<QString, bool>, int> index;
  for (const Sample& x : samples)
    s << x.gesture << ',' << (x.denoise ? "on" : "off") << ',' << index[{x.gesture, x.denoise}]++ << ','
      << x.ms << ',' << x.cpuMs << ',' << x.frameMs << '\n';
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  setUpBenchApplication("bench_gestures");
  QCommandLineParser parser;
  parser.addHelpOption();
  const QCommandLineOption outOpt = outFolderOption();
  const QCommandLineOption repsOpt(QStringLiteral("reps"), QStringLiteral("Repetitions per gesture."),
                                   QStringLiteral("n"), QStringLiteral("20"));
  const QCommandLineOption onlyOpt(QStringLiteral("only"),
                                   QStringLiteral("Comma-separated gestures to make (profiling)."),
                                   QStringLiteral("list"));
  const QCommandLineOption denoiseOpt(QStringLiteral("denoise"), QStringLiteral("off, on or both."),
                                      QStringLiteral("mode"), QStringLiteral("both"));
  parser.addOptions({outOpt, repsOpt, onlyOpt, denoiseOpt});
  parser.process(app);
  const std::string scene = exampleScenePath();
  if (scene.empty()) {
    std::fprintf(stderr, "bench_gestures: the example is not found\n");
    return 2;
  }
  QDir().mkpath(parser.value(outOpt));
  const QDir out(parser.value(outOpt));

  MainWindow w;
  showBenchWindow(w);
  if (!w.openPath(QString::fromStdString(scene))) return 2;
  QElapsedTimer prep;
  prep.start();
  while (w.document()->state() == Document::State::Preparing && prep.elapsed() < 300000)
    QTest::qWait(20);
  std::shared_ptr<const TriangleMesh> chair;
  ObjectKeys chairKeys;
  if (!w.document()->isReady() || !insertChair(w, &chair, &chairKeys)) return 2;
  // Settle: the preview of the scene with the chair renders to its sample cap first (the first
  // seconds after opening are busy with it, which the first gestures measured would pay for).
  QElapsedTimer settle;
  settle.start();
  while (w.renderer()->frameInfo().spp < w.document()->scene().render.spp && settle.elapsed() < 120000)
    QTest::qWait(50);

  GestureBench bench(w, chair, chairKeys);
  const int reps = std::max(1, parser.value(repsOpt).toInt());
  if (parser.isSet(onlyOpt)) bench.setOnly(parser.value(onlyOpt).split(QLatin1Char(',')));
  const QString denoise = parser.value(denoiseOpt);
  if (denoise != QLatin1String("on")) bench.run(false, reps);
  if (denoise != QLatin1String("off")) bench.run(true, reps);
  if (!writeCsv(out.filePath(QStringLiteral("gestures.csv")), bench.samples())) return 1;

  std::map<std::pair<QString, bool>, std::vector<double>> by;
  for (const Sample& s : bench.samples()) by[{s.gesture, s.denoise}].push_back(s.ms);
  std::printf("gesture,denoise,n,median_ms,p90_ms\n");
  for (const auto& [key, v] : by)
    std::printf("%s,%s,%zu,%.1f,%.1f\n", qPrintable(key.first), key.second ? "on" : "off", v.size(),
                quantile(v, 0.5), quantile(v, 0.9));
  return 0;
}
