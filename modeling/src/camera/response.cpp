// The camera response model and its estimate from a photo's edges (see response.h).
#include "inlay/modeling/response.h"
#include "inlay/modeling/photo_codes.h"

#include "code_statistics.h"
#include "lines.h"
#include "noise_level.h"
#include "inlay/modeling/parallel.h"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>

namespace inlay {

namespace {

// The radiance warp W = S_s o T_t o (.)^p and its inverse, on [0,1].
double warp(const ResponseParams& q, double x) {
  double u = std::pow(std::clamp(x, 0.0, 1.0), q.power);
  u = (1 + q.toe) * u * u / std::max(u + q.toe, 1e-300);
  return (1 + q.shoulder) * u / (1 + q.shoulder * u);
}
double unwarp(const ResponseParams& q, double u) {
  u = std::clamp(u, 0.0, 1.0);
  u = u / (1 + q.shoulder - q.shoulder * u);                                     // S^-1
  u = (u + std::sqrt(u * u + 4 * (1 + q.toe) * u * q.toe)) / (2 * (1 + q.toe));  // T^-1
  return std::clamp(std::pow(u, 1 / q.power), 0.0, 1.0);
}

double clampOr(double v, double lo, double hi, double fallback) {
  return std::isfinite(v) ? std::clamp(v, lo, hi) : fallback;
}

}  // namespace

ResponseParams ResponseParams::clamped() const {
  ResponseParams q;
  q.power = clampOr(power, kMinPower, kMaxPower, 1.0);
  q.toe = clampOr(toe, 0.0, kMaxToe, 0.0);
  q.shoulder = clampOr(shoulder, 0.0, kMaxShoulder, 0.0);
  return q;
}

CameraResponse::CameraResponse() { buildTables(); }

CameraResponse CameraResponse::srgb() { return CameraResponse(); }

CameraResponse CameraResponse::linear() {
  CameraResponse r;
  r.family_ = ResponseFamily::Linear;
  r.buildTables();
  return r;
}

CameraResponse CameraResponse::toeShoulder(const ResponseParams& params) {
  CameraResponse r;
  r.family_ = ResponseFamily::ToeShoulder;
  r.params_ = params.clamped();
  r.buildTables();
  return r;
}

std::string CameraResponse::familyName() const {
  switch (family_) {
    case ResponseFamily::Srgb: return "srgb";
    case ResponseFamily::Linear: return "linear";
    case ResponseFamily::ToeShoulder: return "toe_shoulder";
  }
  return "srgb";
}

std::string CameraResponse::describe() const {
  if (family_ != ResponseFamily::ToeShoulder) return familyName();
  char buf[160];
  std::snprintf(buf, sizeof buf, "toe_shoulder (power %.3f, toe %.3f, shoulder %.3g)", params_.power,
                params_.toe, params_.shoulder);
  return buf;
}

double CameraResponse::encode(double x) const {
  switch (family_) {
    case ResponseFamily::Srgb: return linearToSrgb(x);
    case ResponseFamily::Linear: return std::isfinite(x) ? std::clamp(x, 0.0, 1.0) : 0.0;
    case ResponseFamily::ToeShoulder: return std::isfinite(x) ? linearToSrgb(warp(params_, x)) : 0.0;
  }
  return 0;
}

double CameraResponse::decode(double y) const {
  if (!std::isfinite(y)) y = 0;
  switch (family_) {
    case ResponseFamily::Srgb: return srgbToLinear(y);
    case ResponseFamily::Linear: return std::clamp(y, 0.0, 1.0);
    case ResponseFamily::ToeShoulder: return unwarp(params_, srgbToLinear(y));
  }
  return 0;
}

void CameraResponse::buildTables() {
  for (int k = 0; k < 256; ++k)
    table8_[size_t(k)] = family_ == ResponseFamily::Srgb ? srgbToLinear(float(k) / 255.f)
                                                         : float(decode(k / 255.0));
  for (int k = 0; k < 255; ++k) thresholds8_[size_t(k)] = float(decode((k + 0.5) / 255.0));
  // Strictly increasing, codes and thresholds interleaved, whatever the rounding did.
  table8_[0] = 0.f;
  table8_[255] = 1.f;
  for (int k = 0; k < 255; ++k) {
    float& t = thresholds8_[size_t(k)];
    t = std::max(t, std::nextafter(table8_[size_t(k)], 2.f));
    float& next = table8_[size_t(k + 1)];
    next = std::max(next, std::nextafter(t, 2.f));
  }
  INLAY_CHECK(table8_[255] == 1.f);
}

unsigned char CameraResponse::encodeCode8(float v) const {
  if (family_ == ResponseFamily::Srgb) return srgbCode8(v);  // as image_io has always written
  if (!(v > 0.f)) return 0;
  // The first threshold above v is the code's upper bound.
  return (unsigned char)(std::upper_bound(thresholds8_.begin(), thresholds8_.end(), v) -
                         thresholds8_.begin());
}

// Rows in parallel (each value on its own: the result does not depend on the threads).
std::vector<unsigned char> srgbCodesOf(const ImageF& img) {
  std::vector<unsigned char> codes(img.pixelCount() * 3);
  const size_t W = size_t(std::max(0, img.width));
  parallelFor(tbb::blocked_range<int>(0, img.height), [&](const tbb::blocked_range<int>& rows) {
    for (size_t i = size_t(rows.begin()) * W; i < size_t(rows.end()) * W; ++i)
      for (int c = 0; c < 3; ++c)
        codes[i * 3 + size_t(c)] =
            srgbCode8(img.data[i * size_t(img.channels) + size_t(img.channels >= 3 ? c : 0)]);
  });
  return codes;
}

void redecodePhoto(ImageF& img, int bitsPerChannel, const CameraResponse& response) {
  const auto& table = response.table8();
  const double levels = std::exp2(std::min(bitsPerChannel, 16)) - 1;
  const size_t rowValues = size_t(std::max(0, img.width)) * size_t(img.channels);
  parallelFor(tbb::blocked_range<int>(0, img.height), [&](const tbb::blocked_range<int>& rows) {
    for (size_t i = size_t(rows.begin()) * rowValues; i < size_t(rows.end()) * rowValues; ++i) {
      float& v = img.data[i];
      if (bitsPerChannel <= 8) {
        v = table[srgbCode8(v)];
      } else {
        const double e = std::round(linearToSrgb(double(v)) * levels) / levels;
        v = float(response.decode(e));
      }
    }
  });
}

void redecodePhotoFromCodes(ImageF& img, const std::vector<unsigned char>& codes,
                            const CameraResponse& response) {
  if (img.channels != 3 || codes.size() != img.data.size()) return redecodePhoto(img, 8, response);
  const auto& table = response.table8();
  const size_t rowValues = size_t(img.width) * 3;
  parallelFor(tbb::blocked_range<int>(0, img.height), [&](const tbb::blocked_range<int>& rows) {
    for (size_t i = size_t(rows.begin()) * rowValues; i < size_t(rows.end()) * rowValues; ++i)
      img.data[i] = table[codes[i]];
  });
}

// ---------------------------------------------------------------------------------------------
// The estimate.

namespace {

constexpr double kReachPx = 4.0;  // pixels within this distance of a segment are its profile
constexpr double kSidePx = 2.0;   // beyond this the profile is one of the two flat sides
constexpr double kBinPx = 0.25;   // the profile's bins (a slanted edge super-resolves it)
constexpr int kBins = int(2 * kReachPx / kBinPx);

struct EdgeSample {
  float d;  // signed distance to the segment's line, px
  unsigned char code[3];
};

struct Edge {
  std::vector<EdgeSample> samples;
  int lumaLo = 0, lumaHi = 0;  // the two sides' mean luma codes
};

double lumaCode(const unsigned char* c) { return (c[0] + c[1] + c[2]) / 3.0; }

// The photo's pixels within kReachPx of segment [a, b] (away from its ends), no pixel twice.
std::vector<EdgeSample> profileOf(const std::vector<unsigned char>& codes, int W, int H, Vec2 a,
                                  Vec2 b) {
  std::vector<EdgeSample> out;
  const Vec2 t = (b - a).normalized(), n(-t.y(), t.x());
  const double len = (b - a).norm();
  const bool alongX = std::fabs(t.x()) >= std::fabs(t.y());
  const double lo = alongX ? std::min(a.x(), b.x()) : std::min(a.y(), b.y());
  const double hi = alongX ? std::max(a.x(), b.x()) : std::max(a.y(), b.y());
  const double across = kReachPx / std::max(1e-6, alongX ? std::fabs(n.y()) : std::fabs(n.x()));
  for (int i = int(std::floor(lo)); i <= int(std::ceil(hi)); ++i) {
    // The line's other coordinate at this column (row) centre.
    const double s = i + 0.5;
    const double o = alongX ? a.y() + (s - a.x()) * t.y() / t.x() : a.x() + (s - a.y()) * t.x() / t.y();
    for (int j = int(std::floor(o - across)); j <= int(std::ceil(o + across)); ++j) {
      const int x = alongX ? i : j, y = alongX ? j : i;
      if (x < 0 || y < 0 || x >= W || y >= H) continue;
      const Vec2 p(x + 0.5, y + 0.5);
      const double d = n.dot(p - a), u = t.dot(p - a);
      if (std::fabs(d) > kReachPx || u < 3 || u > len - 3) continue;
      EdgeSample e;
      e.d = float(d);
      for (int c = 0; c < 3; ++c) e.code[c] = codes[(size_t(y) * W + x) * 3 + size_t(c)];
      out.push_back(e);
    }
  }
  return out;
}

// A clean edge between two flat, unclipped regions that differ, judged on the codes.
bool cleanEdge(const std::vector<EdgeSample>& s, Edge& edge) {
  double sum[2] = {0, 0}, sum2[2] = {0, 0};
  int n[2] = {0, 0}, clipped = 0;
  for (const EdgeSample& e : s) {
    if (std::max({e.code[0], e.code[1], e.code[2]}) >= 250) ++clipped;
    if (std::fabs(e.d) < kSidePx) continue;
    const int side = e.d > 0;
    const double l = lumaCode(e.code);
    sum[side] += l, sum2[side] += l * l, ++n[side];
  }
  if (n[0] < 8 || n[1] < 8 || clipped > 0) return false;
  double mean[2], sd[2];
  for (int k = 0; k < 2; ++k) {
    mean[k] = sum[k] / n[k];
    sd[k] = std::sqrt(std::max(0.0, sum2[k] / n[k] - mean[k] * mean[k]));
  }
  const double contrast = std::fabs(mean[1] - mean[0]);
  if (contrast < 10) return false;
  if (std::max(sd[0], sd[1]) > std::max(2.5, 0.12 * contrast)) return false;
  // A step, not a bar: the middle stays between the sides (a little ringing allowed).
  const double lo = std::min(mean[0], mean[1]) - 0.2 * contrast,
               hi = std::max(mean[0], mean[1]) + 0.2 * contrast;
  int outside = 0, middle = 0;
  for (const EdgeSample& e : s)
    if (std::fabs(e.d) < kSidePx) {
      ++middle;
      const double l = lumaCode(e.code);
      outside += l < lo || l > hi;
    }
  if (middle < 6 || outside > middle / 10) return false;
  edge.samples = s;
  std::sort(edge.samples.begin(), edge.samples.end(),
            [](const EdgeSample& p, const EdgeSample& q) { return p.d < q.d; });
  edge.lumaLo = int(std::min(mean[0], mean[1]));
  edge.lumaHi = int(std::max(mean[0], mean[1]));
  return true;
}

struct EdgeResiduals {
  double symmetry = 0;  // mean (alpha(d0 + t) + alpha(d0 - t) - 1)^2
  double colour = 0;    // mean squared distance from the colour line, in codes of noise
  bool valid = false;
};

// How far the edge, linearised by `g` (code -> linear), is from a symmetric blur of a step
// between two colours.
EdgeResiduals residualsOf(const Edge& edge, const std::array<double, 256>& g) {
  EdgeResiduals r;
  Vec3 A = Vec3::Zero(), B = Vec3::Zero();
  int nA = 0, nB = 0;
  auto lin = [&](const EdgeSample& e) { return Vec3(g[e.code[0]], g[e.code[1]], g[e.code[2]]); };
  for (const EdgeSample& e : edge.samples) {
    if (e.d >= kSidePx) A += lin(e), ++nA;
    if (e.d <= -kSidePx) B += lin(e), ++nB;
  }
  A /= std::max(1, nA), B /= std::max(1, nB);
  const Vec3 D = A - B;
  const double dd = D.squaredNorm();
  if (!(dd > 1e-18)) return r;
  std::array<double, kBins> alpha{};
  std::array<int, kBins> count{};
  double colour = 0;
  int middle = 0;
  for (const EdgeSample& e : edge.samples) {
    const Vec3 v = lin(e) - B;
    const double a = v.dot(D) / dd;
    const int bin = std::clamp(int((e.d + kReachPx) / kBinPx), 0, kBins - 1);
    alpha[size_t(bin)] += a, ++count[size_t(bin)];
    if (std::fabs(e.d) < kSidePx) {
      // The distance from the colour line against what one code of noise moves the pixel
      // (a curve steep where the codes are noisy must not look worse than it is).
      double noise2 = 0;
      for (int c = 0; c < 3; ++c) {
        const int k = e.code[c];
        const double slope = 0.5 * (g[size_t(std::min(k + 1, 255))] - g[size_t(std::max(k - 1, 0))]);
        noise2 += slope * slope;
      }
      colour += (v - a * D).squaredNorm() / std::max(noise2, 1e-30), ++middle;
    }
  }
  for (int i = 0; i < kBins; ++i)
    if (count[size_t(i)]) alpha[size_t(i)] /= count[size_t(i)];
  // The middle: where the profile crosses 1/2, nearest the segment.
  double d0 = 0, best = 1e9, prevD = 0, prevA = 0;
  bool havePrev = false;
  for (int i = 0; i < kBins; ++i) {
    if (!count[size_t(i)]) continue;
    const double d = -kReachPx + (i + 0.5) * kBinPx;
    if (havePrev && (prevA - 0.5) * (alpha[size_t(i)] - 0.5) <= 0 && prevA != alpha[size_t(i)]) {
      const double c = prevD + (0.5 - prevA) / (alpha[size_t(i)] - prevA) * (d - prevD);
      if (std::fabs(c) < std::fabs(best)) best = c;
    }
    prevD = d, prevA = alpha[size_t(i)], havePrev = true;
  }
  if (std::fabs(best) > kSidePx) return r;
  d0 = best;
  // The blur of a step is point-symmetric about its middle: its line spread (the profile's
  // derivative) within kSidePx of the middle has its mean where the profile crosses 1/2. The
  // gap, in units of the spread's width, is scale-free: a curve cannot shrink it by making the
  // edge look sharper.
  double w = 0, m1 = 0, m2 = 0, prevAlpha = 0, prevPos = 0;
  bool first = true;
  for (int i = 0; i < kBins; ++i) {
    if (!count[size_t(i)]) continue;
    const double d = -kReachPx + (i + 0.5) * kBinPx;
    if (std::fabs(d - d0) > kSidePx + kBinPx) continue;
    if (!first) {
      const double step = alpha[size_t(i)] - prevAlpha, mid = 0.5 * (d + prevPos);
      w += step, m1 += step * mid, m2 += step * mid * mid;
    }
    prevAlpha = alpha[size_t(i)], prevPos = d, first = false;
  }
  if (!(w > 0.5)) return r;
  const double mean = m1 / w, var = m2 / w - mean * mean;
  if (!(var > 1e-4)) return r;
  const double skew = (mean - d0) / std::sqrt(var);
  r.symmetry = skew * skew;
  r.colour = colour / std::max(1, middle);
  r.valid = true;
  return r;
}

struct Fit {
  const std::vector<Edge>* edges;
  const detail::NoiseLevel* noise;
  ResponseEstimateOptions options;

