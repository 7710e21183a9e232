// Scenes that chain, as a user runs them: `simulate --scene-out` (the table at the end) read by
// `plan-pot --scene`, `choose-shot --scene --scene-out` (the table after the chosen stroke) read by
// `simulate --scene`. Each written scene is checked against an independent run: the balls
// `simulate --scene --json` leaves on the table, to the bit. And the text a player reads: the
// stroke in degrees, mm and m/s, no exponent and no "-0".
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "tests/support/billiard_command.h"

namespace billiard::testing {
namespace {

const std::string kLayout = std::string(PROJECT_SOURCE_DIR) + "/tests/data/nine_ball_layout.json";

std::string Temp(const std::string& name) { return ::testing::TempDir() + "/chain_" + name; }

nlohmann::json ReadJson(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return nlohmann::json::parse(text.str(), nullptr, false);
}

nlohmann::json JsonOf(const std::string& args) {
  const CommandResult r = Billiard(args);
  EXPECT_EQ(r.status, 0) << args << ": " << r.out;
  return OneObject(r, args);
}

// The balls a `simulate --scene --json` result leaves on the table, as a scene lists them.
nlohmann::json BallsLeft(const nlohmann::json& result) {
  nlohmann::json left = nlohmann::json::array();
  for (const nlohmann::json& b : result["balls"]) {
    if (b["pocketed"].is_null()) left.push_back({{"id", b["id"]}, {"state", b["state"]}});
  }
  return left;
}

// A pure scene: the keys every --scene reads, and no other.
void ExpectPureScene(const nlohmann::json& scene, const std::string& what) {
  ASSERT_TRUE(scene.is_object()) << what;
  EXPECT_EQ(scene.size(), 3u) << what << ": " << scene.dump();
  for (const char* key : {"table", "params", "balls"}) EXPECT_TRUE(scene.contains(key)) << what << ": " << key;
}

// The cue ball of `scene` struck with `cue` (a stroke as --json prints it): the scene that
// `simulate --scene` plays the stroke from. A planned stroke's "clearance" (what the planner
// found of the robot's cue) is no part of the stroke a scene holds.
nlohmann::json Struck(nlohmann::json scene, nlohmann::json cue) {
  cue.erase("clearance");
  for (nlohmann::json& b : scene["balls"]) {
    if (b["id"] == 0) b["cue"] = cue;
  }
  return scene;
}

TEST(BilliardSceneChain, EachScenesOutputIsTheNextOnesScene) {
  // 1. The layout broken up by a firm stroke; the table at the end written as a scene.
  const std::string end = Temp("end.json");
  const nlohmann::json broken = JsonOf("simulate --scene " + kLayout + " --cue 3.0,0.4,0,0,0 --json --scene-out " + end);
  ASSERT_TRUE(broken["at_rest"]);
  const nlohmann::json end_scene = ReadJson(end);
  ExpectPureScene(end_scene, end);
  EXPECT_EQ(end_scene["balls"], BallsLeft(broken));
  EXPECT_EQ(end_scene["table"], "pool-9ft");
  EXPECT_EQ(end_scene["params"], "pool");

  // 2. plan-pot reads it: a plan or a refusal, never bad input.
  const CommandResult planned = Billiard("plan-pot --scene " + end + " --ball " +
                                         end_scene["balls"].back()["id"].dump() + " --pocket upper_right --json");
  EXPECT_TRUE(planned.status == 0 || planned.status == 3) << planned.out;

  // 3. choose-shot reads it and writes the table after its stroke, played as planned ...
  const std::string next = Temp("next.json");
  const nlohmann::json chosen = JsonOf("choose-shot --scene " + end + " --rules nine-ball --samples 16 --json --scene-out " + next);
  ASSERT_EQ(chosen["status"], "ok");
  const nlohmann::json next_scene = ReadJson(next);
  ExpectPureScene(next_scene, next);
  // ... which is what simulate --scene makes of the stroke played (the chosen pot's, or the
  // safety's where it plays safe) from the same table.
  const bool safe = chosen["plays_safe"].get<bool>();
  const nlohmann::json& played = safe ? chosen["safety"]["stroke"] : chosen["choice"]["cue"];
  const std::string struck = Temp("struck.json");
  std::ofstream(struck) << Struck(end_scene, played).dump();
  const nlohmann::json replayed = JsonOf("simulate --scene " + struck + " --json");
  EXPECT_EQ(next_scene["balls"], BallsLeft(replayed));
  // The called ball went down (a pot the choice rated at p >= 0.5 is played as planned).
  if (!safe && chosen["choice"]["success_probability"].get<double>() >= 0.5) {
    for (const nlohmann::json& b : next_scene["balls"]) EXPECT_NE(b["id"], chosen["choice"]["ball"]);
  }

  // 4. simulate reads the next table: every ball at rest, nothing happens.
  const nlohmann::json still = JsonOf("simulate --scene " + next + " --json");
  EXPECT_TRUE(still["at_rest"]);
  EXPECT_EQ(BallsLeft(still), next_scene["balls"]);
}

TEST(BilliardSceneChain, ASimulationsResultIsPointedToTheSceneOut) {
  const std::string result = Temp("result.json");
  std::ofstream(result) << Billiard("simulate --scene " + kLayout + " --json").out;
  const CommandResult r = Billiard("plan-pot --scene " + result + " --ball 1 --pocket upper_right", true);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("--scene-out"), std::string::npos) << r.out;
  EXPECT_EQ(Billiard("simulate --state 0,0,0,1,0,0,0 --t-end 1 --scene-out " + Temp("x.json")).status, 2);
}

// The text a player reads: the stroke in m/s, degrees and mm, plain numbers, once.
void ExpectReadableStroke(const std::string& args) {
  const CommandResult r = Billiard(args, true);
  ASSERT_EQ(r.status, 0) << args << ": " << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(cue +speed [0-9.]+ m/s, heading -?[0-9.]+ deg, tip )")))
      << args << ": " << r.out;
  EXPECT_EQ(r.out.find(" rad,"), std::string::npos) << r.out;
  EXPECT_FALSE(std::regex_search(r.out, std::regex(R"([0-9]e-[0-9])"))) << args << ": " << r.out;
  EXPECT_FALSE(std::regex_search(r.out, std::regex(R"(-0(\.0+)?(?![0-9.]))"))) << args << ": " << r.out;
}

TEST(BilliardSceneChain, TextOutputNamesTheStrokeInAPlayersUnits) {
  ExpectReadableStroke("plan --from 0.5,0.5 --to 1.5,0.8 --final-speed 0.3 --spin stun");
  ExpectReadableStroke("plan-pot --scene " + kLayout + " --ball 1 --pocket lower_right");
  ExpectReadableStroke("choose-shot --scene " + kLayout + " --rules nine-ball --samples 16");
  // A refusal is said once, as one line.
  const CommandResult refused = Billiard(
      "plan-pot --scene " + std::string(PROJECT_SOURCE_DIR) + "/docs/pictures/pot_scene.json --ball 1 "
      "--pocket upper_right --kind curve", true);
  EXPECT_EQ(refused.status, 3);
  EXPECT_EQ(std::count(refused.out.begin(), refused.out.end(), '\n'), 1) << refused.out;
  const std::string clause = "the cue ball meets ball 2 before ball 1";
  const std::size_t first = refused.out.find(clause);
  EXPECT_NE(first, std::string::npos) << refused.out;
  EXPECT_EQ(refused.out.find(clause, first + 1), std::string::npos) << refused.out;
}

}  // namespace
}  // namespace billiard::testing
