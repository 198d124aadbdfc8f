#include "inlay/modeling/estimate_camera.h"

#include "estimate_camera_internal.h"
#include "inlay/modeling/room_box.h"
#include "layout.h"
#include "lines.h"

#include <ceres/ceres.h>
#include <ceres/rotation.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <random>

namespace inlay {

namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}
constexpr double kDeg = M_PI / 180.0;
const char* kAxisName[3] = {"x", "y", "z"};

// Normalised image coordinates: u = (p - centre) / s, s = half the long side, so focal lengths
// become phi = f / s of order 1 and every quantity is well scaled.
struct Frame {
  Vec2 centre;
  double s = 1;
  Vec2 toNorm(const Vec2& p) const { return (p - centre) / s; }
};

// A segment as the search and the refinement use it.
struct Seg {
  Vec2 a, b;             // normalised endpoints
  Vec2 m, t;             // midpoint, unit direction
  double halfLenPx = 0;  // photo pixels
  double weight = 0;     // score weight: length in photo pixels (user lines: far more)
  double sinTol = 0;     // inlier threshold on sin(angle)
  double sinTol2 = 0;
  int fixedFamily = -1;  // user lines: the index of the direction they belong to
  int source = -1;       // index into the caller's segment list
};

// Image (normalised, homogeneous) of a camera-frame (OpenGL) direction for focal phi and
// principal point pp (normalised, relative to the frame's centre).
Vec3 vpOf(const Vec3& d, double phi, const Vec2& pp = Vec2::Zero()) {
  return Vec3(phi * d.x() - pp.x() * d.z(), -phi * d.y() - pp.y() * d.z(), -d.z());
}

// |sin| of the angle between a segment and the line from its midpoint to h (any w, so a point
// at infinity is ordinary). A segment aimed exactly at h's midpoint position counts as aligned.
double sinTo(const Seg& g, const Vec3& h) {
  const double qx = h.x() - g.m.x() * h.z(), qy = h.y() - g.m.y() * h.z();
  const double qn = std::hypot(qx, qy);
  if (qn < 1e-15) return 0;
  return std::abs(g.t.x() * qy - g.t.y() * qx) / qn;
}

struct Triplet {
  std::array<Vec3, 3> d{Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};  // camera frame, unit
  double phi = 1;
  Vec2 pp{0, 0};  // principal point, normalised, relative to Frame::centre
};

// The robust score of a triplet: length-weighted truncated quadratic of each segment's best fit.
double dataScore(const std::vector<Seg>& segs, const Triplet& tr, size_t limit = SIZE_MAX) {
  Vec3 h[3];
  for (int k = 0; k < 3; ++k) h[k] = vpOf(tr.d[k], tr.phi, tr.pp);
  double sum = 0;
  const size_t n = std::min(limit, segs.size());
  for (size_t i = 0; i < n; ++i) {
    const Seg& g = segs[i];
    double best = 0;
    for (int k = 0; k < 3; ++k) {
      if (g.fixedFamily >= 0 && g.fixedFamily != k) continue;
      // 1 - (sin / sinTol)^2 without roots: cross^2 / (|q|^2 sinTol^2).
      const double qx = h[k].x() - g.m.x() * h[k].z(), qy = h[k].y() - g.m.y() * h[k].z();
      const double q2 = qx * qx + qy * qy;
      const double cr = g.t.x() * qy - g.t.y() * qx;
      const double v = q2 > 1e-30 ? 1.0 - cr * cr / (q2 * g.sinTol2) : 1.0;
      best = std::max(best, v);
    }
    sum += g.weight * best;
  }
  return sum;
}

struct Prior {
  double logPhi0 = 0;
  double sigma = 0.6;
  double penaltyPerSigma2 = 0;  // score units per sigma^2 (search)
  double penalty(double phi) const {
    const double z = (std::log(phi) - logPhi0) / sigma;
    return penaltyPerSigma2 * z * z;
  }
};

// ---------------------------------------------------------------------------------------------
// Refinement: rotation (angle-axis applied on the camera side to the starting directions), log
// focal length and principal point. Residual: the distance in pixels of a segment's endpoints to
// the line through its midpoint and its vanishing point, over the pixel noise.
struct SegmentCost {
  Vec2 m, t;
  double halfLenOverSigma;  // half length (px) / noise (px) * sqrt(weight)
  Vec3 d0;

  template <typename T>
  bool operator()(const T* omega, const T* logPhi, const T* pp, T* r) const {
    const T p0[3] = {T(d0.x()), T(d0.y()), T(d0.z())};
    T d[3];
    ceres::AngleAxisRotatePoint(omega, p0, d);
    const T phi = ceres::exp(logPhi[0]);
    const T hx = phi * d[0] - pp[0] * d[2], hy = -phi * d[1] - pp[1] * d[2], hz = -d[2];
    const T qx = hx - T(m.x()) * hz, qy = hy - T(m.y()) * hz;
    const T cross = T(t.x()) * qy - T(t.y()) * qx;
    const T qn = ceres::sqrt(qx * qx + qy * qy + T(1e-24));
    r[0] = T(halfLenOverSigma) * cross / qn;
    return true;
  }
};

struct PriorCost {
  double logPhi0, invSigma;
  template <typename T>
  bool operator()(const T* logPhi, T* r) const {
    r[0] = (logPhi[0] - T(logPhi0)) * T(invSigma);
    return true;
  }
};

// The principal point's prior: the frame's centre, isotropic.
struct PrincipalPriorCost {
  double invSigma;
  template <typename T>
  bool operator()(const T* pp, T* r) const {
    r[0] = pp[0] * T(invSigma);
    r[1] = pp[1] * T(invSigma);
    return true;
  }
};

class CancelCallback : public ceres::IterationCallback {
 public:
  explicit CancelCallback(const CancelToken* c) : c_(c) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
    return c_ && c_->shouldStop() ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
  }

 private:
  const CancelToken* c_;
};

struct Assignment {
  std::vector<int> family;  // per Seg: direction index or -1
};

Assignment assign(const std::vector<Seg>& segs, const Triplet& tr) {
  Assignment a;
  a.family.assign(segs.size(), -1);
  Vec3 h[3];
  for (int k = 0; k < 3; ++k) h[k] = vpOf(tr.d[k], tr.phi, tr.pp);
  for (size_t i = 0; i < segs.size(); ++i) {
    if (segs[i].fixedFamily >= 0) {
      a.family[i] = segs[i].fixedFamily;
      continue;
    }
    double best = 1.0;
    for (int k = 0; k < 3; ++k) {
      const double r = sinTo(segs[i], h[k]) / segs[i].sinTol;
      if (r < best) {
        best = r;
        a.family[i] = k;
      }
    }
  }
  return a;
}

struct RefineSettings {
  double pixelSigma = 1;    // photo pixels of endpoint noise
  double userWeight = 100;  // user lines count as this many detected ones
  Prior prior;
  bool lockPhi = false;
  double principalSigma = 0;  // normalised; 0: the principal point is held where it starts
  const CancelToken* cancel = nullptr;
};

SegmentCost costOf(const Seg& g, const Vec3& d0, const RefineSettings& rs) {
  const double w = g.fixedFamily >= 0 ? std::sqrt(rs.userWeight) : 1.0;
  return SegmentCost{g.m, g.t, w * g.halfLenPx / rs.pixelSigma, d0};
}

