#include "planner/shot_planner.h"

#include <ceres/ceres.h>

#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>

namespace billiard::planner {

std::string PlanStatusName(PlanStatus status) {
  switch (status) {
    case PlanStatus::kOk:
      return "ok";
    case PlanStatus::kInvalid:
      return "invalid";
    case PlanStatus::kOffTable:
      return "off_table";
    case PlanStatus::kUnreachable:
      return "unreachable";
    case PlanStatus::kNotConverged:
      return "not_converged";
  }
  return "?";
}

physics::SimulationOptions PlannerOptions::DefaultRefinementSimulation() {
  physics::SimulationOptions o;
  o.model = physics::Model::kApproximate;
  o.integrator = physics::Integrator::kRodas4;
  // Endpoints within about 0.4 um of the converged model (docs/benchmarks/report.md), at two
  // thirds of the cost of the simulator's default.
  o.tolerance = 1e-6;
  return o;
}

namespace {

std::string Millimetres(double metres) {
  std::ostringstream s;
  s.precision(3);
  s << metres * 1e3 << " mm";
  return s.str();
}

// The launch of a straight shot as the refinement parametrises it: speed s along the heading
// theta, spin across the line R w = k s, side spin wz held.
class Launch {
 public:
  Launch(const Eigen::Vector2d& from, double spin_ratio, double side_spin, double radius)
      : from_(from), k_(spin_ratio), wz_(side_spin), r_(radius) {}

  physics::BallState State(double speed, double heading) const {
    const Eigen::Vector2d e(std::cos(heading), std::sin(heading));
    const double spin = k_ * speed / r_;  // about z x e
    return physics::MakeBallState(from_.x(), from_.y(), speed * e.x(), speed * e.y(), -spin * e.y(),
                                  spin * e.x(), wz_);
  }

  // d State / d (speed, heading).
  Eigen::Matrix<double, 7, 2> Derivative(double speed, double heading) const {
    const Eigen::Vector2d e(std::cos(heading), std::sin(heading));
    const double kr = k_ / r_;
    Eigen::Matrix<double, 7, 2> d = Eigen::Matrix<double, 7, 2>::Zero();
    d.col(0) << 0, 0, e.x(), e.y(), -kr * e.y(), kr * e.x(), 0;
    d.col(1) << 0, 0, -speed * e.y(), speed * e.x(), -kr * speed * e.x(), -kr * speed * e.y(), 0;
    return d;
  }

 private:
  Eigen::Vector2d from_;
  double k_, wz_, r_;
};

// The miss at the target, (X, Y) of the arrival minus the target, as a function of the launch
// speed and heading.
struct MissFunction {
  const physics::ModelParameters& params;
  const physics::SimulationOptions& simulation;
  Launch launch;
  const ShotRequest& request;
  double t_max;
  int* simulations;  // counts the simulations run

  // The miss, and its Jacobian from the sensitivities when `jacobian` is not null; false when
  // the simulation fails (Ceres then shrinks its step).
  bool Evaluate(double speed, double heading, Eigen::Vector2d* miss,
                Eigen::Matrix2d* jacobian) const {
    ++*simulations;
    physics::Arrival a;
    try {
      a = physics::SimulateArrival(params, launch.State(speed, heading), request.final_speed, t_max,
                                   simulation, jacobian != nullptr);
    } catch (const std::exception&) {
      return false;
    }
    *miss = a.state.head<2>() - request.to;
    if (jacobian) *jacobian = a.sensitivity->topRows<2>() * launch.Derivative(speed, heading);
    return true;
  }

  // The residual alone, for ceres::NumericDiffCostFunction.
  bool operator()(const double* p, double* residual) const {
    Eigen::Vector2d miss;
    if (!Evaluate(p[0], p[1], &miss, nullptr)) return false;
    Eigen::Map<Eigen::Vector2d>(residual, 2) = miss;
    return true;
  }
};

// MissFunction with the sensitivity Jacobian. Every evaluation integrates the sensitivities and
// keeps the Jacobian, because Ceres asks for the Jacobian at each accepted point right after its
// residuals: one simulation per point instead of two.
class ArrivalMiss : public ceres::SizedCostFunction<2, 2> {
 public:
  explicit ArrivalMiss(const MissFunction& f) : f_(f) {}

