#include "inlay/lighting/decompose.h"

#include "inlay/lighting/poisson.h"

#include <tbb/blocked_range.h>
#include "inlay/modeling/parallel.h"
#include "inlay/modeling/vectorize.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace inlay {

namespace {

using Clock = std::chrono::steady_clock;

template <class F>
void forRows(int H, F&& f) {
  parallelFor(tbb::blocked_range<int>(0, H, 16), [&](const tbb::blocked_range<int>& r) {
    for (int y = r.begin(); y < r.end(); ++y) f(y);
  });
}

// Offsets of a pixel's four neighbours in a row-major plane; 0 where the neighbour is outside the
// image, so that its difference to the pixel is 0 (the Neumann boundary of decompose.h's
// Laplacian and gradients).
struct Around {
  ptrdiff_t l, r, u, d;
};

inline Around aroundPixel(int W, int H, int x, int y) {
  return {x > 0 ? -1 : 0, x + 1 < W ? 1 : 0, y > 0 ? -ptrdiff_t(W) : 0, y + 1 < H ? ptrdiff_t(W) : 0};
}

// f(i, Around) for every pixel of row y: the first and last columns apart, so that the interior's
// loop has constant offsets (and vectorises).
template <class F>
INLAY_INLINE inline void forRowPixels(int W, int H, int y, F&& f) {
  const size_t row = size_t(y) * size_t(W);
  if (W < 3) {
    for (int x = 0; x < W; ++x) f(row + size_t(x), aroundPixel(W, H, x, y));
    return;
  }
  const Around first = aroundPixel(W, H, 0, y), last = aroundPixel(W, H, W - 1, y);
  const Around inner{-1, 1, first.u, first.d};
  f(row, first);
  INLAY_IVDEP
  for (size_t i = row + 1; i + 1 < row + size_t(W); ++i) f(i, inner);
  f(row + size_t(W) - 1, last);
}

// The 5-point Laplacian of u at pixel i.
INLAY_INLINE inline float lap(const float* u, size_t i, Around a) {
  const float c = u[i];
  return (u[i + a.l] - c) + (u[i + a.r] - c) + (u[i + a.u] - c) + (u[i + a.d] - c);
}

inline float lap(const std::vector<float>& u, size_t i, Around a) { return lap(u.data(), i, a); }

// What the smooth part's gradient reads besides x: Gamma, Lap B, the edge masks and the weights.
struct SmoothPart {
  const float *G, *lapB, *mx, *my;
  float g1x2, g3x2;
};

// Gradient of the smooth part (the g1 and g3 terms) at `xs`, pixel i.
INLAY_INLINE inline float smoothGradient(const SmoothPart& f, const float* xs, size_t i, Around a) {
  const float xi = xs[i], gxi = f.G[i] * xi;
  const float smooth = f.mx[i + a.l] * (xi - xs[i + a.l]) + f.mx[i] * (xi - xs[i + a.r]) +
                       f.my[i + a.u] * (xi - xs[i + a.u]) + f.my[i] * (xi - xs[i + a.d]);
  // Lap(Gamma x - B) = Lap(Gamma x) - Lap B
  const float lapGx = (f.G[i + a.l] * xs[i + a.l] - gxi) + (f.G[i + a.r] * xs[i + a.r] - gxi) +
                      (f.G[i + a.u] * xs[i + a.u] - gxi) + (f.G[i + a.d] * xs[i + a.d] - gxi);
  return f.g1x2 * smooth - f.g3x2 * f.G[i] * (lapGx - f.lapB[i]);
}

}  // namespace

