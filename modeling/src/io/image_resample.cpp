#include "inlay/modeling/image_resample.h"

#include "inlay/modeling/image_io.h"
#include "inlay/modeling/parallel.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace inlay {

std::array<int, 2> workingSizeFor(int width, int height, double maxPixels) {
  if (width <= 0 || height <= 0 || !(maxPixels > 0) || double(width) * height <= maxPixels)
    return {width, height};
  const double s = std::sqrt(maxPixels / (double(width) * height));
  return {std::max(1, int(std::floor(width * s))), std::max(1, int(std::floor(height * s)))};
}

namespace {

// The guide's value for channel c of the target (its matching channel, or its mean).
inline float guideOf(const float* g, int guideChannels, int c, bool paired) {
  if (paired) return g[c];
  float sum = 0;
  for (int k = 0; k < guideChannels; ++k) sum += g[k];
  return sum / float(guideChannels);
}

// The log of a guide pixel's mean (the range term's coordinate); dark and non-finite as dark.
inline float logLuminance(const float* g, int channels) {
  float sum = 0;
  for (int k = 0; k < channels; ++k) sum += g[k];
  const float v = sum / float(channels);
  return std::log(std::isfinite(v) ? std::max(v, 1e-6f) : 1e-6f);
}

// Along one axis: per full-size index, the first low index of its window and the window's
// spatial weights (2 radius of them; outside the image: weight 0, index clamped).
struct AxisWindow {
  int n = 0;                  // window length (2 radius)
  std::vector<int> first;     // per full index
  std::vector<float> weight;  // per full index, n each
};
AxisWindow axisWindow(int full, int low, int radius, double sigma) {
  AxisWindow a;
  a.n = 2 * radius;
  a.first.resize(size_t(full));
  a.weight.resize(size_t(full) * a.n);
  for (int i = 0; i < full; ++i) {
    const double u = (i + 0.5) * double(low) / full - 0.5;
    const int base = int(std::floor(u));
    a.first[size_t(i)] = base - radius + 1;
    for (int k = 0; k < a.n; ++k) {
      const int j = a.first[size_t(i)] + k;
      const double d = j - u;
      a.weight[size_t(i) * a.n + k] = j < 0 || j >= low ? 0.f
                                                        : float(std::exp(-d * d / (2 * sigma * sigma)));
    }
  }
  return a;
}

// Per low pixel and channel: the value to spread (a ratio to the guide, or the value itself),
// whether it is a ratio, and the value itself (finite), side by side for the taps' reads.
struct LowValue {
  float value = 0, plain = 0;
  bool isRatio = false;
};
std::vector<LowValue> lowValuesOf(const ImageF& low, const ImageF& lowGuide, bool paired,
                                  const JointBilateralOptions& o) {
  std::vector<LowValue> v(low.data.size());
  const int C = low.channels;
  for (size_t p = 0; p < low.pixelCount(); ++p)
    for (int c = 0; c < C; ++c) {
      const size_t i = p * size_t(C) + size_t(c);
      const float t = std::isfinite(low.data[i]) ? low.data[i] : 0.f;
      const float g =
          guideOf(&lowGuide.data[p * size_t(lowGuide.channels)], lowGuide.channels, c, paired);
      const bool ratio = o.ratio && std::isfinite(g) && g > o.darkGuide;
      v[i] = {ratio ? t / g : t, t, ratio};
    }
  return v;
}

}  // namespace

namespace {

// One pixel's taps: the low pixels of its window and their joint weights (spatial x range), and
// the spatial weights alone (for a pixel no neighbour resembles). Sized once per task.
struct PixelTaps {
  explicit PixelTaps(int most) : q(size_t(most)), joint(size_t(most)), spatial(size_t(most)) {}
  std::vector<size_t> q;
  std::vector<float> joint, spatial;
  int n = 0;
  float jointTotal = 0, spatialTotal = 0;
};

}  // namespace

