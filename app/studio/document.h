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

#include <functional>
#include <memory>
#include <optional>

namespace inlay::studio {

// An undo step's text as a recipe rather than a string: it calls tr() with the command's
// source text and arguments (numbers, a user's name) each time it is asked, so the history,
// the Edit menu's Undo/Redo entries and their tooltips follow a change of language
// (Document::retranslateHistory).
using UndoText = std::function<QString()>;

class PrepareWorker;
struct PrepareResult;

// What changed, so listeners can do only the work they need. The viewport ignores the details
// and repaints everything from the document's state.
struct ChangeEvent {
  enum Kind {
    SceneReplaced = 1u << 0,  // a new SceneDoc (open / new from photo); nothing prepared yet
    PrepareStarted = 1u << 1,
    PrepareFinished = 1u << 2,  // state() is Ready or Failed (or Empty after a cancel)
    ObjectPlacement = 1u << 3,  // base_px / height_m / yaw_deg of objectIndex
    ObjectMaterial = 1u << 4,   // material of objectIndex
    Selection = 1u << 5,
    FilePath = 1u << 6,               // filePath() changed (open, save as)
    ObjectsAddedOrRemoved = 1u << 7,  // objects inserted or deleted; indices may have shifted
    Marks = 1u << 8,                  // the scene's marks changed (SceneMarks); preparation restarted
    ObjectShown = 1u << 9,            // name or hidden of objectIndex
  };
  unsigned what = 0;
  int objectIndex = -1;  // for ObjectPlacement / ObjectMaterial
  bool has(Kind k) const { return (what & k) != 0; }
};

bool operator==(const SceneMarks& a, const SceneMarks& b);

// Which list of marks (for removeMark).
enum class MarkKind { Light, Shaft, Surface, Occluder };
// One mark: its list and its index there.
struct MarkRef {
  MarkKind kind = MarkKind::Light;
  int index = -1;
  bool operator==(const MarkRef&) const = default;
};
// One point of a mark that can be dragged on its own. `point` numbers the mark's points:
//   light: its outline's points; surface: its outline's points, then its height click;
//   shaft: the lit patch box's corners (x0y0, x1y0, x1y1, x0y1), then the source box's;
//   occluder: the points of its foreground strokes, then of its background strokes, in order.
struct MarkPoint {
  MarkRef mark;
  int point = -1;
  Vec2 px{0, 0};  // where it is now (image pixels)
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
  // Restores work from a recovery file (Autosaver): the scene as it was, belonging to
  // `originalPath` ("" for a new scene), with unsaved changes (not clean, no undo history).
  bool restoreRecovery(const QString& recoveryPath, const QString& originalPath, QString* error);
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
  // Sets every command's text again in the current language (on QEvent::LanguageChange,
  // before the Undo/Redo actions take their texts from the stack).
  void retranslateHistory();
  int selectedObject() const { return selected_; }
  void setSelectedObject(int index);  // -1: none; not undoable; deselects the mark
  // The selected mark (a light, shaft, surface or occluder), if any; selecting one deselects
  // the object. Not undoable; cleared when the marks change.
  std::optional<MarkRef> selectedMark() const { return selectedMark_; }
  void setSelectedMark(std::optional<MarkRef> mark);
  int objectCount() const { return int(doc_.objects.size()); }

