#include "sim/cue/table_obstacles.h"

#include <gtest/gtest.h>

#include "sim/params/table_specs.h"

namespace billiard::cue {
namespace {

using Eigen::Vector3d;

// The cloth's top is the playing surface; each rail's top is the rail's height from its nose
// line out by its width; below them, inside.
TEST(TableObstaclesTest, TheClothAndTheRailsWhereTheTableSays) {
  const table::TableGeometry t = table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  const std::vector<TableObstacle> obstacles = TableObstacles(t);
  ASSERT_EQ(obstacles.size(), 5u);
  const double L = t.length, W = t.width, w = t.rail_width, h = t.rail_height;
  struct Expected {
    const char* name;
    Vector3d on_top;  // a point of the top face, inside its edges
    Vector3d beside;  // a point just outside the box, toward the playing surface or the floor
  };
  const Expected expected[] = {
      {"the cloth", {L / 2, W / 2, 0.0}, {L / 2, W / 2, 0.001}},
      {"the lower rail", {L / 2, -w / 2, h}, {L / 2, 0.001, h / 2}},
      {"the right rail", {L + w / 2, W / 2, h}, {L - 0.001, W / 2, h / 2}},
      {"the upper rail", {L / 2, W + w / 2, h}, {L / 2, W - 0.001, h / 2}},
      {"the left rail", {-w / 2, W / 2, h}, {0.001, W / 2, h / 2}},
  };
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    SCOPED_TRACE(obstacles[i].name);
    EXPECT_EQ(obstacles[i].name, expected[i].name);
    EXPECT_DOUBLE_EQ(SignedDistance(expected[i].on_top, obstacles[i].box), 0.0);
    EXPECT_NEAR(SignedDistance(expected[i].beside, obstacles[i].box), 0.001, 1e-15);
    EXPECT_LT(SignedDistance(expected[i].on_top - Vector3d(0, 0, 1.0), obstacles[i].box), 0.0)
        << "an obstacle reaches down without end";
  }
  // Beyond a rail's outer edge nothing: the floor is far below.
  for (const TableObstacle& o : obstacles) {
    EXPECT_GT(SignedDistance({L / 2, -w - 0.01, 0.0}, o.box), 0.0) << o.name;
  }
}

// A table written before rails were data: a rail of no width at the nose line, as high as the
// nose.
TEST(TableObstaclesTest, WithoutRailDataAWallAtTheNose) {
  table::TableSpec spec = params::LoadTableSpec(params::kDefaultTable);
  spec.rail.reset();
  const table::TableGeometry t = table::BuildTable(spec);
  const TableObstacle lower = TableObstacles(t)[1];
  EXPECT_DOUBLE_EQ(SignedDistance({1.0, 0.0, t.cushion_height}, lower.box), 0.0);
  EXPECT_DOUBLE_EQ(SignedDistance({1.0, -0.01, 0.0}, lower.box), 0.01);
  EXPECT_DOUBLE_EQ(SignedDistance({1.0, 0.0, t.cushion_height + 0.002}, lower.box), 0.002);
}

}  // namespace
}  // namespace billiard::cue
