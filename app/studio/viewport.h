// The photo / composite view with its overlays and the tools that draw the scene's marks, all in
// immediate mode.
//
// paintEvent() draws, from the Document's state and nothing else: the chosen layer (composite,
// photo, albedo, ...; the photo in "before" mode) scaled by zoom and pan, the back wall with its
// four draggable corners (dashed while it is the automatic estimate, solid once it is the
// user's) and the room's receding edges, the estimate's line segments by vanishing point with
// the two longest of each family extended toward it and their residuals, the estimate's
// confidences and warnings, light outlines, shaft boxes, extrusion outlines with their height
// clicks, occluder scribbles, and each object's base marker with its height and facing gizmo.
// Hit-testing (objects, corners, marks) reads the same state. No overlay object is kept between paints, so nothing can
// fall out of sync with the document. The only state kept here is the input of the tool in use
// (the points of an outline not yet closed, a stroke being drawn), drawn the same way.
//
// Mouse, Select tool: a left click on a mark selects it (Edit > Delete removes it); a left press
// on an object's marker (within kPickRadiusPx) selects it and a
// drag moves its base (Document::moveObject, one undo step per drag; a pixel not on a supporting
// surface keeps the last valid position and reports the reason through statusMessage()); on a
// back-wall corner a drag moves that corner (Document::setBackWallCorner, one undo step) with a
// loupe magnifying the photo under the cursor. Light and Surface tools: clicks add outline points;
// a click on the first point, a double click or Enter closes it (Surface then asks for the height
// click on the floor below the first point); Backspace removes the last point, Escape drops the
// input. Shaft tool: drag a box around the lit patch, then one around its source. Occluder tool:
// left drags draw strokes over the thing in front, right drags over what is behind; the occluder
// is added once it has both, later strokes go to it until Enter starts a new one.
// A drag on a point of a mark (a light's or a table top's outline point, a shaft box's corner,
// an occluder stroke's point) moves that point alone (Document::moveMarkPoint, one undo step).
// Vanishing Lines tool: drag two segments along edges that run in one world direction (X, Y, Z
// keys choose it; z by default); the camera is re-estimated with that vanishing point fixed.
// The selected object carries two handles: a disc at the tip of its facing arrow (its front,
// +z of the model) turns it about its base (yaw; Shift: 15° steps) and a square at the top of
// its height line scales it uniformly (height_m); each drag is one undo step. Dragging an object
// near a wall (Document::kWallSnapM) stands it with its back against the wall, facing into the
// room (Document::wallSnap; Shift: no snapping); dragged away again it takes back its own turn.
// The before/after split (setSplitView): the photo left of a vertical divider, the composite
// right of it; the divider is dragged with the left button in any tool.
// Arrow keys nudge the selected object by one image pixel (ten with Shift), one undo step each.
// Wheel zooms about the cursor; middle drag pans. A model file dropped on the view stands on the
// surface under the cursor (modelDropped; the window reads and inserts it). GUI thread only.
#pragma once

#include "inlay/modeling/core.h"
#include "inlay/modeling/scene_file.h"
#include "document.h"
#include "render_controller.h"

#include <QElapsedTimer>
#include <QImage>
#include <QPointF>
#include <QRectF>
#include <QRegion>
#include <QWidget>

#include <optional>
#include <vector>

class QPainter;

namespace inlay::studio {

class Document;

class Viewport : public QWidget {
  Q_OBJECT

 public:
  static constexpr double kPickRadiusPx = 10.0;  // widget pixels
  static constexpr int kLoupeRadiusPx = 70;      // widget pixels
  static constexpr double kLoupeZoom = 4.0;      // magnification over the current zoom

  enum class Tool { Select, Light, Shaft, Surface, Occluder, VanishingLines };
  // The selected object's on-canvas handles.
  enum class Handle { None, Turn, Height };

  Viewport(Document* document, RenderController* renderer, QWidget* parent = nullptr);

