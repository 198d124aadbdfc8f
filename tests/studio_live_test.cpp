// The studio's newer edits, offscreen, through the mouse where a user would use it: vanishing
// lines drawn by the user (camera re-estimated with that vanishing point, drawn with residuals,
// saved), marks reshaped point by point (one undo step per drag), a live language switch
// (de -> fr -> en), two studios with their own recovery files, object edits taken while the
// scene re-prepares, and the material of a real room surface.
#include "autosave.h"
#include "docks.h"
#include "document.h"
#include "i18n.h"
#include "main_window.h"
#include "render_controller.h"
#include "viewport.h"
#include "child_process.h"
#include "studio_test_support.h"

#include "inlay/engine/pipeline.h"
#include "inlay/modeling/scene_file.h"

#include <QAction>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QApplication>
#include <QLabel>
#include <QLockFile>
#include <QListWidget>
#include <QMenu>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

#include <cstdlib>

using namespace inlay;
using namespace inlay::studio;

namespace {

QString exampleFile(const QString& name) {
  const QString src = qEnvironmentVariable("INLAY_SOURCE_DIR");
  if (!src.isEmpty() && QFile::exists(src + QStringLiteral("/resources/example/") + name))
    return src + QStringLiteral("/resources/example/") + name;
  const std::string scene = exampleScenePath();
  if (scene.empty()) return {};
  return QFileInfo(QString::fromStdString(scene)).absoluteDir().filePath(name);
}

bool waitPrepared(Document* doc) {
  QElapsedTimer t;
  t.start();
  while (doc->state() == Document::State::Preparing && t.elapsed() < inlay::test::waitMs(180000))
    QTest::qWait(20);
  return doc->state() != Document::State::Preparing;
}

// A left drag between two image points.
void dragImage(Viewport* view, const Vec2& a, const Vec2& b, int steps = 5) {
  const QPoint from = view->widgetFromImage(a).toPoint(), to = view->widgetFromImage(b).toPoint();
  QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, from);
  for (int k = 1; k <= steps; ++k) QTest::mouseMove(view, from + (to - from) * k / steps);
  QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, to);
}

// The finite vanishing point of axis `k` of an estimate, or nullopt (at infinity).
std::optional<Vec2> vanishingPoint(const CameraEstimate& e, int k) {
  const Vec3& h = e.vanishingPoints[size_t(k)].homogeneousPx;
  if (std::abs(h.z()) < 1e-9) return std::nullopt;
  return Vec2(h.x() / h.z(), h.y() / h.z());
}

QString plainTitle(const QMenu* menu) { return menu->title().remove(QLatin1Char('&')); }

// A screenshot beside the workflow test's (build tree, studio_workflow_artifacts/live_<name>.png).
void shot(QWidget* w, const QString& name) {
  QDir dir(QCoreApplication::applicationDirPath());
  dir.mkpath(QStringLiteral("studio_workflow_artifacts"));
  const QString path = dir.filePath(QStringLiteral("studio_workflow_artifacts/live_%1.png").arg(name));
  QVERIFY2(w->grab().save(path), qPrintable(path));
}

}  // namespace

class StudioLiveTest : public QObject {
  Q_OBJECT

 private Q_SLOTS:
  void initTestCase();
  void cleanupTestCase();
  void init();
  void cleanup();
  void vanishingLinesFixTheCamera();
  void marksReshapePointByPoint();
  void languageSwitchAppliesAtOnce();
  void twoStudiosKeepTheirOwnRecovery();
  void objectEditsWhilePreparing();
  void roomSurfaceMaterial();

 private:
  std::unique_ptr<MainWindow> openWindow(const QString& path);
  std::unique_ptr<MainWindow> window_;
};

