// The billiard tool as a user runs it: JSON on stdout, one-line reasons and non-zero exits on bad
// input, and the acceptance runs of the physics core.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/billiard_command.h"

namespace {

using billiard::testing::Billiard;
using billiard::testing::CommandResult;
using billiard::testing::RunCommand;

nlohmann::json Json(const std::string& args) {
  const auto start = std::chrono::steady_clock::now();
  const CommandResult r = Billiard(args);
  const double process_us =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.status, 0) << args;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  // A simulation's own time: something, and no more than the whole process took on the test's
  // clock (start-up and output included).
  if (j.contains("wall_us")) {
    EXPECT_GT(j["wall_us"].get<double>(), 0.0) << args;
    EXPECT_LE(j["wall_us"].get<double>(), process_us) << args;
  }
  return j;
}

// The states of the paper's Figs. 6-10 (Kudra et al. 2016), which belong to its ball: every
// command on them says --params paper.
const char* kFigures[] = {"0,0,0,1,-50,0,0", "0,0,0,1,-50,5,0", "0,0,0,1,150,5,0",
                          "0,0,0,1,-50,-3.5,-150", "0,0,0,1,150,0,-150"};

TEST(BilliardSimulate, PrintsTheDocumentedJsonObject) {
  const auto j = Json("simulate --state 0,0,0,1,-50,0,0 --t-end 8 --params paper --json");
  EXPECT_EQ(j["model"], "approx");
  EXPECT_EQ(j["params"], "paper");
  EXPECT_EQ(j["t"], 8.0);
  ASSERT_EQ(j["state"].size(), 7u);
  EXPECT_NEAR(j["state"][1].get<double>(), 2.3785, 1e-4);
  EXPECT_GT(j["steps"].get<long>(), 0);
  EXPECT_GT(j["rhs_evals"].get<long>(), j["steps"].get<long>());
  EXPECT_TRUE(j.contains("wall_us"));  // its value is checked against the clock by Json()
}

TEST(BilliardSimulate, ApproxEndpointsAgreeWhenTheToleranceIsTightenedHundredfold) {
  for (const char* state : kFigures) {
    const std::string base =
        std::string("simulate --state ") + state + " --t-end 8 --params paper --json";
    const auto a = Json(base), b = Json(base + " --tol 1e-9");
    EXPECT_NEAR(a["state"][0].get<double>(), b["state"][0].get<double>(), 1e-6) << state;
    EXPECT_NEAR(a["state"][1].get<double>(), b["state"][1].get<double>(), 1e-6) << state;
    std::fprintf(stderr, "approx %-24s %7.1f us, %ld steps\n", state, a["wall_us"].get<double>(),
                 a["steps"].get<long>());
  }
}

TEST(BilliardSimulate, EveryModelRunsEveryPaperFigure) {
  for (const char* model : {"closed-form", "integral"}) {
    for (const char* state : kFigures) {
      const auto j = Json(std::string("simulate --state ") + state +
                          " --t-end 8 --params paper --json --model " + model);
      EXPECT_EQ(j["model"], model);
      ASSERT_EQ(j["state"].size(), 7u) << state;
      for (const auto& x : j["state"]) EXPECT_TRUE(std::isfinite(x.get<double>()));
      if (std::string(model) == "integral") {
        EXPECT_LE(j["quadrature"]["error_estimate"].get<double>(), 1e-6);
      }
    }
  }
}

TEST(BilliardSimulate, WritesTheTrajectoryAsCsv) {
  const std::string path = ::testing::TempDir() + "/trajectory.csv";
  Json("simulate --state 0,0,0,1,-50,0,0 --t-end 1 --sample-dt 0.1 --json --trajectory " + path);
  FILE* f = std::fopen(path.c_str(), "r");
  ASSERT_NE(f, nullptr);
  int lines = 0;
  for (int c; (c = std::fgetc(f)) != EOF;) lines += c == '\n';
  std::fclose(f);
  EXPECT_EQ(lines, 12);  // header and t = 0, 0.1, ..., 1
  std::remove(path.c_str());
}

