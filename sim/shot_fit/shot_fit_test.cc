#include "sim/shot_fit/shot_fit.h"
#include "sim/shot_fit/shot_recorder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "tests/support/test_data.h"

namespace billiard::shot_fit {
namespace {

table::TableGeometry Carom() { return table::BuildTable(params::LoadTableSpec("carom-10ft")); }

std::string RefusalOf(const std::string& json) {
  try {
    ParseTrackedShots(json, "s.json");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(TrackedShots, RefusesBadInputInOneLineNamingTheShot) {
  EXPECT_EQ(RefusalOf("{"), RefusalOf("{")) << "deterministic";
  EXPECT_NE(RefusalOf("{").find("s.json: invalid JSON"), std::string::npos);
  EXPECT_NE(RefusalOf("{}").find("array \"shots\""), std::string::npos);
  const std::string ball = R"("1": {"t": [0, 0.02], "x": [1, 1.1], "y": [0.5, 0.5]})";
  EXPECT_NE(RefusalOf(R"({"shots": [{"id": 7, "cue_ball": "2", "balls": {)" + ball + "}}]}")
                .find("s.json: shot 7: has no ball \"2\""),
            std::string::npos);
  EXPECT_NE(RefusalOf(R"({"shots": [{"id": 7, "cue_ball": "1", "balls": {"1": {"t": [0.1, 0],
            "x": [1, 1], "y": [1, 1]}}}]})")
                .find("shot 7, ball 1: times decrease"),
            std::string::npos);
  EXPECT_NE(RefusalOf(R"({"shots": [{"id": 7, "cue_ball": "1", "balls": {"1": {"t": [0],
            "x": [1, 2], "y": [1]}}}]})")
                .find("differ in length"),
            std::string::npos);
  for (const std::string& message : {RefusalOf("{"), RefusalOf("{}")})
    EXPECT_EQ(message.find('\n'), std::string::npos);
}

TEST(TrackedShots, ReadBackWhatTheyWrite) {
  const table::TableGeometry table = Carom();
  const physics::ModelParameters p = params::LoadParameters("carom");
  TrackedShots shots;
  shots.source = "simulated";
  shots.shots = SyntheticShots(table, p, 2, 3);
  const TrackedShots back = ParseTrackedShots(TrackedShotsJson(shots), "x");
  ASSERT_EQ(back.shots.size(), 2u);
  EXPECT_EQ(back.source, "simulated");
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(back.shots[i].id, shots.shots[i].id);
    EXPECT_EQ(back.shots[i].cue, shots.shots[i].cue);
    ASSERT_EQ(back.shots[i].balls.size(), shots.shots[i].balls.size());
    for (std::size_t b = 0; b < back.shots[i].balls.size(); ++b) {
      EXPECT_EQ(back.shots[i].balls[b].t, shots.shots[i].balls[b].t);
      EXPECT_EQ(back.shots[i].balls[b].position, shots.shots[i].balls[b].position);
    }
  }
}

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
  const std::vector<TrackedShot> shots = SyntheticShots(table, truth, 20, 2028);

  FitOptions options;
  options.constants = constants;
  options.rounds = 1;
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

// Shots of one ball from the table's centre, struck below, at and above the centre (so that
// they slide), simulated with `truth`, tracked every 20 ms; by default without noise and
// without thinning.
std::vector<TrackedShot> LoneBallShots(const table::TableGeometry& table,
                                       const physics::ModelParameters& truth, double noise = 0.0,
                                       double thinning = 0.0) {
  std::vector<TrackedShot> shots;
  for (int i = 0; i < 4; ++i) {
    Strike s;
    s.stroke.speed = 2.0 + 0.4 * i;
    s.stroke.heading = 0.3 + 1.4 * i;
    s.stroke.tip_height = (0.3 - 0.2 * i) * truth.ball.radius;
    s.time = 0.01;
    shots.push_back(SimulateTrackedShot(table, truth, {{1.42, 0.71}}, 0, s, 6.0, 0.02, noise,
                                        thinning, 100 + i));
  }
  return shots;
}

