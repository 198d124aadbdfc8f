#include "viewport.h"
#include "engine_text.h"

#include "document.h"
#include "model_import.h"

#include <QBitmap>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QElapsedTimer>
#include <QMimeData>
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

// The colour of each world axis's vanishing lines (x, y, z).
const QColor kAxisColour[3] = {QColor(255, 90, 90), QColor(90, 230, 90), QColor(110, 150, 255)};

constexpr double kMinZoom = 0.02, kMaxZoom = 32.0;

// An object's front (+z of its model) turned by `yawDeg` about +y.
Vec3 frontOf(double yawDeg) {
  const double yaw = yawDeg * std::numbers::pi / 180.0;
  return Vec3(std::sin(yaw), 0.0, std::cos(yaw));
}

// The distance from an object's base to its turn handle: outside its footprint.
double turnRadiusM(const std::optional<Vec3>& sizeM, double heightM) {
  if (!sizeM) return std::max(0.3, 0.6 * heightM);
  return std::max(0.3, 0.5 * std::max(sizeM->x(), sizeM->z()) + 0.15);
}

const QColor kTurnColour(80, 200, 255), kHeightColour(255, 215, 70), kSplitColour(255, 255, 255);

QColor srgbColour(const Vec3& linear) {
  auto enc = [](double v) { return int(srgbCode8(float(v))); };
  return QColor(enc(linear.x()), enc(linear.y()), enc(linear.z()));
}

// The part of segment ab inside `r` (Liang-Barsky); false when none is. A line toward a
// vanishing point far outside the widget would otherwise be dashed along its whole length on
// every paint.
bool clipToRect(QPointF& a, QPointF& b, const QRectF& r) {
  double t0 = 0, t1 = 1;
  const QPointF d = b - a;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {a.x() - r.left(), r.right() - a.x(), a.y() - r.top(), r.bottom() - a.y()};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0) t0 = std::max(t0, t);
    else t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  const QPointF a0 = a;
  a = a0 + d * t0;
  b = a0 + d * t1;
  return true;
}

// A line with a dark halo so it reads on any photo.
void haloLine(QPainter& p, QPointF a, QPointF b, const QColor& colour, double width = 1.5,
              Qt::PenStyle style = Qt::SolidLine) {
  if (!clipToRect(a, b, QRectF(p.viewport()).adjusted(-8, -8, 8, 8))) return;
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

// Distance from p to the segment ab.
double distanceToSegment(const QPointF& p, const QPointF& a, const QPointF& b) {
  const QPointF d = b - a;
  const double len2 = d.x() * d.x() + d.y() * d.y();
  const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(p - a, d) / len2, 0.0, 1.0) : 0.0;
  const QPointF q = a + d * t - p;
  return std::hypot(q.x(), q.y());
}

// Whether p is inside `poly` (closed) or within `radius` of its edges (open: of its polyline).
bool nearPolygon(const QPolygonF& poly, const QPointF& p, double radius, bool closed) {
  if (closed && poly.size() >= 3 && poly.containsPoint(p, Qt::OddEvenFill)) return true;
  for (int i = 0; i + 1 < poly.size() + (closed ? 1 : 0); ++i)
    if (distanceToSegment(p, poly[i], poly[(i + 1) % poly.size()]) <= radius) return true;
  return poly.size() == 1 && distanceToSegment(p, poly[0], poly[0]) <= radius;
}

}  // namespace