// One Gauss-Newton-type solve on the assigned segments; returns the moved triplet.
Triplet solveOnce(const std::vector<Seg>& segs, const Assignment& as, const Triplet& start,
                  const RefineSettings& rs) {
  double omega[3] = {0, 0, 0};
  double logPhi = std::log(start.phi);
  double pp[2] = {start.pp.x(), start.pp.y()};
  ceres::Problem::Options po;
  ceres::Problem problem(po);
  int n = 0;
  for (size_t i = 0; i < segs.size(); ++i) {
    const int k = as.family[i];
    if (k < 0) continue;
    auto* cost = new ceres::AutoDiffCostFunction<SegmentCost, 1, 3, 1, 2>(
        new SegmentCost(costOf(segs[i], start.d[k], rs)));
    problem.AddResidualBlock(cost, new ceres::CauchyLoss(2.0), omega, &logPhi, pp);
    ++n;
  }
  if (n == 0) return start;
  problem.AddResidualBlock(new ceres::AutoDiffCostFunction<PriorCost, 1, 1>(
                               new PriorCost{rs.prior.logPhi0, 1.0 / rs.prior.sigma}),
                           nullptr, &logPhi);
  if (rs.lockPhi) problem.SetParameterBlockConstant(&logPhi);
  if (rs.principalSigma > 0)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<PrincipalPriorCost, 2, 2>(
                                 new PrincipalPriorCost{1.0 / rs.principalSigma}),
                             nullptr, pp);
  else problem.SetParameterBlockConstant(pp);
  problem.SetParameterLowerBound(&logPhi, 0, std::log(0.05));
  problem.SetParameterUpperBound(&logPhi, 0, std::log(200.0));
  ceres::Solver::Options opt;
  opt.linear_solver_type = ceres::DENSE_QR;
  opt.max_num_iterations = 30;
  opt.num_threads = 1;
  opt.logging_type = ceres::SILENT;
  opt.minimizer_progress_to_stdout = false;
  CancelCallback cb(rs.cancel);
  opt.callbacks.push_back(&cb);
  ceres::Solver::Summary summary;
  ceres::Solve(opt, &problem, &summary);
  Triplet out = start;
  if (!std::isfinite(logPhi) || !std::isfinite(omega[0] + omega[1] + omega[2]) ||
      !std::isfinite(pp[0] + pp[1]))
    return start;
  out.phi = std::exp(logPhi);
  out.pp = Vec2(pp[0], pp[1]);
  for (int k = 0; k < 3; ++k) {
    double p[3] = {start.d[k].x(), start.d[k].y(), start.d[k].z()}, q[3];
    ceres::AngleAxisRotatePoint(omega, p, q);
    out.d[k] = Vec3(q[0], q[1], q[2]).normalized();
  }
  return out;
}

// Covariance of (omega, log phi, principal point) at the solution, Cauchy weights, noise scale
// from the data.
using Mat6 = Eigen::Matrix<double, 6, 6>;
struct Uncertainty {
  Mat6 cov = Mat6::Identity() * 1e6;
  double logPhiSigma = 10;
  double dataInfoLogPhi = 0;  // information on log phi from the segments alone
  std::array<double, 3> angularSigmaRad{M_PI, M_PI, M_PI};
};

// A weak pull of all six parameters to the solution (information 1e-9): keeps the covariance
// finite, and huge, along directions the lines leave free.
struct RidgeCost {
  double x0[6];
  template <typename T>
  bool operator()(const T* omega, const T* logPhi, const T* pp, T* r) const {
    const T* x[6] = {omega, omega + 1, omega + 2, logPhi, pp, pp + 1};
    for (int j = 0; j < 6; ++j) r[j] = (*x[j] - T(x0[j])) * T(std::sqrt(1e-9));
    return true;
  }
};

// The solve's problem at the solution, each segment's residual scaled by the square root of its
// Cauchy(2) weight over the noise variance the weighted residuals give (IRLS at the optimum), for
// ceres::Covariance; a held block (a locked focal, a held principal point) is constant.
// `dataInfoLogPhi` gets the segments' own information on log phi.
Mat6 covarianceAt(const std::vector<Seg>& segs, const Assignment& as, const Triplet& tr,
                  const RefineSettings& rs, double* dataInfoLogPhi) {
  double x[6] = {0, 0, 0, std::log(tr.phi), tr.pp.x(), tr.pp.y()};
  std::vector<SegmentCost> costs;
  std::vector<double> weights;
  double sumWr2 = 0;
  for (size_t i = 0; i < segs.size(); ++i) {
    if (as.family[i] < 0) continue;
    costs.push_back(costOf(segs[i], tr.d[as.family[i]], rs));
    double r0 = 0;
    costs.back()(x, x + 3, x + 4, &r0);
    weights.push_back(1.0 / (1.0 + (r0 / 2.0) * (r0 / 2.0)));  // Cauchy(2) weight
    sumWr2 += weights.back() * r0 * r0;
  }
  const size_t n = costs.size();
  const double scale2 = std::max(1.0, n > 6 ? sumWr2 / double(n - 6) : 1.0);
  ceres::Problem problem;
  double* blocks[3] = {x, x + 3, x + 4};
  *dataInfoLogPhi = 0;
  for (size_t i = 0; i < n; ++i) {
    costs[i].halfLenOverSigma *= std::sqrt(weights[i] / scale2);
    auto* cost = new ceres::AutoDiffCostFunction<SegmentCost, 1, 3, 1, 2>(new SegmentCost(costs[i]));
    double r = 0, dOmega[3], dLogPhi = 0, dPp[2];
    double* jacobians[3] = {dOmega, &dLogPhi, dPp};
    cost->Evaluate(blocks, &r, jacobians);
    *dataInfoLogPhi += scale2 * dLogPhi * dLogPhi;
    problem.AddResidualBlock(cost, nullptr, x, x + 3, x + 4);
  }
  problem.AddResidualBlock(new ceres::AutoDiffCostFunction<PriorCost, 1, 1>(
                               new PriorCost{rs.prior.logPhi0, 1.0 / rs.prior.sigma}),
                           nullptr, x + 3);
  if (rs.principalSigma > 0)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<PrincipalPriorCost, 2, 2>(
                                 new PrincipalPriorCost{1.0 / rs.principalSigma}),
                             nullptr, x + 4);
  RidgeCost ridge{};
  std::copy(x, x + 6, ridge.x0);
  problem.AddResidualBlock(new ceres::AutoDiffCostFunction<RidgeCost, 6, 3, 1, 2>(new RidgeCost(ridge)),
                           nullptr, x, x + 3, x + 4);
  if (rs.lockPhi) problem.SetParameterBlockConstant(x + 3);
  if (!(rs.principalSigma > 0)) problem.SetParameterBlockConstant(x + 4);
  ceres::Covariance::Options options;
  options.algorithm_type = ceres::DENSE_SVD;
  options.min_reciprocal_condition_number = 1e-300;  // the ridge keeps it invertible: never truncate or
                                                     // refuse (Ceres would log the refusal to stderr)
  options.num_threads = 1;
  ceres::Covariance covariance(options);
  const std::vector<const double*> all = {x, x + 3, x + 4};
  Eigen::Matrix<double, 6, 6, Eigen::RowMajor> c = Eigen::Matrix<double, 6, 6, Eigen::RowMajor>::Zero();
  if (!covariance.Compute(all, &problem) || !covariance.GetCovarianceMatrix(all, c.data()) ||
      !c.allFinite())
    return Mat6::Identity() * 1e6;
  return c;
}

Uncertainty uncertaintyOf(const std::vector<Seg>& segs, const Assignment& as, const Triplet& tr,
                          const RefineSettings& rs) {
  Uncertainty u;
  u.cov = covarianceAt(segs, as, tr, rs, &u.dataInfoLogPhi);
  u.logPhiSigma = std::sqrt(std::max(0.0, u.cov(3, 3)));
  const Eigen::Matrix3d covOmega = u.cov.topLeftCorner<3, 3>();
  for (int k = 0; k < 3; ++k) {
    Eigen::Matrix3d sk;
    const Vec3& d = tr.d[k];
    sk << 0, -d.z(), d.y(), d.z(), 0, -d.x(), -d.y(), d.x(), 0;
    const Eigen::Matrix3d cd = sk * covOmega * sk.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cd);
    u.angularSigmaRad[k] = std::min(M_PI, std::sqrt(std::max(0.0, es.eigenvalues().maxCoeff())));
  }
  return u;
}

// Alternate assignment and solve.
Triplet refine(const std::vector<Seg>& segs, Triplet tr, const RefineSettings& rs, int rounds,
               Assignment* finalAssignment) {
  Assignment as;
  for (int r = 0; r < rounds; ++r) {
    as = assign(segs, tr);
    tr = solveOnce(segs, as, tr, rs);
    if (rs.cancel && rs.cancel->shouldStop()) break;
  }
  as = assign(segs, tr);
  if (finalAssignment) *finalAssignment = as;
  return tr;
}

