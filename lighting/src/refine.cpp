#include "inlay/lighting/refine.h"

#include "inlay/lighting/estimate.h"

#include "inlay/render/path_tracer.h"

#include <Eigen/Dense>
#include <ceres/ceres.h>
#include <tbb/blocked_range.h>
#include "inlay/modeling/parallel.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>

namespace inlay {

namespace {

using Clock = std::chrono::steady_clock;

// One pixel of the reduced grid: the room point it shows and what the photo says there.
struct GridPixel {
  int x = 0, y = 0;  // in the direct-light image
  Vec3 point, normal;
  Vec3 rho, target;
  double weight = 0;  // alpha_i / Z
  uint32_t seed = 0;
};

// A light free to move: its box bounds in normalised room units and which axes can move.
struct FreeLight {
  int index = 0;
  Vec3 lo, hi;  // bounds of the normalised centre
  Vec3 start;   // normalised centre at the start (after moving it into the room)
  std::vector<int> fixedAxes;
  bool size = false;         // its two edge lengths are parameters too (LightRefineSpec::refineSize)
  double logScaleBound = 0;  // |log scale| <= this
  int dims() const { return size ? 5 : 3; }
  double lower(int a) const { return a < 3 ? lo[a] : -logScaleBound; }
  double upper(int a) const { return a < 3 ? hi[a] : logScaleBound; }
  double startOf(int a) const { return a < 3 ? start[a] : 0.0; }
};

// A free light's parameters: normalised centre, and log scale factors of its two edges (zero
// unless its size is refined).
struct Pose {
  Vec3 centre = Vec3::Zero();
  Vec2 logScale = Vec2::Zero();
  double operator[](int a) const { return a < 3 ? centre[a] : logScale[a - 3]; }
  double& operator[](int a) { return a < 3 ? centre[a] : logScale[a - 3]; }
};

// Light `L` moved to centre `centre` with its edges scaled by exp(logScale): the offsets of its
// corners from its centre along its first edge by the first factor, the rest by the second.
AreaLight posedLight(const AreaLight& L, const Vec3& centre, const Vec2& logScale) {
  AreaLight out = L;
  const Vec3 c = L.centre();
  const Vec3 u = (L.cornersWorld[1] - L.cornersWorld[0]).normalized();
  const double su = std::exp(logScale[0]), sv = std::exp(logScale[1]);
  for (size_t i = 0; i < 4; ++i) {
    const Vec3 d = L.cornersWorld[i] - c, du = d.dot(u) * u;
    out.cornersWorld[i] = centre + su * du + sv * (d - du);
  }
  return out;
}

// The refinement problem: positions in, residuals out (intensities solved inside).
class Refinement {
 public:
  Refinement(const RoomTracer& tracer, std::vector<GridPixel> px, std::vector<AreaLight> lights,
             const std::vector<LightRefineSpec>& specs, std::vector<SunLight> suns,
             std::vector<std::vector<Vec3>> sunE, const LightRefineOptions& opt, const Vec3& boxLo,
             const Vec3& boxSize)
      : tracer_(tracer),
        px_(std::move(px)),
        lights_(std::move(lights)),
        specs_(specs),
        suns_(std::move(suns)),
        sunE_(std::move(sunE)),
        opt_(opt),
        boxLo_(boxLo),
        boxSize_(boxSize) {
    const size_t J = lights_.size();
    cache_.resize(J);
    for (size_t j = 0; j < J; ++j) {
      // Intensities: unknown unless locked.
      if (!specs_[j].lock) unknownLights_.push_back(int(j));
      Vec3 s = lights_[j].radiance.cwiseMax(0.0);
      scale_.push_back(std::max(s.maxCoeff(), 1e-9) * opt_.intensityRange);
      start_.push_back(s);
    }
    unknownAreaLights_ = unknownLights_.size();
    // Suns: their strength is unknown too (unless opt.refineSuns is off); only their direction
    // and beam are given. Their direct patch is mostly clipped, but they light the rest of the
    // room by that patch's bounce (sunE includes it), which the photo does show.
    for (size_t k = 0; k < suns_.size() && opt_.refineSuns; ++k) {
      unknownLights_.push_back(int(J + k));
      const Vec3 s = suns_[k].irradianceOverPi.cwiseMax(0.0);
      scale_.push_back(std::max(s.maxCoeff(), 1e-9) * opt_.intensityRange);
      start_.push_back(s);
    }
    // Locked lights do not move: their light is a constant part of the render (so are the
    // suns when their strength is kept).
    fixed_.assign(px_.size(), Vec3::Zero());
    for (size_t k = 0; k < suns_.size() && !opt_.refineSuns; ++k)
      for (size_t i = 0; i < px_.size(); ++i)
        fixed_[i] += sunE_[k][i].cwiseProduct(suns_[k].irradianceOverPi.cwiseMax(0.0));
    for (size_t j = 0; j < J; ++j)
      if (specs_[j].lock) {
        const auto& e = irradiance(int(j), lights_[j].centre());
        for (size_t i = 0; i < px_.size(); ++i) fixed_[i] += e[i] * lights_[j].radiance;
      }
  }

