// The balls of a table state as a scene at rest: the struck ball id 0, the others as asked, by
// id, the message ids kept; a moving ball refused.
#include "planner/node/scene_at_rest.h"

#include <gtest/gtest.h>

#include <string>
#include <unordered_map>

#include "planner/node/testing/node_harness.h"
#include "sim/physics/ball_state.h"

namespace billiard::planner_node::testing {
namespace {

TEST(SceneAtRest, TheStruckBallIsZeroTheOthersAsAskedSortedAndStill) {
  table_state_t t{};
  t.balls = {Ball(12, 1.0, 0.5, 0.01, 0.0), Ball(7, 0.5, 0.6), Ball(30, 2.0, 1.0)};
  std::unordered_map<int, int32_t> message_id;
  std::string moving;
  const auto scene = SceneAtRest(
      t, 0.05, 7, [](int32_t id) { return 100 - id; }, &message_id, &moving);
  ASSERT_TRUE(scene) << moving;
  ASSERT_EQ(scene->size(), 3u);
  EXPECT_EQ((*scene)[0].id, 0);
  EXPECT_EQ((*scene)[1].id, 70);
  EXPECT_EQ((*scene)[2].id, 88);
  EXPECT_EQ(message_id, (std::unordered_map<int, int32_t>{{0, 7}, {70, 30}, {88, 12}}));
  EXPECT_EQ((*scene)[0].state, physics::MakeBallState(0.5, 0.6, 0, 0, 0, 0, 0));
  EXPECT_EQ((*scene)[2].state, physics::MakeBallState(1.0, 0.5, 0, 0, 0, 0, 0))
      << "a ball below the speed limit is at rest";
}

TEST(SceneAtRest, ABallFasterThanTheLimitIsNoSceneYet) {
  table_state_t t{};
  t.balls = {Ball(1, 0.5, 0.5), Ball(4, 1.0, 0.5, 0.3, 0.4)};
  std::unordered_map<int, int32_t> message_id;
  std::string moving;
  EXPECT_FALSE(SceneAtRest(
      t, 0.05, 1, [](int32_t id) { return id; }, &message_id, &moving));
  EXPECT_NE(moving.find("ball 4 is moving (0.5 m/s"), std::string::npos) << moving;
}

}  // namespace
}  // namespace billiard::planner_node::testing