void StudioLiveTest::initTestCase() {
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName(QStringLiteral("InlayTest"));
  // One settings and recovery folder a process: two runs of this test at once (two build trees
  // of one user) must not see, offer or discard each other's recovery files.
  QCoreApplication::setApplicationName(
      QStringLiteral("studio_live_test-%1").arg(QCoreApplication::applicationPid()));
  qunsetenv("INLAY_LANG");
  QSettings().remove(QStringLiteral("language"));
  removeTranslators();
}

void StudioLiveTest::cleanupTestCase() { QFile::remove(QSettings().fileName()); }

void StudioLiveTest::init() {
  if (!QFile::exists(exampleFile(QStringLiteral("scene.json")))) QSKIP("resources/example absent");
}

void StudioLiveTest::cleanup() {
  window_.reset();
  Autosaver::discardAll();
}

std::unique_ptr<MainWindow> StudioLiveTest::openWindow(const QString& path) {
  auto w = std::make_unique<MainWindow>();
  w->setInteractive(false);
  w->resize(1100, 750);
  w->show();
  if (!QTest::qWaitForWindowExposed(w.get()) || !w->openPath(path)) return nullptr;
  return w;
}

void StudioLiveTest::vanishingLinesFixTheCamera() {
  window_ = openWindow(exampleFile(QStringLiteral("photo.png")));  // all estimated
  QVERIFY(window_);
  Document* doc = window_->document();
  Viewport* view = window_->viewport();
  QVERIFY(waitPrepared(doc) && doc->isReady());
  const CameraEstimate before = *doc->lastEstimate();
  const std::optional<Vec2> vp = vanishingPoint(before, 2);
  QVERIFY2(vp, "the example's depth direction should meet inside the plane");
  // Two lines toward a point 25 px off the estimated one: what a user who disagrees draws.
  const Vec2 wanted = *vp + Vec2(25, -12);
  const Vec2 p0(40, 330), p1(470, 350);
  const std::array<Vec2, 4> drawn{p0, p0 + 0.45 * (wanted - p0), p1, p1 + 0.45 * (wanted - p1)};

  window_->toolAction(int(Viewport::Tool::VanishingLines))->trigger();
  QCOMPARE(view->tool(), Viewport::Tool::VanishingLines);
  QTest::keyClick(view, Qt::Key_Z);
  QCOMPARE(view->vanishingAxis(), 2);
  const int steps = doc->undoStack()->count();
  dragImage(view, drawn[0], drawn[1]);
  QCOMPARE(doc->undoStack()->count(), steps);  // one line is not a pair
  dragImage(view, drawn[2], drawn[3]);
  QCOMPARE(doc->undoStack()->count(), steps + 1);
  const auto& lines = doc->scene().camera.vanishingLinesPx[2];
  QVERIFY(lines.has_value());
  for (size_t i = 0; i < 4; ++i) QVERIFY(((*lines)[i] - drawn[i]).norm() < 1.5);
  QVERIFY(waitPrepared(doc));
  QVERIFY2(doc->isReady(), qPrintable(doc->prepareError()));

  // Re-estimated with that vanishing point: it moved to where the user's lines meet.
  const CameraEstimate& after = *doc->lastEstimate();
  const std::optional<Vec2> vpAfter = vanishingPoint(after, 2);
  QVERIFY(vpAfter);
  const Vec3 l0 =
      Vec3((*lines)[0].x(), (*lines)[0].y(), 1).cross(Vec3((*lines)[1].x(), (*lines)[1].y(), 1));
  const Vec3 l1 =
      Vec3((*lines)[2].x(), (*lines)[2].y(), 1).cross(Vec3((*lines)[3].x(), (*lines)[3].y(), 1));
  const Vec3 meet = l0.cross(l1);
  const Vec2 users(meet.x() / meet.z(), meet.y() / meet.z());
  qInfo("z vanishing point: estimated (%.1f, %.1f), user's (%.1f, %.1f), after (%.1f, %.1f)", vp->x(),
        vp->y(), users.x(), users.y(), vpAfter->x(), vpAfter->y());
  QVERIFY((*vpAfter - users).norm() < 0.5 * (*vp - users).norm());
  // The user's segments are in the estimate with finite residuals, and the overlay draws them.
  int userSegments = 0;
  for (const LineSegment& s : after.segments)
    if (s.userGiven && s.family == 2) {
      ++userSegments;
      QVERIFY(std::isfinite(s.residualPx) && s.residualPx < 5);
    }
  QCOMPARE(userSegments, 2);
  const QImage shown = view->grab().toImage();
  // The line's centre pixel near the segment's middle: the bluest within 2 px (at a fractional
  // zoom the rounded middle can fall on the line's anti-aliased edge).
  const QPoint around = view->widgetFromImage(0.5 * (drawn[0] + drawn[1])).toPoint();
  QPoint mid = around;
  auto blueness = [](const QColor& q) { return q.blue() - q.red(); };
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      const QPoint q = around + QPoint(dx, dy);
      if (shown.rect().contains(q) && blueness(shown.pixelColor(q)) > blueness(shown.pixelColor(mid)))
        mid = q;
    }
  const QColor c = shown.pixelColor(mid);
  QVERIFY2(c.blue() > c.red() + 40 && c.blue() > c.green() + 25, qPrintable(c.name()));
  shot(window_.get(), QStringLiteral("vanishing_lines"));

  // Saved under camera.vanishing_lines_px and read back.
  QTemporaryDir dir;
  QVERIFY(window_->saveTo(dir.filePath(QStringLiteral("lines.json"))));
  auto loaded = loadSceneFile(dir.filePath(QStringLiteral("lines.json")).toStdString());
  QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.error().message().c_str());
  QVERIFY(loaded->doc.camera.vanishingLinesPx[2] == lines);
  // Undoable; a degenerate pair is refused with a reason.
  doc->undoStack()->undo();
  QVERIFY(!doc->scene().camera.vanishingLinesPx[2]);
  view->setTool(Viewport::Tool::Select);
  const QColor without = view->grab().toImage().pixelColor(mid);
  QVERIFY2(std::abs(without.blue() - c.blue()) > 30, qPrintable(without.name()));
  QString reason;
  QVERIFY(!doc->setVanishingLines(
      0, std::array<Vec2, 4>{Vec2(0, 0), Vec2(10, 10), Vec2(20, 20), Vec2(30, 30)}, &reason));
  QVERIFY(!reason.isEmpty());
  QVERIFY(!doc->setVanishingLines(
      1, std::array<Vec2, 4>{Vec2(0, 0), Vec2(0.5, 0), Vec2(20, 20), Vec2(30, 35)}, &reason));
}

