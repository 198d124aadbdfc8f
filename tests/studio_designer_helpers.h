// Helpers of the designer QtTests (studio_designer_test, studio_guided_test): the walk-through's
// window and record, shared photos and models, drops of model files on the viewport, and points
// of the prepared scene.
#pragma once

#include "document.h"
#include "main_window.h"
#include "render_controller.h"
#include "viewport.h"

#include "studio_workflow_steps.h"

#include "inlay/engine/pipeline.h"

#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QMimeData>
#include <QUrl>
#include <QtTest>

#include <optional>
#include <string>

namespace inlay::test {

using studio::Document;
using studio::MainWindow;
using studio::Viewport;

// A designer walk-through: the main window shown as for a user, the record of its steps
// (screenshots and figures.csv in `artifacts`, a folder of the build tree) and the timings it
// measures ("figure,milliseconds" rows). GUI thread only.
struct DesignerWalk {
  explicit DesignerWalk(const QString& artifacts) : log(artifacts) {}

  // Shows the window, opens `photo` (the steps' clock restarted) and waits up to `timeoutMs`
  // until its scene is estimated; records the step "photo_opened". Empty, or what went wrong.
  QString openPhoto(const QString& photo, int timeoutMs) {
    if (!showForWorkflow(window)) return QStringLiteral("the window was not exposed");
    log.restart();
    if (!window.openPath(photo)) return QStringLiteral("could not open ") + photo;
    if (!waitReady(window.document(), timeoutMs)) {
      const QString error = window.document()->prepareError();
      return error.isEmpty() ? QStringLiteral("the scene was not ready in time") : error;
    }
    if (!step(QStringLiteral("photo_opened"), timeoutMs))
      return QStringLiteral("the screenshot of photo_opened was not written");
    return {};
  }

  // Waits (up to `timeoutMs`) until the viewport shows the current scene rendered at full
  // preview resolution (not a 1/4 preview of a few samples), so a step's screenshot shows what
  // the step did; returns at once while the scene is not ready (there is no render then).
  // False when it timed out (the shot is taken anyway; the test goes on).
  bool settle(int timeoutMs) {
    const auto* r = window.renderer();
    if (!window.document()->isReady()) return true;
    return QTest::qWaitFor(
        [r] {
          return r->isCurrent() && r->hasFrame() && r->frameInfo().resolutionDivider == 1 &&
                 r->frameInfo().spp >= 2;
        },
        timeoutMs);
  }
  // Records the step (its time first) and its screenshot once settled.
  bool step(const QString& name, int timeoutMs) {
    return log.step(&window, name, [this, name, timeoutMs] {
      if (!settle(timeoutMs)) qInfo("%s: shot before the preview settled", qPrintable(name));
    });
  }

  // Writes figures.csv (the timings, then each step's seconds) and prints both; false when the
  // file could not be written.
  bool report() const {
    const bool written = log.writeFigures(QStringLiteral("figures.csv"), timings);
    qInfo("timings: %s", qPrintable(timings.join(QStringLiteral("; "))));
    qInfo("steps (name, seconds since the photo was opened): %s",
          qPrintable(log.steps().join(QStringLiteral("; "))));
    return written;
  }

  StepLog log;
  MainWindow window;
  QStringList timings;
};

inline QString sharedFile(const QString& relative) {
  const QString shared = qEnvironmentVariable("INLAY_SHARED_DIR");
  const QString path = shared + QLatin1Char('/') + relative;
  return !shared.isEmpty() && QFile::exists(path) ? QFileInfo(path).absoluteFilePath() : QString();
}

inline bool writeText(const QString& path, const QByteArray& text) {
  QFile f(path);
  return f.open(QIODevice::WriteOnly) && f.write(text) == text.size();
}

// A small glTF 2.0 file (one embedded buffer): a box `w` x `h` x `d` metres, or in any unit the
// caller means, standing on y = 0.
inline QByteArray boxGltf(double w, double h, double d) {
  QByteArray bin;
  auto putF = [&](float v) { bin.append(reinterpret_cast<const char*>(&v), 4); };
  auto putU = [&](quint16 v) { bin.append(reinterpret_cast<const char*>(&v), 2); };
  for (int i = 0; i < 8; ++i) {
    putF(float(i & 1 ? w / 2 : -w / 2));
    putF(float(i & 2 ? h : 0));
    putF(float(i & 4 ? d / 2 : -d / 2));
  }
  const quint16 faces[36] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                             2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  for (quint16 f : faces) putU(f);
  QByteArray json =
      QStringLiteral(
          R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]}],
