#include "document.h"

#include "prepare_worker.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QUndoCommand>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <tuple>

namespace inlay::studio {
namespace {

bool sameMaterial(const MaterialKeys& a, const MaterialKeys& b) {
  return a.preset == b.preset && a.albedo == b.albedo && a.roughness == b.roughness && a.ior == b.ior &&
         a.rgb == b.rgb;
}

bool samePlacement(const ObjectKeys& a, const ObjectKeys& b) {
  return a.basePx == b.basePx && a.heightM == b.heightM && a.yawDeg == b.yawDeg;
}

bool sameShown(const ObjectKeys& a, const ObjectKeys& b) {
  return a.name == b.name && a.hidden == b.hidden;
}

bool sameObject(const ObjectKeys& a, const ObjectKeys& b) {
  return samePlacement(a, b) && sameMaterial(a.material, b.material) && sameShown(a, b);
}

// What changed between two versions of object `index`.
ChangeEvent objectChange(int index, const ObjectKeys& before, const ObjectKeys& after) {
  ChangeEvent event;
  event.objectIndex = index;
  if (!samePlacement(before, after)) event.what |= ChangeEvent::ObjectPlacement;
  if (!sameMaterial(before.material, after.material)) event.what |= ChangeEvent::ObjectMaterial;
  if (!sameShown(before, after)) event.what |= ChangeEvent::ObjectShown;
  return event;
}

// A path as it should be written in a scene file saved in `dir`: relative when the file lies
// inside that folder, absolute otherwise (a "../../x" path breaks as soon as the scene moves).
std::string pathForFolder(const std::string& resolved, const std::string& asWritten, const QDir& dir) {
  if (resolved.empty()) return asWritten;
  const QString rel = dir.relativeFilePath(QString::fromStdString(resolved));
  if (rel.startsWith(QLatin1String(".."))) return resolved;
  return rel.toStdString();
}

void putMarks(SceneDoc& doc, const SceneMarks& m) { static_cast<SceneMarks&>(doc) = m; }

bool finitePoints(const std::vector<Vec2>& points) {
  return std::all_of(points.begin(), points.end(),
                     [](const Vec2& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); });
}

// Twice the signed area of a polygon (shoelace).
double doubleArea(const std::vector<Vec2>& poly) {
  double a = 0;
  for (size_t i = 0; i < poly.size(); ++i) {
    const Vec2& p = poly[i];
    const Vec2& q = poly[(i + 1) % poly.size()];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return a;
}

bool validBox(const std::array<double, 4>& b) {
  return std::all_of(b.begin(), b.end(), [](double v) { return std::isfinite(v); }) &&
         b[2] - b[0] >= 2 && b[3] - b[1] >= 2;
}

}  // namespace

bool operator==(const SceneMarks& a, const SceneMarks& b) {
  // The scene file's serialisation compares every key, present or not.
  SceneDoc x, y;
  putMarks(x, a);
  putMarks(y, b);
  return sceneToJson(x) == sceneToJson(y);
}

// A command whose text is built again in the current language on retranslate().
class TextCommand : public QUndoCommand {
 public:
  explicit TextCommand(UndoText text) : text_(std::move(text)) { retranslate(); }
  void retranslate() { setText(text_ ? text_() : QString()); }

 private:
  UndoText text_;
};

// One undoable change of the scene's marks (a corner, a light, a shaft, ...). Moves of one drag
// share a merge id and collapse into one command; one that ends where it started is obsolete.
class MarksCommand : public TextCommand {
 public:
  MarksCommand(Document* doc, SceneMarks before, SceneMarks after, int mergeId, UndoText text)
      : TextCommand(std::move(text)),
        doc_(doc),
        before_(std::move(before)),
        after_(std::move(after)),
        mergeId_(mergeId) {
    setObsolete(before_ == after_);
  }

  void undo() override { doc_->applyMarks(before_); }
  void redo() override { doc_->applyMarks(after_); }
  int id() const override { return mergeId_ > 0 ? 2 : -1; }
  bool mergeWith(const QUndoCommand* other) override {
    const auto* o = dynamic_cast<const MarksCommand*>(other);
    if (!o || o->mergeId_ != mergeId_) return false;
    after_ = o->after_;
    setObsolete(before_ == after_);
    return true;
  }

 private:
  Document* doc_;
  SceneMarks before_, after_;
  int mergeId_;
};

// One undoable change of one object's keys (placement and/or material). Moves of one drag share
// a merge id and collapse into one command; a command whose before equals its after is
// obsolete and leaves the stack.
class ObjectEditCommand : public TextCommand {
 public:
  ObjectEditCommand(Document* doc, int index, ObjectKeys before, ObjectKeys after, int mergeId,
                    UndoText text)
      : TextCommand(std::move(text)),
        doc_(doc),
        index_(index),
        before_(std::move(before)),
        after_(std::move(after)),
        mergeId_(mergeId) {
    setObsolete(sameObject(before_, after_));
  }

  void undo() override { doc_->applyObject(index_, before_); }
  void redo() override { doc_->applyObject(index_, after_); }
  int id() const override { return mergeId_ > 0 ? 1 : -1; }
  bool mergeWith(const QUndoCommand* other) override {
    const auto* o = dynamic_cast<const ObjectEditCommand*>(other);
    if (!o || o->mergeId_ != mergeId_ || o->index_ != index_) return false;
    after_ = o->after_;
    setObsolete(sameObject(before_, after_));
    return true;
  }

 private:
  Document* doc_;
  int index_;
  ObjectKeys before_, after_;
  int mergeId_;
};

// Inserting (or, with `insert` false, removing) one object. Undo does the opposite. The mesh
// is kept here so redo never reloads a file.
class ObjectListCommand : public TextCommand {
 public:
  ObjectListCommand(Document* doc, bool insert, int index, ObjectKeys keys,
                    std::shared_ptr<const TriangleMesh> mesh, UndoText text)
      : TextCommand(std::move(text)),
        doc_(doc),
        insert_(insert),
        index_(index),
        keys_(std::move(keys)),
        mesh_(std::move(mesh)) {}

  void redo() override { insert_ ? add() : doc_->removeObjectAt(index_); }
  void undo() override { insert_ ? doc_->removeObjectAt(index_) : add(); }

