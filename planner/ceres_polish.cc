#include "planner/ceres_polish.h"

#include <ceres/ceres.h>

#include <algorithm>

namespace billiard::planner {

namespace {

// Ends the refinement as soon as the miss is small enough, where Ceres' relative tolerances would
// either stop early (large target distances) or go on polishing nanometres.
class StopWhenClose : public ceres::IterationCallback {
 public:
  explicit StopWhenClose(double miss) : cost_(0.5 * miss * miss) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    return s.cost < cost_ ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }

 private:
  double cost_;
};

// Ceres' own convergence tests, set below anything the miss tolerance reaches: StopWhenClose
// ends the refinement, or the iteration limit.
constexpr double kFunctionTolerance = 1e-16;
constexpr double kGradientTolerance = 1e-16;
constexpr double kParameterTolerance = 1e-14;

// The miss with the sensitivity Jacobian, for Ceres: Ceres asks for the Jacobian at each accepted
// point right after its residuals, and the shot's one simulation of the point serves both.
class ArrivalMiss : public ceres::SizedCostFunction<2, 2> {
 public:
  explicit ArrivalMiss(Shot* shot) : shot_(shot) {}

  bool Evaluate(double const* const* p, double* residuals, double** jacobians) const override {
    Eigen::Vector2d miss;
    Eigen::Matrix2d jacobian;
    if (!shot_->Miss(p[0][0], p[0][1], &miss, &jacobian)) return false;
    Eigen::Map<Eigen::Vector2d> residual(residuals);
    residual = miss;
    if (jacobians && jacobians[0]) {
      Eigen::Map<Eigen::Matrix<double, 2, 2, Eigen::RowMajor>> derivative(jacobians[0]);
      derivative = jacobian;
    }
    return true;
  }

 private:
  Shot* shot_;
};

// The miss alone, for ceres::NumericDiffCostFunction.
struct MissAlone {
  Shot* shot;
  bool operator()(const double* p, double* residual) const {
    Eigen::Vector2d miss;
    if (!shot->Miss(p[0], p[1], &miss, nullptr)) return false;
    Eigen::Map<Eigen::Vector2d>(residual, 2) = miss;
    return true;
  }
};

}  // namespace

int Polish(Shot& shot, double launch[2], int iterations) {
  // Ceres would simulate its first point again for its Jacobian only to stop there.
  if (iterations <= 0) return 0;
  const physics::LaunchSpeedRange& speeds = shot.speeds();
  ceres::Problem problem;
  if (shot.options().jacobian == JacobianMethod::kSensitivities) {
    problem.AddResidualBlock(new ArrivalMiss(&shot), nullptr, launch);
  } else {
    problem.AddResidualBlock(
        new ceres::NumericDiffCostFunction<MissAlone, ceres::CENTRAL, 2, 2>(new MissAlone{&shot}),
        nullptr, launch);
  }
  problem.SetParameterLowerBound(launch, 0, speeds.min);
  problem.SetParameterUpperBound(launch, 0, speeds.max);
  launch[0] = std::clamp(launch[0], speeds.min, speeds.max);
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.num_threads = 1;
  solver.logging_type = ceres::SILENT;
  solver.max_num_iterations = iterations;
  solver.function_tolerance = kFunctionTolerance;
  solver.gradient_tolerance = kGradientTolerance;
  solver.parameter_tolerance = kParameterTolerance;
  StopWhenClose stop(shot.options().miss_tolerance);
  solver.callbacks.push_back(&stop);
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  return static_cast<int>(summary.iterations.size()) - 1;
}

}  // namespace billiard::planner
