// The camera response dock: the curve the photo is decoded with (code -> linear radiance, the
// estimate's or camera.response's) and a choice of Auto / sRGB / Linear, each one undo step
// through Document::setCameraResponse. Below the curve a plain note says what was decided and
// what the user can do about it; "Details" (and the note's tooltip) shows the technical figures:
// the curve's parameters and the estimate's own reasons, translated by engineText(); whether
// it is open is kept in the settings (responseDock/detailsOpen). Redrawn from the document's state on each change.
// Retranslates on QEvent::LanguageChange. GUI thread only.
#pragma once

#include "document.h"

#include <QDockWidget>

class QComboBox;
class QLabel;
class QToolButton;

namespace inlay::studio {

class WrappedLabelFitter;

class ResponseCurveView;

// What the dock's note says was decided about the photo's curve, in one plain sentence (the
// current language).
QString responseDecisionText(ResponseKeys::Mode mode, const PreparedScene& prepared);

class ResponseDock : public QDockWidget {
  Q_OBJECT
 public:
  ResponseDock(Document* document, QWidget* parent = nullptr);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslate();
  void refresh();
  void choose(int index);

  Document* document_;
  QComboBox* choice_;
  QLabel* info_;  // what was decided and what the user can do
  QToolButton* detailsButton_;
  QLabel* details_;  // the technical figures, shown by detailsButton_
  ResponseCurveView* curve_;
  WrappedLabelFitter* fitter_ = nullptr;
};

}  // namespace inlay::studio
