#include "document.h"

#include "prepare_worker.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QUndoCommand>

#include <atomic>
#include <cmath>

namespace inlay::studio {
namespace {

bool sameMaterial(const MaterialKeys& a, const MaterialKeys& b) {
  return a.preset == b.preset && a.albedo == b.albedo && a.roughness == b.roughness &&
         a.ior == b.ior && a.rgb == b.rgb;
}

bool samePlacement(const ObjectKeys& a, const ObjectKeys& b) {
  return a.basePx == b.basePx && a.heightM == b.heightM && a.yawDeg == b.yawDeg;
}

// A path as it should be written in a scene file saved in `dir`: relative when the file lies
// inside that folder, absolute otherwise (a "../../x" path breaks as soon as the scene moves).
std::string pathForFolder(const std::string& resolved, const std::string& asWritten,
                          const QDir& dir) {
  if (resolved.empty()) return asWritten;
  const QString rel = dir.relativeFilePath(QString::fromStdString(resolved));
  if (rel.startsWith(QLatin1String(".."))) return resolved;
  return rel.toStdString();
}

}  // namespace

// One undoable change of one object's keys (placement and/or material). Moves of one drag share
// a merge id and collapse into one command; a command whose before equals its after is
// obsolete and leaves the stack.
class ObjectEditCommand : public QUndoCommand {
 public:
  ObjectEditCommand(Document* doc, int index, ObjectKeys before, ObjectKeys after, int mergeId,
                    const QString& text)
      : QUndoCommand(text),
        doc_(doc),
        index_(index),
        before_(std::move(before)),
        after_(std::move(after)),
        mergeId_(mergeId) {
    setObsolete(samePlacement(before_, after_) && sameMaterial(before_.material, after_.material));
  }