  size_t unknownCount() const { return unknownLights_.size(); }
  size_t residualCount() const {
    size_t n = 3 * px_.size() + 3 * unknownCount();
    for (const FreeLight& f : free_) n += size_t(f.dims());
    return n;
  }
  int evaluations() const { return evaluations_; }
  size_t lightCount() const { return lights_.size(); }
  // Data weights become alpha_i / Z.
  void normaliseData(double Z) {
    for (auto& p : px_) p.weight /= Z;
  }
  // sum_i alpha_i |R_i|^2 of the lights as they come in.
  double startRenderEnergy() {
    std::vector<Vec3> shading(px_.size(), Vec3::Zero());
    for (size_t j = 0; j < lights_.size(); ++j) {
      const auto& e = irradiance(int(j), lights_[j].centre());
      for (size_t i = 0; i < px_.size(); ++i) shading[i] += e[i] * lights_[j].radiance;
    }
    for (size_t k = 0; k < suns_.size(); ++k)
      for (size_t i = 0; i < px_.size(); ++i)
        shading[i] += sunE_[k][i].cwiseProduct(suns_[k].irradianceOverPi);
    double z = 0;
    for (size_t i = 0; i < px_.size(); ++i)
      z += px_[i].weight * px_[i].rho.cwiseProduct(shading[i]).squaredNorm();
    return z;
  }
  Vec3 startCentre(int j) const { return lights_[size_t(j)].centre(); }
  // The light whose intensity is unknown u: area lights 0..J-1, then suns J + k.
  size_t unknownTarget(size_t u) const { return size_t(unknownLights_[u]); }
  // Whether unknown u is a sun's strength.
  bool unknownIsSun(size_t u) const { return u >= unknownAreaLights_; }

  Vec3 centreOf(const Vec3& normalised) const { return boxLo_ + normalised.cwiseProduct(boxSize_); }
  Vec3 normalisedOf(const Vec3& centre) const { return (centre - boxLo_).cwiseQuotient(boxSize_); }

  // E of light j (unit radiance) at every grid pixel with its centre at `centre`; the last
  // position per light is cached (Ceres asks for the Jacobian where it evaluated last).
  // Two positions per light are kept: a rejected trial step does not evict the current point.
  const std::vector<double>& irradiance(int j, const Vec3& centre, const Vec2& logScale = Vec2::Zero()) {
    auto& slots = cache_[size_t(j)];
    for (auto& s : slots)
      if (s.centre == centre && s.logScale == logScale) return s.E;
    slots[1] = std::move(slots[0]);
    slots[0].E = irradianceUncached(j, centre, logScale);
    slots[0].centre = centre;
    slots[0].logScale = logScale;
    return slots[0].E;
  }

  std::vector<double> irradianceUncached(int j, const Vec3& centre,
                                         const Vec2& logScale = Vec2::Zero()) {
    const AreaLight L = posedLight(lights_[size_t(j)], centre, logScale);
    std::vector<double> e(px_.size(), 0.0);
    parallelFor(tbb::blocked_range<size_t>(0, px_.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i < r.end(); ++i) {
        const GridPixel& p = px_[i];
        e[i] = tracer_.unitLightIrradianceOverPi(L, p.point + 1e-5 * p.normal, p.normal,
                                                 opt_.samplesPerLight, p.seed * 131u + uint32_t(j));
      }
    });
    ++evaluations_;
    return e;
  }

  // Residuals for the given irradiance of each moving light (others from the cache):
  // intensities by NNLS, then the weighted data residuals and the priors. `radiance` receives
  // the solved intensities of the unlocked lights when not null.
  void residuals(const std::vector<const std::vector<double>*>& lightE, const std::vector<Pose>& poses,
                 double* r, std::vector<Vec3>* radiance = nullptr) const {
    const size_t U = unknownCount(), N = px_.size();
    // Unit shading of unknown u at pixel i, channel c.
    auto column = [&](size_t u, size_t i, int c) {
      const size_t t = unknownTarget(u);
      return unknownIsSun(u) ? sunE_[t - lights_.size()][i][c] : (*lightE[t])[i];
    };
    std::vector<Vec3> L(U, Vec3::Zero());
    for (int c = 0; c < 3; ++c) {
      std::vector<double> M(U * U, 0.0), q(U, 0.0);
      for (size_t i = 0; i < N; ++i) {
        const GridPixel& p = px_[i];
        const double b = p.target[c] - p.rho[c] * fixed_[i][c];
        for (size_t u = 0; u < U; ++u) {
          const double au = p.rho[c] * column(u, i, c);
          if (au == 0) continue;
          q[u] += p.weight * au * b;
          for (size_t v = u; v < U; ++v) M[u * U + v] += p.weight * au * p.rho[c] * column(v, i, c);
        }
      }
      for (size_t u = 0; u < U; ++u) {
        for (size_t v = 0; v < u; ++v) M[u * U + v] = M[v * U + u];
        // The intensity prior: w / scale^2 (L - L0)^2.
        const double w = opt_.prior * intensityWeight(u) / (scaleOf(u) * scaleOf(u));
        M[u * U + u] += w;
        q[u] += w * startOf(u)[c];
      }
      const auto x = nonNegativeLeastSquares(M, q, int(U));
      for (size_t u = 0; u < U; ++u) L[u][c] = std::clamp(x[u], 0.0, scaleOf(u));
    }
    size_t k = 0;
    for (size_t i = 0; i < N; ++i) {
      const GridPixel& p = px_[i];
      Vec3 shading = fixed_[i];
      for (size_t u = 0; u < U; ++u)
        for (int c = 0; c < 3; ++c) shading[c] += column(u, i, c) * L[u][c];
      const double sw = std::sqrt(p.weight);
      for (int c = 0; c < 3; ++c) r[k++] = sw * (p.rho[c] * shading[c] - p.target[c]);
    }
    for (size_t m = 0; m < free_.size(); ++m) {
      const LightRefineSpec& spec = specs_[size_t(free_[m].index)];
      const double sw = std::sqrt(opt_.prior * spec.positionWeight);
      for (int a = 0; a < 3; ++a) r[k++] = sw * (poses[m].centre[a] - free_[m].start[a]);
      // The size prior: w_size |log scale|^2 (a halving costs as much as a doubling).
      if (free_[m].size)
        for (int a = 0; a < 2; ++a)
          r[k++] = std::sqrt(opt_.prior * spec.sizeWeight) * poses[m].logScale[a];
    }
    for (size_t u = 0; u < U; ++u) {
      const double sw = std::sqrt(opt_.prior * intensityWeight(u)) / scaleOf(u);
      for (int c = 0; c < 3; ++c) r[k++] = sw * (L[u][c] - startOf(u)[c]);
    }
    if (radiance) *radiance = L;
  }

