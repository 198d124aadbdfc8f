// The response estimate's photo-wide statistics (code_statistics.h) and its noise level
// (noise_level.h) against the plain loops over every pixel they replace: the same values, bit for
// bit, on random codes, on flat and noisy regions with clipped parts, and on the extremes (no
// pixel, one pixel, one colour, every code at 0 or 255).
#include "../modeling/src/camera/code_statistics.h"
#include "../modeling/src/camera/noise_level.h"

#include "inlay/modeling/image.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace inlay::detail {
namespace {

std::vector<unsigned char> randomCodes(size_t pixels, int lo, int hi, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> code(lo, hi);
  std::vector<unsigned char> out(pixels * 3);
  for (unsigned char& c : out) c = (unsigned char)code(rng);
  return out;
}

// The loops photoIsUndetermined and darkFillOf ran before (response.cpp).
LumaSpread plainLumaSpread(const std::vector<unsigned char>& codes) {
  LumaSpread s;
  s.pixels = codes.size() / 3;
  for (size_t i = 0; i < s.pixels; ++i) {
    const unsigned char* c = &codes[i * 3];
    const int l = int(std::lround((c[0] + c[1] + c[2]) / 3.0));
    ++s.histogram[size_t(l)];
    s.sum += uint64_t(l), s.sumOfSquares += uint64_t(l) * uint64_t(l);
    s.clipped += std::max({c[0], c[1], c[2]}) >= 254 || std::min({c[0], c[1], c[2]}) <= 1;
  }
  return s;
}

float plainLuminanceQuantile(const std::vector<unsigned char>& codes, double q) {
  std::array<double, 256> lin{};
  for (int k = 0; k < 256; ++k) lin[size_t(k)] = srgbToLinear(float(k) / 255.f);
  std::vector<float> v(codes.size() / 3);
  for (size_t i = 0; i < v.size(); ++i)
    v[i] = float((lin[codes[i * 3]] + lin[codes[i * 3 + 1]] + lin[codes[i * 3 + 2]]) / 3);
  const auto at = v.begin() + std::ptrdiff_t(q * double(v.size() - 1));
  std::nth_element(v.begin(), at, v.end());
  return *at;
}

TEST(CodeStatistics, TheLumaSpreadIsThePlainLoops) {
  for (const auto& codes :
       {randomCodes(100003, 0, 255, 1), randomCodes(5000, 0, 3, 2), randomCodes(7, 250, 255, 3),
        randomCodes(1, 0, 255, 4), std::vector<unsigned char>{}}) {
    const LumaSpread fast = lumaSpreadOf(codes), plain = plainLumaSpread(codes);
    EXPECT_EQ(fast.pixels, plain.pixels);
    EXPECT_EQ(fast.histogram, plain.histogram);
    EXPECT_EQ(fast.sum, plain.sum);
    EXPECT_EQ(fast.sumOfSquares, plain.sumOfSquares);
    EXPECT_EQ(fast.clipped, plain.clipped);
  }
}

TEST(CodeStatistics, LuminanceQuantilesAreWhatSortingGives) {
  const std::vector<double> qs = {0.0, 0.01, 0.5, 0.99, 1.0};
  std::vector<unsigned char> flat(3000 * 3, 117), black(10 * 3, 0), white(10 * 3, 255);
  for (const auto& codes : {randomCodes(200001, 0, 255, 5), randomCodes(999, 20, 30, 6),
                            randomCodes(1, 0, 255, 7), flat, black, white}) {
    const std::vector<float> fast = luminanceQuantiles(codes, qs);
    ASSERT_EQ(fast.size(), qs.size());
    for (size_t k = 0; k < qs.size(); ++k)
      EXPECT_EQ(fast[k], plainLuminanceQuantile(codes, qs[k])) << "q " << qs[k];
  }
  EXPECT_TRUE(luminanceQuantiles({}, qs).empty());
  // Out-of-range quantiles are clamped, not read past the ends.
  const auto codes = randomCodes(100, 0, 255, 8);
  EXPECT_EQ(luminanceQuantiles(codes, {-1.0, 2.0}),
            (std::vector<float>{plainLuminanceQuantile(codes, 0), plainLuminanceQuantile(codes, 1)}));
}

// measureNoiseLevel's blocks as the per-pixel loop found them before (noise_level.cpp), binned
// the same way.
struct PlainPoint {
  double code, sigma;
};
NoiseLevel plainNoiseLevel(const std::vector<unsigned char>& codes, int W, int H) {
  std::vector<PlainPoint> points;
  auto at = [&](int x, int y, int c) { return double(codes[(size_t(y) * W + x) * 3 + size_t(c)]); };
  for (int c = 0; c < 3; ++c)
    for (int by = 1; by + 8 < H; by += 8)
      for (int bx = 1; bx + 8 < W; bx += 8) {
        double lo = 1e9, hi = -1e9, sum = 0, sum2 = 0;
        for (int y = by; y < by + 8; ++y)
          for (int x = bx; x < bx + 8; ++x) {
            double mean = 0;
            for (int dy = -1; dy <= 1; ++dy)
              for (int dx = -1; dx <= 1; ++dx) mean += at(x + dx, y + dy, c);
            mean /= 9;
            lo = std::min(lo, mean), hi = std::max(hi, mean);
            const double r = at(x, y, c) - 0.25 * (at(x - 1, y, c) + at(x + 1, y, c) + at(x, y - 1, c) +
                                                   at(x, y + 1, c));
            sum += mean, sum2 += r * r;
          }
        const double m = sum / 64;
        if (lo <= 3 || hi >= 250 || hi - lo >= std::max(8.0, 0.1 * m)) continue;
        points.push_back({m, std::sqrt(sum2 / 64 / 1.25)});
      }
  NoiseLevel out;
  out.flatBlocks = int(points.size());
  std::sort(points.begin(), points.end(),
            [](const PlainPoint& a, const PlainPoint& b) { return a.code < b.code; });
  const int bins = std::min(12, int(points.size()) / 20);
  for (int b = 0; b < bins; ++b) {
    const size_t i0 = points.size() * size_t(b) / size_t(bins),
                 i1 = points.size() * size_t(b + 1) / size_t(bins);
    std::vector<double> code, sigma;
    for (size_t i = i0; i < i1; ++i) code.push_back(points[i].code), sigma.push_back(points[i].sigma);
    std::nth_element(code.begin(), code.begin() + std::ptrdiff_t(code.size() / 2), code.end());
    std::nth_element(sigma.begin(), sigma.begin() + std::ptrdiff_t(sigma.size() / 2), sigma.end());
    out.bins.push_back({code[code.size() / 2], sigma[sigma.size() / 2], int(i1 - i0)});
  }
  return out;
}

// Flat patches at many levels (a gentle gradient in some), noise of a few codes, a textured band
// (rejected by spread), a clipped band and a black one, and odd sizes (partial blocks at the edges).
std::vector<unsigned char> patchworkCodes(int W, int H, double noise, uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> N(0, 1);
  std::vector<unsigned char> out(size_t(W) * H * 3);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      for (int c = 0; c < 3; ++c) {
        const int patch = (x / 23) + 7 * (y / 19);
        double v = 8 + (patch * 37 + c * 11) % 240 + (patch % 3 == 0 ? 0.05 * (x % 23) : 0);
        if (y > H / 2 && y < H / 2 + 12) v = (x % 2) ? 40 : 200;  // texture
        if (x > W - 15) v = 255;                                  // clipped
        if (y < 6) v = 0;                                         // black
        out[(size_t(y) * W + x) * 3 + size_t(c)] =
            (unsigned char)std::clamp(std::lround(v + noise * N(rng)), 0L, 255L);
      }
  return out;
}

void expectSameNoiseLevel(const NoiseLevel& fast, const NoiseLevel& plain) {
  EXPECT_EQ(fast.flatBlocks, plain.flatBlocks);
  ASSERT_EQ(fast.bins.size(), plain.bins.size());
  for (size_t b = 0; b < fast.bins.size(); ++b) {
    EXPECT_EQ(fast.bins[b].code, plain.bins[b].code) << "bin " << b;
    EXPECT_EQ(fast.bins[b].sigma, plain.bins[b].sigma) << "bin " << b;
    EXPECT_EQ(fast.bins[b].blocks, plain.bins[b].blocks) << "bin " << b;
  }
}

TEST(CodeStatistics, TheNoiseLevelIsThePerPixelLoops) {
  for (const auto& [W, H, noise] : {std::tuple{403, 301, 1.5}, std::tuple{256, 200, 4.0},
                                    std::tuple{97, 45, 0.0}, std::tuple{11, 11, 2.0}}) {
    const auto codes = patchworkCodes(W, H, noise, uint32_t(W));
    const NoiseLevel fast = measureNoiseLevel(codes, W, H), plain = plainNoiseLevel(codes, W, H);
    SCOPED_TRACE(std::to_string(W) + " x " + std::to_string(H));
    EXPECT_GT(plain.flatBlocks, W > 20 ? 0 : -1);
    expectSameNoiseLevel(fast, plain);
  }
  // Random codes: hardly a flat block; every one the loops keep is kept.
  const auto codes = randomCodes(size_t(200) * 150, 100, 120, 9);
  expectSameNoiseLevel(measureNoiseLevel(codes, 200, 150), plainNoiseLevel(codes, 200, 150));
}

}  // namespace
}  // namespace inlay::detail
