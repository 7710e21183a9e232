#include "sim/shot_fit/uncertainty.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/shot_fit/shot_fit.h"

namespace billiard::shot_fit {
namespace {

table::TableGeometry Carom() { return table::BuildTable(params::LoadTableSpec("carom-10ft")); }

// A straight line y = c + s x fitted by least squares to noisy samples, as the blocks of one
// "shot": the slope s its strike, the intercept c the constant (and, with `unexcited`, a second
// constant no sample depends on). The residuals at the solution, fitted minus seen.
struct LineFit {
  std::vector<double> x, r;
  double ssr = 0.0, sxx = 0.0, sum_xx = 0.0;

  explicit LineFit(int n) {
    std::mt19937_64 random(4);
    std::normal_distribution<double> noise(0.0, 0.3);
    std::vector<double> y;
    double mean_x = 0.0, mean_y = 0.0;
    for (int i = 0; i < n; ++i) {
      x.push_back(0.5 + 0.1 * i);
      y.push_back(1.0 + 2.0 * x.back() + noise(random));
      mean_x += x.back() / n;
      mean_y += y.back() / n;
    }
    double sxy = 0.0;
    for (int i = 0; i < n; ++i) {
      sxx += (x[i] - mean_x) * (x[i] - mean_x);
      sxy += (x[i] - mean_x) * (y[i] - mean_y);
      sum_xx += x[i] * x[i];
    }
    const double slope = sxy / sxx, intercept = mean_y - slope * mean_x;
    for (int i = 0; i < n; ++i) {
      r.push_back(intercept + slope * x[i] - y[i]);
      ssr += r.back() * r.back();
    }
  }

