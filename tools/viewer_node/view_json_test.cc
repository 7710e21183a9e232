#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "lcmtypes/billiard/ball_state_t.hpp"
#include "lcmtypes/billiard/shot_request_t.hpp"
#include "sim/params/table_specs.h"
#include "tools/viewer_node/viewer_node.h"

namespace billiard::viewer {
namespace {

// The estimator's classes are the numbers a player reads; its track ids are not.
TEST(BallNumber, IsTheClassNotTheTrack) {
  EXPECT_EQ(BallNumber(ball_state_t::CLASS_CUE), 0);
  EXPECT_EQ(BallNumber(9), 9);
  EXPECT_EQ(BallNumber(15), 15);
  EXPECT_EQ(BallNumber(ball_state_t::CLASS_UNKNOWN), -1);
  EXPECT_EQ(BallNumber(ball_state_t::CLASS_RED), -1);
}

// Pool's set: the 1 a yellow solid, the 9 a white ball with a yellow band, the 8 black.
TEST(LookJson, StripesAreStripes) {
  const nlohmann::json one = LookJson(1), nine = LookJson(9), eight = LookJson(8);
  EXPECT_TRUE(one["band"].is_null());
  EXPECT_EQ(nine["body"], "#ffffff");
  EXPECT_EQ(nine["band"], one["body"]);
  EXPECT_TRUE(nine["dashed"].get<bool>());
  EXPECT_FALSE(one["dashed"].get<bool>());
  EXPECT_EQ(eight["body"], "#0d0d0d");
  EXPECT_EQ(LookJson(ball_state_t::CLASS_CUE)["body"], "#ffffff");
  // A ball not told is not the cue ball.
  EXPECT_NE(LookJson(ball_state_t::CLASS_UNKNOWN)["body"], LookJson(ball_state_t::CLASS_CUE)["body"]);
}

// Snooker's balls by their colours: seven looks apart from each other, from the cue ball's and
// from a ball not told; plain, their paths solid; named as a snooker player names them, and no
// number drawn on them.
TEST(LookJson, SnookerBallsInTheirColours) {
  std::set<std::string> bodies = {LookJson(ball_state_t::CLASS_CUE)["body"],
                                  LookJson(ball_state_t::CLASS_UNKNOWN)["body"]};
  const std::string names[] = {"red", "yellow", "green", "brown", "blue", "pink", "black"};
  for (int c = ball_state_t::CLASS_RED; c <= ball_state_t::CLASS_BLACK; ++c) {
    const nlohmann::json look = LookJson(c);
    EXPECT_TRUE(bodies.insert(look["body"].get<std::string>()).second) << c << " " << look;
    EXPECT_TRUE(look["band"].is_null());
    EXPECT_FALSE(look["dashed"].get<bool>());
    EXPECT_EQ(look["path"], look["body"]);
    EXPECT_EQ(BallName(c), names[c - ball_state_t::CLASS_RED]);
    EXPECT_EQ(BallLabel(c), "");
  }
}

// Pool's balls carry their numbers; the cue ball none; a ball not told a "?".
TEST(BallLabel, NumbersOnPoolsBallsOnly) {
  EXPECT_EQ(BallLabel(9), "9");
  EXPECT_EQ(BallName(9), "9");
  EXPECT_EQ(BallLabel(ball_state_t::CLASS_CUE), "");
  EXPECT_EQ(BallName(ball_state_t::CLASS_CUE), "cue ball");
  EXPECT_EQ(BallLabel(ball_state_t::CLASS_UNKNOWN), "?");
}

// The WPA 9 ft table: 6 pockets, the corners' at the playing surface's corners (within a mouth),
// the middles' at half the length.
TEST(TableJson, SixPocketsWhereTheTableHasThem) {
  const table::TableGeometry pool = table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  const nlohmann::json j = TableJson(pool);
  ASSERT_EQ(j["pockets"].size(), 6u);
  const auto centre = [&](int k) {
    return Eigen::Vector2d(j["pockets"][k]["centre"][0], j["pockets"][k]["centre"][1]);
  };
  EXPECT_EQ(j["pockets"][0]["name"], "lower_left");
  EXPECT_LT(centre(0).norm(), 0.12);
  EXPECT_NEAR(centre(1).x(), 0.5 * pool.length, 1e-9);
  EXPECT_LT((centre(3) - Eigen::Vector2d(pool.length, pool.width)).norm(), 0.12);
  for (const auto& p : j["pockets"]) EXPECT_GT(p["radius"].get<double>(), 0.0286);  // a ball drops
  EXPECT_EQ(j["cushions"].size(), pool.lines.size());
  EXPECT_GE(j["outline"].size(), 6u);
}

cue_command_t Choice() {
  cue_command_t m{};
  m.mode = shot_request_t::MODE_CHOOSE;
  m.status = cue_command_t::STATUS_OK;
  m.object_ball_id = 4;  // the estimator's track 4
  m.pocket = "upper_middle";
  m.cue_speed = 2.5;
  m.heading = M_PI / 2;
  m.tip_side = -1.73472e-18;  // a planner's centre ball
  m.tip_height = 0.012;
  m.success_probability = 0.8;
  m.probability_stderr = 0.03;
  m.num_ball_paths = 1;
  m.ball_paths.push_back({4, 2, {{0.1, 0.2}, {0.3, 0.4}}});
  return m;
}

// The stroke in a player's units, the balls by their numbers.
TEST(PlanJson, StrokeInDegreesMillimetresAndNumbers) {
  const nlohmann::json j = PlanJson(Choice(), {{0, ball_state_t::CLASS_CUE}, {4, 9}});
  EXPECT_EQ(j["object_ball"], 9);
  EXPECT_EQ(j["object_name"], "9");
  EXPECT_DOUBLE_EQ(j["heading_deg"].get<double>(), 90.0);
  EXPECT_EQ(j["tip_side_mm"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(j["tip_height_mm"].get<double>(), 12.0);
  EXPECT_DOUBLE_EQ(j["probability"].get<double>(), 0.8);
  EXPECT_EQ(j["ball_paths"][0]["number"], 9);
  EXPECT_EQ(j["ball_paths"][0]["points"].size(), 2u);
}

// A snooker pot named by its colour, its paths in that colour.
TEST(PlanJson, SnookerBallByItsColour) {
  const nlohmann::json j = PlanJson(Choice(), {{4, ball_state_t::CLASS_PINK}});
  EXPECT_EQ(j["object_ball"], -1);
  EXPECT_EQ(j["object_name"], "pink");
  EXPECT_EQ(j["ball_paths"][0]["look"], LookJson(ball_state_t::CLASS_PINK));
}

// A ball the estimate has not named is -1; a pot the planner was told (not chose) has no chance.
TEST(PlanJson, UnnamedBallAndToldPot) {
  cue_command_t m = Choice();
  m.mode = shot_request_t::MODE_POT;
  const nlohmann::json j = PlanJson(m, {});
  EXPECT_EQ(j["object_ball"], -1);
  EXPECT_TRUE(j["probability"].is_null());
}

}  // namespace
}  // namespace billiard::viewer
