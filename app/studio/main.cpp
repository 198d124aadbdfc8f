// inlay: the studio. See ../../../shared/spec/cli.md ("inlay [SCENE.json | PHOTO]").
//
// --recover restores the work a crash left (Autosaver) without asking; without it the window asks.
// --insert-model MODEL (repeatable) inserts a model file once the scene is prepared, as Insert
// Model… does (OBJ, PLY, glTF, GLB, FBX, DAE, 3DS).
// --show-log shows the Log dock across the bottom of the window (by default its tab is behind the
// Camera Response dock's), for a screenshot of its lines.
// Test hook: inlay --screenshot OUT.png [--wait-spp N | --wait-seconds S] [SCENE | PHOTO] opens
// the scene, waits until the composite reaches N samples per pixel (default 4), or until the
// shown frame was rendered for S seconds (or its render ends, or 60 s pass, times
// INLAY_TEST_WAIT_SCALE), grabs the main window to OUT.png and exits: 0 when the screenshot shows
// the rendered scene, 2 when the scene could not be opened or prepared (the screenshot is still
// written, showing the error), 1 when OUT.png could not be written.
#include "document.h"
#include "i18n.h"
#include "log_dock.h"
#include "main_window.h"
#include "render_controller.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QScreen>
#include <QTimer>

#include <algorithm>

#include <cstdio>

using inlay::studio::Document;
using inlay::studio::MainWindow;

