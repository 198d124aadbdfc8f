#include "inlay/lighting/poisson.h"

#include "inlay/modeling/parallel.h"

#include <opencv2/core.hpp>
#include <tbb/blocked_range.h>

#include <algorithm>
#include <cmath>

namespace inlay {

namespace {

template <class F>
void forRows(int H, F&& f) {
  parallelFor(tbb::blocked_range<int>(0, H, 16), [&](const tbb::blocked_range<int>& r) {
    for (int y = r.begin(); y < r.end(); ++y) f(y);
  });
}

struct Level {
  int w = 0, h = 0;
  std::vector<float> u, f;
};

// Sum of the in-grid 4-neighbours of (x, y) and how many there are.
inline float neighbourSum(const float* u, int x, int y, int w, int h, int& degree) {
  const size_t i = size_t(y) * w + x;
  float s = 0;
  degree = 0;
  if (x > 0) s += u[i - 1], ++degree;
  if (x + 1 < w) s += u[i + 1], ++degree;
  if (y > 0) s += u[i - size_t(w)], ++degree;
  if (y + 1 < h) s += u[i + size_t(w)], ++degree;
  return s;
}

// (L u)_i - f_i = 0 solved for u_i on one colour of the checkerboard: u_i = (sum - f_i) / degree.
void redBlackSweep(Level& L) {
  const int w = L.w, h = L.h;
  float* u = L.u.data();
  const float* f = L.f.data();
  for (int colour = 0; colour < 2; ++colour)
    forRows(h, [&](int y) {
      const bool interiorRow = y > 0 && y + 1 < h;
      for (int x = (y + colour) & 1; x < w; x += 2) {
        const size_t i = size_t(y) * w + x;
        if (interiorRow && x > 0 && x + 1 < w) {
          u[i] = ((u[i - 1] + u[i + 1]) + (u[i - size_t(w)] + u[i + size_t(w)]) - f[i]) * 0.25f;
        } else {
          int d = 0;
          const float s = neighbourSum(u, x, y, w, h, d);
          if (d > 0) u[i] = (s - f[i]) / float(d);
        }
      }
    });
}

float residualAt(const Level& L, int x, int y) {
  const size_t i = size_t(y) * L.w + x;
  const float* u = L.u.data();
  if (x > 0 && x + 1 < L.w && y > 0 && y + 1 < L.h)
    return L.f[i] - ((u[i - 1] + u[i + 1]) + (u[i - size_t(L.w)] + u[i + size_t(L.w)]) - 4 * u[i]);
  int d = 0;
  const float s = neighbourSum(u, x, y, L.w, L.h, d);
  return L.f[i] - (s - float(d) * L.u[i]);
}

// Coarse right-hand side: the sum of the children's residuals (the coarse grid's spacing is
// twice the fine one, so its unit-weight Laplacian sees 4x the fine residual's mean).
void restrictResidual(const Level& fine, Level& coarse) {
  forRows(coarse.h, [&](int Y) {
    for (int X = 0; X < coarse.w; ++X) {
      float s = 0;
      for (int y = 2 * Y; y < std::min(fine.h, 2 * Y + 2); ++y)
        for (int x = 2 * X; x < std::min(fine.w, 2 * X + 2); ++x) s += residualAt(fine, x, y);
      coarse.f[size_t(Y) * coarse.w + X] = s;
    }
  });
}

// Fine u += the coarse correction, bilinear between coarse cell centres (clamped at the edges,
// which keeps the Neumann boundary's zero slope).
void prolongAdd(const Level& coarse, Level& fine) {
  // Per fine column: the two coarse columns and the weight of the second (the same for every row).
  std::vector<int> x0(size_t(fine.w)), x1(size_t(fine.w));
  std::vector<float> ax(size_t(fine.w));
  for (int x = 0; x < fine.w; ++x) {
    const float fx = std::clamp((x + 0.5f) * 0.5f - 0.5f, 0.f, float(coarse.w - 1));
    x0[size_t(x)] = int(fx), x1[size_t(x)] = std::min(int(fx) + 1, coarse.w - 1);
    ax[size_t(x)] = fx - float(int(fx));
  }
  forRows(fine.h, [&](int y) {
    const float fy = std::clamp((y + 0.5f) * 0.5f - 0.5f, 0.f, float(coarse.h - 1));
    const int y0 = int(fy), y1 = std::min(y0 + 1, coarse.h - 1);
    const float ay = fy - float(y0);
    const float* r0 = coarse.u.data() + size_t(y0) * coarse.w;
    const float* r1 = coarse.u.data() + size_t(y1) * coarse.w;
    float* out = fine.u.data() + size_t(y) * fine.w;
    for (int x = 0; x < fine.w; ++x) {
      const size_t a = size_t(x0[size_t(x)]), b = size_t(x1[size_t(x)]);
      const float t = ax[size_t(x)];
      out[x] += (1 - ay) * (r0[a] + t * (r0[b] - r0[a])) + ay * (r1[a] + t * (r1[b] - r1[a]));
    }
  });
}

bool isCoarsest(const Level& L) { return size_t(L.w) * L.h <= 4096 || L.w <= 2 || L.h <= 2; }

void vCycle(std::vector<Level>& levels, size_t l) {
  Level& L = levels[l];
  if (l + 1 == levels.size()) {
    // The coarsest grid: its residual made compatible (sum zero) and solved directly; the
    // sweeps finish where the DCT padded an odd side (there it is only close).
    std::vector<float> r(L.f.size());
    double mean = 0;
    for (int y = 0; y < L.h; ++y)
      for (int x = 0; x < L.w; ++x) mean += r[size_t(y) * L.w + x] = residualAt(L, x, y);
    mean /= double(r.size());
    for (float& v : r) v -= float(mean);
    const std::vector<float> e = poissonNeumannDct(r, L.w, L.h);
    for (size_t i = 0; i < e.size(); ++i) L.u[i] += e[i];
    for (int k = 0; k < 4; ++k) redBlackSweep(L);
    return;
  }
  for (int k = 0; k < 2; ++k) redBlackSweep(L);
  Level& C = levels[l + 1];
  restrictResidual(L, C);
  std::fill(C.u.begin(), C.u.end(), 0.f);
  vCycle(levels, l + 1);
  prolongAdd(C, L);
  for (int k = 0; k < 2; ++k) redBlackSweep(L);
}

double rmsResidual(const Level& L) {
  std::vector<double> rows(size_t(L.h), 0.0);
  forRows(L.h, [&](int y) {
    double s = 0;
    for (int x = 0; x < L.w; ++x) {
      const double r = residualAt(L, x, y);
      s += r * r;
    }
    rows[size_t(y)] = s;
  });
  double s = 0;
  for (double r : rows) s += r;
  return std::sqrt(s / double(std::max<size_t>(1, L.f.size())));
}

}  // namespace

std::vector<float> poissonNeumannDct(const std::vector<float>& div, int W, int H) {
  const int PW = W + (W & 1), PH = H + (H & 1);
  cv::Mat d(PH, PW, CV_32F, cv::Scalar(0));
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) d.at<float>(y, x) = div[size_t(y) * W + x];
  cv::Mat f;
  cv::dct(d, f);
  std::vector<double> cx(static_cast<size_t>(PW)), cy(static_cast<size_t>(PH));
  for (int k = 0; k < PW; ++k) cx[size_t(k)] = 2 * std::cos(M_PI * k / PW) - 2;
  for (int l = 0; l < PH; ++l) cy[size_t(l)] = 2 * std::cos(M_PI * l / PH) - 2;
  for (int l = 0; l < PH; ++l)
    for (int k = 0; k < PW; ++k) {
      const double lam = cx[size_t(k)] + cy[size_t(l)];
      f.at<float>(l, k) = (k == 0 && l == 0) ? 0.f : float(f.at<float>(l, k) / lam);
    }
  cv::dct(f, d, cv::DCT_INVERSE);
  std::vector<float> u(size_t(W) * H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) u[size_t(y) * W + x] = d.at<float>(y, x);
  return u;
}