// ---------------------------------------------------------------------------------------------
// Hypothesis search over a ladder of focal lengths. The same index triples are tried on every
// rung (so rungs compare like with like): segments i, j give direction 1 = n_i x n_j (their
// interpretation planes' normals), segment k the orthogonal direction 2 = d1 x n_k, and
// direction 3 completes the frame.
struct SearchOutput {
  std::vector<std::pair<double, Triplet>> candidates;  // best per rung, best first
  std::vector<SearchProgress> progress;
};

// Hypotheses are scored on the longest segments only (segs come sorted longest first);
// refinement then uses all.
constexpr size_t kSearchSegments = 150;

SearchOutput search(const std::vector<Seg>& segs, const Prior& prior, int iterations, uint32_t seed,
                    Clock::time_point t0, const CancelToken* cancel) {
  SearchOutput out;
  const int n = int(segs.size());
  if (n < 3) return out;
  // Length-weighted sampling (long segments are more often structure than clutter).
  std::vector<double> cdf(n);
  double acc = 0;
  for (int i = 0; i < n; ++i) cdf[i] = (acc += segs[i].weight);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, acc);
  auto draw = [&] { return int(std::lower_bound(cdf.begin(), cdf.end(), uni(rng)) - cdf.begin()); };
  std::vector<std::array<int, 3>> triples;
  triples.reserve(iterations);
  for (int it = 0; it < iterations * 4 && int(triples.size()) < iterations; ++it) {
    const int i = std::min(n - 1, draw()), j = std::min(n - 1, draw()), k = std::min(n - 1, draw());
    if (i == j || j == k || i == k) continue;
    triples.push_back({i, j, k});
  }
  // Rungs: f from 0.25 to 6 times the long side (phi 0.5 .. 12), and the prior itself.
  constexpr int kRungs = 14;
  std::vector<double> rungs;
  rungs.reserve(kRungs + 1);
  for (int r = 0; r < kRungs; ++r) rungs.push_back(0.5 * std::pow(24.0, r / double(kRungs - 1)));
  rungs.push_back(std::exp(prior.logPhi0));
  double bestSoFar = -1e300;
  std::vector<Vec3> normals(n);
  for (double phi : rungs) {
    if (cancel && cancel->shouldStop()) break;
    for (int i = 0; i < n; ++i) {
      const Vec3 ra(segs[i].a.x(), -segs[i].a.y(), -phi), rb(segs[i].b.x(), -segs[i].b.y(), -phi);
      normals[i] = ra.cross(rb).normalized();
    }
    double rungBest = -1e300;
    Triplet rungTr;
    const double pen = prior.penalty(phi);
    for (const auto& tri : triples) {
      Vec3 d1 = normals[tri[0]].cross(normals[tri[1]]);
      if (d1.norm() < 1e-9) continue;
      d1.normalize();
      Vec3 d2 = d1.cross(normals[tri[2]]);
      if (d2.norm() < 1e-9) continue;
      d2.normalize();
      Triplet tr;
      tr.d = {d1, d2, d1.cross(d2)};
      tr.phi = phi;
      const double sc = dataScore(segs, tr, kSearchSegments) - pen;
      if (sc > rungBest) {
        rungBest = sc;
        rungTr = tr;
      }
    }
    if (rungBest > -1e300) out.candidates.push_back({rungBest, rungTr});
    if (rungBest > bestSoFar) {
      bestSoFar = rungBest;
      out.progress.push_back({msSince(t0) / 1000.0, bestSoFar});
    }
  }
  std::sort(out.candidates.begin(), out.candidates.end(),
            [](const auto& x, const auto& y) { return x.first > y.first; });
  return out;
}

// ---------------------------------------------------------------------------------------------
// Directions to world axes: y is the one nearest the camera's up, x the horizontal one nearest
// the camera's right, z = x cross y (so +z points back toward the camera).
std::array<int, 3> axisOrder(const Triplet& tr) {
  int y = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(tr.d[k].y()) > std::abs(tr.d[y].y())) y = k;
  int a = (y + 1) % 3, b = (y + 2) % 3;
  const int x = std::abs(tr.d[a].x()) >= std::abs(tr.d[b].x()) ? a : b;
  const int z = 3 - x - y;
  return {x, y, z};
}

// Triplet in world-axis order with the sign rules of camera.cpp (x right, y up, z = x cross y).
Triplet ordered(const Triplet& tr, const std::array<int, 3>& order) {
  Triplet o;
  o.phi = tr.phi;
  o.pp = tr.pp;
  Vec3 x = tr.d[order[0]], y = tr.d[order[1]];
  if (x.x() < 0) x = -x;
  if (y.y() < 0) y = -y;
  o.d = {x, y, x.cross(y).normalized()};
  return o;
}

// The scene file's form: x / w, or 1e7 px from the principal point along the point's image
// direction when it is farther than that (or at infinity).
Vec2 scenePixel(const Vec3& h, const Vec2& principal) {
  if (std::abs(h.z()) > 1e-300) {
    Vec2 p(h.x() / h.z(), h.y() / h.z());
    if (p.allFinite() && (p - principal).norm() < 1e7) return p;
  }
  const Vec2 dir(h.x() - principal.x() * h.z(), h.y() - principal.y() * h.z());
  return principal + 1e7 * (dir.norm() > 0 ? Vec2(dir.normalized()) : Vec2(1, 0));
}

// Family meaningfulness (-log10 NFA, finish()) for "far beyond chance" and "present".
// Random-line photos reached 6.5, a sparse synthetic facade 8.3, real rooms 50-110.
constexpr double kStrongZ = 7.5;
constexpr double kPresentZ = 0.0;

// log10 P(X >= k), X ~ Binomial(n, p).
double log10BinomialTail(int n, int k, double p) {
  if (k <= 0) return 0.0;
  if (k > n) return -300.0;
  p = std::clamp(p, 1e-12, 1 - 1e-12);
  double best = -1e300;
  std::vector<double> terms;
  for (int j = k; j <= n; ++j) {
    const double t = std::lgamma(n + 1.0) - std::lgamma(j + 1.0) - std::lgamma(n - j + 1.0) +
                     j * std::log(p) + (n - j) * std::log1p(-p);
    terms.push_back(t);
    best = std::max(best, t);
  }
  double sum = 0;
  for (double t : terms) sum += std::exp(t - best);
  return (best + std::log(sum)) / std::log(10.0);
}

struct Core {
  int W = 0, H = 0;
  Frame frame;
  std::vector<LineSegment> segments;  // photo pixels (output)
  std::vector<Seg> segs;              // the ones the solver uses (index -> segments via source)
  double workingScale = 1;
};

void buildSegs(Core& c, const EstimateOptions& o, double pixelTol) {
  const double sinT = std::sin(o.inlierAngleDeg * kDeg);
  const double sinMax = std::sin(3 * o.inlierAngleDeg * kDeg);
  for (size_t i = 0; i < c.segments.size(); ++i) {
    const LineSegment& s = c.segments[i];
    const double len = s.lengthPx();
    if (!(len > 1e-6) || !s.aPx.allFinite() || !s.bPx.allFinite()) continue;
    Seg g;
    g.a = c.frame.toNorm(s.aPx);
    g.b = c.frame.toNorm(s.bPx);
    g.m = 0.5 * (g.a + g.b);
    g.t = (g.b - g.a).normalized();
    g.halfLenPx = 0.5 * len;
    g.sinTol = std::min(sinMax, std::max(sinT, pixelTol / g.halfLenPx));
    g.sinTol2 = g.sinTol * g.sinTol;
    g.weight = s.userGiven ? 100 * len : len;
    g.fixedFamily = s.userGiven ? s.family : -1;
    g.source = int(i);
    c.segs.push_back(g);
  }
}