std::vector<ImageF> jointBilateralUpsample(const std::vector<const ImageF*>& lows,
                                           const ImageF& lowGuide, const ImageF& fullGuide,
                                           const JointBilateralOptions& o) {
  std::vector<ImageF> out;
  const int w = lowGuide.width, h = lowGuide.height, W = fullGuide.width, H = fullGuide.height;
  const int r = std::max(1, o.radius);
  const AxisWindow ax = axisWindow(W, w, r, std::max(0.1, o.sigmaSpatial));
  const AxisWindow ay = axisWindow(H, h, r, std::max(0.1, o.sigmaSpatial));
  std::vector<float> lowLog(lowGuide.pixelCount());
  for (size_t p = 0; p < lowLog.size(); ++p)
    lowLog[p] = logLuminance(&lowGuide.data[p * size_t(lowGuide.channels)], lowGuide.channels);
  // The range weight by |log difference|, tabulated up to 4 sigma (beyond: 0).
  constexpr int kTable = 1024;
  const double sr = std::max(1e-3, o.sigmaRange), step = 4 * sr / kTable;
  std::vector<float> rangeTable(kTable);
  for (int k = 0; k < kTable; ++k)
    rangeTable[size_t(k)] = float(std::exp(-0.5 * std::pow(k * step / sr, 2)));
  std::vector<std::vector<LowValue>> values;
  for (const ImageF* low : lows) {
    const bool paired = lowGuide.channels == low->channels && fullGuide.channels == low->channels;
    values.push_back(lowValuesOf(*low, lowGuide, paired, o));
    out.emplace_back(W, H, low->channels);
  }
  parallelFor(tbb::blocked_range<int>(0, H), [&](const tbb::blocked_range<int>& rows) {
    PixelTaps t(ax.n * ay.n);
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < W; ++x) {
        const float* g = fullGuide.pixel(x, y);
        const float here = logLuminance(g, fullGuide.channels);
        t.n = 0;
        t.jointTotal = t.spatialTotal = 0;
        for (int ky = 0; ky < ay.n; ++ky) {
          const float wy = ay.weight[size_t(y) * ay.n + ky];
          if (wy == 0) continue;
          const size_t row = size_t(ay.first[size_t(y)] + ky) * w;
          for (int kx = 0; kx < ax.n; ++kx) {
            const float ws = wy * ax.weight[size_t(x) * ax.n + kx];
            if (ws == 0) continue;
            const size_t q = row + size_t(ax.first[size_t(x)] + kx);
            const int bin = int(std::fabs(here - lowLog[q]) / step);
            const float wj = bin < kTable ? ws * rangeTable[size_t(bin)] : 0.f;
            t.q[size_t(t.n)] = q, t.joint[size_t(t.n)] = wj, t.spatial[size_t(t.n)] = ws;
            ++t.n;
            t.jointTotal += wj, t.spatialTotal += ws;
          }
        }
        // No neighbour like this pixel (a guide value the working copy never shows): distance only.
        const bool range = t.jointTotal > 1e-6f * t.spatialTotal;
        const float* wt = range ? t.joint.data() : t.spatial.data();
        const float total = range ? t.jointTotal : t.spatialTotal;
        for (size_t k = 0; k < lows.size(); ++k) {
          const int C = lows[k]->channels;
          const bool paired = lowGuide.channels == C && fullGuide.channels == C;
          const LowValue* lv = values[k].data();
          for (int c = 0; c < C; ++c) {
            const float gc = guideOf(g, fullGuide.channels, c, paired);
            float sum = 0;
            for (int m = 0; m < t.n; ++m) {
              const LowValue& l = lv[t.q[size_t(m)] * size_t(C) + size_t(c)];
              sum += wt[m] * (l.isRatio ? l.value * gc : l.value);
            }
            const float v = sum / total;
            if (std::isfinite(v)) {
              out[k].at(x, y, c) = v;
              continue;
            }
            float plain = 0;  // rare: the spatial average of the values themselves
            for (int m = 0; m < t.n; ++m)
              plain += t.spatial[size_t(m)] * lv[t.q[size_t(m)] * size_t(C) + size_t(c)].plain;
            out[k].at(x, y, c) = plain / t.spatialTotal;
          }
        }
      }
  });
  return out;
}

ImageF jointBilateralUpsample(const ImageF& low, const ImageF& lowGuide, const ImageF& fullGuide,
                              const JointBilateralOptions& o) {
  const int w = low.width, h = low.height, W = fullGuide.width, H = fullGuide.height;
  if (low.empty() || fullGuide.empty() || lowGuide.width != w || lowGuide.height != h ||
      (W <= w && H <= h))
    return low.empty() || fullGuide.empty() ? low : resizeImage(low, W, H);
  return std::move(
      jointBilateralUpsample(std::vector<const ImageF*>{&low}, lowGuide, fullGuide, o).front());
}

}  // namespace inlay
