#include "sim/shot_fit/shot_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

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

// Shots of random strikes from random positions (seeded), as the camera tracks them: 50 Hz,
// 1 mm of noise, thinned where a ball moved less than 2 mm (the real recordings' format).
std::vector<TrackedShot> RandomShots(const table::TableGeometry& table,
                                     const physics::ModelParameters& p, int count,
                                     std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double r = p.ball.radius;
  std::vector<TrackedShot> shots;
  while (static_cast<int>(shots.size()) < count) {
    std::vector<Eigen::Vector2d> starts;
    while (starts.size() < 3) {
      const Eigen::Vector2d q(2 * r + unit(random) * (table.length - 4 * r),
                              2 * r + unit(random) * (table.width - 4 * r));
      bool clear = true;
      for (const Eigen::Vector2d& o : starts) clear = clear && (q - o).norm() > 3 * r;
      if (clear) starts.push_back(q);
    }
    Strike s;
    s.stroke.speed = 2.0 + 2.0 * unit(random);
    s.stroke.heading = 2 * M_PI * unit(random);
    s.stroke.tip_side = (unit(random) - 0.5) * 0.8 * r;
    s.stroke.tip_height = (unit(random) - 0.5) * 0.8 * r;
    s.time = 0.02 * unit(random);
    shots.push_back(SimulateTrackedShot(table, p, starts, 0, s, 8.0, 0.02, 0.001, 0.002,
                                        seed + shots.size()));
    shots.back().id = std::to_string(shots.size());
  }
  return shots;
}

// The acceptance of issue 28 on simulated truth: from 20 shots of a table whose constants are
// hidden (each drawn within +-20 % of the carom set's), the fit recovers the sliding friction
// within 3 %, the rolling resistance within 5 % and the cushion restitution within 3 %, and
// reports each as identifiable with an uncertainty below that tolerance. (Not within a few of its
// uncertainties: those are statistical given the start positions, which the fit takes from the
// first, noisy samples; that error biases the constants by a few tenths of a per cent.)
TEST(ShotFit, RecoversHiddenConstantsFromTwentyShots) {
  const table::TableGeometry table = Carom();
  const physics::ModelParameters prior = params::LoadParameters("carom");
  const std::vector<Constant> constants = {Constant::kMu, Constant::kRolling, Constant::kCushion};
  std::mt19937_64 random(28);
  std::uniform_real_distribution<double> factor(0.8, 1.2);
  std::vector<double> hidden;
  for (Constant c : constants) hidden.push_back(ConstantValue(prior, c) * factor(random));
  const physics::ModelParameters truth = WithConstants(prior, constants, hidden);
  const std::vector<TrackedShot> shots = RandomShots(table, truth, 20, 2028);

  FitOptions options;
  options.constants = constants;
  options.rounds = 1;
  options.max_iterations = 100;
  batch::ThreadPool pool(2);
  const ShotsFit fit = FitShots(table, prior, shots, options, pool);
  const double tolerance[] = {0.03, 0.05, 0.03};
  for (std::size_t c = 0; c < constants.size(); ++c) {
    const ConstantFit& f = fit.constants[c];
    SCOPED_TRACE(ConstantName(f.constant));
    EXPECT_TRUE(f.identifiable);
    EXPECT_NEAR(f.value / hidden[c], 1.0, tolerance[c]);
    EXPECT_GT(f.sd, 0.0);
    EXPECT_LT(f.sd, tolerance[c] * hidden[c]);
  }
  EXPECT_LT(fit.median_cue_rmse, 0.005);
}

}  // namespace
}  // namespace billiard::shot_fit
