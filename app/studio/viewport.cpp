#include "viewport.h"

#include "document.h"
#include "render_controller.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

namespace inlay::studio {
namespace {

constexpr double kMinZoom = 0.02, kMaxZoom = 32.0;

QColor srgbColour(const Vec3& linear) {
  auto enc = [](double v) { return int(std::lround(255.0 * linearToSrgb(float(v)))); };
  return QColor(enc(linear.x()), enc(linear.y()), enc(linear.z()));
}

// A line with a dark halo so it reads on any photo.
void haloLine(QPainter& p, const QPointF& a, const QPointF& b, const QColor& colour,
              double width = 1.5, Qt::PenStyle style = Qt::SolidLine) {
  p.setPen(QPen(QColor(0, 0, 0, 150), width + 2.0, Qt::SolidLine, Qt::RoundCap));
  p.drawLine(a, b);
  p.setPen(QPen(colour, width, style, Qt::RoundCap));
  p.drawLine(a, b);
}

void haloPolygon(QPainter& p, const QPolygonF& poly, const QColor& colour, double width = 1.5,
                 Qt::PenStyle style = Qt::SolidLine) {
  p.setBrush(Qt::NoBrush);
  p.setPen(QPen(QColor(0, 0, 0, 150), width + 2.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
  p.drawPolygon(poly);
  p.setPen(QPen(colour, width, style, Qt::RoundCap, Qt::RoundJoin));
  p.drawPolygon(poly);
}

void labelAt(QPainter& p, const QPointF& at, const QString& text, const QColor& colour) {
  const QRectF box = p.fontMetrics().boundingRect(text).adjusted(-3, -1, 3, 1);
  const QRectF placed = box.translated(at - box.bottomLeft() + QPointF(6, -6));
  p.setPen(Qt::NoPen);
  p.setBrush(QColor(0, 0, 0, 160));
  p.drawRoundedRect(placed, 3, 3);
  p.setPen(colour);
  p.drawText(placed, Qt::AlignCenter, text);
}

}  // namespace

Viewport::Viewport(Document* document, RenderController* renderer, QWidget* parent)
    : QWidget(parent), document_(document), renderer_(renderer) {
  setMouseTracking(true);
  setFocusPolicy(Qt::StrongFocus);
  setAttribute(Qt::WA_OpaquePaintEvent);
  setMinimumSize(160, 120);
  auto repaint = [this] {
    if (fit_) updateFit();
    update();
  };
  connect(document_, &Document::changed, this, [this, repaint](const ChangeEvent& e) {
    if (e.has(ChangeEvent::SceneReplaced)) fit_ = true;
    if (e.has(ChangeEvent::SceneReplaced) || e.has(ChangeEvent::ObjectsAddedOrRemoved)) {
      dragObject_ = -1;  // indices may have shifted
      hoverObject_ = -1;
    }
    repaint();
  });
  connect(renderer_, &RenderController::frameUpdated, this, repaint);
}

QSize Viewport::sizeHint() const { return {800, 600}; }

QSize Viewport::imageSize() const {
  if (const PreparedScene* p = document_->prepared())
    if (p->camera.widthPx > 0) return {p->camera.widthPx, p->camera.heightPx};
  if (renderer_->hasFrame()) return renderer_->compositeImage().size();
  return renderer_->photoImage().size();
}

QPointF Viewport::widgetFromImage(const Vec2& imagePx) const {
  return offset_ + QPointF(imagePx.x(), imagePx.y()) * scale_;
}

Vec2 Viewport::imageFromWidget(const QPointF& widgetPos) const {
  const QPointF p = (widgetPos - offset_) / scale_;
  return {p.x(), p.y()};
}

void Viewport::updateFit() {
  const QSize img = imageSize();
  if (img.isEmpty() || width() <= 0 || height() <= 0) return;
  const double s = std::min(double(width()) / img.width(), double(height()) / img.height());
  const double old = scale_;
  scale_ = std::clamp(s, kMinZoom, kMaxZoom);
  offset_ = QPointF((width() - img.width() * scale_) / 2.0, (height() - img.height() * scale_) / 2.0);
  if (old != scale_) Q_EMIT zoomChanged(scale_);
}

void Viewport::zoomToFit() {
  fit_ = true;
  updateFit();
  update();
}

void Viewport::zoomAbout(double factor, const QPointF& widgetPos) {
  const double s = std::clamp(scale_ * factor, kMinZoom, kMaxZoom);
  const Vec2 fixed = imageFromWidget(widgetPos);  // stays under the cursor
  scale_ = s;
  offset_ = widgetPos - QPointF(fixed.x(), fixed.y()) * scale_;
  fit_ = false;
  Q_EMIT zoomChanged(scale_);
  update();
}

void Viewport::zoomIn() { zoomAbout(1.25, QPointF(width() / 2.0, height() / 2.0)); }
void Viewport::zoomOut() { zoomAbout(0.8, QPointF(width() / 2.0, height() / 2.0)); }

void Viewport::setShowBefore(bool before) {
  if (showBefore_ == before) return;
  showBefore_ = before;
  update();
}

void Viewport::resizeEvent(QResizeEvent*) {
  if (fit_) updateFit();
}

int Viewport::objectAt(const QPointF& widgetPos) const {
  int best = -1;
  double bestDist = kPickRadiusPx;
  const auto& objects = document_->scene().objects;
  for (size_t i = 0; i < objects.size(); ++i) {
    const QPointF d = widgetFromImage(objects[i].basePx) - widgetPos;
    const double dist = std::hypot(d.x(), d.y());
    if (dist <= bestDist) {
      bestDist = dist;
      best = int(i);
    }
  }
  return best;
}

void Viewport::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), QColor(45, 45, 48));
  const SceneDoc& doc = document_->scene();
  const PreparedScene* prepared = document_->prepared();

