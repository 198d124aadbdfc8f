#include "inlay/lighting/estimate.h"

#include "inlay/lighting/gather.h"

#include "inlay/render/path_tracer.h"

#include <Eigen/Cholesky>
#include <ceres/ceres.h>
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include "inlay/modeling/cpu_time.h"
#include "inlay/modeling/fingerprint.h"
#include "inlay/modeling/parallel.h"
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <functional>
#include <limits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <numeric>
#include <optional>
#include <random>
#include <time.h>

namespace inlay {

namespace {

struct PixelSurface {
  int surface = -1;
  Vec3 point;
  Vec3 normal;
  double depth = 0;
};

// A gather ray's hit on a room point the photo does not show, and its sampleId (RadianceAt).
struct UnseenRay {
  SurfaceHit hit;
  uint32_t sampleId = 0;
};

// The gather rays of one point, traced once: the photo pixel each ray that lands on a seen
// point reads, the hits on unseen points, and every ray (those that leave the room count as 0).
struct PointRays {
  std::vector<int32_t> seen;
  std::vector<UnseenRay> unseen;
  int rays = 0;
};

// Per ray of a PointRays that lands where the camera does not see: its patch (SurfacePatches::
// find, -1: none) and its unit direct light from each area light and sun (e[k * C + j]), the
// parts of radianceAt's prediction there that stay the same through an estimate's passes.
struct UnseenLights {
  std::vector<int> patch;
  std::vector<double> e;
};

// The albedo the light fit gives a surface hit by the gather where the camera does not see it,
// in its unknowns: a constant plus weighted fitted albedos (the surface's own where the fit has
// its pixels, else the mean of the fitted walls or of every fitted surface, as albedoOfUnseen).
struct UnseenAlbedo {
  Vec3 constant = Vec3::Zero();
  std::vector<std::pair<int, double>> fitted;  // (surface, weight)
};

// Adds the wall and CPU seconds of its lifetime to the step `name` of `steps` (LightingEstimate::
// steps), which it appends on its first call.
class StepTimer {
 public:
  StepTimer(std::vector<LightingStepTime>& steps, const char* name)
      : steps_(steps), name_(name), t0_(std::chrono::steady_clock::now()), cpu0_(processCpuSeconds()) {}
  StepTimer(const StepTimer&) = delete;
  StepTimer& operator=(const StepTimer&) = delete;
  ~StepTimer() {
    auto it = std::find_if(steps_.begin(), steps_.end(),
                           [&](const LightingStepTime& s) { return s.name == name_; });
    if (it == steps_.end()) it = steps_.insert(steps_.end(), LightingStepTime{name_, 0, 0, 0});
    it->seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    it->cpuSeconds += processCpuSeconds() - cpu0_;
    it->calls += 1;
  }

 private:
  std::vector<LightingStepTime>& steps_;
  const char* name_;
  std::chrono::steady_clock::time_point t0_;
  double cpu0_;
};

// The light a sun's clipped sunlit patch on one surface bounces to a pixel: sun strength x the
// patch surface's albedo x `g` (the gathered irradiance / pi of that patch under a unit sun and
// unit albedo). `rhoBlock` and `sunBlock` index the residual's parameter blocks.
struct BounceTerm {
  int rhoBlock = 0, sunBlock = 0;
  double g = 0;
};

// The fit: per pixel and channel, log B = log rho_s + log(sum_j L_j E_j + Gamma).
// A clipped pixel (lowerBoundOnly) only says the prediction reaches the clip level.
struct LogResidual {
  LogResidual(double logBIn, double gammaIn, std::vector<double> eIn, bool lowerBoundOnlyIn = false,
              double gammaClippedIn = -1, std::vector<BounceTerm> bounceIn = {})
      : logB(logBIn),
        gamma(gammaIn),
        e(std::move(eIn)),
        lowerBoundOnly(lowerBoundOnlyIn),
        gammaClipped(gammaClippedIn),
        bounce(std::move(bounceIn)) {}
  double logB, gamma;
  std::vector<double> e;
  bool lowerBoundOnly;
  double gammaClipped;
  std::vector<BounceTerm> bounce;
};

// The residual of a LogResidual and its derivatives, written out (Ceres' automatic
// differentiation of it took about 40 % of the light fit: 2.3 s of CPU per estimate at 816 x 612
// against 1.4 s; the same values). Parameter blocks (one value each): params[0] rho, then each
// light's radiance channel, then (when gammaClipped >= 0) the extra gain of the light gathered
// from clipped pixels, then the albedos of the sunlit patches' surfaces other than this pixel's.
// With shading S,
//   d/d rho = -1/rho, d/d L_j = -e_j / S, d/d gain = -gammaClipped / S, and per bounce term
//   d/d sun = -rho_b g / S, d/d rho_b = -sun g / S;
// zero where a lower bound holds (the residual clamped to 0).
class LogResidualCost final : public ceres::CostFunction {
 public:
  LogResidualCost(LogResidual r, int blocks) : r_(std::move(r)) {
    for (int k = 0; k < blocks; ++k) mutable_parameter_block_sizes()->push_back(1);
    set_num_residuals(1);
  }
  bool Evaluate(double const* const* params, double* residual, double** jacobians) const override {
    const size_t J = r_.e.size();
    double shading = r_.gamma;
    for (size_t j = 0; j < J; ++j) shading += params[1 + j][0] * r_.e[j];
    if (r_.gammaClipped >= 0) shading += params[1 + J][0] * r_.gammaClipped;
    for (const BounceTerm& t : r_.bounce) shading += params[t.sunBlock][0] * params[t.rhoBlock][0] * t.g;
    const double s = shading + 1e-9;
    residual[0] = r_.logB - std::log(params[0][0]) - std::log(s);
    const bool clamped = r_.lowerBoundOnly && residual[0] < 0;
    if (clamped) residual[0] = 0;
    if (!jacobians) return true;
    const int blocks = int(parameter_block_sizes().size());
    double d[64];
    std::vector<double> big;
    double* g = d;
    if (blocks > 64) big.assign(size_t(blocks), 0.0), g = big.data();
    std::fill(g, g + blocks, 0.0);
    if (!clamped) {
      g[0] = -1 / params[0][0];
      for (size_t j = 0; j < J; ++j) g[1 + j] = -r_.e[j] / s;
      if (r_.gammaClipped >= 0) g[1 + J] = -r_.gammaClipped / s;
      for (const BounceTerm& t : r_.bounce) {
        g[t.sunBlock] -= params[t.rhoBlock][0] * t.g / s;
        g[t.rhoBlock] -= params[t.sunBlock][0] * t.g / s;
      }
    }
    for (int k = 0; k < blocks; ++k)
      if (jacobians[k]) jacobians[k][0] = g[k];
    return true;
  }

 private:
  LogResidual r_;
};

// The weak prior of the unseen ceiling's albedo a the fit estimates (LightingOptions::
// fitUnseenCeiling): w log(a / m), m = constant + sum_k weight_k rho_k the fitted walls' mean
// (an UnseenAlbedo). Parameter blocks (one value each): params[0] a, then the walls' albedos in
// the order of `weights`. Derivatives: d/d a = w / a, d/d rho_k = -w weight_k / m.
class CeilingPriorCost final : public ceres::CostFunction {
 public:
  CeilingPriorCost(double w, double constant, std::vector<double> weights)
      : w_(w), constant_(constant), weights_(std::move(weights)) {
    for (size_t k = 0; k <= weights_.size(); ++k) mutable_parameter_block_sizes()->push_back(1);
    set_num_residuals(1);
  }
  bool Evaluate(double const* const* params, double* residual, double** jacobians) const override {
    double m = constant_;
    for (size_t k = 0; k < weights_.size(); ++k) m += weights_[k] * params[1 + k][0];
    m = std::max(m, 1e-9);
    const double a = std::max(params[0][0], 1e-9);
    residual[0] = w_ * std::log(a / m);
    if (!jacobians) return true;
    if (jacobians[0]) jacobians[0][0] = w_ / a;
    for (size_t k = 0; k < weights_.size(); ++k)
      if (jacobians[1 + k]) jacobians[1 + k][0] = -w_ * weights_[k] / m;
    return true;
  }

 private:
  double w_, constant_;
  std::vector<double> weights_;
};

// The information a Gauss-Newton matrix `info` leaves to unknown k once every other unknown is
// fitted alongside (the Schur complement info_kk - info_ko info_oo^-1 info_ok; a ridge of 1e-9 of
// the mean diagonal keeps info_oo invertible where an unknown is told nothing); >= 0, 0 when
// not finite.
double schurInformation(const Eigen::MatrixXd& info, long k) {
  const long n = info.rows();
  if (k < 0 || k >= n) return 0;
  std::vector<long> others;
  for (long i = 0; i < n; ++i)
    if (i != k) others.push_back(i);
  const long m = long(others.size());
  Eigen::MatrixXd oo(m, m);
  Eigen::VectorXd ok(m);
  for (long i = 0; i < m; ++i) {
    ok[i] = info(others[size_t(i)], k);
    for (long j = 0; j < m; ++j) oo(i, j) = info(others[size_t(i)], others[size_t(j)]);
  }
  const double ridge = 1e-9 * (info.trace() / double(n)) + 1e-300;
  oo.diagonal().array() += ridge;
  const double left = m > 0 ? info(k, k) - ok.dot(oo.ldlt().solve(ok)) : info(k, k);
  return std::isfinite(left) ? std::max(0.0, left) : 0.0;
}

// J^T J of a Jacobian (a Gauss-Newton matrix; dense, the fit has few unknowns).
Eigen::MatrixXd gaussNewtonMatrix(const ceres::CRSMatrix& jac) {
  Eigen::MatrixXd info = Eigen::MatrixXd::Zero(jac.num_cols, jac.num_cols);
  for (int r = 0; r < jac.num_rows; ++r)
    for (int i = jac.rows[size_t(r)]; i < jac.rows[size_t(r) + 1]; ++i)
      for (int j = jac.rows[size_t(r)]; j < jac.rows[size_t(r) + 1]; ++j)
        info(jac.cols[size_t(i)], jac.cols[size_t(j)]) += jac.values[size_t(i)] * jac.values[size_t(j)];
  return info;
}

// What the first fit knows of the room, used in the second pass to predict the radiance of
// what the camera does not see (the wall behind it, parts out of frame) instead of guessing
// it from the mean of what it does see.
struct RoomModel {
  bool active = false;
  std::vector<Vec3> rho;        // per surface
  std::vector<Vec3> gammaMean;  // per surface, mean gathered light over its visible pixels
  std::vector<Vec3> lights;     // radiance per light
  SurfacePatches patches;       // gathered light per patch (where no photo pixel tells)
  // With suns: the part of patches.gamma that the suns' light brought (their clipped patches'
  // light and their direct light on unseen surfaces, bounced), at the strengths in `lights`.
  std::vector<Vec3> sunGamma;
};

// Where an estimate's passes stood when they stopped (LightingOptions::warmStart): the room model
// its last pass predicted the unseen room from, that pass's Gamma before its fit (relaxed) and
// the clipped pixels' gain in it.
struct PassState {
  RoomModel model;
  ImageF gathered;
  std::array<double, 3> clippedGainApplied = {0, 0, 0};
};

}  // namespace

// The rays an estimate traced (LightingEstimate::rays): per gather grid point, and per radiosity
// sweep and patch; `key` fingerprints everything their hits depend on (fingerprintOfRays).
struct LightingRays {
  uint64_t key = 0;
  std::vector<PointRays> grid;
  std::vector<std::vector<PointRays>> patchSweeps;
  std::optional<PassState> passes;  // the tracing estimate's, for a warm-started refit
};

// Per surface: `albedo` where `weight` > 0 (seen), else a guess from what is seen: walls the
// weighted mean of the seen walls, the ceiling that or `ceilingAtLeast` grey when that is
// darker, anything else the mean of every seen surface; mid grey when nothing
// is seen.
std::vector<Vec3> albedoOfUnseen(const SceneGeometry& geometry, const std::vector<Vec3>& albedo,
                                 const std::vector<double>& weight, double ceilingAtLeast) {
  Vec3 wallSum = Vec3::Zero(), roomSum = Vec3::Zero();
  double wallN = 0, roomN = 0;
  for (size_t s = 0; s < albedo.size(); ++s) {
    if (!(weight[s] > 0)) continue;
    if (isWall(geometry.surfaces[s].kind)) wallSum += weight[s] * albedo[s], wallN += weight[s];
    roomSum += weight[s] * albedo[s], roomN += weight[s];
  }
  const Vec3 roomMean = roomN > 0 ? Vec3(roomSum / roomN) : Vec3(0.5, 0.5, 0.5);
  const Vec3 wallMean = wallN > 0 ? Vec3(wallSum / wallN) : roomMean;
  const Vec3 ceiling = luminance(wallMean) >= ceilingAtLeast ? wallMean
                                                             : Vec3(Vec3::Constant(ceilingAtLeast));
  std::vector<Vec3> out(albedo.size());
  for (size_t s = 0; s < albedo.size(); ++s) {
    const SurfaceKind k = geometry.surfaces[s].kind;
    out[s] = weight[s] > 0               ? albedo[s]
             : k == SurfaceKind::Ceiling ? ceiling
             : isWall(k)                 ? wallMean
                                         : roomMean;
  }
  return out;
}

namespace {

// The radiance the fitted model gives the clipped sunlit pixels: the surface's albedo times
// (lights + the gathered light [+ suns]). With the suns, at least the photo's clipped value;
// without them, the part that does not scale with the suns' strength (the fit gathers the
// suns' part apart, per unit strength).
template <class PixelSurfaceT>
std::vector<Vec3> predictedBeamRadiance(const ImageF& photo, const std::vector<uint8_t>& inBeam,
                                        const std::vector<PixelSurfaceT>& ps,
                                        const std::vector<Vec3>& rho, const ImageF& gathered,
                                        const std::vector<double>& E,
                                        const std::vector<AreaLight>& lights,
                                        const std::vector<SunLight>& suns, bool withSuns) {
  const size_t N = photo.pixelCount(), J = lights.size(), C = J + suns.size();
  std::vector<Vec3> out(N, Vec3::Zero());
  for (size_t idx = 0; idx < N; ++idx) {
    if (!inBeam[idx] || ps[idx].surface < 0) continue;
    const int x = int(idx % size_t(photo.width)), y = int(idx / size_t(photo.width));
    Vec3 irradiance = gathered.rgb(x, y);
    for (size_t j = 0; j < J; ++j) irradiance += lights[j].radiance * E[idx * C + j];
    for (size_t k = 0; k < suns.size() && withSuns; ++k)
      irradiance += suns[k].irradianceOverPi * E[idx * C + J + k];
    const Vec3 b = photo.rgb(x, y);
    const Vec3 predicted = rho[size_t(ps[idx].surface)].cwiseProduct(irradiance);
    out[idx] = b.allFinite() && withSuns ? Vec3(predicted.cwiseMax(b)) : predicted;
  }
  return out;
}

// Mixes the new gathered light into the previous pass's (gathered <- r gathered + (1 - r)
// previous) and returns the relative change of its mean from the previous one (infinity when
// there is none).
double relaxGathered(ImageF& gathered, const ImageF& previous, double r) {
  if (previous.data.size() != gathered.data.size() || previous.data.empty())
    return std::numeric_limits<double>::infinity();
  double sumNew = 0, sumOld = 0;
  for (size_t i = 0; i < gathered.data.size(); ++i) {
    const double mixed = r * double(gathered.data[i]) + (1 - r) * double(previous.data[i]);
    gathered.data[i] = float(std::isfinite(mixed) ? mixed : previous.data[i]);
    sumNew += gathered.data[i];
    sumOld += previous.data[i];
  }
  return sumOld > 0 ? std::abs(sumNew - sumOld) / sumOld : std::numeric_limits<double>::infinity();
}

}  // namespace

namespace {

std::string pixelText(const Vec2& p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%.0f, %.0f)", p.x(), p.y());
  return buf;
}

// A room surface's name in a sentence ("the left wall", "table 1's top").
std::string surfaceText(const SceneGeometry& g, int id) {
  switch (g.surfaces[size_t(id)].kind) {
    case SurfaceKind::Floor: return "the floor";
    case SurfaceKind::Ceiling: return "the ceiling";
    case SurfaceKind::WallLeft: return "the left wall";
    case SurfaceKind::WallRight: return "the right wall";
    case SurfaceKind::WallBack: return "the back wall";
    case SurfaceKind::WallRear: return "the wall behind the camera";
    default: return "surface '" + g.surfaces[size_t(id)].name + "'";
  }
}

// Why outline point i cannot be carried onto the plane of `surface`, where most of the outline
// lies, and what to do. Its ray meets that plane only behind the camera, or runs along it
// (den ~ 0): the point lies on another surface, and the room box puts the two where the photo
// does not (a wall too far out, a floor crease too high), or the outline crosses a corner.
std::string offSurfaceMessage(const Camera& camera, const SceneGeometry& g,
                              const std::vector<Vec2>& outlinePx, const std::vector<SurfaceHit>& hits,
                              size_t i, int surface, double den) {
  const std::string on = surfaceText(g, surface), here = surfaceText(g, hits[i].surfaceId);
  const SurfaceKind kind = g.surfaces[size_t(surface)].kind;
  std::string out = "point " + std::to_string(i) + " " + pixelText(outlinePx[i]) + " lies on " + here +
                    ", but most of the outline lies on " + on + ", whose plane its ray " +
                    (std::abs(den) < 1e-9 ? "runs along" : "meets only behind the camera") +
                    ": the outline cannot lie on one surface. ";
  if (isBoxSurface(kind))
    out += "Either the room box puts " + on + " where the photo does not show it (" +
           roomBoxAdvice(camera, g.box, kind) + "), or the outline crosses onto " + here +
           " (outline the light within one surface)";
  else out += "Outline the light within one surface";
  if (kind == SurfaceKind::Floor || kind == SurfaceKind::Ceiling) {
    const double y = horizonRowPx(camera, outlinePx[i].x());
    if (std::isfinite(y)) {
      char buf[96];
      std::snprintf(buf, sizeof buf, " (points on the %s are %s the horizon, row y = %.0f there)",
                    kind == SurfaceKind::Floor ? "floor" : "ceiling",
                    kind == SurfaceKind::Floor ? "below" : "above", y);
      out += buf;
    }
  }
  return out;
}

}  // namespace