  static ResponseParams paramsOf(const Vec3& x) {
    ResponseParams q;
    q.power = x[0];
    q.toe = x[1];
    q.shoulder = std::expm1(std::max(0.0, x[2]));
    return q.clamped();
  }
  // The cue's residual (without the prior): the noise level's distance from a quadratic
  // variance, the mean robust edge residual, or (NoiseColour) the first plus edgeWeight times
  // the colour edges' part of the second.
  double data(const ResponseParams& q) const {
    const CameraResponse f = CameraResponse::toeShoulder(q);
    std::array<double, 256> g;
    for (int k = 0; k < 256; ++k) g[size_t(k)] = f.table8()[size_t(k)];
    using Cue = ResponseEstimateOptions::Cue;
    if (options.cue == Cue::Noise) return detail::noiseLevelResidual(*noise, g);
    if (options.cue == Cue::NoiseColour)
      return detail::noiseLevelResidual(*noise, g) +
             (edges->empty() ? 0.0 : options.edgeWeightOrDefault() * edgeResidual(g, Cue::Colour));
    return edgeResidual(g, options.cue);
  }
  // The noise level's residual alone (noise cues; 0 otherwise).
  double noiseData(const ResponseParams& q) const {
    if (!options.noiseCue()) return 0;
    const CameraResponse f = CameraResponse::toeShoulder(q);
    std::array<double, 256> g;
    for (int k = 0; k < 256; ++k) g[size_t(k)] = f.table8()[size_t(k)];
    return detail::noiseLevelResidual(*noise, g);
  }
  // The mean over the edges of the `cue` residual (Symmetry, Colour or Both), each through a
  // Cauchy-like cap at its scale (a skew of 0.2; two codes of noise off the colour line), so a
  // few odd edges cannot dominate; an edge whose middle got lost counts as a bad one (1).
  double edgeResidual(const std::array<double, 256>& g, ResponseEstimateOptions::Cue cue) const {
    using Cue = ResponseEstimateOptions::Cue;
    auto robust = [](double raw, double scale) { return raw / (1 + raw / scale) / scale; };
    double sum = 0;
    int n = 0;
    for (const Edge& e : *edges) {
      const EdgeResiduals r = residualsOf(e, g);
      double v = 1.0;
      if (r.valid)
        v = cue == Cue::Symmetry ? robust(r.symmetry, 0.04)
            : cue == Cue::Colour ? robust(r.colour, 4.0)
                                 : 0.5 * (robust(r.symmetry, 0.04) + robust(r.colour, 4.0));
      sum += v, ++n;
    }
    return n ? sum / n : 0;
  }
  // The pull toward sRGB: on the power, and on the toe and shoulder.
  double prior(const Vec3& x) const {
    const double p = (x[0] - 1) / 0.25, t = x[1] / 0.25, s = std::max(0.0, x[2]) / 1.5;
    return options.priorWeightOrDefault() * p * p +
           options.shapePriorWeightOrDefault() * (t * t + s * s);
  }
  double operator()(const Vec3& x) const {
    const Vec3 lo(ResponseParams::kMinPower, 0, 0),
        hi(ResponseParams::kMaxPower, ResponseParams::kMaxToe, std::log1p(ResponseParams::kMaxShoulder));
    const Vec3 c = x.cwiseMax(lo).cwiseMin(hi);
    return data(paramsOf(c)) + prior(c) + 10 * (x - c).squaredNorm();
  }
};

// Nelder-Mead from `start` (a few hundred evaluations at most).
Vec3 nelderMead(const Fit& f, const Vec3& start, double& value, const CancelToken* cancel,
                const std::function<void(double)>& improved) {
  std::array<Vec3, 4> p;
  std::array<double, 4> v;
  const Vec3 step(0.08, 0.08, 0.4);
  p[0] = start;
  for (int i = 0; i < 3; ++i) {
    p[size_t(i + 1)] = start;
    p[size_t(i + 1)][i] += step[i];
  }
  for (int i = 0; i < 4; ++i) v[size_t(i)] = f(p[size_t(i)]);
  for (int iter = 0; iter < 150; ++iter) {
    if (cancel && cancel->shouldStop()) break;
    std::array<int, 4> o{0, 1, 2, 3};
    std::sort(o.begin(), o.end(), [&](int a, int b) { return v[size_t(a)] < v[size_t(b)]; });
    const size_t best = size_t(o[0]), worst = size_t(o[3]), second = size_t(o[2]);
    if (v[worst] - v[best] < 1e-7) break;
    const Vec3 c = (p[0] + p[1] + p[2] + p[3] - p[worst]) / 3;
    const Vec3 xr = c + (c - p[worst]);
    const double fr = f(xr);
    if (fr < v[best]) {
      const Vec3 xe = c + 2 * (c - p[worst]);
      const double fe = f(xe);
      if (fe < fr) p[worst] = xe, v[worst] = fe;
      else p[worst] = xr, v[worst] = fr;
      improved(std::min(fe, fr));
    } else if (fr < v[second]) {
      p[worst] = xr, v[worst] = fr;
    } else {
      const Vec3 xc = c + 0.5 * (p[worst] - c);
      const double fc = f(xc);
      if (fc < v[worst]) {
        p[worst] = xc, v[worst] = fc;
      } else {
        for (size_t i = 0; i < 4; ++i)
          if (i != best) p[i] = p[best] + 0.5 * (p[i] - p[best]), v[i] = f(p[i]);
      }
    }
  }
  const size_t b = size_t(std::min_element(v.begin(), v.end()) - v.begin());
  value = v[b];
  return p[b];
}

// The parameters minimising `fit`: a coarse grid, then Nelder-Mead from its best point; none
// when cancelled.
std::optional<ResponseParams> searchParams(const Fit& fit, const CancelToken* cancel,
                                           const std::function<void(double)>& improved) {
  double best = std::numeric_limits<double>::infinity();
  Vec3 bestX(1, 0, 0);
  for (double p = 0.4; p <= 1.61; p += 0.1)
    for (double t : {0.0, 0.1, 0.25, 0.5, 1.0})
      for (double s = 0; s <= 6.01; s += 1) {
        if (cancel && cancel->shouldStop()) return std::nullopt;
        const Vec3 x(p, t, s);
        const double v = fit(x);
        if (v < best) best = v, bestX = x, improved(v);
      }
  double value = best;
  const Vec3 x = nelderMead(fit, bestX, value, cancel, improved);
  if (value < best) bestX = x;
  return Fit::paramsOf(bestX.cwiseMax(Vec3(ResponseParams::kMinPower, 0, 0)));
}

// Which parameter of `q` lies at (within 5 % of the range of) a bound of the family, or empty.
std::string atBoundOf(const ResponseParams& q) {
  using P = ResponseParams;
  const double powerSlack = 0.05 * (P::kMaxPower - P::kMinPower);
  if (q.power <= P::kMinPower + powerSlack || q.power >= P::kMaxPower - powerSlack) return "power";
  if (q.toe >= 0.95 * P::kMaxToe) return "toe";
  if (q.shoulder >= 0.95 * P::kMaxShoulder) return "shoulder";
  return {};
}

// The stops a response spans between codes 128 and 254 (sRGB: 2.2).
double topHalfStops(const CameraResponse& r) {
  return std::log2(std::max(r.decode(254 / 255.0), 1e-30) / std::max(r.decode(128 / 255.0), 1e-30));
}

// Why the fitted curve claims more about the bright half of the codes than the photo shows
// (ResponseEstimateOptions::maxTopStops), as a "kept sRGB: ..." decision; empty when it does not.
std::string unsupportedShoulder(const ResponseEstimateOptions& options, const ResponseEstimate& out) {
  const double stops = topHalfStops(out.response);
  if (!(stops > options.maxTopStops)) return {};
  int levels = 0;
  for (const auto& bin : out.noiseLevel) levels += bin[0] >= 128 ? 1 : 0;
  if (levels >= options.minTopLevels) return {};
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "kept sRGB: the fitted %s spans %.1f stops between codes 128 and 254 (sRGB 2.2, "
                "at most %.0f trusted), but the photo's noise was measured at only %d code "
                "level%s in that half (%d needed), so the shoulder is an extrapolation",
                out.response.describe().c_str(), stops, options.maxTopStops, levels,
                levels == 1 ? "" : "s", options.minTopLevels);
  return buf;
}

// The 1st percentile of the pixels' sRGB-decoded luminance (the mean of the three channels'
// linear values) over its median, in [0, 1]; 1 (no evidence of contrast) when the median is black.
double darkFillOf(const std::vector<unsigned char>& codes) {
  const std::vector<float> q = detail::luminanceQuantiles(codes, {0.5, 0.01});
  if (q.empty()) return 1;
  const double median = q[0], dark = q[1];
  return median > 0 ? std::clamp(dark / median, 0.0, 1.0) : 1.0;
}

// Whether the photo's shadows show a contrast curve (ResponseEstimateOptions::maxDarkFill).
bool darkFillShowsContrast(const ResponseEstimateOptions& options, const ResponseEstimate& out) {
  return options.noiseCue() && options.darkFillOn() && out.darkFill < *options.maxDarkFill;
}

// Keeps the fitted curve in `out` only when it lowers the cue's residual enough, the cue (or
// the shadows' contrast) shows enough evidence against sRGB and its shoulder is measured rather
// than extrapolated; otherwise sRGB, with the reason in `decision` (and a warning when only the
// evidence was missing).
void acceptOrKeepSrgb(const ResponseEstimateOptions& options, ResponseEstimate& out) {
  const bool noiseCue = options.noiseCue();
  const bool contrast = darkFillShowsContrast(options, out);
  const double minImprovement = contrast ? options.darkFillMinImprovement
                                         : options.minImprovementOrDefault();
  char buf[320];
  out.decision = "fitted";
  if (!(out.evidence <= (1 - minImprovement) * out.srgbEvidence)) {
    std::snprintf(buf, sizeof buf,
                  "kept sRGB: the fitted %s lowers the %s residual only from %.4f to %.4f",
                  out.response.describe().c_str(), noiseCue ? "noise level" : "edge", out.srgbEvidence,
                  out.evidence);
    out.decision = buf;
  } else if (out.srgbEvidence < options.minSrgbResidualOrDefault() && !contrast) {
    std::snprintf(buf, sizeof buf,
                  "kept sRGB: the %s residual of sRGB, %.4f, is within what photos read rightly as "
                  "sRGB show (below %.2f), so the fitted %s is not trusted",
                  noiseCue ? "noise level" : "edge", out.srgbEvidence,
                  options.minSrgbResidualOrDefault(), out.response.describe().c_str());
    out.decision = buf;
    out.warnings.push_back("camera response: too little evidence for a curve other than sRGB (" +
                           out.decision.substr(std::string("kept sRGB: ").size()) + ")");
  } else if (std::string why = unsupportedShoulder(options, out); !why.empty()) {
    out.decision = why;
    out.warnings.push_back("camera response: an implausible curve was refused (" +
                           why.substr(std::string("kept sRGB: ").size()) + "); using sRGB");
  }
  out.darkFillEvidence = contrast && out.decision == "fitted" &&
                         out.srgbEvidence < options.minSrgbResidualOrDefault();
  if (out.decision != "fitted") {
    out.response = CameraResponse::srgb();
    out.objective = out.srgbObjective;
    out.evidence = out.srgbEvidence;
  } else if (const std::string bound = atBoundOf(out.response.params()); !bound.empty()) {
    out.warnings.push_back("camera response: the fitted " + out.response.describe() +
                           " lies at the family's bound (" + bound +
                           "): the camera's curve may be stronger than the family holds");
  }
}

double threadCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// Why the photo cannot determine a curve, or empty: nearly flat, nearly binary, mostly clipped.
std::string photoIsUndetermined(const std::vector<unsigned char>& codes) {
  const detail::LumaSpread spread = detail::lumaSpreadOf(codes);
  const size_t n = spread.pixels;
  if (n == 0) return "the photo is empty";
  const double sum = double(spread.sum), sum2 = double(spread.sumOfSquares);
  const double sd = std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)));
  if (double(spread.clipped) > 0.5 * n) return "most of the photo is clipped to black or white";
  if (sd < 2) return "the photo is nearly one flat colour";
  const size_t populated = size_t(std::count_if(spread.histogram.begin(), spread.histogram.end(),
                                                [&](size_t h) { return h * 1000 >= n; }));
  if (populated < 8)
    return "the photo is nearly binary (" + std::to_string(populated) + " grey levels in use)";
  return {};
}

