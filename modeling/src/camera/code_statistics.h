// Photo-wide statistics of 8-bit codes for the response estimate (internal to modeling; see
// response.h): what photoIsUndetermined and the dark fill read, computed in parallel and exactly
// as the plain loops over every pixel give them.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace inlay::detail {

// The pixels' luma codes, each the rounded mean of its three codes.
struct LumaSpread {
  std::array<size_t, 256> histogram{};
  uint64_t sum = 0, sumOfSquares = 0;  // of the luma codes (whole numbers: exact)
  size_t clipped = 0;                  // pixels with a code >= 254 or <= 1
  size_t pixels = 0;
};

// `codes`: pixels x 3 interleaved 8-bit codes.
LumaSpread lumaSpreadOf(const std::vector<unsigned char>& codes);

// The pixels' sRGB-decoded luminances (the mean of the three channels' linear values, as a float)
// at the quantiles `qs` (each the value of rank floor(q (n - 1)) in ascending order, what
// nth_element gives), without sorting or storing every value: a histogram of the values' upper 16
// bits (non-negative floats order as their bit patterns), then the values of the bins the ranks
// fall in, ordered. Empty when there are no pixels; each q is clamped to [0, 1].
std::vector<float> luminanceQuantiles(const std::vector<unsigned char>& codes,
                                      const std::vector<double>& qs);

}  // namespace inlay::detail