Expected<AreaLight> lightFromOutline(const Camera& camera, const SceneGeometry& geometry,
                                     const std::vector<Vec2>& outlinePx, const std::string& key) {
  if (outlinePx.size() < 3) return Error{"", key, "a light outline needs at least 3 points"};
  std::vector<SurfaceHit> hits;
  std::vector<int> count(geometry.surfaces.size(), 0);
  for (size_t i = 0; i < outlinePx.size(); ++i) {
    if (!outlinePx[i].allFinite())
      return Error{"", key + "[" + std::to_string(i) + "]", "is not a finite number"};
    const auto h = geometry.intersect(camera.rayThroughPixel(outlinePx[i]));
    if (!h)
      return Error{"", key + "[" + std::to_string(i) + "]",
                   "point " + std::to_string(i) + " " + pixelText(outlinePx[i]) +
                       " does not fall on any surface of the room: " +
                       roomBoxAdvice(camera, geometry.box, SurfaceKind::WallBack)};
    hits.push_back(*h);
    ++count[h->surfaceId];
  }
  const int surface = int(std::max_element(count.begin(), count.end()) - count.begin());
  // Plane of the majority surface; points on other surfaces are projected onto it.
  Vec3 n(0, 0, 0), c(0, 0, 0);
  int k = 0;
  for (const auto& h : hits)
    if (h.surfaceId == surface) {
      n = h.normalWorld;
      c += h.pointWorld;
      ++k;
    }
  c /= k;
  std::vector<Vec3> pts;
  for (size_t i = 0; i < outlinePx.size(); ++i) {
    const Ray r = camera.rayThroughPixel(outlinePx[i]);
    const double den = r.direction.dot(n);
    const double t = std::abs(den) < 1e-9 ? -1.0 : (c - r.origin).dot(n) / den;
    if (!(t > 0))
      return Error{"", key, offSurfaceMessage(camera, geometry, outlinePx, hits, i, surface, den)};
    pts.push_back(r.at(t));
  }
  // An in-plane frame along the room's axes: lights on the ceiling are rectangles aligned with
  // it. Four points are kept as the user drew them; more become their bounding rectangle.
  Vec3 u = std::abs(n.y()) > 0.7 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  u = (u - u.dot(n) * n).normalized();
  const Vec3 v = n.cross(u);
  // The outline's own area (shoelace in the plane): a degenerate outline is refused even when
  // its bounding rectangle would not be.
  double polyArea = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    const Vec3 a = pts[i] - c, b = pts[(i + 1) % pts.size()] - c;
    polyArea += a.dot(u) * b.dot(v) - b.dot(u) * a.dot(v);
  }
  if (!(std::abs(0.5 * polyArea) > 1e-6)) return Error{"", key, "the light outline has no area"};
  AreaLight L;
  if (pts.size() == 4) {
    for (int i = 0; i < 4; ++i) L.cornersWorld[i] = pts[i];
  } else {
    double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
    for (const Vec3& p : pts) {
      u0 = std::min(u0, (p - c).dot(u));
      u1 = std::max(u1, (p - c).dot(u));
      v0 = std::min(v0, (p - c).dot(v));
      v1 = std::max(v1, (p - c).dot(v));
    }
    L.cornersWorld = {c + u0 * u + v0 * v, c + u1 * u + v0 * v, c + u1 * u + v1 * v,
                      c + u0 * u + v1 * v};
  }
  // Points beyond the surface's edge (on a neighbouring wall) were carried past it by the
  // projection onto the plane: the light is clipped to the room's box.
  const RoomBox& b = geometry.box;
  const Vec3 lo(b.xLeftM, 0.0, b.zBackM), hi(b.xRightM, b.ceilingM, b.zRearM);
  for (auto& p : L.cornersWorld) p = p.cwiseMax(lo).cwiseMin(hi);
  if (!(L.area() > 1e-6)) return Error{"", key, "the light outline has no area inside the room"};
  // Face into the room (the hit normal faces the camera side), 1 mm off the surface.
  if (L.normal().dot(n) < 0) std::swap(L.cornersWorld[1], L.cornersWorld[3]);
  for (auto& p : L.cornersWorld) p += 1e-3 * n;
  L.radiance = Vec3(1, 1, 1);
  return L;
}

namespace {

// The state the steps of estimateLighting share: its inputs, the surface behind every pixel, the
// lights' direct light per pixel, and what each gather-and-fit pass leaves to the next. Each
// member function is one named step (the numbers follow the order estimateLighting runs them).
struct LightingFit {
  LightingFit(const ImageF& photoIn, const Camera& cameraIn, const SceneGeometry& geometryIn,
              const std::vector<AreaLight>& lightsGiven, const std::vector<bool>& refineGiven,
              const ImageF& lightMaskIn, const std::vector<SunLight>& sunsIn,
              const LightingOptions& options)
      : photo(photoIn),
        camera(cameraIn),
        geometry(geometryIn),
        lightsIn(lightsGiven),
        refineIn(refineGiven),
        lightMask(lightMaskIn),
        suns(sunsIn),
        opt(options),
        W(photoIn.width),
        H(photoIn.height),
        S(geometryIn.surfaces.size()),
        J(lightsGiven.size()),
        K(sunsIn.size()),
        C(lightsGiven.size() + sunsIn.size()),
        tracer(geometryIn),
        stride(gatherStrideFor(photoIn.width, photoIn.height, options.gatherStride,
                               options.gatherMaxPoints)),
        GW((W + stride - 1) / stride),
        GH((H + stride - 1) / stride),
        gatherSamples(options.gatherSamples) {}

  // Inputs.
  const ImageF& photo;
  const Camera& camera;
  const SceneGeometry& geometry;
  const std::vector<AreaLight>& lightsIn;
  const std::vector<bool>& refineIn;
  const ImageF& lightMask;
  const std::vector<SunLight>& suns;
  const LightingOptions& opt;
  const int W, H;
  const size_t S, J, K;
  const size_t C;  // unknown light strengths: area lights, then suns
  RoomTracer tracer;
  LightingEstimate out;

  // 1. The first surface behind every pixel.
  std::vector<PixelSurface> ps;
  // 2. Mean radiance of each surface where the photo shows it.
  std::vector<Vec3> surfaceRadiance;

  RoomModel model;
  // Gain already given to clipped pixels' radiance (after the first fit): radianceAt returns
  // b (1 + gain) there, so the second pass predicts the unseen parts with the fitted light.
  std::array<double, 3> clippedGainApplied = {0, 0, 0};
  // Clipped pixels inside a sun's beam (a sunlit patch): the model predicts their radiance, so
  // they take that prediction (at least the clip level) instead of the gain fitted to the
  // clipped pixels no light explains (a window's sky, a lamp), which is far brighter.
  std::vector<uint8_t> clippedInBeam;  // W x H, filled once the suns' E is known
  std::vector<Vec3> beamRadiance;      // W x H, the prediction (pass 2; the photo in pass 1)
  // Pass 2's fit gathers the suns' share of those pixels, and of the beam where the camera does
  // not see it, apart (sunBounceAt), per unit strength and albedo, so that it ties the light the
  // sunlit patch bounces onto the walls to the sun's strength: radianceAt then gives those pixels
  // only the rest (beamRadianceNoSun) and unseen points no sunlight.
  bool sunApart = false;
  std::vector<Vec3> beamRadianceNoSun;
  // A few clipped pixels send too little light to tell their gain.
  bool fitClipped = false;
  ImageF gatheredClipped;
  std::array<double, 3> clippedGain = {0, 0, 0};

  // 3. E_j on a coarse grid (Gamma too, per pass), spread to every pixel of the same surface.
  const int stride, GW, GH;
  std::vector<double> gridE;
  std::vector<int> gridSurface;
  std::vector<Vec2> gridPixel;
  int gatherSamples;
  std::vector<double> E;  // W x H x C: unit direct light of each area light and sun
  // Pass 2's bounce terms: (sun, patch surface) pairs and their gathered g (W x H, one channel).
  struct SunPatch {
    size_t sun = 0;
    int surface = 0;
    ImageF g;
  };
  std::vector<SunPatch> sunPatches;

  // 4. The light fit's pixels and unknowns, and the photo it fits (fitPhoto: the mean over a small
  // window of the same surface, LightingOptions::fitWindow).
  std::vector<size_t> candidates;
  ImageF fitPhoto;
  std::vector<bool> refine;
  // Per area light: the light whose radiance it shares (LightingOptions::tieLightsOutOfView), or
  // itself.
  std::vector<size_t> tiedTo;
  std::vector<std::array<double, 3>> rho;
  std::vector<std::array<double, 3>> L;
  std::array<int, 3> fitIterations = {0, 0, 0};  // per channel, over the passes

  // 5. B / (sum L_j E_j + Gamma), unclamped, and sum L_j E_j / shading (green) per pixel.
  ImageF shadingFree;
  std::vector<float> directShare;

  // The gather's and the patches' rays, traced once and replayed by every pass (and by a refit
  // given them: LightingOptions::reuseRays). `tracing`: this estimate fills them.
  std::shared_ptr<const LightingRays> rays;  // what the passes read
  std::shared_ptr<LightingRays> traced;      // what this estimate traces (null: rays reused)
  // The unseen rays' patches and unit direct light (this estimate's lights), per grid point and
  // per sweep and patch: filled by the first pass that predicts the unseen room, read by the rest.
  std::vector<UnseenLights> gridLights;
  std::vector<std::vector<UnseenLights>> patchLights;
  // The unseen room's first bounce apart (LightingOptions::unseenBounceScalesWithLights), from
  // the pass that predicts the unseen room on: per pixel, area light j and surface u of
  // bounceSurfaces (the surfaces the gather's unseen rays hit), the unit direct light of j on u's
  // unseen points gathered at the pixel (unit radiance and albedo; W x H x J x U). The gathered
  // light leaves it out (gatherAll); the fit adds it at its own lights and albedos, each
  // surface's albedo written in the fit's unknowns (bounceAlbedo), so it scales with the lights
  // and with the albedo scale the fit chooses.
  std::vector<int> bounceSurfaces;
  std::vector<UnseenAlbedo> bounceAlbedo;
  std::vector<float> unseenBounce;
  // While the gathered light is gathered without that first bounce (unseenRadianceOf).
  bool withoutUnseenBounce = false;
  // Per area light: its unseen bounce is apart (LightingOptions::unseenBounceOfLightsOutOfView).
  std::vector<bool> bounceApart;
  // The unseen ceiling whose albedo the fit estimates (LightingOptions::fitUnseenCeiling; -1:
  // none this pass): its rho entry is the unknown; its prior (the fitted walls' mean, in the
  // fit's unknowns) and, per channel, whether the photo told it (false: it fell back to the prior).
  int freeCeiling = -1;
  // Set by unseenRoomAlbedo when a sun room's unseen ceiling was lifted above the walls' mean.
  std::string ceilingFloorNote;
  UnseenAlbedo ceilingPrior;
  std::array<bool, 3> ceilingTold = {false, false, false};

  bool stop() const { return opt.cancel && opt.cancel->shouldStop(); }
  bool isLight(int x, int y) const { return !lightMask.empty() && lightMask.at(x, y) > 0.5f; }
  // The sides of an extrusion's prism stand in for the legs and the open space under a table
  // top: the photo there shows the floor and walls behind, lit as the prism is not.
  bool isProxy(int surface) const {
    return geometry.surfaces[size_t(surface)].kind == SurfaceKind::ExtrusionSide;
  }
  // Clipped (or non-finite) pixels say nothing about albedo and light.
  bool saturated(int x, int y) const {
    const float* p = photo.pixel(x, y);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) return true;
    return std::max({p[0], p[1], p[2]}) >= float(opt.saturatedAbove);
  }
  // A pixel inside a sun's beam: the sun's unit irradiance there above 0.05.
  bool inSunBeam(size_t idx) const {
    for (size_t k = 0; k < K; ++k)
      if (E[idx * C + J + k] > 0.05) return true;
    return false;
  }