  // --- The image ---
  const QImage& image = (showBefore_ || !renderer_->hasFrame()) ? renderer_->photoImage()
                                                                 : renderer_->compositeImage();
  const QSize imgSize = imageSize();
  if (!image.isNull()) {
    const QRectF target(offset_, QSizeF(imgSize.width() * scale_, imgSize.height() * scale_));
    const qreal dpr = devicePixelRatioF();
    const QSize screenSize = (target.size() * dpr).toSize();  // device pixels
    if (scale_ * dpr < 1.0 && !screenSize.isEmpty()) {
      if (image.cacheKey() != scaledKey_ || scaledImage_.size() != screenSize) {
        scaledImage_ = image.scaled(screenSize, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
        scaledKey_ = image.cacheKey();
      }
      p.drawImage(target, scaledImage_, QRectF(scaledImage_.rect()));
    } else {
      p.drawImage(target, image, QRectF(image.rect()));  // magnified: nearest, pixels visible
    }
  }
  p.setRenderHint(QPainter::Antialiasing);

  // --- The room: back wall quad and the edges receding toward the camera ---
  const QColor roomColour(90, 200, 255);
  std::optional<std::array<Vec2, 4>> wall;
  if (prepared)
    wall = backWallCornersPx(prepared->camera, prepared->box);
  else
    wall = doc.layout.backWallPx;
  if (wall) {
    QPolygonF quad;
    for (const Vec2& c : *wall) quad << widgetFromImage(c);
    haloPolygon(p, quad, roomColour, 1.5);
  }
  if (prepared) {
    const Camera& cam = prepared->camera;
    const RoomBox& box = prepared->box;
    const double xs[2] = {box.xLeftM, box.xRightM};
    const double ys[2] = {0.0, box.ceilingM};
    for (double x : xs)
      for (double y : ys) {
        const Vec3 back(x, y, box.zBackM);
        const std::optional<Vec2> a = cam.project(back);
        if (!a) continue;
        // Walk toward the camera while the point stays well in front of it.
        std::optional<Vec2> b;
        for (int k = 1; k <= 32; ++k) {
          const Vec3 q(x, y, box.zBackM + (box.zRearM - box.zBackM) * k / 32.0);
          if (cam.depthOf(q) < 0.2) break;
          b = cam.project(q);
        }
        if (b) haloLine(p, widgetFromImage(*a), widgetFromImage(*b), roomColour, 1.0, Qt::DashLine);
      }
  }

  // --- Lights ---
  const QColor lightColour(255, 220, 80);
  for (size_t i = 0; i < doc.lights.size(); ++i) {
    const LightKeys& light = doc.lights[i];
    QPolygonF poly;
    if (light.kind == LightKeys::Kind::PolygonPx) {
      for (const Vec2& q : light.pointsPx) poly << widgetFromImage(q);
    } else if (prepared) {
      for (const Vec3& c : light.cornersM)
        if (auto q = prepared->camera.project(c)) poly << widgetFromImage(*q);
      if (poly.size() != 4) poly.clear();  // partly behind the camera: not drawn
    }
    if (poly.size() < 2) continue;
    haloPolygon(p, poly, lightColour, 1.5,
                light.kind == LightKeys::Kind::PolygonPx ? Qt::SolidLine : Qt::DashLine);
    labelAt(p, poly.boundingRect().topRight(), tr("Light %1").arg(i + 1), lightColour);
  }

  // --- Objects: base marker, height line, facing arrow ---
  for (size_t i = 0; i < doc.objects.size(); ++i) {
    const ObjectKeys& o = doc.objects[i];
    const QPointF base = widgetFromImage(o.basePx);
    const bool selected = int(i) == document_->selectedObject();
    const bool hot = selected || int(i) == hoverObject_ || int(i) == dragObject_;
    const QColor accent = selected ? QColor(255, 150, 40) : QColor(240, 240, 240);
    if (prepared && i < prepared->placements.size()) {
      const Placement& pl = prepared->placements[i];
      const Camera& cam = prepared->camera;
      const Vec3 top = pl.baseWorld + Vec3(0, o.heightM, 0);
      const double yaw = o.yawDeg * std::numbers::pi / 180.0;
      // +x of the object turned by yaw about +y (counter-clockwise seen from above).
      const Vec3 facing(std::cos(yaw), 0.0, -std::sin(yaw));
      const Vec3 tip = pl.baseWorld + facing * std::max(0.15, 0.6 * o.heightM);
      if (auto t = cam.project(top); t && cam.depthOf(top) > 0.05)
        haloLine(p, base, widgetFromImage(*t), accent, hot ? 2.0 : 1.2, Qt::DotLine);
      if (auto t = cam.project(tip); t && cam.depthOf(tip) > 0.05) {
        const QPointF tipW = widgetFromImage(*t);
        haloLine(p, base, tipW, accent, hot ? 2.0 : 1.2);
        const QPointF d = tipW - base;
        const double len = std::hypot(d.x(), d.y());
        if (len > 4) {
          const QPointF u = d / len, n(-u.y(), u.x());
          haloLine(p, tipW, tipW - 7 * u + 4 * n, accent, hot ? 2.0 : 1.2);
          haloLine(p, tipW, tipW - 7 * u - 4 * n, accent, hot ? 2.0 : 1.2);
        }
      }
    }
    const double r = hot ? 7.5 : 6.0;
    p.setPen(QPen(QColor(0, 0, 0, 180), 3.0));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(base, r, r);
    p.setPen(QPen(accent, selected ? 2.5 : 1.5));
    p.setBrush(srgbColour(o.material.albedo));
    p.drawEllipse(base, r, r);
    p.drawLine(base - QPointF(r + 4, 0), base - QPointF(r, 0));
    p.drawLine(base + QPointF(r, 0), base + QPointF(r + 4, 0));
    p.drawLine(base - QPointF(0, r + 4), base - QPointF(0, r));
    p.drawLine(base + QPointF(0, r), base + QPointF(0, r + 4));
    labelAt(p, base, QString::number(i + 1), accent);
  }

  // --- State of the document ---
  QString banner;
  QColor bannerColour(255, 255, 255);
  switch (document_->state()) {
    case Document::State::Preparing:
      banner = tr("Preparing the scene…");
      break;
    case Document::State::Failed:
      banner = tr("The scene could not be prepared: %1").arg(document_->prepareError());
      bannerColour = QColor(255, 140, 140);
      break;
    case Document::State::Empty:
      if (imgSize.isEmpty()) banner = tr("Open a scene or a photo (File menu).");
      break;
    case Document::State::Ready:
      if (showBefore_) banner = tr("Before: the photo without objects");
      break;
  }
  if (!banner.isEmpty()) {
    const QRectF area = QRectF(rect()).adjusted(10, 10, -10, -10);
    const QRectF box =
        p.fontMetrics().boundingRect(area.toRect(), Qt::TextWordWrap, banner).adjusted(-6, -4, 6, 4);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0, 0, 0, 170));
    p.drawRoundedRect(box.translated(6, 4), 4, 4);
    p.setPen(bannerColour);
    p.drawText(area, Qt::TextWordWrap, banner);
  }
}

