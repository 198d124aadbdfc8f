// The photo's noise level function and the grain (render/grain.h): recovery of known noise
// (affine in intensity, pure shot noise, coarse and channel-correlated grain), no grain without
// noise, determinism, untouched pixels bit for bit, the shadow rule, and stiff inputs.
#include "test_support.h"

#include "inlay/render/composite.h"
#include "inlay/render/grain.h"

#include <cmath>
#include <functional>
#include <random>

namespace inlay {
namespace {

constexpr int kW = 480, kH = 360;

// A room-like clean image: a ramp in x from 0.04 to 0.9 (each channel a little apart), with
// steps every 48 px and a few dark bars (edges the measurement must not take for noise).
ImageF cleanScene() {
  ImageF im(kW, kH, 3);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      for (int c = 0; c < 3; ++c) {
        double v = 0.04 + 0.86 * x / double(kW - 1) * (1 - 0.08 * c);
        if ((x / 48) % 2 == 1) v *= 0.9;
        if (y % 60 < 3) v *= 0.3;
        im.at(x, y, c) = float(v);
      }
  return im;
}

// Gaussian white noise fields (one per channel), optionally blurred by a Gaussian of `widthPx`
// (renormalised to unit variance) and sharing `shared` of the variance between channels.
std::vector<ImageF> unitNoise(double widthPx, double shared, uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n01;
  std::vector<ImageF> white(4, ImageF(kW, kH, 1));
  for (auto& f : white)
    for (float& v : f.data) v = float(n01(rng));
  if (widthPx > 0) {
    const int r = int(std::ceil(3 * widthPx));
    std::vector<double> k;
    double ss = 0;
    for (int i = -r; i <= r; ++i)
      k.push_back(std::exp(-0.5 * i * i / (widthPx * widthPx))), ss += k.back() * k.back();
    for (double& v : k) v /= std::sqrt(ss);
    for (auto& f : white) {
      ImageF h(kW, kH, 1), o(kW, kH, 1);
      for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
          double s = 0;
          for (int i = -r; i <= r; ++i) s += k[size_t(i + r)] * f.at((x + i + kW) % kW, y);
          h.at(x, y) = float(s);
        }
      for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
          double s = 0;
          for (int i = -r; i <= r; ++i) s += k[size_t(i + r)] * h.at(x, (y + i + kH) % kH);
          o.at(x, y) = float(s);
        }
      f = o;
    }
  }
  std::vector<ImageF> out(3, ImageF(kW, kH, 1));
  for (int c = 0; c < 3; ++c)
    for (size_t i = 0; i < out[size_t(c)].data.size(); ++i)
      out[size_t(c)].data[i] = float(std::sqrt(shared) * white[0].data[i] +
                                     std::sqrt(1 - shared) * white[size_t(c + 1)].data[i]);
  return out;
}

ImageF noisy(const ImageF& clean, const std::function<double(double)>& sigma, double widthPx = 0,
             double shared = 0, uint32_t seed = 7) {
  const auto n = unitNoise(widthPx, shared, seed);
  ImageF im = clean;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      for (int c = 0; c < 3; ++c) {
        const double v = clean.at(x, y, c);
        im.at(x, y, c) = float(std::clamp(v + sigma(v) * n[size_t(c)].at(x, y), 0.0, 1.0));
      }
  return im;
}

// addGrain on a frame of these layers (no render noise unless given: sRGB standard error).
void addGrainTo(ImageF& composite, const ImageF& photo, const ImageF& with, const ImageF& without,
                const ImageF& mask, const PhotoNoise& noise, uint32_t seed,
                const ImageF& renderNoise = {}) {
  RenderFrame f;
  f.width = with.width, f.height = with.height;
  f.withObjects = with, f.withoutObjects = without, f.mask = mask, f.noise = renderNoise;
  addGrain(composite, photo, f, noise, seed);
}