void StudioLiveTest::marksReshapePointByPoint() {
  window_ = openWindow(exampleFile(QStringLiteral("scene.json")));
  QVERIFY(window_);
  Document* doc = window_->document();
  Viewport* view = window_->viewport();
  QVERIFY(waitPrepared(doc) && doc->isReady());
  // One mark of each kind, away from the object and the back-wall corners.
  QVERIFY(doc->addShaft({300, 290, 380, 330}, {300, 100, 340, 150}));
  QVERIFY(doc->addExtrusion({{60, 250}, {150, 250}, {160, 280}, {50, 280}}, {60, 330}));
  OccluderKeys occ;
  occ.foregroundScribblesPx = {{{420, 200}, {430, 210}, {440, 220}}};
  occ.backgroundScribblesPx = {{{470, 200}, {480, 240}}};
  QVERIFY(doc->addOccluder(occ));
  const SceneMarks start = doc->marks();

  struct Case {
    MarkRef mark;
    int point;
    Vec2 to;
  };
  const int lastLight = int(doc->scene().lights.size()) - 1;
  const Vec2 lightPoint = doc->scene().lights[size_t(lastLight)].pointsPx[1];
  const Case cases[] = {
      {{MarkKind::Light, lastLight}, 1, lightPoint + Vec2(6, 9)},
      {{MarkKind::Shaft, int(doc->scene().shafts.size()) - 1}, 2, Vec2(395, 342)},  // x1y1 corner
      {{MarkKind::Surface, int(doc->scene().surfaces.size()) - 1}, 1, Vec2(158, 244)},
      {{MarkKind::Occluder, int(doc->scene().occluders.size()) - 1}, 1, Vec2(433, 204)},
  };
  for (const Case& c : cases) {
    std::optional<MarkPoint> from;
    for (const MarkPoint& m : doc->markPoints())
      if (m.mark == c.mark && m.point == c.point) from = m;
    QVERIFY(from);
    // Hit-testing finds that very point from the document's state.
    const std::optional<MarkPoint> hit = view->markPointAt(view->widgetFromImage(from->px));
    QVERIFY(hit && hit->mark == c.mark && hit->point == c.point);
    const int steps = doc->undoStack()->count();
    const SceneMarks before = doc->marks();
    const std::vector<MarkPoint> pointsBefore = doc->markPoints();
    dragImage(view, from->px, c.to, 6);
    QCOMPARE(doc->undoStack()->count(), steps + 1);  // the whole drag: one step
    const std::vector<MarkPoint> pointsAfter = doc->markPoints();
    QCOMPARE(pointsAfter.size(), pointsBefore.size());
    int moved = 0;
    for (size_t k = 0; k < pointsAfter.size(); ++k) {
      const MarkPoint& m = pointsAfter[k];
      QVERIFY(m.mark == pointsBefore[k].mark && m.point == pointsBefore[k].point);
      if (m.mark == c.mark && m.point == c.point) {
        QVERIFY2((m.px - c.to).norm() < 1.5,
                 qPrintable(QStringLiteral("%1,%2").arg(m.px.x()).arg(m.px.y())));
        continue;
      }
      // A box corner drags its two neighbours along one coordinate each; the opposite stays.
      const bool neighbour = c.mark.kind == MarkKind::Shaft && m.mark == c.mark &&
                             m.point / 4 == c.point / 4 && (m.point - c.point + 4) % 2 == 1;
      if (!neighbour) moved += (m.px - pointsBefore[k].px).norm() > 1e-9;
    }
    QCOMPARE(moved, 0);
    doc->undoStack()->undo();
    QVERIFY(doc->marks() == before);
    doc->undoStack()->redo();
  }
  doc->setSelectedMark(MarkRef{MarkKind::Surface, int(doc->scene().surfaces.size()) - 1});
  shot(window_.get(), QStringLiteral("reshaped_marks"));
  // A box that would collapse is refused with a reason.
  QString reason;
  QVERIFY(!doc->moveMarkPoint({MarkKind::Shaft, 0}, 0, Vec2(395, 342), 0, &reason));  // box collapses
  QVERIFY(!reason.isEmpty());
  while (doc->undoStack()->canUndo() && !(doc->marks() == start)) doc->undoStack()->undo();
  QVERIFY(doc->marks() == start);
}