// A constant no shot excites: one ball alone on the table never meets another, so nothing says
// what the balls' restitution is; the fit reports it as not identifiable and keeps the prior,
// while the cloth's friction, which every shot shows, is fitted.
TEST(ShotFit, ReportsAConstantNoShotExcitesAsNotIdentifiable) {
  const table::TableGeometry table = Carom();
  const physics::ModelParameters prior = params::LoadParameters("carom");
  const physics::ModelParameters truth = WithConstants(prior, {Constant::kMu}, {0.18});
  const std::vector<TrackedShot> shots = LoneBallShots(table, truth, 0.001, 0.002);
  FitOptions options;
  options.constants = {Constant::kMu, Constant::kBallBall};
  batch::ThreadPool pool(2);
  const ShotsFit fit = FitShots(table, prior, shots, options, pool);
  ASSERT_EQ(fit.constants.size(), 2u);
  EXPECT_TRUE(fit.constants[0].identifiable);
  EXPECT_NEAR(fit.constants[0].value, 0.18, 0.18 * 0.03);
  EXPECT_FALSE(fit.constants[1].identifiable);
  EXPECT_EQ(fit.constants[1].value, prior.collision.ball_restitution);
  EXPECT_EQ(fit.params.collision.ball_restitution, prior.collision.ball_restitution);
}

// The uncertainty counts what the residuals really say. The same shots tracked with noise of the
// same size, once independent from frame to frame and once correlated as a filter's output is
// (AR(1), rho = 0.8: a correlation time (1 + rho) / (1 - rho) = 9 frames): the fit measures the
// correlation time and the correlated noise's uncertainty is about sqrt(9) = 3 times the other's.
TEST(ShotFit, UncertaintyCountsTheResidualsCorrelation) {
  const table::TableGeometry table = Carom();
  const physics::ModelParameters prior = params::LoadParameters("carom");
  const physics::ModelParameters truth = WithConstants(prior, {Constant::kRolling}, {0.011});
  constexpr double kNoise = 0.001, kRho = 0.8;
  auto noisy = [&](double rho) {
    std::vector<TrackedShot> shots = LoneBallShots(table, truth);
    std::mt19937_64 random(5);
    std::normal_distribution<double> gauss(0.0, kNoise * std::sqrt(1.0 - rho * rho));
    for (TrackedShot& shot : shots) {
      Eigen::Vector2d e(gauss(random), gauss(random));
      e /= std::sqrt(1.0 - rho * rho);  // the stationary spread from the first sample on
      for (Eigen::Vector2d& q : shot.balls[0].position) {
        q += e;
        e = rho * e + Eigen::Vector2d(gauss(random), gauss(random));
      }
    }
    return shots;
  };
  FitOptions options;
  options.constants = {Constant::kRolling};
  batch::ThreadPool pool(2);
  const ShotsFit independent = FitShots(table, prior, noisy(0.0), options, pool);
  const ShotsFit correlated = FitShots(table, prior, noisy(kRho), options, pool);
  EXPECT_LT(independent.correlation_time, 1.5);
  EXPECT_GT(correlated.correlation_time, 5.0);
  EXPECT_LT(correlated.correlation_time, 14.0);
  EXPECT_GT(correlated.constants[0].sd, 2.0 * independent.constants[0].sd);
  EXPECT_LT(correlated.constants[0].sd, 4.5 * independent.constants[0].sd);
}

// A fit that runs to the edge of a constant's range found no minimum: the cloth's friction of
// these shots (0.01, a ball that slides across the table) is below the range a fit searches
// (from 0.02). The fit stops at 0.02 with a relative uncertainty of about 7 %, which alone
// would pass for identifiable; it is reported at its bound, not identifiable, and kept at its
// prior.
TEST(ShotFit, NeverReportsAConstantAtItsBoundAsIdentifiable) {
  const table::TableGeometry table = Carom();
  const physics::ModelParameters prior = params::LoadParameters("carom");
  const std::vector<TrackedShot> shots =
      LoneBallShots(table, WithConstants(prior, {Constant::kMu}, {0.01}));
  FitOptions options;
  options.constants = {Constant::kMu};
  batch::ThreadPool pool(2);
  const ShotsFit fit = FitShots(table, prior, shots, options, pool);
  ASSERT_EQ(fit.constants.size(), 1u);
  EXPECT_TRUE(fit.constants[0].at_bound);
  EXPECT_FALSE(fit.constants[0].identifiable);
  EXPECT_EQ(fit.constants[0].value, prior.contact.mu);
  EXPECT_EQ(fit.params.contact.mu, prior.contact.mu);
}