std::vector<float> poissonNeumannMultigrid(const std::vector<float>& f, int W, int H, double tolerance,
                                           int maxCycles, PoissonReport* report) {
  std::vector<Level> levels(1);
  levels[0].w = W, levels[0].h = H;
  levels[0].f = f;
  levels[0].u.assign(f.size(), 0.f);
  while (!isCoarsest(levels.back())) {
    Level c;
    c.w = (levels.back().w + 1) / 2, c.h = (levels.back().h + 1) / 2;
    c.f.assign(size_t(c.w) * c.h, 0.f);
    c.u.assign(c.f.size(), 0.f);
    levels.push_back(std::move(c));
  }
  double fNorm = 0;
  for (float v : f) fNorm += double(v) * v;
  fNorm = std::sqrt(fNorm / double(std::max<size_t>(1, f.size())));
  PoissonReport rep;
  rep.relativeResidual = fNorm > 0 ? 1.0 : 0.0;
  for (int c = 0; c < maxCycles && fNorm > 0 && rep.relativeResidual > tolerance; ++c) {
    vCycle(levels, 0);
    rep.cycles = c + 1;
    rep.relativeResidual = rmsResidual(levels[0]) / fNorm;
    if (!std::isfinite(rep.relativeResidual)) break;
  }
  std::vector<float> u = std::move(levels[0].u);
  double mean = 0;
  for (float v : u) mean += v;
  mean /= double(std::max<size_t>(1, u.size()));
  for (float& v : u) v -= float(mean);
  if (report) *report = rep;
  return u;
}

}  // namespace inlay