  // --- Edits (undoable). Each returns false, changes nothing and sets `reason` (one
  // user-facing line) when the edit is not possible. ---
  // `dragId` > 0: consecutive moves with the same id merge into one undo step.
  bool moveObject(int index, const Vec2& basePx, int dragId = 0, QString* reason = nullptr);
  // `dragId` > 0: the changes of one handle drag merge into one undo step.
  bool setObjectHeight(int index, double heightM, QString* reason = nullptr, int dragId = 0);
  bool setObjectYaw(int index, double yawDeg, QString* reason = nullptr, int dragId = 0);
  // Moves and turns at once (a drag that snaps the object's back to a wall).
  bool moveAndTurnObject(int index, const Vec2& basePx, double yawDeg, int dragId = 0,
                         QString* reason = nullptr);
  bool setMaterial(int index, const MaterialKeys& material, QString* reason = nullptr);
  // Appends an object (its mesh is loaded here, on the calling thread) and selects it.
  bool insertObject(const ObjectKeys& keys, QString* reason = nullptr);
  // The same with a mesh already loaded (Insert Model… loads on a worker thread); `mesh` must
  // be what loadObjectMesh(keys) gives.
  bool insertObject(const ObjectKeys& keys, std::shared_ptr<const TriangleMesh> mesh,
                    QString* reason = nullptr);
  bool removeObject(int index, QString* reason = nullptr);
  // A copy of object `index` standing beside it (the first free spot on a supporting surface
  // to its right, left, front or back; on the same spot when there is none), named
  // "<name> 2", ..., selected. One undo step.
  bool duplicateObject(int index, QString* reason = nullptr);
  // The name the user gives (objects[].name); empty: named after its mesh again.
  bool renameObject(int index, const QString& name, QString* reason = nullptr);
  // Hidden objects stay in the scene (and the file) but are not rendered.
  bool setObjectHidden(int index, bool hidden, QString* reason = nullptr);
  // What the scene tree and Properties call object `index`: its name, else its file's name.
  QString objectName(int index) const;
  // The object's width (x), height (y) and depth (z) in metres as placed, before its turn;
  // nullopt while its mesh is not loaded (the scene is being prepared).
  std::optional<Vec3> objectSizeM(int index) const;
  // A base pixel near `px` where an object can stand: `px` itself when it is on a supporting
  // surface (floor, table top, step), else the first such pixel straight below it (a drop on a
  // wall lands on the floor in front of it). nullopt when there is none or nothing is prepared.
  std::optional<Vec2> supportPointNear(const Vec2& px) const;
  // Where object `index` would stand with its back against a wall when its base is dragged to
  // `basePx`: the nearest wall of the room box whose gap to the object's back (its depth turned
  // to face away from the wall) is under kWallSnapM, with the base moved along the wall's normal
  // so the back is 5 mm off the wall and the yaw facing into the room (0 for the back wall, 90
  // for the left one, -90 for the right one, 180 for the wall behind the camera). nullopt when no
  // wall is that near, the object is not loaded, or the moved base would leave its support (a
  // table top narrower than the snap).
  struct WallSnap {
    Vec2 basePx{0, 0};
    double yawDeg = 0;
    SurfaceKind wall = SurfaceKind::WallBack;
  };
  static constexpr double kWallSnapM = 0.25;
  std::optional<WallSnap> wallSnap(int index, const Vec2& basePx) const;
  // A base pixel where a new object can stand: the first point on a supporting surface along
  // the photo's vertical centre line, from the bottom up. nullopt if there is none (or the
  // scene is not prepared).
  std::optional<Vec2> freeStandingPointPx() const;

  // --- Edits of the scene's marks (undoable). Each pushes one command whose redo and undo
  // replace the marks and restart preparation on the worker (cancelling a running one); they
  // are possible whenever a photo is loaded, also when preparation failed (a fix may cure it).
  // The corners of the back wall as shown: the user's (layout.back_wall_px) when given, else
  // the newest estimate's; nullopt before the first estimate.
  std::optional<std::array<Vec2, 4>> shownBackWallPx() const;
  bool backWallIsUsers() const { return doc_.layout.backWallPx.has_value(); }
  // Keeps the estimated box as the user's (writes layout.back_wall_px).
  bool acceptEstimatedBox(QString* reason = nullptr);
  // Moves one corner (0 TL, 1 TR, 2 BR, 3 BL); the others keep their shown place. A drag passes
  // one dragId for all its moves: one undo step.
  bool setBackWallCorner(int corner, const Vec2& px, int dragId = 0, QString* reason = nullptr);
  // Forgets the user's corners: the box is estimated again.
  bool resetBackWall(QString* reason = nullptr);
  // A light outlined on the photo (>= 3 points, a polygon with area).
  bool addLight(const std::vector<Vec2>& outlinePx, QString* reason = nullptr);
  // A shaft of sunlight: a box around the lit patch and one around its source (window).
  bool addShaft(const std::array<double, 4>& shaftBoxPx, const std::array<double, 4>& sourceBoxPx,
                QString* reason = nullptr);
  // An extrusion (a table top): its outline and a floor click straight below outlinePx[0].
  bool addExtrusion(const std::vector<Vec2>& outlinePx, const Vec2& heightClickPx,
                    QString* reason = nullptr);
  // An occluder from its first strokes (at least one of each kind).
  bool addOccluder(const OccluderKeys& occluder, QString* reason = nullptr);
  // One more stroke for occluder `index` (foreground: over the thing in front).
  bool addOccluderStroke(int index, bool foreground, const std::vector<Vec2>& strokePx,
                         QString* reason = nullptr);
  bool removeMark(MarkKind kind, int index, QString* reason = nullptr);
  // Every draggable point of every mark (see MarkPoint), from the document's state: the
  // viewport draws and hit-tests these.
  std::vector<MarkPoint> markPoints() const;
  // Moves one point of a mark (MarkPoint numbering). A drag passes one dragId: one undo step.
  // Refused when the mark would lose its area (a light or a surface) or a box its size.
  bool moveMarkPoint(MarkRef mark, int point, const Vec2& px, int dragId = 0, QString* reason = nullptr);
  // Two segments {a0, b0, a1, b1} the user drew along world axis `axis` (0 x, 1 y, 2 z): the
  // camera is re-estimated with that vanishing point fixed (camera.vanishing_lines_px). nullopt
  // forgets them. Refused for degenerate segments or two segments on one line. Drawing lines
  // drops camera.vanishing_points_px (a fixed camera would override them).
  bool setVanishingLines(int axis, const std::optional<std::array<Vec2, 4>>& segmentsPx,
                         QString* reason = nullptr);
  // The material of a real surface of the room (room.materials.<surface>, a name from
  // roomSurfaceNames()); nullopt makes it matte again.
  bool setRoomMaterial(const std::string& surface, const std::optional<RoomMaterialKeys>& material,
                       QString* reason = nullptr);
  // The names of the room's surfaces that can take a material (floor, walls, ceiling, the
  // surfaces' tops and sides), of the newest prepared scene (kept while it re-prepares).
  std::vector<std::string> roomSurfaceNames() const;
  // How the photo's codes map to radiance (camera.response: auto, srgb, linear or explicit);
  // one undo step, the scene is prepared again.
  bool setCameraResponse(const ResponseKeys& response, QString* reason = nullptr);
  bool removeMark(MarkRef mark, QString* reason = nullptr);
  SceneMarks marks() const;
  // The newest camera estimate (kept while the scene is re-prepared), or null.
  const CameraEstimate* lastEstimate() const { return lastEstimate_ ? &*lastEstimate_ : nullptr; }