  // Image pixel frame (the scene file's) <-> widget coordinates.
  QPointF widgetFromImage(const Vec2& imagePx) const;
  Vec2 imageFromWidget(const QPointF& widgetPos) const;
  double zoom() const { return scale_; }
  bool showsBefore() const { return showBefore_; }
  Layer layer() const { return layer_; }
  Tool tool() const { return tool_; }
  bool showsVanishingLines() const { return showVanishing_; }
  // The object whose marker is within kPickRadiusPx of `widgetPos` (nearest), or -1.
  int objectAt(const QPointF& widgetPos) const;
  // The back-wall corner (0 TL, 1 TR, 2 BR, 3 BL) within kPickRadiusPx of `widgetPos`, or -1.
  int cornerAt(const QPointF& widgetPos) const;
  // The light, shaft, surface or occluder drawn under `widgetPos` (inside its outline or box,
  // or within kPickRadiusPx of its lines), or nullopt.
  std::optional<MarkRef> markAt(const QPointF& widgetPos) const;
  // The point of a mark (Document::markPoints) within kPickRadiusPx of `widgetPos` (nearest;
  // the selected mark's points first), or nullopt.
  std::optional<MarkPoint> markPointAt(const QPointF& widgetPos) const;
  // The world axis (0 x, 1 y, 2 z) the Vanishing Lines tool draws for; keys X, Y, Z choose it.
  int vanishingAxis() const { return vanishingAxis_; }
  void setVanishingAxis(int axis);
  // Where the selected object's handle is drawn (widget coordinates); nullopt when no object
  // is selected, nothing is prepared or the handle's point is behind the camera.
  std::optional<QPointF> handlePos(Handle handle) const;
  // The selected object's handle within kPickRadiusPx of `widgetPos`.
  Handle handleAt(const QPointF& widgetPos) const;
  // The before/after split: shown, and the divider's place as a fraction of the photo's width.
  bool splitView() const { return split_; }
  double splitFraction() const { return splitFraction_; }
  // The divider's x in widget coordinates.
  double splitWidgetX() const;
  // The finished final render shown in place of the preview composite (the Composite layer,
  // the split's right side), with a banner saying so; null: the preview. The window sets it
  // when Render Final Image finishes and clears it at the next edit.
  const QImage& finalImage() const { return finalImage_; }
  bool showsFinalImage() const { return !finalImage_.isNull(); }
  // True while the loupe is drawn (a corner drag).
  bool loupeShown() const { return dragCorner_ >= 0; }
  // The outline points of the Light / Surface tool not yet committed (image pixels).
  const std::vector<Vec2>& pendingPoints() const { return toolPoints_; }
  QSize sizeHint() const override;

  // Paint durations (ms) since the last clear, for the benchmark and the status figures.
  const std::vector<double>& paintTimesMs() const { return paintTimesMs_; }
  void clearPaintTimes() { paintTimesMs_.clear(); }

 public Q_SLOTS:
  void zoomIn();
  void zoomOut();
  void zoomToFit();
  void setShowBefore(bool before);
  void setLayer(inlay::studio::Layer layer);
  void setTool(inlay::studio::Viewport::Tool tool);
  void setShowVanishingLines(bool show);
  void setSplitView(bool on);
  void setSplitFraction(double fraction);  // clamped to [0, 1]
  // The final image to show (null clears it); `caption`: the banner's text.
  void setFinalImage(const QImage& image, const QString& caption = {});
  // The banner's text over the shown final image (a change of language).
  void setFinalCaption(const QString& caption);
  const QString& finalCaption() const { return finalCaption_; }
  // The camera estimate's lines drawn bottom left on the photo (confidences, focal length,
  // warnings), empty when hidden. When they would cover more than a fifth of the viewport's
  // height (a York photo's box advice is 8 lines at 1024 x 700, over the inserted object), each
  // warning keeps its first line and a last line says where the whole text is.
  QStringList estimateLines() const;
  // Enter: closes the outline being drawn / ends the occluder; Escape drops the tool's input.
  void commitToolInput();
  void cancelToolInput();