Viewport::Viewport(Document* document, RenderController* renderer, QWidget* parent)
    : QWidget(parent), document_(document), renderer_(renderer) {
  setMouseTracking(true);
  setFocusPolicy(Qt::StrongFocus);
  setAttribute(Qt::WA_OpaquePaintEvent);
  setMinimumSize(160, 120);
  setAcceptDrops(true);
  auto repaint = [this] {
    if (fit_) updateFit();
    update();
  };
  connect(document_, &Document::changed, this, [this, repaint](const ChangeEvent& e) {
    if (e.has(ChangeEvent::SceneReplaced)) fit_ = true;
    if (e.has(ChangeEvent::SceneReplaced) || e.has(ChangeEvent::ObjectsAddedOrRemoved)) {
      dragObject_ = -1;  // indices may have shifted
      dragHandle_ = Handle::None;
      hoverObject_ = -1;
    }
    if (e.has(ChangeEvent::SceneReplaced)) {
      dragCorner_ = -1;
      currentOccluder_ = -1;
      cancelToolInput();
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

int Viewport::cornerAt(const QPointF& widgetPos) const {
  const std::optional<std::array<Vec2, 4>> corners = document_->shownBackWallPx();
  if (!corners) return -1;
  int best = -1;
  double bestDist = kPickRadiusPx;
  for (int i = 0; i < 4; ++i) {
    const QPointF d = widgetFromImage((*corners)[size_t(i)]) - widgetPos;
    const double dist = std::hypot(d.x(), d.y());
    if (dist <= bestDist) {
      bestDist = dist;
      best = i;
    }
  }
  return best;
}

std::optional<MarkRef> Viewport::markAt(const QPointF& widgetPos) const {
  const SceneDoc& doc = document_->scene();
  auto polygonOf = [this](const std::vector<Vec2>& points) {
    QPolygonF poly;
    for (const Vec2& q : points) poly << widgetFromImage(q);
    return poly;
  };
  auto rectOf = [this](const std::array<double, 4>& b) {
    return QRectF(widgetFromImage(Vec2(b[0], b[1])), widgetFromImage(Vec2(b[2], b[3]))).normalized();
  };
  for (size_t i = 0; i < doc.lights.size(); ++i)
    if (doc.lights[i].kind == LightKeys::Kind::PolygonPx &&
        nearPolygon(polygonOf(doc.lights[i].pointsPx), widgetPos, kPickRadiusPx, true))
      return MarkRef{MarkKind::Light, int(i)};
  for (size_t i = 0; i < doc.shafts.size(); ++i) {
    const ShaftKeys& s = doc.shafts[i];
    if ((s.shaftBoxPx && rectOf(*s.shaftBoxPx).contains(widgetPos)) ||
        (s.sourceBoxPx && rectOf(*s.sourceBoxPx).contains(widgetPos)))
      return MarkRef{MarkKind::Shaft, int(i)};
  }
  for (size_t i = 0; i < doc.surfaces.size(); ++i)
    if (nearPolygon(polygonOf(doc.surfaces[i].outlinePx), widgetPos, kPickRadiusPx, true))
      return MarkRef{MarkKind::Surface, int(i)};
  for (size_t i = 0; i < doc.occluders.size(); ++i) {
    const OccluderKeys& o = doc.occluders[i];
    for (const auto* strokes : {&o.foregroundScribblesPx, &o.backgroundScribblesPx})
      for (const auto& stroke : *strokes)
        if (nearPolygon(polygonOf(stroke), widgetPos, kPickRadiusPx, false))
          return MarkRef{MarkKind::Occluder, int(i)};
  }
  return std::nullopt;
}

std::optional<MarkPoint> Viewport::markPointAt(const QPointF& widgetPos) const {
  const std::optional<MarkRef> selected = document_->selectedMark();
  std::optional<MarkPoint> best;
  double bestDist = kPickRadiusPx;
  bool bestSelected = false;
  for (const MarkPoint& m : document_->markPoints()) {
    const QPointF d = widgetFromImage(m.px) - widgetPos;
    const double dist = std::hypot(d.x(), d.y());
    const bool isSelected = selected && *selected == m.mark;
    if (dist > kPickRadiusPx || (bestSelected && !isSelected)) continue;
    if (dist <= bestDist || (isSelected && !bestSelected)) {
      best = m;
      bestDist = dist;
      bestSelected = isSelected;
    }
  }
  return best;
}

void Viewport::setVanishingAxis(int axis) {
  if (axis < 0 || axis > 2) return;
  vanishingAxis_ = axis;
  vanishingInput_.clear();
  Q_EMIT statusMessage(toolHint());
  update();
}

void Viewport::setLayer(Layer layer) {
  if (layer_ == layer) return;
  layer_ = layer;
  update();
}

void Viewport::setShowVanishingLines(bool show) {
  if (showVanishing_ == show) return;
  showVanishing_ = show;
  update();
}

void Viewport::setTool(Tool tool) {
  cancelToolInput();
  currentOccluder_ = -1;
  tool_ = tool;
  setCursor(tool == Tool::Select ? Qt::ArrowCursor : Qt::CrossCursor);
  Q_EMIT statusMessage(toolHint());
  update();
}

QString Viewport::toolHint() const {
  switch (tool_) {
    case Tool::Select: return tr("Drag an object or a corner of the back wall.");
    case Tool::Light:
      return tr("Click around a light; click the first point (or press Enter) to close.");
    case Tool::Shaft:
      return shaftBox_ ? tr("Now drag a box around the window the sunlight comes through.")
                       : tr("Drag a box around the patch of sunlight.");
    case Tool::Surface:
      return awaitingHeightClick_
                 ? tr("Click the floor straight below the first point of the outline.")
                 : tr("Click around the top of a table or step; click the first point to close.");
    case Tool::Occluder:
      return tr(
          "Left drag over the thing in front, right drag over what is behind it; Enter "
          "starts another occluder.");
    case Tool::VanishingLines: {
      const QString axis = QLatin1String(vanishingAxis_ == 0 ? "x" : vanishingAxis_ == 1 ? "y" : "z");
      return vanishingInput_.empty()
                 ? tr("Drag along an edge that runs in the %1 direction (keys X, Y, Z choose it).")
                       .arg(axis)
                 : tr("Now drag along a second edge in the %1 direction.").arg(axis);
    }
  }
  return {};
}

const QImage& Viewport::shownImage() {
  if (showBefore_ || layer_ == Layer::Photo) return renderer_->photoImage();
  if (layer_ == Layer::Composite) {
    if (!finalImage_.isNull()) return finalImage_;
    return renderer_->hasFrame() ? renderer_->compositeImage() : renderer_->photoImage();
  }
  layerImage_ = renderer_->layerImage(layer_);
  return layerImage_.isNull() ? renderer_->photoImage() : layerImage_;
}

void Viewport::paintEvent(QPaintEvent*) {
  QElapsedTimer clock;
  clock.start();
  QPainter p(this);
  p.fillRect(rect(), QColor(45, 45, 48));
  paintImage(p);
  p.setRenderHint(QPainter::Antialiasing);
  if (split_) paintSplit(p);
  paintRoom(p);
  if (showVanishing_) paintVanishingLines(p);
  paintMarks(p);
  paintMarkHandles(p);
  paintObjects(p);
  paintHandles(p);
  paintToolInput(p);
  if (loupeShown()) paintLoupe(p);
  paintStatus(p);
  paintTimesMs_.push_back(double(clock.nsecsElapsed()) * 1e-6);
  if (paintTimesMs_.size() > 10000) paintTimesMs_.erase(paintTimesMs_.begin());
}

void Viewport::paintImage(QPainter& p) {
  const QImage& image = shownImage();
  const QSize imgSize = imageSize();
  if (image.isNull()) return;
  const QRectF target(offset_, QSizeF(imgSize.width() * scale_, imgSize.height() * scale_));
  if (split_ && !showBefore_) {
    // Before/after: the photo left of the divider, the shown layer right of it.
    const double x = splitWidgetX();
    p.save();
    p.setClipRect(QRectF(QPointF(x, target.top()), target.bottomRight()));
    paintScaled(p, image, target);
    p.setClipRect(QRectF(target.topLeft(), QPointF(x, target.bottom())));
    paintScaled(p, renderer_->photoImage(), target);
    p.restore();
    return;
  }
  paintScaled(p, image, target);
}

void Viewport::paintScaled(QPainter& p, const QImage& image, const QRectF& target) {
  if (image.isNull()) return;
  const qreal dpr = devicePixelRatioF();
  const QSize screenSize = (target.size() * dpr).toSize();  // device pixels
  if (scale_ * dpr < 1.0 && !screenSize.isEmpty()) {
    // One cache per image (the split draws two): a miss takes the slot not used last.
    const int slot = image.cacheKey() == scaledKey_[1]   ? 1
                     : image.cacheKey() == scaledKey_[0] ? 0
                                                         : 1 - lastSlot_;
    lastSlot_ = slot;
    if (image.cacheKey() != scaledKey_[slot] || scaledImage_[slot].size() != screenSize) {
      scaledImage_[slot] = image.scaled(screenSize, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
      scaledKey_[slot] = image.cacheKey();
    }
    p.drawImage(target, scaledImage_[slot], QRectF(scaledImage_[slot].rect()));
  } else {
    p.drawImage(target, image, QRectF(image.rect()));  // magnified: nearest, pixels visible
  }
}

void Viewport::paintRoom(QPainter& p) {
  const PreparedScene* prepared = document_->prepared();
  const QColor roomColour(90, 200, 255);
  // The corners as the document has them (the user's fix or the estimate); the edges receding
  // toward the camera only once the box is prepared.
  if (const std::optional<std::array<Vec2, 4>> wall = document_->shownBackWallPx()) {
    const bool users = document_->backWallIsUsers();
    QPolygonF quad;
    for (const Vec2& c : *wall) quad << widgetFromImage(c);
    haloPolygon(p, quad, roomColour, 1.5, users ? Qt::SolidLine : Qt::DashLine);
    for (int i = 0; i < 4; ++i) {
      const bool hot = i == hoverCorner_ || i == dragCorner_;
      const double r = hot ? 6.0 : 4.5;
      p.setPen(QPen(QColor(0, 0, 0, 180), 3.0));
      p.setBrush(Qt::NoBrush);
      p.drawRect(QRectF(quad[i] - QPointF(r, r), QSizeF(2 * r, 2 * r)));
      p.setPen(QPen(roomColour, 1.5));
      p.setBrush(users ? roomColour : QColor(0, 0, 0, 120));
      p.drawRect(QRectF(quad[i] - QPointF(r, r), QSizeF(2 * r, 2 * r)));
    }
    labelAt(p, quad[0], users ? tr("Back wall (yours)") : tr("Back wall (estimated)"), roomColour);
  }
  if (!prepared) return;
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

const QRegion& Viewport::objectRegion() {
  const RenderFrame* frame = renderer_->hasFrame() ? renderer_->frameInfo().frame.get() : nullptr;
  if (frame == objectRegionFrame_) return objectRegion_;
  objectRegionFrame_ = frame;
  objectRegion_ = {};
  if (!frame || frame->mask.empty()) return objectRegion_;
  QImage bits(frame->mask.width, frame->mask.height, QImage::Format_MonoLSB);
  bits.setColorTable({qRgb(255, 255, 255), qRgb(0, 0, 0)});  // 1: black, a QBitmap's set bit
  bits.fill(0);
  for (int y = 0; y < frame->mask.height; ++y)
    for (int x = 0; x < frame->mask.width; ++x)
      if (frame->mask.at(x, y, 0) > 0.5f) bits.setPixel(x, y, 1);
  objectRegion_ = QRegion(QBitmap::fromImage(bits));
  return objectRegion_;
}

void Viewport::paintVanishingLines(QPainter& p) {
  const CameraEstimate* e = document_->lastEstimate();
  if (!e) return;
  // Not over the inserted objects: the photo's edges drawn across an object (the lockers'
  // behind a bust) made it look transparent (issue #16, York P1020839).
  p.save();
  if (layer_ == Layer::Composite && !showBefore_ && !split_ && !objectRegion().isEmpty()) {
    const QSize frameSize(renderer_->frameInfo().frame->mask.width,
                          renderer_->frameInfo().frame->mask.height);
    const QSize shown = imageSize();
    QTransform toWidget;
    toWidget.translate(offset_.x(), offset_.y());
    toWidget.scale(scale_ * shown.width() / frameSize.width(),
                   scale_ * shown.height() / frameSize.height());
    p.setTransform(toWidget);
    p.setClipRegion(QRegion(QRect(QPoint(0, 0), frameSize)).subtracted(objectRegion()));
    p.resetTransform();
  }
  const QColor* family = kAxisColour;
  // Every supporting segment in its family's colour, thin.
  std::array<std::vector<const LineSegment*>, 3> byFamily;
  for (const LineSegment& s : e->segments) {
    // The user's own lines are drawn from the scene (paintMarkHandles): an estimate that is
    // still being redone after an undo must not bring them back.
    if (s.family < 0 || s.family > 2 || s.userGiven) continue;
    byFamily[size_t(s.family)].push_back(&s);
    p.setPen(QPen(family[s.family], 1.2));
    p.drawLine(widgetFromImage(s.aPx), widgetFromImage(s.bPx));
  }
  // The two longest of each family extended toward their vanishing point: the pair that shows
  // where it is, with each one's residual.
  for (int f = 0; f < 3; ++f) {
    auto& list = byFamily[size_t(f)];
    std::partial_sort(
        list.begin(), list.begin() + std::min<size_t>(2, list.size()), list.end(),
        [](const LineSegment* a, const LineSegment* b) { return a->lengthPx() > b->lengthPx(); });
    const Vec3& h = e->vanishingPoints[size_t(f)].homogeneousPx;
    for (size_t k = 0; k < std::min<size_t>(2, list.size()); ++k) {
      const LineSegment& s = *list[k];
      const Vec2 mid = 0.5 * (s.aPx + s.bPx);
      Vec2 toward;
      if (std::abs(h.z()) > 1e-9) {
        toward = Vec2(h.x() / h.z(), h.y() / h.z());
      } else {  // at infinity: a long way along its direction
        Vec2 d(h.x(), h.y());
        if (d.norm() < 1e-12) continue;
        toward = mid + d.normalized() * 4.0 * (imageSize().width() + imageSize().height());
      }
      haloLine(p, widgetFromImage(mid), widgetFromImage(toward), family[f], 1.0, Qt::DashLine);
      labelAt(p, widgetFromImage(s.bPx), tr("%1 px").arg(s.residualPx, 0, 'f', 2), family[f]);
    }
  }
  p.restore();
}

void Viewport::paintMarkHandles(QPainter& p) {
  // The selected mark's points, each draggable on its own.
  const std::optional<MarkRef> selected = document_->selectedMark();
  if (selected)
    for (const MarkPoint& m : document_->markPoints()) {
      if (!(m.mark == *selected)) continue;
      const bool hot = dragPoint_ && dragPoint_->point == m.point;
      const QPointF c = widgetFromImage(m.px);
      p.setPen(QPen(QColor(0, 0, 0, 200), 1.0));
      p.setBrush(hot ? QColor(255, 150, 40) : QColor(255, 255, 255));
      p.drawRect(QRectF(c - QPointF(3.5, 3.5), QSizeF(7, 7)));
    }
  // The user's vanishing lines: each pair extended toward the vanishing point it fixes, with
  // the residual the re-estimated camera leaves on it.
  const CameraEstimate* e = document_->lastEstimate();
  const auto& lines = document_->scene().camera.vanishingLinesPx;
  for (int axis = 0; axis < 3; ++axis) {
    if (!lines[size_t(axis)]) continue;
    const auto& q = *lines[size_t(axis)];
    for (int k = 0; k < 2; ++k) {
      const Vec2 a = q[size_t(2 * k)], b = q[size_t(2 * k + 1)];
      haloLine(p, widgetFromImage(a), widgetFromImage(b), kAxisColour[axis], 3.0);
      if (!e) continue;
      const Vec3& h = e->vanishingPoints[size_t(axis)].homogeneousPx;
      const Vec2 mid = 0.5 * (a + b);
      const Vec2 toward = std::abs(h.z()) > 1e-9
                              ? Vec2(h.x() / h.z(), h.y() / h.z())
                              : mid + Vec2(h.x(), h.y()).normalized() * 4.0 *
                                          (imageSize().width() + imageSize().height());
      if (toward.allFinite())
        haloLine(p, widgetFromImage(mid), widgetFromImage(toward), kAxisColour[axis], 1.0, Qt::DashLine);
      for (const LineSegment& s : e->segments)
        if (s.userGiven && s.family == axis && (s.aPx - a).norm() < 1e-6 && (s.bPx - b).norm() < 1e-6)
          labelAt(p, widgetFromImage(b),
                  tr("%1: %2 px")
                      .arg(QLatin1String(axis == 0   ? "x"
                                         : axis == 1 ? "y"
                                                     : "z"))
                      .arg(s.residualPx, 0, 'f', 2),
                  kAxisColour[axis]);
    }
  }
}

void Viewport::paintMarks(QPainter& p) {
  const SceneDoc& doc = document_->scene();
  const PreparedScene* prepared = document_->prepared();
  const std::optional<MarkRef> selected = document_->selectedMark();
  // The selected mark is drawn wider.
  auto width = [&](MarkKind kind, size_t i) {
    return selected && *selected == MarkRef{kind, int(i)} ? 3.5 : 1.5;
  };
  // Lights.
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
    haloPolygon(p, poly, lightColour, width(MarkKind::Light, i),
                light.kind == LightKeys::Kind::PolygonPx ? Qt::SolidLine : Qt::DashLine);
    labelAt(p, poly.boundingRect().topRight(), tr("Light %1").arg(i + 1), lightColour);
  }
  // Shafts: the lit patch's box, the source's box, an arrow from the source to the patch.
  const QColor shaftColour(255, 170, 60);
  auto boxRect = [this](const std::array<double, 4>& b) {
    return QRectF(widgetFromImage(Vec2(b[0], b[1])), widgetFromImage(Vec2(b[2], b[3])));
  };
  for (size_t i = 0; i < doc.shafts.size(); ++i) {
    const ShaftKeys& s = doc.shafts[i];
    if (!s.shaftBoxPx || !s.sourceBoxPx) continue;
    const QRectF patch = boxRect(*s.shaftBoxPx), source = boxRect(*s.sourceBoxPx);
    haloPolygon(p, QPolygonF(patch), shaftColour, width(MarkKind::Shaft, i));
    haloPolygon(p, QPolygonF(source), shaftColour, width(MarkKind::Shaft, i), Qt::DashLine);
    haloLine(p, source.center(), patch.center(), shaftColour, 1.0, Qt::DotLine);
    labelAt(p, patch.topRight(), tr("Shaft %1").arg(i + 1), shaftColour);
  }
  // Surfaces: the top's outline and the height click below its first point.
  const QColor surfaceColour(120, 255, 200);
  for (size_t i = 0; i < doc.surfaces.size(); ++i) {
    const SurfaceKeys& s = doc.surfaces[i];
    if (s.outlinePx.empty()) continue;
    QPolygonF poly;
    for (const Vec2& q : s.outlinePx) poly << widgetFromImage(q);
    haloPolygon(p, poly, surfaceColour, width(MarkKind::Surface, i));
    const QPointF click = widgetFromImage(s.heightClickPx);
    haloLine(p, poly[0], click, surfaceColour, 1.0, Qt::DashLine);
    p.setPen(QPen(QColor(0, 0, 0, 180), 3.0));
    p.setBrush(surfaceColour);
    p.drawEllipse(click, 3.5, 3.5);
    labelAt(p, poly.boundingRect().topRight(), tr("Surface %1").arg(i + 1), surfaceColour);
  }
  // Occluders: foreground strokes green, background strokes red.
  for (size_t i = 0; i < doc.occluders.size(); ++i) {
    const double w = 1.5 + width(MarkKind::Occluder, i);
    const OccluderKeys& o = doc.occluders[i];
    for (const auto& [strokes, colour] : {std::pair{&o.foregroundScribblesPx, QColor(60, 230, 90, 220)},
                                          std::pair{&o.backgroundScribblesPx, QColor(240, 70, 70, 220)}})
      for (const auto& stroke : *strokes) {
        QPolygonF line;
        for (const Vec2& q : stroke) line << widgetFromImage(q);
        p.setPen(QPen(colour, w, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPolyline(line);
      }
  }
}

void Viewport::paintObjects(QPainter& p) {
  const SceneDoc& doc = document_->scene();
  const PreparedScene* prepared = document_->prepared();
  for (size_t i = 0; i < doc.objects.size(); ++i) {
    const ObjectKeys& o = doc.objects[i];
    const QPointF base = widgetFromImage(o.basePx);
    const bool selected = int(i) == document_->selectedObject();
    const bool hot = selected || int(i) == hoverObject_ || int(i) == dragObject_;
    // A hidden object keeps a grey marker (it can still be selected, moved and shown again).
    const QColor accent = selected   ? QColor(255, 150, 40)
                          : o.hidden ? QColor(150, 150, 150)
                                     : QColor(240, 240, 240);
    if (prepared && i < prepared->placements.size()) {
      const Placement& pl = prepared->placements[i];
      const Camera& cam = prepared->camera;
      const Vec3 top = pl.baseWorld + Vec3(0, o.heightM, 0);
      // Its front (+z of the model, glTF's convention) turned by yaw about +y.
      const Vec3 tip = pl.baseWorld +
                       frontOf(o.yawDeg) * turnRadiusM(document_->objectSizeM(int(i)), o.heightM);
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
    labelAt(p, base, o.hidden ? tr("%1 hidden").arg(i + 1) : QString::number(i + 1), accent);
  }
}

void Viewport::paintToolInput(QPainter& p) {
  const QColor colour(255, 255, 255);
  if (!toolPoints_.empty()) {
    QPolygonF line;
    for (const Vec2& q : toolPoints_) line << widgetFromImage(q);
    if (awaitingHeightClick_) {
      haloPolygon(p, line, colour, 1.5);
      haloLine(p, line[0], cursorPos_, colour, 1.0, Qt::DashLine);
    } else {
      line << cursorPos_;
      p.setBrush(Qt::NoBrush);
      p.setPen(QPen(QColor(0, 0, 0, 150), 3.5));
      p.drawPolyline(line);
      p.setPen(QPen(colour, 1.5, Qt::DashLine));
      p.drawPolyline(line);
    }
    for (const Vec2& q : toolPoints_) {
      p.setPen(QPen(QColor(0, 0, 0, 180), 3.0));
      p.setBrush(colour);
      p.drawEllipse(widgetFromImage(q), 3.0, 3.0);
    }
  }
  auto rectOf = [this](const Vec2& a, const Vec2& b) {
    return QRectF(widgetFromImage(a), widgetFromImage(b)).normalized();
  };
  if (shaftBox_)
    haloPolygon(p,
                QPolygonF(QRectF(widgetFromImage(Vec2(shaftBox_->left(), shaftBox_->top())),
                                 widgetFromImage(Vec2(shaftBox_->right(), shaftBox_->bottom())))),
                QColor(255, 170, 60), 1.5);
  if (rubberFrom_ && tool_ == Tool::VanishingLines)
    haloLine(p, widgetFromImage(*rubberFrom_), widgetFromImage(rubberTo_), kAxisColour[vanishingAxis_],
             2.0);
  else if (rubberFrom_)
    haloPolygon(p, QPolygonF(rectOf(*rubberFrom_, rubberTo_)), colour, 1.0, Qt::DashLine);
  if (vanishingInput_.size() >= 2)
    haloLine(p, widgetFromImage(vanishingInput_[0]), widgetFromImage(vanishingInput_[1]),
             kAxisColour[vanishingAxis_], 2.0);
  auto drawStrokes = [&](const std::vector<std::vector<Vec2>>& strokes, const QColor& c) {
    for (const auto& s : strokes) {
      QPolygonF line;
      for (const Vec2& q : s) line << widgetFromImage(q);
      p.setPen(QPen(c, 3.0, Qt::DashLine, Qt::RoundCap, Qt::RoundJoin));
      p.drawPolyline(line);
    }
  };
  drawStrokes(pendingOccluder_.foregroundScribblesPx, QColor(60, 230, 90));
  drawStrokes(pendingOccluder_.backgroundScribblesPx, QColor(240, 70, 70));
  if (stroking_) drawStrokes({stroke_}, strokeForeground_ ? QColor(60, 230, 90) : QColor(240, 70, 70));
}

void Viewport::paintLoupe(QPainter& p) {
  // The photo (not the composite: the corner goes where the photo's edges meet) around the
  // cursor, magnified, with the corner's crosshair.
  const QImage& photo = renderer_->photoImage();
  if (photo.isNull()) return;
  const double r = kLoupeRadiusPx;
  const double zoom = std::max(2.0, scale_ * kLoupeZoom);  // widget px per image px in the loupe
  const std::optional<std::array<Vec2, 4>> corners = document_->shownBackWallPx();
  const Vec2 centre = corners && dragCorner_ >= 0 ? (*corners)[size_t(dragCorner_)]
                                                  : imageFromWidget(cursorPos_);
  // Placed above-left of the cursor, or below-right when that leaves the widget.
  QPointF at = cursorPos_ + QPointF(-r - 30, -r - 30);
  if (at.x() - r < 0 || at.y() - r < 0) at = cursorPos_ + QPointF(r + 30, r + 30);
  const QRectF circle(at - QPointF(r, r), QSizeF(2 * r, 2 * r));
  const double half = r / zoom;  // image pixels from the centre to the loupe's edge
  const QRectF source(centre.x() - half, centre.y() - half, 2 * half, 2 * half);
  p.save();
  QPainterPath clip;
  clip.addEllipse(circle);
  p.setClipPath(clip);
  p.fillRect(circle, QColor(30, 30, 30));
  p.setRenderHint(QPainter::SmoothPixmapTransform, false);
  p.drawImage(circle, photo, source);
  p.setClipping(false);
  p.setPen(QPen(QColor(0, 0, 0, 200), 4.0));
  p.setBrush(Qt::NoBrush);
  p.drawEllipse(circle);
  p.setPen(QPen(QColor(90, 200, 255), 2.0));
  p.drawEllipse(circle);
  haloLine(p, at - QPointF(12, 0), at + QPointF(12, 0), QColor(255, 255, 255), 1.0);
  haloLine(p, at - QPointF(0, 12), at + QPointF(0, 12), QColor(255, 255, 255), 1.0);
  p.restore();
}

void Viewport::paintStatus(QPainter& p) {
  QString banner;
  QColor bannerColour(255, 255, 255);
  switch (document_->state()) {
    case Document::State::Preparing: banner = tr("Preparing the scene…"); break;
    case Document::State::Failed:
      banner = tr("The scene could not be prepared: %1").arg(engineText(document_->prepareError()));
      bannerColour = QColor(255, 140, 140);
      break;
    case Document::State::Empty:
      if (imageSize().isEmpty()) banner = tr("Open a scene or a photo (File menu).");
      break;
    case Document::State::Ready:
      if (showBefore_) banner = tr("Before: the photo without objects");
      else if (!finalImage_.isNull() && layer_ == Layer::Composite) {
        banner = finalCaption_;
        bannerColour = QColor(170, 240, 170);
      }
      break;
  }
  auto box = [&](const QRectF& area, const QString& text, const QColor& colour, int flags) {
    const QRectF r = p.fontMetrics()
                         .boundingRect(area.toRect(), flags | Qt::TextWordWrap, text)
                         .adjusted(-6, -4, 6, 4);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0, 0, 0, 170));
    p.drawRoundedRect(r, 4, 4);
    p.setPen(colour);
    p.drawText(area, flags | Qt::TextWordWrap, text);
  };
  const QRectF area = QRectF(rect()).adjusted(10, 10, -10, -10);
  if (!banner.isEmpty()) box(area, banner, bannerColour, Qt::AlignLeft | Qt::AlignTop);
  // The estimate's confidences and warnings, bottom left.
  const QStringList lines = estimateLines();
  if (lines.isEmpty()) return;
  const bool weak = document_->lastEstimate()->overallConfidence < 0.5 ||
                    !document_->lastEstimate()->manhattan;
  box(area, lines.join(QLatin1Char('\n')), weak ? QColor(255, 190, 120) : QColor(220, 235, 255),
      Qt::AlignLeft | Qt::AlignBottom);
}

QStringList Viewport::estimateLines() const {
  const CameraEstimate* e = showVanishing_ ? document_->lastEstimate() : nullptr;
  if (!e) return {};
  QStringList lines;
  lines << tr("Vanishing points: x %1, y %2, z %3 (confidence)")
               .arg(e->confidence[0], 0, 'f', 2)
               .arg(e->confidence[1], 0, 'f', 2)
               .arg(e->confidence[2], 0, 'f', 2);
  lines << tr("Focal length %1 px (%2–%3 px)")
               .arg(e->camera.focalPx, 0, 'f', 0)
               .arg(e->focalMinPx, 0, 'f', 0)
               .arg(e->focalMaxPx, 0, 'f', 0);
  QStringList warnings;
  for (const std::string& w : e->warnings) warnings << engineText(QString::fromStdString(w));
  const QRect area = rect().adjusted(10, 10, -10, -10);
  const QString whole = (lines + warnings).join(QLatin1Char('\n'));
  if (fontMetrics().boundingRect(area, Qt::TextWordWrap, whole).height() <= height() / 5)
    return lines + warnings;
  for (const QString& w : warnings) lines << fontMetrics().elidedText(w, Qt::ElideRight, area.width());
  lines << tr(
      "The whole warnings: the Log tab (View ▸ Log); this text: View ▸ Vanishing Lines and "
      "Confidence");
  return lines;
}

// ---------------------------------------------------------------- before/after split

double Viewport::splitWidgetX() const {
  return widgetFromImage(Vec2(splitFraction_ * imageSize().width(), 0)).x();
}

void Viewport::setSplitView(bool on) {
  if (split_ == on) return;
  split_ = on;
  draggingSplit_ = false;
  update();
}

void Viewport::setFinalImage(const QImage& image, const QString& caption) {
  if (image.isNull() && finalImage_.isNull()) return;
  finalImage_ = image;
  finalCaption_ = caption;
  update();
}

void Viewport::setFinalCaption(const QString& caption) {
  if (caption == finalCaption_) return;
  finalCaption_ = caption;
  update();
}

void Viewport::setSplitFraction(double fraction) {
  splitFraction_ = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 1.0) : 0.5;
  update();
}

// The divider across the photo with a grip in its middle, "Before" and "After" beside its top.
void Viewport::paintSplit(QPainter& p) {
  const QSize img = imageSize();
  if (img.isEmpty()) return;
  const double x = splitWidgetX();
  const double top = widgetFromImage(Vec2(0, 0)).y(),
               bottom = widgetFromImage(Vec2(0, img.height())).y();
  haloLine(p, QPointF(x, top), QPointF(x, bottom), kSplitColour, draggingSplit_ ? 2.5 : 1.5);
  const QPointF grip(x, 0.5 * (top + bottom));
  p.setPen(QPen(QColor(0, 0, 0, 180), 1.5));
  p.setBrush(kSplitColour);
  p.drawEllipse(grip, 9, 9);
  p.setPen(QPen(QColor(40, 40, 40), 1.5));
  p.drawLine(grip + QPointF(-4, 0), grip + QPointF(-1, -3));
  p.drawLine(grip + QPointF(-4, 0), grip + QPointF(-1, 3));
  p.drawLine(grip + QPointF(4, 0), grip + QPointF(1, -3));
  p.drawLine(grip + QPointF(4, 0), grip + QPointF(1, 3));
  const QFontMetricsF fm(p.font());
  const QString before = tr("Before"), after = tr("After");
  const double y = std::max(top, 0.0) + 8 + fm.ascent();
  labelAt(p, QPointF(x - 12 - fm.horizontalAdvance(before), y), before, kSplitColour);
  labelAt(p, QPointF(x + 12, y), after, kSplitColour);
}

// ---------------------------------------------------------------- object handles

std::optional<QPointF> Viewport::handlePos(Handle handle) const {
  const int i = document_->selectedObject();
  const PreparedScene* prepared = document_->prepared();
  if (handle == Handle::None || i < 0 || i >= document_->objectCount() || !prepared ||
      size_t(i) >= prepared->placements.size())
    return std::nullopt;
  const ObjectKeys& o = document_->scene().objects[size_t(i)];
  const Vec3 base = prepared->placements[size_t(i)].baseWorld;
  const Vec3 at =
      handle == Handle::Height
          ? Vec3(base + Vec3(0, o.heightM, 0))
          : Vec3(base + frontOf(o.yawDeg) * turnRadiusM(document_->objectSizeM(i), o.heightM));
  const Camera& cam = prepared->camera;
  if (cam.depthOf(at) <= 0.05) return std::nullopt;
  const std::optional<Vec2> px = cam.project(at);
  if (!px) return std::nullopt;
  return widgetFromImage(*px);
}

Viewport::Handle Viewport::handleAt(const QPointF& widgetPos) const {
  for (Handle h : {Handle::Height, Handle::Turn})
    if (const std::optional<QPointF> at = handlePos(h)) {
      const QPointF d = *at - widgetPos;
      if (std::hypot(d.x(), d.y()) <= kPickRadiusPx) return h;
    }
  return Handle::None;
}

// The selected object's turn disc (with the circle it moves on, while turning) and height square.
void Viewport::paintHandles(QPainter& p) {
  const int i = document_->selectedObject();
  const PreparedScene* prepared = document_->prepared();
  if (i < 0 || i >= document_->objectCount() || !prepared || size_t(i) >= prepared->placements.size())
    return;
  if (dragHandle_ == Handle::Turn) {
    // The circle on the object's support the disc travels along.
    const ObjectKeys& o = document_->scene().objects[size_t(i)];
    const Vec3 base = prepared->placements[size_t(i)].baseWorld;
    const double r = turnRadiusM(document_->objectSizeM(i), o.heightM);
    QPolygonF ring;
    for (int k = 0; k <= 72; ++k) {
      const Vec3 q = base + frontOf(k * 5.0) * r;
      if (prepared->camera.depthOf(q) <= 0.05) continue;
      if (const auto px = prepared->camera.project(q)) ring << widgetFromImage(*px);
    }
    haloPolygon(p, ring, kTurnColour, 1.2, Qt::DashLine);
  }
  for (Handle h : {Handle::Turn, Handle::Height}) {
    const std::optional<QPointF> at = handlePos(h);
    if (!at) continue;
    const bool hot = h == hoverHandle_ || h == dragHandle_;
    const double r = hot ? 7.5 : 6.0;
    p.setPen(QPen(QColor(0, 0, 0, 200), 3.0));
    p.setBrush(Qt::NoBrush);
    const QRectF box(*at - QPointF(r, r), QSizeF(2 * r, 2 * r));
    h == Handle::Turn ? p.drawEllipse(box) : p.drawRect(box);
    p.setPen(QPen(QColor(20, 20, 20), 1.2));
    p.setBrush(h == Handle::Turn ? kTurnColour : kHeightColour);
    h == Handle::Turn ? p.drawEllipse(box) : p.drawRect(box);
  }
}

void Viewport::dragObjectTo(const Vec2& px, Qt::KeyboardModifiers modifiers) {
  QString reason;
  const Vec2 target = px + dragGrabPx_;
  // Near a wall: its back against it (Shift places freely); elsewhere its own turn.
  const std::optional<Document::WallSnap> snap =
      (modifiers & Qt::ShiftModifier) ? std::nullopt : document_->wallSnap(dragObject_, target);
  const bool ok =
      snap ? document_->moveAndTurnObject(dragObject_, snap->basePx, snap->yawDeg, dragId_, &reason)
           : document_->moveAndTurnObject(dragObject_, target, dragStartYawDeg_, dragId_, &reason);
  if (!ok) {
    Q_EMIT statusMessage(tr("Cannot place the object here: %1").arg(reason));
    return;
  }
  if (!snap) {
    Q_EMIT statusMessage(QString());
    return;
  }
  const QString wall = snap->wall == SurfaceKind::WallLeft    ? tr("the left wall")
                       : snap->wall == SurfaceKind::WallRight ? tr("the right wall")
                       : snap->wall == SurfaceKind::WallBack  ? tr("the back wall")
                                                              : tr("the wall behind the camera");
  Q_EMIT statusMessage(tr("Its back against %1 (hold Shift to place it freely).").arg(wall));
}

void Viewport::dragHandleTo(const Vec2& px, Qt::KeyboardModifiers modifiers) {
  const PreparedScene* prepared = document_->prepared();
  const int i = dragObject_;
  if (!prepared || i < 0 || i >= document_->objectCount() || size_t(i) >= prepared->placements.size())
    return;
  const Vec3 base = prepared->placements[size_t(i)].baseWorld;
  const Ray ray = prepared->camera.rayThroughPixel(px);
  QString reason;
  bool ok = true;
  if (dragHandle_ == Handle::Turn) {
    // Where the cursor's ray meets the plane the object stands on: its front points there.
    if (std::abs(ray.direction.y()) < 1e-9) return;
    const double t = (base.y() - ray.origin.y()) / ray.direction.y();
    if (!(t > 0)) return;  // above the horizon: the turn stays
    const Vec3 v = ray.at(t) - base;
    double yaw = std::atan2(v.x(), v.z()) * 180.0 / std::numbers::pi;
    if (modifiers & Qt::ShiftModifier) yaw = 15.0 * std::round(yaw / 15.0);
    ok = document_->setObjectYaw(i, yaw, &reason, dragId_);
    if (ok) Q_EMIT statusMessage(tr("Turned %1°").arg(yaw, 0, 'f', 1));
  } else {
    // The point of the object's vertical axis nearest to the cursor's ray sets its height.
    const Vec3 up(0, 1, 0), w0 = base - ray.origin;
    const double b = up.dot(ray.direction), denom = 1.0 - b * b;
    if (denom < 1e-9) return;
    const double s = (b * ray.direction.dot(w0) - up.dot(w0)) / denom;
    const double ceiling = prepared->box.ceilingM;
    const double height = std::clamp(s - dragHeightOffsetM_, 0.02, std::max(0.05, ceiling - base.y()));
    ok = document_->setObjectHeight(i, height, &reason, dragId_);
    if (ok) Q_EMIT statusMessage(tr("Height %1 m").arg(height, 0, 'f', 2));
  }
  if (!ok) Q_EMIT statusMessage(reason);
}

// ---------------------------------------------------------------- input

void Viewport::report(bool ok, const QString& reason) { Q_EMIT statusMessage(ok ? toolHint() : reason); }

void Viewport::cancelToolInput() {
  toolPoints_.clear();
  awaitingHeightClick_ = false;
  shaftBox_.reset();
  rubberFrom_.reset();
  stroke_.clear();
  stroking_ = false;
  pendingOccluder_ = {};
  vanishingInput_.clear();
  update();
}

void Viewport::commitToolInput() {
  if ((tool_ == Tool::Light || tool_ == Tool::Surface) && !awaitingHeightClick_) closeOutline();
  else if (tool_ == Tool::Occluder) {
    currentOccluder_ = -1;
    pendingOccluder_ = {};
    Q_EMIT statusMessage(toolHint());
  }
  update();
}

void Viewport::closeOutline() {
  if (toolPoints_.size() < 3) {
    Q_EMIT statusMessage(tr("An outline needs at least three points."));
    return;
  }
  if (tool_ == Tool::Light) {
    QString reason;
    const bool ok = document_->addLight(toolPoints_, &reason);
    toolPoints_.clear();
    report(ok, reason);
  } else {
    awaitingHeightClick_ = true;
    Q_EMIT statusMessage(toolHint());
  }
  update();
}

void Viewport::addOutlinePoint(const QPointF& widgetPos) {
  const Vec2 px = imageFromWidget(widgetPos);
  if (awaitingHeightClick_) {
    QString reason;
    const bool ok = document_->addExtrusion(toolPoints_, px, &reason);
    toolPoints_.clear();
    awaitingHeightClick_ = false;
    report(ok, reason);
    update();
    return;
  }
  if (toolPoints_.size() >= 3) {
    const QPointF d = widgetFromImage(toolPoints_.front()) - widgetPos;
    if (std::hypot(d.x(), d.y()) <= kPickRadiusPx) return closeOutline();
  }
  toolPoints_.push_back(px);
  update();
}

void Viewport::finishStroke() {
  stroking_ = false;
  if (stroke_.empty()) return;
  std::vector<Vec2> stroke = std::move(stroke_);
  stroke_.clear();
  QString reason;
  bool ok = true;
  if (currentOccluder_ >= 0 && currentOccluder_ < int(document_->scene().occluders.size())) {
    ok = document_->addOccluderStroke(currentOccluder_, strokeForeground_, stroke, &reason);
  } else {
    (strokeForeground_ ? pendingOccluder_.foregroundScribblesPx : pendingOccluder_.backgroundScribblesPx)
        .push_back(std::move(stroke));
    if (!pendingOccluder_.foregroundScribblesPx.empty() &&
        !pendingOccluder_.backgroundScribblesPx.empty()) {
      ok = document_->addOccluder(pendingOccluder_, &reason);
      if (ok) currentOccluder_ = int(document_->scene().occluders.size()) - 1;
      pendingOccluder_ = {};
    }
  }
  report(ok, reason);
  update();
}

void Viewport::pressSelect(QMouseEvent* event) {
  if (const Handle h = handleAt(event->position()); h != Handle::None) {
    dragObject_ = document_->selectedObject();
    dragHandle_ = h;
    dragId_ = Document::newDragId();
    const ObjectKeys& o = document_->scene().objects[size_t(dragObject_)];
    dragHeightOffsetM_ = 0;
    if (h == Handle::Height) {
      // Grabbed off the square's centre: the height follows the cursor without a jump.
      const PreparedScene* prepared = document_->prepared();
      const Vec3 base = prepared->placements[size_t(dragObject_)].baseWorld;
      const Ray ray = prepared->camera.rayThroughPixel(imageFromWidget(event->position()));
      const Vec3 w0 = base - ray.origin;
      const double b = ray.direction.y(), denom = 1.0 - b * b;
      if (denom > 1e-9) dragHeightOffsetM_ = (b * ray.direction.dot(w0) - w0.y()) / denom - o.heightM;
    }
    setCursor(h == Handle::Turn ? Qt::SizeHorCursor : Qt::SizeVerCursor);
    return;
  }
  const int hit = objectAt(event->position());
  document_->setSelectedObject(hit);
  if (hit >= 0) {
    dragObject_ = hit;
    dragStartYawDeg_ = document_->scene().objects[size_t(hit)].yawDeg;
    dragId_ = Document::newDragId();
    dragGrabPx_ = document_->scene().objects[size_t(hit)].basePx - imageFromWidget(event->position());
    setCursor(Qt::SizeAllCursor);
    return;
  }
  const int corner = cornerAt(event->position());
  if (corner >= 0) {
    dragCorner_ = corner;
    dragId_ = Document::newDragId();
    dragGrabPx_ = (*document_->shownBackWallPx())[size_t(corner)] - imageFromWidget(event->position());
    setCursor(Qt::BlankCursor);  // the loupe's crosshair shows the point
    return;
  }
  if (const std::optional<MarkPoint> point = markPointAt(event->position())) {
    document_->setSelectedMark(point->mark);
    dragPoint_ = point;
    dragId_ = Document::newDragId();
    dragGrabPx_ = point->px - imageFromWidget(event->position());
    setCursor(Qt::CrossCursor);
    return;
  }
  document_->setSelectedMark(markAt(event->position()));
}

void Viewport::mousePressEvent(QMouseEvent* event) {
  cursorPos_ = event->position();
  if (event->button() == Qt::MiddleButton) {
    panning_ = true;
    lastPanPos_ = event->position();
    setCursor(Qt::ClosedHandCursor);
    return;
  }
  if (split_ && event->button() == Qt::LeftButton && handleAt(event->position()) == Handle::None &&
      std::abs(event->position().x() - splitWidgetX()) <= kPickRadiusPx) {
    draggingSplit_ = true;
    setCursor(Qt::SplitHCursor);
    update();
    return;
  }
  switch (tool_) {
    case Tool::Select:
      if (event->button() == Qt::LeftButton) pressSelect(event);
      break;
    case Tool::Light:
    case Tool::Surface:
      if (event->button() == Qt::LeftButton) addOutlinePoint(event->position());
      break;
    case Tool::Shaft:
    case Tool::VanishingLines:
      if (event->button() == Qt::LeftButton) {
        rubberFrom_ = imageFromWidget(event->position());
        rubberTo_ = *rubberFrom_;
      }
      break;
    case Tool::Occluder:
      if (event->button() == Qt::LeftButton || event->button() == Qt::RightButton) {
        stroking_ = true;
        strokeForeground_ = event->button() == Qt::LeftButton;
        stroke_ = {imageFromWidget(event->position())};
      }
      break;
  }
  update();
}

void Viewport::mouseMoveEvent(QMouseEvent* event) {
  cursorPos_ = event->position();
  if (panning_) {
    offset_ += event->position() - lastPanPos_;
    lastPanPos_ = event->position();
    fit_ = false;
    update();
    return;
  }
  const Vec2 px = imageFromWidget(event->position());
  if (draggingSplit_) {
    const QSize img = imageSize();
    if (!img.isEmpty()) setSplitFraction(px.x() / img.width());
    return;
  }
  if (dragObject_ >= 0) {
    if (dragObject_ >= document_->objectCount()) {
      dragObject_ = -1;
      dragHandle_ = Handle::None;
      return;
    }
    if (dragHandle_ != Handle::None) dragHandleTo(px, event->modifiers());
    else dragObjectTo(px, event->modifiers());
    update();
    return;
  }
  if (dragPoint_) {
    QString reason;
    if (document_->moveMarkPoint(dragPoint_->mark, dragPoint_->point, px + dragGrabPx_, dragId_,
                                 &reason))
      Q_EMIT statusMessage(QString());
    else Q_EMIT statusMessage(reason);
    update();
    return;
  }
  if (dragCorner_ >= 0) {
    QString reason;
    if (!document_->setBackWallCorner(dragCorner_, px + dragGrabPx_, dragId_, &reason))
      Q_EMIT statusMessage(reason);
    update();  // the loupe follows even when the corner did not move
    return;
  }
  if (rubberFrom_) rubberTo_ = px;
  if (stroking_ && (stroke_.empty() || (stroke_.back() - px).norm() >= 1.0)) stroke_.push_back(px);
  if (tool_ == Tool::Select) {
    const Handle handle = handleAt(event->position());
    const int hover = handle != Handle::None ? -1 : objectAt(event->position());
    const int corner = hover >= 0 || handle != Handle::None ? -1 : cornerAt(event->position());
    if (hover != hoverObject_ || corner != hoverCorner_ || handle != hoverHandle_) {
      hoverObject_ = hover;
      hoverCorner_ = corner;
      hoverHandle_ = handle;
      setCursor(handle == Handle::Turn      ? Qt::SizeHorCursor
                : handle == Handle::Height  ? Qt::SizeVerCursor
                : hover >= 0 || corner >= 0 ? Qt::OpenHandCursor
                                            : Qt::ArrowCursor);
    }
  }
  update();  // the tool's rubber band follows the cursor
}

void Viewport::mouseReleaseEvent(QMouseEvent* event) {
  cursorPos_ = event->position();
  if (event->button() == Qt::MiddleButton && panning_) {
    panning_ = false;
    unsetCursor();
    return;
  }
  if (event->button() == Qt::LeftButton && draggingSplit_) {
    draggingSplit_ = false;
    unsetCursor();
    update();
    return;
  }
  if (event->button() == Qt::LeftButton && (dragObject_ >= 0 || dragCorner_ >= 0 || dragPoint_)) {
    dragPoint_.reset();
    dragObject_ = -1;
    dragHandle_ = Handle::None;
    dragCorner_ = -1;
    const bool over = objectAt(event->position()) >= 0 || cornerAt(event->position()) >= 0;
    setCursor(over ? Qt::OpenHandCursor : Qt::ArrowCursor);
  }
  if (tool_ == Tool::Shaft && rubberFrom_ && event->button() == Qt::LeftButton) {
    const Vec2 a = *rubberFrom_, b = imageFromWidget(event->position());
    rubberFrom_.reset();
    const QRectF box = QRectF(QPointF(a.x(), a.y()), QPointF(b.x(), b.y())).normalized();
    if (!shaftBox_) {
      shaftBox_ = box;
      Q_EMIT statusMessage(toolHint());
    } else {
      QString reason;
      const bool ok = document_->addShaft(
          {shaftBox_->left(), shaftBox_->top(), shaftBox_->right(), shaftBox_->bottom()},
          {box.left(), box.top(), box.right(), box.bottom()}, &reason);
      shaftBox_.reset();
      report(ok, reason);
    }
  }
  if (tool_ == Tool::VanishingLines && rubberFrom_ && event->button() == Qt::LeftButton) {
    vanishingInput_.push_back(*rubberFrom_);
    vanishingInput_.push_back(imageFromWidget(event->position()));
    rubberFrom_.reset();
    if (vanishingInput_.size() == 4) {
      QString reason;
      const std::array<Vec2, 4> lines{vanishingInput_[0], vanishingInput_[1], vanishingInput_[2],
                                      vanishingInput_[3]};
      vanishingInput_.clear();
      report(document_->setVanishingLines(vanishingAxis_, lines, &reason), reason);
    } else if ((vanishingInput_[1] - vanishingInput_[0]).norm() < 2) {
      vanishingInput_.clear();
      Q_EMIT statusMessage(tr("Each line must be at least two pixels long."));
    } else {
      Q_EMIT statusMessage(toolHint());
    }
  }
  if (tool_ == Tool::Occluder && stroking_) {
    stroke_.push_back(imageFromWidget(event->position()));
    finishStroke();
  }
  update();
}

void Viewport::mouseDoubleClickEvent(QMouseEvent* event) {
  // Qt sends press, release, double click, release: the first press added the point; the
  // double click closes the outline there.
  if ((tool_ == Tool::Light || tool_ == Tool::Surface) && !awaitingHeightClick_ &&
      event->button() == Qt::LeftButton) {
    closeOutline();
    return;
  }
  mousePressEvent(event);
}

void Viewport::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) update();  // every label is drawn with tr()
  QWidget::changeEvent(event);
}

void Viewport::keyPressEvent(QKeyEvent* event) {
  switch (event->key()) {
    case Qt::Key_Escape: cancelToolInput(); return;
    case Qt::Key_X:
    case Qt::Key_Y:
    case Qt::Key_Z:
      if (tool_ == Tool::VanishingLines) {
        setVanishingAxis(event->key() - Qt::Key_X);
        return;
      }
      break;
    case Qt::Key_Return:
    case Qt::Key_Enter: commitToolInput(); return;
    case Qt::Key_Backspace:
      if (!toolPoints_.empty() && !awaitingHeightClick_) {
        toolPoints_.pop_back();
        update();
        return;
      }
      break;
    default: break;
  }
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
  else Q_EMIT statusMessage(tr("Cannot place the object here: %1").arg(reason));
  event->accept();
}

void Viewport::wheelEvent(QWheelEvent* event) {
  const double steps = event->angleDelta().y() / 120.0;
  if (steps == 0) return;
  zoomAbout(std::pow(1.15, steps), event->position());
  event->accept();
}

// --- Dropping model files ---
namespace {

// The first local model file among the drag's URLs (text/uri-list), or "".
QString droppedModel(const QMimeData* data) {
  if (!data || !data->hasUrls()) return {};
  for (const QUrl& url : data->urls())
    if (url.isLocalFile() && isModelFile(url.toLocalFile())) return url.toLocalFile();
  return {};
}

}  // namespace

void Viewport::dragEnterEvent(QDragEnterEvent* event) {
  if (droppedModel(event->mimeData()).isEmpty()) return event->ignore();  // the window's (a photo)
  event->acceptProposedAction();
}

void Viewport::dragMoveEvent(QDragMoveEvent* event) {
  if (droppedModel(event->mimeData()).isEmpty()) return event->ignore();
  event->acceptProposedAction();
}

void Viewport::dropEvent(QDropEvent* event) {
  const QString path = droppedModel(event->mimeData());
  if (path.isEmpty()) return event->ignore();
  event->acceptProposedAction();
  const Vec2 px = imageFromWidget(event->position());
  // After the drop has returned to the source (a file manager, the library dock): reading the
  // file and a refusal's dialog must not run inside the drag's event loop.
  QMetaObject::invokeMethod(
      this, [this, path, px] { Q_EMIT modelDropped(path, QPointF(px.x(), px.y())); },
      Qt::QueuedConnection);
}

}  // namespace inlay::studio