Prior makePrior(const Core& c, const EstimateOptions& o, double totalWeight) {
  Prior p;
  const double f0 = o.priorFocalPx && *o.priorFocalPx > 0 && std::isfinite(*o.priorFocalPx)
                        ? *o.priorFocalPx
                        : 0.5 * c.W / std::tan(30.0 * kDeg);
  p.logPhi0 = std::log(f0 / c.frame.s);
  p.sigma = o.priorFocalPx ? o.priorLogSigmaExif : o.priorLogSigmaDefault;
  p.penaltyPerSigma2 = 0.005 * totalWeight;
  return p;
}

// The principal point's posterior spread: held (sigma 0) it is an assumption, not a measurement;
// refined, the data locate it where the posterior variance is under half the prior's, i.e. the
// lines carry more information than the prior in every direction.
void setPrincipalUncertainty(CameraEstimate& e, const Uncertainty& u, const RefineSettings& rs,
                             double scalePx) {
  e.principalSigmaPx = Vec2::Zero();
  e.principalFromPrior = true;
  if (!(rs.principalSigma > 0)) return;
  const Eigen::Matrix2d cov = u.cov.block<2, 2>(4, 4);
  if (!cov.allFinite()) return;
  e.principalSigmaPx = scalePx *
                       Vec2(std::sqrt(std::max(0.0, cov(0, 0))), std::sqrt(std::max(0.0, cov(1, 1))));
  const double worst = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(cov).eigenvalues().maxCoeff();
  e.principalFromPrior = !(worst < 0.5 * rs.principalSigma * rs.principalSigma);
}

