// The denoised preview (render/denoise.h): untouched pixels stay the photo bit for bit, the
// filter lowers the error of a few-sample render, its strength falls to nothing as the render
// converges, and black, saturated, huge, non-finite and single-sample frames come out finite.
#include "inlay/modeling/image_io.h"
#include "inlay/render/composite.h"
#include "inlay/render/denoise.h"
#include "inlay/render/session.h"
#include "render_test_scenes.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>

using namespace inlay;

namespace {

// A sphere on the floor of a box room under one ceiling light, seen from above its shadow.
RenderScene sphereScene(int w, int h, Material::Kind kind = Material::Kind::Diffuse) {
  RenderScene s = test::roomScene(test::testCamera(w, h, 60, 1.3, -25), RoomBox{}, 0.6);
  s.lights.push_back(
      test::rectLight(Vec3(-0.3, 2.59, -2.2), Vec3(0.3, 0, 0), Vec3(0, 0, 0.3), Vec3::Constant(20)));
  InsertedObject o;
  o.meshObject = test::sphereMesh(0.35, 16, 32);
  o.worldFromObject = test::translation(Vec3(0.2, 0.35, -2.4));
  o.material.kind = kind;
  o.material.albedo = kind == Material::Kind::Mirror ? Vec3(0.9, 0.9, 0.9) : Vec3(0.8, 0.5, 0.3);
  s.objects.push_back(o);
  if (kind == Material::Kind::Mirror) {  // something for the mirror to show: a block on the floor
    InsertedObject block;
    block.meshObject = test::sphereMesh(0.25, 12, 24);
    block.worldFromObject = test::translation(Vec3(-0.55, 0.25, -2.1));
    block.material.albedo = Vec3(0.1, 0.7, 0.2);
    s.objects.push_back(block);
  }
  return s;
}

struct Rendered {
  DifferentialBuffers buffers;
  ImageF with, without, mask;
};

// `spp` samples per pixel, with the tracer's own guides (DifferentialBuffers::enableGuides).
Rendered render(const PathTracer& tracer, int w, int h, int spp, uint32_t seed) {
  Rendered r{DifferentialBuffers(w, h), {}, {}, {}};
  r.buffers.enableGuides();
  tracer.render(r.buffers, 0, spp, seed, 2);
  r.with = r.buffers.meanWith(), r.without = r.buffers.meanWithout(), r.mask = r.buffers.meanMask();
  return r;
}

// Denoised with the render's own guides.
ImageF denoised(const Rendered& r, const DenoiseOptions& o = {}) {
  const DenoiseGuides g = denoiseGuidesFromBuffers(r.buffers, 2);
  DenoiseInput in;
  in.withObjects = &r.with, in.withoutObjects = &r.without, in.mask = &r.mask;
  in.buffers = &r.buffers, in.guides = &g;
  return denoiseWithObjects(in, o);
}

// Denoised with given guides.
ImageF denoised(const Rendered& r, const DenoiseGuides& g, const DenoiseOptions& o = {}) {
  DenoiseInput in;
  in.withObjects = &r.with, in.withoutObjects = &r.without, in.mask = &r.mask;
  in.buffers = &r.buffers, in.guides = &g;
  return denoiseWithObjects(in, o);
}

// RMSE of two composites (linear, RGB) over the pixels where `where` is true.
double rmse(const ImageF& a, const ImageF& b, const std::vector<uint8_t>& where) {
  double s = 0;
  size_t n = 0;
  for (size_t i = 0; i < where.size(); ++i)
    if (where[i])
      for (int c = 0; c < 3; ++c) s += std::pow(double(a.data[i * 3 + c]) - b.data[i * 3 + c], 2), ++n;
  return n ? std::sqrt(s / double(n)) : 0.0;
}

ImageF clamped(ImageF im) {
  for (float& v : im.data) v = std::clamp(v, 0.f, 1.f);
  return im;
}

std::vector<uint8_t> objectPixels(const ImageF& mask, float above = 0.5f) {
  std::vector<uint8_t> o(mask.pixelCount());
  for (size_t i = 0; i < o.size(); ++i) o[i] = mask.data[i] > above;
  return o;
}

// Pixels where the composite differs from the photo (the object, its shadow and bounce light).
std::vector<uint8_t> changedPixels(const ImageF& composite, const ImageF& photo) {
  std::vector<uint8_t> o(photo.pixelCount());
  for (size_t i = 0; i < o.size(); ++i)
    for (int c = 0; c < 3; ++c)
      o[i] = o[i] || std::abs(composite.data[i * 3 + c] - photo.data[i * 3 + c]) > 2e-3f;
  return o;
}

class DenoiseScene : public ::testing::Test {
 protected:
  static constexpr int kW = 56, kH = 42;
  void SetUp() override {
    scene = sphereScene(kW, kH);
    tracer = std::make_unique<PathTracer>(scene);
    guides = renderDenoiseGuides(*tracer, kW, kH, 2);
    photo = ImageF(kW, kH, 3);
    for (int y = 0; y < kH; ++y)  // a textured photo: tiles of two greys
      for (int x = 0; x < kW; ++x)
        photo.setRgb(x, y, Vec3::Constant(((x / 4 + y / 4) % 2) ? 0.35 : 0.55));
  }
  RenderScene scene;
  std::unique_ptr<PathTracer> tracer;
  DenoiseGuides guides;
  ImageF photo;
};

}  // namespace

