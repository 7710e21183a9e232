// `billiard plan-pot` and `billiard bench-pot` as a user runs them: the documented JSON, the plan
// replayed by `billiard simulate --scene` from its --scene-out (the pocketed ball, the cue ball's
// rest), exit 3 with the status and reason for a refusal, exit 2 for a bad command line.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/billiard_command.h"

namespace billiard::testing {
namespace {

const std::string kScene = std::string(PROJECT_SOURCE_DIR) + "/docs/pictures/pot_scene.json";

TEST(BilliardPlanPot, PrintsThePlanThatSimulateSceneReplays) {
  const std::string out = ::testing::TempDir() + "/pot_played.json";
  const std::string args = "plan-pot --scene " + kScene + " --ball 1 --pocket upper_right --json --scene-out " + out;
  const CommandResult r = Billiard(args);
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json j = OneObject(r, args);
  for (const char* key : {"status", "reason", "ball", "pocket", "kind", "why", "v0", "w0", "cue", "cut_deg",
                          "departure", "margin_deg", "speed_window", "cue_rest", "paths", "events", "solve_us"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["status"], "ok");
  EXPECT_EQ(j["ball"], 1);
  EXPECT_EQ(j["pocket"], "upper_right");
  EXPECT_EQ(j["margin_deg"].size(), 2u);
  EXPECT_GT(j["margin_deg"][0].get<double>(), 0.0);
  EXPECT_TRUE(j["paths"].contains("0") && j["paths"].contains("1"));
  // Ball 2 blocks the straight line: a bank, kick or curve, and the reason why.
  EXPECT_NE(j["kind"], "direct");
  EXPECT_NE(j["why"].get<std::string>().find("blocked by ball 2"), std::string::npos) << j["why"];

  const CommandResult played = Billiard("simulate --scene " + out + " --json");
  ASSERT_EQ(played.status, 0) << played.out;
  const nlohmann::json sim = OneObject(played, "simulate --scene " + out);
  for (const nlohmann::json& ball : sim["balls"]) {
    if (ball["id"] == 1) {
      EXPECT_EQ(ball["pocketed"], "upper_right");
    } else if (ball["id"] == 0) {
      EXPECT_TRUE(ball["pocketed"].is_null());
      EXPECT_NEAR(ball["state"][0].get<double>(), j["cue_rest"][0].get<double>(), 1e-9);
      EXPECT_NEAR(ball["state"][1].get<double>(), j["cue_rest"][1].get<double>(), 1e-9);
    }
  }
  EXPECT_EQ(sim["events"].size(), j["events"].size());
}

TEST(BilliardPlanPot, RefusesWithTheStatusAndReason) {
  for (const auto& [args, status] :
       {std::pair<std::string, std::string>{"--ball 9 --pocket upper_right", "no_such_ball"},
        {"--ball 1 --pocket top_right", "no_such_pocket"},
        {"--ball 1 --pocket upper_right --kind direct", "blocked"},
        {"--ball 1 --pocket upper_right --cue-to 9,9", "target_unreachable"}}) {
    const std::string full = "plan-pot --scene " + kScene + " " + args + " --json";
    const CommandResult r = Billiard(full);
    EXPECT_EQ(r.status, 3) << full;
    const nlohmann::json j = OneObject(r, full);
    EXPECT_EQ(j["status"], status) << full;
    EXPECT_FALSE(j["reason"].get<std::string>().empty());
    // Without --json: the status and reason in one line on stderr.
    const CommandResult said = Billiard("plan-pot --scene " + kScene + " " + args, true);
    EXPECT_EQ(said.status, 3);
    EXPECT_NE(said.out.find("billiard: " + status + ": "), std::string::npos) << said.out;
  }
  for (const std::string args : {"--ball 1 --pocket upper_right --kind sideways",
                                 "--ball 1 --pocket upper_right --cue-to 1,nan",
                                 "--ball 1 --pocket upper_right --cue-radius 0.1",
                                 "--ball 1"}) {
    const CommandResult r = Billiard("plan-pot --scene " + kScene + " " + args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_TRUE(r.out.empty());
  }
  EXPECT_EQ(Billiard("plan-pot --scene /nonexistent.json --ball 1 --pocket upper_right").status, 2);
  // A ball off the table is bad input (2), as in simulate and plot, not a plan refused (3).
  const std::string off = ::testing::TempDir() + "/off_table.json";
  std::ofstream(off) << R"({"table": "pool-9ft", "params": "pool", "balls": [
      {"id": 0, "state": [0.6, 0.6, 0, 0, 0, 0, 0]}, {"id": 1, "state": [3.0, 0.6, 0, 0, 0, 0, 0]}]})";
  const CommandResult r = Billiard("plan-pot --scene " + off + " --ball 1 --pocket upper_right", true);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("ball 1 at (3, 0.6) is off"), std::string::npos) << r.out;
}

TEST(BilliardBenchPot, WritesTheReportAndItsRows) {
  const std::string dir = ::testing::TempDir() + "/bench_pot";
  std::filesystem::remove_all(dir);
  const std::string args = "bench-pot --layouts 12 --margin-checks 4 --position-targets 2 --out " + dir;
  const CommandResult r = Billiard(args);
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json j = OneObject(r, args);
  EXPECT_EQ(j["layouts"], 12);
  EXPECT_EQ(j["truth"]["verified"], j["truth"]["ok"]) << "every ok plan pots when simulated";
  EXPECT_TRUE(std::filesystem::exists(dir + "/pot_report.md"));
  std::ifstream rows(dir + "/pot_results.csv");
  int lines = 0;
  for (std::string line; std::getline(rows, line);) ++lines;
  EXPECT_EQ(lines, 1 + 12 + j["position"]["targets"].get<int>());
}

}  // namespace
}  // namespace billiard::testing