ImageF retinexReflectance(const ImageF& img, const std::vector<uint8_t>& valid,
                          const RetinexOptions& opt) {
  const int W = img.width, H = img.height;
  INLAY_CHECK(img.channels >= 3 && valid.size() == img.pixelCount());
  const size_t N = img.pixelCount();
  std::vector<float> logI(N, 0.f);
  std::vector<std::array<float, 3>> chroma(N, {1.f / 3, 1.f / 3, 1.f / 3});
  forRows(H, [&](int y) {
    for (int x = 0; x < W; ++x) {
      const size_t i = size_t(y) * W + x;
      if (!valid[i]) continue;
      const float* p = img.pixel(x, y);
      const float r = std::max(p[0], 0.f), g = std::max(p[1], 0.f), b = std::max(p[2], 0.f);
      const float sum = r + g + b;
      logI[i] = std::log(std::max(sum / 3.f, 1e-6f));
      if (sum > 1e-9f) chroma[i] = {r / sum, g / sum, b / sum};
    }
  });
  // A derivative is kept (reflectance) when the chromaticity or the intensity jumps.
  auto keep = [&](size_t a, size_t b) -> float {
    if (!valid[a] || !valid[b]) return 0.f;
    const float dl = logI[b] - logI[a];
    const float d0 = chroma[b][0] - chroma[a][0], d1 = chroma[b][1] - chroma[a][1],
                d2 = chroma[b][2] - chroma[a][2];
    const float dc2 = d0 * d0 + d1 * d1 + d2 * d2;
    const float ct = float(opt.chromaThreshold);
    return (std::abs(dl) > opt.intensityThreshold || dc2 > ct * ct) ? dl : 0.f;
  };
  // Kept derivative on the edge to the right (kx) and below (ky) of each pixel, then their
  // divergence (each edge evaluated once).
  std::vector<float> kx(N, 0.f), ky(N, 0.f);
  forRows(H, [&](int y) {
    for (int x = 0; x < W; ++x) {
      const size_t i = size_t(y) * W + x;
      if (x + 1 < W) kx[i] = keep(i, i + 1);
      if (y + 1 < H) ky[i] = keep(i, i + size_t(W));
    }
  });
  std::vector<float> div(N, 0.f);
  forRows(H, [&](int y) {
    for (int x = 0; x < W; ++x) {
      const size_t i = size_t(y) * W + x;
      float d = kx[i] + ky[i];
      if (x > 0) d -= kx[i - 1];
      if (y > 0) d -= ky[i - size_t(W)];
      div[i] = d;
    }
  });
  kx = {}, ky = {};
  std::vector<float> r = poissonNeumannMultigrid(div, W, H, 1e-4);
  double mean = 0, n = 0;
  for (size_t i = 0; i < N; ++i)
    if (valid[i]) mean += r[i], n += 1;
  mean = n > 0 ? mean / n : 0;
  ImageF out(W, H, 3, 0.f);
  forRows(H, [&](int y) {
    for (int x = 0; x < W; ++x) {
      const size_t i = size_t(y) * W + x;
      const float e = std::exp(std::clamp(float(r[i] - mean), -30.f, 30.f));
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = e * 3.f * chroma[i][size_t(c)];
    }
  });
  return out;
}

double pixelNoiseSigma(const ImageF& img, const std::vector<uint8_t>& use) {
  const int W = img.width, H = img.height;
  if (W < 3 || H < 3 || img.channels < 3 || use.size() != img.pixelCount()) return 0;
  std::vector<std::vector<float>> rows(static_cast<size_t>(H));
  forRows(H, [&](int y) {
    if (y == 0 || y + 1 == H) return;
    for (int x = 1; x + 1 < W; ++x) {
      bool all = true;
      for (int dy = -1; dy <= 1 && all; ++dy)
        for (int dx = -1; dx <= 1 && all; ++dx) all = use[size_t(y + dy) * W + x + dx] != 0;
      if (!all) continue;
      for (int c = 0; c < 3; ++c) {
        // [1 -2 1; -2 4 -2; 1 -2 1]: zero on planes, sqrt(36) times the noise on white noise.
        const auto v = [&](int dx, int dy) { return img.at(x + dx, y + dy, c); };
        const float r = v(-1, -1) + v(1, -1) + v(-1, 1) + v(1, 1) -
                        2 * (v(0, -1) + v(-1, 0) + v(1, 0) + v(0, 1)) + 4 * v(0, 0);
        if (std::isfinite(r)) rows[size_t(y)].push_back(std::abs(r));
      }
    }
  });
  std::vector<float> all;
  for (auto& r : rows) all.insert(all.end(), r.begin(), r.end());
  if (all.size() < 16 * 3) return 0;
  // The median: edges (a minority of pixels) do not count as noise.
  std::nth_element(all.begin(), all.begin() + long(all.size() / 2), all.end());
  return double(all[all.size() / 2]) / (0.6745 * 6);
}