  void findPixelSurfaces();
  bool measureSurfaceRadiance();
  void countClippedPixels();
  bool computeDirectLight();
  template <class GridValue, class Store, class Compute>
  void spread(int dims, const GridValue& gridValue, const Store& store, const Compute& compute);
  double lightE(const PixelSurface& p, size_t j, uint32_t id) const;
  long seenPixel(const SurfaceHit& h) const;
  Vec3 radianceAt(const SurfaceHit& h, uint32_t sampleId) const;
  Vec3 seenRadiance(size_t idx) const;
  Vec3 unseenRadiance(const SurfaceHit& h, uint32_t sampleId) const;
  UnseenLights unseenLightsOf(const PointRays& r) const;
  Vec3 unseenRadianceOf(const SurfaceHit& h, int patch, const double* e) const;
  std::vector<UnseenLights> unseenLightsOfAll(const std::vector<PointRays>& points) const;
  template <class Seen, class Unseen>
  Vec3 meanOverRays(const PointRays& r, const Seen& seen, const Unseen& unseen,
                    const UnseenLights* lit) const;
  Vec3 clippedRadianceOf(size_t idx) const;
  ImageF sunBounceImage(size_t k, int surface);
  uint64_t fingerprintOfRays() const;
  void adoptOrTraceRays();
  PointRays traceRays(const Vec3& point, const Vec3& normal, int samples, uint32_t pixelId,
                      uint32_t seed) const;
  void traceGridRays();
  void tracePatchRays(const SurfacePatches& P);
  template <class Seen, class Unseen>
  ImageF gatherImage(const Seen& seen, const Unseen& unseen,
                     const std::vector<UnseenLights>* lit = nullptr);
  void gatherAll();
  void gatherUnseenPatches();
  void gatherUnseenSunPatches();
  ImageF unseenSunBounceImage();
  void gatherUnseenBounce();
  void sumUnseenBounce(const PointRays& pr, const UnseenLights& lit, const std::vector<int>& index,
                       double* sum) const;
  std::vector<bool> fittedSurfaces() const;
  int unseenCeilingUnknown() const;
  UnseenAlbedo meanOfFitted(SurfaceKind kind) const;
  UnseenAlbedo unseenAlbedoInFit(int surface) const;
  double priorCeilingAlbedo(int c) const;
  double ceilingPriorWeight() const;
  void constrainUnseenCeiling(ceres::Problem& problem, int c);
  bool photoTellsCeiling(ceres::Problem& problem, const std::vector<ceres::ResidualBlockId>& data,
                         int c);
  void reportUnseenCeiling();
  double bounceAlbedoOf(size_t u, int c, const std::vector<std::array<double, 3>>& rhoNow) const;
  double unseenBounceAt(size_t idx, int c, const std::vector<double>& albedo,
                        const std::vector<Vec3>& lights) const;
  double fixedGathered(size_t idx, int c) const;
  void addUnseenBounceTerms(size_t idx, int c, std::vector<double>& e, std::vector<BounceTerm>& bounce,
                            const std::function<int(int surface)>& blockOf) const;
  void moveUnseenBounceToFittedLights();
  bool chooseFitPixels();
  void averageFitPhoto();
  void chooseGatherSamples();
  bool gatherAndFit();
  std::vector<Vec3> unseenRoomAlbedo(const std::vector<Vec3>& fitted, const std::vector<double>& weight);
  bool startWarm(ImageF& previousGathered, std::array<double, 3>& previousGain);
  void predictUnseenFromFit();
  bool fit();
  double fitStartRadiance() const;
  void tieLightsOutOfView();
  std::string fitChannel(int c, double& cost);
  ceres::ResidualBlockId addPixelResidual(ceres::Problem& problem, size_t idx, int c,
                                          ceres::LossFunction* loss);
  void boundUnknowns(ceres::Problem& problem, int c);
  void storeFittedLights();
  void perPixelAlbedo();
  void relativeFitResidual();
  void vignettingFromResidual();
};

// Step 1: the first surface behind every pixel.
void LightingFit::findPixelSurfaces() {
  ps.assign(size_t(W) * H, PixelSurface{});
  parallelFor(tbb::blocked_range<int>(0, H), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < W; ++x) {
        const Ray r = camera.rayThroughPixel(Vec2(x + 0.5, y + 0.5));
        const auto h = tracer.intersect(r, 1e-6);
        if (!h) continue;
        PixelSurface& p = ps[size_t(y) * W + x];
        p.surface = h->surfaceId;
        p.point = h->pointWorld;
        p.normal = h->normalWorld;
        p.depth = camera.depthOf(h->pointWorld);
      }
  });
  out.firstSurfacePerPixel.resize(ps.size());
  for (size_t i = 0; i < ps.size(); ++i) out.firstSurfacePerPixel[i] = ps[i].surface;
}

// Step 2: mean radiance of each surface where the photo shows it (for what the camera does not
// see), and of the whole room as the last resort. False when no pixel falls on the room.
bool LightingFit::measureSurfaceRadiance() {
  surfaceRadiance.assign(S, Vec3::Zero());
  std::vector<double> surfaceCount(S, 0);
  Vec3 roomRadiance = Vec3::Zero();
  double roomCount = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const auto& p = ps[size_t(y) * W + x];
      if (p.surface < 0 || isLight(x, y)) continue;
      const Vec3 b = photo.rgb(x, y);
      if (!b.allFinite()) continue;
      surfaceRadiance[p.surface] += b;
      surfaceCount[p.surface] += 1;
      roomRadiance += b;
      roomCount += 1;
    }
  if (roomCount == 0) return false;
  roomRadiance /= roomCount;
  for (size_t s = 0; s < S; ++s)
    surfaceRadiance[s] = surfaceCount[s] > 0 ? Vec3(surfaceRadiance[s] / surfaceCount[s]) : roomRadiance;
  return true;
}

// Whether the clipped pixels of the room are enough to fit their gain (fitClipped).
void LightingFit::countClippedPixels() {
  size_t clippedRoomPixels = 0, roomPixels = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      if (ps[size_t(y) * W + x].surface >= 0 && !isLight(x, y))
        ++roomPixels, clippedRoomPixels += saturated(x, y) ? 1 : 0;
  // A few clipped pixels send too little light to tell their gain.
  fitClipped = clippedRoomPixels > std::max<size_t>(50, roomPixels / 200);
}

double LightingFit::lightE(const PixelSurface& p, size_t j, uint32_t id) const {
  return tracer.unitLightIrradianceOverPi(lightsIn[j], p.point + 1e-5 * p.normal, p.normal,
                                          opt.directSamples, opt.seed + uint32_t(j) * 7919u + id);
}

// Step 3: E_j on a coarse grid, spread to every pixel of the same surface; the suns at every
// pixel; the clipped pixels inside a sun's beam. False when cancelled.
bool LightingFit::computeDirectLight() {
  gridE.assign(size_t(GW) * GH * std::max<size_t>(J, 1), 0.0);
  gridSurface.assign(size_t(GW) * GH, -1);
  gridPixel.assign(size_t(GW) * GH, Vec2());
  // Grid samples: E_j once.
  parallelFor(tbb::blocked_range<int>(0, GH), [&](const tbb::blocked_range<int>& rows) {
    for (int gy = rows.begin(); gy < rows.end(); ++gy) {
      if (stop()) return;
      for (int gx = 0; gx < GW; ++gx) {
        const int x = std::min(W - 1, gx * stride + stride / 2),
                  y = std::min(H - 1, gy * stride + stride / 2);
        const auto& p = ps[size_t(y) * W + x];
        const size_t g = size_t(gy) * GW + gx;
        gridSurface[g] = p.surface;
        gridPixel[g] = Vec2(x, y);
        if (p.surface < 0) continue;
        for (size_t j = 0; j < J; ++j) gridE[g * J + j] = lightE(p, j, uint32_t(y * W + x));
      }
    }
  });
  if (stop()) return false;
  E.assign(size_t(W) * H * std::max<size_t>(C, 1), 0.0);
  if (J > 0)
    spread(
        int(J), [&](size_t g, int d) { return gridE[g * J + size_t(d)]; },
        [&](int x, int y, const double* v) { std::copy(v, v + J, &E[(size_t(y) * W + x) * C]); },
        [&](int x, int y, double* v) {
          for (size_t j = 0; j < J; ++j) v[j] = lightE(ps[size_t(y) * W + x], j, uint32_t(y * W + x));
        });
  // Suns at every pixel: one ray each, and the shaft's edge stays sharp.
  if (K > 0)
    parallelFor(tbb::blocked_range<int>(0, H), [&](const tbb::blocked_range<int>& rows) {
      for (int y = rows.begin(); y < rows.end(); ++y)
        for (int x = 0; x < W; ++x) {
          const auto& p = ps[size_t(y) * W + x];
          if (p.surface < 0) continue;
          for (size_t k = 0; k < K; ++k)
            E[(size_t(y) * W + x) * C + J + k] =
                unitSunIrradianceOverPi(tracer, geometry, suns[k], p.point + 1e-5 * p.normal, p.normal);
        }
    });
  if (stop()) return false;
  if (K > 0) {
    clippedInBeam.assign(size_t(W) * H, 0);
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const size_t idx = size_t(y) * W + x;
        clippedInBeam[idx] = saturated(x, y) && inSunBeam(idx);
      }
  }
  return true;
}

// Spreads grid values to every pixel with bilinear weights over the grid samples of the same
// surface; `compute` fills a pixel whose neighbours are all on other surfaces (a sliver).
// gridValue(g, d), store(x, y, const double* v) and compute(x, y, double* v) are called per
// pixel and corner: templates, so that they inline.
template <class GridValue, class Store, class Compute>
void LightingFit::spread(int dims, const GridValue& gridValue, const Store& store,
                         const Compute& compute) {
  parallelFor(tbb::blocked_range<int>(0, H), [&](const tbb::blocked_range<int>& rows) {
    std::vector<double> v(size_t(std::max(dims, 1)));
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < W; ++x) {
        const auto& p = ps[size_t(y) * W + x];
        if (p.surface < 0) continue;
        const double fx = (x + 0.5) / stride - 0.5, fy = (y + 0.5) / stride - 0.5;
        const int gx0 = std::clamp(int(std::floor(fx)), 0, GW - 1),
                  gy0 = std::clamp(int(std::floor(fy)), 0, GH - 1);
        const double ax = std::clamp(fx - gx0, 0.0, 1.0), ay = std::clamp(fy - gy0, 0.0, 1.0);
        double wsum = 0;
        std::fill(v.begin(), v.end(), 0.0);
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx) {
            const int gx = std::min(gx0 + dx, GW - 1), gy = std::min(gy0 + dy, GH - 1);
            const size_t gi = size_t(gy) * GW + gx;
            if (gridSurface[gi] != p.surface) continue;
            const double w = (dx ? ax : 1 - ax) * (dy ? ay : 1 - ay) + 1e-6;
            wsum += w;
            for (int d = 0; d < dims; ++d) v[size_t(d)] += w * gridValue(gi, d);
          }
        if (wsum > 0)
          for (double& e : v) e /= wsum;
        else compute(x, y, v.data());
        store(x, y, v.data());
      }
  });
}

// The pixel showing room point `h` when the photo tells its radiance there (the camera sees
// that point, not a light outline, finite), else -1.
long LightingFit::seenPixel(const SurfaceHit& h) const {
  const auto px = camera.project(h.pointWorld);
  if (!px) return -1;
  const int x = int(std::floor(px->x())), y = int(std::floor(px->y()));
  if (x < 0 || y < 0 || x >= W || y >= H || isLight(x, y)) return -1;
  const size_t idx = size_t(y) * W + x;
  const auto& p = ps[idx];
  if (p.surface != h.surfaceId ||
      !(std::abs(p.depth - camera.depthOf(h.pointWorld)) < 0.02 * p.depth + 1e-3) ||
      !photo.rgb(x, y).allFinite())
    return -1;
  return long(idx);
}

// Radiance leaving a room point toward another, read from the photo where the camera sees it.
Vec3 LightingFit::radianceAt(const SurfaceHit& h, uint32_t sampleId) const {
  if (const long seen = seenPixel(h); seen >= 0) return seenRadiance(size_t(seen));
  return unseenRadiance(h, sampleId);
}

// radianceAt at a point the camera sees, photo pixel `idx` (seenPixel).
Vec3 LightingFit::seenRadiance(size_t idx) const {
  const int x = int(idx % size_t(W)), y = int(idx / size_t(W));
  const Vec3 b = photo.rgb(x, y);
  if (!clippedInBeam.empty() && clippedInBeam[idx]) {
    if (sunApart) return beamRadianceNoSun[idx];
    return beamRadiance.empty() ? b : beamRadiance[idx];
  }
  return saturated(x, y) ? Vec3(b.cwiseProduct(Vec3(1 + clippedGainApplied[0], 1 + clippedGainApplied[1],
                                                    1 + clippedGainApplied[2])))
                         : b;
}

// radianceAt at a point the camera does not see: the surface's mean radiance in the first pass,
// then the room model's prediction.
Vec3 LightingFit::unseenRadiance(const SurfaceHit& h, uint32_t sampleId) const {
  if (!model.active) return surfaceRadiance[h.surfaceId];
  PointRays one;
  one.unseen.push_back({h, sampleId});
  const UnseenLights lit = unseenLightsOf(one);
  return unseenRadianceOf(h, lit.patch[0], lit.e.data());
}

// The patch and unit direct light of each unseen ray of `r` (UnseenLights).
UnseenLights LightingFit::unseenLightsOf(const PointRays& r) const {
  UnseenLights lit;
  lit.patch.resize(r.unseen.size());
  lit.e.resize(r.unseen.size() * C);
  for (size_t k = 0; k < r.unseen.size(); ++k) {
    const SurfaceHit& h = r.unseen[k].hit;
    const Vec3 p = h.pointWorld + 1e-5 * h.normalWorld;
    lit.patch[k] = model.patches.find(h);
    for (size_t j = 0; j < J; ++j)
      lit.e[k * C + j] = tracer.unitLightIrradianceOverPi(lightsIn[j], p, h.normalWorld, 1,
                                                          r.unseen[k].sampleId * 31u + uint32_t(j));
    for (size_t s = 0; s < K; ++s)
      lit.e[k * C + J + s] = unitSunIrradianceOverPi(tracer, geometry, suns[s], p, h.normalWorld);
  }
  return lit;
}

std::vector<UnseenLights> LightingFit::unseenLightsOfAll(const std::vector<PointRays>& points) const {
  std::vector<UnseenLights> lit(points.size());
  parallelFor(tbb::blocked_range<size_t>(0, points.size()), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) lit[i] = unseenLightsOf(points[i]);
  });
  return lit;
}

// The predicted radiance at an unseen point: albedo times (direct light from the fitted lights
// + the light gathered at its patch, or the surface's mean where no patch was made), from its
// patch and unit direct light `e` (C values).
Vec3 LightingFit::unseenRadianceOf(const SurfaceHit& h, int patch, const double* e) const {
  Vec3 irradiance = patch >= 0 ? model.patches.gamma[size_t(patch)] : model.gammaMean[h.surfaceId];
  for (size_t j = 0; j < J; ++j)
    if (!withoutUnseenBounce || !bounceApart[j]) irradiance += model.lights[j] * e[j];
  for (size_t k = 0; k < K && !sunApart; ++k) irradiance += model.lights[J + k] * e[J + k];
  return model.rho[h.surfaceId].cwiseProduct(irradiance);
}

