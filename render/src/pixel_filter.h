// Internal: the camera's pixel filter, by importance sampling. Each camera sample leaves at a
// position drawn with the filter's density around its pixel's centre (one axis at a time, as
// Cycles does), and every sample weighs the same, so a pixel's mean is the filter-weighted
// average of the image around it. Width 0 is the box of the pixel itself (the sample anywhere
// in the pixel, uniformly); a width w > 0 is a Blackman-Harris window reaching w pixels either
// side of the centre (Cycles' "filter_width" convention: its default 1.5 px reaches 1.5 px,
// a standard deviation of 0.42 px against the box's 0.29 px).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace inlay::detail {

class PixelFilter {
 public:
  static constexpr double kMaxWidth = 8.0;  // pixels; wider widths are cut to this

  // `width` in pixels; 0, negative or not finite: the box.
  explicit PixelFilter(double width = 0) {
    width_ = std::isfinite(width) && width > 0 ? std::min(width, kMaxWidth) : 0.0;
    if (width_ > 0) tabulate();
  }

  double width() const { return width_; }

  // The sample's position along one axis, in pixels from the pixel's left (top) edge, for a
  // uniform number u in [0, 1): the box gives u, the window 0.5 + its inverse CDF at u.
  double position(double u) const {
    if (!(u >= 0)) u = 0;  // NaN too
    u = std::min(u, 1.0);
    if (width_ <= 0) return u;
    const double t = u * kCells;
    const size_t i = std::min(size_t(t), size_t(kCells) - 1);
    const double f = t - double(i);
    return 0.5 + inverse_[i] + f * (inverse_[i + 1] - inverse_[i]);
  }

 private:
  static constexpr int kCells = 1024;

  // Blackman-Harris over [-w, w], zero at both ends (Cycles' filter_func_blackman_harris with
  // its table's width doubled).
  double weight(double x) const {
    constexpr double kTwoPi = 6.283185307179586;
    const double v = kTwoPi * (x / (2 * width_) + 0.5);
    return 0.35875 - 0.48829 * std::cos(v) + 0.14128 * std::cos(2 * v) - 0.01168 * std::cos(3 * v);
  }

  // The inverse CDF at kCells + 1 evenly spaced u: the CDF by the trapezoid rule on a grid
  // eight times finer, inverted by linear interpolation.
  void tabulate() {
    constexpr int n = 8 * kCells;
    std::array<double, n + 1> cdf{};
    const double dx = 2 * width_ / n;
    for (int k = 1; k <= n; ++k)
      cdf[size_t(k)] = cdf[size_t(k - 1)] +
                       0.5 * dx * (weight(-width_ + (k - 1) * dx) + weight(-width_ + k * dx));
    int k = 0;
    for (int i = 0; i <= kCells; ++i) {
      const double target = cdf[n] * double(i) / kCells;
      while (k < n - 1 && cdf[size_t(k + 1)] < target) ++k;
      const double span = cdf[size_t(k + 1)] - cdf[size_t(k)];
      const double f = span > 0 ? std::clamp((target - cdf[size_t(k)]) / span, 0.0, 1.0) : 0.0;
      inverse_[size_t(i)] = -width_ + (k + f) * dx;
    }
  }

  double width_ = 0;
  std::array<double, kCells + 1> inverse_{};
};

}  // namespace inlay::detail
