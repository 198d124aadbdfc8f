// The denoised preview (denoise.h): guides from one camera ray per pixel, then an edge-aware
// à-trous wavelet filter (Dammertz et al. 2010; variance-guided as in Schied et al.'s SVGF,
// 2017) of the composite's delta X divided by the first hit's albedo.
//
// Layout: every per-pixel quantity is a plane of W x H floats, and each tap of a level is one
// loop over a row segment, so the compiler vectorises the weights (the exponential below is
// branch-free for that reason). Rows are parallel; a row without an active pixel is skipped.
#include "inlay/render/denoise.h"

#include "inlay/modeling/parallel.h"
#include "inlay/modeling/vectorize.h"

#include <tbb/blocked_range.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>

namespace inlay {

namespace {

using Plane = std::vector<float>;

// Inputs beyond this magnitude are clamped (photo units: 1 is a white pixel), so squares and
// the filter's sums stay finite in float.
constexpr float kMaxValue = 1e12f;
constexpr float kMinAlbedo = 0.02f;  // demodulation never divides by less

// exp(-e) for e >= 0, branch-free (vectorisable); e >= 87 gives exactly 0. Relative error
// below 2e-5 (degree-5 Taylor polynomial of 2^f on (-1, 0]).
inline float expNeg(float e) {
  const float clamped = std::min(std::max(e, 0.f), 87.f);
  const float x = clamped * -1.44269504f;  // log2 of the result, in [-125.6, 0]
  const int whole = int(x);                // toward zero: in [-125, 0]
  const float f = x - float(whole);        // in (-1, 0]
  const float t = f * 0.69314718f;
  const float p = 1.f + t * (1.f + t * (0.5f + t * (1.f / 6.f + t * (1.f / 24.f + t * (1.f / 120.f)))));
  const float scale = std::bit_cast<float>(uint32_t(whole + 127) << 23);
  return e < 87.f ? scale * p : 0.f;
}

float finiteOr0(float v) { return std::isfinite(v) ? std::clamp(v, -kMaxValue, kMaxValue) : 0.f; }

// The arena of `threads` threads (0 = all cores), made once per thread count and kept: a
// frame's filter runs about ten parallel loops, and a new arena per loop costs its start-up.
tbb::task_arena& arenaFor(int threads) {
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<tbb::task_arena>> arenas;
  std::lock_guard<std::mutex> lock(mutex);
  std::unique_ptr<tbb::task_arena>& a = arenas[std::max(0, threads)];
  if (!a) a = std::make_unique<tbb::task_arena>(threads > 0 ? threads : int(tbb::task_arena::automatic));
  return *a;
}

// Runs body(y0, y1) over blocks of rows on `threads` threads (0 = all cores).
template <class Body>
void forRows(int height, int threads, const Body& body) {
  arenaFor(threads).execute([&] {
    parallelFor(tbb::blocked_range<int>(0, height, 8),
                [&](const tbb::blocked_range<int>& r) { body(r.begin(), r.end()); });
  });
}

// Pixel i was changed by some sample: an object seen, a difference, or a change in any sample.
bool touched(const DenoiseInput& in, size_t i) {
  const float* a = &in.withObjects->data[i * 3];
  const float* b = &in.withoutObjects->data[i * 3];
  const DifferentialBuffers& s = *in.buffers;
  return a[0] != b[0] || a[1] != b[1] || a[2] != b[2] || in.mask->data[i] != 0.f ||
         s.sumChangeSq.data[i] != 0.f || s.sumChange.data[i * 3] != 0.f ||
         s.sumChange.data[i * 3 + 1] != 0.f || s.sumChange.data[i * 3 + 2] != 0.f;
}

// Pixels within `reach` (a square) of a touched one: the only ones the filter may change.
std::vector<uint8_t> activePixels(const DenoiseInput& in, int reach) {
  const int w = in.withObjects->width, h = in.withObjects->height;
  std::vector<int> integral(size_t(w + 1) * size_t(h + 1), 0);  // touched counts, summed area
  for (int y = 0; y < h; ++y) {
    int row = 0;
    for (int x = 0; x < w; ++x) {
      row += touched(in, size_t(y) * w + x) ? 1 : 0;
      integral[size_t(y + 1) * (w + 1) + x + 1] = integral[size_t(y) * (w + 1) + x + 1] + row;
    }
  }
  std::vector<uint8_t> active(size_t(w) * h, 0);
  for (int y = 0; y < h; ++y) {
    const int y0 = std::max(0, y - reach), y1 = std::min(h, y + reach + 1);
    for (int x = 0; x < w; ++x) {
      const int x0 = std::max(0, x - reach), x1 = std::min(w, x + reach + 1);
      const auto at = [&](int yy, int xx) { return integral[size_t(yy) * (w + 1) + xx]; };
      active[size_t(y) * w + x] = at(y1, x1) - at(y0, x1) - at(y1, x0) + at(y0, x0) > 0;
    }
  }
  return active;
}

// The variance of pixel i's mean change (mean over RGB), from its own samples: unbiased with
// n >= 2, the raw second moment with one sample (as the session's error estimate does).
double meanVariance(const DifferentialBuffers& b, size_t i) {
  const int n = b.samples[i];
  if (n <= 0) return 0;
  const double m2 = double(b.sumChangeSq.data[i]) / n;
  if (n == 1) return std::isfinite(m2) ? m2 : 0.0;
  double meanSq = 0;
  for (int c = 0; c < 3; ++c) {
    const double m = double(b.sumChange.data[i * 3 + c]) / n;
    meanSq += m * m / 3.0;
  }
  const double v = std::max(0.0, m2 - meanSq) * n / (n - 1.0) / n;
  return std::isfinite(v) ? v : 0.0;
}

// 3 x 3 binomial blur of a plane (SVGF's variance prefilter: one pixel's estimate is rough).
Plane blur3(const Plane& p, int w, int h, int threads) {
  Plane out(p.size(), 0.f);
  forRows(h, threads, [&](int r0, int r1) {
    for (int y = r0; y < r1; ++y)
      for (int x = 0; x < w; ++x) {
        float s = 0, ws = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int xx = x + dx, yy = y + dy;
            if (xx < 0 || yy < 0 || xx >= w || yy >= h) continue;
            const float k = (dx ? 1.f : 2.f) * (dy ? 1.f : 2.f);
            s += k * p[size_t(yy) * w + xx];
            ws += k;
          }
        out[size_t(y) * w + x] = s / ws;
      }
  });
  return out;
}

// The planes of X / albedo, its variance, the mask, the raw X and its standard error.
struct Signal {
  Plane y[3], var, mask, x[3], stdX, albedoMean;
  Plane kind;      // mask + 2 x specular fraction: the edge stop between surface kinds
  Plane invSigma;  // 1 / the luminance stop (the object's, the room's or the specular one's)
};

Signal signalOf(const DenoiseInput& in, const DenoiseGuides& g, const DenoiseOptions& o) {
  const int threads = o.threads;
  const int w = in.withObjects->width, h = in.withObjects->height;
  const size_t n = size_t(w) * h;
  Signal s;
  for (int c = 0; c < 3; ++c) s.y[c].resize(n), s.x[c].resize(n);
  s.var.resize(n), s.mask.resize(n), s.albedoMean.resize(n), s.kind.resize(n), s.invSigma.resize(n);
  Plane varX(n);
  forRows(h, threads, [&](int r0, int r1) {
    for (size_t i = size_t(r0) * w; i < size_t(r1) * w; ++i) {
      const float m = std::clamp(finiteOr0(in.mask->data[i]), 0.f, 1.f);
      const float spec = g.specular.size() == n ? g.specular[i] : 0.f;
      s.mask[i] = m;
      s.kind[i] = m + 2.f * spec;
      const float sigma = m * o.sigmaLuminanceObject + (1.f - m) * o.sigmaLuminance;
      s.invSigma[i] = 1.f / (spec * o.sigmaLuminanceSpecular + (1.f - spec) * sigma);
      float am = 0;
      for (int c = 0; c < 3; ++c) {
        const float x = finiteOr0(finiteOr0(in.withObjects->data[i * 3 + c]) -
                                  (1.f - m) * finiteOr0(in.withoutObjects->data[i * 3 + c]));
        const float a = std::max(g.albedo[c][i], kMinAlbedo);
        s.x[c][i] = x;
        s.y[c][i] = x / a;
        am += a / 3.f;
      }
      s.albedoMean[i] = am;
      varX[i] = float(std::min(meanVariance(*in.buffers, i), double(kMaxValue) * kMaxValue));
    }
  });
  varX = blur3(varX, w, h, threads);
  s.stdX.resize(n);
  for (size_t i = 0; i < n; ++i) {
    s.stdX[i] = std::sqrt(varX[i]);
    s.var[i] = varX[i] / (s.albedoMean[i] * s.albedoMean[i]);
  }
  return s;
}

// A run of pixels [begin, end) in a row.
struct Span {
  int begin = 0, end = 0;
};

// One à-trous level with step `step`: y, var -> yOut, varOut on the rows [y0, y1).
struct Level {
  const DenoiseGuides& g;
  const DenoiseOptions& o;
  const Signal& s;
  const std::vector<Span>& rowSpan;  // the active pixels of each row lie in [begin, end)
  int w, h, step;
  const Plane* y;  // [3], this level's input
  const Plane* var;
  Plane* yOut;  // [3]
  Plane* varOut;