TEST(BilliardSimulate, RefusesATrajectoryOfTooManySamplesBeforeWritingAny) {
  const std::string path = ::testing::TempDir() + "/too_many_samples.csv";
  std::filesystem::remove(path);
  // The shell's file size limit (10 MB) stops a tool that writes anyway here, not at a full disk.
  const CommandResult r = RunCommand(std::string("ulimit -f 20480 && ") + BILLIARD_BIN +
                                         " simulate --state 0,0,0,1,-50,0,0 --t-end 8 "
                                         "--sample-dt 1e-9 --json --trajectory " +
                                         path,
                                     true);
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  EXPECT_NE(r.out.find("8000000001 samples"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1000000"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(BilliardSimulate, BadInputExitsNonZeroWithAOneLineReason) {
  const char* bad[] = {
      "simulate --state 0,0,0,nan,0,0,0 --t-end 1 --json",
      "simulate --state 0,0,0,1,0,0 --t-end 1 --json",
      "simulate --state 0,0,0,1,0,0,0,0 --t-end 1 --json",
      "simulate --state 0,0,0,1,x,0,0 --t-end 1 --json",
      "simulate --state 0,0,0,1,0,0,0 --t-end=-1 --json",
      "simulate --state 0,0,0,1,0,0,0 --t-end 1 --model magic --json",
      "simulate --state 0,0,0,1,0,0,0 --t-end 1 --params no-such-set --json",
      "simulate --state 0,0,0,1,0,0,0 --t-end inf --json",
      "simulate --state 0,0,0,1,0,0,0 --t-end 1 --tol 0 --json",
      "simulate --state 0,0,0,1,0,0,0 --t-end 1 --integrator euler --json",
      "simulate --state 0,0,0,1,0,0,0 --t-end 1 --model auto --json",
      "simulate --state 0,0,0,1,0,0,0 --t-end 1 --model auto --accuracy=-1 --json",
      "simulate --state 0,0,0,1,0,0,0 --t-end 1 --accuracy 0.01 --json",
      "simulate --state 0,0,0,1,0,0,0 --t-end 1 --sample-dt 0 --json",
      "simulate --state 0,0,0,1,0,0,0 --t-end 1 --sample-dt=-0.1 --json",
      "simulate --state 0,0,0,1,0,0,0 --t-end 1 --sample-dt inf --json",
      "simulate --state 0,0,0,1,0,0,0 --t-end 1 --sample-dt nan --json",
      "bench --quick",
      "bench --quick --out /tmp --threads 0",
  };
  for (const char* args : bad) {
    const CommandResult r = Billiard(args, true);
    EXPECT_NE(r.status, 0) << args;
    EXPECT_EQ(r.out.find('{'), std::string::npos) << args;  // no JSON on failure
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << args << ": " << r.out;
  }
}

TEST(BilliardSimulate, AutoModelSaysWhatItChose) {
  const auto side_spin = Json(
      "simulate --state 0,0,0,1,150,0,-150 --t-end 8 --model auto "
      "--accuracy 10 --params paper --json");
  EXPECT_NE(side_spin["model"], "closed-form");
  EXPECT_EQ(side_spin["auto"]["scene_kind"], "side-spin");
  const auto rolling = Json(
      "simulate --state 0,0,0,1,-50,0,0 --t-end 8 --model auto "
      "--accuracy 0.001 --params paper --json");
  EXPECT_EQ(rolling["model"], "closed-form");
  EXPECT_EQ(rolling["steps"], 0);
  EXPECT_NEAR(rolling["state"][1].get<double>(), 2.3785, 1e-4);
}

// The nodes and every command but `bench` (whose scenes are the paper's) default to one set, the
// pool ball, and a set read from a file is named by its file.
TEST(BilliardSimulate, DefaultsToThePoolSetAndNamesTheFileOfAnother) {
  const auto pool = Json("simulate --state 0.5,0.5,1,0,0,0,0 --t-end 1 --json");
  EXPECT_EQ(pool["params"], "pool");
  EXPECT_FALSE(pool.contains("params_file"));
  const std::string path = ::testing::TempDir() + "/simulate_params.json";
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs(R"({"name":"mine","ball":{"radius":0.03,"mass":0.2,"gravity":9.8},
      "contact":{"patch_radius":0.002,"mu":0.15,"d":0.5,"eps_t":0.01,"eps_r":0.02,
                 "b_t":0.7,"m_t":2,"b_m":0.5,"m_m":2},
      "cue":{"mass":0.5,"tip_restitution":0.8,"max_tip_offset":0.5,"max_speed":5,
             "end_mass":0.01},
    "collision":{"ball_restitution":0.95,"ball_friction_a":0.01,"ball_friction_b":0.108,
                 "ball_friction_c":1.088,"cushion_restitution":0.9,"cushion_friction":0.2},
      "table":{"length":2.84,"width":1.42}})",
               f);
    std::fclose(f);
  }
  const auto mine =
      Json("simulate --state 0.5,0.5,1,0,0,0,0 --t-end 1 --params " + path + " --json");
  EXPECT_EQ(mine["params"], "mine");
  EXPECT_EQ(mine["params_file"], path);
  std::remove(path.c_str());
}

