#include "planner/choice/choice_result.h"

#include <gtest/gtest.h>

#include <cmath>

#include "planner/choice/testing/choice_test.h"
#include "sim/cue/clearance.h"
#include "sim/params/robots.h"

namespace billiard::choice {
namespace {

using ChoiceResultTest = testing::ChoiceTest;

TEST(ChoiceStatusTest, Names) {
  EXPECT_STREQ(ChoiceStatusName(ChoiceStatus::kOk), "ok");
  EXPECT_STREQ(ChoiceStatusName(ChoiceStatus::kInvalid), "invalid");
  EXPECT_STREQ(ChoiceStatusName(ChoiceStatus::kNoTarget), "no_target");
  EXPECT_STREQ(ChoiceStatusName(ChoiceStatus::kNoPlan), "no_plan");
}

TEST_F(ChoiceResultTest, RefusesWhatCannotBePlayed) {
  EXPECT_EQ(Unplayable(table_, params_, {table::AtRest(1, 1, 0.5)}, Rules::kAny)->status,
            ChoiceStatus::kInvalid);
  EXPECT_EQ(Unplayable(table_, params_, {table::AtRest(0, 1, 0.5)}, Rules::kAny)->status,
            ChoiceStatus::kNoTarget);
  table::SceneBall moving = table::AtRest(1, 1.5, 0.5);
  moving.state[physics::kVx] = 0.1;
  const auto refused = Unplayable(table_, params_, {table::AtRest(0, 1, 0.5), moving}, Rules::kAny);
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, ChoiceStatus::kInvalid);
  EXPECT_EQ(refused->reason, "ball 1 is moving: a choice starts at rest");
  const auto overlapping = Unplayable(table_, params_, {table::AtRest(0, 1, 0.5), table::AtRest(1, 1.01, 0.5)},
                                      Rules::kAny);
  ASSERT_TRUE(overlapping);
  EXPECT_EQ(overlapping->status, ChoiceStatus::kInvalid);
  EXPECT_FALSE(Unplayable(table_, params_, {table::AtRest(0, 1, 0.5), table::AtRest(1, 1.5, 0.5)}, Rules::kAny));
}

// Nothing plans: the fallback rolls the cue ball straight at the first legal target's centre
// (the lowest under nine-ball), and it is the stroke to play.
TEST_F(ChoiceResultTest, TheFallbackHitsTheFirstLegalTargetFullInTheFace) {
  const std::vector<table::SceneBall> balls = {table::AtRest(0, 1, 0.5), table::AtRest(4, 1.3, 0.9),
                                               table::AtRest(2, 0.6, 0.1)};
  ChoiceResult r;
  NoPlan(table_, params_.ball.radius, balls, Rules::kNineBall, std::nullopt, "why", &r);
  EXPECT_EQ(r.status, ChoiceStatus::kNoPlan);
  EXPECT_EQ(r.reason, "why");
  ASSERT_TRUE(r.fallback);
  EXPECT_DOUBLE_EQ(r.fallback->heading, std::atan2(0.1 - 0.5, 0.6 - 1.0));
  EXPECT_GT(r.fallback->speed, 0.0);
  EXPECT_EQ(r.stroke(), &*r.fallback);
}

// With a robot the fallback is raised as a pot is: off the rail the gantry's cue clears it at
// the elevation cue::ElevationFor finds; a robot that cannot raise its cue so far has none.
TEST_F(ChoiceResultTest, TheFallbackIsRaisedForTheRobotsCueOrThereIsNone) {
  const double r0 = params_.ball.radius;
  const std::vector<table::SceneBall> balls = {table::AtRest(0, 1, r0 + 1e-3), table::AtRest(1, 1, 0.9)};
  cue::Robot gantry = params::LoadRobot("gantry");
  ChoiceResult raised;
  NoPlan(table_, r0, balls, Rules::kAny, gantry, "why", &raised);
  ASSERT_TRUE(raised.fallback);
  EXPECT_GT(raised.fallback->elevation, 0.0);
  EXPECT_TRUE(cue::Clearance(table_, r0, balls, 0, *raised.fallback, gantry).clears);
  gantry.elevation.max = 5.0 * M_PI / 180;
  ChoiceResult none;
  NoPlan(table_, r0, balls, Rules::kAny, gantry, "why", &none);
  EXPECT_FALSE(none.fallback);
  EXPECT_NE(none.reason.find("cue_blocked"), std::string::npos) << none.reason;
}

TEST(ChoiceResultStrokeTest, TheChosenPotsStrokeElseNone) {
  ChoiceResult r;
  EXPECT_EQ(r.stroke(), nullptr);  // nothing to play
  r.fallback = physics::CueStroke{1.0, 0.5, 0, 0, 0};
  r.candidates.resize(2);
  r.candidates[0].plan.stroke.heading = 2.0;
  EXPECT_EQ(r.stroke(), &r.candidates[0].plan.stroke);
}

}  // namespace
}  // namespace billiard::choice