void StudioLiveTest::languageSwitchAppliesAtOnce() {
  window_ = std::make_unique<MainWindow>();
  window_->setInteractive(false);
  window_->show();
  QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
  QCOMPARE(plainTitle(window_->fileMenu()), QStringLiteral("File"));
  auto choose = [&](const QString& name) {
    for (QAction* a : window_->findChildren<QAction*>())
      if (a->text() == name) {
        a->trigger();
        QCoreApplication::processEvents();  // QEvent::LanguageChange is posted
        return true;
      }
    return false;
  };
  struct Step {
    QString menuItem, file, edit, tools, layers, undo;
  };
  const Step steps[] = {
      {QStringLiteral("Deutsch"), QStringLiteral("Datei"), QStringLiteral("Bearbeiten"),
       QStringLiteral("Werkzeuge"), QStringLiteral("Ebenen"), QStringLiteral("Rückgängig")},
      {QStringLiteral("Français"), QStringLiteral("Fichier"), QStringLiteral("Édition"),
       QStringLiteral("Outils"), QStringLiteral("Calques"), QStringLiteral("Annuler")},
      {QStringLiteral("English"), QStringLiteral("File"), QStringLiteral("Edit"),
       QStringLiteral("Tools"), QStringLiteral("Layers"), QStringLiteral("Undo")},
  };
  for (const Step& s : steps) {
    QVERIFY2(choose(s.menuItem), qPrintable(s.menuItem));
    QCoreApplication::processEvents();
    // The same window, without a restart: menus, docks, toolbar actions, status bar.
    QCOMPARE(plainTitle(window_->fileMenu()), s.file);
    QCOMPARE(plainTitle(window_->editMenu()), s.edit);
    QCOMPARE(plainTitle(window_->toolsMenu()), s.tools);
    QCOMPARE(window_->layersDock()->windowTitle(), s.layers);
    QCOMPARE(window_->undoAction()->text().remove(QLatin1Char('&')), s.undo);
    // The status bar's figures: their tooltips in the new language.
    const QString tip = QCoreApplication::translate("inlay::studio::MainWindow",
                                                    "Samples per pixel of the shown composite");
    if (s.menuItem != QLatin1String("English"))
      QVERIFY(tip != QLatin1String("Samples per pixel of the shown composite"));
    const QList<QLabel*> labels = window_->findChildren<QLabel*>();
    QVERIFY(std::any_of(labels.begin(), labels.end(), [&](QLabel* l) { return l->toolTip() == tip; }));
  }
  const QString germanTool = [&] {
    choose(QStringLiteral("Deutsch"));
    return window_->toolAction(0)->text();
  }();
  choose(QStringLiteral("English"));
  QVERIFY(germanTool != window_->toolAction(0)->text());
  QSettings().remove(QStringLiteral("language"));
  removeTranslators();
}