  std::vector<FreeLight> free_;  // lights whose positions are parameters (set by the caller)

 private:
  double intensityWeight(size_t u) const {
    return unknownIsSun(u) ? opt_.sunIntensityWeight : specs_[unknownTarget(u)].intensityWeight;
  }
  const Vec3& startOf(size_t u) const { return start_[unknownTarget(u)]; }
  // scale_ and start_ are indexed by light; unknown u maps through unknownTarget.
  double scaleOf(size_t u) const { return scale_[unknownTarget(u)]; }

  const RoomTracer& tracer_;
  std::vector<GridPixel> px_;
  std::vector<AreaLight> lights_;
  const std::vector<LightRefineSpec>& specs_;
  std::vector<SunLight> suns_;
  std::vector<std::vector<Vec3>> sunE_;  // per sun and grid pixel: unit shading, direct + bounce
  size_t unknownAreaLights_ = 0;
  const LightRefineOptions& opt_;
  Vec3 boxLo_, boxSize_;
  struct Cached {
    Vec3 centre = Vec3::Constant(std::nan(""));
    Vec2 logScale = Vec2::Zero();
    std::vector<double> E;
  };
  std::vector<std::array<Cached, 2>> cache_;
  std::vector<int> unknownLights_;
  std::vector<double> scale_;
  std::vector<Vec3> start_;
  std::vector<Vec3> fixed_;
  int evaluations_ = 0;
};

}  // namespace

double outlineDisplacementBoundM(const Camera& camera, const AreaLight& light,
                                 const std::vector<Vec2>& outlinePx, const LightRefineOptions& options) {
  constexpr double kFree = std::numeric_limits<double>::infinity();
  if (outlinePx.empty() || !(camera.focalPx > 0) || !std::isfinite(camera.focalPx)) return kFree;
  Vec2 lo = outlinePx.front(), hi = lo;
  for (const Vec2& q : outlinePx) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  const double diagonalPx = (hi - lo).norm();
  const double metresPerPx = (light.centre() - camera.centreWorld()).norm() / camera.focalPx;
  const double uncertaintyPx = std::max(std::max(options.outlineUncertaintyPx, 0.0),
                                        std::max(options.outlineUncertaintyFraction, 0.0) * diagonalPx);
  const double bound = uncertaintyPx * metresPerPx;
  return std::isfinite(bound) && bound >= 0 ? bound : kFree;
}

double refineRowWeight(double y, int height) {
  if (height <= 0) return 0;
  const double mid = 0.5 * height;
  if (y <= mid) return 1;
  const double t = std::clamp((double(height) - y) / mid, 0.0, 1.0);
  return t * t;
}

std::vector<double> nonNegativeLeastSquares(const std::vector<double>& Min,
                                            const std::vector<double>& qin, int n) {
  std::vector<double> x(size_t(std::max(n, 0)), 0.0);
  if (n <= 0) return x;
  const Eigen::Map<const Eigen::MatrixXd> M(Min.data(), n, n);
  const Eigen::Map<const Eigen::VectorXd> q(qin.data(), n);
  if (!M.allFinite() || !q.allFinite()) return x;
  const double maxDiag = M.diagonal().cwiseAbs().maxCoeff();
  const double tol = 1e-12 * (maxDiag > 0 ? maxDiag : 1.0);
  Eigen::VectorXd xs = Eigen::VectorXd::Zero(n);
  std::vector<bool> passive(size_t(n), false);
  // Solve the unconstrained problem on the passive set (others held at 0).
  auto solvePassive = [&]() {
    std::vector<int> P;
    for (int i = 0; i < n; ++i)
      if (passive[size_t(i)]) P.push_back(i);
    Eigen::MatrixXd A(P.size(), P.size());
    Eigen::VectorXd b(P.size());
    for (size_t a = 0; a < P.size(); ++a) {
      b[long(a)] = q[P[a]];
      for (size_t c = 0; c < P.size(); ++c) A(long(a), long(c)) = M(P[a], P[c]);
      A(long(a), long(a)) += tol;  // slop for a singular passive set
    }
    const Eigen::VectorXd s = A.ldlt().solve(b);
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    for (size_t a = 0; a < P.size(); ++a) z[P[a]] = s[long(a)];
    return z;
  };
  for (int outer = 0; outer < 3 * n + 3; ++outer) {
    const Eigen::VectorXd w = q - M * xs;
    int best = -1;
    for (int i = 0; i < n; ++i)
      if (!passive[size_t(i)] && w[i] > tol && (best < 0 || w[i] > w[best])) best = i;
    if (best < 0) break;
    passive[size_t(best)] = true;
    for (int inner = 0; inner < 3 * n + 3; ++inner) {
      const Eigen::VectorXd z = solvePassive();
      bool allPositive = z.allFinite();
      for (int i = 0; i < n && allPositive; ++i)
        if (passive[size_t(i)] && z[i] <= 0) allPositive = false;
      if (allPositive) {
        xs = z;
        break;
      }
      // Step toward z until the first passive variable reaches 0; drop those at 0.
      double step = 1;
      for (int i = 0; i < n; ++i)
        if (passive[size_t(i)] && !(z[i] > 0)) {
          const double den = xs[i] - z[i];
          if (den > 0 && std::isfinite(den)) step = std::min(step, xs[i] / den);
        }
      if (z.allFinite()) xs += step * (z - xs);
      for (int i = 0; i < n; ++i)
        if (passive[size_t(i)] && xs[i] <= tol) passive[size_t(i)] = false, xs[i] = 0;
    }
  }
  for (int i = 0; i < n; ++i) x[size_t(i)] = std::isfinite(xs[i]) ? std::max(0.0, xs[i]) : 0.0;
  return x;
}