// The measured sigma against the true one at intensities across the data, within `tol`.
void expectRecovers(const PhotoNoise& m, const std::function<double(double)>& sigma, double tol) {
  ASSERT_FALSE(m.empty());
  for (int c = 0; c < 3; ++c)
    for (double I : {0.1, 0.2, 0.35, 0.5, 0.65, 0.75}) {
      const double got = m.sigma(c, I), want = sigma(I);
      EXPECT_NEAR(got / want, 1.0, tol)
          << "channel " << c << " at I = " << I << ": " << got << " vs " << want;
    }
}

// Measured noise level function recovers sigma(I) = a + b I within 10 % (white, independent).
TEST(Grain, RecoversAffineNoiseLevelFunction) {
  const auto sigma = [](double I) { return 0.004 + 0.02 * I; };
  const PhotoNoise m = measurePhotoNoise(noisy(cleanScene(), sigma));
  expectRecovers(m, sigma, 0.10);
  EXPECT_LT(m.grainWidthPx, 0.37);  // neighbours' correlation below 0.05: white
  EXPECT_LT(m.channelCorrelation, 0.1);
}

// Pure shot noise, sigma = k sqrt(I), within 10 %.
TEST(Grain, RecoversShotNoise) {
  const auto sigma = [](double I) { return 0.025 * std::sqrt(I); };
  expectRecovers(measurePhotoNoise(noisy(cleanScene(), sigma)), sigma, 0.10);
}

// Coarse grain shared between channels (what JPEG and demosaicing leave): the total sigma within
// 12 %, the width within 0.25 px, the channel correlation within 0.1.
TEST(Grain, RecoversCoarseCorrelatedGrain) {
  const auto sigma = [](double I) { return 0.003 + 0.015 * I; };
  const PhotoNoise m = measurePhotoNoise(noisy(cleanScene(), sigma, 1.0, 0.6));
  expectRecovers(m, sigma, 0.12);
  EXPECT_NEAR(m.grainWidthPx, 1.0, 0.25);
  EXPECT_NEAR(m.channelCorrelation, 0.6, 0.1);
}

TEST(Grain, NoNoiseNoGrain) {
  const ImageF clean = cleanScene();
  const PhotoNoise m = measurePhotoNoise(clean);
  EXPECT_TRUE(m.empty());
  EXPECT_FALSE(m.notes.empty());
  ImageF with(kW, kH, 3, 0.3f), without(kW, kH, 3, 0.2f), mask(kW, kH, 1, 0.5f);
  const ImageF composite = differentialComposite(clean, with, without, mask);
  ImageF grained = composite;
  addGrainTo(grained, clean, with, without, mask, m, 1);
  EXPECT_TRUE(test::sameBits(grained.data.data(), composite.data.data(), composite.data.size()));
}

PhotoNoise constantNoise(double sigma, double widthPx = 0, double rho = 0) {
  PhotoNoise n;
  for (auto& l : n.levels) l = {{0.0, sigma}, {1.0, sigma}};
  n.grainWidthPx = widthPx;
  n.channelCorrelation = rho;
  return n;
}