namespace {

// The solver's inputs checked: sizes, masks and weights (decomposeIntrinsic's contract).
std::optional<Error> checkSolverInput(const ImageF& photo, const ImageF& gathered, const ImageF& rho0,
                                      const std::vector<uint8_t>& valid,
                                      const std::vector<uint8_t>& clipped, const DecomposeOptions& opt) {
  const int W = photo.width, H = photo.height;
  if (W <= 0 || H <= 0 || photo.channels < 3) return Error{"", "photo", "the photo is empty"};
  if (gathered.width != W || gathered.height != H || gathered.channels < 3)
    return Error{"", "gathered", "Gamma must be W x H x 3 like the photo"};
  if (rho0.width != W || rho0.height != H || rho0.channels < 3)
    return Error{"", "rho0", "the starting albedo must be W x H x 3 like the photo"};
  const size_t N = photo.pixelCount();
  if (valid.size() != N) return Error{"", "valid", "the mask must have one entry per pixel"};
  if (!clipped.empty() && clipped.size() != N)
    return Error{"", "clipped", "the mask must be empty or have one entry per pixel"};
  for (double w : {opt.g1, opt.g2, opt.g3, opt.s, opt.c, opt.tolerance, opt.objectiveTolerance})
    if (!std::isfinite(w) || w < 0) return Error{"", "options", "weights must be finite and >= 0"};
  if (!(opt.unitsPerWhite > 0) || !std::isfinite(opt.unitsPerWhite))
    return Error{"", "options.unitsPerWhite", "must be a positive number"};
  return std::nullopt;
}

// The photo's linear value that is one unit of B and Gamma in the objective (kappa): the mean
// gathered irradiance of the valid pixels (normaliseByMeanGamma), over the units per white
// (unitsPerWhite, or one per standard deviation of the photo's noise, unitsFromNoise).
double objectiveUnit(const ImageF& photo, const ImageF& gathered, const std::vector<uint8_t>& valid,
                     const std::vector<uint8_t>& clipped, const DecomposeOptions& opt) {
  const int W = photo.width, H = photo.height;
  const size_t N = photo.pixelCount();
  double kappa = 1;
  if (opt.normaliseByMeanGamma) {
    double sum = 0, n = 0;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        if (valid[size_t(y) * W + x])
          for (int c = 0; c < 3; ++c) {
            const float g = gathered.at(x, y, c);
            if (std::isfinite(g) && g > 0) sum += g;
            n += 1;
          }
    if (n > 0 && sum / n > 1e-12) kappa = sum / n;
  }
  double units = opt.unitsPerWhite;
  if (opt.unitsFromNoise) {
    // Noise of the measured pixels only: clipped ones are flat at the clip level.
    std::vector<uint8_t> measured(valid);
    for (size_t i = 0; i < N && !clipped.empty(); ++i) measured[i] = measured[i] && !clipped[i];
    const double sigma = pixelNoiseSigma(photo, measured) / kappa;  // in the photo's units
    if (sigma > 0 && std::isfinite(sigma)) units = std::min(units, 1 / sigma);
  }
  return kappa / units;
}

// A start for the solver other than rho0: the albedo and the dual variable (W x H x 3).
struct WarmStart {
  ImageF albedo, dual;
};

// The primal-dual (Condat-Vu) solve of the objective in decompose.h, per channel plane, in the
// objective's units: the planes, the edge masks and the steps, then iterations until the
// residuals or the objective settle.
class PrimalDualSolver {
 public:
  PrimalDualSolver(int width, int height, double unit, const DecomposeOptions& options)
      : W(width), H(height), N(size_t(width) * size_t(height)), kappa(unit), opt(options) {}
  void load(const ImageF& photo, const ImageF& gathered, const ImageF& rho0,
            const std::vector<uint8_t>& valid, const std::vector<uint8_t>& clipped);
  void warmStart(const WarmStart& warm);
  void iterate(Decomposition& out, Clock::time_point t0);
  void writeLayers(Decomposition& out) const;
  ImageF dual() const;

 private:
  // Per channel planes (row-major, W x H).
  struct Plane {
    // lapB: the Laplacian of B (a constant of the smooth part's gradient); tau: the primal step.
    std::vector<float> B, G, lapB, x0, lo, hi, wg2, tau, x, y, xn, yn;
  };
  void edgeMasks();
  void chooseSteps();
  void diagonalSteps();
  SmoothPart smoothPart(const Plane& p) const {
    return {p.G.data(), p.lapB.data(), mx.data(), my.data(), g1x2, g3x2};
  }
  double objective() const;
  void step(Plane& p) const;
  void residuals(const Plane& p, double& pSum, double& dSum);

  const int W, H;
  const size_t N;
  const double kappa;
  const DecomposeOptions& opt;
  std::vector<Plane> P;
  std::vector<float> mx, my;                      // mask on the edge to the right / below
  std::vector<float> scratchPrimal, scratchDual;  // squared residuals per pixel (residuals())
  float gammaMax = 0;
  double sigma = 0;  // the dual step (the primal one is per pixel: Plane::tau)
  float sigmaF = 0, g1x2 = 0, g3x2 = 0;
};

// B and Gamma in the objective's units, the start x0 within its box [0, min(1, B / Gamma)]
// (no upper cap where B is clipped or not finite), the g2 weights; then the masks and steps.
void PrimalDualSolver::load(const ImageF& photo, const ImageF& gathered, const ImageF& rho0,
                            const std::vector<uint8_t>& valid, const std::vector<uint8_t>& clipped) {
  const float invK = float(1 / kappa);
  P.assign(3, Plane{});
  for (int c = 0; c < 3; ++c) {
    Plane& p = P[size_t(c)];
    p.B.resize(N), p.G.resize(N), p.x0.resize(N), p.hi.resize(N), p.wg2.resize(N), p.lo.assign(N, 0.f);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const size_t i = size_t(y) * W + x;
        float b = photo.at(x, y, c), g = gathered.at(x, y, c), r0 = rho0.at(x, y, c);
        const bool finite = std::isfinite(b) && std::isfinite(g);
        if (!std::isfinite(b)) b = 0;
        if (!std::isfinite(g)) g = 0;
        if (!std::isfinite(r0)) r0 = 0.5f;
        b = std::max(b, 0.f) * invK;
        g = std::max(g, 0.f) * invK;
        p.B[i] = b;
        p.G[i] = g;
        gammaMax = std::max(gammaMax, g);
        const bool lower = !finite || (!clipped.empty() && clipped[i]);
        float hi = 1;
        if (!lower && g > 0) hi = std::min(1.f, b / g);
        p.hi[i] = std::max(hi, 0.f);
        p.x0[i] = std::clamp(r0, 0.f, p.hi[i]);
        p.wg2[i] = (valid[i] && finite) ? float(2 * opt.g2) * g * g : 0.f;
        if (opt.holdInvalid && !valid[i]) p.lo[i] = p.hi[i] = p.x0[i];
      }
    p.x = p.x0;
    p.y.assign(N, 0.f);
    p.xn.assign(N, 0.f), p.yn.assign(N, 0.f), p.lapB.assign(N, 0.f);
    forRows(H, [&](int y) {
      forRowPixels(W, H, y, [&](size_t i, Around a) { p.lapB[i] = lap(p.B, i, a); });
    });
  }
  scratchPrimal.assign(N, 0.f), scratchDual.assign(N, 0.f);
  edgeMasks();
  chooseSteps();
}

