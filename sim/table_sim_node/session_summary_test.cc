#include "sim/table_sim_node/session_summary.h"

#include <gtest/gtest.h>

#include <cmath>

namespace billiard::table_sim_node {
namespace {

ShotResult Missed(double miss_m) {
  ShotResult s;
  s.miss_m = miss_m;
  s.status = "ok";
  return s;
}

// The misses' median (the middle pair's mean for an even count), largest, mean and spread (the
// population's standard deviation); the counters as the node reported them.
TEST(SessionSummary, TheMissesStatisticsAndTheCounters) {
  node_status_t health{};
  health.num_counters = 1;
  health.counter_names = {"resent"};
  health.counter_values = {3};
  health.received = 40;
  health.dropped = 2;
  std::vector<ShotResult> shots = {Missed(0.3), Missed(0.1), Missed(0.2), Missed(0.4)};
  shots[1].status = "unreachable";
  shots[1].reason = "behind a ball";
  const nlohmann::json even = SessionSummary(shots, health, 12.5);
  EXPECT_DOUBLE_EQ(even["median_miss_m"].get<double>(), 0.25);
  EXPECT_DOUBLE_EQ(even["max_miss_m"].get<double>(), 0.4);
  EXPECT_DOUBLE_EQ(even["mean_miss_m"].get<double>(), 0.25);
  EXPECT_NEAR(even["stddev_miss_m"].get<double>(), std::sqrt(0.0125), 1e-12);
  EXPECT_EQ(even["counters"]["resent"], 3);
  EXPECT_EQ(even["received"], 40);
  EXPECT_EQ(even["wall_s"], 12.5);
  ASSERT_EQ(even["shots"].size(), 4u);
  EXPECT_FALSE(even["shots"][0].contains("reason"));
  EXPECT_EQ(even["shots"][1]["reason"], "behind a ball");

  shots.pop_back();
  EXPECT_DOUBLE_EQ(SessionSummary(shots, health, 1.0)["median_miss_m"].get<double>(), 0.2);
  EXPECT_FALSE(SessionSummary({}, health, 1.0).contains("median_miss_m"));
}

GameShot Decision(double decision_ms, double rms_mm) {
  GameShot s;
  s.status = "ok";
  s.decision_ms = decision_ms;
  s.position_rms_mm = rms_mm;
  s.position_max_mm = 2.0 * rms_mm;
  return s;
}

// Two racks: one cleared in a single visit (a run-out) after its break, one with a foul. The
// totals: attempts are the called shots, pots the called balls that dropped legally, balls per
// visit the balls dropped on legal shots; the decisions leave out the break and the refusals,
// their median the upper middle.
TEST(GameSummary, TheRacksTotalsAndTheDecisions) {
  GameResult run_out;
  run_out.seed = 1;
  run_out.cleared = true;
  run_out.visits = 1;
  GameShot brk = Decision(90.0, 1.0);
  brk.break_shot = true;
  brk.potted = {3};
  GameShot nine = Decision(20.0, 2.0);
  nine.called = 9;
  nine.potted = {9};
  nine.called_potted = true;
  nine.first_contact = 9;
  run_out.shots = {brk, nine};

  GameResult fouled;
  fouled.seed = 2;
  fouled.visits = 3;
  GameShot foul = Decision(40.0, 3.0);
  foul.called = 2;
  foul.potted = {2, 5};
  foul.foul = true;
  foul.foul_reason = "scratch";
  GameShot miss = Decision(30.0, 4.0);
  miss.called = 4;
  miss.misidentified = 1;
  GameShot refused = Decision(10.0, 5.0);
  refused.status = "busy";
  fouled.shots = {foul, miss, refused};

  const nlohmann::json j = GameSummary({run_out, fouled}, "nine-ball");
  EXPECT_EQ(j["kind"], "nine-ball");
  ASSERT_EQ(j["racks"].size(), 2u);
  EXPECT_EQ(j["racks"][0]["run_out"], true);
  EXPECT_EQ(j["racks"][0]["balls_potted"], 2);
  EXPECT_EQ(j["racks"][1]["attempts"], 2);
  EXPECT_EQ(j["racks"][1]["fouls"], 1);
  EXPECT_EQ(j["racks"][1]["balls_potted"], 0);
  EXPECT_EQ(j["racks"][1]["shots"][0]["foul_reason"], "scratch");
  EXPECT_TRUE(j["racks"][1]["shots"][1]["first_contact"].is_null());
  EXPECT_EQ(j["racks"][0]["shots"][1]["called"]["ball"], 9);

  const nlohmann::json& s = j["summary"];
  EXPECT_EQ(s["racks"], 2);
  EXPECT_EQ(s["cleared"], 1);
  EXPECT_EQ(s["run_outs"], 1);
  EXPECT_EQ(s["shots"], 5);
  EXPECT_EQ(s["attempts"], 3);
  EXPECT_EQ(s["pots"], 1);
  EXPECT_DOUBLE_EQ(s["pots_per_attempt"].get<double>(), 1.0 / 3.0);
  EXPECT_EQ(s["fouls"], 1);
  EXPECT_EQ(s["visits"], 4);
  EXPECT_DOUBLE_EQ(s["balls_per_visit"].get<double>(), 2.0 / 4.0);
  EXPECT_EQ(s["decisions"], 3);  // 20, 40 and 30 ms
  EXPECT_EQ(s["median_decision_ms"], 30.0);
  EXPECT_EQ(s["max_decision_ms"], 40.0);
  EXPECT_EQ(s["median_position_rms_mm"], 3.0);  // of 2, 3 and 4 mm
  EXPECT_EQ(s["max_position_error_mm"], 8.0);
  EXPECT_EQ(s["misidentified_ball_decisions"], 1);
}

// A match of two racks: A breaks the first and runs it out (a break-and-run), B breaks the
// second, fouls, and A plays a safety, then the shot limit. Each player's tally is its own shots';
// the win rate's interval is Wilson's, whose bounds at 0 and n of n are closed forms:
// [0, z^2 / (n + z^2)] and [n / (n + z^2), 1].
TEST(GameSummary, AMatchTalliesEachPlayerAsBilliardMatchDoes) {
  GameResult first;
  first.cleared = true;
  first.winner = 0;
  first.reason = "9 potted legally";
  first.break_and_run = true;
  GameShot brk = Decision(0.0, 1.0);
  brk.break_shot = true;
  brk.potted = {3};
  GameShot nine = Decision(20.0, 1.0);
  nine.called = 9;
  nine.called_potted = true;
  first.shots = {brk, nine};

  GameResult second;
  second.breaker = 1;
  second.reason = "shot limit";
  GameShot dry = brk;
  dry.player = 1;
  dry.potted.clear();
  GameShot foul = Decision(30.0, 1.0);
  foul.player = 1;
  foul.called = 1;
  foul.foul = true;
  GameShot safety = Decision(40.0, 1.0);
  safety.safety = true;
  second.shots = {dry, foul, safety};

  const nlohmann::json j = GameSummary({first, second}, "nine-ball", {"ours", "easiest-looking"});
  EXPECT_EQ(j["racks"][0]["breaker"], "ours");
  EXPECT_EQ(j["racks"][0]["winner"], "ours");
  EXPECT_TRUE(j["racks"][1]["winner"].is_null());
  EXPECT_EQ(j["racks"][1]["reason"], "shot limit");
  EXPECT_EQ(j["racks"][1]["shots"][1]["player"], "easiest-looking");
  EXPECT_EQ(j["racks"][1]["shots"][2]["safety"], true);
  const nlohmann::json tallies[2] = {
      {{"name", "ours"}, {"racks_won", 1}, {"win_rate", 0.5}, {"break_and_runs", 1},
       {"attempts", 1}, {"pots", 1}, {"safeties", 1}, {"fouls", 0}},
      {{"name", "easiest-looking"}, {"racks_won", 0}, {"win_rate", 0.0}, {"break_and_runs", 0},
       {"attempts", 1}, {"pots", 0}, {"safeties", 0}, {"fouls", 1}}};
  for (int k = 0; k < 2; ++k) {
    for (const auto& [key, value] : tallies[k].items()) {
      EXPECT_EQ(j["players"][k][key], value) << k << " " << key;
    }
  }
  const nlohmann::json& b = j["players"][1];
  const double z2 = 1.959963984540054 * 1.959963984540054;
  EXPECT_EQ(b["interval95"][0], 0.0);
  EXPECT_NEAR(b["interval95"][1].get<double>(), z2 / (2 + z2), 1e-12);
  const nlohmann::json itself = GameSummary({first}, "eight-ball", {"ours", "ours"});
  EXPECT_EQ(itself["players"][1]["name"], "ours (B)");
  EXPECT_EQ(itself["racks"][0]["winner"], "ours (A)");
  // Alone (no players), a game's summary has none of this.
  EXPECT_FALSE(GameSummary({first}, "nine-ball").contains("players"));
  EXPECT_FALSE(GameSummary({first}, "nine-ball")["racks"][0].contains("breaker"));
}

// Per ball, the RMS error over its tracked frames; over all balls, the RMS over every frame,
// not the mean of the balls' RMS.
TEST(DrawnNoiseJson, InIdentifyNoisesUnits) {
  const nlohmann::json j = DrawnNoiseJson({60, 0.025, 0.25 * M_PI / 180.0, 0.8e-3});
  EXPECT_EQ(j["strokes"], 60);
  EXPECT_DOUBLE_EQ(j["speed_fraction"], 0.025);
  EXPECT_DOUBLE_EQ(j["heading_deg"], 0.25);
  EXPECT_DOUBLE_EQ(j["tip_mm"], 0.8);
}

TEST(SceneSummary, TheTrackingErrorOverEveryFrame) {
  SceneResult scene;
  scene.events = 7;
  scene.final_balls = {{0, physics::BallState::Zero()}, {5, physics::BallState::Zero()}};
  scene.pockets = {"", "lower_left"};
  BallTracking a, b, c;
  a.id = 0;
  a.frames = 4;
  a.sum_squared_error = 4 * 1e-6;  // 1 mm in each frame
  a.max_error = 1e-3;
  b.id = 5;
  b.frames = 1;
  b.sum_squared_error = 16e-6;  // 4 mm
  b.max_error = 4e-3;
  b.lost = 2;
  c.id = 7;  // never tracked
  c.lost = 5;
  scene.tracking.balls = {a, b, c};
  scene.tracking.swaps = 1;
  const nlohmann::json j = SceneSummary(scene, "break");
  EXPECT_EQ(j["name"], "break");
  EXPECT_EQ(j["events"], 7);
  EXPECT_TRUE(j["balls"][0]["pocketed"].is_null());
  EXPECT_EQ(j["balls"][1]["pocketed"], "lower_left");
  EXPECT_NEAR(j["tracking"]["balls"][0]["rms_error_mm"].get<double>(), 1.0, 1e-12);
  EXPECT_FALSE(j["tracking"]["balls"][2].contains("rms_error_mm"));
  EXPECT_NEAR(j["tracking"]["rms_error_mm"].get<double>(), std::sqrt(20.0 / 5.0), 1e-12);
  EXPECT_NEAR(j["tracking"]["max_error_mm"].get<double>(), 4.0, 1e-12);
  EXPECT_EQ(j["tracking"]["lost_ball_frames"], 7);
  EXPECT_EQ(j["tracking"]["swaps"], 1);
  EXPECT_FALSE(j.contains("pots"));
}

}  // namespace
}  // namespace billiard::table_sim_node