TEST_F(DenoiseScene, GuidesSeeTheObjectAndTheRoom) {
  const PathTracer::FirstHit centre = tracer->firstHit(Vec2(0.5 * kW, 0.5 * kH));
  ASSERT_TRUE(centre.hit);
  int objectPx = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const size_t i = size_t(y) * kW + x;
      const double a = guides.albedo[0][i];
      EXPECT_TRUE(std::abs(a - 0.6) < 1e-6 || std::abs(a - 0.8) < 1e-6 || a == 1.0)
          << a;  // room, sphere, light
      const double n = std::hypot(guides.normal[0][i], guides.normal[1][i], guides.normal[2][i]);
      EXPECT_NEAR(n, 1.0, 1e-4);
      EXPECT_GT(guides.distance[i], 0.5f);
      objectPx += std::abs(a - 0.8) < 1e-6;
    }
  EXPECT_GT(objectPx, 50);  // the sphere covers a patch of the frame
}

// The guides the tracer records as it renders: the render's radiance sums are the same bits as
// without them, and on a diffuse scene they agree with the camera-ray guides (firstHit) wherever
// a pixel lies wholly on one surface.
TEST_F(DenoiseScene, TracerGuidesAreTheFirstHitsAndChangeNoRadiance) {
  const Rendered r = render(*tracer, kW, kH, 4, 7);
  DifferentialBuffers plain(kW, kH);
  tracer->render(plain, 0, 4, 7, 2);
  EXPECT_FALSE(plain.hasGuides());
  ASSERT_TRUE(r.buffers.hasGuides());
  for (auto member : {&DifferentialBuffers::sumWith, &DifferentialBuffers::sumWithout,
                      &DifferentialBuffers::sumMask, &DifferentialBuffers::sumChange,
                      &DifferentialBuffers::sumChangeSq, &DifferentialBuffers::sumDiffSq})
    EXPECT_TRUE(test::sameBits(r.buffers.*member, plain.*member));
  const DenoiseGuides g = denoiseGuidesFromBuffers(r.buffers, 2);
  int inside = 0, agree = 0;
  for (size_t i = 0; i < size_t(kW) * kH; ++i) {
    if (r.mask.data[i] != 0.f && r.mask.data[i] != 1.f) continue;          // an object's edge
    if (std::abs(g.albedo[0][i] - guides.albedo[0][i]) > 1e-5f) continue;  // a light's or wall's edge
    ++inside;
    const float cosN = g.normal[0][i] * guides.normal[0][i] + g.normal[1][i] * guides.normal[1][i] +
                       g.normal[2][i] * guides.normal[2][i];
    agree += cosN > 0.98f && std::abs(g.distance[i] / guides.distance[i] - 1.f) < 0.1f;
  }
  EXPECT_GT(inside, kW * kH * 8 / 10);
  EXPECT_GT(agree, inside * 95 / 100) << agree << " of " << inside;
}

