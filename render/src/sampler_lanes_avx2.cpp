// SampleRng (sampling.h) for eight lanes at once in AVX2's 32-bit integer lanes, built with
// -mavx2: the constructor's pixel key and reversed sample index, then get2() of a few pairs, every
// step the scalar one lane by lane (wrapping 32-bit products, the same shifts), so the same bits.
// Nothing here is inline in a header the rest of the build shares.
#include "simd_lanes.h"

#if defined(__AVX2__)
#include <immintrin.h>

namespace inlay::detail {
namespace {

using U = __m256i;

inline U all(uint32_t v) { return _mm256_set1_epi32(int(v)); }
inline U add(U a, U b) { return _mm256_add_epi32(a, b); }
inline U mul(U a, U b) { return _mm256_mullo_epi32(a, b); }
inline U xorOf(U a, U b) { return _mm256_xor_si256(a, b); }
inline U andOf(U a, U b) { return _mm256_and_si256(a, b); }
inline U orOf(U a, U b) { return _mm256_or_si256(a, b); }

// pcgHash.
inline U pcgHash(U v) {
  const U state = add(mul(v, all(747796405u)), all(2891336453u));
  const U shift = add(_mm256_srli_epi32(state, 28), all(4u));
  const U word = mul(xorOf(_mm256_srlv_epi32(state, shift), state), all(277803737u));
  return xorOf(_mm256_srli_epi32(word, 22), word);
}

// reverseBits: the bytes of each lane reversed, then the bits inside each byte.
inline U reverseBits(U x) {
  const U bytes = _mm256_setr_epi8(3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12, 3, 2, 1, 0, 7,
                                   6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12);
  x = _mm256_shuffle_epi8(x, bytes);
  x = orOf(_mm256_slli_epi32(andOf(x, all(0x0f0f0f0fu)), 4),
           _mm256_srli_epi32(andOf(x, all(0xf0f0f0f0u)), 4));
  x = orOf(_mm256_slli_epi32(andOf(x, all(0x33333333u)), 2),
           _mm256_srli_epi32(andOf(x, all(0xccccccccu)), 2));
  x = orOf(_mm256_slli_epi32(andOf(x, all(0x55555555u)), 1),
           _mm256_srli_epi32(andOf(x, all(0xaaaaaaaau)), 1));
  return x;
}

// laineKarras.
inline U laineKarras(U x, U seed) {
  x = add(x, seed);
  x = xorOf(x, mul(x, all(0x6c50b47cu)));
  x = xorOf(x, mul(x, all(0xb82f1e52u)));
  x = xorOf(x, mul(x, all(0xc7afe638u)));
  x = xorOf(x, mul(x, all(0x8d22f6e6u)));
  return x;
}

// reversedSobol1: four table lookups, one per byte of the index.
inline U reversedSobol1(U i, const uint32_t* table) {
  const int* t = reinterpret_cast<const int*>(table);
  const U low = all(0xffu);
  U r = _mm256_i32gather_epi32(t, andOf(i, low), 4);
  r = xorOf(r, _mm256_i32gather_epi32(t + 256, andOf(_mm256_srli_epi32(i, 8), low), 4));
  r = xorOf(r, _mm256_i32gather_epi32(t + 512, andOf(_mm256_srli_epi32(i, 16), low), 4));
  return xorOf(r, _mm256_i32gather_epi32(t + 768, _mm256_srli_epi32(i, 24), 4));
}

// toUnit: double(bits >> 8) / 2^24, four lanes at a time (exact both ways).
inline void toUnit(U bits, double* out) {
  const U top = _mm256_srli_epi32(bits, 8);  // below 2^24: a signed 32-bit integer as it is
  const __m256d scale = _mm256_set1_pd(1.0 / 16777216.0);
  _mm256_storeu_pd(out, _mm256_mul_pd(_mm256_cvtepi32_pd(_mm256_castsi256_si128(top)), scale));
  _mm256_storeu_pd(out + 4, _mm256_mul_pd(_mm256_cvtepi32_pd(_mm256_extracti128_si256(top, 1)), scale));
}

inline U load(const uint32_t* p) { return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p)); }

}  // namespace

void samplerLanesAvx2(SamplerLanes& s) {
  // SampleRng's constructor.
  const U pixelKey = pcgHash(add(load(s.y), pcgHash(add(load(s.x), pcgHash(all(s.seed))))));
  const U reversedSample = reverseBits(load(s.sample));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(s.pixelKey), pixelKey);
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(s.reversedSample), reversedSample);
  // get2() of each pair.
  for (int k = 0; k < s.pairs && k < kSamplerPairs; ++k) {
    const U pairSeed = pcgHash(xorOf(pixelKey, all(s.pairHash[k])));
    const U index = reverseBits(laineKarras(reversedSample, pairSeed));
    toUnit(reverseBits(laineKarras(index, pcgHash(pairSeed))), s.u[k][0]);
    toUnit(reverseBits(
               laineKarras(reversedSobol1(index, s.sobol1Reversed), pcgHash(add(pairSeed, all(1u))))),
           s.u[k][1]);
  }
}

}  // namespace inlay::detail
#else
namespace inlay::detail {
// Not an x86-64 build: cpuHasAvx2() is false and this is never called.
void samplerLanesAvx2(SamplerLanes&) {}
}  // namespace inlay::detail
#endif