 private:
  void add() { doc_->insertObjectAt(index_, keys_, mesh_); }
  Document* doc_;
  bool insert_;
  int index_;
  ObjectKeys keys_;
  std::shared_ptr<const TriangleMesh> mesh_;
};

Document::Document(QObject* parent) : QObject(parent) {
  thread_.setObjectName(QStringLiteral("inlay-prepare"));
  worker_ = new PrepareWorker;
  worker_->moveToThread(&thread_);
  connect(&thread_, &QThread::finished, worker_, &QObject::deleteLater);
  connect(worker_, &PrepareWorker::progressed, this, [this] {
    const PrepareWorker::Progress p = worker_->latestProgress();
    if (p.jobId == jobId_ && state_ == State::Preparing) Q_EMIT prepareProgress(p.stage, p.fraction);
  });
  connect(worker_, &PrepareWorker::finished, this, [this] { onPrepared(worker_->takeResult()); });
  thread_.start();
}

Document::~Document() {
  if (cancel_) cancel_->cancel();
  thread_.requestInterruption();
  thread_.quit();
  thread_.wait();
}

int Document::newDragId() {
  static std::atomic<int> next{1};
  return next++;
}

void Document::resetTo(SceneDoc doc, const QString& filePath) {
  if (cancel_) cancel_->cancel();
  undo_.clear();
  doc_ = std::move(doc);
  filePath_ = filePath;
  prepared_.reset();
  prepareError_.clear();
  warnings_.clear();
  loadWarnings_.clear();
  estimatedBackWallPx_.reset();
  lastEstimate_.reset();
  roomSurfaceNames_.clear();
  selectedMark_.reset();
  state_ = State::Empty;
  selected_ = doc_.objects.empty() ? -1 : 0;
  Q_EMIT changed({ChangeEvent::SceneReplaced | ChangeEvent::FilePath | ChangeEvent::Selection});
}

bool Document::openSceneFile(const QString& path, QString* error) {
  Expected<SceneLoadResult> loaded = loadSceneFile(QDir::toNativeSeparators(path).toStdString());
  if (!loaded.ok()) {
    if (error) *error = QString::fromStdString(loaded.error().message());
    return false;
  }
  resetTo(std::move(loaded->doc), QFileInfo(path).absoluteFilePath());
  for (const std::string& w : loaded->warnings) loadWarnings_ << QString::fromStdString(w);
  warnings_ = loadWarnings_;
  prepare();
  return true;
}

bool Document::restoreRecovery(const QString& recoveryPath, const QString& originalPath,
                               QString* error) {
  Expected<SceneLoadResult> loaded = loadSceneFile(QDir::toNativeSeparators(recoveryPath).toStdString());
  if (!loaded.ok()) {
    if (error) *error = QString::fromStdString(loaded.error().message());
    return false;
  }
  resetTo(std::move(loaded->doc),
          originalPath.isEmpty() ? QString() : QFileInfo(originalPath).absoluteFilePath());
  undo_.resetClean();  // the restored work is in no file yet
  prepare();
  return true;
}

void Document::newFromPhoto(const QString& photoPath) {
  SceneDoc doc;
  doc.photo = QFileInfo(photoPath).absoluteFilePath().toStdString();
  doc.photoResolved = doc.photo;
  resetTo(std::move(doc), QString());
  prepare();
}

bool Document::saveAs(const QString& path, QString* error) {
  const QFileInfo info(path);
  const QDir dir = info.absoluteDir();
  SceneDoc out = doc_;
  out.photo = pathForFolder(out.photoResolved, out.photo, dir);
  for (ObjectKeys& o : out.objects)
    if (o.mesh.rfind("builtin:", 0) != 0) o.mesh = pathForFolder(o.meshResolved, o.mesh, dir);
  const Status saved = saveSceneFile(info.absoluteFilePath().toStdString(), out);
  if (!saved.ok()) {
    if (error) *error = QString::fromStdString(saved.error().message());
    return false;
  }
  doc_ = std::move(out);
  if (prepared_) {
    prepared_->doc.photo = doc_.photo;
    for (size_t i = 0; i < doc_.objects.size() && i < prepared_->doc.objects.size(); ++i)
      prepared_->doc.objects[i].mesh = doc_.objects[i].mesh;
  }
  undo_.setClean();
  if (filePath_ != info.absoluteFilePath()) {
    filePath_ = info.absoluteFilePath();
    Q_EMIT changed({ChangeEvent::FilePath});
  }
  return true;
}

void Document::prepare() {
  if (cancel_) cancel_->cancel();
  ++jobId_;
  cancel_ = std::make_shared<CancelToken>();
  prepared_.reset();
  prepareError_.clear();
  state_ = State::Preparing;
  Q_EMIT changed({ChangeEvent::PrepareStarted});
  worker_->submit(jobId_, doc_, cancel_);
}

void Document::cancelPrepare() {
  if (state_ != State::Preparing || !cancel_) return;
  cancel_->cancel();
  ++jobId_;  // the cancelled job's result, when it arrives, is dropped
  state_ = State::Empty;
  prepareError_ = tr("Preparation was cancelled.");
  Q_EMIT changed({ChangeEvent::PrepareFinished});
}

void Document::onPrepared(const PrepareResult& result) {
  if (result.jobId != jobId_) return;  // superseded or cancelled
  warnings_ = loadWarnings_ + result.warnings;
  if (result.scene) {
    prepared_ = std::make_unique<PreparedScene>(std::move(*result.scene));
    // The engine may have filled in estimated keys; the objects are the user's, edited perhaps
    // while this scene was prepared.
    const std::vector<ObjectKeys> preparedWith = std::move(prepared_->doc.objects);
    prepared_->doc.objects = doc_.objects;
    if (const QString why = catchUpObjects(preparedWith); !why.isEmpty()) {
      prepared_.reset();
      state_ = State::Failed;
      prepareError_ = why;
      Q_EMIT changed({ChangeEvent::PrepareFinished});
      return;
    }
    // The estimate's own corners only: with the user's corners the box is theirs, and undoing
    // back to the estimate must show the estimate, not their last fix.
    if (!prepared_->doc.layout.backWallPx) estimatedBackWallPx_ = prepared_->backWallPx;
    if (prepared_->cameraEstimate) lastEstimate_ = prepared_->cameraEstimate;
    roomSurfaceNames_.clear();
    for (const Surface& s : prepared_->geometry.surfaces)
      if (s.kind != SurfaceKind::OccluderCard) roomSurfaceNames_.push_back(s.name);
    state_ = State::Ready;
  } else if (result.cancelled) {
    state_ = State::Empty;
    prepareError_ = tr("Preparation was cancelled.");
  } else {
    state_ = State::Failed;
    prepareError_ = result.error;
  }
  Q_EMIT changed({ChangeEvent::PrepareFinished});
}

QString Document::catchUpObjects(const std::vector<ObjectKeys>& preparedWith) {
  // Edits while preparing change keys only (inserting and removing restart preparation).
  INLAY_CHECK(preparedWith.size() == doc_.objects.size() &&
              prepared_->placements.size() == doc_.objects.size());
  for (size_t i = 0; i < doc_.objects.size(); ++i) {
    const ObjectKeys& now = doc_.objects[i];
    if (!samePlacement(preparedWith[i], now)) {
      const Expected<Placement> placed = placeObjectAt(*prepared_, i);
      if (!placed.ok()) return QString::fromStdString(placed.error().message());
      prepared_->placements[i] = placed.value();
      prepared_->renderScene.objects[i].worldFromObject = placed->worldFromObject;
    }
    if (!sameMaterial(preparedWith[i].material, now.material)) {
      InsertedObject& o = prepared_->renderScene.objects[i];
      setObjectMaterial(o, now.material);
    }
  }
  return {};
}

void Document::setSelectedObject(int index) {
  if (index < -1 || index >= objectCount()) index = -1;
  if (index == selected_ && (index < 0 || !selectedMark_)) return;
  selected_ = index;
  if (index >= 0) selectedMark_.reset();
  Q_EMIT changed({ChangeEvent::Selection});
}

void Document::setSelectedMark(std::optional<MarkRef> mark) {
  if (mark) {
    const size_t counts[4] = {doc_.lights.size(), doc_.shafts.size(), doc_.surfaces.size(),
                              doc_.occluders.size()};
    if (mark->index < 0 || size_t(mark->index) >= counts[int(mark->kind)]) mark.reset();
  }
  if (mark == selectedMark_ && (!mark || selected_ < 0)) return;
  selectedMark_ = mark;
  if (mark) selected_ = -1;
  Q_EMIT changed({ChangeEvent::Selection});
}

bool Document::editObject(int index, const ObjectKeys& keys, int mergeId, UndoText text,
                          QString* reason) {
  auto fail = [&](const QString& why) {
    if (reason) *reason = why;
    return false;
  };
  if (const QString why = whyObjectsCannotChange(index, true); !why.isEmpty()) return fail(why);
  if (!std::isfinite(keys.basePx.x()) || !std::isfinite(keys.basePx.y()))
    return fail(tr("The position is not a number."));
  if (!(keys.heightM > 0) || !std::isfinite(keys.heightM))
    return fail(tr("The height must be greater than zero."));

  const ObjectKeys& current = doc_.objects[size_t(index)];
  if (!samePlacement(current, keys) && prepared_) {
    // Try the placement on the prepared scene, then put the old keys back.
    ObjectKeys& slot = prepared_->doc.objects[size_t(index)];
    const ObjectKeys saved = slot;
    slot = keys;
    const Expected<Placement> placed = placeObjectAt(*prepared_, size_t(index));
    slot = saved;
    if (!placed.ok()) return fail(QString::fromStdString(placed.error().message()));
  }
  if (sameObject(current, keys)) return true;  // nothing to do
  undo_.push(new ObjectEditCommand(this, index, current, keys, mergeId, std::move(text)));
  return true;
}

bool Document::moveObject(int index, const Vec2& basePx, int dragId, QString* reason) {
  if (index < 0 || index >= objectCount()) return editObject(index, {}, 0, {}, reason);
  ObjectKeys keys = doc_.objects[size_t(index)];
  keys.basePx = basePx;
  return editObject(
      index, keys, dragId, [n = index + 1] { return tr("Move object %1").arg(n); }, reason);
}

bool Document::setObjectHeight(int index, double heightM, QString* reason, int dragId) {
  if (index < 0 || index >= objectCount()) return editObject(index, {}, 0, {}, reason);
  ObjectKeys keys = doc_.objects[size_t(index)];
  keys.heightM = heightM;
  return editObject(
      index, keys, dragId, [n = index + 1] { return tr("Change height of object %1").arg(n); }, reason);
}

bool Document::setObjectYaw(int index, double yawDeg, QString* reason, int dragId) {
  if (index < 0 || index >= objectCount()) return editObject(index, {}, 0, {}, reason);
  if (!std::isfinite(yawDeg)) {
    if (reason) *reason = tr("The turn is not a number.");
    return false;
  }
  ObjectKeys keys = doc_.objects[size_t(index)];
  keys.yawDeg = yawDeg;
  return editObject(
      index, keys, dragId, [n = index + 1] { return tr("Turn object %1").arg(n); }, reason);
}

bool Document::moveAndTurnObject(int index, const Vec2& basePx, double yawDeg, int dragId,
                                 QString* reason) {
  if (index < 0 || index >= objectCount()) return editObject(index, {}, 0, {}, reason);
  if (!std::isfinite(yawDeg)) {
    if (reason) *reason = tr("The turn is not a number.");
    return false;
  }
  ObjectKeys keys = doc_.objects[size_t(index)];
  keys.basePx = basePx;
  keys.yawDeg = yawDeg;
  return editObject(
      index, keys, dragId, [n = index + 1] { return tr("Move object %1").arg(n); }, reason);
}

std::optional<Document::WallSnap> Document::wallSnap(int index, const Vec2& basePx) const {
  const std::optional<Vec3> size = objectSizeM(index);
  if (!size || !prepared_ || !basePx.allFinite()) return std::nullopt;
  const Camera& cam = prepared_->camera;
  const SceneGeometry& geometry = prepared_->geometry;
  const auto hit = geometry.intersect(cam.rayThroughPixel(basePx), /*supportsOnly=*/true);
  if (!hit || hit->normalWorld.y() < 0.5) return std::nullopt;
  const Vec3 base = hit->pointWorld;
  const RoomBox& box = geometry.box;
  // Each wall: its kind, a point on it and its normal into the room.
  const std::array<std::tuple<SurfaceKind, Vec3, Vec3>, 4> walls = {{
      {SurfaceKind::WallBack, Vec3(0, 0, box.zBackM), Vec3(0, 0, 1)},
      {SurfaceKind::WallLeft, Vec3(box.xLeftM, 0, 0), Vec3(1, 0, 0)},
      {SurfaceKind::WallRight, Vec3(box.xRightM, 0, 0), Vec3(-1, 0, 0)},
      {SurfaceKind::WallRear, Vec3(0, 0, box.zRearM), Vec3(0, 0, -1)},
  }};
  const double halfDepth = 0.5 * size->z();
  constexpr double kGapM = 0.005;  // off the wall, so the back never pierces it
  std::optional<WallSnap> best;
  double bestGap = kWallSnapM;
  for (const auto& [kind, onWall, normal] : walls) {
    const double distance = (base - onWall).dot(normal);
    const double gap = distance - halfDepth;
    if (distance <= 0 || gap >= bestGap) continue;
    const Vec3 snapped = base + normal * (halfDepth + kGapM - distance);
    const std::optional<Vec2> px = cam.project(snapped);
    if (!px || px->x() < 0 || px->y() < 0 || px->x() >= cam.widthPx || px->y() >= cam.heightPx) continue;
    // Still on the same support (a table top it would slide off does not snap).
    const auto there = geometry.intersect(cam.rayThroughPixel(*px), /*supportsOnly=*/true);
    if (!there || there->normalWorld.y() < 0.5 || std::abs(there->pointWorld.y() - base.y()) > 0.01)
      continue;
    bestGap = gap;
    best = WallSnap{*px, std::atan2(normal.x(), normal.z()) * 180.0 / std::numbers::pi, kind};
  }
  return best;
}

bool Document::setMaterial(int index, const MaterialKeys& material, QString* reason) {
  if (index < 0 || index >= objectCount()) return editObject(index, {}, 0, {}, reason);
  ObjectKeys keys = doc_.objects[size_t(index)];
  keys.material = material;
  return editObject(
      index, keys, 0, [n = index + 1] { return tr("Change material of object %1").arg(n); }, reason);
}

std::optional<Vec2> Document::freeStandingPointPx() const {
  if (!prepared_) return std::nullopt;
  const Camera& cam = prepared_->camera;
  for (double f = 0.92; f > 0.3; f -= 0.04) {
    const Vec2 px(0.5 * cam.widthPx, f * cam.heightPx);
    if (prepared_->geometry.intersect(cam.rayThroughPixel(px), /*supportsOnly=*/true)) return px;
  }
  return std::nullopt;
}

QString Document::whyObjectsCannotChange(int index, bool whilePreparing) const {
  if (index != -1 && (index < 0 || index >= objectCount()))
    return tr("There is no object %1.").arg(index + 1);
  if (state_ == State::Preparing)
    return whilePreparing ? QString() : tr("The scene is still being prepared.");
  if (state_ != State::Ready || !prepared_) return tr("The scene could not be prepared.");
  return {};
}

bool Document::insertObject(const ObjectKeys& keys, QString* reason) {
  auto fail = [&](const QString& why) {
    if (reason) *reason = why;
    return false;
  };
  if (const QString why = whyObjectsCannotChange(-1); !why.isEmpty()) return fail(why);
  if (!(keys.heightM > 0) || !std::isfinite(keys.heightM))
    return fail(tr("The height must be greater than zero."));
  const std::string key = "objects[" + std::to_string(doc_.objects.size()) + "]";
  // The engine's loader, so the studio honours `subdivide` as render does.
  Expected<TriangleMesh> mesh = loadObjectMesh(keys);
  if (!mesh.ok()) return fail(QString::fromStdString(mesh.error().underKey(key).message()));
  return insertObject(keys, std::make_shared<const TriangleMesh>(std::move(mesh.value())), reason);
}

bool Document::insertObject(const ObjectKeys& keys, std::shared_ptr<const TriangleMesh> mesh,
                            QString* reason) {
  auto fail = [&](const QString& why) {
    if (reason) *reason = why;
    return false;
  };
  if (const QString why = whyObjectsCannotChange(-1); !why.isEmpty()) return fail(why);
  if (!mesh || mesh->empty()) return fail(tr("The model has no triangles."));
  if (!(keys.heightM > 0) || !std::isfinite(keys.heightM))
    return fail(tr("The height must be greater than zero."));
  const std::string key = "objects[" + std::to_string(doc_.objects.size()) + "]";
  const Expected<Placement> placed = placeObject(*mesh, prepared_->geometry, prepared_->camera,
                                                 keys.basePx, keys.heightM, keys.yawDeg, key);
  if (!placed.ok()) return fail(QString::fromStdString(placed.error().message()));
  const int index = objectCount();
  UndoText name = [n = index + 1] { return tr("object %1").arg(n); };
  if (!keys.name.empty()) name = [fixed = QString::fromStdString(keys.name)] { return fixed; };
  undo_.push(new ObjectListCommand(this, true, index, keys, std::move(mesh),
                                   [name] { return tr("Insert %1").arg(name()); }));
  return true;
}

bool Document::duplicateObject(int index, QString* reason) {
  auto fail = [&](const QString& why) {
    if (reason) *reason = why;
    return false;
  };
  if (const QString why = whyObjectsCannotChange(index); !why.isEmpty()) return fail(why);
  ObjectKeys copy = doc_.objects[size_t(index)];
  copy.name = uniqueName(objectName(index)).toStdString();
  copy.hidden = false;
  const std::shared_ptr<const TriangleMesh> mesh =
      prepared_->renderScene.objects[size_t(index)].meshObject;
  copy.basePx = spotBeside(index).value_or(copy.basePx);
  const int at = objectCount();
  undo_.push(new ObjectListCommand(this, true, at, copy, mesh, [name = objectNameText(index)] {
    return tr("Duplicate %1").arg(name());
  }));
  return true;
}

QString Document::uniqueName(const QString& base) const {
  // "chair" -> "chair 2"; "chair 2" -> "chair 3": the number counts up from the base's own.
  QString stem = base;
  int n = 1;
  const int space = base.lastIndexOf(QLatin1Char(' '));
  bool isNumber = false;
  const int tail = space > 0 ? base.mid(space + 1).toInt(&isNumber) : 0;
  if (isNumber && tail > 0) {
    stem = base.left(space);
    n = tail;
  }
  auto taken = [this](const QString& name) {
    for (int i = 0; i < objectCount(); ++i)
      if (objectName(i) == name) return true;
    return false;
  };
  QString name;
  do name = QStringLiteral("%1 %2").arg(stem).arg(++n);
  while (taken(name));
  return name;
}

std::optional<Vec2> Document::spotBeside(int index) const {
  if (!prepared_ || size_t(index) >= prepared_->placements.size()) return std::nullopt;
  const std::optional<Vec3> size = objectSizeM(index);
  if (!size) return std::nullopt;
  const Camera& cam = prepared_->camera;
  const Vec3 base = prepared_->placements[size_t(index)].baseWorld;
  const double step = 1.15 * std::max({size->x(), size->z(), 0.05});
  for (const Vec3& dir : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)}) {
    std::optional<Vec2> px = cam.project(base + step * dir);
    if (!px || px->x() < 0 || px->y() < 0 || px->x() >= cam.widthPx || px->y() >= cam.heightPx) continue;
    const auto hit = prepared_->geometry.intersect(cam.rayThroughPixel(*px), /*supportsOnly=*/true);
    // The same level (a duplicate on a table top stays on it, not on the floor beside it).
    if (hit && hit->normalWorld.y() >= 0.5 && std::abs(hit->pointWorld.y() - base.y()) < 0.02) return px;
  }
  return std::nullopt;
}

