// Helpers shared by the GoogleTest suites.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <string>

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
  auto p = std::filesystem::temp_directory_path() / ("inlay_test_" + name + "_" +
                                                      std::to_string(::getpid()));
  std::filesystem::remove_all(p);
  std::filesystem::create_directories(p);
  return p;
}

}  // namespace inlay::test

// Skips the test (reported as skipped by ctest through gtest) when ../shared is missing.
#define INLAY_REQUIRE_SHARED()                                                   \
  do {                                                                           \
    if (inlay::test::sharedDir().empty()) GTEST_SKIP() << "../shared not present"; \
  } while (0)