  void rows(int y0, int y1) const {
    const size_t width = size_t(w);
    std::vector<float> wsum(width), vsum(width), ysum[3], invLum(width), invPlane(width);
    for (auto& v : ysum) v.resize(width);
    for (int row = y0; row < y1; ++row) {
      const size_t base = size_t(row) * w;
      // Pixels out of the span are untouched and out of reach of any touched pixel: their
      // delta is zero, and so is every neighbour's; they pass through.
      const Span span = rowSpan[size_t(row)];
      for (int c = 0; c < 3; ++c) {
        std::copy_n(&y[c][base], span.begin, &yOut[c][base]);
        std::copy_n(&y[c][base + span.end], w - span.end, &yOut[c][base + span.end]);
      }
      std::copy_n(&(*var)[base], span.begin, &(*varOut)[base]);
      std::copy_n(&(*var)[base + span.end], w - span.end, &(*varOut)[base + span.end]);
      if (span.begin >= span.end) continue;
      for (int x = span.begin; x < span.end; ++x) {
        const size_t i = base + x;
        constexpr float kCentre = 0.25f;  // h(0)^2 of the kernel (1/4, 1/2, 1/4)
        wsum[x] = kCentre;
        for (int c = 0; c < 3; ++c) ysum[c][x] = kCentre * y[c][i];
        vsum[x] = kCentre * kCentre * (*var)[i];
        invLum[x] = s.invSigma[i] / (std::sqrt((*var)[i]) + 1e-20f);
        invPlane[x] = 1.f / (o.sigmaPlane * std::max(g.distance[i], 1e-6f));
      }
      for (int dy = -1; dy <= 1; ++dy) {
        const int rr = row + dy * step;
        if (rr < 0 || rr >= h) continue;
        for (int dx = -1; dx <= 1; ++dx)
          if (dx || dy)
            tap(base, size_t(rr) * w, dx * step, (dx ? 0.5f : 1.f) * (dy ? 0.5f : 1.f) * 0.25f, span,
                wsum.data(), ysum, vsum.data(), invLum.data(), invPlane.data());
      }
      for (int x = span.begin; x < span.end; ++x) {
        const size_t i = base + x;
        const float inv = 1.f / wsum[x];  // >= the centre's weight
        for (int c = 0; c < 3; ++c) yOut[c][i] = ysum[c][x] * inv;
        (*varOut)[i] = vsum[x] * inv * inv;
      }
    }
  }

