// The ball a request names: by id, or by class the one the estimator is surest of.
#include "planner/node/named_ball.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "lcmtypes/billiard/shot_request_t.hpp"
#include "planner/node/testing/node_harness.h"

namespace billiard::planner_node::testing {
namespace {

constexpr int32_t kByClass = shot_request_t::BALL_BY_CLASS;

class NamedBallTest : public ::testing::Test {
 protected:
  NamedBallTest() {
    table_.balls = {Classed(4, 0.5, 0.5, 2, 0.6f), Classed(1, 1.0, 0.5, 2, 0.8f),
                    Classed(6, 1.5, 0.5, 2, 0.8f), Classed(3, 2.0, 0.5, 7, 0.3f)};
    table_.num_balls = static_cast<int32_t>(table_.balls.size());
  }
  table_state_t table_{};
};

TEST_F(NamedBallTest, ByIdIsThatBallWhateverItsClass) {
  const std::vector<const ball_state_t*> balls = BallsOf(table_);
  ASSERT_EQ(balls.size(), 4u);
  EXPECT_EQ(Named(balls, 3, 0), balls[3]) << "a ball by id needs no confidence";
  EXPECT_EQ(Named(balls, 8, 2), nullptr);
}

TEST_F(NamedBallTest, ByClassIsTheSurestThenTheLowerIdInAnyOrder) {
  std::vector<const ball_state_t*> balls = BallsOf(table_);
  for (int turn = 0; turn < 2; ++turn) {
    const ball_state_t* two = Named(balls, kByClass, 2);
    ASSERT_NE(two, nullptr);
    EXPECT_EQ(two->ball_id, 1) << "0.8 over 0.6, and id 1 before id 6 at 0.8";
    std::reverse(balls.begin(), balls.end());
  }
}

TEST_F(NamedBallTest, ByClassNeedsTheConfidenceAsked) {
  const std::vector<const ball_state_t*> balls = BallsOf(table_);
  EXPECT_EQ(Named(balls, kByClass, 7), nullptr) << "0.3 is below kMinClassConfidence";
  const ball_state_t* faint = Named(balls, kByClass, 7, 0.0f);
  ASSERT_NE(faint, nullptr);
  EXPECT_EQ(faint->ball_id, 3);
  EXPECT_EQ(Named(balls, kByClass, 2, 0.9f), nullptr);
  EXPECT_EQ(Named(balls, kByClass, 5), nullptr) << "no ball of the class";
}

}  // namespace
}  // namespace billiard::planner_node::testing
