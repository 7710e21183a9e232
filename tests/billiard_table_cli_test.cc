// The table's commands as a user runs them: `billiard rack`, `billiard simulate --scene`,
// `billiard bench-scenes`; their JSON, their refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "tests/support/billiard_command.h"

namespace billiard::testing {
namespace {

std::string WriteFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

nlohmann::json Rack(const std::string& args) {
  const CommandResult r = Billiard("rack " + args);
  EXPECT_EQ(r.status, 0) << args;
  return OneObject(r, "rack " + args);
}

// The eight-ball rack of `seed` with its cue ball sent at `speed` m/s up the table.
std::string BreakScene(int seed, double speed) {
  nlohmann::json scene = Rack("eight-ball --seed " + std::to_string(seed));
  scene["balls"][0]["state"][2] = speed;
  return WriteFile("break_" + std::to_string(seed) + ".json", scene.dump());
}

TEST(BilliardRack, WritesEveryBallOfTheGameAtRestOnItsTable) {
  const nlohmann::json eight = Rack("eight-ball --seed 5");
  EXPECT_EQ(eight["table"], "pool-9ft");
  EXPECT_EQ(eight["params"], "pool");
  std::set<int> ids;
  for (const auto& b : eight["balls"]) {
    ids.insert(b["id"].get<int>());
    for (int k = 2; k < 7; ++k) EXPECT_EQ(b["state"][k].get<double>(), 0.0);
  }
  EXPECT_EQ(ids.size(), 16u);
  EXPECT_EQ(*ids.begin(), 0);
  EXPECT_EQ(*ids.rbegin(), 15);
  const nlohmann::json snooker = Rack("snooker");
  EXPECT_EQ(snooker["table"], "snooker-12ft");
  EXPECT_EQ(snooker["params"], "snooker");
  EXPECT_EQ(snooker["balls"].size(), 22u);
  const nlohmann::json carom = Rack("three-cushion");
  EXPECT_EQ(carom["table"], "carom-10ft");
  EXPECT_EQ(carom["balls"].size(), 3u);
  EXPECT_EQ(Rack("nine-ball --seed 2")["balls"].size(), 10u);
}

TEST(BilliardRack, TheSeedDecidesTheRackAndOnlyIt) {
  EXPECT_EQ(Rack("eight-ball --seed 7"), Rack("eight-ball --seed 7"));
  EXPECT_NE(Rack("eight-ball --seed 7"), Rack("eight-ball --seed 8"));
  const CommandResult bad = Billiard("rack straight-pool", true);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("straight-pool"), std::string::npos) << bad.out;
  // A negative seed is bad input, not a seed wrapped round to 2^64 - 1.
  const CommandResult negative = Billiard("rack nine-ball --seed -1", true);
  EXPECT_EQ(negative.status, 2);
  EXPECT_NE(negative.out.find("--seed"), std::string::npos) << negative.out;
}

TEST(BilliardSimulateScene, RunsABreakUntilEveryBallRestsAndReportsItsEvents) {
  const std::string scene = BreakScene(3, 7.0);
  const std::string args = "simulate --scene " + scene + " --json";
  const CommandResult r = Billiard(args);
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json j = OneObject(r, args);
  EXPECT_TRUE(j["at_rest"].get<bool>());
  EXPECT_EQ(j["table"], "pool-9ft");
  EXPECT_EQ(j["balls"].size(), 16u);
  EXPECT_GT(j["wall_us"].get<double>(), 0.0);
  std::set<std::string> types;
  double last = 0.0;
  for (const auto& e : j["events"]) {
    types.insert(e["type"].get<std::string>());
    EXPECT_GE(e["t"].get<double>(), last);  // in time order
    last = e["t"].get<double>();
  }
  EXPECT_TRUE(types.count("ball_ball"));
  EXPECT_TRUE(types.count("ball_cushion"));
  EXPECT_TRUE(types.count("transition"));
  EXPECT_EQ(j["t"].get<double>(), last);
  for (const auto& b : j["balls"]) {
    if (b["pocketed"].is_null()) {
      for (int k = 2; k < 7; ++k) EXPECT_EQ(b["state"][k].get<double>(), 0.0) << b;
    } else {
      EXPECT_TRUE(b["pocketed"].is_string());
    }
  }
  // Deterministic: the same scene, the same events, bit for bit.
  const nlohmann::json again = OneObject(Billiard(args), args);
  EXPECT_EQ(again["events"], j["events"]);
  EXPECT_EQ(again["balls"], j["balls"]);
}

TEST(BilliardSimulateScene, StopsAtTEndAndWritesEveryBallsTrajectory) {
  const std::string scene = BreakScene(4, 5.0);
  const std::string csv = ::testing::TempDir() + "/break_trajectory.csv";
  const std::string args =
      "simulate --scene " + scene + " --t-end 0.5 --sample-dt 0.01 --trajectory " + csv + " --json";
  const CommandResult r = Billiard(args);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(OneObject(r, args)["t"].get<double>(), 0.5);
  std::ifstream in(csv);
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header, "t,id,X,Y,vx,vy,wx,wy,wz");
  int rows = 0;
  while (std::getline(in, line)) ++rows;
  EXPECT_EQ(rows, 51 * 16);  // t = 0, 0.01, ..., 0.5 for each ball
}

