#include "caustic_map.h"

#include "sampling.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace inlay::detail {

namespace {
constexpr int64_t kCellBias = int64_t(1) << 20;  // 21 bits per axis: +-1e6 cells
}  // namespace

uint64_t CausticMap::cellKey(int64_t x, int64_t y, int64_t z) const {
  auto axis = [](int64_t c) { return uint64_t(std::clamp<int64_t>(c + kCellBias, 0, 2 * kCellBias - 1)); };
  return (axis(x) << 42) | (axis(y) << 21) | axis(z);
}

CausticMap::CausticMap(std::vector<CausticPhoton> photons, double radius) {
  if (!(radius > 0) || !std::isfinite(radius)) return;
  radius_ = radius;
  std::erase_if(photons, [](const CausticPhoton& p) {
    return !p.point.allFinite() || !p.normal.allFinite() || !p.flux.allFinite() || !(p.flux.maxCoeff() > 0);
  });
  std::vector<uint64_t> keys(photons.size());
  for (size_t i = 0; i < photons.size(); ++i) {
    const Vec3 c = (photons[i].point / radius_).array().floor().matrix();
    keys[i] = cellKey(int64_t(c.x()), int64_t(c.y()), int64_t(c.z()));
  }
  std::vector<size_t> order(photons.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return keys[a] < keys[b]; });
  photons_.reserve(photons.size());
  keys_.reserve(photons.size());
  for (size_t i : order) photons_.push_back(photons[i]), keys_.push_back(keys[i]);
  lo_ = Vec3::Constant(1e300), hi_ = Vec3::Constant(-1e300);
  for (const CausticPhoton& p : photons_) {
    lo_ = lo_.cwiseMin(p.point), hi_ = hi_.cwiseMax(p.point);
    totalFlux_ += p.flux.mean();
  }
  lo_ -= Vec3::Constant(radius_), hi_ += Vec3::Constant(radius_);
}

Vec3 CausticMap::irradiance(const Vec3& p, const Vec3& n) const {
  Vec3 sum = Vec3::Zero();
  if (photons_.empty() || !p.allFinite()) return sum;
  if ((p.array() < lo_.array()).any() || (p.array() > hi_.array()).any()) return sum;
  const Vec3 c = (p / radius_).array().floor().matrix();
  const double r2 = radius_ * radius_;
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dz = -1; dz <= 1; ++dz) {
        const uint64_t key = cellKey(int64_t(c.x()) + dx, int64_t(c.y()) + dy, int64_t(c.z()) + dz);
        const auto range = std::equal_range(keys_.begin(), keys_.end(), key);
        for (auto it = range.first; it != range.second; ++it) {
          const CausticPhoton& ph = photons_[size_t(it - keys_.begin())];
          const Vec3 d = ph.point - p;
          const double d2 = d.squaredNorm();
          if (d2 >= r2 || ph.normal.dot(n) <= 0.5 || std::abs(d.dot(n)) > 0.1 * radius_) continue;
          sum += ph.flux * (1.0 - d2 / r2);
        }
      }
  return sum * (2.0 / (kPi * r2));
}

}  // namespace inlay::detail
