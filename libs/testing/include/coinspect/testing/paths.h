// Where tests find the repository, the build folder and the shared reference data.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace coinspect::testing {

inline std::filesystem::path sourceDir() {
  return COINSPECT_SOURCE_DIR;
}
inline std::filesystem::path binaryDir() {
  return COINSPECT_BINARY_DIR;
}

// The CARIC MBS scenario lives in ../shared (GPL-2.0 data, never copied into the repository).
// COINSPECT_SHARED_DIR in the environment overrides the configured location.
inline std::filesystem::path caricMbsDir() {
  const char* env = std::getenv("COINSPECT_SHARED_DIR");
  const std::filesystem::path shared = env ? env : COINSPECT_SHARED_DIR;
  return shared / "data" / "caric-mbs";
}

inline bool haveCaricMbs() {
  return std::filesystem::exists(caricMbsDir() / "mbs.stl");
}

// A fresh empty folder for one test's outputs, under the build tree.
inline std::filesystem::path scratchDir(const std::string& name) {
  const auto dir = binaryDir() / "test-scratch" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace coinspect::testing

// Skips the current test cleanly when ../shared is absent (e.g. a checkout without it).
#define COINSPECT_REQUIRE_CARIC_MBS()                                                        \
  do {                                                                                       \
    if (!::coinspect::testing::haveCaricMbs())                                               \
      GTEST_SKIP() << "CARIC MBS data not found at " << ::coinspect::testing::caricMbsDir(); \
  } while (0)