  void undo() override { doc_->applyObject(index_, before_); }
  void redo() override { doc_->applyObject(index_, after_); }
  int id() const override { return mergeId_ > 0 ? 1 : -1; }
  bool mergeWith(const QUndoCommand* other) override {
    const auto* o = dynamic_cast<const ObjectEditCommand*>(other);
    if (!o || o->mergeId_ != mergeId_ || o->index_ != index_) return false;
    after_ = o->after_;
    setObsolete(samePlacement(before_, after_) && sameMaterial(before_.material, after_.material));
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
class ObjectListCommand : public QUndoCommand {
 public:
  ObjectListCommand(Document* doc, bool insert, int index, ObjectKeys keys,
                    std::shared_ptr<const TriangleMesh> mesh, const QString& text)
      : QUndoCommand(text),
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
  qRegisterMetaType<PrepareResult>();
  thread_.setObjectName(QStringLiteral("inlay-prepare"));
  worker_ = new PrepareWorker;
  worker_->moveToThread(&thread_);
  connect(&thread_, &QThread::finished, worker_, &QObject::deleteLater);
  connect(worker_, &PrepareWorker::progress, this,
          [this](quint64 jobId, const QString& stage, double fraction) {
            if (jobId == jobId_ && state_ == State::Preparing)
              Q_EMIT prepareProgress(stage, fraction);
          });
  connect(worker_, &PrepareWorker::finished, this, &Document::onPrepared);
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
  for (const std::string& w : loaded->warnings) warnings_ << QString::fromStdString(w);
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
  QMetaObject::invokeMethod(
      worker_, [w = worker_, id = jobId_, doc = doc_, token = cancel_] { w->run(id, doc, token); },
      Qt::QueuedConnection);
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
  for (const QString& w : result.warnings) warnings_ << w;
  if (result.scene) {
    prepared_ = std::make_unique<PreparedScene>(std::move(*result.scene));
    // The engine may have filled in estimated keys; the objects are the user's.
    prepared_->doc.objects = doc_.objects;
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

void Document::setSelectedObject(int index) {
  if (index < -1 || index >= objectCount()) index = -1;
  if (index == selected_) return;
  selected_ = index;
  Q_EMIT changed({ChangeEvent::Selection});
}

bool Document::editObject(int index, const ObjectKeys& keys, int mergeId, const QString& text,
                          QString* reason) {
  auto fail = [&](const QString& why) {
    if (reason) *reason = why;
    return false;
  };
  if (const QString why = whyObjectsCannotChange(index); !why.isEmpty()) return fail(why);
  if (!std::isfinite(keys.basePx.x()) || !std::isfinite(keys.basePx.y()))
    return fail(tr("The position is not a number."));
  if (!(keys.heightM > 0) || !std::isfinite(keys.heightM))
    return fail(tr("The height must be greater than zero."));

  const ObjectKeys& current = doc_.objects[size_t(index)];
  if (!samePlacement(current, keys)) {
    // Try the placement on the prepared scene, then put the old keys back.
    ObjectKeys& slot = prepared_->doc.objects[size_t(index)];
    const ObjectKeys saved = slot;
    slot = keys;
    const Expected<Placement> placed = placeObjectAt(*prepared_, size_t(index));
    slot = saved;
    if (!placed.ok()) return fail(QString::fromStdString(placed.error().message()));
  }
  if (samePlacement(current, keys) && sameMaterial(current.material, keys.material))
    return true;  // nothing to do
  undo_.push(new ObjectEditCommand(this, index, current, keys, mergeId, text));
  return true;
}

bool Document::moveObject(int index, const Vec2& basePx, int dragId, QString* reason) {
  if (index < 0 || index >= objectCount()) return editObject(index, {}, 0, {}, reason);
  ObjectKeys keys = doc_.objects[size_t(index)];
  keys.basePx = basePx;
  return editObject(index, keys, dragId, tr("Move object %1").arg(index + 1), reason);
}

bool Document::setObjectHeight(int index, double heightM, QString* reason) {
  if (index < 0 || index >= objectCount()) return editObject(index, {}, 0, {}, reason);
  ObjectKeys keys = doc_.objects[size_t(index)];
  keys.heightM = heightM;
  return editObject(index, keys, 0, tr("Change height of object %1").arg(index + 1), reason);
}

bool Document::setObjectYaw(int index, double yawDeg, QString* reason) {
  if (index < 0 || index >= objectCount()) return editObject(index, {}, 0, {}, reason);
  ObjectKeys keys = doc_.objects[size_t(index)];
  keys.yawDeg = yawDeg;
  return editObject(index, keys, 0, tr("Turn object %1").arg(index + 1), reason);
}

bool Document::setMaterial(int index, const MaterialKeys& material, QString* reason) {
  if (index < 0 || index >= objectCount()) return editObject(index, {}, 0, {}, reason);
  ObjectKeys keys = doc_.objects[size_t(index)];
  keys.material = material;
  return editObject(index, keys, 0, tr("Change material of object %1").arg(index + 1), reason);
}

std::optional<Vec2> Document::freeStandingPointPx() const {
  if (!prepared_) return std::nullopt;
  const Camera& cam = prepared_->camera;
  for (double f = 0.92; f > 0.3; f -= 0.04) {
    const Vec2 px(0.5 * cam.widthPx, f * cam.heightPx);
    if (prepared_->geometry.intersect(cam.rayThroughPixel(px), /*supportsOnly=*/true))
      return px;
  }
  return std::nullopt;
}

QString Document::whyObjectsCannotChange(int index) const {
  if (index != -1 && (index < 0 || index >= objectCount())) return tr("There is no object %1.").arg(index + 1);
  if (state_ == State::Preparing) return tr("The scene is still being prepared.");
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
  Expected<TriangleMesh> mesh = loadMesh(keys.meshResolved.empty() ? keys.mesh : keys.meshResolved);
  if (!mesh.ok()) return fail(QString::fromStdString(mesh.error().underKey(key + ".mesh").message()));
  auto shared = std::make_shared<const TriangleMesh>(std::move(mesh.value()));
  const Expected<Placement> placed = placeObject(*shared, prepared_->geometry, prepared_->camera,
                                                 keys.basePx, keys.heightM, keys.yawDeg, key);
  if (!placed.ok()) return fail(QString::fromStdString(placed.error().message()));
  const int index = objectCount();
  undo_.push(new ObjectListCommand(this, true, index, keys, std::move(shared),
                                   tr("Insert object %1").arg(index + 1)));
  return true;
}

bool Document::removeObject(int index, QString* reason) {
  auto fail = [&](const QString& why) {
    if (reason) *reason = why;
    return false;
  };
  if (const QString why = whyObjectsCannotChange(index); !why.isEmpty()) return fail(why);
  undo_.push(new ObjectListCommand(this, false, index, doc_.objects[size_t(index)],
                                   prepared_->renderScene.objects[size_t(index)].meshObject,
                                   tr("Delete object %1").arg(index + 1)));
  return true;
}

void Document::insertObjectAt(int index, const ObjectKeys& keys,
                              std::shared_ptr<const TriangleMesh> mesh) {
  INLAY_CHECK(prepared_ && index >= 0 && index <= objectCount() && mesh);
  INLAY_CHECK(prepared_->renderScene.objects.size() == doc_.objects.size() &&
              prepared_->placements.size() == doc_.objects.size());
  const auto at = [index](auto& v) { return v.begin() + index; };
  doc_.objects.insert(at(doc_.objects), keys);
  prepared_->doc.objects.insert(at(prepared_->doc.objects), keys);
  InsertedObject object;
  object.material = materialFromKeys(keys.material, mesh.get());
  object.meshObject = std::move(mesh);
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
  INLAY_CHECK(prepared_ && index >= 0 && index < objectCount());
  const auto at = [index](auto& v) { return v.begin() + index; };
  doc_.objects.erase(at(doc_.objects));
  prepared_->doc.objects.erase(at(prepared_->doc.objects));
  prepared_->renderScene.objects.erase(at(prepared_->renderScene.objects));
  prepared_->placements.erase(at(prepared_->placements));
  if (selected_ >= objectCount()) selected_ = objectCount() - 1;
  Q_EMIT changed({ChangeEvent::ObjectsAddedOrRemoved | ChangeEvent::Selection, index});
}

void Document::applyObject(int index, const ObjectKeys& keys) {
  INLAY_CHECK(index >= 0 && index < objectCount() && prepared_);
  ObjectKeys& current = doc_.objects[size_t(index)];
  ChangeEvent event;
  event.objectIndex = index;
  if (!samePlacement(current, keys)) event.what |= ChangeEvent::ObjectPlacement;
  if (!sameMaterial(current.material, keys.material)) event.what |= ChangeEvent::ObjectMaterial;
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
  if (event.has(ChangeEvent::ObjectMaterial) &&
      size_t(index) < prepared_->renderScene.objects.size()) {
    InsertedObject& o = prepared_->renderScene.objects[size_t(index)];
    o.material = materialFromKeys(keys.material, o.meshObject.get());
  }
  if (event.what) Q_EMIT changed(event);
}

}  // namespace inlay::studio