// On a mirror sphere the guides are what the mirror shows (the room, the green ball, the light):
// the mirror's reflectance times theirs, farther than the mirror itself.
TEST(DenoiseMirror, GuidesShowTheReflection) {
  constexpr int w = 56, h = 42;
  const RenderScene scene = sphereScene(w, h, Material::Kind::Mirror);
  TracerOptions box;  // the ball's reflection is a few pixels: the box keeps them apart
  box.pixelFilterWidth = 0;
  const PathTracer tracer(scene, box);
  const DenoiseGuides first = renderDenoiseGuides(tracer, w, h, 2);
  const Rendered r = render(tracer, w, h, 8, 3);
  const DenoiseGuides g = denoiseGuidesFromBuffers(r.buffers, 2);
  int mirror = 0, reflectsRoom = 0, reflectsBall = 0, farther = 0;
  for (size_t i = 0; i < size_t(w) * h; ++i) {
    if (r.mask.data[i] != 1.f || std::abs(first.albedo[1][i] - 0.9f) > 1e-5f) continue;
    ++mirror;  // wholly on the mirror sphere
    reflectsRoom += std::abs(g.albedo[0][i] - 0.9f * 0.6f) < 1e-4f;
    reflectsBall += g.albedo[1][i] > 0.5f && g.albedo[0][i] < 0.2f;
    farther += g.distance[i] > first.distance[i] + 0.05f;
  }
  EXPECT_GT(mirror, 50);
  EXPECT_GT(reflectsRoom, mirror / 3);
  EXPECT_GE(reflectsBall, 2);  // a small patch of the sphere at this size
  EXPECT_GT(farther, mirror * 9 / 10);
}

// Mean |horizontal and vertical difference| of channel-mean values between neighbours both in
// `where`: how much detail an image shows there.
double imageDetail(const ImageF& im, const std::vector<uint8_t>& where) {
  double s = 0;
  int n = 0;
  auto v = [&](int x, int y) { return (im.at(x, y, 0) + im.at(x, y, 1) + im.at(x, y, 2)) / 3.0; };
  for (int y = 0; y + 1 < im.height; ++y)
    for (int x = 0; x + 1 < im.width; ++x) {
      const size_t i = size_t(y) * im.width + x;
      if (!where[i]) continue;
      if (where[i + 1]) s += std::abs(v(x + 1, y) - v(x, y)), ++n;
      if (where[i + im.width]) s += std::abs(v(x, y + 1) - v(x, y)), ++n;
    }
  return n ? s / n : 0.0;
}

// The filter keeps a mirror's reflection (the guides are what it shows): on the mirror sphere the
// denoised composite is no farther from a converged render than the raw one, and keeps the converged
// render's detail (the camera-ray guides, the mirror's own surface, blurred it away). Measured
// away from the light's reflection, a few pixels far above white whose error is their pixel
// coverage (no filter's business), on the composite clamped to [0, 1] as bench_denoise does.
TEST(DenoiseMirror, KeepsTheReflectionSharp) {
  constexpr int w = 56, h = 42;
  const RenderScene scene = sphereScene(w, h, Material::Kind::Mirror);
  // Two bounces: what the mirror shows is lit directly and by one bounce, and no caustic path
  // (light - mirror - floor - mirror) puts fireflies into the reference.
  TracerOptions twoBounces;
  twoBounces.maxDepth = 2;
  const PathTracer tracer(scene, twoBounces);
  ImageF photo(w, h, 3);
  std::fill(photo.data.begin(), photo.data.end(), 0.4f);
  const Rendered ref = render(tracer, w, h, 256, 99);
  const ImageF refC = clamped(differentialComposite(photo, ref.with, ref.without, ref.mask));
  std::vector<uint8_t> mirror = objectPixels(ref.mask, 0.999f);
  const DenoiseGuides first = renderDenoiseGuides(tracer, w, h, 2);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      mirror[i] = mirror[i] && std::abs(first.albedo[1][i] - 0.9f) < 1e-5f;  // not the green ball
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = std::clamp(x + dx, 0, w - 1), yy = std::clamp(y + dy, 0, h - 1);
          if (ref.with.at(xx, yy, 0) > 1.f) mirror[i] = 0;  // the light's reflection
        }
    }
  const double refDetail = imageDetail(refC, mirror);
  for (int spp : {2, 8, 32}) {
    const Rendered r = render(tracer, w, h, spp, 5);
    const ImageF raw = clamped(differentialComposite(photo, r.with, r.without, r.mask));
    const ImageF den = clamped(differentialComposite(photo, denoised(r), r.without, r.mask));
    const ImageF old = clamped(differentialComposite(photo, denoised(r, first), r.without, r.mask));
    std::printf(
        "%d spp: mirror RMSE raw %.4f, denoised %.4f (camera-ray guides %.4f); detail "
        "%.4f, %.4f (%.4f), converged %.4f\n",
        spp, rmse(raw, refC, mirror), rmse(den, refC, mirror), rmse(old, refC, mirror),
        imageDetail(raw, mirror), imageDetail(den, mirror), imageDetail(old, mirror), refDetail);
    if (const char* dump = std::getenv("INLAY_DENOISE_DUMP")) {
      const std::string d = dump + std::string("/mirror") + std::to_string(spp);
      saveImage(d + "_raw.exr", raw);
      saveImage(d + "_den.exr", den);
      saveImage(d + "_old.exr", old);
      saveImage(d + "_ref.exr", refC);
    }
    // No worse than raw (within a tenth: little noise is left here away from the highlight), far
    // better than with the mirror's own guides, and as detailed as the converged render.
    EXPECT_LT(rmse(den, refC, mirror), 1.1 * rmse(raw, refC, mirror)) << spp << " spp";
    EXPECT_LT(rmse(den, refC, mirror), 0.8 * rmse(old, refC, mirror)) << spp << " spp";
    EXPECT_GT(imageDetail(den, mirror), 0.9 * refDetail) << spp << " spp";
    EXPECT_TRUE(test::allFinite(den));
  }
}