// The smoothness mask per edge: a sigmoid of |grad B|^2 over the three channels.
void PrimalDualSolver::edgeMasks() {
  mx.assign(N, 0.f), my.assign(N, 0.f);
  forRows(H, [&](int y) {
    for (int x = 0; x < W; ++x) {
      const size_t i = size_t(y) * W + x;
      auto mask = [&](size_t j) {
        double g2 = 0;
        for (int c = 0; c < 3; ++c)
          g2 += std::pow(double(P[size_t(c)].B[j] - P[size_t(c)].B[i]) * kappa, 2);
        return float(1 - 1 / (1 + std::exp(-opt.s * (g2 - opt.c))));
      };
      if (x + 1 < W) mx[i] = mask(i + 1);
      if (y + 1 < H) my[i] = mask(i + size_t(W));
    }
  });
}

// Steps of the Condat-Vu iteration; it converges when T^-1 - Q / 2 - Lap^T sigma Lap is positive
// definite, T the primal steps, Q >= the smooth part's Hessian, |Lap^T Lap| <= 64.
void PrimalDualSolver::chooseSteps() {
  g1x2 = float(2 * opt.g1), g3x2 = float(2 * opt.g3);
  if (opt.diagonalSteps) {
    diagonalSteps();
    return;
  }
  // Scalar: tau Lf / 2 + tau sigma 64 <= 0.95 with Lf <= 16 g1 + 16 g3 max(Gamma)^2; the primal
  // step takes what the smooth part allows, the dual step the rest.
  const double Lf = 16 * opt.g1 + 16 * opt.g3 * double(gammaMax) * gammaMax;
  const double tau = std::min(0.9 / std::max(Lf, 1e-30), 1.0 / 16);
  sigma = 0.5 / (64 * tau);
  sigmaF = float(sigma);
  for (auto& p : P) p.tau.assign(N, float(tau));
}

// Diagonal step metrics (Pock & Chambolle 2011's preconditioning, extended to the smooth term):
// by Gershgorin's bounds (Q = diag(q), q_i the absolute row sum of the Hessian) a per-pixel step
// 1 / tau_i = (q_i / 2 + 64 sigma) / 0.95 satisfies the condition. The scalar step is set by
// the brightest pixel's q (max Gamma^2) and crawls where Gamma is small. sigma balances the
// dual step against the median pixel's primal one (64 sigma = median q / 2).
void PrimalDualSolver::diagonalSteps() {
  std::vector<double> q(3 * N);
  for (int c = 0; c < 3; ++c) {
    const Plane& p = P[size_t(c)];
    forRows(H, [&](int y) {
      for (int x = 0; x < W; ++x) {
        const size_t i = size_t(y) * W + x;
        double m = 0, degree = 0, gammaAround = 0;
        auto edge = [&](size_t j, float mask) { m += mask, degree += 1, gammaAround += p.G[j]; };
        if (x > 0) edge(i - 1, mx[i - 1]);
        if (x + 1 < W) edge(i + 1, mx[i]);
        if (y > 0) edge(i - size_t(W), my[i - size_t(W)]);
        if (y + 1 < H) edge(i + size_t(W), my[i]);
        const double g = p.G[i];
        q[size_t(c) * N + i] = 4 * opt.g1 * m + 2 * opt.g3 * g * (degree * g + gammaAround);
      }
    });
  }
  std::vector<double> sorted(q);
  std::nth_element(sorted.begin(), sorted.begin() + long(sorted.size() / 2), sorted.end());
  const double qMedian = sorted[sorted.size() / 2];
  // Without a smooth part the unpreconditioned balance: tau = sigma = 1 / 8.
  sigma = std::isfinite(qMedian) && qMedian > 1e-12 ? qMedian / 2 / 64 : 1.0 / 8;
  if (!std::isfinite(sigma)) sigma = 1.0 / 8;
  sigmaF = float(sigma);
  for (int c = 0; c < 3; ++c) {
    Plane& p = P[size_t(c)];
    p.tau.resize(N);
    for (size_t i = 0; i < N; ++i) {
      const double t = 0.95 / (q[size_t(c) * N + i] / 2 + 64 * sigma);
      p.tau[i] = std::isfinite(t) ? float(t) : 0.f;
    }
  }
}

