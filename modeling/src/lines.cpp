#include "lines.h"

#include "layout.h"

#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc/fast_line_detector.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace inlay::detail {

namespace {

float luminance(const ImageF& im, int x, int y) {
  const float* p = im.pixel(x, y);
  if (im.channels >= 3) return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
  return p[0];
}

// Area average by an integer factor k in each direction, luminance only: one pass over the
// photo, memory of the reduced image only.
cv::Mat binnedLuminance(const ImageF& im, int k) {
  const int w = std::max(1, im.width / k), h = std::max(1, im.height / k);
  cv::Mat out(h, w, CV_32F, cv::Scalar(0));
  const int usedW = std::min(im.width, w * k), usedH = std::min(im.height, h * k);
  for (int y = 0; y < usedH; ++y) {
    float* row = out.ptr<float>(y / k);
    for (int x = 0; x < usedW; ++x) {
      const float v = luminance(im, x, y);
      row[x / k] += std::isfinite(v) ? v : 0.f;
    }
  }
  out *= 1.0 / (double(k) * k);
  return out;
}

// The 8-bit sRGB code of a linear value, as lround(255 * linearToSrgb(v)) but without a pow per
// pixel: the code is the number of code boundaries at or below v (linearToSrgb is monotone), each
// boundary found once by bisection on floats.
class SrgbEncoder {
 public:
  SrgbEncoder() {
    for (int code = 1; code < 256; ++code) {
      float lo = 0.f, hi = 1.f;  // code(lo) < code <= code(hi)
      while (std::nextafter(lo, hi) < hi) {
        const float mid = 0.5f * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (codeOf(mid) >= code ? hi : lo) = mid;
      }
      boundary_[code - 1] = hi;
    }
  }
  unsigned char operator()(float v) const {
    if (!(v > 0.f)) return 0;
    return static_cast<unsigned char>(std::upper_bound(boundary_.begin(), boundary_.end(), v) -
                                      boundary_.begin());
  }
  static int codeOf(float v) { return int(std::lround(255.f * linearToSrgb(v))); }

 private:
  std::array<float, 255> boundary_{};  // boundary_[c - 1]: the least v of code c
};

}  // namespace

unsigned char srgbCode8(float linear) {
  static const SrgbEncoder encode;
  return encode(linear);
}

DetectedLines detectLineSegments(const ImageF& linearRgb, int maxWorkingSidePx, int maxSegments,
                                 const CancelToken* cancel) {
  DetectedLines out;
  const int longSide = std::max(linearRgb.width, linearRgb.height);
  const int target = std::max(16, std::min(maxWorkingSidePx, longSide));
  const int k = std::max(1, longSide / target);
  cv::Mat lum = binnedLuminance(linearRgb, k);
  if (cancel && cancel->shouldStop()) return out;
  const double afterBin = std::max(lum.cols, lum.rows);
  if (afterBin > target) {
    const double s = target / afterBin;
    cv::Mat r;
    cv::resize(lum, r,
               cv::Size(std::max(1, int(std::lround(lum.cols * s))),
                        std::max(1, int(std::lround(lum.rows * s)))),
               0, 0, cv::INTER_AREA);
    lum = r;
  }
  out.workingWidth = lum.cols;
  out.workingHeight = lum.rows;
  // Working pixel = photo pixel * (working / photo) per axis; binning trims at most k-1 pixels,
  // so use the width ratio (the error is below a working pixel).
  out.workingScale = double(lum.cols) / double(linearRgb.width);
  const double sy = double(lum.rows) / double(linearRgb.height);

  // Encode for edges the eye sees (and the detector's thresholds were made for).
  cv::Mat grey8(lum.rows, lum.cols, CV_8U);
  for (int y = 0; y < lum.rows; ++y) {
    const float* s = lum.ptr<float>(y);
    unsigned char* d = grey8.ptr<unsigned char>(y);
    for (int x = 0; x < lum.cols; ++x)
      d[x] = srgbCode8(s[x]);
  }
  if (lum.cols < 8 || lum.rows < 8) return out;
  // Rendered and high-ISO photos are noisy: a light blur keeps edges, drops noise segments.
  cv::GaussianBlur(grey8, grey8, cv::Size(0, 0), 1.0);
  out.edges = photoEdgesOf(grey8, linearRgb.width, linearRgb.height);
  const double diag = std::hypot(double(lum.cols), double(lum.rows));
  const int minLength = std::max(6, int(std::lround(0.025 * diag)));
  auto fld = cv::ximgproc::createFastLineDetector(minLength, 1.414f, 20.0, 40.0, 3, false);
  std::vector<cv::Vec4f> raw;
  fld->detect(grey8, raw);
  if (cancel && cancel->shouldStop()) return out;

  out.segments.reserve(raw.size());
  for (const auto& r : raw) {
    LineSegment s;
    // OpenCV puts pixel centres at integers, the photo frame at +0.5: shift, then scale.
    s.aPx = Vec2((r[0] + 0.5) / out.workingScale, (r[1] + 0.5) / sy);
    s.bPx = Vec2((r[2] + 0.5) / out.workingScale, (r[3] + 0.5) / sy);
    if (!s.aPx.allFinite() || !s.bPx.allFinite() || s.lengthPx() <= 0) continue;
    out.segments.push_back(s);
  }
  std::sort(out.segments.begin(), out.segments.end(),
            [](const LineSegment& a, const LineSegment& b) { return a.lengthPx() > b.lengthPx(); });
  if (int(out.segments.size()) > maxSegments) out.segments.resize(std::max(0, maxSegments));
  return out;
}

}  // namespace inlay::detail