namespace {

// Ceres' view: one block per moving light (its centre, and its log edge scales when its size is
// refined); derivatives by forward differences that recompute only the moved light's irradiance.
class RefineCost : public ceres::CostFunction {
 public:
  RefineCost(Refinement& r, double step) : r_(r), step_(step) {
    for (const FreeLight& f : r_.free_) mutable_parameter_block_sizes()->push_back(f.dims());
    set_num_residuals(int(r_.residualCount()));
  }

  bool Evaluate(double const* const* params, double* residuals, double** jacobians) const override {
    const size_t F = r_.free_.size(), R = size_t(num_residuals());
    std::vector<Pose> poses(F);
    for (size_t m = 0; m < F; ++m)
      for (int a = 0; a < r_.free_[m].dims(); ++a) poses[m][a] = params[m][a];
    std::vector<const std::vector<double>*> E(r_.lightCount());
    for (size_t m = 0; m < F; ++m)
      E[size_t(r_.free_[m].index)] =
          &r_.irradiance(r_.free_[m].index, r_.centreOf(poses[m].centre), poses[m].logScale);
    for (size_t j = 0; j < E.size(); ++j)
      if (!E[j]) E[j] = &r_.irradiance(int(j), r_.startCentre(int(j)));
    r_.residuals(E, poses, residuals);
    if (!jacobians) return true;
    std::vector<double> plus(R);
    for (size_t m = 0; m < F; ++m) {
      if (!jacobians[m]) continue;
      const FreeLight& f = r_.free_[m];
      const size_t D = size_t(f.dims());
      const std::vector<double>* keep = E[size_t(f.index)];
      for (int a = 0; a < f.dims(); ++a) {
        if (std::find(f.fixedAxes.begin(), f.fixedAxes.end(), a) != f.fixedAxes.end()) {
          for (size_t k = 0; k < R; ++k) jacobians[m][k * D + size_t(a)] = 0;
          continue;
        }
        // Forward differences (the fixed samples make E smooth; half the renders of central
        // ones), stepping inward at the upper bound: past a wall the light is hidden.
        const double h = poses[m][a] + step_ > f.upper(a) ? -step_ : step_;
        std::vector<Pose> moved = poses;
        moved[m][a] += h;
        const std::vector<double> e =
            r_.irradianceUncached(f.index, r_.centreOf(moved[m].centre), moved[m].logScale);
        E[size_t(f.index)] = &e;
        r_.residuals(E, moved, plus.data());
        E[size_t(f.index)] = keep;
        for (size_t k = 0; k < R; ++k) jacobians[m][k * D + size_t(a)] = (plus[k] - residuals[k]) / h;
      }
    }
    return true;
  }

 private:
  Refinement& r_;
  double step_;
};

}  // namespace

namespace {

// Seconds on LightRefineOptions::clock, or on the steady clock when none is given.
class RefineClock {
 public:
  explicit RefineClock(const std::function<double()>& clock) : clock_(clock), t0_(now()) {}
  double now() const {
    if (clock_) return clock_();
    return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
  }
  double seconds() const { return now() - t0_; }

