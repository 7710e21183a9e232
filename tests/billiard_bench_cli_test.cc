// `billiard bench --quick` as a user runs it: the report's files and structure, a finite error for
// every method on every scene, the batch's scaling (the figures themselves are the committed full
// run's).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/support/billiard_command.h"

namespace {

using billiard::testing::Billiard;
using billiard::testing::CommandResult;

// The quick benchmark: the report's structure and finite errors for every method (no timing).
TEST(BilliardBench, QuickRunWritesTheReportAndEveryErrorIsFinite) {
  const std::string dir = ::testing::TempDir() + "/bench_quick";
  const std::string args = "bench --quick --out " + dir;
  const auto start = std::chrono::steady_clock::now();
  const CommandResult r = Billiard(args);
  const double process_us =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
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
  std::map<std::string, std::vector<double>> wall_us;  // each method's runs
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
    wall_us[field[0]].push_back(std::stod(field[5]));
  }
  std::fclose(csv);
  EXPECT_EQ(rows, scenes * methods);
  for (const auto& m : j["methods"]) {
    const std::string method = m["method"];
    EXPECT_TRUE(std::isfinite(m["p95_error_integral_m"].get<double>())) << method;
    // The summary is the median of the method's runs in results.csv (the mean of the two middle
    // ones for an even count), and each run took part of the process's time on the test's clock.
    std::vector<double> runs = wall_us[method];
    ASSERT_EQ(static_cast<long>(runs.size()), scenes) << method;
    std::sort(runs.begin(), runs.end());
    const std::size_t half = runs.size() / 2;
    const double median = runs.size() % 2 ? runs[half] : 0.5 * (runs[half - 1] + runs[half]);
    const double median_us = m["median_us"].get<double>();
    EXPECT_NEAR(median_us, median, 1e-6 * median) << method;
    EXPECT_GT(runs.front(), 0.0) << method;
    EXPECT_LE(runs.back(), process_us) << method;
    EXPECT_LE(median_us, m["p95_us"].get<double>()) << method;
  }
  // Against the peers (bench/peer_comparison.h): Figs. 6-10, both peers reach the endpoint
  // accuracy somewhere in their sweep, and the report has the table (no timing).
  const auto& figures = j.at("peers").at("figures");
  EXPECT_EQ(figures.size(), 5u);
  for (const auto& f : figures) {
    for (const char* peer : {"odeint", "cvode"}) {
      ASSERT_TRUE(f.at(peer).at("found").get<bool>()) << f["scene"] << " " << peer;
      EXPECT_LE(f[peer]["error_m"].get<double>(), j["peers"]["endpoint_accuracy_m"].get<double>())
          << f["scene"] << " " << peer;
    }
    EXPECT_GT(f.at("floor").at("steps").get<long>(), 0) << f["scene"];
  }
  std::ifstream report(dir + "/report.md");
  const std::string text((std::istreambuf_iterator<char>(report)),
                         std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("## Against the peers"), std::string::npos);
  // The batch's scaling: the quick run's 20 random shots on 1 and 2 threads (--threads, 2 by
  // default), the same final states on both.
  const auto& scaling = j["batch_scaling"];
  EXPECT_EQ(scaling["shots"], 20);
  ASSERT_EQ(scaling["runs"].size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const auto& run = scaling["runs"][i];
    EXPECT_EQ(run["threads"], 1 << i);
    EXPECT_TRUE(run["identical"].get<bool>());
    EXPECT_GT(run["shots_per_s"].get<double>(), 0.0);
  }
}

}  // namespace