TEST(Grain, FieldIsDeterministicUnitVarianceAndIndependent) {
  for (double width : {0.0, 1.5}) {
    const PhotoNoise n = constantNoise(0.01, width);
    double s = 0, ss = 0, cross = 0, chan = 0;
    const int N = 20000;
    for (int i = 0; i < N; ++i) {
      const int x = (i * 37) % 1000 * 7, y = i / 3;  // pixels far apart
      const float g = grainAt(n, x, y, 0, 5);
      EXPECT_EQ(g, grainAt(n, x, y, 0, 5));
      s += g, ss += g * g;
      cross += g * grainAt(n, x, y, 0, 6);  // another seed
      chan += g * grainAt(n, x, y, 1, 5);   // another channel
    }
    EXPECT_NEAR(s / N, 0.0, 0.03) << width;
    EXPECT_NEAR(ss / N, 1.0, 0.05) << width;
    EXPECT_NEAR(cross / N, 0.0, 0.03) << width;
    EXPECT_NEAR(chan / N, 0.0, 0.03) << width;
  }
  // White grain: neighbours independent; coarse grain: neighbours correlated.
  double white = 0, coarse = 0;
  for (int i = 0; i < 20000; ++i) {
    white += grainAt(constantNoise(1), i, 3 * i, 2, 9) * grainAt(constantNoise(1), i + 1, 3 * i, 2, 9);
    coarse += grainAt(constantNoise(1, 1.5), i, 3 * i, 2, 9) *
              grainAt(constantNoise(1, 1.5), i + 1, 3 * i, 2, 9);
  }
  EXPECT_NEAR(white / 20000, 0.0, 0.03);
  EXPECT_NEAR(coarse / 20000, std::exp(-1.0 / (4 * 1.5 * 1.5)), 0.05);
}

// An object (mask 1) of constant render value over a noisy photo; a shadow (mask 0, with <
// without) and a bounce-lit patch (with > without) beside it; the rest untouched.
struct Frame {
  ImageF photo, with, without, mask;
};
Frame objectShadowBounce(const ImageF& photo) {
  Frame f{photo, ImageF(kW, kH, 3, 0.f), ImageF(kW, kH, 3, 0.f), ImageF(kW, kH, 1, 0.f)};
  for (int y = 100; y < 300; ++y)
    for (int x = 100; x < 400; ++x)
      for (int c = 0; c < 3; ++c) {
        if (x < 200) {  // object
          f.mask.at(x, y) = 1;
          f.with.at(x, y, c) = 0.5f;
        } else if (x < 300) {  // shadow: half the light
          f.with.at(x, y, c) = 0.1f, f.without.at(x, y, c) = 0.2f;
        } else {  // bounce: more light
          f.with.at(x, y, c) = 0.3f, f.without.at(x, y, c) = 0.2f;
        }
      }
  return f;
}

TEST(Grain, ObjectGetsFullSigmaShadowKeepsPhotoNoiseUntouchedStaysBitForBit) {
  const auto sigma = [](double I) { return 0.002 + 0.03 * I; };
  const ImageF photo = noisy(cleanScene(), sigma);
  PhotoNoise n;
  for (auto& l : n.levels)
    for (int i = 0; i <= 10; ++i) l.push_back({i / 10.0, sigma(i / 10.0)});
  const Frame f = objectShadowBounce(photo);
  const ImageF composite = differentialComposite(f.photo, f.with, f.without, f.mask);
  ImageF out = composite;
  addGrainTo(out, f.photo, f.with, f.without, f.mask, n, 3);
  ImageF again = composite;
  addGrainTo(again, f.photo, f.with, f.without, f.mask, n, 3);
  EXPECT_TRUE(test::sameBits(out.data.data(), again.data.data(), out.data.size()));

  double s = 0, ss = 0, cnt = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      for (int c = 0; c < 3; ++c) {
        const bool object = f.mask.at(x, y) > 0,
                   changed = object || f.with.at(x, y, c) != f.without.at(x, y, c);
        if (!changed) {
          ASSERT_TRUE(test::sameBits(out.pixel(x, y) + c, photo.pixel(x, y) + c, 1)) << x << "," << y;
        } else if (object) {
          const double d = out.at(x, y, c) - 0.5;
          s += d, ss += d * d, cnt += 1;
        } else if (f.with.at(x, y, c) < f.without.at(x, y, c)) {
          // A shadow darkens: sigma falls, the photo's own noise is already more than enough.
          ASSERT_EQ(out.at(x, y, c), composite.at(x, y, c));
        }
      }
  const double sd = std::sqrt(ss / cnt - (s / cnt) * (s / cnt));
  EXPECT_NEAR(sd / sigma(0.5), 1.0, 0.05);
  // Bounce-lit pixels keep the photo's noise and get the missing part: sigma^2(out) -
  // sigma^2(photo) on average.
  double added = 0, expected = 0;
  for (int y = 100; y < 300; ++y)
    for (int x = 300; x < 400; ++x) {
      const double d = out.at(x, y, 1) - composite.at(x, y, 1);
      const double so = n.sigma(1, composite.at(x, y, 1)), sp = n.sigma(1, photo.at(x, y, 1));
      added += d * d, expected += so * so - sp * sp;
    }
  EXPECT_GT(expected, 0.0);
  EXPECT_NEAR(added / expected, 1.0, 0.1);
}