 private:
  const std::function<double()>& clock_;
  double t0_;
};

// After each iteration: records the objective, and ends the solve on cancel (abort), at the
// evaluation budget (the deterministic stop) or at the time guard (the last resort, flagged).
class RefineCallback : public ceres::IterationCallback {
 public:
  RefineCallback(const RefineClock& clock, const LightRefineOptions& opt, const Refinement& problem,
                 LightRefineResult& out)
      : clock_(clock), opt_(opt), problem_(problem), out_(out) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    // An unsuccessful step reports its rejected candidate's cost: only accepted points count.
    if (s.iteration == 0 || s.step_is_successful) out_.history.push_back({clock_.seconds(), 2 * s.cost});
    if (opt_.cancel && opt_.cancel->shouldStop()) return ceres::SOLVER_ABORT;
    if (problem_.evaluations() >= opt_.maxEvaluations) {
      out_.stoppedByBudget = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    if (clock_.seconds() >= opt_.guardSeconds) {
      out_.stoppedByGuard = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const RefineClock& clock_;
  const LightRefineOptions& opt_;
  const Refinement& problem_;
  LightRefineResult& out_;
};

double sumSquares(const std::vector<double>& r, size_t from, size_t to) {
  double s = 0;
  for (size_t k = from; k < to; ++k) s += r[k] * r[k];
  return s;
}

// The light's centre interval along each axis that keeps its corners `margin` inside the box
// [lo, hi]; an axis where the light does not fit is pinned at its centre.
void boundsInRoom(const AreaLight& L, const Vec3& lo, const Vec3& hi, double margin, Vec3* cLo,
                  Vec3* cHi, std::vector<int>* pinned) {
  const Vec3 c = L.centre();
  Vec3 mn = c, mx = c;
  for (const Vec3& p : L.cornersWorld) mn = mn.cwiseMin(p), mx = mx.cwiseMax(p);
  for (int a = 0; a < 3; ++a) {
    (*cLo)[a] = lo[a] + margin + (c[a] - mn[a]);
    (*cHi)[a] = hi[a] - margin - (mx[a] - c[a]);
    if (!((*cHi)[a] - (*cLo)[a] > 1e-6)) {
      (*cLo)[a] = (*cHi)[a] = std::clamp(c[a], lo[a], hi[a]);
      pinned->push_back(a);
    }
  }
}

// Narrows the centre interval [cLo, cHi] to within `radius` (metres) of `centre` along each
// axis; an axis left narrower than `minRange` (the finite-difference step) is pinned there.
void boundDisplacement(const Vec3& centre, double radius, const Vec3& minRange, Vec3* cLo, Vec3* cHi,
                       std::vector<int>* pinned) {
  if (!std::isfinite(radius)) return;
  for (int a = 0; a < 3; ++a) {
    if (std::find(pinned->begin(), pinned->end(), a) != pinned->end()) continue;
    (*cLo)[a] = std::max((*cLo)[a], centre[a] - radius);
    (*cHi)[a] = std::min((*cHi)[a], centre[a] + radius);
    if (!((*cHi)[a] - (*cLo)[a] >= minRange[a])) {
      (*cLo)[a] = (*cHi)[a] = centre[a];
      pinned->push_back(a);
    }
  }
}

// The room box the lights stay in; light positions are normalised to it.
struct RoomFrame {
  Vec3 lo, hi, size;
};

Expected<RoomFrame> roomFrameOf(const SceneGeometry& geometry) {
  const RoomBox& b = geometry.box;
  const Vec3 lo(b.xLeftM, 0.0, b.zBackM), hi(b.xRightM, b.ceilingM, b.zRearM);
  if (!((hi - lo).minCoeff() > 1e-3) || !lo.allFinite() || !hi.allFinite())
    return Error{"", "room", "the room box has no volume"};
  return RoomFrame{lo, hi, hi - lo};
}

// What refineLights needs of its images, options and suns before it starts; the error names it.
Status checkRefineInput(const ImageF& albedo, const ImageF& direct, const std::vector<uint8_t>& usable,
                        const std::vector<SunLight>& suns, const LightRefineOptions& opt) {
  const int W = direct.width, H = direct.height;
  if (direct.empty() || direct.channels < 3)
    return Error{"", "direct", "the direct-light image is empty"};
  if (albedo.width != W || albedo.height != H || albedo.channels < 3)
    return Error{"", "albedo", "the albedo image does not match the direct-light image"};
  if (!usable.empty() && usable.size() != size_t(W) * H)
    return Error{"", "usable", "the mask does not match the direct-light image"};
  if (!(opt.gridPixels > 0 && opt.samplesPerLight > 0 && opt.prior >= 0 && opt.intensityRange > 0 &&
        opt.stepNormalised > 0 && std::isfinite(opt.prior) && std::isfinite(opt.intensityRange) &&
        opt.sunIntensityWeight >= 0 && std::isfinite(opt.sunIntensityWeight) && opt.sizeRange >= 1 &&
        std::isfinite(opt.sizeRange)))
    return Error{"", "options", "refinement options out of range"};
  if (!(opt.maxEvaluations >= 1))
    return Error{"", "options.maxEvaluations",
                 "the refinement's budget is " + std::to_string(opt.maxEvaluations) +
                     " evaluations; give at least 1 (default 2000)"};
  if (!(opt.guardSeconds > 0))  // NaN too; infinity: no guard
    return Error{"", "options.guardSeconds",
                 "the refinement's time guard is not a positive number of seconds; give one, or "
                 "infinity for none (default 300)"};
  for (size_t k = 0; k < suns.size(); ++k) {
    if (!suns[k].irradianceOverPi.allFinite())
      return Error{"", "suns[" + std::to_string(k) + "]", "the sun's strength is not a finite number"};
    if (k < opt.sunBounce.size() && !opt.sunBounce[k].empty() &&
        (opt.sunBounce[k].width != W || opt.sunBounce[k].height != H || opt.sunBounce[k].channels < 3))
      return Error{"", "suns[" + std::to_string(k) + "]",
                   "the sun's bounce image does not match the direct-light image"};
  }
  return {};
}

// Checks each light (finite, with an area, sane weights), clamps its intensity at zero and moves
// each unlocked one into the room, so that its bounds hold from the start (a note says so). The
// lights free to move, with their bounds in the room's normalised frame.
Expected<std::vector<FreeLight>> freeLightsInRoom(std::vector<AreaLight>& lights,
                                                  const std::vector<LightRefineSpec>& specs,
                                                  const RoomFrame& room, const LightRefineOptions& opt,
                                                  std::vector<std::string>& notes) {
  std::vector<FreeLight> free;
  for (size_t j = 0; j < lights.size(); ++j) {
    const std::string key = "lights[" + std::to_string(j) + "]";
    AreaLight& L = lights[j];
    bool finite = L.radiance.allFinite();
    for (const Vec3& p : L.cornersWorld) finite = finite && p.allFinite();
    if (!finite) return Error{"", key, "the light's corners or intensity are not finite numbers"};
    if (!(L.area() > 0)) return Error{"", key, "the light has no area"};
    const LightRefineSpec& s = specs[j];
    if (!(s.positionWeight >= 0 && s.intensityWeight >= 0 && s.sizeWeight >= 0 &&
          std::isfinite(s.positionWeight) && std::isfinite(s.intensityWeight) &&
          std::isfinite(s.sizeWeight)))
      return Error{"", key + ".weights", "weights must be finite and non-negative"};
    if (!(s.maxDisplacementM >= 0))  // NaN or negative; infinity is free
      return Error{"", key, "the largest displacement must be a non-negative number of metres"};
    L.radiance = L.radiance.cwiseMax(0.0);
    if (s.lock) continue;
    FreeLight f;
    f.index = int(j);
    Vec3 cLo, cHi;
    boundsInRoom(L, room.lo, room.hi, opt.marginM, &cLo, &cHi, &f.fixedAxes);
    const Vec3 c = L.centre(), moved = c.cwiseMax(cLo).cwiseMin(cHi);
    if ((moved - c).norm() > 5e-3)  // millimetres of round-off are not news
      notes.push_back(key + ": outside the room; moved " + std::to_string((moved - c).norm()) +
                      " m to fit inside it");
    if (f.fixedAxes.size() == 3)
      notes.push_back(key + ": larger than the room in every direction; its position is kept");
    boundDisplacement(moved, s.maxDisplacementM, opt.stepNormalised * room.size, &cLo, &cHi,
                      &f.fixedAxes);
    for (auto& p : L.cornersWorld) p += moved - c;
    f.lo = (cLo - room.lo).cwiseQuotient(room.size);
    f.hi = (cHi - room.lo).cwiseQuotient(room.size);
    f.start = (moved - room.lo).cwiseQuotient(room.size);
    f.size = s.refineSize;
    f.logScaleBound = std::log(opt.sizeRange);
    if (f.fixedAxes.size() < 3) free.push_back(f);
  }
  return free;
}

// The reduced grid: pixel centres every `stride` pixels (about opt.gridPixels in all) that show
// a matte room surface and carry data, with the room point each shows.
std::vector<GridPixel> reducedGrid(const Camera& camera, const RoomTracer& tracer, const ImageF& albedo,
                                   const ImageF& direct, const std::vector<uint8_t>& usable,
                                   const LightRefineOptions& opt) {
  const int W = direct.width, H = direct.height;
  const int stride = std::max(1, int(std::lround(std::sqrt(double(W) * H / opt.gridPixels))));
  std::vector<GridPixel> px;
  for (int y = stride / 2; y < H; y += stride)
    for (int x = stride / 2; x < W; x += stride) {
      const size_t idx = size_t(y) * W + x;
      if (!usable.empty() && !usable[idx]) continue;
      const double alpha = refineRowWeight(y + 0.5, H);
      const Vec3 rho = albedo.rgb(x, y), d = direct.rgb(x, y);
      if (!(alpha > 0) || !rho.allFinite() || !d.allFinite()) continue;
      const Vec2 pc((x + 0.5) * camera.widthPx / W, (y + 0.5) * camera.heightPx / H);
      const auto hit = tracer.intersect(camera.rayThroughPixel(pc), 1e-6);
      if (!hit || isNonMatte(opt.nonMatteSurfaces, hit->surfaceId)) continue;
      GridPixel g;
      g.x = x, g.y = y;
      g.point = hit->pointWorld;
      g.normal = hit->normalWorld;
      g.rho = rho.cwiseMax(0.0);
      g.target = d.cwiseMax(0.0);
      g.weight = alpha;
      g.seed = uint32_t(idx);
      px.push_back(g);
    }
  return px;
}

// Per sun and grid pixel: its unit direct light and (when given) its sunlit patch's unit bounce.
// The direct component D left that bounce out (it was in the gathered light at the estimate's
// strength), so it goes back into each pixel's target at that strength.
std::vector<std::vector<Vec3>> sunShadingOnGrid(const RoomTracer& tracer, const SceneGeometry& geometry,
                                                const std::vector<SunLight>& suns,
                                                const LightRefineOptions& opt,
                                                std::vector<GridPixel>& px) {
  std::vector<std::vector<Vec3>> sunE(suns.size(), std::vector<Vec3>(px.size(), Vec3::Zero()));
  for (size_t k = 0; k < suns.size(); ++k)
    parallelFor(tbb::blocked_range<size_t>(0, px.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i < r.end(); ++i) {
        const double e = unitSunIrradianceOverPi(tracer, geometry, suns[k],
                                                 px[i].point + 1e-5 * px[i].normal, px[i].normal);
        sunE[k][i] = Vec3::Constant(e);
        if (k >= opt.sunBounce.size() || opt.sunBounce[k].empty()) continue;
        const Vec3 g = opt.sunBounce[k].rgb(px[i].x, px[i].y).cwiseMax(0.0);
        if (!g.allFinite()) continue;
        sunE[k][i] += g;
        px[i].target += px[i].rho.cwiseProduct(g).cwiseProduct(suns[k].irradianceOverPi.cwiseMax(0.0));
      }
    });
  return sunE;
}

// sum_i alpha_i |target_i|^2, the data term's scale.
double targetEnergy(const std::vector<GridPixel>& px) {
  double Z = 0;
  for (const GridPixel& g : px) Z += g.weight * g.target.squaredNorm();
  return Z;
}

// The data weights become alpha_i / Z, Z the targets' energy; for a black photo the start's
// render instead (a note says so).
void normaliseData(Refinement& problem, double Z, std::vector<std::string>& notes) {
  if (!(Z > 1e-20)) {
    notes.push_back("the photo's direct light is black: the lights are fitted to darkness");
    Z = problem.startRenderEnergy();
  }
  problem.normaliseData(Z > 1e-30 ? Z : 1.0);
}

// An unlocked light that lights no grid pixel keeps its start intensity (its prior): a note.
void noteLightsThatLightNothing(Refinement& problem, const std::vector<AreaLight>& lights,
                                const std::vector<LightRefineSpec>& specs,
                                std::vector<std::string>& notes) {
  for (size_t j = 0; j < lights.size(); ++j) {
    if (specs[j].lock) continue;
    const auto& e = problem.irradiance(int(j), lights[j].centre());
    if (std::all_of(e.begin(), e.end(), [](double v) { return v <= 0; }))
      notes.push_back("lights[" + std::to_string(j) +
                      "] lights none of the room the photo shows: its intensity stays at its start");
  }
}

// Ceres' parameter blocks: per free light its pose (normalised centre; log edge scales when its
// size is refined).
class PoseBlocks {
 public:
  explicit PoseBlocks(const std::vector<FreeLight>& free) : free_(free), blocks_(free.size()) {
    reset();
  }
  // Back to the start.
  void reset() {
    for (size_t m = 0; m < free_.size(); ++m) {
      blocks_[m].resize(size_t(free_[m].dims()));
      for (int a = 0; a < free_[m].dims(); ++a) blocks_[m][size_t(a)] = free_[m].startOf(a);
    }
  }
  Pose pose(size_t m) const {
    Pose pose;
    for (int a = 0; a < free_[m].dims(); ++a) pose[a] = blocks_[m][size_t(a)];
    return pose;
  }
  double* block(size_t m) { return blocks_[m].data(); }
  // Bounds hold even if the solver stepped on them with round-off; a non-finite value goes back
  // to its start.
  void clampToBounds() {
    for (size_t m = 0; m < free_.size(); ++m)
      for (int a = 0; a < free_[m].dims(); ++a) {
        double& v = blocks_[m][size_t(a)];
        v = std::isfinite(v) ? std::clamp(v, free_[m].lower(a), free_[m].upper(a)) : free_[m].startOf(a);
      }
  }