// Pixels the filter cannot reach from any changed pixel, and pixels whose filtered delta is
// exactly zero outside the object, composite to the photo bit for bit.
TEST_F(DenoiseScene, UntouchedPixelsStayThePhotoBitForBit) {
  TracerOptions direct;  // direct light only: the object and its shadow change the frame, little else
  direct.maxDepth = 1;
  const PathTracer directTracer(scene, direct);
  const Rendered r = render(directTracer, kW, kH, 2, 11);
  DenoiseOptions o;
  o.levels = 3;  // a reach of 7 px leaves part of this small frame out of reach
  const ImageF out = denoised(r, o);
  const ImageF raw = differentialComposite(photo, r.with, r.without, r.mask);
  const ImageF den = differentialComposite(photo, out, r.without, r.mask);
  const int reach = denoiseReachPx(o);
  int farPx = 0, changedPx = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      bool near = false;
      for (int yy = std::max(0, y - reach); yy <= std::min(kH - 1, y + reach); ++yy)
        for (int xx = std::max(0, x - reach); xx <= std::min(kW - 1, x + reach); ++xx) {
          const size_t j = size_t(yy) * kW + xx;
          near = near || r.buffers.sumChangeSq.data[j] != 0 || r.mask.data[j] != 0 ||
                 r.with.rgb(xx, yy) != r.without.rgb(xx, yy);
        }
      const size_t i = size_t(y) * kW + x;
      const bool same = test::sameBits(&den.data[i * 3], &photo.data[i * 3], 3);
      const bool zeroDelta = r.mask.data[i] == 0 && out.rgb(x, y) == r.without.rgb(x, y);
      if (!near) {
        EXPECT_TRUE(same) << x << "," << y;
      }
      if (zeroDelta) {
        EXPECT_TRUE(same) << x << "," << y;
      }
      farPx += !near;
      changedPx += !test::sameBits(&den.data[i * 3], &raw.data[i * 3], 3);
    }
  EXPECT_GT(farPx, 20);       // the test covers some pixels out of reach
  EXPECT_GT(changedPx, 100);  // and the filter did change the object and its shadow
}

TEST_F(DenoiseScene, LowersTheErrorOfAFewSampleRender) {
  const Rendered ref = render(*tracer, kW, kH, 256, 99);
  const ImageF refC = differentialComposite(photo, ref.with, ref.without, ref.mask);
  const std::vector<uint8_t> obj = objectPixels(ref.mask, 0.999f);
  std::vector<uint8_t> around = changedPixels(refC, photo);  // the surroundings: shadow, bounce light
  for (size_t i = 0; i < around.size(); ++i) around[i] = around[i] && ref.mask.data[i] == 0;
  for (int spp : {1, 4}) {
    const Rendered r = render(*tracer, kW, kH, spp, 5);
    const ImageF raw = differentialComposite(photo, r.with, r.without, r.mask);
    const ImageF den = differentialComposite(photo, denoised(r), r.without, r.mask);
    if (const char* dump = std::getenv("INLAY_DENOISE_DUMP")) {
      const std::string d = dump + std::string("/") + std::to_string(spp);
      saveImage(d + "_raw.png", raw);
      saveImage(d + "_den.png", den);
      saveImage(d + "_ref.png", refC);
    }
    // The object's inside (its edge pixels' error is the mask's, which the filter leaves alone).
    EXPECT_LT(rmse(den, refC, obj), (spp == 1 ? 0.5 : 0.6) * rmse(raw, refC, obj))
        << spp << " spp, object";
    std::printf("%d spp: object %.4f -> %.4f, surroundings %.4f -> %.4f\n", spp, rmse(raw, refC, obj),
                rmse(den, refC, obj), rmse(raw, refC, around), rmse(den, refC, around));
    EXPECT_LT(rmse(den, refC, around), (spp == 1 ? 0.75 : 0.6) * rmse(raw, refC, around))
        << spp << " spp, surroundings";
    EXPECT_TRUE(test::allFinite(den));
  }
}

