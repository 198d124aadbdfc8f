// Photo-wide statistics of 8-bit codes (see code_statistics.h).
#include "code_statistics.h"

#include "inlay/modeling/image.h"
#include "inlay/modeling/parallel.h"

#include <algorithm>
#include <cstring>

namespace inlay::detail {

namespace {

constexpr size_t kChunks = 16;  // pixel ranges summed on their own, then added in order

// Pixel range k of kChunks over n pixels.
std::pair<size_t, size_t> chunkOf(size_t k, size_t n) {
  return {n * k / kChunks, n * (k + 1) / kChunks};
}

// The luminance darkFill reads: the mean of the three codes' sRGB-decoded values, as a float.
class Luminance {
 public:
  Luminance() {
    for (int k = 0; k < 256; ++k) lin_[size_t(k)] = srgbToLinear(float(k) / 255.f);
  }
  float operator()(const unsigned char* c) const {
    return float((lin_[c[0]] + lin_[c[1]] + lin_[c[2]]) / 3);
  }

 private:
  std::array<double, 256> lin_{};
};

uint32_t upperBits(float v) {
  uint32_t u;
  std::memcpy(&u, &v, sizeof u);
  return u >> 16;
}

}  // namespace

LumaSpread lumaSpreadOf(const std::vector<unsigned char>& codes) {
  const size_t n = codes.size() / 3;
  std::vector<LumaSpread> parts(kChunks);
  parallelFor(tbb::blocked_range<size_t>(0, kChunks), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t k = r.begin(); k < r.end(); ++k) {
      LumaSpread& s = parts[k];
      const auto [i0, i1] = chunkOf(k, n);
      for (size_t i = i0; i < i1; ++i) {
        const unsigned char* c = &codes[i * 3];
        const int sum = c[0] + c[1] + c[2];
        const uint64_t l = uint64_t(sum + 1) / 3;  // lround(sum / 3.0): never a half
        ++s.histogram[l];
        s.sum += l, s.sumOfSquares += l * l;
        s.clipped += std::max({c[0], c[1], c[2]}) >= 254 || std::min({c[0], c[1], c[2]}) <= 1;
      }
    }
  });
  LumaSpread out;
  out.pixels = n;
  for (const LumaSpread& s : parts) {
    for (size_t b = 0; b < 256; ++b) out.histogram[b] += s.histogram[b];
    out.sum += s.sum, out.sumOfSquares += s.sumOfSquares, out.clipped += s.clipped;
  }
  return out;
}

std::vector<float> luminanceQuantiles(const std::vector<unsigned char>& codes,
                                      const std::vector<double>& qs) {
  const size_t n = codes.size() / 3;
  if (n == 0) return {};
  static const Luminance luminance;
  constexpr size_t kBins = 1 << 16;
  std::vector<std::vector<uint32_t>> counts(kChunks);
  parallelFor(tbb::blocked_range<size_t>(0, kChunks), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t k = r.begin(); k < r.end(); ++k) {
      counts[k].assign(kBins, 0);
      const auto [i0, i1] = chunkOf(k, n);
      for (size_t i = i0; i < i1; ++i) ++counts[k][upperBits(luminance(&codes[i * 3]))];
    }
  });
  std::vector<size_t> histogram(kBins, 0);
  for (const auto& c : counts)
    for (size_t b = 0; b < kBins; ++b) histogram[b] += c[b];
  // Each quantile's bin and its rank within the bin; then one pass gathers those bins' values.
  std::vector<size_t> bins, ranks;
  for (double q : qs) {
    size_t rank = size_t(std::clamp(q, 0.0, 1.0) * double(n - 1)), bin = 0;
    while (rank >= histogram[bin]) rank -= histogram[bin++];  // rank < n: a bin holds it
    bins.push_back(bin), ranks.push_back(rank);
  }
  std::vector<std::vector<float>> inBin(qs.size());
  for (size_t i = 0; i < n; ++i) {
    const float v = luminance(&codes[i * 3]);
    for (size_t k = 0; k < bins.size(); ++k)
      if (upperBits(v) == bins[k]) inBin[k].push_back(v);
  }
  std::vector<float> out;
  for (size_t k = 0; k < bins.size(); ++k) {
    std::vector<float>& v = inBin[k];
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(ranks[k]), v.end());
    out.push_back(v[ranks[k]]);
  }
  return out;
}

}  // namespace inlay::detail