// The part of radianceAt that comes from clipped photo pixels (a window, an over-exposed wall
// by a lamp): there the photo gives only a lower bound of the radiance, so the light they send
// is gathered apart and the fit gives it an extra gain k (Gamma + k Gamma_clipped), with the
// clipped radiance's total factor 1 + k at least 1. The second pass starts from the first's.
// `idx`: the seen photo pixel (seenPixel); what the camera does not see sends none of it.
Vec3 LightingFit::clippedRadianceOf(size_t idx) const {
  const int x = int(idx % size_t(W)), y = int(idx / size_t(W));
  if (!saturated(x, y) || (!clippedInBeam.empty() && clippedInBeam[idx])) return Vec3::Zero();
  return photo.rgb(x, y);
}

// The light of `surface` under sun k at unit strength and unit albedo where the photo does not
// tell it: its clipped sunlit pixels (the sun's irradiance there) and what the camera does not
// see (the sun's irradiance at the hit). The fit multiplies in the sun and the albedo.
ImageF LightingFit::sunBounceImage(size_t k, int surface) {
  return gatherImage(
      [this, k, surface](size_t idx) -> Vec3 {
        return ps[idx].surface == surface && clippedInBeam[idx]
                   ? Vec3(Vec3::Constant(E[idx * C + J + k]))
                   : Vec3(Vec3::Zero());
      },
      [this, k, surface](const SurfaceHit& h, uint32_t) -> Vec3 {
        if (h.surfaceId != surface) return Vec3::Zero();
        return Vec3::Constant(unitSunIrradianceOverPi(
            tracer, geometry, suns[k], h.pointWorld + 1e-5 * h.normalWorld, h.normalWorld));
      });
}

// The mean of `seen` (per photo pixel) and `unseen` (per hit and sampleId) over a point's rays;
// a ray that left the room, or a radiance that is not finite, counts as 0. `lit`: the rays'
// UnseenLights, when `unseen` is the room model's prediction (unseenRadiance): read instead.
template <class Seen, class Unseen>
Vec3 LightingFit::meanOverRays(const PointRays& r, const Seen& seen, const Unseen& unseen,
                               const UnseenLights* lit) const {
  Vec3 sum = Vec3::Zero();
  for (const int32_t idx : r.seen) {
    const Vec3 radiance = seen(size_t(idx));
    if (radiance.allFinite()) sum += radiance;
  }
  for (size_t k = 0; k < r.unseen.size(); ++k) {
    const UnseenRay& u = r.unseen[k];
    const Vec3 radiance = lit ? unseenRadianceOf(u.hit, lit->patch[k], lit->e.data() + k * C)
                              : Vec3(unseen(u.hit, u.sampleId));
    if (radiance.allFinite()) sum += radiance;
  }
  return r.rays > 0 ? Vec3(sum / r.rays) : Vec3(Vec3::Zero());
}

// What the traced rays' hits depend on: the photo (its finite pixels), the lights' mask, the
// camera, the room, the gather's grid and samples, the patches and the seed.
uint64_t LightingFit::fingerprintOfRays() const {
  Fingerprint f;
  for (const int v : {W, H, stride, gatherSamples, opt.patchSamples, opt.patchSweeps}) f.value(v);
  f.value(opt.seed);
  f.value(opt.patchesAcrossRoom);
  f.bytes(photo.data.data(), photo.data.size() * sizeof(float));
  f.bytes(lightMask.data.data(), lightMask.data.size() * sizeof(float));
  for (const int v : {camera.widthPx, camera.heightPx}) f.value(v);
  for (const double v : {camera.focalPx, camera.principalPx.x(), camera.principalPx.y(), camera.heightM})
    f.value(v);
  f.bytes(camera.worldFromCamera.data(), 9 * sizeof(double));
  f.value(geometry.box);
  for (const Surface& surface : geometry.surfaces) {
    f.value(surface.kind);
    f.value(surface.groupIndex);
    f.value(surface.cardAlpha.get());
    const TriangleMesh& m = surface.meshWorld;
    f.bytes(m.positions.data(), m.positions.size() * sizeof(Vec3f));
    f.bytes(m.normals.data(), m.normals.size() * sizeof(Vec3f));
    f.bytes(m.triangles.data(), m.triangles.size() * sizeof(m.triangles[0]));
  }
  return f.get();
}

// The rays of LightingOptions::reuseRays when they were traced for this estimate's inputs, in
// full; otherwise this estimate traces its own (its first gather and its first patches' sweeps).
void LightingFit::adoptOrTraceRays() {
  const uint64_t key = fingerprintOfRays();
  const auto& given = opt.reuseRays;
  if (given && given->key == key && !given->grid.empty() &&
      given->patchSweeps.size() == size_t(std::max(0, opt.patchSweeps))) {
    rays = given;
    out.raysReused = true;
  } else {
    traced = std::make_shared<LightingRays>();
    traced->key = key;
    rays = traced;
  }
  out.rays = rays;
}

// A point's gather rays (gatherIrradianceOverPi's), each sorted by what it found.
PointRays LightingFit::traceRays(const Vec3& point, const Vec3& normal, int samples, uint32_t pixelId,
                                 uint32_t seed) const {
  PointRays r;
  forEachGatherRay(tracer, point, normal, samples, pixelId, seed, [&](const SurfaceHit* h, uint32_t id) {
    ++r.rays;
    if (!h) return;
    if (const long seen = seenPixel(*h); seen >= 0) r.seen.push_back(int32_t(seen));
    else r.unseen.push_back({*h, id});
  });
  return r;
}

// The gather's rays at every grid point on the room (once per estimate, or none when reused).
void LightingFit::traceGridRays() {
  if (!traced || !traced->grid.empty()) return;
  std::vector<PointRays> grid(gridSurface.size());
  parallelFor(tbb::blocked_range<size_t>(0, grid.size()), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t g = r.begin(); g < r.end(); ++g) {
      if (stop()) return;
      if (gridSurface[g] < 0) continue;
      const int x = int(gridPixel[g].x()), y = int(gridPixel[g].y());
      const auto& p = ps[size_t(y) * W + x];
      grid[g] = traceRays(p.point, p.normal, gatherSamples, uint32_t(y * W + x), opt.seed);
    }
  });
  if (!stop()) traced->grid = std::move(grid);
}

// The light `seen` and `unseen` send to every pixel (radianceAt split at seenPixel): gathered on
// the grid from its traced rays, spread to the pixels.
template <class Seen, class Unseen>
ImageF LightingFit::gatherImage(const Seen& seen, const Unseen& unseen,
                                const std::vector<UnseenLights>* lit) {
  traceGridRays();
  std::vector<Vec3> grid(gridSurface.size(), Vec3::Zero());
  if (rays->grid.size() == grid.size())
    parallelFor(tbb::blocked_range<size_t>(0, grid.size()), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t g = r.begin(); g < r.end(); ++g)
        if (gridSurface[g] >= 0)
          grid[g] = meanOverRays(rays->grid[g], seen, unseen,
                                 lit && lit->size() == grid.size() ? &(*lit)[g] : nullptr);
    });
  const RadianceAt radiance = [&](const SurfaceHit& h, uint32_t id) -> Vec3 {
    const long px = seenPixel(h);
    return px >= 0 ? Vec3(seen(size_t(px))) : Vec3(unseen(h, id));
  };
  ImageF image(W, H, 3, 0.f);
  spread(
      3, [&](size_t g, int d) { return grid[g][d]; },
      [&](int x, int y, const double* v) { image.setRgb(x, y, Vec3(v[0], v[1], v[2])); },
      [&](int x, int y, double* v) {
        const auto& p = ps[size_t(y) * W + x];
        const Vec3 g = gatherIrradianceOverPi(tracer, p.point, p.normal, gatherSamples,
                                              uint32_t(y * W + x), opt.seed, radiance)
                           .mean;
        v[0] = g[0], v[1] = g[1], v[2] = g[2];
      });
  return image;
}

// Gamma from the photo (and the model where it does not tell), the light from clipped pixels
// apart, and (pass 2 with a sun) each sunlit patch's bounce per unit strength.
void LightingFit::gatherAll() {
  traceGridRays();
  if (model.active && gridLights.empty() && !stop()) gridLights = unseenLightsOfAll(rays->grid);
  gatherUnseenBounce();
  withoutUnseenBounce = !unseenBounce.empty();
  out.gathered = gatherImage([this](size_t idx) { return seenRadiance(idx); },
                             [this](const SurfaceHit& h, uint32_t id) { return unseenRadiance(h, id); },
                             model.active ? &gridLights : nullptr);
  withoutUnseenBounce = false;
  if (fitClipped)
    gatheredClipped = gatherImage([this](size_t idx) { return clippedRadianceOf(idx); },
                                  [](const SurfaceHit&, uint32_t) { return Vec3(Vec3::Zero()); });
  sunPatches.clear();
  if (!sunApart) return;
  // The surfaces each sun lights: where it clips in the photo, and where its beam meets a
  // patch of the room (seen or not).
  std::vector<uint8_t> patchOn(S * K, 0);
  for (size_t idx = 0; idx < clippedInBeam.size(); ++idx)
    if (clippedInBeam[idx] && ps[idx].surface >= 0)
      for (size_t k = 0; k < K; ++k)
        if (E[idx * C + J + k] > 0) patchOn[size_t(ps[idx].surface) * K + k] = 1;
  const SurfacePatches& P = model.patches;
  for (size_t i = 0; i < P.point.size(); ++i)
    for (size_t k = 0; k < K; ++k)
      if (unitSunIrradianceOverPi(tracer, geometry, suns[k], P.point[i] + 1e-4 * P.normal[i],
                                  P.normal[i]) > 0)
        patchOn[size_t(P.surface[i]) * K + k] = 1;
  for (size_t k = 0; k < K; ++k)
    for (size_t s = 0; s < S; ++s)
      if (patchOn[s * K + k]) sunPatches.push_back({k, int(s), sunBounceImage(k, int(s))});
  if (opt.gatherSunBounceUnseen && K == 1 && !model.sunGamma.empty() && !sunPatches.empty()) {
    out.sunBounceUnseen = {unseenSunBounceImage()};
    out.sunBounceUnseenAt = {model.lights[J]};
  }
}

// The light gathered at every patch of the room (radiosity by Jacobi sweeps from the surface
// means): what the photo shows is read from it, the rest predicted from the previous sweep.
void LightingFit::gatherUnseenPatches() {
  const double roomSize = std::max({geometry.box.xRightM - geometry.box.xLeftM,
                                    geometry.box.zRearM - geometry.box.zBackM, geometry.box.ceilingM});
  // The same patches every pass (only their light changes): made once.
  if (model.patches.point.empty())
    model.patches = makeSurfacePatches(geometry, std::max(0.05, roomSize / opt.patchesAcrossRoom));
  SurfacePatches& P = model.patches;
  for (size_t i = 0; i < P.point.size(); ++i) P.gamma[i] = model.gammaMean[size_t(P.surface[i])];
  tracePatchRays(P);
  if (stop()) return;
  std::vector<Vec3> next(P.point.size());
  auto seen = [this](size_t idx) { return seenRadiance(idx); };
  auto unseen = [this](const SurfaceHit& h, uint32_t id) { return unseenRadiance(h, id); };
  if (patchLights.empty())
    for (const std::vector<PointRays>& sweepRays : rays->patchSweeps)
      patchLights.push_back(unseenLightsOfAll(sweepRays));
  for (int sweep = 0; sweep < opt.patchSweeps; ++sweep) {
    const std::vector<PointRays>& sweepRays = rays->patchSweeps[size_t(sweep)];
    const std::vector<UnseenLights>& lit = patchLights[size_t(sweep)];
    parallelFor(tbb::blocked_range<size_t>(0, P.point.size()), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i < r.end(); ++i)
        next[i] = meanOverRays(sweepRays[i], seen, unseen, &lit[i]);
    });
    std::swap(P.gamma, next);
  }
}

// The suns' share of the unseen patches' gathered light (model.sunGamma): the same sweeps as
// gatherUnseenPatches with the suns' light as the only source, read where the photo clips their
// patch (the model's radiance there less its part without the suns) and, where the camera does
// not see, the room model's albedo times the suns' direct light and this share.
void LightingFit::gatherUnseenSunPatches() {
  const SurfacePatches& P = model.patches;
  std::vector<Vec3> gamma(P.point.size(), Vec3::Zero()), next(P.point.size());
  for (int sweep = 0; sweep < opt.patchSweeps && size_t(sweep) < patchLights.size(); ++sweep) {
    const std::vector<PointRays>& sweepRays = rays->patchSweeps[size_t(sweep)];
    const std::vector<UnseenLights>& lit = patchLights[size_t(sweep)];
    parallelFor(tbb::blocked_range<size_t>(0, P.point.size()), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i < r.end(); ++i) {
        Vec3 sum = Vec3::Zero();
        for (const int32_t idx : sweepRays[i].seen)
          if (clippedInBeam[size_t(idx)])
            sum += beamRadiance[size_t(idx)] - beamRadianceNoSun[size_t(idx)];
        for (size_t k = 0; k < sweepRays[i].unseen.size(); ++k) {
          const SurfaceHit& h = sweepRays[i].unseen[k].hit;
          const int patch = lit[i].patch[k];
          Vec3 irradiance = patch >= 0 ? gamma[size_t(patch)] : Vec3::Zero();
          for (size_t j = 0; j < K; ++j) irradiance += model.lights[J + j] * lit[i].e[k * C + J + j];
          const Vec3 radiance = model.rho[size_t(h.surfaceId)].cwiseProduct(irradiance);
          if (radiance.allFinite()) sum += radiance;
        }
        next[i] = sweepRays[i].rays > 0 ? Vec3(sum / sweepRays[i].rays) : Vec3::Zero();
      }
    });
    std::swap(gamma, next);
  }
  model.sunGamma = std::move(gamma);
}

// Per unit strength of the (one) sun: the light its share of the unseen patches' light
// (model.sunGamma) sends to each pixel, through the room model's albedo where the camera does
// not see (LightingEstimate::sunBounceUnseen).
ImageF LightingFit::unseenSunBounceImage() {
  const Vec3 strength = model.lights[J];
  ImageF image =
      gatherImage([](size_t) { return Vec3(Vec3::Zero()); },
                  [this](const SurfaceHit& h, uint32_t) -> Vec3 {
                    const int patch = model.patches.find(h);
                    if (patch < 0 || size_t(patch) >= model.sunGamma.size()) return Vec3::Zero();
                    return model.rho[size_t(h.surfaceId)].cwiseProduct(model.sunGamma[size_t(patch)]);
                  });
  for (size_t i = 0; i < image.data.size(); ++i) {
    const double s = strength[int(i % 3)];
    image.data[i] = s > 0 && std::isfinite(image.data[i]) ? float(image.data[i] / s) : 0.f;
  }
  return image;
}

