#include "sim/shot_fit/execution_noise_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sim/params/execution_noise.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/shot_fit/synthetic_shots.h"

namespace billiard::shot_fit {
namespace {

constexpr double kPeriod = 1.0 / 30.0, kTracking = 5e-4, kDuration = 0.6;
constexpr double kDegree = M_PI / 180.0;

const physics::ModelParameters& Pool() {
  static const physics::ModelParameters p = params::LoadParameters("pool");
  return p;
}

params::ExecutionNoise Noise(double speed, double heading_deg, double tip_mm) {
  params::ExecutionNoise n;
  n.speed = speed;
  n.heading = heading_deg * kDegree;
  n.tip_offset = tip_mm * 1e-3;
  return n;
}

// `scenes`' strokes played with `plant` (params::Perturbed, what the table simulator executes),
// tracked at 30 Hz with half a millimetre of error, each launch fitted and held against the
// commanded stroke; the shots whose launch has too few frames before a collision are left out.
std::vector<LaunchResidual> ResidualsOf(const params::ExecutionNoise& plant,
                                        std::vector<SyntheticScene> scenes, std::uint64_t seed) {
  const table::TableGeometry table =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  std::mt19937_64 random(seed);
  std::normal_distribution<double> unit;
  std::vector<LaunchResidual> out;
  for (SyntheticScene& scene : scenes) {
    const physics::CueStroke commanded = scene.strike.stroke;
    scene.strike.stroke = params::Perturbed(commanded, plant, Pool().ball.radius,
                                            [&] { return unit(random); });
    const TrackedShot shot = SimulateTrackedShot(table, Pool(), scene.starts, 0, scene.strike,
                                                 kDuration, kPeriod, kTracking, 0.0, random());
    const MeasuredLaunch launch = FitLaunch(shot, commanded, Pool());
    if (launch.ok) out.push_back(ResidualOf(commanded, scene.starts[0], launch, Pool()));
  }
  return out;
}

// `count` seeded SyntheticScenes' strokes (three balls, cue speeds 2-4 m/s, tip offsets within
// 0.4 r; `centre`: every tip at the centre) through ResidualsOf.
std::vector<LaunchResidual> Residuals(const params::ExecutionNoise& plant, int count,
                                      std::uint64_t seed, bool centre = false) {
  const table::TableGeometry table =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  std::vector<SyntheticScene> scenes = SyntheticScenes(table, Pool().ball.radius, count, seed);
  for (SyntheticScene& scene : scenes) {
    if (centre) scene.strike.stroke.tip_side = scene.strike.stroke.tip_height = 0.0;
  }
  return ResidualsOf(plant, std::move(scenes), seed);
}

// The loop's strokes (LoopScenes: one ball, 0.25-0.6 m/s, the spin styles in turn, or all
// natural) through ResidualsOf.
std::vector<LaunchResidual> LoopResiduals(const params::ExecutionNoise& plant, int count,
                                          std::uint64_t seed, bool natural_only = false) {
  const table::TableGeometry table =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  return ResidualsOf(plant, LoopScenes(table, Pool().ball.radius, count, seed, natural_only),
                     seed);
}

void ExpectWithin(const Spread& s, double truth, double relative, const char* what) {
  EXPECT_TRUE(s.identified) << what;
  EXPECT_LE(s.lower, truth) << what << " " << s.value << " [" << s.lower << ", " << s.upper << "]";
  EXPECT_GE(s.upper, truth) << what << " " << s.value << " [" << s.lower << ", " << s.upper << "]";
  EXPECT_NEAR(s.value, truth, relative * truth) << what;
}

// Issue 47's plant: 0.25 degree of heading, 2.5 % of speed, 0.8 mm of tip offset, the tip's
// spread known. From 400 shots the heading and the speed are recovered inside their intervals
// and within 15 %: the squirt of the tip's side error (0.2 degree at 0.8 mm, as much as the
// heading's) and the speed its height error changes are subtracted in variance.
TEST(FitExecutionNoise, RecoversHeadingAndSpeedWithTheTipKnown) {
  const params::ExecutionNoise plant = Noise(0.025, 0.25, 0.8);
  NoiseFitOptions options;
  options.tip_prior = plant.tip_offset;
  options.fit_tip = false;
  const NoiseFit fit = FitExecutionNoise(Residuals(plant, 400, 5), options);
  ExpectWithin(fit.speed, plant.speed, 0.15, "speed");
  ExpectWithin(fit.heading, plant.heading, 0.15, "heading");
  EXPECT_FALSE(fit.tip.identified);
  EXPECT_GE(fit.used.size(), 250u);
}

// The tip's spread alone (a perfect heading and speed): identified from the squirt and the speed
// of the off-centre strokes, inside its interval and within 10 %.
TEST(FitExecutionNoise, IdentifiesTheTipFromSquirtAndSpeed) {
  const params::ExecutionNoise plant = Noise(0.0, 0.0, 0.8);
  const NoiseFit fit = FitExecutionNoise(Residuals(plant, 400, 5));
  ExpectWithin(fit.tip, plant.tip_offset, 0.1, "tip");
  EXPECT_LT(fit.heading.value, 0.1 * kDegree);
}

// The estimate converges: from 60 shots and from 400, the truth inside both intervals, the
// second narrower by about sqrt(400 / 60).
TEST(FitExecutionNoise, ConvergesWithinItsInterval) {
  const params::ExecutionNoise plant = Noise(0.025, 0.25, 0.8);
  const std::vector<LaunchResidual> many = Residuals(plant, 400, 6);
  const std::vector<LaunchResidual> few(many.begin(), many.begin() + 60);
  const NoiseFit small = FitExecutionNoise(few), large = FitExecutionNoise(many);
  ExpectWithin(small.heading, plant.heading, 0.3, "heading of 60");
  ExpectWithin(small.speed, plant.speed, 0.3, "speed of 60");
  EXPECT_LT(large.heading.upper - large.heading.lower,
            0.6 * (small.heading.upper - small.heading.lower));
  EXPECT_LT(large.speed.upper - large.speed.lower, 0.6 * (small.speed.upper - small.speed.lower));
}

// Half the default noise (0.05 degree, 0.5 %, 0.25 mm): the tracking's error is a good part
// of what the launches show, and subtracted in variance the spreads come back; the launches'
// raw spread of direction is wider than the heading's.
TEST(FitExecutionNoise, SubtractsTheTrackingsError) {
  const params::ExecutionNoise plant = Noise(0.005, 0.05, 0.25);
  const std::vector<LaunchResidual> shots = Residuals(plant, 400, 7);
  const NoiseFit fit = FitExecutionNoise(shots);
  ExpectWithin(fit.heading, plant.heading, 0.2, "heading");
  ExpectWithin(fit.speed, plant.speed, 0.2, "speed");
  double direction = 0.0;
  for (const LaunchResidual& s : shots) direction += s.residual[1] * s.residual[1];
  EXPECT_GT(std::sqrt(direction / shots.size()), 1.2 * plant.heading);
}

// A launch the cut misjudged (5 degrees off: a collision inside its frames) is left out.
TEST(FitExecutionNoise, LeavesOutLaunchesFarOff) {
  const params::ExecutionNoise plant = Noise(0.025, 0.25, 0.8);
  std::vector<LaunchResidual> shots = Residuals(plant, 200, 8);
  for (int k = 0; k < 5; ++k) shots[k].residual[1] += 5.0 * kDegree;
  const NoiseFit fit = FitExecutionNoise(shots);
  EXPECT_GE(fit.rejected, 5u);
  ExpectWithin(fit.heading, plant.heading, 0.2, "heading");
}

// Strokes all at the centre: the tip's error changes neither the launch's speed nor (but by the
// squirt, like the heading's) its direction, so its spread is held at the prior, said so.
TEST(FitExecutionNoise, HoldsTheTipWhereNoStrokeShowsIt) {
  const params::ExecutionNoise plant = Noise(0.025, 0.25, 0.0);
  NoiseFitOptions options;
  options.tip_prior = 0.0;
  const NoiseFit fit = FitExecutionNoise(Residuals(plant, 200, 9, true), options);
  EXPECT_FALSE(fit.tip.identified);
  EXPECT_EQ(fit.tip.value, 0.0);
  ExpectWithin(fit.heading, plant.heading, 0.2, "heading");
  ExpectWithin(fit.speed, plant.speed, 0.2, "speed");
}

// The loop's strokes with the spin styles in turn (issue 47's plant, nothing held): the frames
// see each slide end, so the velocity the ball rolls on shows the spin the tip's height gave
// (launch_spin.h), which a speed error does not change, and the tip's spread is identified with
// the speed's and the heading's. From 1000 shots all three are inside their intervals and within
// 10 % (0.75 mm, 2.53 %, 0.266 degree). From 60 the tip, the squirt it implies and the heading
// still trade: on these strokes 1.07 mm [0.81, 1.41], 1.6 % and 0.08 degree
// (docs/identification.md).
TEST(FitExecutionNoise, IdentifiesTheTipFromTheSpinOfTheLoopsStrokes) {
  const params::ExecutionNoise plant = Noise(0.025, 0.25, 0.8);
  const std::vector<LaunchResidual> shots = LoopResiduals(plant, 1000, 12);
  ASSERT_GE(shots.size(), 950u);
  const NoiseFit fit = FitExecutionNoise(shots);
  ExpectWithin(fit.tip, plant.tip_offset, 0.1, "tip");
  ExpectWithin(fit.speed, plant.speed, 0.1, "speed");
  ExpectWithin(fit.heading, plant.heading, 0.1, "heading");
}

// The same strokes all at the natural roll's height (what the loop played before --spins): the
// tip's height error and the speed's change the rolling speed alike on every stroke, so the two
// cannot be told apart and the tip is held at its prior.
TEST(FitExecutionNoise, HoldsTheTipWhereEveryStrokeRollsNaturally) {
  const params::ExecutionNoise plant = Noise(0.025, 0.25, 0.8);
  const NoiseFit fit = FitExecutionNoise(LoopResiduals(plant, 400, 11, true));
  EXPECT_FALSE(fit.tip.identified);
}

// Many spin styles of few shots each (eight of six), the residuals drawn from the linear model
// itself (each coordinate one error, a bias per style, no tracking error): the variances
// averaged over 300 such sets are the drawn ones. The likelihood's own maximum would leave the
// biases' eight degrees of freedom in them, 40 / 48 of each (17 % low); the restricted
// likelihood's is unbiased in a balanced design (Searle, Casella and McCulloch 1992, ch. 6).
TEST(FitExecutionNoise, TakesTheBiasesDegreesOfFreedomOutOfTheVariances) {
  constexpr int kSets = 300, kStyles = 8, kShotsPerStyle = 6;
  const Eigen::Vector3d spread(0.025, 0.25 * kDegree, 0.8e-3);
  std::mt19937_64 random(31);
  std::normal_distribution<double> unit;
  Eigen::Vector3d mean_variance = Eigen::Vector3d::Zero();
  for (int set = 0; set < kSets; ++set) {
    std::vector<LaunchResidual> shots;
    for (int style = 0; style < kStyles; ++style) {
      const Eigen::Vector4d bias =
          0.01 * Eigen::Vector4d(unit(random), unit(random), unit(random), unit(random));
      for (int k = 0; k < kShotsPerStyle; ++k) {
        LaunchResidual shot;
        shot.jacobian.setIdentity();  // the residual is the error: speed, heading, tip, tip
        shot.cue_speed = 1.0;
        shot.style = style;
        shot.residual = bias + Eigen::Vector4d(spread[0] * unit(random), spread[1] * unit(random),
                                               spread[2] * unit(random), spread[2] * unit(random));
        shots.push_back(shot);
      }
    }
    const NoiseFit fit = FitExecutionNoise(shots);
    mean_variance +=
        Eigen::Vector3d(fit.speed.value * fit.speed.value, fit.heading.value * fit.heading.value,
                        fit.tip.value * fit.tip.value) /
        kSets;
  }
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(mean_variance[j] / (spread[j] * spread[j]), 1.0, 0.05) << j;
  }
}

TEST(FitExecutionNoise, NeedsThreeShots) {
  EXPECT_THROW(FitExecutionNoise(std::vector<LaunchResidual>(2)), std::invalid_argument);
}

}  // namespace
}  // namespace billiard::shot_fit