 private:
  const std::vector<FreeLight>& free_;
  std::vector<std::vector<double>> blocks_;
};

// The residuals `r` at the poses (the intensities solved inside); `radiance` (may be null)
// receives the intensities of the unknowns.
void evaluateAt(Refinement& problem, const std::vector<AreaLight>& lights, const PoseBlocks& params,
                std::vector<double>& r, std::vector<Vec3>* radiance) {
  const std::vector<FreeLight>& free = problem.free_;
  std::vector<const std::vector<double>*> E(lights.size(), nullptr);
  std::vector<Pose> poses(free.size());
  for (size_t m = 0; m < free.size(); ++m) {
    poses[m] = params.pose(m);
    E[size_t(free[m].index)] =
        &problem.irradiance(free[m].index, problem.centreOf(poses[m].centre), poses[m].logScale);
  }
  for (size_t j = 0; j < E.size(); ++j)
    if (!E[j]) E[j] = &problem.irradiance(int(j), lights[j].centre());
  problem.residuals(E, poses, r.data(), radiance);
}

// Ceres over the free lights' poses within their bounds; the objective after each accepted step
// goes to out.history. An unusable solution leaves the start (a note says so). Returns why the
// solver stopped.
std::string solvePoses(Refinement& problem, PoseBlocks& params, const LightRefineOptions& opt,
                       const RefineClock& clock, LightRefineResult& out) {
  const std::vector<FreeLight>& free = problem.free_;
  ceres::Problem cp;
  std::vector<double*> blocks;
  for (size_t m = 0; m < free.size(); ++m) blocks.push_back(params.block(m));
  cp.AddResidualBlock(new RefineCost(problem, opt.stepNormalised), nullptr, blocks);
  for (size_t m = 0; m < free.size(); ++m) {
    if (!free[m].fixedAxes.empty())
      cp.SetManifold(params.block(m), new ceres::SubsetManifold(free[m].dims(), free[m].fixedAxes));
    for (int a = 0; a < free[m].dims(); ++a) {
      if (std::find(free[m].fixedAxes.begin(), free[m].fixedAxes.end(), a) != free[m].fixedAxes.end())
        continue;
      cp.SetParameterLowerBound(params.block(m), a, free[m].lower(a));
      cp.SetParameterUpperBound(params.block(m), a, free[m].upper(a));
    }
  }
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = opt.maxIterations;  // the time limit is RefineCallback's guard alone
  so.num_threads = 1;
  so.logging_type = ceres::SILENT;
  so.function_tolerance = 1e-4;
  so.parameter_tolerance = 1e-4;  // of the normalised position: about half a millimetre
  RefineCallback callback(clock, opt, problem, out);
  so.callbacks.push_back(&callback);
  // No projected line search at the bounds: each of its steps costs a full Jacobian.
  so.max_num_line_search_step_size_iterations = 0;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &cp, &summary);
  if (!summary.IsSolutionUsable()) {
    out.notes.push_back("light refinement failed (" + summary.message + "): the start is kept");
    params.reset();
  }
  params.clampToBounds();
  const std::string iterations = " (" + std::to_string(summary.iterations.size()) + " iterations)";
  if (out.stoppedByGuard) {
    char note[256];
    std::snprintf(note, sizeof note,
                  "stopped by its time guard after %.0f s (%d of its budget of %d evaluations): the "
                  "machine was too slow or too loaded, and the lights may differ on another machine",
                  clock.seconds(), problem.evaluations(), opt.maxEvaluations);
    out.notes.push_back(note);
    return std::string("Stopped by the time guard.") + iterations;
  }
  if (out.stoppedByBudget)
    return "Stopped at the budget of " + std::to_string(opt.maxEvaluations) + " evaluations." +
           iterations;
  return summary.message + iterations;
}

// The refined lights into `out`: the free ones at their solved poses (a grown one kept inside
// the room: the position bounds hold for its start size), each unknown's fitted intensity (area
// lights, and the suns with refineSuns).
void storeRefinedLights(const Refinement& problem, const PoseBlocks& params,
                        const std::vector<Vec3>& radiance, const RoomFrame& room,
                        const LightRefineOptions& opt, std::vector<AreaLight> lights,
                        LightRefineResult& out) {
  const size_t areaLights = lights.size();
  out.lights = std::move(lights);
  for (size_t m = 0; m < problem.free_.size(); ++m) {
    AreaLight& L = out.lights[size_t(problem.free_[m].index)];
    const Pose pose = params.pose(m);
    L = posedLight(L, problem.centreOf(pose.centre), pose.logScale);
    if (problem.free_[m].size)
      for (auto& p : L.cornersWorld)
        p = p.cwiseMax(room.lo + Vec3::Constant(opt.marginM))
                .cwiseMin(room.hi - Vec3::Constant(opt.marginM));
  }
  for (size_t u = 0; u < radiance.size(); ++u) {
    const size_t t = problem.unknownTarget(u);
    const Vec3 v = radiance[u].allFinite() ? radiance[u] : Vec3::Zero();
    if (problem.unknownIsSun(u)) out.suns[t - areaLights].irradianceOverPi = v;
    else out.lights[t].radiance = v;
  }
}

std::atomic<uint64_t> gRefinementRuns{0};

}  // namespace