  bool Evaluate(double const* const* p, double* residuals, double** jacobians) const override {
    const double speed = p[0][0], heading = p[0][1];
    if (speed != cached_speed_ || heading != cached_heading_) {
      if (!f_.Evaluate(speed, heading, &miss_, &jacobian_)) return false;
      cached_speed_ = speed;
      cached_heading_ = heading;
    }
    Eigen::Map<Eigen::Vector2d> residual(residuals);
    residual = miss_;
    if (jacobians && jacobians[0]) {
      Eigen::Map<Eigen::Matrix<double, 2, 2, Eigen::RowMajor>> jacobian(jacobians[0]);
      jacobian = jacobian_;
    }
    return true;
  }

 private:
  MissFunction f_;
  mutable double cached_speed_ = NAN, cached_heading_ = NAN;
  mutable Eigen::Vector2d miss_;
  mutable Eigen::Matrix2d jacobian_;
};

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

bool OnTable(const Eigen::Vector2d& x, const physics::ModelParameters& p) {
  const double r = p.ball.radius;
  return x.x() >= r && x.x() <= p.table.length - r && x.y() >= r && x.y() <= p.table.width - r;
}

ShotPlan Refused(PlanStatus status, std::string reason) {
  ShotPlan plan;
  plan.status = status;
  plan.reason = std::move(reason);
  return plan;
}

// The 5-DOF ball, which side spin and rolling resistance while sliding slow down differently
// from the closed form, is given kArrivalTimeFactor times the closed form's time to the final
// speed, plus kArrivalTimeMargin, to arrive.
constexpr double kArrivalTimeFactor = 3.0;
constexpr double kArrivalTimeMargin = 5.0;  // [s]

// Ceres' own convergence tests, set below anything the miss tolerance reaches: StopWhenClose
// ends the refinement, or the iteration limit.
constexpr double kFunctionTolerance = 1e-16;
constexpr double kGradientTolerance = 1e-16;
constexpr double kParameterTolerance = 1e-14;

// Step 1: a sound request and parameter set, start and target on the table, and a closed-form
// launch that reaches the target; the refusal otherwise.
std::optional<ShotPlan> CheckRequest(const ShotRequest& q, const physics::ModelParameters& params,
                                     LaunchSolution* guess) {
  try {
    physics::ValidateParameters(params);
  } catch (const std::invalid_argument& e) {
    return Refused(PlanStatus::kInvalid, std::string("invalid parameters: ") + e.what());
  }
  *guess = InvertClosedForm(q, physics::ClosedFormParameters::From(params));
  if (guess->malformed) return Refused(PlanStatus::kInvalid, guess->reason);
  if (!OnTable(q.from, params)) {
    return Refused(PlanStatus::kOffTable, "the ball is not on the playing surface");
  }
  if (!OnTable(q.to, params)) {
    return Refused(PlanStatus::kOffTable,
                   "the target is beyond the playing surface (its centre must stay a radius "
                   "inside the " +
                       std::to_string(params.table.length) + " x " +
                       std::to_string(params.table.width) + " m table)");
  }
  if (!guess->ok) return Refused(PlanStatus::kUnreachable, guess->reason);
  return std::nullopt;
}

std::string NoStrokeGivesTheSpin(double spin_ratio, const ShotRequest& q,
                                 const physics::ModelParameters& params) {
  std::ostringstream reason;
  reason.precision(3);
  reason << "no stroke gives this spin (R w / v = " << spin_ratio
         << " across the line, wz = " << q.side_spin << " rad/s) within the robot's tip offset of "
         << params.cue.max_tip_offset << " r and cue speed of " << params.cue.max_speed << " m/s";
  return reason.str();
}

// The shot once its spin is fixed: the launch as speed and heading, their bounds, and the
// simulations that measure where it arrives.
class Shot {
 public:
  Shot(const ShotRequest& q, const physics::ModelParameters& params, const PlannerOptions& options,
       const Launch& launch, const physics::LaunchSpeedRange& speeds, double t_max)
      : q_(q),
        params_(params),
        options_(options),
        launch_(launch),
        speeds_(speeds),
        t_max_(t_max) {}