bool Document::renameObject(int index, const QString& name, QString* reason) {
  if (index < 0 || index >= objectCount()) return editObject(index, {}, 0, {}, reason);
  ObjectKeys keys = doc_.objects[size_t(index)];
  UndoText before = objectNameText(index);
  keys.name = name.trimmed().toStdString();
  return editObject(
      index, keys, 0, [before] { return tr("Rename %1").arg(before()); }, reason);
}

bool Document::setObjectHidden(int index, bool hidden, QString* reason) {
  if (index < 0 || index >= objectCount()) return editObject(index, {}, 0, {}, reason);
  ObjectKeys keys = doc_.objects[size_t(index)];
  keys.hidden = hidden;
  UndoText text = [hidden, name = objectNameText(index)] {
    return (hidden ? tr("Hide %1") : tr("Show %1")).arg(name());
  };
  return editObject(index, keys, 0, std::move(text), reason);
}

UndoText Document::objectNameText(int index) const {
  if (index >= 0 && index < objectCount() && doc_.objects[size_t(index)].name.empty()) {
    const std::string& mesh = doc_.objects[size_t(index)].mesh;
    if (mesh == "builtin:sphere") return [] { return tr("sphere"); };
    if (mesh == "builtin:cube") return [] { return tr("cube"); };
  }
  return [fixed = objectName(index)] { return fixed; };
}