TEST(BilliardSimulate, NegativeNumbersAreAcceptedWithEquals) {
  const auto j = Json("simulate --state=-1,0,0,1,-50,0,0 --t-end 1 --json");
  EXPECT_EQ(j["state"][0], -1.0);
}

// A file that is no LCM log is bad input, not a replay that differs.
void ExpectReplayRefusesInput(const std::string& path, const std::string& reason) {
  const CommandResult r = Billiard("replay " + path + " --json", true);
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  EXPECT_NE(r.out.find(reason), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("differs"), std::string::npos) << r.out;
}

TEST(BilliardReplay, SaysAFileIsNotAnLcmLog) {
  const std::string path = ::testing::TempDir() + "/not_a_log.lcm";
  std::ofstream(path) << "t,X,Y\n0,0.6,0.635\n";
  ExpectReplayRefusesInput(path, "is not an LCM log");
  std::filesystem::remove(path);
}

TEST(BilliardReplay, SaysALogIsEmpty) {
  const std::string path = ::testing::TempDir() + "/empty.lcm";
  std::ofstream{path};
  ExpectReplayRefusesInput(path, "is empty");
  std::filesystem::remove(path);
}

TEST(BilliardFitContact, ReproducesThePaperTable) {
  const auto fixed = Json("fit-contact --fix-m 2 --json");
  EXPECT_NEAR(fixed["bT"].get<double>(), 0.68102, 0.02 * 0.68102);
  EXPECT_NEAR(fixed["bM"].get<double>(), 0.480909, 0.02 * 0.480909);
  EXPECT_EQ(fixed["mT"], 2.0);
  const auto free = Json("fit-contact --json");
  EXPECT_NEAR(free["bT"].get<double>(), 0.771, 0.05 * 0.771);
  EXPECT_NEAR(free["mT"].get<double>(), 2.655, 0.05 * 2.655);
  EXPECT_NEAR(free["bM"].get<double>(), 0.419, 0.05 * 0.419);
  EXPECT_NEAR(free["mM"].get<double>(), 3.073, 0.05 * 3.073);
  EXPECT_LT(free["cost"].get<double>(), fixed["cost"].get<double>());
}

TEST(BilliardFitContact, RejectsAnExponentBelowOne) {
  EXPECT_NE(Billiard("fit-contact --fix-m 0.5 --json").status, 0);
}

}  // namespace
