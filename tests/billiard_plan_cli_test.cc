// `billiard plan` as a user runs it: one JSON object on stdout, exit 3 with the status and reason
// for a refused plan, exit 2 with a one-line reason for a bad command line.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "planner/testing/request_suite.h"
#include "tests/support/billiard_command.h"

namespace {

using billiard::testing::Billiard;
using billiard::testing::CommandResult;
using billiard::testing::OneObject;

void ExpectEveryDocumentedKey(const nlohmann::json& j) {
  for (const char* key : {"v0", "w0", "cue", "predicted_final", "closed_form_miss_m",
                          "refined_miss_m", "solve_us", "iterations", "arrival_time", "status"}) {
    EXPECT_TRUE(j.contains(key)) << key << " in " << j;
  }
  EXPECT_EQ(j["v0"].size(), 2u);
  EXPECT_EQ(j["w0"].size(), 3u);
  EXPECT_EQ(j["predicted_final"].size(), 2u);
  for (const char* key : {"speed", "heading", "tip_side", "tip_height", "elevation"}) {
    EXPECT_TRUE(j["cue"].contains(key)) << "cue." << key << " in " << j;
  }
}

TEST(BilliardPlan, PrintsTheDocumentedJsonObject) {
  const std::string args = "plan --from 0.5,0.5 --to 1.5,0.8 --json";
  const auto start = std::chrono::steady_clock::now();
  const CommandResult r = Billiard(args);
  const double process_us =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = OneObject(r, args);
  ExpectEveryDocumentedKey(j);
  // The planning time: something, and within the whole process run on the test's clock.
  EXPECT_GT(j["solve_us"].get<double>(), 0.0);
  EXPECT_LE(j["solve_us"].get<double>(), process_us);
  EXPECT_EQ(j["status"], "ok");
  EXPECT_FALSE(j.contains("reason"));
  EXPECT_LT(std::hypot(j["predicted_final"][0].get<double>() - 1.5,
                       j["predicted_final"][1].get<double>() - 0.8),
            1e-3);
  EXPECT_LE(j["refined_miss_m"].get<double>(), 1e-4);
  EXPECT_GT(j["cue"]["speed"].get<double>(), 0.0);
  // No side spin: the cue points along the line to the target.
  EXPECT_NEAR(j["cue"]["heading"].get<double>(), std::atan2(0.3, 1.0), 1e-3);
  EXPECT_GT(j["arrival_time"].get<double>(), 0.0);
  std::fprintf(stderr, "plan: %d iterations, %.0f us, miss %.2e m (closed form %.2e m)\n",
               j["iterations"].get<int>(), j["solve_us"].get<double>(),
               j["refined_miss_m"].get<double>(), j["closed_form_miss_m"].get<double>());
}

TEST(BilliardPlan, EverySpinChoiceAnswersWithOneObject) {
  for (const char* spin : {"--spin stun", "--spin natural", "--spin follow", "--spin draw",
                           "--slide 0.2", "--spin natural --side-spin=-20", "--no-refine"}) {
    const std::string args =
        std::string("plan --from 0.5,0.5 --to 1.5,0.8 --final-speed 0.3 --json ") + spin;
    const CommandResult r = Billiard(args);
    const auto j = OneObject(r, args);
    ExpectEveryDocumentedKey(j);
    EXPECT_EQ(r.status, j["status"] == "ok" ? 0 : 3) << args;
    std::fprintf(stderr, "%-32s %s, %d iterations, miss %.2e m (closed form %.2e m), %.0f us\n",
                 spin, j["status"].get<std::string>().c_str(), j["iterations"].get<int>(),
                 j["refined_miss_m"].get<double>(), j["closed_form_miss_m"].get<double>(),
                 j["solve_us"].get<double>());
  }
}

TEST(BilliardPlan, RefusedPlanSaysWhyAndExitsThree) {
  const std::string args = "plan --from 0.5,0.5 --to 5,0.5 --json";
  const CommandResult r = Billiard(args);
  EXPECT_EQ(r.status, 3);
  const auto j = OneObject(r, args);
  ExpectEveryDocumentedKey(j);
  EXPECT_EQ(j["status"], "off_table");
  ASSERT_TRUE(j.contains("reason"));
  EXPECT_NE(j["reason"].get<std::string>().find("beyond the playing surface"), std::string::npos)
      << j["reason"];

  // Without --json: nothing on stdout, the reason in one line on stderr.
  const CommandResult human = Billiard("plan --from 0.5,0.5 --to 5,0.5", true);
  EXPECT_EQ(human.status, 3);
  EXPECT_EQ(std::count(human.out.begin(), human.out.end(), '\n'), 1) << human.out;
  EXPECT_NE(human.out.find("off_table"), std::string::npos) << human.out;
}

TEST(BilliardPlan, BadCommandLineExitsTwoWithAOneLineReason) {
  const char* bad[] = {
      "plan --from 0.5,0.5 --to 1.5,0.8 --spin stun --slide 0.1 --json",
      "plan --from 0.5,0.5 --to nan,0 --json",
      "plan --from 0.5 --to 1.5,0.8 --json",
      "plan --from 0.5,0.5 --to 1.5,x --json",
      "plan --from 0.5,0.5 --json",
      "plan --from 0.5,0.5 --to 1.5,0.8 --spin sideways --json",
      "plan --from 0.5,0.5 --to 1.5,0.8 --final-speed nan --json",
      "plan --from 0.5,0.5 --to 1.5,0.8 --final-speed -0.3 --json",  // bad input, not a refusal
      "plan --from 0.5,0.5 --to 1.5,0.8 --slide inf --json",
      "plan --from 0.5,0.5 --to 1.5,0.8 --params no-such-set --json",
  };
  for (const char* args : bad) {
    const CommandResult r = Billiard(args, true);
    EXPECT_EQ(r.status, 2) << args << ": " << r.out;
    EXPECT_EQ(r.out.find('{'), std::string::npos) << args;  // no JSON on failure
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << args << ": " << r.out;
  }
}

TEST(BilliardPlan, HumanSummaryGoesToStderr) {
  const CommandResult r = Billiard("plan --from 0.5,0.5 --to 1.5,0.8");
  EXPECT_EQ(r.status, 0);
  EXPECT_TRUE(r.out.empty()) << r.out;
}

std::string Numbers(std::initializer_list<double> values) {
  std::string text;
  char number[40];
  for (double v : values) {
    std::snprintf(number, sizeof number, "%.17g", v);
    text += (text.empty() ? "" : ",") + std::string(number);
  }
  return text;
}

TEST(BilliardPlan, PlannedLaunchesLandOnTheTargetWhenBilliardSimulateRunsThem) {
  // The acceptance check as a user would run it: plan, then simulate the plan's v0, w0 with the
  // simulator's defaults until the speed falls to the requested final speed.
  billiard::planner::testing::RequestSuite suite({2.54, 1.27}, 7);
  int planned = 0;
  for (int i = 0; i < 25; ++i) {
    const billiard::planner::ShotRequest q = suite.Next(i);
    std::string args = "plan --from=" + Numbers({q.from.x(), q.from.y()}) +
                       " --to=" + Numbers({q.to.x(), q.to.y()}) + " --final-speed " +
                       Numbers({q.final_speed}) + " --side-spin=" + Numbers({q.side_spin}) +
                       " --json";
    if (q.slide_length) {
      args += " --slide " + Numbers({*q.slide_length});
    } else {
      const char* names[] = {"stun", "follow", "natural", "draw"};
      args += std::string(" --spin ") + names[static_cast<int>(q.style)];
    }
    const CommandResult plan = Billiard(args);
    const auto j = OneObject(plan, args);
    if (plan.status == 3) {  // out of reach (a cushion in the way, a draw beyond the tip offset)
      EXPECT_EQ(j["status"], "unreachable") << args;
      continue;
    }
    ASSERT_EQ(plan.status, 0) << args << ": " << plan.out;
    ++planned;
    const std::string simulate = "simulate --state=" +
                                 Numbers({q.from.x(), q.from.y(), j["v0"][0], j["v0"][1],
                                          j["w0"][0], j["w0"][1], j["w0"][2]}) +
                                 " --t-end 60 --until-speed " + Numbers({q.final_speed}) +
                                 " --json";
    const CommandResult sim = Billiard(simulate);
    ASSERT_EQ(sim.status, 0) << simulate;
    const auto end = OneObject(sim, simulate);
    EXPECT_TRUE(end["arrived"].get<bool>()) << simulate;
    EXPECT_LT(std::hypot(end["state"][0].get<double>() - q.to.x(),
                         end["state"][1].get<double>() - q.to.y()),
              5e-4)
        << args << "\n"
        << simulate;
  }
  EXPECT_GE(planned, 22);
}

TEST(BilliardBenchPlanner, RefinedPlansAllLandAndSensitivitiesNeedFewerSimulations) {
  char dir[] = "/tmp/bench_planner_XXXXXX";
  ASSERT_NE(mkdtemp(dir), nullptr);
  const std::string args = std::string("bench-planner --requests 20 --out ") + dir;
  const CommandResult r = Billiard(args);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = OneObject(r, args);
  const auto& sensitivities = j["variants"]["refined/sensitivities"];
  const auto& differences = j["variants"]["refined/central-differences"];
  EXPECT_GE(sensitivities["planned"].get<int>(), 18);
  EXPECT_EQ(sensitivities["within_0_5_mm"], sensitivities["planned"]);
  EXPECT_EQ(differences["within_0_5_mm"], differences["planned"]);
  EXPECT_LT(sensitivities["median_simulations"].get<double>(),
            differences["median_simulations"].get<double>());
  // The closed form alone misses by centimetres on spin-heavy shots.
  EXPECT_GT(j["variants"]["closed-form"]["p95_closed_form_miss_m"].get<double>(), 0.01);
  for (const char* file : {"/planner_report.md", "/planner_results.csv"}) {
    EXPECT_GT(std::filesystem::file_size(std::string(dir) + file), 100u) << file;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