// The photo's clean straight edges between two flat regions; why they cannot determine a
// curve, or empty.
std::string cleanEdgesOf(const ImageF& img, const std::vector<unsigned char>& codes,
                         const ResponseEstimateOptions& options, std::vector<Edge>& edges,
                         int& segmentsFound) {
  const auto lines = detail::detectLineSegments(img, 1024, options.maxSegments, options.cancel);
  segmentsFound = int(lines.segments.size());
  int lo = 255, hi = 0;
  for (const LineSegment& s : lines.segments) {
    if (options.cancel && options.cancel->shouldStop()) break;
    if (s.lengthPx() < options.minEdgeLengthPx) continue;
    Edge e;
    if (!cleanEdge(profileOf(codes, img.width, img.height, s.aPx, s.bPx), e)) continue;
    lo = std::min(lo, e.lumaLo), hi = std::max(hi, e.lumaHi);
    edges.push_back(std::move(e));
  }
  if (int(edges.size()) < options.minEdges)
    return "too few clean edges between flat regions (" + std::to_string(edges.size()) + " of " +
           std::to_string(options.minEdges) + " needed)";
  if (hi - lo < 48)
    return "the edges cover only codes " + std::to_string(lo) + " to " + std::to_string(hi);
  return {};
}

}  // namespace