 Q_SIGNALS:
  // A transient message for the status bar (empty: clear it).
  void statusMessage(const QString& message);
  void zoomChanged(double zoom);
  // A model file (a local file or file URL, text/uri-list) was dropped; imagePx: where.
  void modelDropped(const QString& path, QPointF imagePx);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void changeEvent(QEvent* event) override;  // a language switch: the hint and labels again
  // Drops of model files (OBJ, PLY, glTF, GLB, FBX, DAE, 3DS) as local file URLs: the object
  // stands where the cursor is (see modelDropped). Other drops go on to the window (a photo or
  // a scene opens).
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dragMoveEvent(QDragMoveEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  QSize imageSize() const;
  void zoomAbout(double factor, const QPointF& widgetPos);
  void updateFit();
  const QImage& shownImage();
  // Paint steps, in drawing order.
  void paintImage(QPainter& p);
  void paintScaled(QPainter& p, const QImage& image, const QRectF& target);
  void paintRoom(QPainter& p);
  void paintVanishingLines(QPainter& p);
  // The pixels the shown frame's objects cover (mask over one half), in the frame's pixels;
  // cached per frame. The estimate's lines are not drawn over them.
  const QRegion& objectRegion();
  void paintMarks(QPainter& p);
  void paintObjects(QPainter& p);
  void paintHandles(QPainter& p);
  void paintSplit(QPainter& p);
  void paintMarkHandles(QPainter& p);
  void paintToolInput(QPainter& p);
  void paintLoupe(QPainter& p);
  void paintStatus(QPainter& p);
  // Tool input.
  void pressSelect(QMouseEvent* event);
  void dragObjectTo(const Vec2& px, Qt::KeyboardModifiers modifiers);
  void dragHandleTo(const Vec2& px, Qt::KeyboardModifiers modifiers);
  void addOutlinePoint(const QPointF& widgetPos);
  void closeOutline();
  void finishStroke();
  void report(bool ok, const QString& reason);
  QString toolHint() const;

  Document* document_;
  RenderController* renderer_;
  double scale_ = 1.0;  // widget pixels per image pixel
  QPointF offset_;      // widget position of the image's top-left corner
  bool fit_ = true;     // keep fitting on resize until the user zooms or pans
  bool showBefore_ = false;
  bool showVanishing_ = true;
  QRegion objectRegion_;
  const void* objectRegionFrame_ = nullptr;  // the frame objectRegion_ was made from
  Layer layer_ = Layer::Composite;
  Tool tool_ = Tool::Select;

  std::optional<MarkPoint> dragPoint_;  // a mark's point being dragged (Select tool)
  int dragObject_ = -1;
  double dragStartYawDeg_ = 0;        // the dragged object's own turn (restored off a wall)
  Handle dragHandle_ = Handle::None;  // a handle of dragObject_ being dragged
  double dragHeightOffsetM_ = 0;      // Height: the cursor's height on the line minus height_m
  Handle hoverHandle_ = Handle::None;
  bool split_ = false;
  double splitFraction_ = 0.5;
  bool draggingSplit_ = false;
  int dragCorner_ = -1;
  int dragId_ = 0;
  Vec2 dragGrabPx_{0, 0};  // the dragged point minus the image point under the cursor
  bool panning_ = false;
  QPointF lastPanPos_;
  QPointF cursorPos_;
  int hoverObject_ = -1;
  int hoverCorner_ = -1;

  // Input of the tool in use (image pixels).
  std::vector<Vec2> toolPoints_;      // Light / Surface outline
  bool awaitingHeightClick_ = false;  // Surface: outline closed, the floor click comes next
  std::optional<QRectF> shaftBox_;    // Shaft: the lit patch's box, drawn first
  std::optional<Vec2> rubberFrom_;    // Shaft: the corner where the box drag started
  Vec2 rubberTo_{0, 0};
  std::vector<Vec2> stroke_;  // Occluder: the stroke being drawn
  bool strokeForeground_ = true;
  bool stroking_ = false;
  OccluderKeys pendingOccluder_;      // strokes before the occluder has both kinds
  int currentOccluder_ = -1;          // the occluder later strokes go to
  int vanishingAxis_ = 2;             // Vanishing Lines: the axis drawn for
  std::vector<Vec2> vanishingInput_;  // Vanishing Lines: the first segment's ends, once drawn

  // The shown image resampled to the screen size when zoomed out (smooth resampling of a large
  // photo on every paint would make drags stutter). A cache of pixels, not of overlay state.
  QImage scaledImage_[2];
  qint64 scaledKey_[2] = {0, 0};
  int lastSlot_ = 0;
  QImage finalImage_;  // the finished final render (full resolution), shown until an edit
  QString finalCaption_;
  QImage layerImage_;  // keeps the image of a non-composite layer alive during a paint
  std::vector<double> paintTimesMs_;
};

}  // namespace inlay::studio