namespace {

// `inlay --help` and `--version` print and exit without a window: with no display (over ssh,
// in a container) Qt's windowing plugin would abort before they are read ("could not connect to
// display ... Reinstalling the application may fix this problem"), so they run offscreen.
void printWithoutDisplay(int argc, char** argv) {
  const bool display = qEnvironmentVariableIsSet("DISPLAY") ||
                       qEnvironmentVariableIsSet("WAYLAND_DISPLAY") ||
                       qEnvironmentVariableIsSet("QT_QPA_PLATFORM");
  if (display) return;
  for (int i = 1; i < argc; ++i) {
    const QByteArray arg(argv[i]);
    if (arg == "-h" || arg == "--help" || arg == "--help-all" || arg == "-v" || arg == "--version")
      qputenv("QT_QPA_PLATFORM", "offscreen");
  }
}

// --show-log: the Log dock across the bottom, where its lines are read whole.
void showLogAcrossTheBottom(MainWindow& window) {
  window.addDockWidget(Qt::BottomDockWidgetArea, window.logDock());
  window.logDock()->show();
  // Once laid out: a dock added before the window's first layout keeps its minimum height.
  QTimer::singleShot(0, &window,
                     [&window] { window.resizeDocks({window.logDock()}, {300}, Qt::Vertical); });
}

int writeScreenshot(MainWindow& window, const QString& path) {
  const QPixmap shot = window.grab();
  if (shot.isNull() || !shot.save(path)) {
    std::fprintf(stderr, "inlay: %s: cannot write the screenshot\n", qUtf8Printable(path));
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  printWithoutDisplay(argc, argv);
  QApplication app(argc, argv);
  QApplication::setOrganizationName(QStringLiteral("Inlay"));
  QApplication::setApplicationName(QStringLiteral("inlay"));
  QApplication::setApplicationVersion(QString::fromLatin1(inlay::versionString()));
  inlay::studio::installTranslators();

  QCommandLineParser parser;
  parser.setApplicationDescription(
      QCoreApplication::translate("main", "Insert synthetic objects into a photograph."));
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument(
      QStringLiteral("file"),
      QCoreApplication::translate("main", "A scene file (.json) or a photo; none: the example."),
      QStringLiteral("[SCENE.json | PHOTO]"));
  const QCommandLineOption screenshotOpt(
      QStringLiteral("screenshot"),
      QCoreApplication::translate("main", "Grab the window to <file> once rendered, then exit."),
      QStringLiteral("file"));
  const QCommandLineOption waitSppOpt(
      QStringLiteral("wait-spp"),
      QCoreApplication::translate("main", "Samples per pixel to wait for (default 4)."),
      QStringLiteral("n"), QStringLiteral("4"));
  const QCommandLineOption waitSecondsOpt(
      QStringLiteral("wait-seconds"),
      QCoreApplication::translate("main", "Instead: render seconds of the shown frame to wait for."),
      QStringLiteral("s"));
  const QCommandLineOption showLogOpt(
      QStringLiteral("show-log"),
      QCoreApplication::translate("main", "Show the Log dock across the bottom of the window."));
  const QCommandLineOption recoverOpt(
      QStringLiteral("recover"),
      QCoreApplication::translate("main", "Restore unsaved work left by a crash without asking."));
  const QCommandLineOption insertModelOpt(
      QStringLiteral("insert-model"),
      QCoreApplication::translate("main", "Insert the model <file> into the scene once it is prepared."),
      QStringLiteral("file"));
  parser.addOption(insertModelOpt);
  parser.addOption(recoverOpt);
  parser.addOption(screenshotOpt);
  parser.addOption(waitSppOpt);
  parser.addOption(waitSecondsOpt);
  parser.addOption(showLogOpt);
  // Not process(): a usage error exits with 2, as cli.md asks.
  if (!parser.parse(QCoreApplication::arguments())) {
    std::fprintf(stderr, "inlay: %s\n", qUtf8Printable(parser.errorText()));
    return 2;
  }
  if (parser.isSet(QStringLiteral("help"))) parser.showHelp(0);
  if (parser.isSet(QStringLiteral("version"))) parser.showVersion();

  const QStringList files = parser.positionalArguments();
  if (files.size() > 1) {
    std::fprintf(stderr, "inlay: %s\n",
                 qUtf8Printable(QCoreApplication::translate("main", "Give at most one file.")));
    return 2;
  }
  bool sppOk = false;
  const int waitSpp = parser.value(waitSppOpt).toInt(&sppOk);
  if (!sppOk || waitSpp < 0) {
    std::fprintf(stderr, "inlay: --wait-spp: %s\n",
                 qUtf8Printable(QCoreApplication::translate("main", "expected a number >= 0")));
    return 2;
  }
  bool secondsOk = true;
  const double waitSeconds =
      parser.isSet(waitSecondsOpt) ? parser.value(waitSecondsOpt).toDouble(&secondsOk) : -1.0;
  if (!secondsOk || (parser.isSet(waitSecondsOpt) && !(waitSeconds >= 0))) {
    std::fprintf(stderr, "inlay: --wait-seconds: %s\n",
                 qUtf8Printable(QCoreApplication::translate("main", "expected a number >= 0")));
    return 2;
  }
  const bool screenshot = parser.isSet(screenshotOpt);

  MainWindow window;
  window.setInteractive(!screenshot);
  // Screenshots at 1280 x 800, or the screen's size when it is smaller (xvfb-run -s "-screen 0
  // 1024x700x24" shows the studio as a small screen does).
  if (screenshot)
    window.resize(QSize(1280, 800).boundedTo(
        window.screen() ? window.screen()->availableGeometry().size() : QSize(1280, 800)));
  window.show();
  if (parser.isSet(showLogOpt)) showLogAcrossTheBottom(window);
  bool opened = files.isEmpty() ? window.openExample() : window.openPath(files.first());
  // Work a crash left behind replaces what was opened (after asking, unless --recover).
  if (parser.isSet(recoverOpt)) opened = window.restoreRecovery() || opened;
  else if (!screenshot) window.offerRecovery();
  if (opened)
    for (const QString& model : parser.values(insertModelOpt))
      opened = window.insertModelFile(QDir::current().absoluteFilePath(model)) && opened;
  if (!screenshot) return app.exec();

  // --- Screenshot mode ---
  const QString out = QDir::current().absoluteFilePath(parser.value(screenshotOpt));
  if (!opened) {
    const int rc = writeScreenshot(window, out);
    return rc ? rc : 2;
  }
  // A loaded machine (or a sanitizer build) waits longer: INLAY_TEST_WAIT_SCALE, as the tests.
  const double waitScale =
      std::max(1.0, qEnvironmentVariable("INLAY_TEST_WAIT_SCALE", QStringLiteral("1")).toDouble());
  int exitCode = -1;
  QElapsedTimer clock;
  clock.start();
  auto check = [&] {
    if (exitCode >= 0) return;
    const Document::State state = window.document()->state();
    const auto* renderer = window.renderer();
    bool done = false;
    int rc = 0;
    if (!window.lastModelError().isEmpty()) {  // a model was refused (the window said why)
      done = true;
      rc = 2;
    } else if (window.pendingModelCount() > 0) {
      return;  // a model is being read or waits for the scene
    } else if (state == Document::State::Failed || state == Document::State::Empty) {
      if (state == Document::State::Empty)  // a failure was already reported by the window
        std::fprintf(stderr, "inlay: %s\n", qUtf8Printable(window.document()->prepareError()));
      done = true;
      rc = 2;
    } else if (renderer->isCurrent() && ((waitSeconds >= 0 ? renderer->frameInfo().seconds >= waitSeconds
                                                           : renderer->frameInfo().spp >= waitSpp) ||
                                         renderer->frameInfo().final)) {
      done = true;
      if (waitSeconds >= 0)
        std::fprintf(stderr, "inlay: screenshot of the frame at %.2f s, %d spp\n",
                     renderer->frameInfo().seconds, renderer->frameInfo().spp);
    } else if (clock.elapsed() > 60'000 * waitScale) {
      std::fprintf(stderr, "inlay: the render did not reach %d spp within %.0f s; grabbing anyway\n",
                   waitSpp, 60.0 * waitScale);
      done = true;
    }
    if (!done) return;
    const int written = writeScreenshot(window, out);
    exitCode = written ? written : rc;
    QCoreApplication::exit(exitCode);
  };
  QObject::connect(window.renderer(), &inlay::studio::RenderController::frameUpdated, &app, check,
                   Qt::QueuedConnection);
  QObject::connect(window.document(), &Document::changed, &app, check, Qt::QueuedConnection);
  QTimer poll;
  QObject::connect(&poll, &QTimer::timeout, &app, check);
  poll.start(250);
  const int rc = app.exec();
  return exitCode >= 0 ? exitCode : rc;
}