// The objective at the current x, summed over the channels.
double PrimalDualSolver::objective() const {
  double f = 0;
  for (int c = 0; c < 3; ++c) {
    const Plane& p = P[size_t(c)];
    std::vector<double> rows(size_t(H), 0.0);
    forRows(H, [&](int y) {
      double s = 0;
      for (int x = 0; x < W; ++x) {
        const size_t i = size_t(y) * W + x;
        s += std::abs(lap(p.x, i, aroundPixel(W, H, x, y)));
        const double d = p.x[i] - p.x0[i];
        s += 0.5 * p.wg2[i] * d * d;
        const double Di = p.B[i] - p.G[i] * p.x[i];
        if (x + 1 < W) {
          const double gx = p.x[i + 1] - p.x[i];
          const double dD = (p.B[i + 1] - p.G[i + 1] * p.x[i + 1]) - Di;
          s += opt.g1 * mx[i] * gx * gx + opt.g3 * dD * dD;
        }
        if (y + 1 < H) {
          const size_t j = i + size_t(W);
          const double gy = p.x[j] - p.x[i];
          const double dD = (p.B[j] - p.G[j] * p.x[j]) - Di;
          s += opt.g1 * my[i] * gy * gy + opt.g3 * dD * dD;
        }
      }
      rows[size_t(y)] = s;
    });
    for (double r : rows) f += r;
  }
  return f;
}

// One iteration on one plane, two passes over it: the primal step (the smooth part's gradient and
// Lap^T y computed on the fly), then the dual step from the new and old x.
void PrimalDualSolver::step(Plane& p) const {
  const SmoothPart f = smoothPart(p);
  const float *x = p.x.data(), *y = p.y.data(), *tau = p.tau.data(), *wg2 = p.wg2.data();
  const float *x0 = p.x0.data(), *lo = p.lo.data(), *hi = p.hi.data();
  float *xn = p.xn.data(), *yn = p.yn.data();
  // Primal: x+ = prox_{tau g}(x - tau (grad f + Lap^T y)), g = box + g2 term.
  forRows(H, [&](int row) {
    forRowPixels(W, H, row, [&](size_t i, Around a) INLAY_INLINE {
      const float v = x[i] - tau[i] * (smoothGradient(f, x, i, a) + lap(y, i, a));
      const float w = tau[i] * wg2[i];
      xn[i] = std::min(std::max((v + w * x0[i]) / (1 + w), lo[i]), hi[i]);
    });
  });
  // Dual: y+ = clip(y + sigma Lap(2 x+ - x), -1, 1) (prox of the conjugate of |.|_1).
  const float s = sigmaF;
  forRows(H, [&](int row) {
    forRowPixels(W, H, row, [&](size_t i, Around a) INLAY_INLINE {
      yn[i] = std::min(std::max(y[i] + s * (2 * lap(xn, i, a) - lap(x, i, a)), -1.f), 1.f);
    });
  });
}

// Squared residuals of the last step (x -> xn, y -> yn) of the primal-dual iteration (Goldstein et
// al. 2013), with the smooth term's gradient change (Condat-Vu); the primal one times its
// per-pixel step. Per pixel into the scratch planes (a vectorised pass), then summed per row;
// added to pSum and dSum.
void PrimalDualSolver::residuals(const Plane& p, double& pSum, double& dSum) {
  const SmoothPart f = smoothPart(p);
  const float *x = p.x.data(), *y = p.y.data(), *xn = p.xn.data(), *yn = p.yn.data();
  const float *tau = p.tau.data(), invSigma = float(1 / sigma);
  float *sp = scratchPrimal.data(), *sd = scratchDual.data();
  std::vector<double> ps(size_t(H), 0.0), ds(size_t(H), 0.0);
  forRows(H, [&](int row) {
    forRowPixels(W, H, row, [&](size_t i, Around a) INLAY_INLINE {
      const float dly = lap(y, i, a) - lap(yn, i, a);
      const float dgf = smoothGradient(f, x, i, a) - smoothGradient(f, xn, i, a);
      const float rp = (x[i] - xn[i]) - tau[i] * (dly + dgf);
      const float rd = (y[i] - yn[i]) * invSigma - (lap(x, i, a) - lap(xn, i, a));
      sp[i] = rp * rp, sd[i] = rd * rd;
    });
    double sumP = 0, sumD = 0;
    for (size_t i = size_t(row) * size_t(W); i < size_t(row + 1) * size_t(W); ++i)
      sumP += sp[i], sumD += sd[i];
    ps[size_t(row)] = sumP, ds[size_t(row)] = sumD;
  });
  for (int row = 0; row < H; ++row) pSum += ps[size_t(row)], dSum += ds[size_t(row)];
}

// The objective's decrease still to come per pixel and channel, extrapolated from the last two
// decreases in `history` as a geometric series (ratio r = last / previous: r / (1 - r) times the
// last); infinite while the objective rises or its decrease does not shrink.
double remainingDecrease(const std::vector<DecomposeSample>& history, size_t values) {
  const size_t n = history.size();
  if (n < 3 || values == 0) return INFINITY;
  const double previous = history[n - 3].objective - history[n - 2].objective;
  const double last = history[n - 2].objective - history[n - 1].objective;
  if (last == 0 && previous == 0) return 0;
  if (!(last >= 0) || !(last < previous)) return INFINITY;
  const double r = last / previous;
  return last * r / (1 - r) / double(values);
}

