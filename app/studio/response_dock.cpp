#include "response_dock.h"

#include "engine_text.h"
#include "wrapped_labels.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QEvent>
#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QScrollArea>
#include <QSettings>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <array>
#include <cmath>

namespace inlay::studio {

ResponsePlot responsePlot(const CameraResponse& response) {
  ResponsePlot plot;
  const auto stopsOf = [](const CameraResponse& r) {
    std::array<double, 256> out{};
    const double mid = r.table8()[size_t(kResponsePlotMidCode)];
    for (size_t k = 0; k < out.size(); ++k) {
      const double ratio = r.table8()[k] / mid;
      // Code 0 (and a curve that is not finite) sits on the plot's floor.
      out[k] = std::isfinite(ratio) && ratio > 0 ? std::log2(ratio) : -kResponsePlotMaxStops;
    }
    return out;
  };
  plot.curve = stopsOf(response);
  plot.srgb = stopsOf(CameraResponse::srgb());
  double top = 0, bottom = 0;
  for (const auto* c : {&plot.curve, &plot.srgb}) {  // code 0 (no light) left out
    top = std::max(top, *std::max_element(c->begin() + 1, c->end()));
    bottom = std::min(bottom, *std::min_element(c->begin() + 1, c->end()));
  }
  plot.top = std::ceil(std::clamp(top, 1.0, kResponsePlotMaxStops));
  plot.bottom = std::floor(std::clamp(bottom, -kResponsePlotMaxStops, -1.0));
  for (auto* c : {&plot.curve, &plot.srgb}) {
    for (double& v : *c) v = std::clamp(v, plot.bottom, plot.top);
    (*c)[0] = plot.bottom;
  }
  return plot;
}

// The decode curve in stops above the code of mid-grey (code across, stops up) over the sRGB
// curve for reference: a linear axis would show a long shoulder as a line along zero.
class ResponseCurveView : public QWidget {
  // Its own translation context (without it tr() was QWidget's, and the caption stayed English
  // in German and French although the .ts files translate it).
  Q_DECLARE_TR_FUNCTIONS(inlay::studio::ResponseCurveView)

 public:
  explicit ResponseCurveView(QWidget* parent) : QWidget(parent) {
    setMinimumSize(160, 90);
    setObjectName(QStringLiteral("responseCurve"));
  }
  static QString caption() { return tr("code (up: stops above mid-grey)"); }
  void setResponse(const CameraResponse& r) {
    plot_ = responsePlot(r);
    update();
  }

 protected:
  void paintEvent(QPaintEvent*) override {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), palette().base());
    // The caption wraps below the plot when the dock is narrower than it (French is long).
    const int captionWidth = width() - 34 - 8;
    const int captionHeight =
        fontMetrics()
            .boundingRect(QRect(0, 0, captionWidth, 1 << 16), Qt::TextWordWrap, caption())
            .height();
    const QRectF area = QRectF(rect()).adjusted(34, 8, -8, -(captionHeight + 4));
    const auto y = [&](double stops) {
      return area.bottom() - area.height() * (stops - plot_.bottom) / (plot_.top - plot_.bottom);
    };
    p.setPen(palette().mid().color());
    p.drawRect(area);
    p.drawLine(QPointF(area.left(), y(0)), QPointF(area.right(), y(0)));
    p.setPen(palette().text().color());
    p.drawText(QRectF(area.left(), area.bottom() + 2, area.width(), captionHeight),
               Qt::AlignHCenter | Qt::AlignTop | Qt::TextWordWrap, caption());
    for (double stops : {plot_.top, 0.0, plot_.bottom})
      p.drawText(QRectF(0, y(stops) - 8, 32, 16), Qt::AlignRight | Qt::AlignVCenter,
                 stops > 0 ? QStringLiteral("+%1").arg(stops) : QString::number(stops));
    const auto path = [&](const std::array<double, 256>& stops) {
      QPainterPath out;
      for (size_t k = 0; k < stops.size(); ++k) {
        const QPointF q(area.left() + area.width() * double(k) / 255.0, y(stops[k]));
        k == 0 ? out.moveTo(q) : out.lineTo(q);
      }
      return out;
    };
    p.setPen(QPen(palette().mid().color(), 1, Qt::DashLine));
    p.drawPath(path(plot_.srgb));
    p.setPen(QPen(palette().highlight().color(), 2));
    p.drawPath(path(plot_.curve));
  }

 private:
  ResponsePlot plot_ = responsePlot(CameraResponse::srgb());
};

