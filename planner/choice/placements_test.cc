#include "planner/choice/placements.h"

#include <gtest/gtest.h>

#include "planner/choice/lookahead.h"
#include "planner/choice/scene_balls.h"
#include "planner/choice/testing/choice_test.h"

namespace billiard::choice {
namespace {

using PlacementsTest = testing::ChoiceTest;

// Every place is on the surface, clear of the object balls (the cue ball lifted), at most one
// per target and pocket, best first, and its estimate is EasyPotEstimate's from there for one
// target and pocket.
TEST_F(PlacementsTest, PlacesAreOnTheTableClearAndBestFirst) {
  const double r = params_.ball.radius;
  const std::vector<table::SceneBall> balls = {table::AtRest(0, 0.4, 0.9), table::AtRest(1, 1.6, 0.68),
                                               table::AtRest(2, 0.7, 0.4), table::AtRest(3, 2.1, 1.0)};
  ChoiceOptions options;
  const std::vector<Placement> places = CandidatePlacements(table_, r, balls, options);
  ASSERT_FALSE(places.empty());
  EXPECT_LE(places.size(), 3 * table_.pockets.size());
  std::vector<table::SceneBall> others(balls.begin() + 1, balls.end());
  for (std::size_t i = 0; i < places.size(); ++i) {
    EXPECT_TRUE(table_.OnSurface(places[i].place, r));
    for (const table::SceneBall& b : others) {
      EXPECT_GE((Position(b) - places[i].place).norm(), 2 * r);
    }
    EXPECT_GT(places[i].estimate, 0.0);
    if (i > 0) EXPECT_GE(places[i - 1].estimate, places[i].estimate);
    bool found = false;
    for (int ball : {1, 2, 3}) {
      for (const table::Pocket& p : table_.pockets) {
        found |= EasyPotEstimate(r, WithCueBallAt(others, places[i].place), ball, p,
                                 options.noise) == places[i].estimate;
      }
    }
    EXPECT_TRUE(found) << i;
  }
}

// A place lies behind its target as seen from the pocket: for the 1 (nine-ball: the only
// target) near a corner, the best place is on the far side of the 1 from that corner, a short
// straight pot.
TEST_F(PlacementsTest, TheCueBallGoesBehindTheTarget) {
  const Eigen::Vector2d corner = table_.PocketNamed("upper_right")->centre;
  const Eigen::Vector2d o = corner - 0.3 * Eigen::Vector2d(1, 1).normalized();
  ChoiceOptions options;
  options.rules = Rules::kNineBall;
  const std::vector<table::SceneBall> balls = {table::AtRest(1, o.x(), o.y()), table::AtRest(5, 0.5, 0.3)};
  const std::vector<Placement> places =
      CandidatePlacements(table_, params_.ball.radius, balls, options);
  ASSERT_FALSE(places.empty());
  EXPECT_GT((places.front().place - corner).norm(), (o - corner).norm());
  EXPECT_GT(places.front().estimate, 0.99);
}

}  // namespace
}  // namespace billiard::choice