// Each sweep's rays from every patch (once per estimate, or none when reused): sweep k casts
// its own rays, the same in every pass.
void LightingFit::tracePatchRays(const SurfacePatches& P) {
  const size_t sweeps = size_t(std::max(0, opt.patchSweeps));
  if (!traced || traced->patchSweeps.size() == sweeps) return;
  std::vector<std::vector<PointRays>> sweepRays(sweeps);
  for (size_t sweep = 0; sweep < sweeps; ++sweep) {
    std::vector<PointRays>& patchRays = sweepRays[sweep];
    patchRays.resize(P.point.size());
    parallelFor(tbb::blocked_range<size_t>(0, P.point.size()), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i < r.end(); ++i) {
        if (stop()) return;
        patchRays[i] = traceRays(P.point[i] + 1e-4 * P.normal[i], P.normal[i], opt.patchSamples,
                                 uint32_t(i) * 2654435761u + uint32_t(sweep), opt.seed + 101u);
      }
    });
  }
  if (!stop()) traced->patchSweeps = std::move(sweepRays);
}

// The unseen room's first bounce apart (unseenBounce): on the grid, per unseen ray the unit
// direct light of each area light at its hit (gridLights), summed per hit surface over the
// point's rays; spread to the pixels. A pixel with no grid point on its surface (a sliver)
// traces its own rays, as the gather does there.
void LightingFit::gatherUnseenBounce() {
  unseenBounce.clear(), bounceSurfaces.clear(), bounceAlbedo.clear();
  freeCeiling = -1;
  if (!opt.unseenBounceScalesWithLights || !model.active || J == 0 ||
      gridLights.size() != gridSurface.size() || rays->grid.size() != gridSurface.size() ||
      std::none_of(bounceApart.begin(), bounceApart.end(), [](bool b) { return b; }))
    return;
  std::vector<int> index(S, -1);
  for (const PointRays& pr : rays->grid)
    for (const UnseenRay& u : pr.unseen)
      if (index[size_t(u.hit.surfaceId)] < 0) {
        index[size_t(u.hit.surfaceId)] = int(bounceSurfaces.size());
        bounceSurfaces.push_back(u.hit.surfaceId);
      }
  const size_t U = bounceSurfaces.size(), D = J * U;
  if (D == 0) return;
  std::vector<double> grid(gridSurface.size() * D, 0.0);
  parallelFor(tbb::blocked_range<size_t>(0, gridSurface.size()),
              [&](const tbb::blocked_range<size_t>& r) {
                for (size_t g = r.begin(); g < r.end(); ++g)
                  if (gridSurface[g] >= 0)
                    sumUnseenBounce(rays->grid[g], gridLights[g], index, &grid[g * D]);
              });
  unseenBounce.assign(size_t(W) * H * D, 0.f);
  spread(
      int(D), [&](size_t g, int d) { return grid[g * D + size_t(d)]; },
      [&](int x, int y, const double* v) {
        for (size_t d = 0; d < D; ++d) unseenBounce[(size_t(y) * W + x) * D + d] = float(v[d]);
      },
      [&](int x, int y, double* v) {
        const PixelSurface& p = ps[size_t(y) * W + x];
        const PointRays pr = traceRays(p.point, p.normal, gatherSamples, uint32_t(y * W + x), opt.seed);
        std::fill(v, v + D, 0.0);
        sumUnseenBounce(pr, unseenLightsOf(pr), index, v);
      });
  for (const int u : bounceSurfaces) bounceAlbedo.push_back(unseenAlbedoInFit(u));
  const int unknown = unseenCeilingUnknown();
  for (const UnseenAlbedo& a : bounceAlbedo)
    if (unknown >= 0 && a.fitted.size() == 1 && a.fitted[0].first == unknown) freeCeiling = unknown;
  if (freeCeiling >= 0) ceilingPrior = meanOfFitted(SurfaceKind::Ceiling);
}

// Adds to `sum` (J x U values) the unit direct light of each area light whose bounce is apart at
// the unseen hits of `pr` (their UnseenLights `lit`), per hit surface (`index`: its place in
// bounceSurfaces, or -1), over all of the point's rays.
void LightingFit::sumUnseenBounce(const PointRays& pr, const UnseenLights& lit,
                                  const std::vector<int>& index, double* sum) const {
  const size_t U = bounceSurfaces.size();
  if (pr.rays <= 0 || lit.e.size() < pr.unseen.size() * C) return;
  for (size_t k = 0; k < pr.unseen.size(); ++k) {
    const int u = index[size_t(pr.unseen[k].hit.surfaceId)];
    if (u < 0) continue;
    for (size_t j = 0; j < J; ++j) {
      const double e = lit.e[k * C + j];
      if (bounceApart[j] && std::isfinite(e)) sum[j * U + size_t(u)] += e / pr.rays;
    }
  }
}

// Per surface: whether the light fit has pixels of it.
std::vector<bool> LightingFit::fittedSurfaces() const {
  std::vector<bool> fitted(S, false);
  for (size_t idx : candidates) fitted[size_t(ps[idx].surface)] = true;
  return fitted;
}

// The ceiling whose albedo the fit estimates (LightingOptions::fitUnseenCeiling): the first
// ceiling surface the fit has no pixels of (several share its unknown); -1 when the option is
// off, the fit's model is told the ceiling (fitUnseenCeilingAlbedo) or every ceiling is fitted.
int LightingFit::unseenCeilingUnknown() const {
  const Vec3& told = opt.fitUnseenCeilingAlbedo;
  if (!opt.fitUnseenCeiling || ((told.array() >= 0).all() && told.allFinite())) return -1;
  const std::vector<bool> fitted = fittedSurfaces();
  for (size_t s = 0; s < S; ++s)
    if (!fitted[s] && geometry.surfaces[s].kind == SurfaceKind::Ceiling) return int(s);
  return -1;
}

// The albedo an unseen surface of `kind` takes from the fitted ones: a wall or ceiling the mean
// of the fitted walls, anything else (or when no wall is fitted) the mean of every fitted
// surface; mid grey when the fit has none (albedoOfUnseen's rule, in the fit's unknowns).
UnseenAlbedo LightingFit::meanOfFitted(SurfaceKind kind) const {
  const std::vector<bool> fitted = fittedSurfaces();
  std::vector<int> walls, all;
  for (size_t s = 0; s < S; ++s)
    if (fitted[s]) {
      all.push_back(int(s));
      if (isWall(geometry.surfaces[s].kind)) walls.push_back(int(s));
    }
  const bool wallLike = isWall(kind) || kind == SurfaceKind::Ceiling;
  const std::vector<int>& from = wallLike && !walls.empty() ? walls : all;
  UnseenAlbedo a;
  for (const int s : from) a.fitted.emplace_back(s, 1.0 / double(from.size()));
  if (from.empty()) a.constant = Vec3::Constant(0.5);
  return a;
}

// UnseenAlbedo of `surface`: its own fitted albedo where the fit has its pixels; a ceiling the
// fit's model is told (LightingOptions::fitUnseenCeilingAlbedo) that constant; an unseen
// ceiling the fit's unknown for it (unseenCeilingUnknown), else meanOfFitted.
UnseenAlbedo LightingFit::unseenAlbedoInFit(int surface) const {
  UnseenAlbedo a;
  if (fittedSurfaces()[size_t(surface)]) {
    a.fitted.emplace_back(surface, 1.0);
    return a;
  }
  const SurfaceKind kind = geometry.surfaces[size_t(surface)].kind;
  const Vec3& told = opt.fitUnseenCeilingAlbedo;
  if (kind == SurfaceKind::Ceiling && (told.array() >= 0).all() && told.allFinite()) {
    a.constant = told;
    return a;
  }
  const int unknown = kind == SurfaceKind::Ceiling ? unseenCeilingUnknown() : -1;
  if (unknown >= 0) {
    a.fitted.emplace_back(unknown, 1.0);
    return a;
  }
  return meanOfFitted(kind);
}

// Channel c of bounce surface u's albedo (bounceAlbedo) at the fitted albedos `rhoNow`.
double LightingFit::bounceAlbedoOf(size_t u, int c,
                                   const std::vector<std::array<double, 3>>& rhoNow) const {
  double a = bounceAlbedo[u].constant[c];
  for (const auto& [s, w] : bounceAlbedo[u].fitted) a += w * rhoNow[size_t(s)][size_t(c)];
  return a;
}

// The unseen bounce at pixel `idx`, channel c, with each unseen surface's albedo in channel c
// (`albedo`, U values: bounceAlbedoOf) and the area lights' radiances `lights` (0 when it is not
// apart).
double LightingFit::unseenBounceAt(size_t idx, int c, const std::vector<double>& albedo,
                                   const std::vector<Vec3>& lights) const {
  const size_t U = bounceSurfaces.size();
  double sum = 0;
  for (size_t u = 0; u < U; ++u) {
    const double a = albedo[u];
    for (size_t j = 0; j < J; ++j) sum += lights[j][c] * a * double(unseenBounce[(idx * J + j) * U + u]);
  }
  return std::isfinite(sum) ? sum : 0.0;
}

// The part of Gamma the fit takes as fixed: the gathered light, which holds no unseen first
// bounce while that is apart (gatherAll), at least 0.
double LightingFit::fixedGathered(size_t idx, int c) const {
  const double g = out.gathered.at(int(idx % size_t(W)), int(idx / size_t(W)), c);
  return std::isfinite(g) ? std::max(0.0, g) : 0.0;
}

// The unseen bounce at pixel `idx`, channel c, as terms of the fit: a constant albedo adds to the
// light's e_j, a fitted one is a bounce term (light x albedo x g) on that albedo's block
// (`blockOf`: the residual's block of a surface's albedo, added when new).
void LightingFit::addUnseenBounceTerms(size_t idx, int c, std::vector<double>& e,
                                       std::vector<BounceTerm>& bounce,
                                       const std::function<int(int surface)>& blockOf) const {
  const size_t U = bounceSurfaces.size();
  if (unseenBounce.empty() || U == 0) return;
  for (size_t j = 0; j < J; ++j)
    for (size_t u = 0; u < U; ++u) {
      const double g = unseenBounce[(idx * J + j) * U + u];
      if (!(g > 0) || !std::isfinite(g)) continue;
      e[tiedTo[j]] += bounceAlbedo[u].constant[c] * g;
      for (const auto& [s, w] : bounceAlbedo[u].fitted) {
        const int rhoBlock = blockOf(s), lightBlock = int(1 + tiedTo[j]);
        auto same = [&](const BounceTerm& t) {
          return t.rhoBlock == rhoBlock && t.sunBlock == lightBlock;
        };
        const auto it = std::find_if(bounce.begin(), bounce.end(), same);
        if (it != bounce.end()) it->g += w * g;
        else bounce.push_back({rhoBlock, lightBlock, w * g});
      }
    }
}

// The gathered light with the unseen bounce at the fitted radiances and albedos instead of the
// room model's (what the fit used), so the albedo and the next pass see the same Gamma.
void LightingFit::moveUnseenBounceToFittedLights() {
  if (unseenBounce.empty()) return;
  std::vector<Vec3> lights;
  for (size_t j = 0; j < J; ++j) lights.push_back(out.lights[j].radiance);
  // The unseen surfaces' albedos once, not per pixel.
  std::array<std::vector<double>, 3> albedo;
  for (int c = 0; c < 3; ++c)
    for (size_t u = 0; u < bounceSurfaces.size(); ++u)
      albedo[size_t(c)].push_back(bounceAlbedoOf(u, c, rho));
  parallelFor(tbb::blocked_range<size_t>(0, size_t(W) * H), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t idx = r.begin(); idx < r.end(); ++idx) {
      if (ps[idx].surface < 0) continue;
      const int x = int(idx % size_t(W)), y = int(idx / size_t(W));
      for (int c = 0; c < 3; ++c)
        out.gathered.at(x, y, c) =
            float(fixedGathered(idx, c) + unseenBounceAt(idx, c, albedo[size_t(c)], lights));
    }
  });
}

// Step 4: the pixels the light fit uses and its unknowns. Clipped pixels count only inside a
// sun's beam (as lower bounds): elsewhere a clipped pixel is a window or a lamp that no light
// here explains. False when no pixel is usable.
bool LightingFit::chooseFitPixels() {
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const size_t idx = size_t(y) * W + x;
      const auto& p = ps[idx];
      if (p.surface < 0 || isLight(x, y) || !photo.rgb(x, y).allFinite()) continue;
      if (isNonMatte(opt.nonMatteSurfaces, p.surface)) continue;
      if (isProxy(p.surface)) continue;
      if (saturated(x, y) && !inSunBeam(idx)) continue;
      if (luminance(photo.rgb(x, y)) < opt.blackBelow) continue;
      candidates.push_back(idx);
    }
  if (candidates.empty()) return false;
  std::mt19937 rng(opt.seed);
  std::shuffle(candidates.begin(), candidates.end(), rng);
  if (candidates.size() > size_t(opt.fitPixels)) candidates.resize(size_t(opt.fitPixels));
  averageFitPhoto();

  out.lights = lightsIn;
  out.suns = suns;
  refine.assign(C, true);
  for (size_t j = 0; j < J && j < refineIn.size(); ++j) refine[j] = refineIn[j];
  tieLightsOutOfView();
  rho.assign(S, {0.5, 0.5, 0.5});
  L.assign(C, {0, 0, 0});
  return true;
}

// The photo the light fit reads: per pixel the mean over the (2 fitWindow + 1)^2 pixels around it
// that show the same surface, are finite and neither a light nor clipped (a clipped pixel keeps
// its own value: a lower bound). The fit compares logarithms, and the log of a noisy value is
// biased low (by about half its relative variance, more under the robust loss, which discounts
// the rare bright samples of a path-traced or high-ISO photo): averaging first removes most of it.
void LightingFit::averageFitPhoto() {
  fitPhoto = photo;
  const int r = std::max(0, opt.fitWindow);
  // Rooms with a sun keep the pixels as they are: the fit ties the sun's strength to its clipped
  // patch's bounce and the window's clipped gain pixel by pixel next to the beam's sharp edge
  // (averaged, AClippedSunPatchsBounceTellsTheSunsStrength and
  // ClippedSunPatchDoesNotShareTheWindowsGain fail).
  if (r == 0 || K > 0) return;
  auto usable = [&](int x, int y, int surface) {
    return ps[size_t(y) * W + x].surface == surface && !isLight(x, y) && !saturated(x, y);
  };
  // Only the fit's pixels are read: the mean at those, not at every pixel of the photo.
  parallelFor(tbb::blocked_range<size_t>(0, candidates.size()),
              [&](const tbb::blocked_range<size_t>& range) {
                for (size_t i = range.begin(); i < range.end(); ++i) {
                  const int x = int(candidates[i] % size_t(W)), y = int(candidates[i] / size_t(W));
                  const int s = ps[candidates[i]].surface;
                  if (s < 0 || !usable(x, y, s)) continue;
                  Vec3 sum = Vec3::Zero();
                  int n = 0;
                  for (int yy = std::max(0, y - r); yy <= std::min(H - 1, y + r); ++yy)
                    for (int xx = std::max(0, x - r); xx <= std::min(W - 1, x + r); ++xx)
                      if (usable(xx, yy, s)) sum += photo.rgb(xx, yy), ++n;
                  if (n > 0) fitPhoto.setRgb(x, y, Vec3(sum / n));
                }
              });
}

