#include "sim/shot_fit/shot_model.h"

#include <gtest/gtest.h>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/shot_fit/synthetic_shots.h"

namespace billiard::shot_fit {
namespace {

table::TableGeometry Carom() { return table::BuildTable(params::LoadTableSpec("carom-10ft")); }

Strike StrikeAt(double speed, double heading) {
  Strike s;
  s.stroke.speed = speed;
  s.stroke.heading = heading;
  s.time = 0.007;
  return s;
}

// The strike that made a shot tracked without noise follows it to the sample: every ball's
// error is zero; the same strike 1 % faster misses by millimetres.
TEST(ShotModel, TheStrikeThatMadeANoiselessShotLeavesNoError) {
  const table::TableGeometry table = Carom();
  const physics::ModelParameters p = params::LoadParameters("carom");
  Strike truth = StrikeAt(2.5, 0.4);
  truth.stroke.tip_side = 0.2 * p.ball.radius;
  const TrackedShot shot = SimulateTrackedShot(table, p, {{0.7, 0.4}, {2.0, 1.0}, {1.5, 0.3}}, 0,
                                               truth, 6.0, 0.02, 0.0, 0.0, 1);
  const ShotErrors errors = Errors(table, p, shot, truth);
  ASSERT_EQ(errors.rmse.size(), 3u);
  for (double rmse : errors.rmse) EXPECT_LT(rmse, 1e-12);
  EXPECT_LT(errors.rmse_all, 1e-12);

  Strike faster = truth;
  faster.stroke.speed *= 1.01;
  EXPECT_GT(Errors(table, p, shot, faster).rmse[0], 1e-3);
}

// Two balls the tracking saw overlapping move apart along their line, by half the overlap each
// (their midpoint kept), to a micrometre's clearance; a ball seen beyond the cushion's line
// comes back onto the playing surface; a ball clear of all stays where it was.
TEST(Placed, MovesOverlappingBallsApartSymmetricallyAndBallsOntoTheSurface) {
  const table::TableGeometry table = Carom();
  const double r = 0.03;
  const Eigen::Vector2d middle(1.0, 0.7), along(0.6, 0.8);
  const std::vector<Eigen::Vector2d> placed = Placed(
      table, r,
      {middle - 0.025 * along, middle + 0.025 * along, {table.length + 0.01, 0.2}, {2.0, 1.0}});
  const Eigen::Vector2d apart = placed[1] - placed[0];
  EXPECT_NEAR(apart.norm(), 2.0 * r + 1e-6, 1e-12);
  EXPECT_NEAR(apart.normalized().dot(along), 1.0, 1e-12);
  EXPECT_LT((0.5 * (placed[0] + placed[1]) - middle).norm(), 1e-12);
  EXPECT_EQ(placed[2], Eigen::Vector2d(table.length - r, 0.2));
  EXPECT_EQ(placed[3], Eigen::Vector2d(2.0, 1.0));
}

// The impacts name the piece of the cost: a strike a hair faster makes the same impacts, one
// that passes the object ball by meets the cushion first.
TEST(ImpactSequence, IsTheSameOnOnePieceOfTheCostAndDiffersAcrossPieces) {
  const table::TableGeometry table = Carom();
  const physics::ModelParameters p = params::LoadParameters("carom");
  TrackedShot shot;
  for (const Eigen::Vector2d& at : {Eigen::Vector2d(0.7, 0.71), Eigen::Vector2d(1.4, 0.71)})
    shot.balls.push_back({"", {0.0}, {at}});
  const ShotModel model(table, p, shot);
  const std::uint64_t hit = ImpactSequence(model.Run(StrikeAt(2.0, 0.0), 1.0));
  EXPECT_EQ(ImpactSequence(model.Run(StrikeAt(2.0001, 0.0), 1.0)), hit);
  EXPECT_NE(ImpactSequence(model.Run(StrikeAt(2.0, 0.5), 1.0)), hit);
}

}  // namespace
}  // namespace billiard::shot_fit