// A fit that stops a hair inside the edge of its range with a tiny standard deviation is at its
// bound, as one that reaches it: the adaptive loop's truth fitted mu 0.5995 +- 0.0003 against
// the range's 0.6 from shots that never slide (docs/benchmarks/adaptive_loop_report.md). A wide
// fit near a bound is merely unknown (its sd says so), and a known fit 3 sd clear of both is
// inside.
TEST(ShotFit, AFitWithin3SdOfItsRangesEdgeIsAtItsBound) {
  EXPECT_TRUE(AtRangeBound(0.5995, 0.0003, true, 0.02, 0.6));
  EXPECT_TRUE(AtRangeBound(0.6, 0.0, true, 0.02, 0.6));
  EXPECT_TRUE(AtRangeBound(0.02 * (1 + 1e-7), 0.5, false, 0.02, 0.6));
  EXPECT_FALSE(AtRangeBound(0.5995, 0.0003, false, 0.02, 0.6));
  EXPECT_FALSE(AtRangeBound(0.5985, 0.0003, true, 0.02, 0.6));
  EXPECT_FALSE(AtRangeBound(0.24, 0.0004, true, 0.02, 0.6));
}

// The same fit gives the same answer on one thread as on two (each shot its own job, the sums
// in shot order).
TEST(ShotFit, IsTheSameOnAnyThreadCount) {
  const table::TableGeometry table = Carom();
  const physics::ModelParameters prior = params::LoadParameters("carom");
  const std::vector<TrackedShot> shots =
      SyntheticShots(table, WithConstants(prior, {Constant::kMu}, {0.21}), 2, 7);
  FitOptions options;
  options.constants = {Constant::kMu};
  batch::ThreadPool one(1), two(2);
  const ShotsFit a = FitShots(table, prior, shots, options, one);
  const ShotsFit b = FitShots(table, prior, shots, options, two);
  EXPECT_EQ(a.constants[0].value, b.constants[0].value);
  for (std::size_t i = 0; i < shots.size(); ++i) {
    EXPECT_EQ(a.shots[i].strike.stroke.speed, b.shots[i].strike.stroke.speed);
    EXPECT_EQ(a.shots[i].rmse_cue, b.shots[i].rmse_cue);
  }
}

// The real dev recordings (tailuge/billiards, GPL-3.0; shared/data/real-shots/README.md): they
// read as 60 shots of three balls, and the shipped carom set follows the first two to well
// within a ball's travel (the benchmark report has the distribution over all of them).
TEST(ShotFit, FollowsRealShotsWithTheShippedCaromSet) {
  BILLIARD_TEST_DATA_OR_SKIP(path, "real-shots/three_cushion_dev.json");
  const TrackedShots tracked = ReadTrackedShots(path);
  ASSERT_EQ(tracked.shots.size(), 60u);
  for (const TrackedShot& shot : tracked.shots) EXPECT_EQ(shot.balls.size(), 3u);
  EXPECT_NE(tracked.source.find("tailuge/billiards"), std::string::npos);
  const table::TableGeometry table = Carom();
  const physics::ModelParameters p = params::LoadParameters("carom-fitted");
  for (int i = 0; i < 2; ++i) {
    const ShotFit fit = FitStrike(table, p, tracked.shots[i], FitOptions{});
    EXPECT_LT(fit.rmse_cue, 0.25) << "shot " << fit.id;
  }
}


// A loop's messages cut into shots: the balls of the last state before the strike at rest at
// time 0, the later states as samples, a track that appears mid-shot not followed, a strike
// commanded again (same utime) ignored, one of an unknown track skipped.
TEST(ShotRecorder, CutsStrikesAndStatesIntoShots) {
  ShotRecorder recorder;
  recorder.State(1000000, {{7, {1.0, 0.5}}, {9, {2.0, 0.5}}});
  recorder.Strike(1020000, 7);
  recorder.State(1040000, {{7, {1.1, 0.5}}, {9, {2.0, 0.5}}, {12, {0.3, 0.3}}});
  recorder.Strike(1020000, 7);  // the same answer again
  recorder.State(1060000, {{7, {1.2, 0.5}}});
  recorder.Strike(1070000, 42);  // no such track: closes the shot, starts none
  recorder.Finish();
  ASSERT_EQ(recorder.shots().size(), 1u);
  EXPECT_EQ(recorder.skipped(), 1);
  const TrackedShot& shot = recorder.shots()[0];
  ASSERT_EQ(shot.balls.size(), 2u);
  EXPECT_EQ(shot.cue, 0u);
  EXPECT_EQ(shot.balls[0].t, (std::vector<double>{0.0, 0.04, 0.06}));
  EXPECT_DOUBLE_EQ(shot.balls[0].position[2].x(), 1.2);
  EXPECT_EQ(shot.balls[1].t.size(), 2u);
}

}  // namespace
}  // namespace billiard::shot_fit