void StudioLiveTest::twoStudiosKeepTheirOwnRecovery() {
  Autosaver::discardAll();
  auto a = openWindow(exampleFile(QStringLiteral("scene.json")));
  auto b = openWindow(exampleFile(QStringLiteral("scene.json")));
  QVERIFY(a && b);
  QVERIFY(waitPrepared(a->document()) && waitPrepared(b->document()));
  QVERIFY(a->document()->isReady() && b->document()->isReady());
  QVERIFY(a->autosaver()->scenePath() != b->autosaver()->scenePath());
  QVERIFY(a->document()->addLight({{380, 20}, {420, 22}, {420, 32}, {380, 30}}));
  QVERIFY(b->document()->moveObject(0, b->document()->scene().objects[0].basePx + Vec2(-20, 3)));
  QVERIFY(a->autosaver()->saveNow() && b->autosaver()->saveNow());
  QVERIFY(QFile::exists(a->autosaver()->scenePath()) && QFile::exists(b->autosaver()->scenePath()));
  // Each file holds its own studio's work.
  auto sa = loadSceneFile(a->autosaver()->scenePath().toStdString());
  auto sb = loadSceneFile(b->autosaver()->scenePath().toStdString());
  QVERIFY(sa.ok() && sb.ok());
  QCOMPARE(sa->doc.lights.size(), b->document()->scene().lights.size() + 1);
  QVERIFY(sb->doc.objects[0].basePx == b->document()->scene().objects[0].basePx);
  QVERIFY(sa->doc.objects[0].basePx != sb->doc.objects[0].basePx);
  // Both studios run: nothing is offered to a third.
  QVERIFY(Autosaver::pendingAll().empty());
  // A studio that died (its process is gone, its lock stale) left work behind: only that is
  // offered, never the living studios' files.
  QString prefix = a->autosaver()->scenePath();
  prefix.truncate(prefix.lastIndexOf(QStringLiteral("-recovery-")) + int(qstrlen("-recovery-")));
  const QString deadPath = prefix + QStringLiteral("dead-0.json");
  QVERIFY(QFile::copy(a->autosaver()->scenePath(), deadPath));
  test::ChildProcess dying;  // a real process (posix_spawn), so under ThreadSanitizer too
  QVERIFY(dying.start({"--lock-and-die", (prefix + QStringLiteral("dead-0.lock")).toStdString()}, {},
                      false));
  QCOMPARE(QString::fromStdString(test::ChildProcess::describe(
               dying.waitFor(std::chrono::milliseconds(test::waitMs(30000))))),
           QStringLiteral("exit code 0"));
  QVERIFY(QFile::exists(prefix + QStringLiteral("dead-0.lock")));
  const std::vector<Autosaver::Recovery> offered = Autosaver::pendingAll();
  QCOMPARE(int(offered.size()), 1);
  QCOMPARE(offered[0].scenePath, deadPath);
  // A third studio restores it into its own files; the dead studio's files go.
  auto c = std::make_unique<MainWindow>();
  c->setInteractive(false);
  QVERIFY(c->restoreRecovery());
  QVERIFY(!QFile::exists(deadPath));
  QVERIFY(QFile::exists(c->autosaver()->scenePath()));
  QCOMPARE(c->document()->scene().lights.size(), sa->doc.lights.size());
  QVERIFY(Autosaver::pendingAll().empty());
  QVERIFY(QFile::exists(a->autosaver()->scenePath()) && QFile::exists(b->autosaver()->scenePath()));
  a.reset();
  c.reset();
  b.reset();
}