void Document::retranslateHistory() {
  // The stack hands out const commands; each is one of ours, created non-const by a push.
  for (int i = 0; i < undo_.count(); ++i)
    if (const auto* c = dynamic_cast<const TextCommand*>(undo_.command(i)))
      const_cast<TextCommand*>(c)->retranslate();
}

QString Document::objectName(int index) const {
  if (index < 0 || index >= objectCount()) return {};
  const ObjectKeys& o = doc_.objects[size_t(index)];
  if (!o.name.empty()) return QString::fromStdString(o.name);
  if (o.mesh == "builtin:sphere") return tr("sphere");
  if (o.mesh == "builtin:cube") return tr("cube");
  return QFileInfo(QString::fromStdString(o.mesh)).completeBaseName();
}

std::optional<Vec3> Document::objectSizeM(int index) const {
  if (!prepared_ || index < 0 || size_t(index) >= prepared_->renderScene.objects.size() ||
      index >= objectCount())
    return std::nullopt;
  const auto& mesh = prepared_->renderScene.objects[size_t(index)].meshObject;
  if (!mesh || mesh->empty()) return std::nullopt;
  const Eigen::Vector3f sizes = mesh->bounds().sizes();
  if (!(sizes.y() > 0)) return std::nullopt;
  const double scale = doc_.objects[size_t(index)].heightM / double(sizes.y());
  return Vec3(sizes.x() * scale, doc_.objects[size_t(index)].heightM, sizes.z() * scale);
}