void Viewport::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::MiddleButton) {
    panning_ = true;
    lastPanPos_ = event->position();
    setCursor(Qt::ClosedHandCursor);
    return;
  }
  if (event->button() != Qt::LeftButton) return;
  const int hit = objectAt(event->position());
  document_->setSelectedObject(hit);
  if (hit >= 0) {
    dragObject_ = hit;
    dragId_ = Document::newDragId();
    dragGrabPx_ = document_->scene().objects[size_t(hit)].basePx - imageFromWidget(event->position());
    setCursor(Qt::SizeAllCursor);
  }
  update();
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
  if (panning_) {
    offset_ += event->position() - lastPanPos_;
    lastPanPos_ = event->position();
    fit_ = false;
    update();
    return;
  }
  if (dragObject_ >= 0) {
    if (dragObject_ >= document_->objectCount()) {
      dragObject_ = -1;
      return;
    }
    const Vec2 target = imageFromWidget(event->position()) + dragGrabPx_;
    QString reason;
    if (document_->moveObject(dragObject_, target, dragId_, &reason))
      Q_EMIT statusMessage(QString());
    else
      Q_EMIT statusMessage(tr("Cannot place the object here: %1").arg(reason));
    return;
  }
  const int hover = objectAt(event->position());
  if (hover != hoverObject_) {
    hoverObject_ = hover;
    setCursor(hover >= 0 ? Qt::OpenHandCursor : Qt::ArrowCursor);
    update();
  }
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
  if (event->button() == Qt::MiddleButton && panning_) {
    panning_ = false;
    unsetCursor();
    return;
  }
  if (event->button() == Qt::LeftButton && dragObject_ >= 0) {
    dragObject_ = -1;
    setCursor(objectAt(event->position()) >= 0 ? Qt::OpenHandCursor : Qt::ArrowCursor);
    update();
  }
}

void Viewport::keyPressEvent(QKeyEvent* event) {
  const int i = document_->selectedObject();
  Vec2 step(0, 0);
  switch (event->key()) {
    case Qt::Key_Left: step = Vec2(-1, 0); break;
    case Qt::Key_Right: step = Vec2(1, 0); break;
    case Qt::Key_Up: step = Vec2(0, -1); break;
    case Qt::Key_Down: step = Vec2(0, 1); break;
    default: QWidget::keyPressEvent(event); return;
  }
  if (i < 0 || i >= document_->objectCount()) {
    QWidget::keyPressEvent(event);
    return;
  }
  if (event->modifiers() & Qt::ShiftModifier) step *= 10.0;
  QString reason;
  if (document_->moveObject(i, document_->scene().objects[size_t(i)].basePx + step, 0, &reason))
    Q_EMIT statusMessage(QString());
  else
    Q_EMIT statusMessage(tr("Cannot place the object here: %1").arg(reason));
  event->accept();
}

void Viewport::wheelEvent(QWheelEvent* event) {
  const double steps = event->angleDelta().y() / 120.0;
  if (steps == 0) return;
  zoomAbout(std::pow(1.15, steps), event->position());
  event->accept();
}

}  // namespace inlay::studio