// The gather's rays per pixel when not given: from a pilot on up to 64 grid points, for the
// noise it leaves (LightingOptions::gatherNoise).
void LightingFit::chooseGatherSamples() {
  if (gatherSamples <= 0) {
    std::vector<std::pair<Vec3, Vec3>> pilot;
    std::vector<size_t> onRoom;
    for (size_t g = 0; g < gridSurface.size(); ++g)
      if (gridSurface[g] >= 0) onRoom.push_back(g);
    const size_t step = std::max<size_t>(1, onRoom.size() / 64);
    for (size_t i = 0; i < onRoom.size(); i += step) {
      const Vec2& px = gridPixel[onRoom[i]];
      const auto& p = ps[size_t(px.y()) * W + size_t(px.x())];
      pilot.emplace_back(p.point, p.normal);
    }
    GatherSampleCountOptions go;
    go.relativeNoise = opt.gatherNoise;
    gatherSamples = gatherSamplesForNoise(
        tracer, pilot, opt.seed, [this](const SurfaceHit& h, uint32_t id) { return radianceAt(h, id); },
        go);
  }
  out.gatherSamples = gatherSamples;
  out.gatherStride = stride;
  out.gatherPoints = GW * GH;
}

// The gather-and-fit passes. Pass 1 guesses what the camera does not see from the mean of what
// it sees; later passes predict it from the fitted albedo and lights. False when cancelled.
bool LightingFit::gatherAndFit() {
  // With a sun, pass 2 gathers its clipped patch apart and fits its bounce with its strength:
  // pass 1 is not mixed into it (that counts the bounce twice). From pass 3 on the passes are
  // relaxed and stop as the plain ones do (LightingOptions::sunRoomToFixedPoint).
  const bool sunScheme = K > 0;
  const bool settle = !sunScheme || opt.sunRoomToFixedPoint;
  const int passes = !sunScheme ? std::max(2, opt.maxPasses)
                     : settle   ? std::max(3, opt.maxPasses)
                                : std::max(1, opt.sunRoomPasses);
  const int firstRelaxed = sunScheme ? 2 : 1;
  const double relax = std::clamp(opt.passRelaxation, 0.05, 1.0);
  ImageF previousGathered;  // the last pass's Gamma as its fit used it (before the suns' bounce)
  std::array<double, 3> previousGain = {0, 0, 0};  // the clipped pixels' gain in that Gamma
  // A warm start goes on from the earlier estimate's passes: its first pass is this one's second.
  const int first = startWarm(previousGathered, previousGain) ? 1 : 0;
  for (int pass = first; pass < passes; ++pass) {
    {
      const StepTimer timer(out.steps, "gather");
      gatherAll();
    }
    const double r = settle && pass >= firstRelaxed ? relax : 1.0;
    const double change = relaxGathered(out.gathered, previousGathered, r);
    previousGathered = out.gathered;
    // The mixed Gamma holds the clipped pixels' gain mixed alike: the fit's extra gain is on
    // top of that.
    for (size_t c = 0; c < 3; ++c)
      previousGain[c] = clippedGainApplied[c] = r * clippedGainApplied[c] + (1 - r) * previousGain[c];
    if (stop()) return false;
    {
      const StepTimer timer(out.steps, "light fit");
      if (!fit()) return false;
    }
    out.passes = pass + 1 - first;
    if (settle && pass >= firstRelaxed + 1 && change < opt.passTolerance) break;
    if (pass == passes - 1) {
      if (passes > 2)
        out.notes.push_back("gathered light still changed by " +
                            std::to_string(int(std::lround(100 * change))) + "% in the last of " +
                            std::to_string(passes - first) +
                            " passes (the walls the camera does not see are uncertain)");
      break;
    }
    const StepTimer timer(out.steps, "unseen patches");
    predictUnseenFromFit();
  }
  if (traced && K == 0) traced->passes = PassState{model, previousGathered, previousGain};
  return true;
}

// Adopts the passes of the estimate whose rays this one replays (LightingOptions::warmStart): its
// room model, Gamma and clipped gain, so that the first pass predicts the unseen room as that
// estimate's later passes did. Rooms with a sun start over (their pass 2 gathers the sunlit
// patch apart). True when adopted.
bool LightingFit::startWarm(ImageF& previousGathered, std::array<double, 3>& previousGain) {
  if (!opt.warmStart || K > 0 || !out.raysReused || !rays->passes) return false;
  const PassState& state = *rays->passes;
  if (!state.model.active || state.gathered.width != W || state.gathered.height != H ||
      state.model.rho.size() != S || state.model.lights.size() != C)
    return false;
  model = state.model;
  previousGathered = state.gathered;
  previousGain = clippedGainApplied = state.clippedGainApplied;
  out.warmStarted = true;
  return true;
}

// The fit's model of the albedo of the surfaces the camera does not see (albedoOfUnseen, from the
// fitted ones `fitted` where `weight` > 0). An unseen ceiling takes the oracle
// fitUnseenCeilingAlbedo when given, else the fit's own estimate (freeCeiling) when it made one,
// else, in a room with a sun, at least LightingOptions::sunRoomUnseenCeilingAtLeast grey: when
// that lifts it above the walls' mean, ceilingFloorNote says so (the photo does not show it).
std::vector<Vec3> LightingFit::unseenRoomAlbedo(const std::vector<Vec3>& fitted,
                                                const std::vector<double>& weight) {
  const double atLeast = K > 0 ? std::max(0.0, opt.sunRoomUnseenCeilingAtLeast) : 0.0;
  std::vector<Vec3> a = albedoOfUnseen(geometry, fitted, weight, atLeast);
  const std::vector<Vec3> wallsMean = albedoOfUnseen(geometry, fitted, weight, 0.0);
  const Vec3& told = opt.fitUnseenCeilingAlbedo;
  const bool oracle = (told.array() >= 0).all() && told.allFinite();
  ceilingFloorNote.clear();
  for (size_t s = 0; s < S; ++s) {
    if (weight[s] != 0 || geometry.surfaces[s].kind != SurfaceKind::Ceiling) continue;
    if (oracle) {
      a[s] = told;
    } else if (freeCeiling >= 0) {
      const auto& r = rho[size_t(freeCeiling)];
      a[s] = Vec3(r[0], r[1], r[2]);
    } else if (a[s] != wallsMean[s]) {
      char text[320];
      std::snprintf(text, sizeof text,
                    "the ceiling the camera does not see: the light fit's model of the room gives it "
                    "%.2f grey, not the seen walls' mean (%.2f; a sunlit patch lights the ceiling "
                    "straight on, and the photo does not show its albedo)",
                    a[s].x(), luminance(wallsMean[s]));
      ceilingFloorNote = text;
    }
  }
  return a;
}

// After a pass's fit: the room model (per-surface albedo and mean Gamma, the fitted lights, the
// patches' gathered light) that the next pass predicts what the camera does not see from.
void LightingFit::predictUnseenFromFit() {
  model.active = true;
  for (size_t c = 0; c < 3; ++c) clippedGainApplied[c] += clippedGain[c];
  model.rho.assign(S, Vec3::Zero());
  model.gammaMean.assign(S, Vec3::Zero());
  std::vector<double> n(S, 0.0);
  for (size_t idx = 0; idx < ps.size(); ++idx) {
    const int s = ps[idx].surface;
    if (s < 0) continue;
    model.gammaMean[s] += out.gathered.rgb(int(idx % W), int(idx / W));
    n[s] += 1;
  }
  Vec3 gammaAll = Vec3::Zero();
  double nAll = 0;
  for (size_t s = 0; s < S; ++s)
    if (n[s] > 0) gammaAll += model.gammaMean[s], nAll += n[s];
  gammaAll /= std::max(1.0, nAll);
  std::vector<Vec3> fitted(S);
  std::vector<double> weight(S);
  for (size_t s = 0; s < S; ++s) {
    model.gammaMean[s] = n[s] > 0 ? Vec3(model.gammaMean[s] / n[s]) : gammaAll;
    fitted[s] = Vec3(rho[s][0], rho[s][1], rho[s][2]);
    weight[s] = n[s] > 0 ? 1.0 : 0.0;
  }
  model.rho = unseenRoomAlbedo(fitted, weight);
  if (!clippedInBeam.empty()) {
    beamRadiance = predictedBeamRadiance(photo, clippedInBeam, ps, model.rho, out.gathered, E,
                                         out.lights, out.suns, true);
    beamRadianceNoSun = predictedBeamRadiance(photo, clippedInBeam, ps, model.rho, out.gathered, E,
                                              out.lights, out.suns, false);
  }
  model.lights.clear();
  for (const auto& l : out.lights) model.lights.push_back(l.radiance);
  for (const auto& sun : out.suns) model.lights.push_back(sun.irradianceOverPi);
  // The unseen patches take the sunlit patch's full radiance and the suns' direct light (in
  // every pass: apart, from the third pass on they lost the sun's bounce through the unseen room).
  sunApart = false;
  gatherUnseenPatches();
  if (K == 1) gatherUnseenSunPatches();
  // The unseen patches took the sunlit patch's full radiance; the fit's gather takes its sun
  // part apart.
  sunApart = K > 0;
}

// The last pass's estimate of the unseen ceiling's albedo (LightingEstimate::unseenCeilingAlbedo,
// unseenCeilingTold); a note names the channels the photo did not tell (they took the walls'
// mean) and an estimate at a bound of [0.05, 1].
void LightingFit::reportUnseenCeiling() {
  if (!ceilingFloorNote.empty()) out.notes.push_back(ceilingFloorNote);
  if (freeCeiling < 0) return;
  const auto& a = rho[size_t(freeCeiling)];
  out.unseenCeilingAlbedo = Vec3(a[0], a[1], a[2]);
  out.unseenCeilingTold = ceilingTold;
  const char* names[] = {"red", "green", "blue"};
  std::string untold, bound;
  for (size_t c = 0; c < 3; ++c) {
    if (!ceilingTold[c]) untold += std::string(untold.empty() ? "" : ", ") + names[c];
    else if (a[c] <= 0.05 + 1e-6 || a[c] >= 1 - 1e-6)
      bound += std::string(bound.empty() ? "" : ", ") + names[c];
  }
  char value[64];
  std::snprintf(value, sizeof value, "%.2f, %.2f, %.2f", a[0], a[1], a[2]);
  if (!untold.empty())
    out.notes.push_back("the photo does not tell the unseen ceiling's albedo (" + untold +
                        "): the seen walls' mean is used (" + value + ")");
  if (!bound.empty())
    out.notes.push_back("the unseen ceiling's albedo came out at a bound of [0.05, 1] (" + bound +
                        "): " + value);
}

// The estimated lights placed out of the photo's view share one radiance when there are several
// (LightingOptions::tieLightsOutOfView): the photo shows only their sum on the walls, which the
// fit cannot split between them (scenes-train t11). A note says so.
void LightingFit::tieLightsOutOfView() {
  tiedTo.resize(J);
  bounceApart.assign(J, false);
  std::vector<size_t> unseen;
  for (size_t j = 0; j < J; ++j) {
    tiedTo[j] = j;
    const auto p = camera.project(lightsIn[j].centre());
    const bool inView = p && p->x() >= 0 && p->y() >= 0 && p->x() <= camera.widthPx &&
                        p->y() <= camera.heightPx;
    bounceApart[j] = inView || opt.unseenBounceOfLightsOutOfView;
    if (refine[j] && !inView) unseen.push_back(j);
  }
  if (!opt.tieLightsOutOfView || unseen.size() < 2) return;
  std::string list;
  for (size_t j : unseen) {
    tiedTo[j] = unseen.front();
    list += (list.empty() ? "" : ", ") + std::to_string(j);
  }
  out.notes.push_back("lights " + list +
                      " are out of view: they share one radiance (the photo shows only their sum)");
}

// The light fit's start: with albedo 0.6 everywhere, the median radiance that explains the
// direct part.
double LightingFit::fitStartRadiance() const {
  std::vector<double> ratios;
  for (size_t idx : candidates) {
    double esum = 0;
    for (size_t j = 0; j < C; ++j) esum += E[idx * C + j];
    if (esum < 1e-6) continue;
    const int x = int(idx % W), y = int(idx / W);
    const double b = luminance(fitPhoto.rgb(x, y)), g = luminance(out.gathered.rgb(x, y));
    ratios.push_back(std::max(0.0, b / 0.6 - g) / esum);
  }
  double start = 1.0;
  if (!ratios.empty()) {
    std::nth_element(ratios.begin(), ratios.begin() + long(ratios.size() / 2), ratios.end());
    start = std::max(1e-6, ratios[ratios.size() / 2]);
  }
  return start;
}

// Fit light radiances (per channel) and one reference albedo per surface: the albedo should be
// as flat within a surface as the lights and Gamma allow (robust to texture). False when
// cancelled.
bool LightingFit::fit() {
  const double start = fitStartRadiance();
  // A light kept as given starts (and stays) at its radiance; the others start at `start`.
  for (size_t j = 0; j < C; ++j)
    for (int c = 0; c < 3; ++c) L[j][c] = refine[j] ? start : std::max(0.0, lightsIn[j].radiance[c]);
  for (auto& r : rho) r = {0.5, 0.5, 0.5};
  clippedGain = {0, 0, 0};
  // The channels share no unknown: fitted side by side, each solver on one thread.
  std::array<double, 3> cost = {0, 0, 0};
  std::array<std::string, 3> failed;
  parallelFor(tbb::blocked_range<int>(0, 3, 1), [&](const tbb::blocked_range<int>& r) {
    for (int c = r.begin(); c < r.end(); ++c)
      if (!stop()) failed[size_t(c)] = fitChannel(c, cost[size_t(c)]);
  });
  if (stop()) return false;
  for (const std::string& note : failed)
    if (!note.empty()) out.notes.push_back(note);
  out.fitIterations = fitIterations[0] + fitIterations[1] + fitIterations[2];
  const double count = 3.0 * double(candidates.size());
  out.fitRmsLog = std::sqrt(2 * (cost[0] + cost[1] + cost[2]) / std::max(1.0, count));
  storeFittedLights();
  return true;
}

// The light fit's residual of candidate pixel `idx` in channel c (a LogResidual under `loss`):
// its albedo, the lights (tied ones share one), the clipped gain, the suns' and the unseen
// room's bounce terms.
ceres::ResidualBlockId LightingFit::addPixelResidual(ceres::Problem& problem, size_t idx, int c,
                                                     ceres::LossFunction* loss) {
  const int x = int(idx % W), y = int(idx / W);
  const int s = ps[idx].surface;
  std::vector<double> e(C);
  for (size_t j = 0; j < C; ++j) e[j] = E[idx * C + j];
  for (size_t j = 0; j < J; ++j)
    if (tiedTo[j] != j) e[tiedTo[j]] += e[j], e[j] = 0;  // one radiance for the tied lights
  const double b = fitPhoto.at(x, y, c);
  std::vector<double*> blocks{&rho[s][c]};
  for (size_t j = 0; j < C; ++j) blocks.push_back(&L[j][c]);
  if (fitClipped) blocks.push_back(&clippedGain[size_t(c)]);
  // The residual's block of a surface's albedo (added when new).
  auto blockOf = [&](int surface) {
    const auto it = std::find(blocks.begin(), blocks.end(), &rho[size_t(surface)][c]);
    if (it != blocks.end()) return int(it - blocks.begin());
    blocks.push_back(&rho[size_t(surface)][c]);
    return int(blocks.size()) - 1;
  };
  // A sun lights the pixel directly and by its sunlit patch's bounce (sun x patch albedo).
  std::vector<BounceTerm> bounce;
  for (const SunPatch& sp : sunPatches) {
    BounceTerm t;
    t.g = sp.g.at(x, y, 0);
    if (!(t.g > 0)) continue;
    t.sunBlock = int(1 + J + sp.sun);
    t.rhoBlock = blockOf(sp.surface);
    bounce.push_back(t);
  }
  addUnseenBounceTerms(idx, c, e, bounce, blockOf);
  auto* f = new LogResidualCost(
      LogResidual(std::log(std::max(0.01 * opt.blackBelow, b)), fixedGathered(idx, c), e,
                  b >= opt.saturatedAbove, fitClipped ? double(gatheredClipped.at(x, y, c)) : -1.0,
                  std::move(bounce)),
      int(blocks.size()));
  return problem.AddResidualBlock(f, loss, blocks);
}