std::optional<Vec2> Document::supportPointNear(const Vec2& px) const {
  if (!prepared_ || !px.allFinite()) return std::nullopt;
  const Camera& cam = prepared_->camera;
  auto supports = [&](const Vec2& q) {
    const auto hit = prepared_->geometry.intersect(cam.rayThroughPixel(q), /*supportsOnly=*/true);
    return hit && hit->normalWorld.y() >= 0.5;
  };
  if (px.x() < 0 || px.x() >= cam.widthPx || px.y() < 0 || px.y() >= cam.heightPx) return std::nullopt;
  const double step = std::max(1.0, cam.heightPx / 400.0);
  for (double y = px.y(); y < cam.heightPx; y += step)
    if (supports(Vec2(px.x(), y))) return Vec2(px.x(), y);
  return std::nullopt;
}

bool Document::removeObject(int index, QString* reason) {
  auto fail = [&](const QString& why) {
    if (reason) *reason = why;
    return false;
  };
  if (const QString why = whyObjectsCannotChange(index); !why.isEmpty()) return fail(why);
  undo_.push(new ObjectListCommand(this, false, index, doc_.objects[size_t(index)],
                                   prepared_->renderScene.objects[size_t(index)].meshObject,
                                   [n = index + 1] { return tr("Delete object %1").arg(n); }));
  return true;
}

void Document::insertObjectAt(int index, const ObjectKeys& keys,
                              std::shared_ptr<const TriangleMesh> mesh) {
  INLAY_CHECK(index >= 0 && index <= objectCount() && mesh);
  if (!prepared_) {  // undone / redone while the marks are being re-prepared
    std::vector<ObjectKeys> objects = doc_.objects;
    objects.insert(objects.begin() + index, keys);
    return changeObjectsUnprepared(std::move(objects), index);
  }
  INLAY_CHECK(prepared_->renderScene.objects.size() == doc_.objects.size() &&
              prepared_->placements.size() == doc_.objects.size());
  const auto at = [index](auto& v) { return v.begin() + index; };
  doc_.objects.insert(at(doc_.objects), keys);
  prepared_->doc.objects.insert(at(prepared_->doc.objects), keys);
  InsertedObject object;
  object.meshObject = std::move(mesh);
  setObjectMaterial(object, keys.material);
  prepared_->renderScene.objects.insert(at(prepared_->renderScene.objects), object);
  // Validated before the command was pushed, against the same mesh and geometry.
  const Expected<Placement> placed = placeObjectAt(*prepared_, size_t(index));
  INLAY_CHECK(placed.ok());
  prepared_->renderScene.objects[size_t(index)].worldFromObject = placed->worldFromObject;
  prepared_->placements.insert(at(prepared_->placements), placed.value());
  selected_ = index;
  Q_EMIT changed({ChangeEvent::ObjectsAddedOrRemoved | ChangeEvent::Selection, index});
}

