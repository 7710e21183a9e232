// `billiard choose-shot` and `billiard play` as a user runs them: the documented JSON, the
// nine-ball rule, results that do not depend on the thread count, the binomial standard error,
// exit 3 with the status and reason for a refusal, exit 2 for a bad command line.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "tests/support/billiard_command.h"

namespace billiard::testing {
namespace {

const std::string kScene = std::string(PROJECT_SOURCE_DIR) + "/tests/data/nine_ball_layout.json";
const std::string kFew = " --samples 16";

nlohmann::json Choose(const std::string& options) {
  const std::string args = "choose-shot --scene " + kScene + kFew + " --json " + options;
  const CommandResult r = Billiard(args);
  EXPECT_EQ(r.status, 0) << args << ": " << r.out;
  return OneObject(r, args);
}

TEST(BilliardChooseShot, PrintsTheChoiceUnderNineBallRules) {
  const nlohmann::json j = Choose("--rules nine-ball");
  for (const char* key : {"choice", "candidates", "cue_placement", "decision_us", "status", "likely"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["status"], "ok");
  EXPECT_TRUE(j["cue_placement"].is_null());
  const nlohmann::json& c = j["choice"];
  for (const char* key : {"ball", "pocket", "kind", "cue", "margin_deg", "success_probability",
                          "probability_stderr", "next_shot_value"}) {
    EXPECT_TRUE(c.contains(key)) << key;
  }
  EXPECT_EQ(c["ball"], 1);  // the lowest on the table
  for (const nlohmann::json& candidate : j["candidates"]) EXPECT_EQ(candidate["ball"], 1);
  const double p = c["success_probability"], n = c["samples"];
  EXPECT_GE(p, 0.0);
  EXPECT_LE(p, 1.0);
  EXPECT_NEAR(c["probability_stderr"].get<double>(), std::sqrt(p * (1 - p) / n), 1e-12);
  EXPECT_GE(c["next_shot_value"].get<double>(), 0.0);
  EXPECT_LE(c["next_shot_value"].get<double>(), 1.0);
}

// A long cut under the tournaments' noise whose miss leaves the 1 open: it plays safe and says
// why, the safety's chance of winning above the attempt's; the nine-ball layout's pot it plays.
// The table's constants known, as in a match (planner/game/match.h): drawn within the pool
// set's uncertainty the two chances are within a hundredth (0.454 and 0.460), too near to test.
TEST(BilliardChooseShot, PlaysSafeWhenThatWinsMoreRacksAndSaysWhy) {
  const std::string scene = std::string(PROJECT_SOURCE_DIR) + "/tests/data/nine_ball_safety.json";
  const std::string args = "choose-shot --scene " + scene + kFew +
                           " --rules nine-ball --noise computational-pool --exact-constants --json";
  const CommandResult r = Billiard(args);
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json j = OneObject(r, args);
  EXPECT_EQ(j["plays_safe"], true);
  EXPECT_EQ(j["safety"]["target"], 1);
  EXPECT_GT(j["safety"]["win"].get<double>(), j["attempt_win"].get<double>());
  EXPECT_NE(j["reason"].get<std::string>().find("playing safe on ball 1"), std::string::npos);
  // At the default 64 samples: with 16 the second level's values of a few executions can rank a
  // bank (9 of 16) above the sure direct pot, whose confirmation then falls below the safety.
  const std::string layout = "choose-shot --scene " + kScene + " --rules nine-ball --json";
  const CommandResult played = Billiard(layout);
  ASSERT_EQ(played.status, 0) << played.out;
  const nlohmann::json pot = OneObject(played, layout);
  EXPECT_EQ(pot["plays_safe"], false);
  EXPECT_TRUE(pot["safety"].is_null());
}

TEST(BilliardChooseShot, SameChoiceWhateverTheThreads) {
  nlohmann::json one = Choose("--rules nine-ball --threads 1");
  nlohmann::json two = Choose("--rules nine-ball --threads 2");
  for (nlohmann::json* j : {&one, &two}) {
    j->erase("decision_us");
    (*j)["choice"].erase("solve_us");
    for (nlohmann::json& c : (*j)["candidates"]) c.erase("solve_us");
  }
  EXPECT_EQ(one, two);
}

TEST(BilliardChooseShot, PlacesTheCueBallInHand) {
  const nlohmann::json j = Choose("--rules nine-ball --ball-in-hand");
  ASSERT_EQ(j["cue_placement"].size(), 2u);
  const double x = j["cue_placement"][0], y = j["cue_placement"][1];
  EXPECT_GT(x, 0.0);
  EXPECT_LT(x, 2.54);
  EXPECT_GT(y, 0.0);
  EXPECT_LT(y, 1.27);
  EXPECT_EQ(j["choice"]["ball"], 1);
}

TEST(BilliardChooseShot, RefusesWithTheStatusAndReason) {
  const std::string lone = ::testing::TempDir() + "/lone_cue_ball.json";
  std::ofstream(lone) << R"({"table": "pool-9ft", "params": "pool",
      "balls": [{"id": 0, "state": [1.0, 0.6, 0, 0, 0, 0, 0]}]})";
  const std::string args = "choose-shot --scene " + lone + " --json";
  const CommandResult r = Billiard(args);
  EXPECT_EQ(r.status, 3);
  const nlohmann::json j = OneObject(r, args);
  EXPECT_EQ(j["status"], "no_target");
  EXPECT_FALSE(j["reason"].get<std::string>().empty());
  EXPECT_TRUE(j["choice"].is_null());