  // Adds the neighbour at (x + ox, row rr) of every pixel x of the row at `base`. Row pointers
  // (the pixel's `_i`, the neighbour's `_j`) keep every access affine, so the loop vectorises.
  void tap(size_t base, size_t nbase, int ox, float k, Span span, float* wsum, std::vector<float>* ysum,
           float* vsum, const float* invLum, const float* invPlane) const {
    const int x0 = std::max(span.begin, -ox), x1 = std::min(span.end, w - ox);
    const float sn = o.sigmaNormal, invA = 1.f / o.sigmaAlbedo, invM = 1.f / o.sigmaMask;
    const size_t nb = nbase + size_t(ox);  // x + ox >= 0 on [x0, x1)
    const float *y0i = y[0].data() + base, *y1i = y[1].data() + base, *y2i = y[2].data() + base;
    const float *y0j = y[0].data() + nb, *y1j = y[1].data() + nb, *y2j = y[2].data() + nb,
                *vj = var->data() + nb;
    const float *n0i = g.normal[0].data() + base, *n1i = g.normal[1].data() + base,
                *n2i = g.normal[2].data() + base;
    const float *n0j = g.normal[0].data() + nb, *n1j = g.normal[1].data() + nb,
                *n2j = g.normal[2].data() + nb;
    const float *p0i = g.position[0].data() + base, *p1i = g.position[1].data() + base,
                *p2i = g.position[2].data() + base;
    const float *p0j = g.position[0].data() + nb, *p1j = g.position[1].data() + nb,
                *p2j = g.position[2].data() + nb;
    const float *a0i = g.albedo[0].data() + base, *a1i = g.albedo[1].data() + base,
                *a2i = g.albedo[2].data() + base;
    const float *a0j = g.albedo[0].data() + nb, *a1j = g.albedo[1].data() + nb,
                *a2j = g.albedo[2].data() + nb;
    const float *mi = s.kind.data() + base, *mj = s.kind.data() + nb;
    float *ws = wsum, *vs = vsum, *s0 = ysum[0].data(), *s1 = ysum[1].data(), *s2 = ysum[2].data();
    // The sums are the row's own scratch, never one of the planes read: no alias checks needed.
    INLAY_IVDEP
    for (int x = x0; x < x1; ++x) {
      const float lum =
          (std::abs(y0i[x] - y0j[x]) + std::abs(y1i[x] - y1j[x]) + std::abs(y2i[x] - y2j[x])) *
          (1.f / 3.f);
      const float cosN = n0i[x] * n0j[x] + n1i[x] * n1j[x] + n2i[x] * n2j[x];
      const float plane =
          std::abs(n0i[x] * (p0j[x] - p0i[x]) + n1i[x] * (p1j[x] - p1i[x]) + n2i[x] * (p2j[x] - p2i[x]));
      const float alb = std::abs(a0i[x] - a0j[x]) + std::abs(a1i[x] - a1j[x]) +
                        std::abs(a2i[x] - a2j[x]);
      const float e = lum * invLum[x] + sn * (1.f - cosN) + plane * invPlane[x] + alb * invA +
                      std::abs(mi[x] - mj[x]) * invM;
      const float wt = k * expNeg(e);
      ws[x] += wt;
      s0[x] += wt * y0j[x];
      s1[x] += wt * y1j[x];
      s2[x] += wt * y2j[x];
      vs[x] += wt * wt * vj[x];
    }
  }
};

bool sizesMatch(const DenoiseInput& in) {
  if (!in.withObjects || !in.withoutObjects || !in.mask || !in.buffers || !in.guides) return false;
  const int w = in.withObjects->width, h = in.withObjects->height;
  const DifferentialBuffers& b = *in.buffers;
  const DenoiseGuides& g = *in.guides;
  return w > 0 && h > 0 && in.withObjects->channels == 3 && in.withoutObjects->width == w &&
         in.withoutObjects->height == h && in.withoutObjects->channels == 3 && in.mask->width == w &&
         in.mask->height == h && in.mask->channels == 1 && b.width == w && b.height == h &&
         b.samples.size() == size_t(w) * h && g.width == w && g.height == h &&
         g.distance.size() == size_t(w) * h;
}

// The filtered delta back into a with-object image, within the clamp, for the active pixels.
ImageF writeBack(const DenoiseInput& in, const Signal& s, const Plane* yFiltered,
                 const std::vector<uint8_t>& active, float clampSigmas, int threads) {
  ImageF out = *in.withObjects;
  const size_t w = size_t(out.width);
  forRows(out.height, threads, [&](int r0, int r1) {
    for (size_t i = size_t(r0) * w; i < size_t(r1) * w; ++i) {
      if (!active[i]) continue;
      const float lim = clampSigmas * s.stdX[i];
      float x[3];
      bool zero = true;
      for (int c = 0; c < 3; ++c) {
        const float a = std::max(in.guides->albedo[c][i], kMinAlbedo);
        x[c] = std::clamp(yFiltered[c][i] * a, s.x[c][i] - lim, s.x[c][i] + lim);
        if (!std::isfinite(x[c])) x[c] = s.x[c][i];
        zero = zero && x[c] == 0.f;
      }
      const float m = s.mask[i];
      for (int c = 0; c < 3; ++c) {
        const float without = in.withoutObjects->data[i * 3 + c];
        // A zero delta outside the object: exactly the without-object value (the photo, composited).
        const float v = zero && m == 0.f ? without : x[c] + (1.f - m) * finiteOr0(without);
        out.data[i * 3 + c] = std::isfinite(v) ? v : finiteOr0(in.withObjects->data[i * 3 + c]);
      }
    }
  });
  return out;
}

}  // namespace