  ShotBlocks Blocks(bool unexcited) const {
    const int n = static_cast<int>(x.size());
    Eigen::MatrixXd j = Eigen::MatrixXd::Zero(n, unexcited ? 3 : 2);
    for (int i = 0; i < n; ++i) {
      j(i, 0) = x[i];
      j(i, 1) = 1.0;
    }
    ShotBlocks b = BlocksOf(j, 1, r);
    b.lagged = {ssr};  // uncorrelated: no products at any lag
    return b;
  }
};

// With uncorrelated residuals the constant's uncertainty is the textbook standard error of a
// regression's intercept, the slope a nuisance parameter: s sqrt(sum x^2 / (n S_xx)), s^2 the
// residuals' sum of squares over n - 2.
TEST(ConstantsCovariance, OfUncorrelatedResidualsIsTheTextbookStandardError) {
  constexpr int kSamples = 40;
  const LineFit line(kSamples);
  double tau = 0.0;
  const Eigen::MatrixXd cov = ConstantsCovariance({line.Blocks(false)}, 1, &tau);
  EXPECT_EQ(tau, 1.0);
  const double s2 = line.ssr / (kSamples - 2);
  const double textbook = std::sqrt(s2 * line.sum_xx / (kSamples * line.sxx));
  EXPECT_NEAR(std::sqrt(cov(0, 0)), textbook, 1e-9 * textbook);
}

// Residuals correlated at lag 1 (rho_1 = 0.5: tau = 2) say half as much: the variance doubles.
TEST(ConstantsCovariance, GrowsWithTheResidualsCorrelationTime) {
  const LineFit line(40);
  ShotBlocks correlated = line.Blocks(false);
  correlated.lagged = {line.ssr, 0.5 * line.ssr};
  double independent_tau = 0.0, tau = 0.0;
  const double independent = ConstantsCovariance({line.Blocks(false)}, 1, &independent_tau)(0, 0);
  const double variance = ConstantsCovariance({correlated}, 1, &tau)(0, 0);
  EXPECT_DOUBLE_EQ(tau, 2.0);
  EXPECT_NEAR(variance, 2.0 * independent, 1e-12 * independent);
}

// A constant no residual depends on has an infinite variance; the other's is what it would be
// alone, but for the degree of freedom the second constant takes.
TEST(ConstantsCovariance, IsInfiniteForAConstantNoShotExcites) {
  constexpr int kSamples = 40;
  const LineFit line(kSamples);
  double tau = 0.0;
  const Eigen::MatrixXd cov = ConstantsCovariance({line.Blocks(true)}, 2, &tau);
  EXPECT_EQ(cov(1, 1), std::numeric_limits<double>::infinity());
  const double expected = line.ssr / (kSamples - 3) * line.sum_xx / (kSamples * line.sxx);
  EXPECT_NEAR(cov(0, 0), expected, 1e-9 * expected);
}

// A fit that stops a hair inside the edge of its range with a tiny standard deviation is at its
// bound, as one that reaches it: the adaptive loop's truth fitted mu 0.5995 +- 0.0003 against
// the range's 0.6 from shots that never slide (docs/benchmarks/adaptive_loop_report.md). A wide
// fit near a bound is merely unknown (its sd says so), and a known fit 3 sd clear of both is
// inside.
TEST(AtRangeBound, AFitWithin3SdOfItsRangesEdgeIsAtItsBound) {
  EXPECT_TRUE(AtRangeBound(0.5995, 0.0003, true, 0.02, 0.6));
  EXPECT_TRUE(AtRangeBound(0.6, 0.0, true, 0.02, 0.6));
  EXPECT_TRUE(AtRangeBound(0.02 * (1 + 1e-7), 0.5, false, 0.02, 0.6));
  EXPECT_FALSE(AtRangeBound(0.5995, 0.0003, false, 0.02, 0.6));
  EXPECT_FALSE(AtRangeBound(0.5985, 0.0003, true, 0.02, 0.6));
  EXPECT_FALSE(AtRangeBound(0.24, 0.0004, true, 0.02, 0.6));
}

// Identifiable: a relative sd of at most max_relative_sd and clear of the range's bounds (mu's
// is 0.02-0.6). Otherwise the constant goes back to its prior, its sd and bound reported.
TEST(JudgeIdentifiable, KeepsAPinnedConstantInsideItsRangeAndRestoresTheOthersPrior) {
  ConstantFit fit;
  fit.constant = Constant::kMu;
  fit.prior = 0.25;
  const auto judged = [&](double value, double sd) {
    ConstantFit f = fit;
    JudgeIdentifiable(value, sd * sd, 0.2, &f);
    return f;
  };
  const ConstantFit pinned = judged(0.2, 0.01);
  EXPECT_TRUE(pinned.identifiable);
  EXPECT_FALSE(pinned.at_bound);
  EXPECT_EQ(pinned.value, 0.2);
  EXPECT_DOUBLE_EQ(pinned.sd, 0.01);

  const ConstantFit wide = judged(0.2, 0.05);
  EXPECT_FALSE(wide.identifiable);
  EXPECT_FALSE(wide.at_bound);
  EXPECT_EQ(wide.value, 0.25);
  EXPECT_DOUBLE_EQ(wide.sd, 0.05);

  const ConstantFit at_edge = judged(0.5995, 0.0003);
  EXPECT_FALSE(at_edge.identifiable);
  EXPECT_TRUE(at_edge.at_bound);
  EXPECT_EQ(at_edge.value, 0.25);

  EXPECT_FALSE(judged(0.2, std::numeric_limits<double>::infinity()).identifiable);
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
TEST(FitShots, ReportsAConstantNoShotExcitesAsNotIdentifiable) {
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
TEST(FitShots, UncertaintyCountsTheResidualsCorrelation) {
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
TEST(FitShots, NeverReportsAConstantAtItsBoundAsIdentifiable) {
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

}  // namespace
}  // namespace billiard::shot_fit

namespace billiard::shot_fit {
namespace {

// The fit's sds under the set's keys; rolling's in d, d = 5 r mu_r / a with a held; a constant
// not identifiable (or of infinite sd) carries none.
TEST(SetUncertainty, NamesTheSetsKeysAndConvertsRollingToD) {
  const physics::ModelParameters pool = params::LoadParameters("pool");
  std::vector<ConstantFit> fits(4);
  fits[0] = {Constant::kCushion, 0.85, 0.86, 0.004, false, true};
  fits[1] = {Constant::kRolling, 0.01, 0.011, 0.0002, false, true};
  fits[2] = {Constant::kMu, 0.2, 0.2, 0.01, false, false};
  fits[3] = {Constant::kBallBall, 0.95, 0.95, std::numeric_limits<double>::infinity(), false, true};
  const auto sd = SetUncertainty(fits, pool);
  ASSERT_EQ(sd.size(), 2u);
  EXPECT_EQ(sd[0].first, "collision.cushion_restitution");
  EXPECT_EQ(sd[0].second, 0.004);
  EXPECT_EQ(sd[1].first, "contact.d");
  // d moves with mu_r at 5 r / a: the pool set's d of 0.51 for mu_r = 0.01.
  EXPECT_NEAR(sd[1].second, 0.0002 * pool.contact.d / pool.RollingResistance(), 1e-12);
}

}  // namespace
}  // namespace billiard::shot_fit