// The camera of a refined triplet (its directions made an exact rotation).
Camera cameraOf(const Core& c, const Triplet& tr, double heightM) {
  Camera cam;
  cam.widthPx = c.W;
  cam.heightPx = c.H;
  cam.principalPx = c.frame.centre + c.frame.s * tr.pp;
  cam.focalPx = tr.phi * c.frame.s;
  cam.heightM = heightM;
  Mat3 cameraFromWorld;
  for (int k = 0; k < 3; ++k) cameraFromWorld.col(k) = tr.d[k];
  Eigen::JacobiSVD<Mat3> svd(cameraFromWorld, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 r = svd.matrixU() * svd.matrixV().transpose();
  if (r.determinant() < 0) r = -r;  // cannot happen with z = x cross y; keep a rotation anyway
  cam.worldFromCamera = r.transpose();
  return cam;
}

// Per family, what its supporting segments say; and the chance model's inputs over the
// detected segments.
struct FamilyTally {
  double chanceSum = 0;  // sum of the detected segments' chance to fit a point by accident
  int detected = 0;      // detected (not user-given) segments
  std::array<int, 3> count{0, 0, 0}, userCount{0, 0, 0}, tight{0, 0, 0};
  std::array<double, 3> length{0, 0, 0}, sumR2{0, 0, 0};
  std::array<double, 3> angMin{1e9, 1e9, 1e9}, angMax{-1e9, -1e9, -1e9};
};

// The caller's segments get their families and residuals, and each family its tally. Chance
// model (a contrario, as LSD itself): a segment fits a given vanishing point within half its
// inlier tolerance by accident with probability p_i = 2 asin(sinTol / 2) / pi. Real structure
// fits far tighter than the tolerance, noise does not.
FamilyTally tallyFamilies(Core& c, const Triplet& tr, const Assignment& as) {
  for (auto& s : c.segments) {
    s.family = s.userGiven ? s.family : -1;
    s.residualPx = 0;
  }
  Vec3 h[3];
  for (int k = 0; k < 3; ++k) h[k] = vpOf(tr.d[k], tr.phi, tr.pp);
  FamilyTally f;
  std::array<Vec2, 3> meanDir{Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};
  auto chanceOf = [](const Seg& g) {
    return std::clamp(2.0 * std::asin(std::min(1.0, 0.5 * g.sinTol)) / M_PI, 1e-4, 0.5);
  };
  for (size_t i = 0; i < c.segs.size(); ++i) {
    const Seg& g = c.segs[i];
    if (g.fixedFamily < 0) {
      f.chanceSum += chanceOf(g);
      ++f.detected;
    }
    const int k = as.family[i];
    if (k < 0) continue;
    LineSegment& s = c.segments[g.source];
    s.family = k;
    s.residualPx = g.halfLenPx * sinTo(g, h[k]);
    ++f.count[k];
    if (s.userGiven) ++f.userCount[k];
    else if (sinTo(g, h[k]) < 0.5 * g.sinTol) ++f.tight[k];
    f.length[k] += s.lengthPx();
    f.sumR2[k] += s.residualPx * s.residualPx;
    // Doubled angle: direction of an undirected line.
    meanDir[k] +=
        Vec2(std::cos(2 * std::atan2(g.t.y(), g.t.x())), std::sin(2 * std::atan2(g.t.y(), g.t.x())));
  }
  // The spread of each family's directions about their mean.
  for (size_t i = 0; i < c.segs.size(); ++i) {
    const int k = as.family[i];
    if (k < 0) continue;
    const Vec2& t = c.segs[i].t;
    const double mean = 0.5 * std::atan2(meanDir[k].y(), meanDir[k].x());
    double a = std::atan2(t.y(), t.x()) - mean;
    while (a > M_PI / 2) a -= M_PI;
    while (a < -M_PI / 2) a += M_PI;
    f.angMin[k] = std::min(f.angMin[k], a);
    f.angMax[k] = std::max(f.angMax[k], a);
  }
  return f;
}

// Each vanishing point as the camera sees it, with its family's support.
void describeVanishingPoints(CameraEstimate& e, const Camera& cam, const Triplet& tr,
                             const FamilyTally& f, const Uncertainty& u) {
  const double diag = std::hypot(double(cam.widthPx), double(cam.heightPx));
  for (int k = 0; k < 3; ++k) {
    VanishingPointInfo& v = e.vanishingPoints[k];
    v.homogeneousPx = cam.vanishingPointOf(Vec3::Unit(k));
    v.directionCamera = tr.d[k];
    const double xyn = std::hypot(v.homogeneousPx.x(), v.homogeneousPx.y());
    v.atInfinity = std::abs(v.homogeneousPx.z()) * 1000 * diag < xyn;
    v.segmentCount = f.count[k];
    v.supportLengthPx = f.length[k];
    v.rmsResidualPx = f.count[k] ? std::sqrt(f.sumR2[k] / f.count[k]) : 0;
    v.angularSigmaDeg = u.angularSigmaRad[k] / kDeg;
    v.nearlyParallel = f.count[k] >= 2 && (f.angMax[k] - f.angMin[k]) < 2.0 * kDeg;
    e.vanishingPointsPx[k] = scenePixel(v.homogeneousPx, cam.principalPx);
  }
}

// Support beyond chance: -log10 of the number of false alarms, NFA = (vanishing points tried)
// x P(at least `tight` of `detected` segments fit by accident), binomial with the mean chance.
// A Manhattan frame is found strongest family first: its point is one of the segment pairs'
// (times the focal rungs); the second lies on the great circle orthogonal to the first (one
// per segment and rung); the third is then fixed (one per rung). Each point's confidence is
// that significance times the precision of its direction; zScore (out) is the significance.
void setConfidences(CameraEstimate& e, const FamilyTally& f, std::array<double, 3>& zScore) {
  const double p = f.detected > 0 ? f.chanceSum / f.detected : 0.01;
  const double n = std::max(1, f.detected);
  const double firstTests = 0.5 * n * std::max(1.0, n - 1) * 15.0;
  std::array<double, 3> raw{};
  for (int k = 0; k < 3; ++k) raw[k] = -log10BinomialTail(f.detected, f.tight[k], p);
  std::array<int, 3> rank{0, 1, 2};
  std::sort(rank.begin(), rank.end(), [&](int a, int b) { return raw[a] > raw[b]; });
  const double tests[3] = {firstTests, n * 15.0, 15.0};
  for (int order = 0; order < 3; ++order) {
    const int k = rank[order];
    const double z = f.userCount[k] > 0 ? 100.0 : raw[k] - std::log10(tests[order]);
    zScore[k] = z;
    // Calibrated on noise and random-line photos (best family up to 6.5) and real rooms (50-110
    // for a wall's or floor's lines, 2-20 for a sparse second or third family).
    const double significance = std::clamp((z + 1.0) / 8.0, 0.0, 1.0);
    VanishingPointInfo& v = e.vanishingPoints[k];
    const double sig = v.angularSigmaDeg;
    const double precision = 1.0 / (1.0 + sig * sig);
    v.confidence = std::clamp(significance * precision, 0.0, 1.0);
    e.confidence[k] = v.confidence;
  }
  std::array<double, 3> sorted = e.confidence;
  std::sort(sorted.begin(), sorted.end());
  e.overallConfidence = sorted[1];
}

// Fill the estimate from a refined, world-ordered triplet: camera, vanishing points, segment
// families and residuals, confidences, focal interval. zScore (out): per axis the family's
// meaningfulness (-log10 NFA; 100 for user lines) for the Manhattan decision.
void finish(CameraEstimate& e, Core& c, const Triplet& tr, const Assignment& as, const Uncertainty& u,
            const RefineSettings& rs, const EstimateOptions& o, bool lockedFocal,
            std::array<double, 3>& zScore) {
  e.camera = cameraOf(c, tr, o.cameraHeightM);
  const FamilyTally f = tallyFamilies(c, tr, as);
  describeVanishingPoints(e, e.camera, tr, f, u);
  setConfidences(e, f, zScore);
  const Camera& cam = e.camera;
  const double fs = lockedFocal ? 0.0 : u.logPhiSigma;
  e.focalMinPx = cam.focalPx * std::exp(-2 * fs);
  e.focalMaxPx = cam.focalPx * std::exp(2 * fs);
  // The photo determines f when its information beats the prior's.
  e.focalFromPrior = !lockedFocal && u.dataInfoLogPhi < 1.0 / (rs.prior.sigma * rs.prior.sigma);
  setPrincipalUncertainty(e, u, rs, c.frame.s);
  e.segments = c.segments;
}

void addVpWarnings(CameraEstimate& e) {
  for (int k = 0; k < 3; ++k) {
    const auto& v = e.vanishingPoints[k];
    if (v.segmentCount < 3)
      e.warnings.push_back(std::string("vanishing point ") + kAxisName[k] + ": only " +
                           std::to_string(v.segmentCount) +
                           " supporting line(s); it rests on the other two");
    else if (v.nearlyParallel)
      e.warnings.push_back(std::string("vanishing point ") + kAxisName[k] +
                           ": its lines are nearly parallel in the photo, so its distance is "
                           "uncertain");
  }
}

// Each vanishing point's supporters, from the segments' families (the last step of every path,
// so indices and families always agree).
void indexSupporters(CameraEstimate& e) {
  for (auto& v : e.vanishingPoints) v.segmentIndices.clear();
  for (size_t i = 0; i < e.segments.size(); ++i) {
    const int k = e.segments[i].family;
    if (k >= 0 && k < 3) e.vanishingPoints[k].segmentIndices.push_back(int(i));
  }
}

void fallbackCamera(CameraEstimate& e, const Core& c, const Prior& prior, const EstimateOptions& o,
                    const std::optional<Vec3>& upCamera, double upConfidence) {
  // The fallback's points are not the segments' (only the vertical, when it was kept): the
  // others support nothing.
  for (auto& s : e.segments)
    if (!(upCamera && s.family == 1)) {
      s.family = -1;
      s.residualPx = 0;
    }
  const double f = std::exp(prior.logPhi0) * c.frame.s;
  e.camera = levelCamera(c.W, c.H, f, o.cameraHeightM);
  e.camera.principalPx = c.frame.centre;
  if (upCamera) {
    // Vertical lines only: tilt so that world up is the measured vertical, no yaw.
    Vec3 y = *upCamera;
    if (y.y() < 0) y = -y;
    Vec3 x = Vec3::UnitX() - y * y.x();
    x.normalize();
    const Vec3 z = x.cross(y);
    Mat3 cw;
    cw.col(0) = x;
    cw.col(1) = y;
    cw.col(2) = z;
    e.camera.worldFromCamera = cw.transpose();
  }
  const double diag = std::hypot(double(c.W), double(c.H));
  for (int k = 0; k < 3; ++k) {
    auto& v = e.vanishingPoints[k];
    v.homogeneousPx = e.camera.vanishingPointOf(Vec3::Unit(k));
    v.directionCamera = e.camera.cameraFromWorld().col(k);
    const double xyn = std::hypot(v.homogeneousPx.x(), v.homogeneousPx.y());
    v.atInfinity = std::abs(v.homogeneousPx.z()) * 1000 * diag < xyn;
    v.confidence = (k == 1 && upCamera) ? upConfidence : 0.0;
    e.confidence[k] = v.confidence;
    if (!(k == 1 && upCamera)) {
      v.segmentCount = 0;
      v.supportLengthPx = 0;
      v.rmsResidualPx = 0;
      v.angularSigmaDeg = 180;
      v.nearlyParallel = false;
    }
    e.vanishingPointsPx[k] = scenePixel(v.homogeneousPx, e.camera.principalPx);
  }
  e.overallConfidence = 0;
  e.manhattan = false;
  e.focalMinPx = f * std::exp(-2 * prior.sigma);
  e.focalMaxPx = f * std::exp(2 * prior.sigma);
  e.focalFromPrior = true;
  // At the prior's centre, as uncertain as the prior says (0 when held).
  const double ppSigma = o.principalPx ? 0.0 : std::max(0.0, o.principalSigma) * c.frame.s;
  e.principalSigmaPx = Vec2(ppSigma, ppSigma);
  e.principalFromPrior = true;
  e.warnings.push_back(std::string("no Manhattan structure found (too few lines in three orthogonal "
                                   "directions): the camera is a fallback: ") +
                       (o.priorFocalPx ? "the EXIF focal length" : "a 60 degree field of view") +
                       (upCamera ? ", tilted to the vertical lines" : ", level"));
}

void runLayout(CameraEstimate& e, const EstimateOptions& o,
               const std::array<std::optional<Vec2>, 4>& fixed,
               const std::optional<std::array<Vec2, 4>>& start) {
  detail::LayoutInput li;
  li.camera = &e.camera;
  li.segments = &e.segments;
  li.fixedCornersPx = fixed;
  li.startCornersPx = start;
  li.edges = e.photoEdges.get();
  li.cancel = o.cancel;
  // The horizon is as sure as the vertical vanishing point (a fallback's is not measured).
  const double upSigmaDeg = e.vanishingPoints[1].angularSigmaDeg;
  li.rules.horizonSigmaRad = upSigmaDeg < 90 ? upSigmaDeg * M_PI / 180 : 0.0;
  li.refuseImplausible = o.refuseImplausibleBox;
  const auto lr = detail::estimateLayout(li);
  e.backWallPx = lr.cornersPx;
  e.layoutScore = lr.ok ? lr.score01 : 0.0;
  // One sentence about the box at most: what to do in the studio, then why.
  const auto dragAll = [&](const std::string& why) {
    detail::BoxDoubts d;
    d.refused = why;
    return "box layout: " + detail::boxAdvice(d, e.backWallPx, e.camera.widthPx, e.camera.heightPx);
  };
  const size_t before = e.warnings.size();
  if (!lr.ok) e.warnings.push_back(dragAll(lr.problem + "; the back wall is a default"));
  else if (!lr.advice.empty()) e.warnings.push_back("box layout: " + lr.advice);
  // A box the room builder accepts, or an ordinary room in front of the camera.
  if (!roomFromBackWall(e.camera, e.backWallPx).ok()) {
    bool anyFixed = false;
    for (const auto& f : fixed) anyFixed |= f.has_value();
    if (!anyFixed) {
      RoomBox box;
      box.xLeftM = -2.5;
      box.xRightM = 2.5;
      box.zBackM = -5.0;
      box.ceilingM = e.camera.heightM + 1.1;
      e.backWallPx = backWallCornersPx(e.camera, box);
      e.layoutScore = 0;
      e.warnings.resize(before);  // this replaces what the search said about its box
      e.warnings.push_back(dragAll("no valid back wall found; an ordinary 5 m room is assumed"));
    }
  }
}

// The best refined triplet of the search's best few rungs' winners (by refined score).
struct RefinedBest {
  bool have = false;
  double score = -1e300;
  Triplet triplet;
  Assignment as;
};

// Refine the best few rungs' winners; keep the best refined score. Nothing when cancelled.
std::optional<RefinedBest> refineCandidates(const Core& c, const SearchOutput& so,
                                            const RefineSettings& rs, const Prior& prior,
                                            const CancelToken* cancel) {
  RefinedBest best;
  for (size_t i = 0; i < std::min<size_t>(3, so.candidates.size()); ++i) {
    Assignment as;
    const Triplet tr = refine(c.segs, so.candidates[i].second, rs, 3, &as);
    const double sc = dataScore(c.segs, tr) - prior.penalty(tr.phi);
    if (sc > best.score) {
      best.score = sc;
      best.triplet = tr;
      best.as = as;
      best.have = true;
    }
    if (cancel && cancel->shouldStop()) return std::nullopt;
  }
  return best;
}

// The estimate from the best refined triplet, its axes in world order. Manhattan: one family
// far beyond chance (random lines reach z of about 11), a second one present (the third follows
// from orthogonality); else the fallback camera, tilted to the vertical lines when they are.
void estimateFromBest(CameraEstimate& e, Core& c, const RefinedBest& best, const RefineSettings& rs,
                      const Prior& prior, const EstimateOptions& o, Clock::time_point ts) {
  const auto order = axisOrder(best.triplet);
  Triplet w = ordered(best.triplet, order);
  Assignment as = best.as;
  for (int& f : as.family)
    if (f >= 0) f = int(std::find(order.begin(), order.end(), f) - order.begin());
  const Uncertainty u = uncertaintyOf(c.segs, as, w, rs);
  std::array<double, 3> z{};
  finish(e, c, w, as, u, rs, o, false, z);
  e.timings.refineMs = msSince(ts);
  std::array<double, 3> zs = z;
  std::sort(zs.begin(), zs.end());
  e.manhattan = zs[2] >= kStrongZ && zs[1] >= kPresentZ;
  if (!e.manhattan) {
    const bool vertical = z[1] >= kStrongZ;
    const Vec3 up = w.d[1];
    const double upConf = e.confidence[1];
    fallbackCamera(e, c, prior, o, vertical ? std::optional<Vec3>(up) : std::nullopt, upConf);
    return;
  }
  addVpWarnings(e);
  if (e.focalFromPrior)
    e.warnings.push_back(
        std::string("the focal length is not determined by the lines (vanishing points at "
                    "infinity); it comes from ") +
        (o.priorFocalPx ? "the EXIF focal length" : "a 60 degree field of view"));
}

// Segments -> vanishing-point search over focal rungs -> refinement of the best -> the estimate
// (or the fallback camera) -> the back wall.
Expected<CameraEstimate> estimateCore(Core& c, const EstimateOptions& o, Clock::time_point t0,
                                      CameraEstimate e) {
  const double workPx = 1.0 / std::max(1e-9, c.workingScale);  // one working pixel, in photo px
  buildSegs(c, o, 1.0 * workPx);
  double totalW = 0;
  for (const Seg& g : c.segs) totalW += g.weight;
  const Prior prior = makePrior(c, o, totalW);
  auto cancelled = [&] { return o.cancel && o.cancel->shouldStop(); };
  if (cancelled()) return Error{"", "estimate", "cancelled"};

  auto ts = Clock::now();
  SearchOutput so = search(c.segs, prior, std::max(1, o.searchIterations), o.seed, t0, o.cancel);
  e.progress = so.progress;
  e.timings.vanishingMs = msSince(ts);
  if (cancelled()) return Error{"", "estimate", "cancelled"};

  ts = Clock::now();
  RefineSettings rs;
  rs.pixelSigma = workPx;
  rs.prior = prior;
  rs.principalSigma = o.principalPx ? 0.0 : std::max(0.0, o.principalSigma);
  rs.cancel = o.cancel;
  const auto best = refineCandidates(c, so, rs, prior, o.cancel);
  if (!best) return Error{"", "estimate", "cancelled"};
  if (!so.progress.empty() && best->have) e.progress.push_back({msSince(t0) / 1000.0, best->score});
  if (best->have) {
    estimateFromBest(e, c, *best, rs, prior, o, ts);
  } else {
    for (auto& s : c.segments) s.family = -1;
    e.segments = c.segments;
    fallbackCamera(e, c, prior, o, std::nullopt, 0);
    e.timings.refineMs = msSince(ts);
  }

  ts = Clock::now();
  if (o.estimateLayout) runLayout(e, o, {}, std::nullopt);
  else
    e.backWallPx = {Vec2(0.25 * c.W, 0.25 * c.H), Vec2(0.75 * c.W, 0.25 * c.H),
                    Vec2(0.75 * c.W, 0.75 * c.H), Vec2(0.25 * c.W, 0.75 * c.H)};
  e.timings.layoutMs = msSince(ts);
  if (cancelled()) return Error{"", "estimate", "cancelled"};
  indexSupporters(e);
  e.timings.totalMs = msSince(t0);
  return e;
}

// The normalisation frame: centred on the known principal point if there is one (the refinement
// holds it there), else on the image centre (where the principal point's prior lies).
Core makeCore(int W, int H, const std::optional<Vec2>& principalPx = std::nullopt) {
  Core c;
  c.W = W;
  c.H = H;
  c.frame.centre = principalPx && principalPx->allFinite() ? *principalPx : Vec2(0.5 * W, 0.5 * H);
  c.frame.s = 0.5 * std::max(W, H);
  return c;
}

// ---------------------------------------------------------------------------------------------
// The correction (correctEstimate): check what the user fixed, add the user's lines to the
// previous estimate's segments, start from the previous camera turned toward the user's
// vanishing points, refit, then search the back wall again.

// Two user lines of one axis: finite, at least 2 pixels long, not the same line.
Status checkVanishingLines(const std::array<Vec2, 4>& p, int axis) {
  const std::string key = std::string("correction.vanishing_lines_px[") + kAxisName[axis] + "]";
  for (const Vec2& q : p)
    if (!q.allFinite()) return Error{"", key, "is not a finite number"};
  if ((p[1] - p[0]).norm() < 2 || (p[3] - p[2]).norm() < 2)
    return Error{"", key, "a line is shorter than 2 pixels"};
  const Vec3 l0 = Vec3(p[0].x(), p[0].y(), 1).cross(Vec3(p[1].x(), p[1].y(), 1));
  const double dist0 = std::abs(l0.dot(Vec3(p[2].x(), p[2].y(), 1))) / l0.head<2>().norm();
  const double dist1 = std::abs(l0.dot(Vec3(p[3].x(), p[3].y(), 1))) / l0.head<2>().norm();
  if (dist0 < 1 && dist1 < 1) return Error{"", key, "the two lines are the same line"};
  return Status::Ok();
}

// The correction's input errors (correctEstimate's header lists them), in the order of its keys.
Status checkCorrection(const Camera& pc, const EstimateCorrection& corr) {
  if (pc.widthPx <= 0 || pc.heightPx <= 0 || !pc.worldFromCamera.allFinite() || !(pc.focalPx > 0))
    return Error{"", "correction.previous", "is not an estimate of a photo"};
  if (corr.lockedFocalPx && !(std::isfinite(*corr.lockedFocalPx) && *corr.lockedFocalPx > 0))
    return Error{"", "correction.focal_px", "must be a positive finite number"};
  for (int k = 0; k < 3; ++k)
    if (corr.vanishingLinesPx[k])
      if (Status s = checkVanishingLines(*corr.vanishingLinesPx[k], k); !s) return s;
  if (corr.fixedCamera) {
    const Camera& f = *corr.fixedCamera;
    const Mat3& r = f.worldFromCamera;
    if (f.widthPx != pc.widthPx || f.heightPx != pc.heightPx)
      return Error{"", "correction.camera", "is for a photo of another size"};
    if (!(std::isfinite(f.focalPx) && f.focalPx > 0) || !f.principalPx.allFinite() || !r.allFinite() ||
        (r * r.transpose() - Mat3::Identity()).norm() > 1e-6 || std::abs(r.determinant() - 1) > 1e-6)
      return Error{"", "correction.camera", "is not a pinhole camera with a rotation"};
  }
  for (int i = 0; i < 4; ++i)
    if (corr.backWallCornersPx[i] && !corr.backWallCornersPx[i]->allFinite())
      return Error{"", "correction.back_wall_px[" + std::to_string(i) + "]", "is not a finite number"};
  return Status::Ok();
}

// The user's lines as segments of their family: explicit vanishing lines, and back-wall edges
// with both corners placed.
void addUserLines(Core& c, const EstimateCorrection& corr) {
  for (int k = 0; k < 3; ++k)
    if (corr.vanishingLinesPx[k]) {
      const auto& p = *corr.vanishingLinesPx[k];
      for (int j = 0; j < 2; ++j) {
        LineSegment s;
        s.aPx = p[2 * j];
        s.bPx = p[2 * j + 1];
        s.family = k;
        s.userGiven = true;
        c.segments.push_back(s);
      }
    }
  const auto& bc = corr.backWallCornersPx;
  const int edgeFamily[4] = {0, 1, 0, 1};  // TL-TR top (x), TR-BR right (y), BR-BL, BL-TL
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    if (bc[i] && bc[j] && (*bc[j] - *bc[i]).norm() >= 2) {
      LineSegment s;
      s.aPx = *bc[i];
      s.bPx = *bc[j];
      s.family = edgeFamily[i];
      s.userGiven = true;
      c.segments.push_back(s);
    }
  }
}