  // Where a launch at (speed, heading) arrives (its speed down to the final speed, or at rest).
  physics::Arrival Simulate(double speed, double heading, int* simulations) const {
    ++*simulations;
    return physics::SimulateArrival(params_, launch_.State(speed, heading), q_.final_speed, t_max_,
                                    options_.simulation);
  }

  // The residual of the refinement, for Ceres.
  MissFunction Miss(int* simulations) const {
    return {params_, options_.simulation, launch_, q_, t_max_, simulations};
  }

  // Turning the heading turns the whole path about the ball, so how far the ball gets depends on
  // the launch speed alone, and grows with it: a speed at a bound that already carries the ball
  // past the target (or still leaves it short) decides the request without a refinement.
  std::optional<std::string> BeyondReach(double speed, int* simulations) const {
    const bool slowest = speed <= speeds_.min, fastest = speed >= speeds_.max;
    if (!slowest && !fastest) return std::nullopt;
    const double bound = slowest ? speeds_.min : speeds_.max;
    const double distance = (q_.to - q_.from).norm();
    const double travel = (Simulate(bound, 0.0, simulations).state.head<2>() - q_.from).norm();
    std::ostringstream reason;
    reason.precision(3);
    if (slowest && travel > distance + options_.acceptable_miss) {
      reason << "the side spin needs a launch of at least " << bound << " m/s to stay within "
             << "the tip offset of " << params_.cue.max_tip_offset << " r, which carries the "
             << "ball " << travel << " m, past the target";
      return reason.str();
    }
    if (fastest && travel < distance - options_.acceptable_miss) {
      reason << "needs a faster launch than the robot's cue speed of " << params_.cue.max_speed
             << " m/s gives (at most " << bound << " m/s, which reaches " << travel << " m)";
      return reason.str();
    }
    return std::nullopt;
  }

  // Step 3: Levenberg-Marquardt on (speed, heading) within the speed bounds, from `launch`;
  // returns the iterations.
  int Refine(double launch[2], int* simulations) const {
    ceres::Problem problem;
    const MissFunction miss = Miss(simulations);
    if (options_.jacobian == JacobianMethod::kSensitivities) {
      problem.AddResidualBlock(new ArrivalMiss(miss), nullptr, launch);
    } else {
      problem.AddResidualBlock(
          new ceres::NumericDiffCostFunction<MissFunction, ceres::CENTRAL, 2, 2>(
              new MissFunction(miss)),
          nullptr, launch);
    }
    problem.SetParameterLowerBound(launch, 0, speeds_.min);
    problem.SetParameterUpperBound(launch, 0, speeds_.max);
    launch[0] = std::clamp(launch[0], speeds_.min, speeds_.max);
    ceres::Solver::Options solver;
    solver.linear_solver_type = ceres::DENSE_QR;
    solver.num_threads = 1;
    solver.logging_type = ceres::SILENT;
    solver.max_num_iterations = options_.max_iterations;
    solver.function_tolerance = kFunctionTolerance;
    solver.gradient_tolerance = kGradientTolerance;
    solver.parameter_tolerance = kParameterTolerance;
    StopWhenClose stop(options_.miss_tolerance);
    solver.callbacks.push_back(&stop);
    ceres::Solver::Summary summary;
    ceres::Solve(solver, &problem, &summary);
    return static_cast<int>(summary.iterations.size()) - 1;
  }

  // Step 4: the planned launch simulated once more: the launch state, where and when it arrives,
  // the path there, and the miss. Whether it arrived (within the time limit).
  bool Predict(const double launch[2], ShotPlan* plan) const {
    const physics::Arrival arrival = Simulate(launch[0], launch[1], &plan->simulations);
    const physics::BallState start = arrival.trajectory->At(0.0);
    plan->v0 = start.segment<2>(physics::kVx);
    plan->w0 = start.segment<3>(physics::kWx);
    plan->predicted_final = arrival.state.head<2>();
    plan->arrival_time = arrival.time;
    plan->refined_miss_m = (plan->predicted_final - q_.to).norm();
    const int samples =
        std::max(1, static_cast<int>(std::ceil(arrival.time / options_.path_sample_dt)));
    for (int i = 0; i <= samples; ++i) {
      const double t = arrival.time * i / samples;
      plan->predicted_path.push_back(i == samples
                                         ? plan->predicted_final
                                         : Eigen::Vector2d(arrival.trajectory->At(t).head<2>()));
    }
    return arrival.reached;
  }