TEST(BilliardSimulateScene, RefusesBadScenesWithTheReason) {
  const auto refusal = [](const std::string& scene, const std::string& extra = "") {
    const std::string path = WriteFile("bad_scene.json", scene);
    return Billiard("simulate --scene " + path + " " + extra + " --json", true);
  };
  const std::string ball0 = R"({"id":0,"state":[1.0,0.6,0,0,0,0,0]})";
  const std::string ball1 = R"({"id":1,"state":[1.01,0.6,0,0,0,0,0]})";
  const auto overlap =
      refusal(R"({"table":"pool-9ft","params":"pool","balls":[)" + ball0 + "," + ball1 + "]}");
  EXPECT_EQ(overlap.status, 2);
  EXPECT_NE(overlap.out.find("overlap"), std::string::npos) << overlap.out;
  const auto table = refusal(R"({"table":"pool-99ft","params":"pool","balls":[)" + ball0 + "]}");
  EXPECT_EQ(table.status, 2);
  EXPECT_NE(table.out.find("pool-99ft"), std::string::npos) << table.out;
  const auto off = refusal(R"({"table":"pool-9ft","params":"pool","balls":[{"id":2,"state":[)"
                           R"(3.0,0.6,0,0,0,0,0]}]})");
  EXPECT_EQ(off.status, 2);
  EXPECT_NE(off.out.find("ball 2"), std::string::npos) << off.out;
  // Over the lower-left pocket's mouth, short of its capture line: a still ball there would
  // never drop.
  const auto mouth = refusal(R"({"table":"pool-9ft","params":"pool","balls":[{"id":3,"state":[)"
                             R"(0.01,0.01,0,0,0,0,0]}]})");
  EXPECT_EQ(mouth.status, 2);
  EXPECT_NE(mouth.out.find("ball 3"), std::string::npos) << mouth.out;
  const auto range = refusal(R"({"table":"pool-9ft","params":"pool","balls":[{"id":0,"state":[)"
                             R"(1e400,0.6,0,0,0,0,0]}]})");
  EXPECT_EQ(range.status, 2);
  EXPECT_NE(range.out.find("1e400"), std::string::npos) << range.out;
  const auto key = refusal(R"({"table":"pool-9ft","params":"pool","balls":[],"bals":[]})");
  EXPECT_EQ(key.status, 2);
  EXPECT_NE(key.out.find("bals"), std::string::npos) << key.out;
  const auto model = refusal(R"({"table":"pool-9ft","params":"pool","balls":[)" + ball0 + "]}",
                             "--model integral");
  EXPECT_EQ(model.status, 2);
  EXPECT_NE(model.out.find("auto, closed-form, approx"), std::string::npos) << model.out;
  // One line each.
  for (const auto& r : {overlap, table, off, mouth, range, key, model}) {
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  }
  const CommandResult both = Billiard("simulate --scene x.json --state 0,0,0,0,0,0,0 --t-end 1");
  EXPECT_EQ(both.status, 2);
  // The scene names its parameter set; --params beside it is refused, known set or not.
  const std::string scene = WriteFile("one_ball.json", R"({"table":"pool-9ft","params":"pool","balls":[)" + ball0 + "]}");
  for (const char* set : {"nosuch", "paper"}) {
    const CommandResult params = Billiard("simulate --scene " + scene + " --params " + set, true);
    EXPECT_EQ(params.status, 2) << set;
    EXPECT_NE(params.out.find("--params"), std::string::npos) << params.out;
  }
}

TEST(BilliardSimulateScene, MovesBallsByTheFiveDofModelWhereAskedOrNeeded) {
  const std::string scene = BreakScene(5, 7.0);
  nlohmann::json by_model;
  for (const char* model : {"closed-form", "approx", "auto"}) {
    const std::string args =
        std::string("simulate --scene ") + scene + " --model " + model + " --json";
    const CommandResult r = Billiard(args);
    ASSERT_EQ(r.status, 0) << r.out;
    by_model[model] = OneObject(r, args);
    EXPECT_EQ(by_model[model]["model"], model);
    EXPECT_TRUE(by_model[model]["at_rest"].get<bool>()) << model;
  }
  EXPECT_EQ(by_model["auto"]["accuracy_m"], 5e-3);
  // The 5-DOF model's balls end elsewhere than the closed form's (rolling resistance while they
  // slide, side spin).
  const auto cue_apart = [&](const char* a, const char* b) {
    const auto& sa = by_model[a]["balls"][0]["state"];
    const auto& sb = by_model[b]["balls"][0]["state"];
    return std::hypot(sa[0].get<double>() - sb[0].get<double>(),
                      sa[1].get<double>() - sb[1].get<double>());
  };
  EXPECT_GT(cue_apart("closed-form", "approx"), 1e-3);
}

TEST(BilliardBenchScenes, ReportsTimesAndEventsPerBreakForEachModel) {
  const std::string args = "bench-scenes --breaks 3 --repeats 1";
  const CommandResult r = Billiard(args);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.is_array());
  ASSERT_EQ(j.size(), 3u);
  EXPECT_EQ(j[0]["cushion_model"], "mathavan-2010");
  EXPECT_EQ(j[1]["cushion_model"], "han-2005");
  EXPECT_EQ(j[2]["model"], "auto");
  for (const auto& run : j) {
    EXPECT_EQ(run["breaks"], 3);
    EXPECT_GT(run["median_events"].get<double>(), 10.0);
    EXPECT_GT(run["median_us"].get<double>(), 0.0);
  }
}

}  // namespace
}  // namespace billiard::testing