"materials":[{"name":"oak","pbrMetallicRoughness":{"baseColorFactor":[0.55,0.35,0.2,1],"metallicFactor":0,"roughnessFactor":0.6}}],
"buffers":[{"byteLength":%1,"uri":"data:application/octet-stream;base64,%2"}],
"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":96},{"buffer":0,"byteOffset":96,"byteLength":72}],
"accessors":[{"bufferView":0,"componentType":5126,"count":8,"type":"VEC3","min":[%3,0,%5],"max":[%4,%6,%7]},
{"bufferView":1,"componentType":5123,"count":36,"type":"SCALAR"}]})")
          .arg(bin.size())
          .arg(QString::fromLatin1(bin.toBase64()))
          .arg(-w / 2)
          .arg(w / 2)
          .arg(-d / 2)
          .arg(h)
          .arg(d / 2)
          .toUtf8();
  return json;
}

// A small bookshelf side as OBJ without a unit: a U-shaped (concave) front and back face, 8
// corners each, joined by quads. 1 x 1.8 x 0.3 units.
inline QByteArray concaveShelfObj() {
  const double xy[8][2] = {{0, 0},     {1, 0},     {1, 1.8},   {0.8, 1.8},
                           {0.8, 0.2}, {0.2, 0.2}, {0.2, 1.8}, {0, 1.8}};
  QByteArray obj = "# a U-shaped shelf with concave octagon faces\n";
  for (double z : {0.0, 0.3})
    for (const auto& p : xy)
      obj += QByteArray("v ") + QByteArray::number(p[0]) + ' ' + QByteArray::number(p[1]) + ' ' +
             QByteArray::number(z) + '\n';
  obj += "f 8 7 6 5 4 3 2 1\nf 9 10 11 12 13 14 15 16\n";
  for (int i = 0; i < 8; ++i) {
    const int a = i + 1, b = (i + 1) % 8 + 1;
    obj += "f " + QByteArray::number(a) + ' ' + QByteArray::number(b) + ' ' + QByteArray::number(b + 8) +
           ' ' + QByteArray::number(a + 8) + '\n';
  }
  return obj;
}

// Drops the file URL on the viewport at `widgetPos`, as a file manager or the model library's
// thumbnails do (text/uri-list): enter, move, drop.
inline bool dropUrl(QWidget* on, const QString& path, QPoint widgetPos) {
  QMimeData data;
  data.setData(QStringLiteral("text/uri-list"), QUrl::fromLocalFile(path).toEncoded() + "\r\n");
  QDragEnterEvent enter(widgetPos, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
  QCoreApplication::sendEvent(on, &enter);
  if (!enter.isAccepted()) return false;
  QDragMoveEvent move(widgetPos, Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
  QCoreApplication::sendEvent(on, &move);
  QDropEvent drop(QPointF(widgetPos), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
  QCoreApplication::sendEvent(on, &drop);
  QCoreApplication::processEvents();  // the viewport hands the drop on once it has returned
  return drop.isAccepted();
}

inline bool waitNoPendingModels(MainWindow& w, int timeoutMs) {
  QElapsedTimer t;
  t.start();
  while (w.pendingModelCount() > 0 && t.elapsed() < timeoutMs) QTest::qWait(20);
  return w.pendingModelCount() == 0;
}

// Every key of every object, as the scene file writes them.
inline std::string objectsJson(const Document* doc) {
  SceneDoc d;
  d.objects = doc->scene().objects;
  return sceneToJson(d);
}

// The supporting surface's height under object `i` (0: the floor).
inline double standsAtY(const Document* doc, int i) {
  return doc->prepared()->placements[size_t(i)].baseWorld.y();
}

// A floor pixel near the bottom middle of the photo and a wall pixel above the floor line.
inline std::optional<Vec2> floorPixel(const Document* doc, double fx) {
  const Camera& cam = doc->prepared()->camera;
  for (double fy = 0.95; fy > 0.4; fy -= 0.02) {
    const Vec2 px(fx * cam.widthPx, fy * cam.heightPx);
    const auto hit = doc->prepared()->geometry.intersect(cam.rayThroughPixel(px), true);
    if (hit && std::abs(hit->pointWorld.y()) < 1e-6) return px;
  }
  return std::nullopt;
}

// The brightest 40 x 18 pixel patch in the upper 45 % of the photo (a ceiling light), in image
// pixels.
inline QRectF brightestPatch(const QImage& photo) {
  const QImage g = photo.convertToFormat(QImage::Format_Grayscale8);
  const int w = 40, h = 18;
  long best = -1;
  QRectF out;
  for (int y = 0; y + h < int(0.45 * g.height()); y += 3)
    for (int x = 0; x + w < g.width(); x += 4) {
      long sum = 0;
      for (int r = y; r < y + h; r += 2)
        for (int c = x; c < x + w; c += 2) sum += g.constScanLine(r)[c];
      if (sum > best) best = sum, out = QRectF(x, y, w, h);
    }
  return out;
}

inline QByteArray readAll(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// The widget point where a world point shows (the object's camera).
inline QPoint widgetOf(const Document* doc, const Viewport* view, const Vec3& world) {
  const std::optional<Vec2> px = doc->prepared()->camera.project(world);
  return px ? view->widgetFromImage(*px).toPoint() : QPoint(-1, -1);
}

}  // namespace inlay::test