// A render not yet converged carries noise of its own: the grain makes up only the rest.
TEST(Grain, RenderNoiseCountsTowardTheGrain) {
  const Frame f = objectShadowBounce(cleanScene());
  const PhotoNoise n = constantNoise(0.02);
  const ImageF clean = differentialComposite(f.photo, f.with, f.without, f.mask);
  // The session's sRGB standard error for a linear one of 0.012 at the object's value 0.5.
  const double slope = 1.055 / 2.4 * std::pow(0.5, 1.0 / 2.4 - 1.0);
  ImageF renderNoise(kW, kH, 1, float(0.012 * slope)), tooNoisy(kW, kH, 1, float(0.05 * slope));
  ImageF partial = clean, none = clean;
  addGrainTo(partial, f.photo, f.with, f.without, f.mask, n, 4, renderNoise);
  addGrainTo(none, f.photo, f.with, f.without, f.mask, n, 4, tooNoisy);
  double ss = 0, cnt = 0;
  for (int y = 100; y < 300; ++y)
    for (int x = 100; x < 200; ++x) {
      const double d = partial.at(x, y, 0) - 0.5;
      ss += d * d, cnt += 1;
      ASSERT_EQ(none.at(x, y, 0), clean.at(x, y, 0));
    }
  EXPECT_NEAR(std::sqrt(ss / cnt) / std::sqrt(0.02 * 0.02 - 0.012 * 0.012), 1.0, 0.05);
}

TEST(Grain, DifferentSeedsDifferentGrain) {
  const Frame f = objectShadowBounce(cleanScene());
  const PhotoNoise n = constantNoise(0.02, 0.8, 0.5);
  ImageF a = differentialComposite(f.photo, f.with, f.without, f.mask), b = a;
  addGrainTo(a, f.photo, f.with, f.without, f.mask, n, 1);
  addGrainTo(b, f.photo, f.with, f.without, f.mask, n, 2);
  double diff = 0;
  for (int y = 100; y < 300; ++y) diff += std::abs(a.at(150, y, 0) - b.at(150, y, 0));
  EXPECT_GT(diff / 200, 0.01);
  // addGrain's field is grainAt's.
  const ImageF clean = differentialComposite(f.photo, f.with, f.without, f.mask);
  for (int y = 100; y < 300; y += 7)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR((a.at(150, y, c) - clean.at(150, y, c)) / 0.02, grainAt(n, 150, y, c, 1), 1e-3);
}