void Document::removeObjectAt(int index) {
  INLAY_CHECK(index >= 0 && index < objectCount());
  if (!prepared_) {
    std::vector<ObjectKeys> objects = doc_.objects;
    objects.erase(objects.begin() + index);
    const int selected = std::min(selected_, int(objects.size()) - 1);
    return changeObjectsUnprepared(std::move(objects), selected);
  }
  const auto at = [index](auto& v) { return v.begin() + index; };
  doc_.objects.erase(at(doc_.objects));
  prepared_->doc.objects.erase(at(prepared_->doc.objects));
  prepared_->renderScene.objects.erase(at(prepared_->renderScene.objects));
  prepared_->placements.erase(at(prepared_->placements));
  if (selected_ >= objectCount()) selected_ = objectCount() - 1;
  Q_EMIT changed({ChangeEvent::ObjectsAddedOrRemoved | ChangeEvent::Selection, index});
}

void Document::applyObject(int index, const ObjectKeys& keys) {
  INLAY_CHECK(index >= 0 && index < objectCount());
  if (!prepared_ && state_ == State::Preparing) {
    // The document takes the edit now (the viewport draws it); the scene being prepared
    // catches up when it arrives (catchUpObjects).
    const ChangeEvent event = objectChange(index, doc_.objects[size_t(index)], keys);
    doc_.objects[size_t(index)] = keys;
    if (event.what) Q_EMIT changed(event);
    return;
  }
  if (!prepared_) {
    std::vector<ObjectKeys> objects = doc_.objects;
    objects[size_t(index)] = keys;
    return changeObjectsUnprepared(std::move(objects), selected_);
  }
  ObjectKeys& current = doc_.objects[size_t(index)];
  const ChangeEvent event = objectChange(index, current, keys);
  current = keys;
  prepared_->doc.objects[size_t(index)] = keys;

  if (event.has(ChangeEvent::ObjectPlacement)) {
    // Validated before the command was pushed, and undo/redo only revisit validated keys.
    const Expected<Placement> placed = placeObjectAt(*prepared_, size_t(index));
    INLAY_CHECK(placed.ok());
    if (size_t(index) < prepared_->placements.size())
      prepared_->placements[size_t(index)] = placed.value();
    if (size_t(index) < prepared_->renderScene.objects.size())
      prepared_->renderScene.objects[size_t(index)].worldFromObject = placed->worldFromObject;
  }
  if (event.has(ChangeEvent::ObjectMaterial) && size_t(index) < prepared_->renderScene.objects.size()) {
    InsertedObject& o = prepared_->renderScene.objects[size_t(index)];
    setObjectMaterial(o, keys.material);
  }
  if (event.what) Q_EMIT changed(event);
}

}  // namespace inlay::studio

namespace inlay::studio {

// --- The scene's marks ---

SceneMarks Document::marks() const {
  return doc_;  // its SceneMarks part
}

std::optional<std::array<Vec2, 4>> Document::shownBackWallPx() const {
  if (doc_.layout.backWallPx) return doc_.layout.backWallPx;
  return estimatedBackWallPx_;
}

bool Document::editMarks(const SceneMarks& after, int mergeId, UndoText text, QString* reason) {
  if (doc_.photo.empty()) {
    if (reason) *reason = tr("Open a photo first.");
    return false;
  }
  SceneMarks before = marks();
  if (before == after) return true;
  undo_.push(new MarksCommand(this, std::move(before), after, mergeId, std::move(text)));
  return true;
}

void Document::applyMarks(const SceneMarks& m) {
  putMarks(doc_, m);
  const bool wasSelected = selectedMark_.has_value();
  selectedMark_.reset();  // indices may have shifted
  Q_EMIT changed({ChangeEvent::Marks | (wasSelected ? unsigned(ChangeEvent::Selection) : 0u)});
  prepare();
}

bool Document::acceptEstimatedBox(QString* reason) {
  const std::optional<std::array<Vec2, 4>> shown = shownBackWallPx();
  if (!shown) {
    if (reason) *reason = tr("There is no estimated box yet.");
    return false;
  }
  SceneMarks m = marks();
  m.layout.backWallPx = *shown;
  return editMarks(
      m, 0, [] { return tr("Accept the estimated box"); }, reason);
}

bool Document::setBackWallCorner(int corner, const Vec2& px, int dragId, QString* reason) {
  std::optional<std::array<Vec2, 4>> corners = shownBackWallPx();
  if (corner < 0 || corner > 3 || !corners) {
    if (reason) *reason = tr("There is no such corner of the back wall.");
    return false;
  }
  if (!std::isfinite(px.x()) || !std::isfinite(px.y())) {
    if (reason) *reason = tr("The position is not a number.");
    return false;
  }
  (*corners)[size_t(corner)] = px;
  SceneMarks m = marks();
  m.layout.backWallPx = *corners;
  return editMarks(
      m, dragId, [] { return tr("Move a corner of the back wall"); }, reason);
}

bool Document::resetBackWall(QString* reason) {
  SceneMarks m = marks();
  m.layout.backWallPx.reset();
  return editMarks(
      m, 0, [] { return tr("Estimate the box again"); }, reason);
}

bool Document::addLight(const std::vector<Vec2>& outlinePx, QString* reason) {
  if (outlinePx.size() < 3 || !finitePoints(outlinePx) || std::abs(doubleArea(outlinePx)) < 4.0) {
    if (reason) *reason = tr("A light's outline needs at least three points around an area.");
    return false;
  }
  SceneMarks m = marks();
  LightKeys light;
  light.kind = LightKeys::Kind::PolygonPx;
  light.pointsPx = outlinePx;
  m.lights.push_back(light);
  return editMarks(
      m, 0, [n = int(m.lights.size())] { return tr("Outline light %1").arg(n); }, reason);
}

bool Document::addShaft(const std::array<double, 4>& shaftBoxPx,
                        const std::array<double, 4>& sourceBoxPx, QString* reason) {
  if (!validBox(shaftBoxPx) || !validBox(sourceBoxPx)) {
    if (reason) *reason = tr("Each box of a shaft must be at least two pixels wide and high.");
    return false;
  }
  SceneMarks m = marks();
  ShaftKeys shaft;
  shaft.shaftBoxPx = shaftBoxPx;
  shaft.sourceBoxPx = sourceBoxPx;
  m.shafts.push_back(shaft);
  return editMarks(
      m, 0, [n = int(m.shafts.size())] { return tr("Add shaft %1").arg(n); }, reason);
}

bool Document::addExtrusion(const std::vector<Vec2>& outlinePx, const Vec2& heightClickPx,
                            QString* reason) {
  if (outlinePx.size() < 3 || !finitePoints(outlinePx) || std::abs(doubleArea(outlinePx)) < 4.0 ||
      !finitePoints({heightClickPx})) {
    if (reason) *reason = tr("A surface's outline needs at least three points around an area.");
    return false;
  }
  SceneMarks m = marks();
  SurfaceKeys surface;
  surface.kind = "extrusion";
  surface.outlinePx = outlinePx;
  surface.heightClickPx = heightClickPx;
  m.surfaces.push_back(surface);
  return editMarks(
      m, 0, [n = int(m.surfaces.size())] { return tr("Add surface %1").arg(n); }, reason);
}

bool Document::addOccluder(const OccluderKeys& occluder, QString* reason) {
  auto usable = [](const std::vector<std::vector<Vec2>>& strokes) {
    return !strokes.empty() && std::all_of(strokes.begin(), strokes.end(),
                                           [](const auto& s) { return !s.empty() && finitePoints(s); });
  };
  if (!usable(occluder.foregroundScribblesPx) || !usable(occluder.backgroundScribblesPx)) {
    if (reason)
      *reason = tr("An occluder needs a stroke over the thing in front and one over what is behind it.");
    return false;
  }
  SceneMarks m = marks();
  m.occluders.push_back(occluder);
  return editMarks(
      m, 0, [n = int(m.occluders.size())] { return tr("Add occluder %1").arg(n); }, reason);
}

bool Document::addOccluderStroke(int index, bool foreground, const std::vector<Vec2>& strokePx,
                                 QString* reason) {
  if (index < 0 || index >= int(doc_.occluders.size()) || strokePx.empty() || !finitePoints(strokePx)) {
    if (reason) *reason = tr("There is no such occluder, or the stroke is empty.");
    return false;
  }
  SceneMarks m = marks();
  OccluderKeys& o = m.occluders[size_t(index)];
  (foreground ? o.foregroundScribblesPx : o.backgroundScribblesPx).push_back(strokePx);
  return editMarks(
      m, 0, [n = index + 1] { return tr("Add a stroke to occluder %1").arg(n); }, reason);
}

bool Document::removeMark(MarkRef mark, QString* reason) {
  return removeMark(mark.kind, mark.index, reason);
}

bool Document::removeMark(MarkKind kind, int index, QString* reason) {
  SceneMarks m = marks();
  auto erase = [&](auto& list, const char* source) {
    if (index < 0 || index >= int(list.size())) {
      if (reason) *reason = tr("There is no such mark.");
      return false;
    }
    list.erase(list.begin() + index);
    return editMarks(
        m, 0, [source, n = index + 1] { return tr(source).arg(n); }, reason);
  };
  switch (kind) {
    case MarkKind::Light: return erase(m.lights, QT_TR_NOOP("Delete light %1"));
    case MarkKind::Shaft: return erase(m.shafts, QT_TR_NOOP("Delete shaft %1"));
    case MarkKind::Surface: return erase(m.surfaces, QT_TR_NOOP("Delete surface %1"));
    case MarkKind::Occluder: return erase(m.occluders, QT_TR_NOOP("Delete occluder %1"));
  }
  return false;
}

void Document::changeObjectsUnprepared(std::vector<ObjectKeys> objects, int selected) {
  doc_.objects = std::move(objects);
  selected_ = std::clamp(selected, -1, objectCount() - 1);
  Q_EMIT changed({ChangeEvent::ObjectsAddedOrRemoved | ChangeEvent::Selection});
  prepare();
}

}  // namespace inlay::studio