// The strength falls with the samples: the denoised composite's distance to the raw one shrinks,
// and at convergence it is below 0.002 on the object.
TEST_F(DenoiseScene, AgreesWithTheRawRenderAtConvergence) {
  double previous = 1e9;
  for (int spp : {4, 32, 512}) {
    const Rendered r = render(*tracer, kW, kH, spp, 21);
    const ImageF raw = differentialComposite(photo, r.with, r.without, r.mask);
    const ImageF den = differentialComposite(photo, denoised(r), r.without, r.mask);
    const double d = rmse(den, raw, objectPixels(r.mask));
    std::printf("%d spp: denoised - raw on the object %.5f\n", spp, d);
    EXPECT_LT(d, previous) << spp;
    previous = d;
    if (spp == 512) {
      EXPECT_LT(d, 0.002);
    }
  }
}

namespace {

// A synthetic W x H frame on a flat floor: guides, sums of `spp` samples per pixel from `value`.
struct Synthetic {
  int w = 40, h = 30;
  DifferentialBuffers b{40, 30};
  DenoiseGuides g;
  ImageF with, without, mask;
  Synthetic() {
    g.width = w, g.height = h;
    const size_t n = size_t(w) * h;
    for (int c = 0; c < 3; ++c) g.albedo[c].assign(n, 0.5f), g.normal[c].assign(n, c == 1 ? 1.f : 0.f);
    for (int c = 0; c < 3; ++c) g.position[c].resize(n);
    g.distance.assign(n, 3.f);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const size_t i = size_t(y) * w + x;
        g.position[0][i] = 0.01f * x, g.position[1][i] = 0, g.position[2][i] = -3.f - 0.01f * y;
      }
  }
  // Every pixel gets `spp` samples of with = without + delta(x, y, k), without = base.
  template <class Delta>
  void fill(int spp, float base, const Delta& delta) {
    b.clear();
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        for (int k = 0; k < spp; ++k) {
          const float d = delta(x, y, k);
          for (int c = 0; c < 3; ++c) {
            b.sumWith.at(x, y, c) += base + d;
            b.sumWithout.at(x, y, c) += base;
            b.sumChange.at(x, y, c) += d;
          }
          b.sumChangeSq.at(x, y) += d * d;
          b.samples[size_t(y) * w + x] += 1;
        }
    with = b.meanWith(), without = b.meanWithout(), mask = b.meanMask();
  }
  ImageF run() const {
    DenoiseInput in;
    in.withObjects = &with, in.withoutObjects = &without, in.mask = &mask, in.buffers = &b,
    in.guides = &g;
    return denoiseWithObjects(in);
  }
};

}  // namespace

TEST(DenoiseStability, BlackFrameStaysBlackBitForBit) {
  Synthetic s;
  s.fill(1, 0.f, [](int, int, int) { return 0.f; });
  EXPECT_TRUE(test::sameBits(s.run(), s.with));
}

TEST(DenoiseStability, SaturatedFrameStaysFiniteAndInRange) {
  Synthetic s;
  s.fill(2, 1.f, [](int x, int, int k) { return (x + k) % 3 == 0 ? 0.f : 4.f; });  // far above white
  const ImageF out = s.run();
  ASSERT_TRUE(test::allFinite(out));
  for (float v : out.data) EXPECT_TRUE(v >= 1.f && v <= 5.f) << v;
}

TEST(DenoiseStability, HugeValuesGiveNoNanOrInf) {
  for (float huge : {1e20f, 1e30f, FLT_MAX / 4}) {
    Synthetic s;
    s.fill(2, 0.5f, [&](int x, int y, int k) { return (x * 7 + y * 3 + k) % 11 == 0 ? huge : 0.f; });
    const ImageF out = s.run();
    EXPECT_TRUE(test::allFinite(out)) << huge;
  }
}