// The previous estimate's detected segments and the user's lines, about the principal point
// that is held: a fixed camera's, else the previous estimate's. It is the normalisation origin
// (vanishing points assume it).
Core correctionCore(const CameraEstimate& previous, const EstimateCorrection& corr) {
  const Camera& pc = previous.camera;
  Core c = makeCore(pc.widthPx, pc.heightPx);
  c.frame.centre = corr.fixedCamera ? corr.fixedCamera->principalPx : pc.principalPx;
  c.workingScale = previous.workingScale;
  for (const auto& s : previous.segments)
    if (!s.userGiven) c.segments.push_back(s);
  addUserLines(c, corr);
  return c;
}

// The focal length's prior: the caller's, else the previous estimate's held loosely.
Prior correctionPrior(const Core& c, const EstimateOptions& o, double previousFocalPx) {
  double totalW = 0;
  for (const Seg& g : c.segs) totalW += g.fixedFamily >= 0 ? 0 : g.weight;
  EstimateOptions po = o;
  if (!po.priorFocalPx) po.priorFocalPx = previousFocalPx;
  Prior prior = makePrior(c, po, totalW);
  if (!o.priorFocalPx) prior.sigma = o.priorLogSigmaDefault;
  return prior;
}

// Per axis, the user's vanishing point (normalised homogeneous) where two user lines give one.
std::array<std::optional<Vec3>, 3> userVanishingPoints(const Core& c) {
  std::array<std::optional<Vec3>, 3> userH;
  for (int k = 0; k < 3; ++k) {
    std::vector<const Seg*> lines;
    for (const Seg& g : c.segs)
      if (g.fixedFamily == k) lines.push_back(&g);
    if (lines.size() < 2) continue;
    const auto lineOf = [](const Seg* g) {
      return Vec3(g->a.x(), g->a.y(), 1).cross(Vec3(g->b.x(), g->b.y(), 1));
    };
    const Vec3 h = lineOf(lines[0]).cross(lineOf(lines[1]));
    if (h.norm() > 1e-12) userH[k] = h.normalized();
  }
  return userH;
}