// The bounds of the light fit's unknowns in channel c: albedos in [0.02, 1], the clipped gain at
// least undoing the gain already applied, lights in [0, 1e9]; a light kept as given or tied to
// another is constant.
void LightingFit::boundUnknowns(ceres::Problem& problem, int c) {
  for (size_t s = 0; s < S; ++s)
    if (problem.HasParameterBlock(&rho[s][c])) {
      problem.SetParameterLowerBound(&rho[s][c], 0, 0.02);
      problem.SetParameterUpperBound(&rho[s][c], 0, 1.0);
    }
  if (problem.HasParameterBlock(&clippedGain[size_t(c)])) {
    problem.SetParameterLowerBound(&clippedGain[size_t(c)], 0, -clippedGainApplied[size_t(c)]);
    problem.SetParameterUpperBound(&clippedGain[size_t(c)], 0, 1e3);
  }
  for (size_t j = 0; j < C; ++j)
    if (problem.HasParameterBlock(&L[j][c])) {
      problem.SetParameterLowerBound(&L[j][c], 0, 0.0);
      problem.SetParameterUpperBound(&L[j][c], 0, 1e9);
      if (!refine[j] || (j < J && tiedTo[j] != j)) problem.SetParameterBlockConstant(&L[j][c]);
    }
}

// One channel of the light fit: per candidate pixel a LogResidual (Cauchy loss), the albedos,
// the lights and the clipped gain bounded, the unseen ceiling's albedo (when the fit estimates
// it) given its prior and, where the photo does not tell it, held at that prior; its final cost
// is added to `cost`. Returns why the solver failed, or nothing.
std::string LightingFit::fitChannel(int c, double& cost) {
  ceres::Problem problem;
  // One loss shared by every residual (the problem deletes it once).
  ceres::LossFunction* loss = new ceres::CauchyLoss(0.15);
  std::vector<ceres::ResidualBlockId> data;
  for (size_t idx : candidates) data.push_back(addPixelResidual(problem, idx, c, loss));
  boundUnknowns(problem, c);
  constrainUnseenCeiling(problem, c);
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = 100;
  if (opt.fitFunctionTolerance > 0 && opt.fitFunctionTolerance < 1)  // else Ceres' default
    so.function_tolerance = opt.fitFunctionTolerance;
  so.num_threads = 1;  // the channels run in parallel (fit)
  so.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  if (freeCeiling >= 0) {
    ceilingTold[size_t(c)] = photoTellsCeiling(problem, data, c);
    if (!ceilingTold[size_t(c)] && problem.HasParameterBlock(&rho[size_t(freeCeiling)][c])) {
      rho[size_t(freeCeiling)][c] = priorCeilingAlbedo(c);
      problem.SetParameterBlockConstant(&rho[size_t(freeCeiling)][c]);
      fitIterations[size_t(c)] += int(summary.iterations.size());
      ceres::Solve(so, &problem, &summary);
    }
  }
  cost += summary.final_cost;
  fitIterations[size_t(c)] += int(summary.iterations.size());
  for (size_t j = 0; j < J; ++j) L[j][c] = L[tiedTo[j]][c];
  if (summary.IsSolutionUsable()) return "";
  return "light fit (channel " + std::to_string(c) + ") failed: " + summary.message;
}

// LightingOptions::unseenCeilingPriorWeight, 0 when negative or not finite.
double LightingFit::ceilingPriorWeight() const {
  const double w = opt.unseenCeilingPriorWeight;
  return std::isfinite(w) ? std::max(0.0, w) : 0.0;
}

// The prior of the unseen ceiling's albedo in channel c (the fitted walls' mean, ceilingPrior, at
// the current albedos) within its bounds [0.05, 1]; 0.5 when not finite.
double LightingFit::priorCeilingAlbedo(int c) const {
  double m = ceilingPrior.constant[c];
  for (const auto& [s, w] : ceilingPrior.fitted) m += w * rho[size_t(s)][size_t(c)];
  return std::isfinite(m) ? std::clamp(m, 0.05, 1.0) : 0.5;
}

// The unseen ceiling's albedo in channel c as an unknown (when the fit estimates it and a pixel's
// bounce term uses it): bounded to [0.05, 1], started at its prior, and the prior's residual
// (CeilingPriorCost, weight LightingOptions::unseenCeilingPriorWeight, at least 0) on it and on
// the fitted walls it reads.
void LightingFit::constrainUnseenCeiling(ceres::Problem& problem, int c) {
  if (freeCeiling < 0) return;
  double* a = &rho[size_t(freeCeiling)][c];
  if (!problem.HasParameterBlock(a)) return;
  problem.SetParameterLowerBound(a, 0, 0.05);
  problem.SetParameterUpperBound(a, 0, 1.0);
  *a = priorCeilingAlbedo(c);
  std::vector<double*> blocks{a};
  std::vector<double> weights;
  for (const auto& [s, w] : ceilingPrior.fitted)
    if (problem.HasParameterBlock(&rho[size_t(s)][c])) {
      blocks.push_back(&rho[size_t(s)][c]);
      weights.push_back(w);
    }
  problem.AddResidualBlock(new CeilingPriorCost(ceilingPriorWeight(), ceilingPrior.constant[c], weights),
                           nullptr, blocks);
}

// Whether the photo tells the unseen ceiling's albedo a in channel c more than its prior does:
// the information the pixels' residuals `data` give log a at the fit, every other free unknown
// fitted alongside (schurInformation of their Gauss-Newton matrix, the robust loss applied),
// above the prior's w^2. False when it cannot be evaluated.
bool LightingFit::photoTellsCeiling(ceres::Problem& problem,
                                    const std::vector<ceres::ResidualBlockId>& data, int c) {
  double* a = &rho[size_t(freeCeiling)][c];
  if (!problem.HasParameterBlock(a) || problem.IsParameterBlockConstant(a)) return false;
  ceres::Problem::EvaluateOptions eo;
  eo.residual_blocks = data;
  std::vector<double*> all;
  problem.GetParameterBlocks(&all);
  long k = -1;
  for (double* p : all)
    if (!problem.IsParameterBlockConstant(p)) {
      if (p == a) k = long(eo.parameter_blocks.size());
      eo.parameter_blocks.push_back(p);
    }
  ceres::CRSMatrix jac;
  double total = 0;
  if (!problem.Evaluate(eo, &total, nullptr, nullptr, &jac)) return false;
  const double told = schurInformation(gaussNewtonMatrix(jac), k) * (*a) * (*a);
  const double w = ceilingPriorWeight();
  return std::isfinite(told) && told > w * w;
}

// The fitted radiances into out.lights and out.suns; the suns' bounce at the fitted strengths
// and albedos, and the clipped pixels' fitted gain, join the gathered light.
void LightingFit::storeFittedLights() {
  for (size_t j = 0; j < J; ++j) {
    Vec3 r(L[j][0], L[j][1], L[j][2]);
    if (!r.allFinite()) r = lightsIn[j].radiance;
    out.lights[j].radiance = r.cwiseMax(0.0);
  }
  moveUnseenBounceToFittedLights();
  for (size_t k = 0; k < K; ++k) {
    Vec3 r(L[J + k][0], L[J + k][1], L[J + k][2]);
    if (!r.allFinite()) r = Vec3::Zero();
    out.suns[k].irradianceOverPi = r.cwiseMax(0.0);
  }
  out.sunBounce.assign(sunPatches.empty() ? 0 : K, ImageF(W, H, 3, 0.f));
  for (const SunPatch& sp : sunPatches)
    for (size_t i = 0; i < out.gathered.data.size(); ++i) {
      const int c = int(i % 3);
      const float v = float(rho[size_t(sp.surface)][size_t(c)]) * sp.g.data[i];
      out.sunBounce[sp.sun].data[i] += v;
      out.gathered.data[i] += float(out.suns[sp.sun].irradianceOverPi[c]) * v;
    }
  if (fitClipped) {
    for (size_t c = 0; c < 3; ++c)
      if (!std::isfinite(clippedGain[c])) clippedGain[c] = 0;
    for (size_t i = 0; i < out.gathered.data.size(); ++i)
      out.gathered.data[i] += float(clippedGain[i % 3]) * gatheredClipped.data[i];
    for (size_t c = 0; c < 3; ++c) out.clippedGain[int(c)] = clippedGainApplied[c] + clippedGain[c];
  }
}

// Step 5: per-pixel albedo B / (sum L_j E_j + Gamma) (the light fit's, physicalAlbedo) and
// direct light; the shading-free image and each pixel's direct share for the decomposition.
void LightingFit::perPixelAlbedo() {
  out.albedo = ImageF(W, H, 3, 0.f);
  out.direct = ImageF(W, H, 3, 0.f);
  shadingFree = ImageF(W, H, 3, 0.f);
  directShare.assign(size_t(W) * H, 1.f);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const size_t idx = size_t(y) * W + x;
      const auto& p = ps[idx];
      if (p.surface < 0) continue;
      Vec3 a;
      const Vec3 g = out.gathered.rgb(x, y);
      for (int c = 0; c < 3; ++c) {
        double shading = g[c];
        for (size_t j = 0; j < J; ++j) shading += out.lights[j].radiance[c] * E[idx * C + j];
        for (size_t k = 0; k < K; ++k) shading += out.suns[k].irradianceOverPi[c] * E[idx * C + J + k];
        const double b = photo.at(x, y, c);
        double r = shading > 1e-9 ? b / shading : rho[p.surface][c];
        shadingFree.at(x, y, c) = float(std::isfinite(r) ? std::max(r, 0.0) : rho[p.surface][c]);
        if (c == 1 && shading > 1e-9) directShare[idx] = float((shading - g[c]) / shading);
        if (isLight(x, y) || saturated(x, y)) r = rho[p.surface][c];
        a[c] = std::clamp(std::isfinite(r) ? r : rho[p.surface][c], 0.0, 1.0);
      }
      out.albedo.setRgb(x, y, a);
      const Vec3 b = photo.rgb(x, y);
      out.direct.setRgb(x, y,
                        b.allFinite() ? Vec3((b - a.cwiseProduct(g)).cwiseMax(0.0)) : Vec3::Zero());
    }
  out.physicalAlbedo = out.albedo;
}

// The model's residual against the photo relative to the photo's own spread, in log space
// (LightingEstimate::fitResidualRelative): scale-free, and a power applied to the photo scales
// both alike.
void LightingFit::relativeFitResidual() {
  std::vector<double> residual, logB;
  for (size_t idx : candidates) {
    const int x = int(idx % W), y = int(idx / W);
    if (saturated(x, y)) continue;
    for (int c = 0; c < 3; ++c) {
      const double b = photo.at(x, y, c), r = shadingFree.at(x, y, c);
      const double rhoS = rho[size_t(ps[idx].surface)][size_t(c)];
      if (!(b > 0) || !(r > 0) || !(rhoS > 0)) continue;
      residual.push_back(std::abs(std::log(r / rhoS)));
      logB.push_back(std::log(b));
    }
  }
  if (residual.size() < 16) return;
  auto median = [](std::vector<double>& v) {
    std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  const double mid = median(logB);
  for (double& l : logB) l = std::abs(l - mid);
  const double spread = median(logB);
  if (spread > 0) out.fitResidualRelative = median(residual) / spread;
}

// LightingEstimate::vignetting: per fit pixel the log residual against its surface's fitted
// albedo (mean over the channels) and its squared radius; then the v whose fall-off, with a
// median offset per surface, leaves the least mean absolute residual.
void LightingFit::vignettingFromResidual() {
  std::vector<double> logQ, r2;
  std::vector<int> surface;
  const double cx = W / 2.0, cy = H / 2.0, corner2 = cx * cx + cy * cy;
  for (size_t idx : candidates) {
    const int x = int(idx % W), y = int(idx / W);
    if (saturated(x, y)) continue;
    double sum = 0;
    int n = 0;
    for (int c = 0; c < 3; ++c) {
      const double r = shadingFree.at(x, y, c), rhoS = rho[size_t(ps[idx].surface)][size_t(c)];
      if (r > 0 && rhoS > 0 && std::isfinite(r)) sum += std::log(r / rhoS), ++n;
    }
    if (n == 0) continue;
    logQ.push_back(sum / n);
    r2.push_back(((x + 0.5 - cx) * (x + 0.5 - cx) + (y + 0.5 - cy) * (y + 0.5 - cy)) / corner2);
    surface.push_back(ps[idx].surface);
  }
  if (logQ.size() < 100) return;
  std::vector<std::vector<double>> perSurface(S);
  auto meanAbsResidual = [&](double v) {
    for (auto& p : perSurface) p.clear();
    for (size_t i = 0; i < logQ.size(); ++i)
      perSurface[size_t(surface[i])].push_back(logQ[i] - std::log(1 - v * r2[i]));
    std::vector<double> offset(S, 0.0);
    for (size_t s = 0; s < S; ++s)
      if (!perSurface[s].empty()) {
        auto& p = perSurface[s];
        std::nth_element(p.begin(), p.begin() + long(p.size() / 2), p.end());
        offset[s] = p[p.size() / 2];
      }
    double cost = 0;
    for (size_t i = 0; i < logQ.size(); ++i)
      cost += std::abs(logQ[i] - std::log(1 - v * r2[i]) - offset[size_t(surface[i])]);
    return cost / double(logQ.size());
  };
  const double none = meanAbsResidual(0);
  double best = none, bestV = 0;
  for (int k = 1; k <= 60; ++k) {
    const double cost = meanAbsResidual(0.01 * k);
    if (cost < best) best = cost, bestV = 0.01 * k;
  }
  out.vignetting = bestV;
  out.vignettingResidualRatio = none > 0 ? best / none : 1;
}

// Step 6, the decomposition: colour Retinex from the photo alone, scaled per channel so that its
// median ratio to the physical per-pixel albedo is 1 (Retinex has no scale of its own), then the
// geometry-aware objective, whose data terms tie rho * Gamma to the photo.
}  // namespace

// What LightingOptions::deferDecomposition leaves for finishDecomposition: the decomposition's
// inputs as the estimate made them.
struct PendingDecomposition {
  // The estimate's photo and gathered light (the sun ratio changes the estimate's before the
  // response check's verdict) and the decomposition's start (rho0).
  ImageF photo, gathered, start;
  std::vector<uint8_t> valid, clipped;  // its masks (Decomposer::masks)
  std::vector<int> surface;             // per pixel: the surface it shows (-1: none)
  DecomposeOptions options;
  bool renderFittedCeiling = false;
  int threads = 0;  // LightingOptions::threads
};