int denoiseReachPx(const DenoiseOptions& options) {
  return (1 << std::clamp(options.levels, 0, 12)) - 1;
}

DenoiseGuides renderDenoiseGuides(const PathTracer& tracer, int width, int height, int threads) {
  DenoiseGuides g;
  if (width <= 0 || height <= 0) return g;
  g.width = width, g.height = height;
  const size_t n = size_t(width) * height;
  for (int c = 0; c < 3; ++c)
    g.albedo[c].assign(n, 1.f), g.normal[c].assign(n, 0.f), g.position[c].assign(n, 0.f);
  g.distance.assign(n, 1e6f);
  const Camera& cam = tracer.scene().camera;
  const double sx = double(cam.widthPx) / width, sy = double(cam.heightPx) / height;
  forRows(height, threads, [&](int y0, int y1) {
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < width; ++x) {
        const PathTracer::FirstHit hit = tracer.firstHit(Vec2((x + 0.5) * sx, (y + 0.5) * sy));
        if (!hit.hit || !hit.point.allFinite() || !hit.normal.allFinite()) continue;
        const size_t i = size_t(y) * width + x;
        for (int c = 0; c < 3; ++c) {
          g.albedo[c][i] = float(hit.albedo[c]);
          g.normal[c][i] = float(hit.normal[c]);
          g.position[c][i] = float(hit.point[c]);
        }
        g.distance[i] = float(std::max(hit.distance, 1e-6));
      }
  });
  return g;
}