namespace {

// Whether "Details" was open when the studio last closed (it opens so again).
constexpr const char* kDetailsOpenKey = "responseDock/detailsOpen";

// What the dock's note says was decided, in one plain sentence (the dock's language).
QString decisionOf(ResponseKeys::Mode mode, const PreparedScene& prepared) {
  using Mode = ResponseKeys::Mode;
  const auto& e = prepared.responseEstimate;
  // An EXR/HDR photo is linear whatever the list says (the engine warns about a choice).
  if (!prepared.photo.wasSrgbEncoded || (mode == Mode::Auto && !e))
    return ResponseDock::tr("The photo already holds light values (EXR/HDR): it needs no curve.");
  if (mode == Mode::Srgb)
    return ResponseDock::tr("Uses the standard sRGB curve, as chosen in the list.");
  if (mode == Mode::Linear)
    return ResponseDock::tr(
        "Uses a straight (linear) curve, as chosen in the list: the photo's values "
        "are read as light directly.");
  if (mode != Mode::Auto) return ResponseDock::tr("Uses the curve given in the scene file.");
  const bool noise = e->noiseBins > 0;
  if (!e->determined)
    return ResponseDock::tr(
        "Kept the standard sRGB curve: the photo does not show enough to estimate "
        "its own tone curve.");
  // The pipeline's check (PrepareOptions::checkResponseByLightFit) took the fitted curve away.
  if (curveRefusedByTheLightFit(*e))
    return ResponseDock::tr(
        "Kept the standard sRGB curve: the room's lighting explains the photo better with it "
        "than with the curve estimated from the photo.");
  if (e->decision != "fitted")
    return noise ? ResponseDock::tr(
                       "Kept the standard sRGB curve: the photo's noise does not show a "
                       "different tone curve clearly.")
                 : ResponseDock::tr(
                       "Kept the standard sRGB curve: the photo's edges do not show a "
                       "different tone curve clearly.");
  return noise ? ResponseDock::tr(
                     "Uses the tone curve estimated from the photo's noise; it differs "
                     "from the standard sRGB curve (dashed).")
               : ResponseDock::tr(
                     "Uses the tone curve estimated from the photo's edges; it differs "
                     "from the standard sRGB curve (dashed).");
}

// What the user can do about it, or empty when the curve is the user's own choice.
QString adviceOf(ResponseKeys::Mode mode, const PreparedScene& prepared) {
  const auto& e = prepared.responseEstimate;
  if (mode != ResponseKeys::Mode::Auto || !e) return {};
  if (e->determined && e->decision == "fitted")
    return ResponseDock::tr(
        "If the inserted objects look too bright or too flat against the room, "
        "choose sRGB in the list above and compare.");
  return ResponseDock::tr(
      "If the photo was edited, or comes from a phone with strong contrast, its "
      "curve may still differ: choose Linear in the list above (it reads the "
      "photo's contrast as softer) and compare the objects' shading.");
}

// The technical figures: the curve, what the estimate measured and why it decided so (the
// engine's sentences in the dock's language).
QString detailsOf(const PreparedScene& prepared) {
  QStringList lines{
      ResponseDock::tr("Curve: %1").arg(QString::fromStdString(prepared.response.describe()))};
  if (const auto& e = prepared.responseEstimate) {
    if (e->noiseBins > 0)
      lines << ResponseDock::tr("Estimated from the photo's noise (%1 levels) in %2 ms.")
                   .arg(e->noiseBins)
                   .arg(qRound(1000 * e->seconds));
    else
      lines << ResponseDock::tr("Estimated from %1 edges in %2 ms.")
                   .arg(e->edgesUsed)
                   .arg(qRound(1000 * e->seconds));
    // A warning repeats the decision's reason; the decision alone when nothing warned.
    if (e->determined && e->decision != "fitted" && e->warnings.empty())
      lines << engineText(QString::fromStdString(e->decision));
    for (const auto& w : e->warnings) lines << engineText(QString::fromStdString(w));
  }
  return lines.join(QLatin1Char('\n'));
}

// The dock's scroll area: it asks for all of its content's height but insists only on the part
// above `scrolling` (the curve, the note and the Details button always show; the details
// scroll when the dock is shorter), and asks again whenever the content's layout changes.
class NotesScrollArea : public QScrollArea {
 public:
  NotesScrollArea(QWidget* parent, QWidget* scrolling) : QScrollArea(parent), scrolling_(scrolling) {}
  QSize sizeHint() const override { return widget() ? widget()->sizeHint() : QScrollArea::sizeHint(); }
  QSize minimumSizeHint() const override {
    if (!widget()) return QScrollArea::minimumSizeHint();
    QSize s = widget()->minimumSizeHint();
    if (scrolling_->isVisibleTo(widget()))
      s.rheight() -= scrolling_->minimumHeight() + widget()->layout()->spacing();
    return s;
  }

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override {
    if (watched == widget() && event->type() == QEvent::LayoutRequest) updateGeometry();
    return QScrollArea::eventFilter(watched, event);
  }

 private:
  QWidget* scrolling_;
};

}  // namespace

QString responseDecisionText(ResponseKeys::Mode mode, const PreparedScene& prepared) {
  return decisionOf(mode, prepared);
}