  // Step 5: the verdict on the prediction: converged, on the table all the way, and a stroke the
  // robot can give.
  void Conclude(const double launch[2], bool arrived, ShotPlan* plan) const {
    if (!arrived || (options_.refine && plan->refined_miss_m > options_.acceptable_miss)) {
      if (auto reason = BeyondReach(launch[0], &plan->simulations)) {
        plan->status = PlanStatus::kUnreachable;
        plan->reason = *reason;
      } else {
        plan->status = PlanStatus::kNotConverged;
        plan->reason = "refinement ended " + Millimetres(plan->refined_miss_m) + " from the target";
      }
      return;
    }
    for (const Eigen::Vector2d& x : plan->predicted_path) {
      if (!OnTable(x, params_)) {
        plan->status = PlanStatus::kUnreachable;
        plan->reason = "the path leaves the playing surface (a cushion is in the way)";
        return;
      }
    }
    const physics::StrokeSolution stroke = physics::StrokeFor(plan->v0, plan->w0, params_);
    if (!stroke.ok) {
      plan->status = PlanStatus::kUnreachable;
      plan->reason = stroke.reason;
      return;
    }
    plan->stroke = stroke.stroke;
    plan->status = PlanStatus::kOk;
  }

 private:
  const ShotRequest& q_;
  const physics::ModelParameters& params_;
  const PlannerOptions& options_;
  Launch launch_;
  physics::LaunchSpeedRange speeds_;
  double t_max_;
};

ShotPlan Plan(const ShotRequest& q, const physics::ModelParameters& params,
              const PlannerOptions& options) {
  LaunchSolution guess;
  if (auto refusal = CheckRequest(q, params, &guess)) return *refusal;

  // Step 2: the spin the closed form chose, held, and the launch speeds the cue gives with it.
  const double r = params.ball.radius;
  const double speed0 = guess.v0.norm();
  const Eigen::Vector2d e0 = guess.v0 / speed0;
  const double heading0 = std::atan2(e0.y(), e0.x());
  const double spin_ratio = r * (e0.x() * guess.w0.y() - e0.y() * guess.w0.x()) / speed0;
  const physics::LaunchSpeedRange speeds =
      physics::LaunchSpeedsFor(spin_ratio, q.side_spin, params);
  if (speeds.min > speeds.max) {
    return Refused(PlanStatus::kUnreachable, NoStrokeGivesTheSpin(spin_ratio, q, params));
  }
  const Launch launch(q.from, spin_ratio, q.side_spin, r);
  const physics::ClosedFormTrajectory closed_form(physics::ClosedFormParameters::From(params),
                                                  launch.State(speed0, heading0));
  const double t_max =
      kArrivalTimeFactor * closed_form.TimeAtSpeed(q.final_speed) + kArrivalTimeMargin;
  const Shot shot(q, params, options, launch, speeds, t_max);

  ShotPlan plan;
  plan.slide_length = guess.slide_length;
  double p[2] = {speed0, heading0};
  // Not through the refinement's residual, which hides why a simulation failed: that reason (a
  // step budget, say) is what the refusal must report.
  plan.closed_form_miss_m =
      (shot.Simulate(p[0], p[1], &plan.simulations).state.head<2>() - q.to).norm();
  if (auto reason = shot.BeyondReach(p[0], &plan.simulations)) {
    return Refused(PlanStatus::kUnreachable, *reason);
  }
  if (options.refine) plan.iterations = shot.Refine(p, &plan.simulations);
  const bool arrived = shot.Predict(p, &plan);
  shot.Conclude(p, arrived, &plan);
  return plan;
}

}  // namespace

ShotPlan PlanShot(const ShotRequest& request, const physics::ModelParameters& params,
                  const PlannerOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  ShotPlan plan;
  try {
    plan = Plan(request, params, options);
  } catch (const std::exception& e) {
    plan = Refused(PlanStatus::kNotConverged, std::string("simulation failed: ") + e.what());
  }
  plan.solve_us =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
  return plan;
}

}  // namespace billiard::planner
