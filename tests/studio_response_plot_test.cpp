// The Camera Response dock's curve (app/studio/response_dock.h, responsePlot): each code in
// stops above mid-grey, so a long highlight shoulder, a toe or a straight (linear) curve shows
// its shape instead of a line along zero. Every curve of the family, at its bounds too, gives
// finite, rising stops inside the plot's range. Needs nothing from ../shared.
#include "response_dock.h"

#include <QtTest>

#include <cmath>

using namespace inlay;
using namespace inlay::studio;

namespace {

ResponseParams params(double power, double toe, double shoulder) {
  ResponseParams p;
  p.power = power;
  p.toe = toe;
  p.shoulder = shoulder;
  return p;
}

// Whether every value is finite, inside [bottom, top] and rises (or stays) with the code.
bool risesInsideTheRange(const std::array<double, 256>& stops, const ResponsePlot& plot) {
  for (size_t k = 0; k < stops.size(); ++k) {
    if (!std::isfinite(stops[k]) || stops[k] < plot.bottom || stops[k] > plot.top) return false;
    if (k > 0 && stops[k] < stops[k - 1]) return false;
  }
  return true;
}

}  // namespace

class ResponsePlotTest : public QObject {
  Q_OBJECT

 private Q_SLOTS:
  void sRgbReadsZeroAtMidGreyAndItsOwnStopsElsewhere() {
    const ResponsePlot plot = responsePlot(CameraResponse::srgb());
    QCOMPARE(plot.curve[kResponsePlotMidCode], 0.0);
    // Code 255 is linear 1: log2(1 / 0.1812) stops above code 118.
    QVERIFY(std::abs(plot.curve[255] - std::log2(1.0 / CameraResponse::srgb().table8()[118])) < 1e-9);
    QCOMPARE(plot.curve, plot.srgb);
    QCOMPARE(plot.top, 3.0);
    // Code 1 is linear 0.0003: 9.2 stops below mid-grey; code 0 sits on the floor.
    QCOMPARE(plot.bottom, -10.0);
    QCOMPARE(plot.curve[0], -10.0);
  }

  // The long shoulder the noise cue fits (shoulder near 1000) on a linear axis was a line along
  // zero up to code ~250; in stops its highlights rise far above sRGB's.
  void aLongShoulderRisesAboveSrgbInTheHighlights() {
    const ResponsePlot plot = responsePlot(CameraResponse::toeShoulder(params(0.99, 0, 996)));
    QVERIFY(plot.curve[250] > plot.srgb[250] + 4);
    QVERIFY(plot.top > 8);
    QVERIFY(std::abs(plot.curve[64] - plot.srgb[64]) < 1.5);
  }

  void everyCurveAtTheFamilysBoundsStaysFiniteAndRising() {
    const double maxToe = ResponseParams::kMaxToe, maxShoulder = ResponseParams::kMaxShoulder;
    for (const CameraResponse& r :
         {CameraResponse::srgb(), CameraResponse::linear(),
          CameraResponse::toeShoulder(params(ResponseParams::kMinPower, 0, 0)),
          CameraResponse::toeShoulder(params(ResponseParams::kMaxPower, 0, 0)),
          CameraResponse::toeShoulder(params(1, maxToe, 0)),
          CameraResponse::toeShoulder(params(1, 0, maxShoulder)),
          CameraResponse::toeShoulder(params(ResponseParams::kMinPower, maxToe, maxShoulder)),
          CameraResponse::toeShoulder(params(ResponseParams::kMaxPower, maxToe, maxShoulder)),
          CameraResponse::toeShoulder(params(std::nan(""), INFINITY, -1))}) {
      const ResponsePlot plot = responsePlot(r);
      QVERIFY2(risesInsideTheRange(plot.curve, plot), r.describe().c_str());
      QVERIFY2(risesInsideTheRange(plot.srgb, plot), r.describe().c_str());
      QVERIFY(plot.top >= 1 && plot.top <= kResponsePlotMaxStops);
      QVERIFY(plot.bottom <= -1 && plot.bottom >= -kResponsePlotMaxStops);
      QCOMPARE(plot.curve[0], plot.bottom);
    }
  }
};

QTEST_MAIN(ResponsePlotTest)
#include "studio_response_plot_test.moc"