void StudioLiveTest::objectEditsWhilePreparing() {
  window_ = openWindow(exampleFile(QStringLiteral("scene.json")));
  QVERIFY(window_);
  Document* doc = window_->document();
  Viewport* view = window_->viewport();
  QVERIFY(waitPrepared(doc) && doc->isReady());
  const Vec2 base0 = doc->scene().objects[0].basePx;
  QVERIFY(doc->addLight({{380, 20}, {420, 22}, {420, 32}, {380, 30}}));  // re-prepares
  QCOMPARE(doc->state(), Document::State::Preparing);
  // A drag of the object with the mouse while the scene re-prepares: taken at once.
  const Vec2 target = base0 + Vec2(-25, 5);
  dragImage(view, base0, target, 5);
  QCOMPARE(doc->state(), Document::State::Preparing);
  QVERIFY((doc->scene().objects[0].basePx - target).norm() < 1.5);
  QCOMPARE(view->objectAt(view->widgetFromImage(doc->scene().objects[0].basePx)), 0);  // drawn there
  MaterialKeys red = doc->scene().objects[0].material;
  red.preset = "glossy";
  red.albedo = Vec3(0.8, 0.1, 0.1);
  QVERIFY(doc->setMaterial(0, red));
  QVERIFY(doc->setObjectHeight(0, 0.42));
  QVERIFY(waitPrepared(doc));
  QVERIFY2(doc->isReady(), qPrintable(doc->prepareError()));
  // The new scene caught up: the object stands where the document says, in its new material.
  const PreparedScene* p = doc->prepared();
  QVERIFY((*p->camera.project(p->placements[0].baseWorld) - doc->scene().objects[0].basePx).norm() <
          1e-3);
  QCOMPARE(p->doc.objects[0].heightM, 0.42);
  QCOMPARE(p->renderScene.objects[0].material.kind, Material::Kind::Glossy);
  QVERIFY(p->renderScene.objects[0].material.albedo.isApprox(Vec3(0.8, 0.1, 0.1)));
  // Undo walks back through the edits made while preparing.
  doc->undoStack()->undo();
  doc->undoStack()->undo();
  doc->undoStack()->undo();
  QVERIFY((doc->scene().objects[0].basePx - base0).norm() < 1e-9);
}

