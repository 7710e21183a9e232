// `billiard bench --quick` as a user runs it: the report's files and structure, a finite error for
// every method on every scene (the figures themselves are the committed full run's).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/billiard_command.h"

namespace {

using billiard::testing::Billiard;
using billiard::testing::CommandResult;

// The quick benchmark: the report's structure and finite errors for every method (no timing).
TEST(BilliardBench, QuickRunWritesTheReportAndEveryErrorIsFinite) {
  const std::string dir = ::testing::TempDir() + "/bench_quick";
  const std::string args = "bench --quick --out " + dir;
  const CommandResult r = Billiard(args);
  ASSERT_EQ(r.status, 0) << args;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["out"], dir);
  const long scenes = j["scenes"], methods = j["methods"].size();
  EXPECT_GE(scenes, 30);
  EXPECT_GE(methods, 4);
  for (const char* file :
       {"/report.md", "/results.csv", "/speed_vs_error.png", "/model_choice.json"}) {
    FILE* f = std::fopen((dir + file).c_str(), "rb");
    EXPECT_NE(f, nullptr) << file;
    if (f) std::fclose(f);
  }
  FILE* csv = std::fopen((dir + "/results.csv").c_str(), "r");
  ASSERT_NE(csv, nullptr);
  char line[1024];
  ASSERT_NE(std::fgets(line, sizeof line, csv), nullptr);  // header
  long rows = 0;
  while (std::fgets(line, sizeof line, csv)) {
    ++rows;
    std::string text(line);
    std::array<std::string, 11> field;
    for (int i = 0, start = 0; i < 11; ++i) {
      const std::size_t comma = text.find(',', start);
      field[i] = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      start = static_cast<int>(comma + 1);
    }
    EXPECT_EQ(field[4], "1") << "failed run: " << text;
    for (int i : {8, 9}) EXPECT_TRUE(std::isfinite(std::stod(field[i]))) << text;
  }
  std::fclose(csv);
  EXPECT_EQ(rows, scenes * methods);
  for (const auto& m : j["methods"]) {
    EXPECT_TRUE(std::isfinite(m["p95_error_integral_m"].get<double>())) << m["method"];
    EXPECT_GE(m["median_us"].get<double>(), 0.0);
  }
}

}  // namespace
