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

#include <array>

class QComboBox;
class QLabel;
class QToolButton;

namespace inlay::studio {

class WrappedLabelFitter;

class ResponseCurveView;

// The code of mid-grey in sRGB (118: linear 0.18), where every plotted curve reads 0 stops:
// exposure does not change a curve's shape.
inline constexpr int kResponsePlotMidCode = 118;
// The plot's vertical range is at most this many stops either way.
inline constexpr double kResponsePlotMaxStops = 16;

// What the dock's curve draws: each code's decoded radiance in stops above the curve's own at
// kResponsePlotMidCode, clamped to [bottom, top] (whole stops, the range of both curves; code
// 0 at the bottom), for the response and for sRGB (dashed, for reference).
struct ResponsePlot {
  std::array<double, 256> curve{}, srgb{};
  double bottom = -1, top = 1;
};
ResponsePlot responsePlot(const CameraResponse& response);

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