// The refinement's start: the previous rotation, turned (least squares) toward the user's
// vanishing points; the focal length locked, or from two finite user points' orthogonality, or
// the previous one.
Triplet correctionStart(const Core& c, const EstimateCorrection& corr, const Camera& pc) {
  Triplet start;
  start.phi = (corr.lockedFocalPx ? *corr.lockedFocalPx : pc.focalPx) / c.frame.s;
  const std::array<std::optional<Vec3>, 3> userH = userVanishingPoints(c);
  if (!corr.lockedFocalPx) {
    for (int a = 0; a < 3; ++a)
      for (int b = a + 1; b < 3; ++b)
        if (userH[a] && userH[b] && std::abs(userH[a]->z()) > 1e-3 && std::abs(userH[b]->z()) > 1e-3) {
          const Vec3& p = *userH[a];
          const Vec3& q = *userH[b];
          const double f2 = -(p.x() * q.x() + p.y() * q.y()) / (p.z() * q.z());
          if (f2 > 0.05 * 0.05 && f2 < 200 * 200) start.phi = std::sqrt(f2);
        }
  }
  Mat3 target = Mat3::Zero();
  const Mat3 cw0 = pc.cameraFromWorld();
  for (int k = 0; k < 3; ++k) {
    Vec3 d = cw0.col(k);
    double w = 1;
    if (userH[k]) {
      // Camera direction of the user's VP, signed like the previous one.
      const Vec3& h = *userH[k];
      Vec3 u(h.x() / start.phi, -h.y() / start.phi, -h.z());
      u.normalize();
      if (u.dot(d) < 0) u = -u;
      d = u;
      w = 100;
    }
    target += w * d * Vec3::Unit(k).transpose();
  }
  Eigen::JacobiSVD<Mat3> svd(target, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 r = svd.matrixU() * svd.matrixV().transpose();
  if (r.determinant() < 0) {
    Mat3 u = svd.matrixU();
    u.col(2) = -u.col(2);
    r = u * svd.matrixV().transpose();
  }
  for (int k = 0; k < 3; ++k) start.d[k] = r.col(k);
  return start;
}

// The corrected triplet: a fixed camera kept as given (the segments only re-assigned to its
// vanishing points, its focal length locked in rs), else refined from the start.
Triplet fitCorrection(const Core& c, const EstimateCorrection& corr, const Triplet& start,
                      RefineSettings& rs, Assignment& as) {
  if (!corr.fixedCamera) return refine(c.segs, start, rs, 3, &as);
  Triplet tr;
  for (int k = 0; k < 3; ++k) tr.d[k] = corr.fixedCamera->cameraFromWorld().col(k);
  tr.phi = corr.fixedCamera->focalPx / c.frame.s;
  rs.lockPhi = true;
  as = assign(c.segs, tr);
  return tr;
}

// What the user fixed stays as fixed: the principal point held where the previous estimate put
// it (or the fixed camera's, exact), a fixed camera exactly; Manhattan once the photo or the
// user showed it.
void keepWhatWasFixed(CameraEstimate& e, const CameraEstimate& previous, const EstimateCorrection& corr,
                      std::array<double, 3> z) {
  e.principalSigmaPx = corr.fixedCamera ? Vec2::Zero() : previous.principalSigmaPx;
  e.principalFromPrior = corr.fixedCamera ? true : previous.principalFromPrior;
  if (corr.fixedCamera) {
    e.camera = *corr.fixedCamera;
    for (int k = 0; k < 3; ++k) {
      e.vanishingPoints[k].homogeneousPx = e.camera.vanishingPointOf(Vec3::Unit(k));
      e.vanishingPointsPx[k] = scenePixel(e.vanishingPoints[k].homogeneousPx, e.camera.principalPx);
    }
  }
  std::sort(z.begin(), z.end());
  e.manhattan = previous.manhattan || corr.fixedCamera || (z[2] >= kStrongZ && z[1] >= kPresentZ);
}

// The back wall again for the corrected camera. A small change of camera (a dragged corner, a
// nudged line) searches it locally from where it was, so it does not jump; a large one (or a
// camera the user typed) globally. Placed corners must make a room.
Status relayoutCorrected(CameraEstimate& e, const CameraEstimate& previous,
                         const EstimateCorrection& corr, const EstimateOptions& o) {
  const Camera& pc = previous.camera;
  const auto ts = Clock::now();
  const double turnDeg =
      std::acos(std::clamp(((pc.worldFromCamera.transpose() * e.camera.worldFromCamera).trace() - 1) / 2,
                           -1.0, 1.0)) /
      kDeg;
  const bool bigChange = corr.fixedCamera || turnDeg > 2.0 ||
                         std::abs(std::log(e.camera.focalPx / pc.focalPx)) > 0.05;
  runLayout(e, o, corr.backWallCornersPx,
            bigChange ? std::nullopt : std::optional<std::array<Vec2, 4>>(previous.backWallPx));
  e.timings.layoutMs = msSince(ts);
  bool anyFixed = false;
  for (const auto& f : corr.backWallCornersPx) anyFixed |= f.has_value();
  if (anyFixed) {
    const auto room = roomFromBackWall(e.camera, e.backWallPx);
    if (!room.ok()) return room.error().underKey("correction");
  }
  return Status::Ok();
}

}  // namespace