// Iterates until converged (residuals, a flat objective or its estimated gap), the cap,
// non-finite residuals or cancellation; fills out's history, iterations, converged and report.
void PrimalDualSolver::iterate(Decomposition& out, Clock::time_point t0) {
  auto seconds = [&] { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  const int every = std::max(1, opt.historyEvery);
  double primal = INFINITY, dual = INFINITY;
  std::string stopReason = "the iteration cap";
  const char* convergedBy = "";
  for (int it = 1; it <= std::max(1, opt.maxIterations); ++it) {
    const bool record = (it % every == 0) || it == opt.maxIterations;
    double pSum = 0, dSum = 0;
    for (auto& p : P) {
      step(p);
      if (record) residuals(p, pSum, dSum);
      std::swap(p.x, p.xn);
      std::swap(p.y, p.yn);
    }
    out.iterations = it;
    if (record) {
      primal = std::sqrt(pSum / (3.0 * N));  // already times the steps
      dual = sigma * std::sqrt(dSum / (3.0 * N));
      const double f = objective();
      const double fPrev = out.history.empty() ? INFINITY : out.history.back().objective;
      out.history.push_back({seconds(), it, f, primal, dual});
      if (!std::isfinite(primal) || !std::isfinite(dual) || !std::isfinite(f)) {
        stopReason = "non-finite residuals";
        break;
      }
      const bool residualsSmall = primal < opt.tolerance && dual < opt.tolerance;
      const bool objectiveFlat = std::abs(fPrev - f) <= opt.objectiveTolerance * std::abs(f);
      const bool gapSmall = opt.gapTolerance > 0 &&
                            2 * remainingDecrease(out.history, 3 * N) <= opt.gapTolerance;
      if (it >= opt.minIterations && (residualsSmall || objectiveFlat || gapSmall)) {
        out.converged = true;
        convergedBy = residualsSmall ? "residuals" : objectiveFlat ? "objective" : "objective gap";
        break;
      }
    }
    if (opt.cancel && opt.cancel->shouldStop()) {
      stopReason = "cancellation";
      break;
    }
  }
  if (out.history.empty() || out.history.back().iteration != out.iterations) {
    // The last state is always in the history (residuals from the last recorded step).
    out.history.push_back({seconds(), out.iterations, objective(), primal, dual});
  }
  char buf[256];
  if (out.converged)
    std::snprintf(buf, sizeof buf,
                  "converged (%s) after %d iterations (%.2f s): primal residual %.2e, dual %.2e, "
                  "tolerance %.1e, objective change tolerance %.1e, gap tolerance %.1e per value",
                  convergedBy, out.iterations, seconds(), primal, dual, opt.tolerance,
                  opt.objectiveTolerance, opt.gapTolerance);
  else
    std::snprintf(buf, sizeof buf,
                  "not converged: stopped by %s after %d iterations (%.2f s): primal residual "
                  "%.2e, dual %.2e, tolerance %.1e",
                  stopReason.c_str(), out.iterations, seconds(), primal, dual, opt.tolerance);
  out.report = buf;
}

// The albedo (the start where x is not finite) and D = B - Gamma rho back in the photo's units.
void PrimalDualSolver::writeLayers(Decomposition& out) const {
  out.albedo = ImageF(W, H, 3, 0.f);
  out.direct = ImageF(W, H, 3, 0.f);
  for (int c = 0; c < 3; ++c) {
    const Plane& p = P[size_t(c)];
    forRows(H, [&](int y) {
      for (int x = 0; x < W; ++x) {
        const size_t i = size_t(y) * W + x;
        const float r = std::isfinite(p.x[i]) ? p.x[i] : p.x0[i];
        out.albedo.at(x, y, c) = r;
        out.direct.at(x, y, c) = std::max(0.f, float((p.B[i] - p.G[i] * r) * kappa));
      }
    });
  }
}

ImageF PrimalDualSolver::dual() const {
  ImageF out(W, H, 3, 0.f);
  for (int c = 0; c < 3; ++c)
    for (size_t i = 0; i < N; ++i) out.data[i * 3 + size_t(c)] = P[size_t(c)].y[i];
  return out;
}

void PrimalDualSolver::warmStart(const WarmStart& warm) {
  for (int c = 0; c < 3; ++c) {
    Plane& p = P[size_t(c)];
    for (size_t i = 0; i < N; ++i) {
      const float a = warm.albedo.data[i * 3 + size_t(c)], d = warm.dual.data[i * 3 + size_t(c)];
      if (std::isfinite(a)) p.x[i] = std::clamp(a, p.lo[i], p.hi[i]);
      if (std::isfinite(d)) p.y[i] = std::clamp(d, -1.f, 1.f);
    }
  }
}

// Largest albedo a pixel allows: 1, and rho * Gamma <= B where B is a measurement (not clipped).
float albedoCap(float b, float g, bool clippedPixel) {
  if (clippedPixel || !std::isfinite(b) || !std::isfinite(g) || !(g > 0)) return 1.f;
  return std::clamp(b / g, 0.f, 1.f);
}

// Box average of f x f blocks; `use` (may be empty) picks the samples, all when none is used.
ImageF boxDown(const ImageF& img, int f, const std::vector<uint8_t>& use) {
  const int W = img.width, H = img.height, w = (W + f - 1) / f, h = (H + f - 1) / f;
  ImageF out(w, h, 3, 0.f);
  forRows(h, [&](int by) {
    for (int bx = 0; bx < w; ++bx)
      for (int pass = 0; pass < 2; ++pass) {
        double sum[3] = {0, 0, 0}, n = 0;
        for (int y = by * f; y < std::min(H, (by + 1) * f); ++y)
          for (int x = bx * f; x < std::min(W, (bx + 1) * f); ++x) {
            if (pass == 0 && !use.empty() && !use[size_t(y) * W + x]) continue;
            const float* p = img.pixel(x, y);
            if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) continue;
            for (int c = 0; c < 3; ++c) sum[c] += std::max(p[c], 0.f);
            n += 1;
          }
        if (n == 0) continue;
        for (int c = 0; c < 3; ++c) out.at(bx, by, c) = float(sum[c] / n);
        break;
      }
  });
  return out;
}