TEST(DenoiseStability, NonFiniteInputsDoNotSpread) {
  Synthetic s;
  s.fill(2, 0.5f, [](int x, int y, int) { return (x + y) % 2 ? 0.1f : 0.f; });
  s.with.at(10, 10, 0) = std::numeric_limits<float>::quiet_NaN();
  s.with.at(20, 15, 1) = std::numeric_limits<float>::infinity();
  s.b.sumChangeSq.at(5, 5) = std::numeric_limits<float>::infinity();
  const ImageF out = s.run();
  EXPECT_TRUE(test::allFinite(out));
}

// One sample per pixel of a smooth shadow (true delta -0.2 inside a disc), each sample either
// fully blocked or not: the denoised frame is much closer to the truth than the raw one.
TEST(DenoiseStability, SingleSampleFrameIsCleaned) {
  Synthetic s;
  auto truth = [](int x, int y) {
    const double r = std::hypot(x - 20.0, y - 15.0);
    return r < 10 ? -0.2 : 0.0;
  };
  std::mt19937 rng(3);
  s.fill(1, 0.5f, [&](int x, int y, int) {
    // A blocked sample removes 0.4 with probability 1/2: mean -0.2 inside the disc.
    return truth(x, y) != 0 && std::uniform_real_distribution<float>(0, 1)(rng) < 0.5f ? -0.4f : 0.f;
  });
  const ImageF out = s.run();
  ASSERT_TRUE(test::allFinite(out));
  double rawErr = 0, denErr = 0;
  for (int y = 0; y < s.h; ++y)
    for (int x = 0; x < s.w; ++x) {
      const double t = 0.5 + truth(x, y);
      rawErr += std::pow(s.with.at(x, y, 0) - t, 2);
      denErr += std::pow(out.at(x, y, 0) - t, 2);
    }
  EXPECT_LT(denErr, 0.5 * rawErr);
}

TEST(DenoiseStability, MismatchedSizesReturnTheInput) {
  Synthetic s;
  s.fill(1, 0.5f, [](int x, int, int) { return x % 2 ? 0.1f : 0.f; });
  s.g.width = 10;
  EXPECT_TRUE(test::sameBits(s.run(), s.with));
}

// The session's hook: denoised full-resolution frames (all of them, or the final one), marked
// so, and pixels no sample changed composite to the photo as the raw session's do.
TEST(DenoiseSession, FramesAreDenoisedAndKeepUntouchedPixels) {
  const int w = 48, h = 36;
  const RenderScene scene = sphereScene(w, h);
  struct Last : FrameSink {
    std::mutex m;
    std::shared_ptr<const RenderFrame> frame;
    void onFrame(std::shared_ptr<const RenderFrame> f) override {
      std::lock_guard<std::mutex> lock(m);
      frame = std::move(f);
    }
  };
  using Mode = SessionOptions::Denoise;
  const Mode modes[3] = {Mode::Off, Mode::All, Mode::Final};
  std::shared_ptr<const RenderFrame> frames[3];
  for (int k = 0; k < 3; ++k) {
    Last sink;
    SessionOptions opt;
    opt.targetSpp = 4;
    opt.startDivider = 1;
    opt.threads = 2;
    opt.denoise = modes[k];
    RenderSession session(&sink, opt);
    session.setScene(scene);
    ASSERT_TRUE(session.waitUntilDone(60));
    frames[k] = sink.frame;
  }
  ASSERT_TRUE(frames[0] && frames[1] && frames[2]);
  EXPECT_FALSE(frames[0]->denoised);
  EXPECT_TRUE(frames[1]->denoised);
  EXPECT_TRUE(frames[2]->denoised);  // Final: the last frame only, the same as All's last
  EXPECT_TRUE(test::sameBits(frames[1]->withObjects, frames[2]->withObjects));
  EXPECT_TRUE(test::sameBits(frames[0]->withoutObjects, frames[1]->withoutObjects));
  int changed = 0;
  for (size_t i = 0; i < frames[0]->mask.pixelCount(); ++i) {
    const bool untouched = frames[0]->withObjects.rgb(int(i % w), int(i / w)) ==
                               frames[0]->withoutObjects.rgb(int(i % w), int(i / w)) &&
                           frames[0]->mask.data[i] == 0;
    const bool same =
        test::sameBits(&frames[0]->withObjects.data[i * 3], &frames[1]->withObjects.data[i * 3], 3);
    changed += !same;
    if (untouched && frames[1]->withObjects.rgb(int(i % w), int(i / w)) ==
                         frames[1]->withoutObjects.rgb(int(i % w), int(i / w))) {
      EXPECT_TRUE(same);
    }
  }
  EXPECT_GT(changed, 50);
}
