// The test-data directory: real camera frames and real shots, which are test data beside the
// repository and not ours to ship (shared/data/, each file saying where it comes from).
//
// As OpenCV's tests find theirs through OPENCV_TEST_DATA_PATH: the environment variable
// BILLIARD_TEST_DATA names the directory, else the one beside the source tree that CMake saw
// (BILLIARD_DEFAULT_TEST_DATA). A test that needs a file it cannot find is skipped with the
// reason (ctest reports it as skipped), never failed:
//
//   BILLIARD_TEST_DATA_OR_SKIP(photo, "real-tables/snooker_overhead_1280x720.png");
//   cv::Mat image = cv::imread(photo);
#pragma once

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <cstdlib>
#include <string>

namespace billiard::testing {

inline std::string TestDataDir() {
  const char* from_environment = std::getenv("BILLIARD_TEST_DATA");
  if (from_environment != nullptr && *from_environment != '\0') return from_environment;
  return BILLIARD_DEFAULT_TEST_DATA;
}

// The path of `relative` inside the test-data directory, or "" when no such file is there.
inline std::string TestDataPath(const std::string& relative) {
  const std::string path = TestDataDir() + "/" + relative;
  struct stat info;
  return stat(path.c_str(), &info) == 0 ? path : std::string();
}

inline std::string MissingTestData(const std::string& relative) {
  return "test data " + relative + " not found in " + TestDataDir() +
         " (set BILLIARD_TEST_DATA to the directory that holds real-tables/ and real-shots/)";
}

}  // namespace billiard::testing

// Declares `const std::string var`, the path of `relative` in the test-data directory, or skips
// the test (returning from it) with the reason.
#define BILLIARD_TEST_DATA_OR_SKIP(var, relative)                      \
  const std::string var = ::billiard::testing::TestDataPath(relative); \
  if (var.empty()) GTEST_SKIP() << ::billiard::testing::MissingTestData(relative)