uint64_t lightRefinementRuns() { return gRefinementRuns.load(); }

Expected<LightRefineResult> refineLights(const Camera& camera, const SceneGeometry& geometry,
                                         const ImageF& albedo, const ImageF& direct,
                                         const std::vector<uint8_t>& usable,
                                         const std::vector<AreaLight>& lightsIn,
                                         const std::vector<LightRefineSpec>& specsIn,
                                         const std::vector<SunLight>& suns,
                                         const LightRefineOptions& opt) {
  const RefineClock clock(opt.clock);
  gRefinementRuns.fetch_add(1);
  if (Status st = checkRefineInput(albedo, direct, usable, suns, opt); !st) return st.error();
  std::vector<LightRefineSpec> specs = specsIn;
  specs.resize(lightsIn.size());
  LightRefineResult out;
  out.suns = suns;
  const auto room = roomFrameOf(geometry);
  if (!room) return room.error();
  std::vector<AreaLight> lights = lightsIn;  // each free one moved into the room
  auto free = freeLightsInRoom(lights, specs, *room, opt, out.notes);
  if (!free) return free.error();

  // The problem on the reduced grid: the photo's direct light there, the suns' share of it.
  const RoomTracer tracer(geometry);
  std::vector<GridPixel> px = reducedGrid(camera, tracer, albedo, direct, usable, opt);
  if (px.empty())
    return Error{"", "photo", "no pixel of the photo shows the room with usable direct light"};
  out.pixels = int(px.size());
  std::vector<std::vector<Vec3>> sunE = sunShadingOnGrid(tracer, geometry, suns, opt, px);
  const double Z = targetEnergy(px);  // with the suns' bounce put back
  Refinement problem(tracer, std::move(px), lights, specs, suns, std::move(sunE), opt, room->lo,
                     room->size);
  problem.free_ = std::move(*free);
  normaliseData(problem, Z, out.notes);
  noteLightsThatLightNothing(problem, lights, specs, out.notes);

  // The objective at the start, the solve, the objective and intensities at its end.
  PoseBlocks params(problem.free_);
  const size_t R = problem.residualCount(), dataEnd = 3 * size_t(out.pixels);
  std::vector<double> r(R);
  evaluateAt(problem, lights, params, r, nullptr);
  out.initialObjective = sumSquares(r, 0, R);
  out.initialDataTerm = sumSquares(r, 0, dataEnd);
  out.history.push_back({clock.seconds(), out.initialObjective});
  out.report = problem.free_.empty() ? "no light free to move: intensities solved in closed form"
                                     : solvePoses(problem, params, opt, clock, out);
  if (opt.cancel && opt.cancel->shouldStop()) return Error{"", "", "cancelled"};
  std::vector<Vec3> radiance;
  evaluateAt(problem, lights, params, r, &radiance);
  out.finalObjective = sumSquares(r, 0, R);
  out.finalDataTerm = sumSquares(r, 0, dataEnd);
  out.history.push_back({clock.seconds(), out.finalObjective});
  storeRefinedLights(problem, params, radiance, *room, opt, std::move(lights), out);
  out.evaluations = problem.evaluations();
  out.seconds = clock.seconds();
  return out;
}

}  // namespace inlay