namespace {

// The decomposition from `start`: its albedo and direct light replace the light fit's wherever a
// pixel shows the room (`surface` >= 0).
std::optional<Error> decomposeInto(LightingEstimate& out, const ImageF& photo, const ImageF& gathered,
                                   const ImageF& start, const std::vector<uint8_t>& valid,
                                   const std::vector<uint8_t>& clipped, const std::vector<int>& surface,
                                   const DecomposeOptions& options) {
  auto dec = decomposeIntrinsic(photo, gathered, start, valid, clipped, options);
  out.decomposeStart = start;
  out.decomposeValid = valid;
  out.decomposeClipped = clipped;
  if (!dec) return dec.error().underKey("decomposition");
  out.decomposeHistory = dec->history;
  out.decomposeReport = dec->report;
  out.decomposeConverged = dec->converged;
  if (!dec->converged) out.notes.push_back("decomposition: " + dec->report);
  const int W = photo.width, H = photo.height;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      if (surface[size_t(y) * W + x] < 0) continue;
      out.albedo.setRgb(x, y, dec->albedo.rgb(x, y));
      out.direct.setRgb(x, y, dec->direct.rgb(x, y));
    }
  return std::nullopt;
}

// Each surface's mean albedo over its valid pixels; surfaces the camera does not see: walls and
// the ceiling take the mean of the walls it sees.
void meanAlbedoOfSurfaces(LightingEstimate& out, const std::vector<uint8_t>& valid,
                          const std::vector<int>& surface, const SceneGeometry& geometry,
                          bool renderFittedCeiling) {
  const size_t S = geometry.surfaces.size();
  const int W = out.albedo.width, H = out.albedo.height;
  std::vector<Vec3> albedoSum(S, Vec3::Zero());
  std::vector<double> albedoCount(S, 0);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const size_t idx = size_t(y) * W + x;
      if (!valid[idx]) continue;
      albedoSum[size_t(surface[idx])] += out.albedo.rgb(x, y);
      albedoCount[size_t(surface[idx])] += 1;
    }
  std::vector<Vec3> meanSeen(S, Vec3::Zero());
  for (size_t s = 0; s < S; ++s)
    if (albedoCount[s] > 0) meanSeen[s] = albedoSum[s] / albedoCount[s];
  out.surfaceMeanAlbedo = albedoOfUnseen(geometry, meanSeen, albedoCount, kUnseenCeilingAlbedo);
  if (!renderFittedCeiling) return;
  // The fit's estimate of an unseen ceiling where the photo told it (LightingOptions::
  // renderFittedCeiling).
  for (size_t s = 0; s < S; ++s)
    if (albedoCount[s] == 0 && geometry.surfaces[s].kind == SurfaceKind::Ceiling)
      for (int c = 0; c < 3; ++c)
        if (out.unseenCeilingTold[size_t(c)] && std::isfinite(out.unseenCeilingAlbedo[c]))
          out.surfaceMeanAlbedo[s][c] = out.unseenCeilingAlbedo[c];
}

class Decomposer {
 public:
  explicit Decomposer(LightingFit& fit) : f(fit), W(fit.W), H(fit.H) {}
  std::optional<Error> run();  // the decomposition's error, if any
  void surfaceMeanAlbedo();

 private:
  void masks();
  ImageF anchoredRetinex(const ImageF& image, const std::vector<uint8_t>& use, bool gammaAnchor,
                         const ImageF* fallback) const;
  LightingFit& f;
  const int W, H;
  std::vector<uint8_t> valid, validPhoto, clipped;
  bool haveIndirect = false;
};

// The decomposition's masks: photo pixels with a measurement (validPhoto), those the model
// explains (valid: its data terms apply) and the clipped ones.
void Decomposer::masks() {
  const LightingOptions& opt = f.opt;
  valid.assign(size_t(W) * H, 0), validPhoto.assign(size_t(W) * H, 0), clipped.assign(size_t(W) * H, 0);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const size_t idx = size_t(y) * W + x;
      clipped[idx] = f.saturated(x, y) ? 1 : 0;
      validPhoto[idx] = f.ps[idx].surface >= 0 && !f.isLight(x, y) && !clipped[idx] &&
                        luminance(f.photo.rgb(x, y)) > 0.1 * opt.blackBelow;
      // A pixel brighter than any reflectance could make it under the modelled light is one
      // the model does not explain (a light or an opening it lacks, a surface that is not
      // where the geometry says, such as the floor seen between a table's legs): its albedo
      // comes from the photo's own Retinex, and the data terms leave it alone.
      const Vec3 sf = f.shadingFree.rgb(x, y);
      valid[idx] = validPhoto[idx] && sf.maxCoeff() <= opt.unexplainedAbove &&
                   !f.isProxy(f.ps[idx].surface);
    }
  size_t nValid = 0, nIndirect = 0;
  for (size_t i = 0; i < valid.size(); ++i)
    if (valid[i]) ++nValid, nIndirect += f.directShare[i] < 0.25f;
  haveIndirect = nIndirect >= std::max<size_t>(200, nValid / 50);
}

// Retinex of `image`, scaled per channel so its median ratio to the physical albedo is 1.
// With `gammaAnchor`, the ratio is also taken where Gamma dominates the shading: there
// rho = B / Gamma does not depend on the fitted lights (the flat direction rho / k, L * k);
// the scale is the geometric mean of the two anchors when there are enough such pixels.
// `fallback`: the albedo of pixels not in `use` (default: the physical one).
ImageF Decomposer::anchoredRetinex(const ImageF& image, const std::vector<uint8_t>& use,
                                   bool gammaAnchor, const ImageF* fallback) const {
  const ImageF& physical = f.out.albedo;
  const ImageF rel = retinexReflectance(image, use, f.opt.retinex);
  auto medianRatio = [&](int c, bool indirectOnly) {
    std::vector<float> ratio;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        if (valid[size_t(y) * W + x] && rel.at(x, y, c) > 1e-4f && physical.at(x, y, c) > 0 &&
            physical.at(x, y, c) < 1 && (!indirectOnly || f.directShare[size_t(y) * W + x] < 0.25f))
          ratio.push_back(physical.at(x, y, c) / rel.at(x, y, c));
    if (ratio.empty()) return 1.0;
    std::nth_element(ratio.begin(), ratio.begin() + long(ratio.size() / 2), ratio.end());
    return double(ratio[ratio.size() / 2]);
  };
  Vec3 scale(1, 1, 1);
  for (int c = 0; c < 3; ++c) {
    scale[c] = medianRatio(c, false);
    if (gammaAnchor && haveIndirect) scale[c] = std::sqrt(scale[c] * medianRatio(c, true));
  }
  ImageF a(W, H, 3, 0.f);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const size_t idx = size_t(y) * W + x;
      if (f.ps[idx].surface < 0) continue;
      for (int c = 0; c < 3; ++c) {
        // Lamps and clipped pixels carry no reflectance: the fallback stands.
        const float r = use[idx] ? float(scale[c] * rel.at(x, y, c))
                                 : (fallback ? *fallback : physical).at(x, y, c);
        a.at(x, y, c) = std::clamp(std::isfinite(r) ? r : 0.5f, 0.f, 1.f);
      }
    }
  return a;
}

// The baseline Retinex, then (LightingOptions::objective) the decomposition started from Retinex
// of the shading-free image; its albedo and direct light replace the physical ones.
std::optional<Error> Decomposer::run() {
  LightingEstimate& out = f.out;
  masks();
  std::optional<StepTimer> timer(std::in_place, out.steps, "retinex");
  // The baseline: Retinex of the photo alone.
  out.retinexAlbedo = anchoredRetinex(f.photo, validPhoto, false, nullptr);
  if (!f.opt.objective) {
    out.albedo = out.retinexAlbedo;
    return std::nullopt;
  }
  // The start: Retinex of the photo with the geometry's shading divided out (what is left of
  // shading there is noise and model error, which the thresholds remove).
  const ImageF rho0 = anchoredRetinex(f.shadingFree, valid, true, &out.retinexAlbedo);
  DecomposeOptions dopt = f.opt.decompose;
  if (!dopt.cancel) dopt.cancel = f.opt.cancel;
  if (f.opt.deferDecomposition) {
    auto pending = std::make_shared<PendingDecomposition>();
    pending->photo = f.photo;
    pending->gathered = out.gathered;
    pending->start = rho0;
    pending->valid = valid;
    pending->clipped = clipped;
    pending->surface = out.firstSurfacePerPixel;
    pending->options = dopt;
    pending->renderFittedCeiling = f.opt.renderFittedCeiling;
    pending->threads = f.opt.threads;
    out.pendingDecomposition = std::move(pending);
    return std::nullopt;
  }
  timer.emplace(out.steps, "decomposition");
  return decomposeInto(out, f.photo, out.gathered, rho0, valid, clipped, out.firstSurfacePerPixel, dopt);
}

// Each surface's mean albedo (meanAlbedoOfSurfaces) with the decomposition's masks.
void Decomposer::surfaceMeanAlbedo() {
  meanAlbedoOfSurfaces(f.out, valid, f.out.firstSurfacePerPixel, f.geometry, f.opt.renderFittedCeiling);
}

}  // namespace

int gatherStrideFor(int width, int height, int stride, int maxPoints) {
  int s = std::max(1, stride);
  if (maxPoints <= 0 || width <= 0 || height <= 0) return s;
  auto points = [&](int k) { return int64_t((width + k - 1) / k) * int64_t((height + k - 1) / k); };
  // From below the answer (the square grid's stride), up to the first that fits.
  const double square = std::sqrt(double(width) * double(height) / double(maxPoints));
  s = std::max(s, int(std::floor(square)));
  while (points(s) > maxPoints && s < std::max(width, height)) ++s;
  return s;
}

Expected<LightingEstimate> estimateLighting(const ImageF& photo, const Camera& camera,
                                            const SceneGeometry& geometry,
                                            const std::vector<AreaLight>& lightsIn,
                                            const std::vector<bool>& refineIn, const ImageF& lightMask,
                                            const std::vector<SunLight>& suns,
                                            const LightingOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  if (photo.width <= 0 || photo.height <= 0 || photo.channels < 3)
    return Error{"", "photo", "the photo is empty"};
  std::unique_ptr<tbb::global_control> threadLimit;
  if (opt.threads > 0)
    threadLimit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                        size_t(opt.threads));
  auto cancelled = [] { return Error{"", "", "cancelled"}; };

  LightingFit fit(photo, camera, geometry, lightsIn, refineIn, lightMask, suns, opt);
  std::vector<LightingStepTime>& steps = fit.out.steps;
  std::optional<StepTimer> timer(std::in_place, steps, "surfaces");
  fit.findPixelSurfaces();
  if (fit.stop()) return cancelled();
  if (!fit.measureSurfaceRadiance())
    return Error{"", "photo", "no pixel of the photo falls on the room"};
  fit.countClippedPixels();
  timer.emplace(steps, "direct light");
  if (!fit.computeDirectLight()) return cancelled();
  timer.emplace(steps, "fit pixels");
  if (!fit.chooseFitPixels())
    return Error{"", "photo", "every pixel of the room is black or saturated: nothing to fit"};
  timer.emplace(steps, "gather");
  fit.chooseGatherSamples();
  fit.adoptOrTraceRays();
  timer.reset();
  if (!fit.gatherAndFit()) return cancelled();
  fit.reportUnseenCeiling();
  timer.emplace(steps, "per-pixel albedo");
  fit.perPixelAlbedo();
  fit.relativeFitResidual();
  fit.vignettingFromResidual();
  timer.reset();
  Decomposer decomposer(fit);
  if (auto error = decomposer.run()) return *error;
  if (!fit.out.pendingDecomposition) decomposer.surfaceMeanAlbedo();
  fit.out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return std::move(fit.out);
}

std::optional<Error> finishDecomposition(LightingEstimate& estimate, const SceneGeometry& geometry) {
  const std::shared_ptr<const PendingDecomposition> pending = std::move(estimate.pendingDecomposition);
  estimate.pendingDecomposition.reset();
  if (!pending) return std::nullopt;
  const PendingDecomposition& d = *pending;
  std::unique_ptr<tbb::global_control> threadLimit;  // the estimate's, as estimateLighting sets it
  if (d.threads > 0)
    threadLimit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                        size_t(d.threads));
  {
    const StepTimer timer(estimate.steps, "decomposition");
    if (auto error = decomposeInto(estimate, d.photo, d.gathered, d.start, d.valid, d.clipped, d.surface,
                                   d.options))
      return error;
  }
  meanAlbedoOfSurfaces(estimate, d.valid, d.surface, geometry, d.renderFittedCeiling);
  return std::nullopt;
}

ImageF radianceForBounces(const ImageF& photo, const Camera& camera, const SceneGeometry& geometry,
                          const LightingEstimate& lighting, double saturatedAbove) {
  ImageF out = photo;
  const int W = photo.width, H = photo.height;
  if (lighting.suns.empty() || photo.channels < 3 || lighting.albedo.width != W ||
      lighting.albedo.height != H || lighting.gathered.width != W || lighting.gathered.height != H)
    return out;
  const RoomTracer tracer(geometry);
  // The light fit's albedo: at clipped pixels its surface's, fitted with the suns' strengths
  // (their product is what the unclipped room determines).
  const bool physical = lighting.physicalAlbedo.width == W && lighting.physicalAlbedo.height == H;
  const ImageF& rho = physical ? lighting.physicalAlbedo : lighting.albedo;
  parallelFor(tbb::blocked_range<int>(0, H), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y)
      for (int x = 0; x < W; ++x) {
        const Vec3 b = photo.rgb(x, y);
        if (!b.allFinite() || b.maxCoeff() < saturatedAbove) continue;
        const auto h = tracer.intersect(camera.rayThroughPixel(Vec2((x + 0.5) * camera.widthPx / W,
                                                                    (y + 0.5) * camera.heightPx / H)),
                                        1e-6);
        if (!h) continue;
        const Vec3 p = h->pointWorld + 1e-5 * h->normalWorld;
        Vec3 sunlight = Vec3::Zero();
        for (const SunLight& sun : lighting.suns)
          sunlight += sun.irradianceOverPi *
                      unitSunIrradianceOverPi(tracer, geometry, sun, p, h->normalWorld);
        if (!(sunlight.maxCoeff() > 0)) continue;  // clipped but no sun: a window or a lamp
        Vec3 irradiance = lighting.gathered.rgb(x, y) + sunlight;
        for (size_t j = 0; j < lighting.lights.size(); ++j)
          irradiance += lighting.lights[j].radiance *
                        tracer.unitLightIrradianceOverPi(lighting.lights[j], p, h->normalWorld, 16,
                                                         uint32_t(y * W + x) * 31u + uint32_t(j));
        const Vec3 predicted = rho.rgb(x, y).cwiseProduct(irradiance);
        if (predicted.allFinite()) out.setRgb(x, y, predicted.cwiseMax(b));
      }
  });
  return out;
}

}  // namespace inlay
