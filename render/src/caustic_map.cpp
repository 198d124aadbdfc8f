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
  auto axis = [](int64_t c) {
    return uint64_t(std::clamp<int64_t>(c + kCellBias, 0, 2 * kCellBias - 1));
  };
  return (axis(x) << 42) | (axis(y) << 21) | axis(z);
}

CausticMap::CausticMap(std::vector<CausticPhoton> photons, double radius) {
  if (!(radius > 0) || !std::isfinite(radius)) return;
  radius_ = radius;
  std::erase_if(photons, [](const CausticPhoton& p) {
    return !p.point.allFinite() || !p.normal.allFinite() || !p.flux.allFinite() ||
           !(p.flux.maxCoeff() > 0);
  });
  for (const CausticPhoton& p : photons) totalFlux_ += p.flux.mean();
  photons = merged(std::move(photons));
  std::vector<uint64_t> keys(photons.size());
  for (size_t i = 0; i < photons.size(); ++i) keys[i] = cellOf(photons[i].point, radius_);
  std::vector<size_t> order(photons.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return keys[a] < keys[b]; });
  photons_.reserve(photons.size());
  cells_.reserve(photons.size());
  for (size_t i : order) {
    auto [cell, added] =
        cells_.try_emplace(keys[i], uint32_t(photons_.size()), uint32_t(photons_.size()));
    ++cell->second.second;
    photons_.push_back(photons[i]);
  }
  lo_ = Vec3::Constant(1e300), hi_ = Vec3::Constant(-1e300);
  for (const CausticPhoton& p : photons_) lo_ = lo_.cwiseMin(p.point), hi_ = hi_.cwiseMax(p.point);
  lo_ -= Vec3::Constant(radius_), hi_ += Vec3::Constant(radius_);
}

uint64_t CausticMap::cellOf(const Vec3& p, double size) const {
  const Vec3 c = (p / size).array().floor().matrix();
  return cellKey(int64_t(c.x()), int64_t(c.y()), int64_t(c.z()));
}

// Photons in one cell of a sixth of the radius whose normals share their dominant axis and sign
// become one: their flux summed, at their flux-weighted mean point, with their mean normal. A
// focused caustic puts tens of thousands of photons within one radius; merged, a lookup sums a
// few hundred at most, and the estimate moves by less than a quarter of the radius's blur.
std::vector<CausticPhoton> CausticMap::merged(std::vector<CausticPhoton> photons) const {
  auto normalClass = [](const Vec3& n) {
    int axis = 0;
    n.cwiseAbs().maxCoeff(&axis);
    return uint64_t(2 * axis + (n[axis] < 0 ? 1 : 0));
  };
  std::vector<std::pair<uint64_t, uint64_t>> keys(photons.size());
  for (size_t i = 0; i < photons.size(); ++i)
    keys[i] = {cellOf(photons[i].point, radius_ / kMergeCells), normalClass(photons[i].normal)};
  std::vector<size_t> order(photons.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return keys[a] < keys[b]; });
  std::vector<CausticPhoton> out;
  for (size_t k = 0; k < order.size();) {
    CausticPhoton sum{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    double weight = 0;
    size_t j = k;
    for (; j < order.size() && keys[order[j]] == keys[order[k]]; ++j) {
      const CausticPhoton& p = photons[order[j]];
      const double w = p.flux.mean();
      sum.point += w * p.point, sum.normal += p.normal, sum.flux += p.flux, weight += w;
    }
    const double len = sum.normal.norm();
    sum.point = weight > 0 ? Vec3(sum.point / weight) : photons[order[k]].point;
    sum.normal = len > 1e-12 ? Vec3(sum.normal / len) : photons[order[k]].normal;
    out.push_back(sum);
    k = j;
  }
  return out;
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
        const auto cell = cells_.find(key);
        if (cell == cells_.end()) continue;
        for (uint32_t k = cell->second.first; k < cell->second.second; ++k) {
          const CausticPhoton& ph = photons_[k];
          const Vec3 d = ph.point - p;
          const double d2 = d.squaredNorm();
          if (d2 >= r2 || ph.normal.dot(n) <= 0.5 || std::abs(d.dot(n)) > 0.1 * radius_) continue;
          sum += ph.flux * (1.0 - d2 / r2);
        }
      }
  return sum * (2.0 / (kPi * r2));
}

}  // namespace inlay::detail
