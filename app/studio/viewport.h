// The photo / composite view with its overlays, drawn in immediate mode.
//
// paintEvent() draws, from the Document's state and nothing else: the composite (or the photo
// in "before" mode) scaled by zoom and pan, the back wall's quad and the room's receding edges,
// the outlines of the lights, and each object's base marker with its height and facing gizmo.
// Hit-testing reads the same state. No overlay object is kept between paints, so nothing can
// fall out of sync with the document.
//
// Mouse: left press on an object's marker (within kPickRadiusPx) selects it and a drag moves its
// base (Document::moveObject, one undo step per drag; a pixel not on a supporting surface keeps
// the last valid position and reports the reason through statusMessage()). Arrow keys nudge
// the selected object by one image pixel (ten with Shift), one undo step each. Wheel zooms
// about the cursor; middle drag pans. GUI thread only.
#pragma once

#include "inlay/modeling/core.h"

#include <QImage>
#include <QPointF>
#include <QWidget>

namespace inlay::studio {

class Document;
class RenderController;

class Viewport : public QWidget {
  Q_OBJECT

 public:
  static constexpr double kPickRadiusPx = 10.0;  // widget pixels

  Viewport(Document* document, RenderController* renderer, QWidget* parent = nullptr);

  // Image pixel frame (the scene file's) <-> widget coordinates.
  QPointF widgetFromImage(const Vec2& imagePx) const;
  Vec2 imageFromWidget(const QPointF& widgetPos) const;
  double zoom() const { return scale_; }
  bool showsBefore() const { return showBefore_; }
  // The object whose marker is within kPickRadiusPx of `widgetPos` (nearest), or -1.
  int objectAt(const QPointF& widgetPos) const;
  QSize sizeHint() const override;

 public Q_SLOTS:
  void zoomIn();
  void zoomOut();
  void zoomToFit();
  void setShowBefore(bool before);

 Q_SIGNALS:
  // A transient message for the status bar (empty: clear it).
  void statusMessage(const QString& message);
  void zoomChanged(double zoom);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;

 private:
  QSize imageSize() const;
  void zoomAbout(double factor, const QPointF& widgetPos);
  void updateFit();

  Document* document_;
  RenderController* renderer_;
  double scale_ = 1.0;  // widget pixels per image pixel
  QPointF offset_;      // widget position of the image's top-left corner
  bool fit_ = true;     // keep fitting on resize until the user zooms or pans
  bool showBefore_ = false;

  int dragObject_ = -1;
  int dragId_ = 0;
  Vec2 dragGrabPx_{0, 0};  // base_px minus the image point under the cursor at the press
  bool panning_ = false;
  QPointF lastPanPos_;
  int hoverObject_ = -1;

  // The shown image resampled to the screen size when zoomed out (smooth resampling of a large
  // photo on every paint would make drags stutter). A cache of pixels, not of overlay state.
  QImage scaledImage_;
  qint64 scaledKey_ = 0;
};

}  // namespace inlay::studio