  EXPECT_EQ(Billiard("choose-shot --scene " + kScene + " --rules snooker --json").status, 2);
  EXPECT_EQ(Billiard("choose-shot --scene " + kScene + " --noise no-such-noise --json").status, 2);
  // A noise that does not load is refused before the first choice, not after the calibration.
  EXPECT_EQ(Billiard("bench-game --layouts 0 --noise no-such-noise").status, 2);
  EXPECT_EQ(Billiard("bench-game --layouts 0 --plant-noise no-such-noise").status, 2);
  EXPECT_EQ(Billiard("play --json").status, 2);
  EXPECT_EQ(Billiard("play --rack nine-ball --seed -1 --json").status, 2);
  // A ball off the table is bad input (2), as in simulate, plot and plan-pot.
  const std::string off = ::testing::TempDir() + "/off_table.json";
  std::ofstream(off) << R"({"table": "pool-9ft", "params": "pool", "balls": [
      {"id": 0, "state": [0.6, 0.6, 0, 0, 0, 0, 0]}, {"id": 1, "state": [3.0, 0.6, 0, 0, 0, 0, 0]}]})";
  EXPECT_EQ(Billiard("choose-shot --scene " + off + " --json").status, 2);
  EXPECT_EQ(Billiard("play --scene " + off + " --json").status, 2);
}

TEST(BilliardPlay, PlaysARackAndSumsItUp) {
  const std::string open = ::testing::TempDir() + "/open_table.json";
  std::ofstream(open) << R"({"table": "pool-9ft", "params": "pool", "balls": [
      {"id": 0, "state": [0.6, 0.6, 0, 0, 0, 0, 0]}, {"id": 1, "state": [1.9, 0.9, 0, 0, 0, 0, 0]},
      {"id": 2, "state": [0.8, 0.35, 0, 0, 0, 0, 0]}]})";
  const std::string args = "play --scene " + open + " --rules nine-ball" + kFew + " --shot-limit 6 --json";
  const CommandResult r = Billiard(args);
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json j = OneObject(r, args);
  const nlohmann::json& s = j["summary"];
  for (const char* key : {"shots", "attempts", "pots", "pots_per_attempt", "fouls", "visits",
                          "balls_potted", "cleared", "run_out", "median_decision_us"}) {
    EXPECT_TRUE(s.contains(key)) << key;
  }
  EXPECT_EQ(s["shots"], j["shots"].size());
  EXPECT_LE(s["pots"].get<int>(), s["attempts"].get<int>());
  // Nine-ball: the first call is the 1, the lowest.
  EXPECT_EQ(j["shots"][0]["ball"], 1);
  if (s["cleared"]) EXPECT_TRUE(j["balls_left"] == nlohmann::json::array({0}) || j["balls_left"].empty());
}

// Seeds 1, 2, 5 and 7 once stopped mid-rack (a ball left hanging in a pocket's jaws made a scene
// no player could be asked about): every rack now ends cleared or at the shot limit, each shot
// recorded with its status, and the summary says how it ended.
TEST(BilliardPlay, EveryRackEndsClearedOrAtTheShotLimit) {
  for (const char* seed : {"1", "2", "5", "7"}) {
    const std::string args = std::string("play --rack nine-ball --rules nine-ball --json --seed ") + seed;
    const CommandResult r = Billiard(args);
    ASSERT_EQ(r.status, 0) << args << ": " << r.out;
    const nlohmann::json j = OneObject(r, args);
    const nlohmann::json& s = j["summary"];
    EXPECT_TRUE(s["end"] == "cleared" || s["end"] == "shot_limit") << args << ": " << s.dump();
    EXPECT_EQ(s["cleared"], s["end"] == "cleared");
    EXPECT_EQ(s["shots"], j["shots"].size());
    for (const nlohmann::json& shot : j["shots"]) {
      EXPECT_FALSE(shot["status"].get<std::string>().empty()) << shot.dump();
    }
  }
}

}  // namespace
}  // namespace billiard::testing
