// The numbers a choice knows the balls of a table state by.
#include "planner/node/ball_numbers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "planner/node/testing/node_harness.h"

namespace billiard::planner_node::testing {
namespace {

// The numbers a choice knows the balls by, from the estimator's classes and the rack's one of
// each: the surer of two yellows is the 1, a faint 9 is still the 9, the other yellow takes the
// lowest number nobody claims, an unknown ball the next.
TEST(BallNumbers, AreTheClassesWithOneOfEachNumber) {
  table_state_t t{};
  t.balls = {Classed(10, 0.5, 0.5, ball_state_t::CLASS_CUE, 0.9f),
             Classed(11, 1.0, 0.5, 1, 0.6f),
             Classed(12, 1.5, 0.5, 1, 0.9f),
             Classed(13, 2.0, 0.5, 9, 0.2f),
             Classed(14, 2.0, 1.0, ball_state_t::CLASS_UNKNOWN, 0.0f),
             Classed(15, 0.5, 1.0, 2, 0.8f)};
  t.num_balls = static_cast<int32_t>(t.balls.size());
  const auto n = BallNumbers(t, 10);
  EXPECT_EQ(n.at(10), 0);
  EXPECT_EQ(n.at(12), 1);
  EXPECT_EQ(n.at(13), 9);
  EXPECT_EQ(n.at(15), 2);
  EXPECT_EQ(n.at(11), 3);
  EXPECT_EQ(n.at(14), 4);
}

// Seventeen balls without a class: every number once, 1 to 15 by their ids, then 16 and 17.
TEST(BallNumbers, AreEachOnceAndRunPastTheRackWhenTheBallsDo) {
  table_state_t t{};
  for (int32_t id = 40; id > 22; --id) t.balls.push_back(Ball(id, 0.1 * (id - 22), 0.5));
  t.num_balls = static_cast<int32_t>(t.balls.size());
  const auto n = BallNumbers(t, 40);
  ASSERT_EQ(n.size(), t.balls.size());
  std::set<int> numbers;
  for (const auto& [id, number] : n) numbers.insert(number);
  EXPECT_EQ(numbers.size(), n.size()) << "a number given twice";
  EXPECT_EQ(*numbers.begin(), 0);
  EXPECT_EQ(*numbers.rbegin(), 17);
  for (int32_t id = 23; id < 40; ++id) EXPECT_EQ(n.at(id), id - 22) << id;
}

TEST(BallNumbers, DoNotDependOnTheOrderOfTheTableStatesBalls) {
  table_state_t t{};
  t.balls = {Classed(7, 0.5, 0.5, ball_state_t::CLASS_CUE, 0.9f), Classed(3, 1.0, 0.5, 4, 0.7f),
             Classed(9, 1.5, 0.5, 4, 0.7f), Classed(2, 2.0, 0.5, 6, 0.3f),
             Classed(5, 2.0, 1.0, ball_state_t::CLASS_UNKNOWN, 0.0f)};
  t.num_balls = static_cast<int32_t>(t.balls.size());
  const auto forwards = BallNumbers(t, 7);
  std::reverse(t.balls.begin(), t.balls.end());
  EXPECT_EQ(BallNumbers(t, 7), forwards);
  EXPECT_EQ(forwards.at(3), 4) << "of two as sure, the lower id";
  EXPECT_EQ(forwards.at(2), 6) << "a faint 6 is still the 6";
}

}  // namespace
}  // namespace billiard::planner_node::testing