ResponseEstimate estimateResponse(const ImageF& img, const ResponseEstimateOptions& options) {
  const bool empty = img.width <= 0 || img.height <= 0 || img.empty();
  return estimateResponseFromCodes(img, empty ? std::vector<unsigned char>{} : srgbCodesOf(img),
                                   options);
}

ResponseEstimate estimateResponseFromCodes(const ImageF& img, const std::vector<unsigned char>& codes,
                                           const ResponseEstimateOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  auto seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };
  const double cpu0 = threadCpuSeconds();
  ResponseEstimate out;
  auto undetermined = [&](const std::string& why) {
    out.response = CameraResponse::srgb();
    out.decision = why;
    out.determined = false;
    out.cpuSeconds = threadCpuSeconds() - cpu0;
    out.warnings.push_back("camera response: " + why + "; using sRGB (give camera.response to choose)");
    out.seconds = seconds();
    return out;
  };
  if (img.width <= 0 || img.height <= 0 || img.empty()) return undetermined("the photo is empty");
  INLAY_CHECK(codes.size() == img.pixelCount() * 3);
  if (std::string why = photoIsUndetermined(codes); !why.empty()) return undetermined(why);
  out.darkFill = darkFillOf(codes);

  std::vector<Edge> edges;
  detail::NoiseLevel noise;
  if (options.noiseCue()) {
    noise = detail::measureNoiseLevel(codes, img.width, img.height, options.noiseQuantileOrDefault());
    out.noiseBins = int(noise.bins.size());
    if (!noise.undetermined.empty()) return undetermined(noise.undetermined);
  }
  if (options.cue == ResponseEstimateOptions::Cue::NoiseColour) {
    // The edges where there are enough of them; otherwise the noise level alone.
    if (std::string why = cleanEdgesOf(img, codes, options, edges, out.segmentsFound); !why.empty()) {
      out.edgeNote = "the noise level alone: " + why;
      edges.clear();
    }
  } else if (!options.noiseCue()) {
    if (std::string why = cleanEdgesOf(img, codes, options, edges, out.segmentsFound); !why.empty()) {
      out.edgesUsed = int(edges.size());
      return undetermined(why);
    }
  }
  out.edgesUsed = int(edges.size());

  Fit fit{&edges, &noise, options};
  out.srgbObjective = fit.data(ResponseParams{});
  out.srgbEvidence = options.noiseCue() ? fit.noiseData(ResponseParams{}) : out.srgbObjective;
  if (options.evaluateAt) {
    out.response = CameraResponse::toeShoulder(*options.evaluateAt);
    out.objective = fit.data(out.response.params());
    out.evidence = options.noiseCue() ? fit.noiseData(out.response.params()) : out.objective;
    out.determined = true;
    out.seconds = seconds();
    return out;
  }
  auto improved = [&](double v) { out.history.emplace_back(seconds(), v); };
  const std::optional<ResponseParams> fitted = searchParams(fit, options.cancel, improved);
  if (!fitted) return undetermined("cancelled");
  if (options.noiseCue())
    for (const detail::NoiseBin& b : noise.bins) out.noiseLevel.push_back({b.code, b.sigma});
  out.response = CameraResponse::toeShoulder(*fitted);
  out.objective = fit.data(*fitted);
  out.evidence = options.noiseCue() ? fit.noiseData(*fitted) : out.objective;
  out.determined = true;
  acceptOrKeepSrgb(options, out);
  out.seconds = seconds();
  out.cpuSeconds = threadCpuSeconds() - cpu0;
  return out;
}

}  // namespace inlay