ImageF denoiseWithObjects(const DenoiseInput& in, const DenoiseOptions& options) {
  if (!sizesMatch(in)) return in.withObjects ? *in.withObjects : ImageF();
  const int w = in.withObjects->width, h = in.withObjects->height;
  const std::vector<uint8_t> active = activePixels(in, denoiseReachPx(options));
  std::vector<Span> rowSpan(static_cast<size_t>(h));
  bool any = false;
  for (int y = 0; y < h; ++y) {
    const uint8_t* row = active.data() + size_t(y) * w;
    Span& sp = rowSpan[size_t(y)];
    while (sp.begin < w && !row[sp.begin]) ++sp.begin;
    sp.end = w;
    while (sp.end > sp.begin && !row[sp.end - 1]) --sp.end;
    if (sp.begin >= sp.end) sp = Span{0, 0};
    any = any || sp.begin < sp.end;
  }
  if (!any) return *in.withObjects;
  const Signal s = signalOf(in, *in.guides, options);
  Plane ping[3] = {s.y[0], s.y[1], s.y[2]}, pong[3];
  Plane pingVar = s.var, pongVar(s.var.size());
  for (auto& p : pong) p.resize(s.var.size());
  for (int level = 0; level < std::clamp(options.levels, 0, 12); ++level) {
    const Level step{*in.guides, options, s, rowSpan, w, h, 1 << level, ping, &pingVar, pong, &pongVar};
    forRows(h, options.threads, [&](int y0, int y1) { step.rows(y0, y1); });
    for (int c = 0; c < 3; ++c) std::swap(ping[c], pong[c]);
    std::swap(pingVar, pongVar);
  }
  return writeBack(in, s, ping, active, options.clampSigmas, options.threads);
}