ResponseDock::ResponseDock(Document* document, QWidget* parent)
    : QDockWidget(parent), document_(document) {
  setObjectName(QStringLiteral("responseDock"));
  auto* body = new QWidget(this);
  auto* layout = new QVBoxLayout(body);
  choice_ = new QComboBox(body);
  for (int i = 0; i < 4; ++i) choice_->addItem(QString());
  curve_ = new ResponseCurveView(body);
  info_ = new QLabel(body);
  info_->setWordWrap(true);
  info_->setTextFormat(Qt::RichText);
  info_->setObjectName(QStringLiteral("responseInfo"));
  detailsButton_ = new QToolButton(body);
  detailsButton_->setObjectName(QStringLiteral("responseDetailsButton"));
  detailsButton_->setCheckable(true);
  detailsButton_->setAutoRaise(true);
  detailsButton_->setArrowType(Qt::RightArrow);
  detailsButton_->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  details_ = new QLabel(body);
  details_->setWordWrap(true);
  details_->setObjectName(QStringLiteral("responseDetails"));
  details_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  details_->setVisible(false);
  layout->addWidget(choice_);
  layout->addWidget(curve_, 1);
  layout->addWidget(info_);
  layout->addWidget(detailsButton_);
  layout->addWidget(details_);
  // The details scroll rather than get cut off when the dock is too short for them.
  auto* scroll = new NotesScrollArea(this, details_);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  scroll->setWidget(body);
  setWidget(scroll);
  fitter_ = new WrappedLabelFitter(body, {info_, details_});  // the notes never cut off
  connect(choice_, &QComboBox::activated, this, &ResponseDock::choose);
  connect(detailsButton_, &QToolButton::toggled, this, [this](bool open) {
    detailsButton_->setArrowType(open ? Qt::DownArrow : Qt::RightArrow);
    details_->setVisible(open);
    QSettings().setValue(QLatin1String(kDetailsOpenKey), open);
    fitter_->fit();
  });
  detailsButton_->setChecked(QSettings().value(QLatin1String(kDetailsOpenKey), false).toBool());
  connect(document_, &Document::changed, this, [this](const ChangeEvent&) { refresh(); });
  retranslate();
}

void ResponseDock::changeEvent(QEvent* event) {
  if (event->type() == QEvent::LanguageChange) retranslate();
  QDockWidget::changeEvent(event);
}

// The title, the choices and the notes in the current language (a language switch at run time).
void ResponseDock::retranslate() {
  setWindowTitle(tr("Camera Response"));
  choice_->setItemText(0, tr("Auto (estimated from the photo)"));
  choice_->setItemText(1, tr("sRGB"));
  choice_->setItemText(2, tr("Linear"));
  choice_->setItemText(3, tr("Explicit (from the scene file)"));
  choice_->setToolTip(tr("How the photo's pixel values map to light (camera.response)"));
  curve_->setAccessibleName(ResponseCurveView::caption());  // what a screen reader says
  detailsButton_->setText(tr("Details"));
  detailsButton_->setToolTip(tr("The curve's parameters and what the estimate measured"));
  refresh();
}

void ResponseDock::choose(int index) {
  static const ResponseKeys::Mode modes[] = {ResponseKeys::Mode::Auto, ResponseKeys::Mode::Srgb,
                                             ResponseKeys::Mode::Linear};
  if (index < 0 || index > 2) return refresh();  // "explicit" is the file's, not a choice here
  ResponseKeys keys;
  keys.mode = modes[index];
  if (keys == document_->scene().camera.response) return;
  QString why;
  if (!document_->setCameraResponse(keys, &why)) info_->setText(why.toHtmlEscaped());
}

// The note: what was decided and what the user can do, the figures behind "Details" (and in
// the note's tooltip).
void ResponseDock::refresh() {
  const ResponseKeys::Mode mode = document_->scene().camera.response.mode;
  choice_->setCurrentIndex(mode == ResponseKeys::Mode::Auto     ? 0
                           : mode == ResponseKeys::Mode::Srgb   ? 1
                           : mode == ResponseKeys::Mode::Linear ? 2
                                                                : 3);
  const PreparedScene* prepared = document_->prepared();
  if (!prepared) {
    info_->setText(tr("Preparing the scene...").toHtmlEscaped());
    info_->setToolTip(QString());
    fitter_->fit();
    return;
  }
  curve_->setResponse(prepared->response);
  // The decision in bold, the advice below it.
  QString text = QStringLiteral("<b>%1</b>").arg(responseDecisionText(mode, *prepared).toHtmlEscaped());
  if (const QString advice = adviceOf(mode, *prepared); !advice.isEmpty())
    text += QStringLiteral("<br>") + advice.toHtmlEscaped();
  const QString details = detailsOf(*prepared);
  info_->setText(text);
  info_->setToolTip(details);
  details_->setText(details);
  fitter_->fit();
}

}  // namespace inlay::studio
