#include "response_dock.h"

#include "wrapped_labels.h"

#include <QComboBox>
#include <QEvent>
#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QVBoxLayout>

namespace inlay::studio {

// The decode curve (code 0..255 across, linear 0..1 up) over the sRGB curve for reference.
class ResponseCurveView : public QWidget {
 public:
  explicit ResponseCurveView(QWidget* parent) : QWidget(parent) { setMinimumSize(160, 90); }
  void setResponse(const CameraResponse& r) {
    response_ = r;
    update();
  }

 protected:
  void paintEvent(QPaintEvent*) override {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), palette().base());
    const QRectF area = QRectF(rect()).adjusted(28, 8, -8, -20);
    p.setPen(palette().mid().color());
    p.drawRect(area);
    p.setPen(palette().text().color());
    p.drawText(QRectF(area.left(), area.bottom() + 2, area.width(), 16), Qt::AlignCenter, tr("code"));
    p.drawText(QRectF(0, area.top(), 26, 16), Qt::AlignRight, QStringLiteral("1"));
    p.drawText(QRectF(0, area.bottom() - 16, 26, 16), Qt::AlignRight, QStringLiteral("0"));
    auto curve = [&](const CameraResponse& r) {
      QPainterPath path;
      for (int k = 0; k < 256; ++k) {
        const QPointF q(area.left() + area.width() * k / 255.0,
                        area.bottom() - area.height() * r.table8()[size_t(k)]);
        k == 0 ? path.moveTo(q) : path.lineTo(q);
      }
      return path;
    };
    p.setPen(QPen(palette().mid().color(), 1, Qt::DashLine));
    p.drawPath(curve(CameraResponse::srgb()));
    p.setPen(QPen(palette().highlight().color(), 2));
    p.drawPath(curve(response_));
  }

 private:
  CameraResponse response_;
};

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
  info_->setObjectName(QStringLiteral("responseInfo"));
  layout->addWidget(choice_);
  layout->addWidget(curve_, 1);
  layout->addWidget(info_);
  setWidget(body);
  fitter_ = new WrappedLabelFitter(body, {info_});  // the notes below the curve never cut off
  connect(choice_, &QComboBox::activated, this, &ResponseDock::choose);
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
  if (!document_->setCameraResponse(keys, &why)) info_->setText(why);
}

void ResponseDock::refresh() {
  const ResponseKeys::Mode mode = document_->scene().camera.response.mode;
  choice_->setCurrentIndex(mode == ResponseKeys::Mode::Auto     ? 0
                           : mode == ResponseKeys::Mode::Srgb   ? 1
                           : mode == ResponseKeys::Mode::Linear ? 2
                                                                : 3);
  const PreparedScene* prepared = document_->prepared();
  if (!prepared) {
    info_->setText(tr("Preparing the scene..."));
    fitter_->fit();
    return;
  }
  curve_->setResponse(prepared->response);
  QString text = QString::fromStdString(prepared->response.describe());
  if (const auto& e = prepared->responseEstimate) {
    if (e->noiseBins > 0)
      text += tr("\nEstimated from the photo's noise (%1 levels) in %2 ms.")
                  .arg(e->noiseBins)
                  .arg(qRound(1000 * e->seconds));
    else
      text += tr("\nEstimated from %1 edges in %2 ms.").arg(e->edgesUsed).arg(qRound(1000 * e->seconds));
    if (e->determined && e->decision != "fitted")
      text += QStringLiteral("\n") + QString::fromStdString(e->decision);
    for (const auto& w : e->warnings) text += QStringLiteral("\n") + QString::fromStdString(w);
  }
  info_->setText(text);
  fitter_->fit();
}

}  // namespace inlay::studio
