// Helpers shared by the GoogleTest suites.
#pragma once

#include <bit>
#include <csignal>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/resource.h>

#include <gtest/gtest.h>

namespace inlay::test {

// ../shared (ground-truth scenes, York photos, models); empty when absent (a user's clone).
inline std::string sharedDir() {
  const char* env = std::getenv("INLAY_SHARED_DIR");
  std::string d = env ? env : INLAY_SHARED_DIR;
  return std::filesystem::is_directory(d) ? d : std::string();
}

// A fresh temporary folder for one test.
inline std::filesystem::path tempDir(const std::string& name) {
  auto p = std::filesystem::temp_directory_path() /
           ("inlay_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(p);
  std::filesystem::create_directories(p);
  return p;
}

inline std::string readBytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline size_t countFiles(const std::filesystem::path& dir) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

// Bit-for-bit equality of n floats, compared as their bit patterns: +0 and -0 differ and a NaN
// equals the same NaN, as "the photo's own bits, unchanged" means (== on floats says otherwise).
inline bool sameBits(const float* a, const float* b, size_t n) {
  for (size_t i = 0; i < n; ++i)
    if (std::bit_cast<uint32_t>(a[i]) != std::bit_cast<uint32_t>(b[i])) return false;
  return true;
}

// Caps the size of files this process may write, so a write fails part-way as on a full disk
// (works as root, unlike a read-only folder).
class FileSizeCap {
 public:
  explicit FileSizeCap(rlim_t bytes) {
    getrlimit(RLIMIT_FSIZE, &old_);
    previous_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit r = old_;
    r.rlim_cur = bytes;
    setrlimit(RLIMIT_FSIZE, &r);
  }
  ~FileSizeCap() {
    setrlimit(RLIMIT_FSIZE, &old_);
    std::signal(SIGXFSZ, previous_);
  }
  FileSizeCap(const FileSizeCap&) = delete;
  FileSizeCap& operator=(const FileSizeCap&) = delete;

 private:
  rlimit old_{};
  void (*previous_)(int) = nullptr;
};

}  // namespace inlay::test

// Skips the test (reported as skipped by ctest through gtest) when ../shared is missing.
#define INLAY_REQUIRE_SHARED()                                                     \
  do {                                                                             \
    if (inlay::test::sharedDir().empty()) GTEST_SKIP() << "../shared not present"; \
  } while (0)