// Mask of f x f blocks: set where at least half the block's pixels are.
std::vector<uint8_t> maskDown(const std::vector<uint8_t>& m, int W, int H, int f) {
  const int w = (W + f - 1) / f, h = (H + f - 1) / f;
  std::vector<uint8_t> out(size_t(w) * h, 0);
  if (m.empty()) return {};
  for (int by = 0; by < h; ++by)
    for (int bx = 0; bx < w; ++bx) {
      int on = 0, n = 0;
      for (int y = by * f; y < std::min(H, (by + 1) * f); ++y)
        for (int x = bx * f; x < std::min(W, (bx + 1) * f); ++x) on += m[size_t(y) * W + x] != 0, ++n;
      out[size_t(by) * w + bx] = 2 * on >= n;
    }
  return out;
}

// `blocks` (one value per f x f block of a larger image) bilinearly interpolated at the centre of
// that image's pixel (x, y), channel c.
float interpolateBlocks(const ImageF& blocks, int f, int x, int y, int c) {
  const int w = blocks.width, h = blocks.height;
  const double fy = std::clamp((y + 0.5) / f - 0.5, 0.0, double(h - 1));
  const double fx = std::clamp((x + 0.5) / f - 0.5, 0.0, double(w - 1));
  const int y0 = int(fy), y1 = std::min(y0 + 1, h - 1), x0 = int(fx), x1 = std::min(x0 + 1, w - 1);
  const float ay = float(fy - y0), ax = float(fx - x0);
  return (1 - ay) * ((1 - ax) * blocks.at(x0, y0, c) + ax * blocks.at(x1, y0, c)) +
         ay * ((1 - ax) * blocks.at(x0, y1, c) + ax * blocks.at(x1, y1, c));
}

// `blocks` interpolated over a W x H image (interpolateBlocks).
ImageF upsample(const ImageF& blocks, int W, int H, int f) {
  ImageF out(W, H, 3, 0.f);
  forRows(H, [&](int y) {
    for (int x = 0; x < W; ++x)
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = interpolateBlocks(blocks, f, x, y, c);
  });
  return out;
}

// The albedo change the solver made on f x f block means (against the start as it clamped it),
// per block.
ImageF blockChange(const ImageF& albedoS, const ImageF& Bs, const ImageF& Gs, const ImageF& r0s,
                   const std::vector<uint8_t>& clippedS) {
  const int w = Bs.width, h = Bs.height;
  ImageF change(w, h, 3, 0.f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const bool lower = !clippedS.empty() && clippedS[size_t(y) * w + x];
        const float start =
            std::clamp(r0s.at(x, y, c), 0.f, albedoCap(Bs.at(x, y, c), Gs.at(x, y, c), lower));
        change.at(x, y, c) = albedoS.at(x, y, c) - start;
      }
  return change;
}

struct LevelResult {
  Decomposition out;
  ImageF dual;
  int coarseIterations = 0, coarseLevels = 0;
};

// One level of the pyramid: the level below (2 x 2 block means, g2 x 4 so that the objective
// approximates the same continuous one) solved first, its albedo change and dual variable
// carried up as the start.
LevelResult solveLevel(const ImageF& photo, const ImageF& gathered, const ImageF& rho0,
                       const std::vector<uint8_t>& valid, const std::vector<uint8_t>& clipped,
                       const DecomposeOptions& opt, double kappa, int levels, Clock::time_point t0) {
  const int W = photo.width, H = photo.height;
  LevelResult r;
  std::optional<WarmStart> warm;
  if (levels > 0 && std::min(W, H) >= 64) {
    const ImageF Bs = boxDown(photo, 2, valid), Gs = boxDown(gathered, 2, valid);
    const ImageF r0s = boxDown(rho0, 2, {});
    const std::vector<uint8_t> validS = maskDown(valid, W, H, 2), clippedS = maskDown(clipped, W, H, 2);
    DecomposeOptions coarseOpt = opt;
    coarseOpt.g2 *= 4;
    coarseOpt.maxIterations = std::min(opt.maxIterations, opt.coarseIterations);
    LevelResult c = solveLevel(Bs, Gs, r0s, validS, clippedS, coarseOpt, kappa, levels - 1, t0);
    const ImageF change = upsample(blockChange(c.out.albedo, Bs, Gs, r0s, clippedS), W, H, 2);
    warm.emplace();
    warm->albedo = rho0;
    for (size_t i = 0; i < warm->albedo.data.size(); ++i) {
      const float a = std::isfinite(rho0.data[i]) ? rho0.data[i] : 0.5f;
      warm->albedo.data[i] = a + change.data[i];
    }
    warm->dual = upsample(c.dual, W, H, 2);
    r.coarseIterations = c.coarseIterations + c.out.iterations;
    r.coarseLevels = c.coarseLevels + 1;
  }
  PrimalDualSolver solver(W, H, kappa, opt);
  solver.load(photo, gathered, rho0, valid, clipped);
  if (warm) solver.warmStart(*warm);
  solver.iterate(r.out, t0);
  solver.writeLayers(r.out);
  r.dual = solver.dual();
  return r;
}

