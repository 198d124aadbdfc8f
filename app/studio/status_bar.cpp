#include "status_bar.h"

#include <QEvent>
#include <QFontMetrics>
#include <QHelpEvent>
#include <QLabel>
#include <QPainter>
#include <QStyle>
#include <QStyleOption>
#include <QTextLayout>
#include <QToolTip>

#include <algorithm>

namespace inlay::studio {

// ---------------------------------------------------------------- StatusMessage

StatusMessage::StatusMessage(QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("statusMessage"));
  // As wide as the bar leaves it; kMaxLines high.
  setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
}

void StatusMessage::setText(const QString& text) {
  if (text == text_) return;
  text_ = text;
  relayout();
}

QString StatusMessage::toolTipText() const {
  if (!elided_) return {};
  const QString bar = parentWidget() ? parentWidget()->toolTip() : QString();
  return bar.isEmpty() ? text_ : text_ + QStringLiteral("\n\n") + bar;
}

// Always room for kMaxLines: the bar keeps its height whatever it shows.
int StatusMessage::linesHeight() const { return kMaxLines * fontMetrics().lineSpacing(); }

QSize StatusMessage::sizeHint() const { return {fontMetrics().averageCharWidth() * 40, linesHeight()}; }

QSize StatusMessage::minimumSizeHint() const {
  return {fontMetrics().averageCharWidth() * 8, linesHeight()};
}

// Word-wraps the text at the current width into at most kMaxLines lines; what does not fit
// ends the last line as "…".
void StatusMessage::relayout() {
  lines_.clear();
  elided_ = false;
  QString text = text_;
  text.replace(QLatin1Char('\n'), QLatin1Char(' '));
  const int width = contentsRect().width();
  if (!text.isEmpty() && width <= 0) lines_ << text;
  if (!text.isEmpty() && width > 0) {
    QTextLayout layout(text, font());
    QTextOption option;
    option.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    layout.setTextOption(option);
    layout.beginLayout();
    for (QTextLine line = layout.createLine(); line.isValid(); line = layout.createLine()) {
      line.setLineWidth(width);
      if (lines_.size() + 1 == kMaxLines) {  // the last line takes the rest, elided if need be
        const QString rest = text.mid(line.textStart()).trimmed();
        const QString shown = fontMetrics().elidedText(rest, Qt::ElideRight, width);
        elided_ = shown != rest;
        lines_ << shown;
        break;
      }
      lines_ << text.mid(line.textStart(), line.textLength()).trimmed();
    }
    layout.endLayout();
  }
  update();
}

bool StatusMessage::event(QEvent* event) {
  if (event->type() == QEvent::ToolTip) {
    const QString tip = toolTipText();
    if (tip.isEmpty()) {
      event->ignore();  // the bar's own tooltip, if any
      return false;
    }
    QToolTip::showText(static_cast<QHelpEvent*>(event)->globalPos(), tip, this);
    return true;
  }
  if (event->type() == QEvent::FontChange) relayout();
  return QWidget::event(event);
}

void StatusMessage::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.setPen(palette().color(QPalette::WindowText));
  const QRect r = contentsRect();
  const int lineHeight = fontMetrics().lineSpacing();
  int y = r.top() + (r.height() - int(lines_.size()) * lineHeight) / 2;
  for (const QString& line : lines_) {
    p.drawText(QRect(r.left(), y, r.width(), lineHeight),
               Qt::AlignLeading | Qt::AlignVCenter | Qt::TextSingleLine, line);
    y += lineHeight;
  }
}

void StatusMessage::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  relayout();
}

// ---------------------------------------------------------------- StatusBar

StatusBar::StatusBar(QWidget* parent) : QStatusBar(parent), message_(new StatusMessage(this)) {
  // The message is a permanent widget that takes the bar's free width; QStatusBar's own drawing
  // of it is left out (paintEvent).
  addPermanentWidget(message_, 1);
  connect(this, &QStatusBar::messageChanged, message_, &StatusMessage::setText);
}

void StatusBar::addField(QLabel* field, int priority) {
  fields_.push_back({field, priority});
  addPermanentWidget(field);
  fitFields();
}

void StatusBar::setFieldSamples(QLabel* field, const QStringList& samples) {
  int widest = 0;
  for (const QString& s : samples) widest = std::max(widest, field->fontMetrics().horizontalAdvance(s));
  const QMargins m = field->contentsMargins();
  field->setMinimumWidth(widest + m.left() + m.right() + 2 * field->margin() + 2);
  fitFields();
}

// The bar's panel and the fields' frames, as QStatusBar draws them, but not the message: the
// StatusMessage draws it.
void StatusBar::paintEvent(QPaintEvent*) {
  QPainter p(this);
  QStyleOption panel;
  panel.initFrom(this);
  style()->drawPrimitive(QStyle::PE_PanelStatusBar, &panel, &p, this);
  for (const Field& f : fields_) {
    if (f.label->isHidden()) continue;
    QStyleOption frame(0);
    frame.rect = f.label->geometry().adjusted(-2, -1, 2, 1);
    frame.palette = palette();
    frame.state = QStyle::State_None;
    style()->drawPrimitive(QStyle::PE_FrameStatusBarItem, &frame, &p, f.label);
  }
}

void StatusBar::resizeEvent(QResizeEvent* event) {
  QStatusBar::resizeEvent(event);
  fitFields();
}

// Shows every field that leaves the message kMinMessageWidth; the others (lowest priority
// first) are hidden until the bar is wide enough again.
void StatusBar::fitFields() {
  if (fitting_) return;
  fitting_ = true;
  std::vector<Field> byPriority;
  for (const Field& f : fields_)
    if (f.priority > 0) byPriority.push_back(f);
  std::stable_sort(byPriority.begin(), byPriority.end(),
                   [](const Field& a, const Field& b) { return a.priority < b.priority; });
  const int spacing = 6 + 4;  // the layout's spacing and the frame around each field
  auto fieldsWidth = [&] {
    int w = 0;
    for (const Field& f : fields_)
      if (!f.label->isHidden())
        w += std::max(f.label->sizeHint().width(), f.label->minimumWidth()) + spacing;
    return w;
  };
  const int grip = isSizeGripEnabled() ? 20 : 0;
  const int free = width() - grip - 12;
  for (const Field& f : byPriority) f.label->setHidden(false);
  for (const Field& f : byPriority) {
    if (free - fieldsWidth() >= kMinMessageWidth) break;
    f.label->setHidden(true);
  }
  fitting_ = false;
}

}  // namespace inlay::studio