  // A unique id for a new drag (for moveObject's dragId).
  static int newDragId();

 Q_SIGNALS:
  void changed(const inlay::studio::ChangeEvent& event);
  // stage: the engine's stage name ("photo", "camera", "room", "lighting", "objects").
  void prepareProgress(const QString& stage, double fraction);

 private:
  // Why objects cannot be edited now (index -1: any object, e.g. inserting); empty when they can.
  // `whilePreparing`: an edit of an existing object's keys, which the document takes at once
  // and the new PreparedScene catches up with (catchUpObjects).
  QString whyObjectsCannotChange(int index, bool whilePreparing = false) const;
  friend class ObjectEditCommand;
  friend class ObjectListCommand;
  friend class MarksCommand;
  // Validates and pushes a change of the marks (see the mark edits).
  bool editMarks(const SceneMarks& after, int mergeId, UndoText text, QString* reason);
  // Replaces the marks and restarts preparation (from an undo command).
  void applyMarks(const SceneMarks& marks);
  // An object edit while nothing is prepared (undo during preparation): the keys are the
  // document's, so preparation restarts with them.
  void changeObjectsUnprepared(std::vector<ObjectKeys> objects, int selected);
  // Validates `keys` for object `index` and pushes the command (see the edit functions).
  bool editObject(int index, const ObjectKeys& keys, int mergeId, UndoText text, QString* reason);
  // Applies object keys already known to be valid (from an undo command).
  void applyObject(int index, const ObjectKeys& keys);
  // Insert / remove one object everywhere it is mirrored (from an undo command).
  void insertObjectAt(int index, const ObjectKeys& keys, std::shared_ptr<const TriangleMesh> mesh);
  void removeObjectAt(int index);
  void onPrepared(const PrepareResult& result);
  // "chair" -> "chair 2" (or the next number no object has).
  QString uniqueName(const QString& base) const;
  // objectName(index) as an undo text: a user's or file's name stays, "sphere" follows the language.
  UndoText objectNameText(int index) const;
  // A base pixel beside object `index` on the same surface level (for a duplicate).
  std::optional<Vec2> spotBeside(int index) const;
  // Applies the object edits made while the scene was being prepared to the new PreparedScene;
  // returns the reason when one cannot stand where the user put it.
  QString catchUpObjects(const std::vector<ObjectKeys>& preparedWith);
  void resetTo(SceneDoc doc, const QString& filePath);

  SceneDoc doc_;
  QString filePath_;
  State state_ = State::Empty;
  std::unique_ptr<PreparedScene> prepared_;
  QString prepareError_;
  QStringList warnings_;  // of the file (loadWarnings_) and of the newest preparation
  QStringList loadWarnings_;
  QUndoStack undo_;
  int selected_ = -1;
  std::optional<MarkRef> selectedMark_;
  std::optional<std::array<Vec2, 4>> estimatedBackWallPx_;  // of the newest automatic estimate
  std::optional<CameraEstimate> lastEstimate_;
  std::vector<std::string> roomSurfaceNames_;  // of the newest prepared scene

  QThread thread_;
  PrepareWorker* worker_ = nullptr;  // lives on thread_
  quint64 jobId_ = 0;
  std::shared_ptr<CancelToken> cancel_;
};

}  // namespace inlay::studio

Q_DECLARE_METATYPE(inlay::studio::ChangeEvent)
