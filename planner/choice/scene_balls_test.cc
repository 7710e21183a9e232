#include "planner/choice/scene_balls.h"

#include <gtest/gtest.h>

namespace billiard::choice {
namespace {


TEST(SceneBallsTest, FindsABallByItsIdAndReadsWhereItLies) {
  const std::vector<table::SceneBall> balls = {table::AtRest(0, 0.5, 0.4), table::AtRest(3, 1.2, 0.9)};
  ASSERT_NE(FindBall(balls, 3), nullptr);
  EXPECT_EQ(FindBall(balls, 3), &balls[1]);
  EXPECT_EQ(Position(*FindBall(balls, 3)), Eigen::Vector2d(1.2, 0.9));
  EXPECT_EQ(FindBall(balls, 9), nullptr);
}

// The cue ball placed: first, at rest where asked, the one it replaces gone, the others kept.
TEST(SceneBallsTest, PlacesTheCueBallFirst) {
  table::SceneBall moving = table::AtRest(0, 0.5, 0.4);
  moving.state[physics::kVx] = 1.0;
  const auto placed = WithCueBallAt({table::AtRest(2, 1, 1), moving, table::AtRest(5, 2, 0.5)}, {0.3, 0.6});
  ASSERT_EQ(placed.size(), 3u);
  EXPECT_EQ(placed[0].id, 0);
  EXPECT_EQ(Position(placed[0]), Eigen::Vector2d(0.3, 0.6));
  EXPECT_EQ(placed[0].state.tail<5>().norm(), 0.0);
  EXPECT_EQ(placed[1].id, 2);
  EXPECT_EQ(placed[2].id, 5);
  EXPECT_EQ(WithCueBallAt({table::AtRest(4, 1, 1)}, {0.3, 0.6}).front().id, 0);  // lifted or not
}

}  // namespace
}  // namespace billiard::choice
