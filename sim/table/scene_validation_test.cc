// A camera's scene made one the simulation accepts: overlaps pushed apart by halves, a ball in
// a rail moved onto the surface, a valid scene unchanged, beyond the tolerance refused.
#include "sim/table/scene_validation.h"

#include <gtest/gtest.h>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"

namespace billiard::table {
namespace {

// A camera's scene: touching balls measured overlapping, one a hair into the rail.
TEST(SettledScene, PushesOverlapsApartByHalvesAndBallsOntoTheSurface) {
  const physics::ModelParameters p = params::LoadParameters("pool");
  const TableGeometry t = BuildTable(params::LoadTableSpec(params::kDefaultTable));
  const double r = p.ball.radius;
  std::vector<SceneBall> balls = {
      {0, physics::MakeBallState(1.0, 0.6, 0.1, 0, 0, 0, 0)},
      {1, physics::MakeBallState(1.0 + 2 * r - 8e-4, 0.6, 0, 0, 0, 0, 0)},
      {2, physics::MakeBallState(1.8, r - 3e-4, 0, 0, 0, 0, 0)}};
  EXPECT_THROW(ValidateScene(t, r, balls), std::invalid_argument);
  const std::vector<SceneBall> settled = SettledScene(t, r, balls, 2e-3);
  EXPECT_NO_THROW(ValidateScene(t, r, settled));
  // Each of the pair moved by half the overlap along the line of centres; the middle stays.
  EXPECT_NEAR(settled[0].state.x(), 1.0 - 4e-4, 1e-8);
  EXPECT_NEAR(settled[1].state.x(), 1.0 + 2 * r - 4e-4, 1e-8);
  EXPECT_DOUBLE_EQ(settled[0].state.y(), 0.6);
  EXPECT_DOUBLE_EQ(settled[0].state[physics::kVx], 0.1);  // the motion kept
  // The ball in the rail is on the surface, moved by less than the tolerance.
  EXPECT_TRUE(t.OnSurface(settled[2].state.head<2>(), r));
  EXPECT_LT((settled[2].state.head<2>() - balls[2].state.head<2>()).norm(), 2e-3);
  // A scene already valid is unchanged, bit for bit.
  const std::vector<SceneBall> again = SettledScene(t, r, settled, 2e-3);
  for (std::size_t i = 0; i < again.size(); ++i) EXPECT_EQ(again[i].state, settled[i].state);
  // Beyond the tolerance it is refused as ValidateScene refuses it.
  balls[1].state.x() = 1.0 + 2 * r - 5e-3;
  EXPECT_THROW(SettledScene(t, r, balls, 2e-3), std::invalid_argument);
}

}  // namespace
}  // namespace billiard::table
