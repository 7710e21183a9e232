#include "sim/shot_fit/shot_fit.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"

namespace billiard::shot_fit {
namespace {

table::TableGeometry Carom() { return table::BuildTable(params::LoadTableSpec("carom-10ft")); }

TEST(ShotFit, RecoversTheStrikeOfASimulatedShot) {
  const table::TableGeometry table = Carom();
  const physics::ModelParameters p = params::LoadParameters("carom");
  Strike truth;
  truth.stroke.speed = 3.0;
  truth.stroke.heading = 0.35;
  truth.stroke.tip_side = 0.3 * p.ball.radius;
  truth.stroke.tip_height = 0.2 * p.ball.radius;
  truth.time = 0.011;
  const TrackedShot shot = SimulateTrackedShot(
      table, p, {{0.7, 0.4}, {2.0, 1.0}, {1.5, 0.3}}, 0, truth, 8.0, 0.02, 0.001, 0.002, 1);
  const ShotFit fit = FitStrike(table, p, shot, FitOptions{});
  EXPECT_LT(fit.rmse_cue, 0.003);
  EXPECT_NEAR(fit.strike.stroke.speed, truth.stroke.speed, 0.03);
  EXPECT_NEAR(fit.strike.stroke.heading, truth.stroke.heading, 1e-3);
}

}  // namespace
}  // namespace billiard::shot_fit