namespace inlay::studio {

// --- Reshaping marks point by point, vanishing lines, room materials ---
namespace {

// The corners of a box {x0, y0, x1, y1} in MarkPoint order: x0y0, x1y0, x1y1, x0y1.
std::array<Vec2, 4> boxCorners(const std::array<double, 4>& b) {
  return {Vec2(b[0], b[1]), Vec2(b[2], b[1]), Vec2(b[2], b[3]), Vec2(b[0], b[3])};
}

// Moves corner `c` of a box; the opposite corner stays. The result is normalised (x0 <= x1).
std::array<double, 4> boxWithCorner(const std::array<double, 4>& b, int c, const Vec2& px) {
  const Vec2 opposite = boxCorners(b)[size_t((c + 2) % 4)];
  return {std::min(px.x(), opposite.x()), std::min(px.y(), opposite.y()), std::max(px.x(), opposite.x()),
          std::max(px.y(), opposite.y())};
}

// The occluder's points in MarkPoint order, as pointers into `o`.
std::vector<Vec2*> occluderPoints(OccluderKeys& o) {
  std::vector<Vec2*> out;
  for (auto* strokes : {&o.foregroundScribblesPx, &o.backgroundScribblesPx})
    for (auto& stroke : *strokes)
      for (Vec2& q : stroke) out.push_back(&q);
  return out;
}

}  // namespace

std::vector<MarkPoint> Document::markPoints() const {
  std::vector<MarkPoint> out;
  auto add = [&](MarkKind kind, size_t i, int point, const Vec2& px) {
    out.push_back({MarkRef{kind, int(i)}, point, px});
  };
  for (size_t i = 0; i < doc_.lights.size(); ++i)
    if (doc_.lights[i].kind == LightKeys::Kind::PolygonPx)
      for (size_t k = 0; k < doc_.lights[i].pointsPx.size(); ++k)
        add(MarkKind::Light, i, int(k), doc_.lights[i].pointsPx[k]);
  for (size_t i = 0; i < doc_.shafts.size(); ++i) {
    const ShaftKeys& s = doc_.shafts[i];
    if (s.shaftBoxPx)
      for (int c = 0; c < 4; ++c) add(MarkKind::Shaft, i, c, boxCorners(*s.shaftBoxPx)[size_t(c)]);
    if (s.sourceBoxPx)
      for (int c = 0; c < 4; ++c) add(MarkKind::Shaft, i, 4 + c, boxCorners(*s.sourceBoxPx)[size_t(c)]);
  }
  for (size_t i = 0; i < doc_.surfaces.size(); ++i) {
    const SurfaceKeys& s = doc_.surfaces[i];
    if (s.outlinePx.empty()) continue;  // stairs from base_px or a profile: not reshaped here
    for (size_t k = 0; k < s.outlinePx.size(); ++k) add(MarkKind::Surface, i, int(k), s.outlinePx[k]);
    add(MarkKind::Surface, i, int(s.outlinePx.size()), s.heightClickPx);
  }
  for (size_t i = 0; i < doc_.occluders.size(); ++i) {
    OccluderKeys copy = doc_.occluders[i];
    const std::vector<Vec2*> points = occluderPoints(copy);
    for (size_t k = 0; k < points.size(); ++k) add(MarkKind::Occluder, i, int(k), *points[k]);
  }
  return out;
}

bool Document::moveMarkPoint(MarkRef mark, int point, const Vec2& px, int dragId, QString* reason) {
  auto fail = [&](const QString& why) {
    if (reason) *reason = why;
    return false;
  };
  if (!std::isfinite(px.x()) || !std::isfinite(px.y())) return fail(tr("The position is not a number."));
  SceneMarks m = marks();
  const size_t i = size_t(mark.index);
  const QString noPoint = tr("There is no such point.");
  UndoText text;
  const int n = mark.index + 1;
  switch (mark.kind) {
    case MarkKind::Light: {
      if (mark.index < 0 || i >= m.lights.size()) return fail(noPoint);
      std::vector<Vec2>& pts = m.lights[i].pointsPx;
      if (point < 0 || size_t(point) >= pts.size()) return fail(noPoint);
      pts[size_t(point)] = px;
      if (std::abs(doubleArea(pts)) < 4.0) return fail(tr("The outline would lose its area."));
      text = [n] { return tr("Reshape light %1").arg(n); };
      break;
    }
    case MarkKind::Shaft: {
      if (mark.index < 0 || i >= m.shafts.size() || point < 0 || point > 7) return fail(noPoint);
      auto& box = point < 4 ? m.shafts[i].shaftBoxPx : m.shafts[i].sourceBoxPx;
      if (!box) return fail(noPoint);
      box = boxWithCorner(*box, point % 4, px);
      if (!validBox(*box))
        return fail(tr("Each box of a shaft must be at least two pixels wide and high."));
      text = [n] { return tr("Reshape shaft %1").arg(n); };
      break;
    }
    case MarkKind::Surface: {
      if (mark.index < 0 || i >= m.surfaces.size()) return fail(noPoint);
      SurfaceKeys& s = m.surfaces[i];
      if (point < 0 || size_t(point) > s.outlinePx.size() || s.outlinePx.empty()) return fail(noPoint);
      (size_t(point) == s.outlinePx.size() ? s.heightClickPx : s.outlinePx[size_t(point)]) = px;
      if (std::abs(doubleArea(s.outlinePx)) < 4.0) return fail(tr("The outline would lose its area."));
      text = [n] { return tr("Reshape surface %1").arg(n); };
      break;
    }
    case MarkKind::Occluder: {
      if (mark.index < 0 || i >= m.occluders.size()) return fail(noPoint);
      const std::vector<Vec2*> points = occluderPoints(m.occluders[i]);
      if (point < 0 || size_t(point) >= points.size()) return fail(noPoint);
      *points[size_t(point)] = px;
      text = [n] { return tr("Reshape occluder %1").arg(n); };
      break;
    }
  }
  const std::optional<MarkRef> keep = selectedMark_;
  const bool ok = editMarks(m, dragId, std::move(text), reason);
  if (ok && keep == mark) setSelectedMark(mark);  // reshaping keeps the mark selected
  return ok;
}

bool Document::setVanishingLines(int axis, const std::optional<std::array<Vec2, 4>>& segmentsPx,
                                 QString* reason) {
  auto fail = [&](const QString& why) {
    if (reason) *reason = why;
    return false;
  };
  if (axis < 0 || axis > 2) return fail(tr("There is no such axis."));
  if (segmentsPx) {
    const auto& q = *segmentsPx;
    if (!finitePoints({q.begin(), q.end()})) return fail(tr("The position is not a number."));
    if ((q[1] - q[0]).norm() < 2 || (q[3] - q[2]).norm() < 2)
      return fail(tr("Each line must be at least two pixels long."));
    const Vec2 d = (q[1] - q[0]).normalized();
    auto offLine = [&](const Vec2& r) {
      return std::abs(d.x() * (r - q[0]).y() - d.y() * (r - q[0]).x());
    };
    if (offLine(q[2]) < 1 && offLine(q[3]) < 1)
      return fail(tr("The two lines lie on one line: draw two different edges."));
  }
  SceneMarks m = marks();
  m.camera.vanishingLinesPx[size_t(axis)] = segmentsPx;
  // Given vanishing points fix the whole camera and would override the lines: drawing lines
  // asks for the camera to be re-estimated around them.
  if (segmentsPx) m.camera.vanishingPointsPx.reset();
  const char* const names[3] = {"x", "y", "z"};
  const QLatin1String name(names[axis]);
  UndoText text = [name] { return tr("Draw the %1 vanishing lines").arg(name); };
  if (!segmentsPx) text = [name] { return tr("Forget the %1 vanishing lines").arg(name); };
  return editMarks(m, 0, std::move(text), reason);
}

std::vector<std::string> Document::roomSurfaceNames() const { return roomSurfaceNames_; }

bool Document::setRoomMaterial(const std::string& surface,
                               const std::optional<RoomMaterialKeys>& material, QString* reason) {
  auto fail = [&](const QString& why) {
    if (reason) *reason = why;
    return false;
  };
  const std::vector<std::string> names = roomSurfaceNames();
  if (std::find(names.begin(), names.end(), surface) == names.end())
    return fail(tr("The room has no surface %1.").arg(QString::fromStdString(surface)));
  if (material &&
      (material->preset != "glossy" && material->preset != "mirror" && material->preset != "diffuse"))
    return fail(tr("Unknown material."));
  if (material &&
      (!(material->roughness >= 0 && material->roughness <= 1) || !material->reflectance.allFinite()))
    return fail(tr("The roughness must lie between 0 and 1."));
  SceneMarks m = marks();
  if (material) m.room.materials[surface] = *material;
  else m.room.materials.erase(surface);
  return editMarks(
      m, 0,
      [name = QString::fromStdString(surface)] { return tr("Change the material of %1").arg(name); },
      reason);
}

bool Document::setCameraResponse(const ResponseKeys& response, QString* reason) {
  SceneMarks m = marks();
  m.camera.response = response;
  return editMarks(
      m, 0, [] { return tr("Change the camera response"); }, reason);
}

}  // namespace inlay::studio
