#include "sim/shot_fit/joint_fit.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/shot_fit/synthetic_shots.h"

namespace billiard::shot_fit {
namespace {

table::TableGeometry Carom() { return table::BuildTable(params::LoadTableSpec("carom-10ft")); }

// The Schur complement solves the whole damped system: the constants' step of the reduced
// system and each strike's step back-substituted are the step of the full Levenberg-Marquardt
// system (J^T J + lambda diag(J^T J)) d = -J^T r over every strike and the constants, written
// out as one matrix.
TEST(Reduce, GivesTheStepOfTheWholeDampedSystem) {
  constexpr int kShots = 3, kStrike = 4, kConstants = 2, kRows = 15;
  constexpr double kLambda = 0.3;
  std::mt19937_64 random(11);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const auto random_matrix = [&](int rows, int cols) {
    Eigen::MatrixXd m(rows, cols);
    for (int i = 0; i < rows; ++i)
      for (int j = 0; j < cols; ++j) m(i, j) = gauss(random);
    return m;
  };
  const int n = kShots * kStrike + kConstants;
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(kShots * kRows, n);
  const Eigen::VectorXd r = random_matrix(kShots * kRows, 1);
  std::vector<ShotBlocks> blocks;
  for (int s = 0; s < kShots; ++s) {
    Eigen::MatrixXd shot(kRows, kStrike + kConstants);
    shot << random_matrix(kRows, kStrike), random_matrix(kRows, kConstants);
    j.block(s * kRows, s * kStrike, kRows, kStrike) = shot.leftCols(kStrike);
    j.block(s * kRows, kShots * kStrike, kRows, kConstants) = shot.rightCols(kConstants);
    const Eigen::VectorXd rs = r.segment(s * kRows, kRows);
    blocks.push_back(BlocksOf(shot, kStrike, std::vector<double>(rs.data(), rs.data() + kRows)));
  }
  Eigen::MatrixXd a = j.transpose() * j;
  a.diagonal() += kLambda * a.diagonal().eval();
  const Eigen::VectorXd step = -a.ldlt().solve(j.transpose() * r);

  const Reduced reduced = Reduce(blocks, kConstants, kLambda);
  const Eigen::VectorXd dc = -reduced.s.ldlt().solve(reduced.g);
  EXPECT_LT((dc - step.tail(kConstants)).norm(), 1e-9 * step.norm());
  for (int s = 0; s < kShots; ++s) {
    const Eigen::VectorXd ds = -reduced.a_inv[s] * (blocks[s].gs + blocks[s].sc * dc);
    EXPECT_LT((ds - step.segment(s * kStrike, kStrike)).norm(), 1e-9 * step.norm()) << s;
  }
}

// One ball struck alone, where and as SyntheticScenes' first ball is, tracked without noise.
std::vector<TrackedShot> LoneBallShots(const table::TableGeometry& table,
                                       const physics::ModelParameters& truth,
                                       std::vector<Strike>* strikes) {
  std::vector<TrackedShot> shots;
  for (const SyntheticScene& scene : SyntheticScenes(table, truth.ball.radius, 3, 6)) {
    strikes->push_back(scene.strike);
    shots.push_back(SimulateTrackedShot(table, truth, {scene.starts[0]}, 0, scene.strike, 6.0,
                                        kSyntheticPeriod, 0.0, 0.0, 0));
  }
  return shots;
}

struct LoneBallProblem {
  table::TableGeometry table = Carom();
  physics::ModelParameters truth =
      WithConstants(params::LoadParameters("carom"), {Constant::kMu}, {0.18});
  std::vector<Strike> strikes;
  std::vector<TrackedShot> shots = LoneBallShots(table, truth, &strikes);
  std::vector<Constant> constants = {Constant::kMu, Constant::kBallBall};
  FitOptions options;
  batch::ThreadPool pool{2};
  JointProblem problem{table, truth, shots, {0, 1, 2}, constants, options, pool};

  std::vector<std::vector<double>> StrikeVectors() const {
    std::vector<std::vector<double>> x;
    for (std::size_t i = 0; i < shots.size(); ++i)
      x.push_back(ToVector(strikes[i], Layout(options, truth.ball.radius, shots[i])));
    return x;
  }
  std::vector<double> TrueValues() const {
    return {truth.contact.mu, truth.collision.ball_restitution};
  }
};

// At the truth of noiseless shots the residuals vanish, and with them the gradient; the cloth's
// friction, which every slide shows, has a column, the balls' restitution, which no shot of one
// ball excites, none at all.
TEST(JointProblem, AtTheTruthTheGradientVanishesAndAnUnexcitedConstantHasNoColumn) {
  LoneBallProblem lone;
  const std::vector<std::vector<double>> x = lone.StrikeVectors();
  const std::vector<ShotBlocks> blocks = lone.problem.LinearizeAll(x, lone.TrueValues());
  ASSERT_EQ(blocks.size(), 3u);
  for (std::size_t s = 0; s < blocks.size(); ++s) {
    const ShotBlocks& b = blocks[s];
    EXPECT_LT(b.squares, 1e-20);
    EXPECT_LT(b.gc.norm(), 1e-9);
    EXPECT_GT(b.cc(0, 0), 1.0);
    EXPECT_EQ(b.cc(1, 1), 0.0);
    EXPECT_EQ(b.sc.col(1).norm(), 0.0);
    EXPECT_EQ(b.residuals, 2 * lone.problem.Samples(s));
  }
}

// From a friction 5 % off and the true strikes, the joint solve finds the friction the shots
// were made with, and leaves the strikes where they were.
TEST(SolveJoint, RecoversTheFrictionOfNoiselessShots) {
  LoneBallProblem lone;
  lone.constants = {Constant::kMu};
  std::vector<std::vector<double>> x = lone.StrikeVectors();
  const std::vector<std::vector<double>> truth = x;
  std::vector<double> values = {0.95 * lone.truth.contact.mu};
  SolveJoint(lone.problem, lone.options, &x, &values);
  EXPECT_NEAR(values[0], lone.truth.contact.mu, 1e-4 * lone.truth.contact.mu);
  for (std::size_t s = 0; s < x.size(); ++s)
    EXPECT_NEAR(x[s][0], truth[s][0], 1e-3 * truth[s][0]) << "the speed of shot " << s;
}

// A shot whose strike is far off (its RMSE decimetres where the others' are millimetres) is no
// inlier; the others are.
TEST(Inliers, LeaveOutAShotFarFromTheMedian) {
  LoneBallProblem lone;
  std::vector<std::vector<double>> x = lone.StrikeVectors();
  x[0][0] *= 1.001;  // each speed a little off
  x[1][0] *= 1.002;
  x[2][0] *= 0.999;
  EXPECT_EQ(Inliers(lone.problem, x, lone.TrueValues(), 3.0), (std::vector<std::size_t>{0, 1, 2}));
  x[1][1] += 0.3;  // shot 1's heading far off
  EXPECT_EQ(Inliers(lone.problem, x, lone.TrueValues(), 3.0), (std::vector<std::size_t>{0, 2}));
}

TEST(Median, OfOddAndEvenCountsAndOfNone) {
  EXPECT_EQ(Median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_EQ(Median({4.0, 1.0, 3.0, 2.0}), 2.5);
  EXPECT_EQ(Median({}), 0.0);
}

}  // namespace
}  // namespace billiard::shot_fit