// The whole frame's field drawn once (the studio's preview) gives every frame the same bits as
// drawing the grain per frame over its changed box; a field of another size is not used.
TEST(Grain, WholeFrameFieldGivesTheSameBits) {
  const Frame f = objectShadowBounce(cleanScene());
  for (const PhotoNoise& n : {constantNoise(0.02, 0.8, 0.5), constantNoise(0.01, 0.0, 0.0)}) {
    RenderFrame frame;
    frame.width = kW, frame.height = kH;
    frame.withObjects = f.with, frame.withoutObjects = f.without, frame.mask = f.mask;
    const ImageF clean = differentialComposite(f.photo, f.with, f.without, f.mask);
    ImageF drawn = clean, cached = clean, wrongSize = clean;
    addGrain(drawn, f.photo, frame, n, 5);
    const ImageF field = grainField(n, kW, kH, 5);
    ASSERT_EQ(field.width, kW);
    addGrain(cached, f.photo, frame, n, 5, &field);
    EXPECT_EQ(0, std::memcmp(drawn.data.data(), cached.data.data(), drawn.data.size() * sizeof(float)));
    EXPECT_NE(0, std::memcmp(drawn.data.data(), clean.data.data(), drawn.data.size() * sizeof(float)));
    const ImageF small = grainField(n, kW / 2, kH, 5);
    addGrain(wrongSize, f.photo, frame, n, 5, &small);
    EXPECT_EQ(0,
              std::memcmp(drawn.data.data(), wrongSize.data.data(), drawn.data.size() * sizeof(float)));
  }
  EXPECT_TRUE(grainField(PhotoNoise{}, kW, kH, 5).empty());
}

void expectFinite(const ImageF& im) {
  for (float v : im.data) ASSERT_TRUE(std::isfinite(v));
}

void expectFiniteModel(const PhotoNoise& m) {
  EXPECT_TRUE(std::isfinite(m.grainWidthPx));
  EXPECT_TRUE(std::isfinite(m.channelCorrelation));
  for (int c = 0; c < 3; ++c)
    for (double I : {-1.0, 0.0, 0.5, 1e30, double(NAN), double(INFINITY)})
      EXPECT_TRUE(std::isfinite(m.sigma(c, I))) << I;
}

TEST(Grain, StiffInputsGiveFiniteResults) {
  const ImageF black(kW, kH, 3, 0.f), white(kW, kH, 3, 1.f), flat(kW, kH, 3, 0.37f);
  for (const ImageF* im : {&black, &white, &flat}) {
    const PhotoNoise m = measurePhotoNoise(*im);
    EXPECT_TRUE(m.empty());
    expectFiniteModel(m);
  }
  // Saturated: most of a noisy photo clipped at 1.
  ImageF clipped = noisy(cleanScene(), [](double) { return 0.02; });
  for (float& v : clipped.data) v = std::min(1.f, v * 4.f);
  expectFiniteModel(measurePhotoNoise(clipped));
  // Huge values, and non-finite pixels among them.
  ImageF huge = noisy(cleanScene(), [](double I) { return 0.01 + 0.01 * I; });
  for (float& v : huge.data) v *= 1e30f;
  huge.at(5, 5, 1) = NAN, huge.at(50, 7, 0) = INFINITY;
  const PhotoNoise hm = measurePhotoNoise(huge);
  expectFiniteModel(hm);
  EXPECT_FALSE(hm.empty());
  EXPECT_NEAR(hm.sigma(1, 0.5e30) / (0.015e30), 1.0, 0.15);
  Frame f = objectShadowBounce(huge);
  for (float& v : f.with.data) v *= 1e30f;
  for (float& v : f.without.data) v *= 1e30f;
  f.with.at(150, 150, 0) = NAN;
  ImageF out = differentialComposite(f.photo, f.with, f.without, f.mask);
  addGrainTo(out, f.photo, f.with, f.without, f.mask, hm, 1);
  expectFinite(out);
  // Tiny images: no model, no crash.
  for (int s : {1, 3, 7, 8, 9}) {
    const ImageF tiny(s, s, 3, 0.5f);
    const PhotoNoise m = measurePhotoNoise(tiny);
    EXPECT_TRUE(m.empty());
    ImageF with(s, s, 3, 0.6f), without(s, s, 3, 0.5f), mask(s, s, 1, 1.f);
    ImageF c = differentialComposite(tiny, with, without, mask);
    addGrainTo(c, tiny, with, without, mask, constantNoise(0.1, 2.0, 0.5), 1);
    expectFinite(c);
  }
}

}  // namespace
}  // namespace inlay
