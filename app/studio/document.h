// The studio's document: the scene file being edited (SceneDoc), what the engine prepared from
// it (PreparedScene), the undo stack, and the selection.
//
// Ownership and threads: a Document lives on the GUI thread and every public method must be
// called there. prepareScene() runs on the document's own worker thread (PrepareWorker moved
// into a QThread); its result comes back by queued signal and is dropped when a newer job was
// started or the job was cancelled. The PreparedScene is only ever read or written on the GUI
// thread (the renderer gets copies: RenderSession::setScene copies the RenderScene, and the
// frame sink gets its own snapshot), so edits need no lock.
//
// Edits go through the narrow API below (moveObject, setObjectHeight, ...). Each one validates
// first (the new base pixel must land on a supporting surface), then pushes a QUndoCommand; a
// drag passes one dragId for all its moves so they merge into one undo step, and a drag that
// ends where it started leaves no undo step. Every change, undoable or not, is announced by the
// one signal changed(ChangeEvent).
#pragma once

#include "inlay/engine/pipeline.h"

#include <QObject>
#include <QString>
#include <QStringList>
#include <QThread>
#include <QUndoStack>

#include <memory>
#include <optional>

namespace inlay::studio {

class PrepareWorker;
struct PrepareResult;

// What changed, so listeners can do only the work they need. The viewport ignores the details
// and repaints everything from the document's state.
struct ChangeEvent {
  enum Kind {
    SceneReplaced = 1u << 0,    // a new SceneDoc (open / new from photo); nothing prepared yet
    PrepareStarted = 1u << 1,
    PrepareFinished = 1u << 2,  // state() is Ready or Failed (or Empty after a cancel)
    ObjectPlacement = 1u << 3,  // base_px / height_m / yaw_deg of objectIndex
    ObjectMaterial = 1u << 4,   // material of objectIndex
    Selection = 1u << 5,
    FilePath = 1u << 6,         // filePath() changed (open, save as)
    ObjectsAddedOrRemoved = 1u << 7,  // objects inserted or deleted; indices may have shifted
  };
  unsigned what = 0;
  int objectIndex = -1;  // for ObjectPlacement / ObjectMaterial
  bool has(Kind k) const { return (what & k) != 0; }
};

class Document : public QObject {
  Q_OBJECT

 public:
  enum class State {
    Empty,      // nothing loaded, or preparation cancelled
    Preparing,  // prepareScene() running on the worker thread
    Ready,      // prepared() is valid
    Failed,     // prepareError() says why; the SceneDoc is still shown and can be saved
  };

  explicit Document(QObject* parent = nullptr);
  ~Document() override;  // cancels a running preparation and joins the worker thread

  // --- Opening and saving (not undoable; opening clears the undo stack) ---
  // Parses a scene file and starts preparing it. On a parse error returns false, leaves the
  // document unchanged and sets `error` to one user-facing line.
  bool openSceneFile(const QString& path, QString* error);
  // A new document holding only the photo (camera, room and lights are estimated).
  void newFromPhoto(const QString& photoPath);
  // Writes the scene file atomically. Relative paths (photo, meshes) are rewritten against the
  // new folder. Marks the undo stack clean.
  bool saveAs(const QString& path, QString* error);
  // (Re)starts prepareScene() for the current SceneDoc; cancels a running job.
  void prepare();
  void cancelPrepare();

  // --- State ---
  const SceneDoc& scene() const { return doc_; }
  State state() const { return state_; }
  bool isReady() const { return state_ == State::Ready; }
  // Valid only in state Ready; GUI thread only.
  const PreparedScene* prepared() const { return prepared_.get(); }
  QString prepareError() const { return prepareError_; }
  QStringList warnings() const { return warnings_; }
  QString filePath() const { return filePath_; }
  QUndoStack* undoStack() { return &undo_; }
  int selectedObject() const { return selected_; }
  void setSelectedObject(int index);  // -1: none; not undoable
  int objectCount() const { return int(doc_.objects.size()); }

  // --- Edits (undoable). Each returns false, changes nothing and sets `reason` (one
  // user-facing line) when the edit is not possible. ---
  // `dragId` > 0: consecutive moves with the same id merge into one undo step.
  bool moveObject(int index, const Vec2& basePx, int dragId = 0, QString* reason = nullptr);
  bool setObjectHeight(int index, double heightM, QString* reason = nullptr);
  bool setObjectYaw(int index, double yawDeg, QString* reason = nullptr);
  bool setMaterial(int index, const MaterialKeys& material, QString* reason = nullptr);
  // Appends an object (its mesh is loaded here, on the calling thread) and selects it.
  bool insertObject(const ObjectKeys& keys, QString* reason = nullptr);
  bool removeObject(int index, QString* reason = nullptr);
  // A base pixel where a new object can stand: the first point on a supporting surface along
  // the photo's vertical centre line, from the bottom up. nullopt if there is none (or the
  // scene is not prepared).
  std::optional<Vec2> freeStandingPointPx() const;

  // A unique id for a new drag (for moveObject's dragId).
  static int newDragId();

 Q_SIGNALS:
  void changed(const inlay::studio::ChangeEvent& event);
  // stage: the engine's stage name ("photo", "camera", "room", "lighting", "objects").
  void prepareProgress(const QString& stage, double fraction);

 private:
  // Why objects cannot be edited now (index -1: any object, e.g. inserting); empty when they can.
  QString whyObjectsCannotChange(int index) const;
  friend class ObjectEditCommand;
  friend class ObjectListCommand;
  // Validates `keys` for object `index` and pushes the command (see the edit functions).
  bool editObject(int index, const ObjectKeys& keys, int mergeId, const QString& text,
                  QString* reason);
  // Applies object keys already known to be valid (from an undo command).
  void applyObject(int index, const ObjectKeys& keys);
  // Insert / remove one object everywhere it is mirrored (from an undo command).
  void insertObjectAt(int index, const ObjectKeys& keys, std::shared_ptr<const TriangleMesh> mesh);
  void removeObjectAt(int index);
  void onPrepared(const PrepareResult& result);
  void resetTo(SceneDoc doc, const QString& filePath);

  SceneDoc doc_;
  QString filePath_;
  State state_ = State::Empty;
  std::unique_ptr<PreparedScene> prepared_;
  QString prepareError_;
  QStringList warnings_;
  QUndoStack undo_;
  int selected_ = -1;

  QThread thread_;
  PrepareWorker* worker_ = nullptr;  // lives on thread_
  quint64 jobId_ = 0;
  std::shared_ptr<CancelToken> cancel_;
};


}  // namespace inlay::studio

Q_DECLARE_METATYPE(inlay::studio::ChangeEvent)