// The solver at the photo's own resolution (decomposeIntrinsic checks the input first).
Expected<Decomposition> solveAtFullResolution(const ImageF& photo, const ImageF& gathered,
                                              const ImageF& rho0, const std::vector<uint8_t>& valid,
                                              const std::vector<uint8_t>& clipped,
                                              const DecomposeOptions& opt) {
  const auto t0 = Clock::now();
  if (auto error = checkSolverInput(photo, gathered, rho0, valid, clipped, opt)) return *error;
  const double kappa = objectiveUnit(photo, gathered, valid, clipped, opt);
  LevelResult r =
      solveLevel(photo, gathered, rho0, valid, clipped, opt, kappa, std::max(0, opt.pyramidLevels), t0);
  if (r.coarseLevels > 0) {
    char buf[96];
    std::snprintf(buf, sizeof buf, " (started from %d coarser levels: %d iterations there)",
                  r.coarseLevels, r.coarseIterations);
    r.out.report += buf;
  }
  r.out.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return std::move(r.out);
}

}  // namespace

std::atomic<uint64_t> gDecompositionRuns{0};

uint64_t decompositionRuns() { return gDecompositionRuns.load(); }

Expected<Decomposition> decomposeIntrinsic(const ImageF& photo, const ImageF& gathered,
                                           const ImageF& rho0, const std::vector<uint8_t>& valid,
                                           const std::vector<uint8_t>& clipped,
                                           const DecomposeOptions& opt) {
  gDecompositionRuns.fetch_add(1);
  const int W = photo.width, H = photo.height;
  const size_t N = photo.pixelCount();
  const int f = opt.maxSolvePixels > 0 && N > size_t(opt.maxSolvePixels)
                    ? int(std::ceil(std::sqrt(double(N) / double(opt.maxSolvePixels))))
                    : 1;
  if (f <= 1 || gathered.width != W || gathered.height != H || rho0.width != W || rho0.height != H ||
      valid.size() != N || (!clipped.empty() && clipped.size() != N) || photo.channels < 3 ||
      gathered.channels < 3 || rho0.channels < 3)
    return solveAtFullResolution(photo, gathered, rho0, valid, clipped, opt);
  // A large photo: the solver runs on f x f block means, and its change to the start is carried
  // back bilinearly onto the full-resolution start (which keeps the photo's fine texture), then
  // held to the full-resolution constraints.
  const auto t0 = Clock::now();
  const ImageF Bs = boxDown(photo, f, valid), Gs = boxDown(gathered, f, valid);
  const ImageF r0s = boxDown(rho0, f, {});
  const std::vector<uint8_t> validS = maskDown(valid, W, H, f), clippedS = maskDown(clipped, W, H, f);
  auto small = solveAtFullResolution(Bs, Gs, r0s, validS, clippedS, opt);
  if (!small) return small;
  const ImageF change = blockChange(small->albedo, Bs, Gs, r0s, clippedS);
  Decomposition out;
  out.history = std::move(small->history);
  out.iterations = small->iterations;
  out.converged = small->converged;
  out.albedo = ImageF(W, H, 3, 0.f);
  out.direct = ImageF(W, H, 3, 0.f);
  forRows(H, [&](int y) {
    for (int x = 0; x < W; ++x) {
      const bool lower = !clipped.empty() && clipped[size_t(y) * W + x];
      for (int c = 0; c < 3; ++c) {
        float b = photo.at(x, y, c), g = gathered.at(x, y, c), r = rho0.at(x, y, c);
        const float cap = albedoCap(b, g, lower);
        r = std::clamp((std::isfinite(r) ? r : 0.5f) + interpolateBlocks(change, f, x, y, c), 0.f, cap);
        b = std::isfinite(b) ? std::max(b, 0.f) : 0.f;
        g = std::isfinite(g) ? std::max(g, 0.f) : 0.f;
        out.albedo.at(x, y, c) = r;
        out.direct.at(x, y, c) = std::max(0.f, b - g * r);
      }
    }
  });
  out.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  char buf[96];
  std::snprintf(buf, sizeof buf, " (solved on %dx%d blocks of the %dx%d photo)", f, f, W, H);
  out.report = small->report + buf;
  return out;
}

}  // namespace inlay