DenoiseGuides denoiseGuidesFromBuffers(const DifferentialBuffers& b, int threads) {
  DenoiseGuides g;
  if (!b.hasGuides()) return g;
  g.width = b.width, g.height = b.height;
  const size_t n = size_t(b.width) * b.height;
  for (int c = 0; c < 3; ++c) g.albedo[c].resize(n), g.normal[c].resize(n), g.position[c].resize(n);
  g.distance.resize(n), g.specular.resize(n);
  forRows(b.height, threads, [&](int y0, int y1) {
    for (size_t i = size_t(y0) * b.width; i < size_t(y1) * b.width; ++i) {
      const float records = b.sumGuideDistance.data[i * 3 + 1];
      const float inv = records > 0 ? 1.f / records : 0.f;
      float nn = 0;
      for (int c = 0; c < 3; ++c)
        nn += b.sumGuideNormal.data[i * 3 + c] * b.sumGuideNormal.data[i * 3 + c];
      const float invN = nn > 1e-12f && std::isfinite(nn) ? 1.f / std::sqrt(nn) : 0.f;
      for (int c = 0; c < 3; ++c) {
        const float a = b.sumGuideAlbedo.data[i * 3 + c] * inv;
        g.albedo[c][i] = records > 0 && std::isfinite(a) ? std::clamp(a, 0.f, 1.f) : 1.f;
        g.normal[c][i] = b.sumGuideNormal.data[i * 3 + c] * invN;
        g.position[c][i] = finiteOr0(b.sumGuidePosition.data[i * 3 + c] * inv);
      }
      const float d = b.sumGuideDistance.data[i * 3] * inv;
      g.distance[i] = records > 0 && std::isfinite(d) ? std::max(d, 1e-6f) : 1e6f;
      g.specular[i] = std::clamp(b.sumGuideDistance.data[i * 3 + 2] * inv, 0.f, 1.f);
    }
  });
  return g;
}

void denoiseFrame(RenderFrame& frame, const DifferentialBuffers& buffers, const PathTracer& tracer,
                  DenoiseGuides* guides, const DenoiseOptions& options) {
  const int w = frame.withObjects.width, h = frame.withObjects.height;
  if (buffers.hasGuides() && buffers.width == w && buffers.height == h)
    *guides = denoiseGuidesFromBuffers(buffers, options.threads);  // they refine with the samples
  else if (guides->width != w || guides->height != h)
    *guides = renderDenoiseGuides(tracer, w, h, options.threads);
  DenoiseInput in;
  in.withObjects = &frame.withObjects;
  in.withoutObjects = &frame.withoutObjects;
  in.mask = &frame.mask;
  in.buffers = &buffers;
  in.guides = guides;
  if (!sizesMatch(in)) return;
  frame.withObjects = denoiseWithObjects(in, options);
  frame.denoised = true;
}

}  // namespace inlay