void StudioLiveTest::roomSurfaceMaterial() {
  window_ = openWindow(exampleFile(QStringLiteral("scene.json")));
  QVERIFY(window_);
  Document* doc = window_->document();
  QVERIFY(waitPrepared(doc) && doc->isReady());
  PropertiesDock* dock = window_->propertiesDock();
  QComboBox* surface = dock->roomSurfaceBox();
  QVERIFY(surface->isEnabled());
  const int floor = surface->findData(QStringLiteral("floor"));  // shown as "Floor"
  QVERIFY(floor >= 0);
  surface->setCurrentIndex(floor);
  QCOMPARE(dock->roomPresetBox()->currentData().toString(), QStringLiteral("diffuse"));
  const int steps = doc->undoStack()->count();
  // Glossy, then its roughness: two undo steps, re-prepared, rendered.
  dock->roomPresetBox()->setCurrentIndex(1);
  Q_EMIT dock->roomPresetBox()->activated(1);
  QCOMPARE(doc->undoStack()->count(), steps + 1);
  QCOMPARE(doc->scene().room.materials.at("floor").preset, std::string("glossy"));
  QVERIFY(dock->roomRoughnessBox()->isEnabled());
  dock->roomRoughnessBox()->setValue(0.35);
  QCOMPARE(doc->undoStack()->count(), steps + 2);
  QCOMPARE(doc->scene().room.materials.at("floor").roughness, 0.35);
  QVERIFY(waitPrepared(doc) && doc->isReady());
  const PreparedScene* p = doc->prepared();
  size_t floorId = 0;
  while (floorId < p->geometry.surfaces.size() && p->geometry.surfaces[floorId].name != "floor")
    ++floorId;
  QVERIFY(floorId < p->renderScene.roomMaterials.size());
  QVERIFY(p->renderScene.roomMaterials[floorId].has_value());
  QCOMPARE(p->renderScene.roomMaterials[floorId]->kind, Material::Kind::Glossy);
  QCOMPARE(p->renderScene.roomMaterials[floorId]->roughness, 0.35);
  shot(window_.get(), QStringLiteral("glossy_floor"));
  // Saved under room.materials.
  QTemporaryDir dir;
  QVERIFY(window_->saveTo(dir.filePath(QStringLiteral("glossy.json"))));
  auto loaded = loadSceneFile(dir.filePath(QStringLiteral("glossy.json")).toStdString());
  QVERIFY(loaded.ok());
  QCOMPARE(loaded->doc.room.materials.at("floor").roughness, 0.35);
  // A mirror on the left wall; back to matte by undo, and by choosing Matte.
  const int wall = surface->findData(QStringLiteral("wall_left"));
  QVERIFY(wall >= 0);
  surface->setCurrentIndex(wall);
  dock->roomPresetBox()->setCurrentIndex(2);
  Q_EMIT dock->roomPresetBox()->activated(2);
  QCOMPARE(doc->scene().room.materials.at("wall_left").preset, std::string("mirror"));
  doc->undoStack()->undo();
  QVERIFY(!doc->scene().room.materials.count("wall_left"));
  surface->setCurrentIndex(surface->findData(QStringLiteral("floor")));
  QCOMPARE(dock->roomPresetBox()->currentData().toString(), QStringLiteral("glossy"));
  dock->roomPresetBox()->setCurrentIndex(0);
  Q_EMIT dock->roomPresetBox()->activated(0);
  QVERIFY(doc->scene().room.materials.empty());
  QString reason;
  QVERIFY(!doc->setRoomMaterial("no_such_wall", RoomMaterialKeys{}, &reason));
  QVERIFY(!reason.isEmpty());
}

int main(int argc, char** argv) {
  // A studio that dies holding its lock: takes the lock at argv[2] and exits without unlocking.
  if (argc >= 3 && qstrcmp(argv[1], "--lock-and-die") == 0) {
    QCoreApplication app(argc, argv);
    auto* lock = new QLockFile(QString::fromLocal8Bit(argv[2]));
    if (!lock->tryLock(0)) return 1;
    std::_Exit(0);
  }
  QApplication app(argc, argv);
  StudioLiveTest test;
  return QTest::qExec(&test, argc, argv);
}
#include "studio_live_test.moc"
