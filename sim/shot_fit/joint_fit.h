// The strikes of several shots and the constants they share (fit_constants.h), fitted together.
//
// The strikes are independent given the constants; the constants couple them. Alternating
// (strikes with the constants fixed, then constants with the strikes fixed) was tried first and
// barely moved: the blocks are strongly coupled (a faster strike and a higher friction look alike
// for a while). So they are solved jointly, by a Levenberg-Marquardt of our own over the reduced
// system: each shot's Gauss-Newton blocks from central differences of its residuals (one job per
// shot on a batch::ThreadPool), the strikes eliminated by the Schur complement, the constants'
// step solved, each strike's step back-substituted. The sums run in shot order, so the steps
// are the same on any thread count.
//
// Pieces: a difference step that changes a shot's sequence of impacts (ImpactSequence) gives way
// to the one-sided difference on the other side; where both do, the shot says nothing of that
// parameter at that point.
//
// Robust: a shot the model cannot follow (a kiss the tracking lost, a miscue) would pull every
// constant. Inliers leaves out the shots whose RMSE exceeds a multiple of the median, and
// SolveJoint weighs the others by Cauchy's loss of their RMSE.
//
// Module: billiard::shot_fit.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "sim/batch/thread_pool.h"
#include "sim/physics/parameters.h"
#include "sim/shot_fit/fit_constants.h"
#include "sim/shot_fit/strike_fit.h"
#include "sim/shot_fit/tracked_shot.h"
#include "sim/table/table_geometry.h"

namespace billiard::shot_fit {

// The joint problem of the strikes of several shots and the shared constants, linearized at one
// point: for each shot its Gauss-Newton blocks, from central differences of its residuals.
struct ShotBlocks {
  Eigen::MatrixXd ss, sc, cc;  // J_s^T J_s, J_s^T J_c, J_c^T J_c
  Eigen::VectorXd gs, gc;      // J_s^T r, J_c^T r
  double squares = 0.0;
  int residuals = 0;
  // The residuals' autocovariance, unnormalised (LaggedProducts, correlation_time.h).
  std::vector<double> lagged;
};

// The blocks of a shot whose Jacobian is `j` (its first n columns the strike's, the others the
// constants') at residuals `residuals`; `lagged` left empty.
ShotBlocks BlocksOf(const Eigen::MatrixXd& j, std::size_t n, const std::vector<double>& residuals);

// The shots `included` (indices into `shots`), each with its strike vector (strike_fit.h's
// Layout), and the values of `constants`, the others as in `base`; the samples up to `horizon`.
// Holds references to its arguments, which must outlive it.
struct JointProblem {
  // Per included shot: its sum of squares (infinite where it does not simulate) and impacts.
  using Evaluations = std::vector<std::pair<double, std::uint64_t>>;

  const table::TableGeometry& table;
  const physics::ModelParameters& base;  // the constants not fitted
  const std::vector<TrackedShot>& shots;
  std::vector<std::size_t> included;
  const std::vector<Constant>& constants;
  const FitOptions& options;
  batch::ThreadPool& pool;
  double horizon = std::numeric_limits<double>::infinity();  // the samples up to it count

  // Shot s's residuals at (strike, values), empty where it does not simulate, and its impacts.
  struct Evaluation {
    std::vector<double> r;
    std::uint64_t impacts = 0;
    double Squares() const;
  };
  Evaluation Evaluate(std::size_t s, const std::vector<double>& strike,
                      const std::vector<double>& values) const;

  // Shot s's Jacobian at (strike, values), where its evaluation is e0: the strike's columns
  // (DifferenceSteps), then the constants'. Central differences within the piece of the cost
  // the point lies on: a step that changes the impacts gives way to the one-sided difference of
  // the other, and where both do, the shot says nothing of that parameter here (its column is
  // zero).
  Eigen::MatrixXd Jacobian(std::size_t s, const std::vector<double>& strike,
                           const std::vector<double>& values, const Evaluation& e0) const;

  // Shot s's blocks at (strike, values) from its Jacobian, and its residuals' LaggedProducts.
  // Throws std::runtime_error where shot s does not simulate.
  ShotBlocks Linearize(std::size_t s, const std::vector<double>& strike,
                       const std::vector<double>& values) const;

  // Every included shot's blocks (job j: included[j] at strikes[j]), on the pool.
  std::vector<ShotBlocks> LinearizeAll(const std::vector<std::vector<double>>& strikes,
                                       const std::vector<double>& values) const;

  // Each included shot's sum of squares and impacts, on the pool.
  Evaluations EvaluateAll(const std::vector<std::vector<double>>& strikes,
                          const std::vector<double>& values) const;

  // The samples of included shot j up to the horizon (at least 1).
  int Samples(std::size_t j) const;
};

// The reduced system of the constants, the strikes eliminated: with each shot's strike block
// damped as A_s = J_s^T J_s + lambda diag(J_s^T J_s),
//   S = sum_s J_c^T J_c + lambda diag(sum_s J_c^T J_c) - sum_s J_c^T J_s A_s^-1 J_s^T J_c,
//   g = sum_s J_c^T r - J_c^T J_s A_s^-1 J_s^T r.
// The constants' step solves S dc = -g; shot s's step is then -A_s^-1 (J_s^T r + J_s^T J_c dc).
struct Reduced {
  Eigen::MatrixXd s;
  Eigen::VectorXd g;
  std::vector<Eigen::MatrixXd> a_inv;  // per shot
};
Reduced Reduce(const std::vector<ShotBlocks>& blocks, std::size_t k, double lambda);

// Levenberg-Marquardt over the strikes of the included shots and the constants together, by the
// reduced system (each iteration one linearization of every shot on the pool, summed in shot
// order: the same steps on any thread count), within the bounds (a step is clamped to them).
// Robust: shot j of n_j samples and mean squared error e_j costs n_j c^2 log(1 + e_j / c^2)
// (Cauchy's loss of the shot's RMSE, c the median RMSE when the solve starts), so that the
// constants follow the typical shot rather than the few the model cannot follow; iteratively
// reweighted, each shot's blocks weighted by 1 / (1 + e_j / c^2) at each linearization.
void SolveJoint(const JointProblem& problem, const FitOptions& options,
                std::vector<std::vector<double>>* strikes, std::vector<double>* values);

// Of the shots `problem` includes, at (strikes, values), those whose RMSE over the horizon is
// at most `outlier_factor` times the median.
std::vector<std::size_t> Inliers(const JointProblem& problem,
                                 const std::vector<std::vector<double>>& strikes,
                                 const std::vector<double>& values, double outlier_factor);

// The median of `v`; 0 when it is empty.
double Median(std::vector<double> v);

}  // namespace billiard::shot_fit
