// inlay::Fingerprint: a 64-bit FNV-1a hash of what a computation reads, to tell whether an earlier
// result still serves (the light fit's traced rays, the camera the response check's copy found).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace inlay {

// FNV-1a over 64-bit words (a tail shorter than a word padded with zeros).
class Fingerprint {
 public:
  void bytes(const void* data, size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; i += 8) {
      uint64_t word = 0;
      std::memcpy(&word, p + i, std::min<size_t>(8, n - i));
      h_ = (h_ ^ word) * 0x100000001b3ull;
    }
  }
  template <class T>
  void value(const T& v) {
    bytes(&v, sizeof v);
  }
  uint64_t get() const { return h_; }

 private:
  uint64_t h_ = 0xcbf29ce484222325ull;
};

}  // namespace inlay