Expected<CameraEstimate> estimateCameraFromSegments(int widthPx, int heightPx,
                                                    const std::vector<LineSegment>& segments,
                                                    const EstimateOptions& options) {
  const auto t0 = Clock::now();
  if (widthPx <= 0 || heightPx <= 0) return Error{"", "photo", "the image has no pixels"};
  Core c = makeCore(widthPx, heightPx, options.principalPx);
  for (const auto& s : segments) {
    if (!s.aPx.allFinite() || !s.bPx.allFinite()) continue;
    LineSegment t = s;
    t.family = -1;
    t.userGiven = false;
    c.segments.push_back(t);
  }
  std::sort(c.segments.begin(), c.segments.end(),
            [](const LineSegment& a, const LineSegment& b) { return a.lengthPx() > b.lengthPx(); });
  if (int(c.segments.size()) > options.maxSegments) c.segments.resize(std::max(0, options.maxSegments));
  CameraEstimate e;
  return estimateCore(c, options, t0, e);
}

Expected<CameraEstimate> estimateCamera(const ImageF& linearRgb, const EstimateOptions& options) {
  const auto t0 = Clock::now();
  if (linearRgb.width <= 0 || linearRgb.height <= 0 || linearRgb.empty())
    return Error{"", "photo", "the image has no pixels"};
  if (linearRgb.channels != 1 && linearRgb.channels != 3 && linearRgb.channels != 4)
    return Error{"", "photo",
                 "has " + std::to_string(linearRgb.channels) + " channels (1, 3 or 4 expected)"};
  if (linearRgb.data.size() != linearRgb.pixelCount() * size_t(linearRgb.channels))
    return Error{"", "photo", "the pixel buffer does not match its size"};
  Core c = makeCore(linearRgb.width, linearRgb.height, options.principalPx);
  const auto dl = detail::detectLineSegments(linearRgb, std::max(16, options.maxWorkingSidePx),
                                             std::max(0, options.maxSegments), options.cancel);
  if (options.cancel && options.cancel->shouldStop()) return Error{"", "estimate", "cancelled"};
  c.segments = dl.segments;
  c.workingScale = dl.workingScale;
  CameraEstimate e;
  e.workingScale = dl.workingScale;
  e.photoEdges = dl.edges;
  e.timings.linesMs = msSince(t0);
  return estimateCore(c, options, t0, e);
}

Expected<CameraEstimate> correctEstimate(const CameraEstimate& previous, const EstimateCorrection& corr,
                                         const EstimateOptions& o) {
  const auto t0 = Clock::now();
  const Camera& pc = previous.camera;
  if (Status s = checkCorrection(pc, corr); !s) return s.error();

  CameraEstimate e;
  e.workingScale = previous.workingScale;
  e.photoEdges = previous.photoEdges;
  Core c = correctionCore(previous, corr);
  const double workPx = 1.0 / std::max(1e-9, c.workingScale);
  buildSegs(c, o, workPx);
  const Prior prior = correctionPrior(c, o, pc.focalPx);
  const Triplet start = correctionStart(c, corr, pc);

  RefineSettings rs;
  rs.pixelSigma = workPx;
  rs.prior = prior;
  rs.lockPhi = corr.lockedFocalPx.has_value();
  rs.cancel = o.cancel;
  const auto ts = Clock::now();
  Assignment as;
  Triplet tr = fitCorrection(c, corr, start, rs, as);
  if (o.cancel && o.cancel->shouldStop()) return Error{"", "estimate", "cancelled"};
  if (rs.lockPhi && !corr.fixedCamera) tr.phi = *corr.lockedFocalPx / c.frame.s;
  // Keep the world-axis meaning the user worked with; only re-apply the sign rules.
  const Triplet w = ordered(tr, {0, 1, 2});
  const Uncertainty u = uncertaintyOf(c.segs, as, w, rs);
  std::array<double, 3> z{};
  finish(e, c, w, as, u, rs, o, rs.lockPhi, z);
  keepWhatWasFixed(e, previous, corr, z);
  addVpWarnings(e);
  e.timings.refineMs = msSince(ts);

  if (Status s = relayoutCorrected(e, previous, corr, o); !s) return s.error();
  indexSupporters(e);
  e.timings.totalMs = msSince(t0);
  return e;
}

namespace detail {

double segmentResidualGradientError() {
  struct Case {
    Vec2 a, b;
    Vec3 d0;
    double logPhi;
    double omega[3];
    double pp[2];
  };
  const Case cases[] = {
      {{-0.3, 0.2},
       {0.4, 0.25},
       Vec3(1, 0.05, 0.3).normalized(),
       std::log(1.2),
       {0.01, -0.02, 0.03},
       {0.02, -0.03}},
      {{0.1, -0.5}, {0.12, 0.5}, Vec3(0, 1, 0), std::log(0.8), {0, 0, 0}, {0, 0}},  // VP at infinity
      {{-0.5, 0.0},
       {0.5, 0.0},
       Vec3(1, 0, 0),
       std::log(2.0),
       {0.0, 0.0, 0.0},
       {0.05, 0.0}},  // both at infinity
      {{0.2, 0.1},
       {-0.3, -0.2},
       Vec3(0.1, -0.2, -1).normalized(),
       std::log(5.0),
       {0.2, -0.1, 0.05},
       {-0.04, 0.01}},
      {{0.0, 0.0},
       {0.3, 0.1},
       Vec3(0.3, -0.1, -1).normalized(),
       std::log(1.0),
       {0, 0, 0},
       {0, 0}},  // aimed at its VP
  };
  double worst = 0;
  for (const Case& k : cases) {
    Seg g;
    g.a = k.a;
    g.b = k.b;
    g.m = 0.5 * (k.a + k.b);
    g.t = (k.b - k.a).normalized();
    g.halfLenPx = 0.5 * (k.b - k.a).norm() * 400;
    RefineSettings rs;
    const SegmentCost cost = costOf(g, k.d0, rs);
    ceres::AutoDiffCostFunction<SegmentCost, 1, 3, 1, 2> ad(new SegmentCost(cost));
    double omega[3] = {k.omega[0], k.omega[1], k.omega[2]}, logPhi = k.logPhi;
    double pp[2] = {k.pp[0], k.pp[1]};
    const double* params[3] = {omega, &logPhi, pp};
    double r = 0, j0[3] = {}, j1[1] = {}, j2[2] = {};  // Evaluate fills them
    double* jac[3] = {j0, j1, j2};
    ad.Evaluate(params, &r, jac);
    const double analytic[6] = {j0[0], j0[1], j0[2], j1[0], j2[0], j2[1]};
    for (int j = 0; j < 6; ++j) {
      double x[6] = {omega[0], omega[1], omega[2], logPhi, pp[0], pp[1]}, xp[6], xm[6], rp, rm;
      const double h = 1e-6;
      std::copy(x, x + 6, xp);
      std::copy(x, x + 6, xm);
      xp[j] += h;
      xm[j] -= h;
      cost(xp, xp + 3, xp + 4, &rp);
      cost(xm, xm + 3, xm + 4, &rm);
      const double numeric = (rp - rm) / (2 * h);
      const double err = std::abs(numeric - analytic[j]) / std::max(1.0, std::abs(numeric));
      worst = std::max(worst, err);
    }
  }
  return worst;
}

}  // namespace detail

}  // namespace inlay
