// The camera response dock: the curve the photo is decoded with (code -> linear radiance, the
// estimate's or camera.response's) and a choice of Auto / sRGB / Linear, each one undo step
// through Document::setCameraResponse. Redrawn from the document's state on each change.
// Retranslates on QEvent::LanguageChange. GUI thread only.
#pragma once

#include "document.h"

#include <QDockWidget>

class QComboBox;
class QLabel;

namespace inlay::studio {

class WrappedLabelFitter;

class ResponseCurveView;

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
  QLabel* info_;
  ResponseCurveView* curve_;
  WrappedLabelFitter* fitter_ = nullptr;
};

}  // namespace inlay::studio
