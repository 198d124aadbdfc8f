#include "wrapped_labels.h"

#include <QEvent>
#include <QLabel>
#include <QWidget>

namespace inlay::studio {

WrappedLabelFitter::WrappedLabelFitter(QWidget* container, const QList<QLabel*>& labels)
    : QObject(container), container_(container) {
  for (QLabel* l : labels) {
    labels_ << l;
    // Its width is the layout's to give (a long note must not widen the dock and squeeze the
    // viewport); only its height follows its text.
    l->setSizePolicy(QSizePolicy::Ignored, l->sizePolicy().verticalPolicy());
  }
  container_->installEventFilter(this);
}

int WrappedLabelFitter::neededHeight(const QLabel* label) {
  const QMargins m = label->contentsMargins();
  const int width = label->width() - m.left() - m.right() - 2 * label->margin();
  if (width <= 0) return label->minimumHeight();
  const QRect text = label->fontMetrics().boundingRect(
      QRect(0, 0, width, 1 << 20), Qt::TextWordWrap | Qt::AlignLeft | Qt::AlignTop, label->text());
  return text.height() + m.top() + m.bottom() + 2 * label->margin();
}

void WrappedLabelFitter::fit() {
  queued_ = false;
  for (QLabel* l : std::as_const(labels_)) {
    if (!l || l->width() <= 0) continue;
    const int h = neededHeight(l);
    if (h != l->minimumHeight()) l->setMinimumHeight(h);
  }
}

bool WrappedLabelFitter::eventFilter(QObject* watched, QEvent* event) {
  if (watched == container_ && !queued_ &&
      (event->type() == QEvent::Resize || event->type() == QEvent::LayoutRequest)) {
    // After the event: the layout has given the labels their new widths by then.
    queued_ = true;
    QMetaObject::invokeMethod(
        this, [this] { fit(); }, Qt::QueuedConnection);
  }
  return QObject::eventFilter(watched, event);
}

}  // namespace inlay::studio
