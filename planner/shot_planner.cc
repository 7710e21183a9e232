#include "planner/shot_planner.h"

#include <ceres/ceres.h>

#include <chrono>
#include <cmath>
#include <deque>
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

// Where a run arrives, seen from the ball: its distance from the ball, and the angle from the
// launch heading to the arrival's direction, in (-pi, pi].
struct Reach {
  double reach = 0.0, turn = 0.0;
};

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// The root nearest 0 of f + b x + c x^2 (b > 0); Newton's step where there is none.
double QuadraticRoot(double f, double b, double c) {
  const double discriminant = b * b - 4.0 * c * f;
  return discriminant < 0.0 ? -f / b : -2.0 * f / (b + std::sqrt(discriminant));
}

// Aim's corrections before it hands over to Polish: from centimetres the second lands within
// the tolerance; needing more means the quadratic model does not hold there.
constexpr int kAimSteps = 3;

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

  // Where a launch at (speed, heading) arrives (its speed down to the final speed, or at rest),
  // with d state / d initial state there when `with_sensitivity`. Each launch is simulated once:
  // the refinement starts from the closed-form launch, already simulated for its miss, and ends
  // on the launch that becomes the plan, whose prediction reads that run again (a run with
  // sensitivities has the same states as one without). Throws as SimulateArrival does.
  const physics::Arrival& Arrive(double speed, double heading, bool with_sensitivity) {
    for (const Run& run : runs_) {
      if (run.speed == speed && run.heading == heading &&
          (run.arrival.sensitivity || !with_sensitivity)) {
        return run.arrival;
      }
    }
    ++simulations_;
    runs_.push_back(
        {speed, heading,
         physics::SimulateArrival(params_, launch_.State(speed, heading), q_.final_speed, t_max_,
                                  options_.simulation, with_sensitivity)});
    return runs_.back().arrival;
  }

  // Whether the refinement takes its Jacobian from the sensitivities, so that a first simulation
  // should carry them.
  bool NeedsSensitivities() const {
    return options_.refine && options_.jacobian == JacobianMethod::kSensitivities;
  }

  // The miss at the target (arrival minus target) of a launch, and, when `jacobian` is not null,
  // its derivative with respect to (speed, heading) from the sensitivities; false when the
  // simulation fails (Ceres then shrinks its step).
  bool Miss(double speed, double heading, Eigen::Vector2d* miss, Eigen::Matrix2d* jacobian) {
    try {
      const physics::Arrival& a = Arrive(speed, heading, jacobian != nullptr);
      *miss = a.state.head<2>() - q_.to;
      if (jacobian) *jacobian = a.sensitivity->topRows<2>() * launch_.Derivative(speed, heading);
    } catch (const std::exception&) {
      return false;
    }
    return true;
  }

  int simulations() const { return simulations_; }

  // Whether the run of a launch already simulated is within the miss tolerance.
  bool Close(const double launch[2]) {
    return (Arrive(launch[0], launch[1], false).state.head<2>() - q_.to).norm() <
           options_.miss_tolerance;
  }

  // Step 3a: Newton's method on the launch speed alone. Turning the heading turns the whole path
  // about the ball, so a run at speed s, whatever its heading, says where every heading goes:
  // its reach (distance from the ball) and its turn (the angle from the heading to the arrival)
  // depend on s alone, and the heading that meets the target is the target's bearing minus the
  // turn at the speed that reaches it. Both are modelled as quadratics in the launch's kinetic
  // energy, e = s^2, rather than its speed: friction takes energy by the metre, so the reach is
  // nearly linear in e (exactly so for a ball that rolls to rest), and what the quadratic misses
  // is the little curvature left. The first run, with sensitivities, gives the values and the
  // rates of change; each later run, without, the curvatures through it. On the benchmark's
  // requests one or two corrections take the closed form's centimetres below the tolerance,
  // where Gauss-Newton on (speed, heading) took two runs with sensitivities more. Stops at a
  // failed simulation or a speed beyond the bounds, `launch` at its last good run; returns the
  // corrections made.
  int Aim(double launch[2]);

  // Step 3b: Levenberg-Marquardt (Ceres) on (speed, heading) within the speed bounds, from
  // `launch`, for at most `iterations`; returns the iterations.
  int Polish(double launch[2], int iterations);

  // Turning the heading turns the whole path about the ball, so how far the ball gets depends on
  // the launch speed alone, and grows with it: a speed at a bound that already carries the ball
  // past the target (or still leaves it short) decides the request without a refinement.
  std::optional<std::string> BeyondReach(double speed, double heading) {
    const bool slowest = speed <= speeds_.min, fastest = speed >= speeds_.max;
    if (!slowest && !fastest) return std::nullopt;
    const double bound = slowest ? speeds_.min : speeds_.max;
    const double distance = (q_.to - q_.from).norm();
    const double travel = (Arrive(bound, heading, false).state.head<2>() - q_.from).norm();
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

  // Step 3: the launch corrected until its simulated miss is below the tolerance, within the
  // speed bounds (Aim, then Polish when Aim does not get there); returns the corrections made.
  int Refine(double launch[2]) {
    int iterations = 0;
    if (options_.jacobian == JacobianMethod::kSensitivities) {
      iterations = Aim(launch);
      if (Close(launch)) return iterations;
    }
    return iterations + Polish(launch, options_.max_iterations - iterations);
  }

  // Step 4: the planned launch's arrival: the launch state, where and when it arrives, the path
  // there, and the miss. Whether it arrived (within the time limit).
  bool Predict(const double launch[2], ShotPlan* plan) {
    const physics::Arrival& arrival = Arrive(launch[0], launch[1], false);
    const physics::BallState start = arrival.trajectory->At(0.0);
    plan->v0 = start.segment<2>(physics::kVx);
    plan->w0 = start.segment<3>(physics::kWx);
    plan->predicted_final = arrival.state.head<2>();
    plan->arrival_time = arrival.time;
    plan->refined_miss_m = (plan->predicted_final - q_.to).norm();
    const int samples =
        std::max(1, static_cast<int>(std::ceil(arrival.time / options_.path_sample_dt)));
    plan->predicted_path.reserve(samples + 1);
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
  void Conclude(const double launch[2], bool arrived, ShotPlan* plan) {
    if (!arrived || (options_.refine && plan->refined_miss_m > options_.acceptable_miss)) {
      if (auto reason = BeyondReach(launch[0], launch[1])) {
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
  Reach ReachOf(const physics::Arrival& a, double heading) const {
    const Eigen::Vector2d x = a.state.head<2>() - q_.from;
    return {x.norm(), std::remainder(std::atan2(x.y(), x.x()) - heading, 2.0 * M_PI)};
  }

  struct Run {
    double speed, heading;
    physics::Arrival arrival;
  };

  const ShotRequest& q_;
  const physics::ModelParameters& params_;
  const PlannerOptions& options_;
  Launch launch_;
  physics::LaunchSpeedRange speeds_;
  double t_max_;
  std::deque<Run> runs_;  // every launch simulated, in order (a deque keeps references valid)
  int simulations_ = 0;
};

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

int Shot::Aim(double launch[2]) {
  const Eigen::Vector2d want = q_.to - q_.from;
  const double distance = want.norm(), bearing = std::atan2(want.y(), want.x());
  const double s0 = launch[0];
  const physics::Arrival& first = Arrive(s0, launch[1], true);
  if (Close(launch)) return 0;
  const Reach r0 = ReachOf(first, launch[1]);
  // The rates of change of the reach and the turn with e = s^2, from d x / d s.
  const Eigen::Vector2d x = first.state.head<2>() - q_.from;
  const Eigen::Vector2d dx_de =
      first.sensitivity->topRows<2>() * launch_.Derivative(s0, launch[1]).col(0) / (2.0 * s0);
  const Reach rate{x.dot(dx_de) / r0.reach, Cross(x, dx_de) / x.squaredNorm()};
  if (!(rate.reach > 0.0) || !std::isfinite(rate.turn)) return 0;
  Reach curvature;
  int steps = 0;
  while (steps < std::min(kAimSteps, options_.max_iterations)) {
    const double de = QuadraticRoot(r0.reach - distance, rate.reach, curvature.reach);
    const double speed = std::sqrt(s0 * s0 + de);
    if (!(speed >= speeds_.min && speed <= speeds_.max)) break;
    const double heading = bearing - (r0.turn + (rate.turn + curvature.turn * de) * de);
    Reach r;
    try {
      r = ReachOf(Arrive(speed, heading, false), heading);
    } catch (const std::exception&) {
      break;  // Polish shrinks its step where a simulation fails
    }
    launch[0] = speed;
    launch[1] = heading;
    ++steps;
    if (Close(launch) || de == 0.0) break;
    curvature = {(r.reach - r0.reach - rate.reach * de) / (de * de),
                 (r.turn - r0.turn - rate.turn * de) / (de * de)};
  }
  return steps;
}

int Shot::Polish(double launch[2], int iterations) {
  // Ceres would simulate its first point again for its Jacobian only to stop there.
  if (iterations <= 0) return 0;
  ceres::Problem problem;
  if (options_.jacobian == JacobianMethod::kSensitivities) {
    problem.AddResidualBlock(new ArrivalMiss(this), nullptr, launch);
  } else {
    problem.AddResidualBlock(
        new ceres::NumericDiffCostFunction<MissAlone, ceres::CENTRAL, 2, 2>(new MissAlone{this}),
        nullptr, launch);
  }
  problem.SetParameterLowerBound(launch, 0, speeds_.min);
  problem.SetParameterUpperBound(launch, 0, speeds_.max);
  launch[0] = std::clamp(launch[0], speeds_.min, speeds_.max);
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::DENSE_QR;
  solver.num_threads = 1;
  solver.logging_type = ceres::SILENT;
  solver.max_num_iterations = iterations;
  solver.function_tolerance = kFunctionTolerance;
  solver.gradient_tolerance = kGradientTolerance;
  solver.parameter_tolerance = kParameterTolerance;
  StopWhenClose stop(options_.miss_tolerance);
  solver.callbacks.push_back(&stop);
  ceres::Solver::Summary summary;
  ceres::Solve(solver, &problem, &summary);
  return static_cast<int>(summary.iterations.size()) - 1;
}

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
  Shot shot(q, params, options, launch, speeds, t_max);

  ShotPlan plan;
  plan.slide_length = guess.slide_length;
  double p[2] = {speed0, heading0};
  // Not through the refinement's residual, which hides why a simulation failed: that reason (a
  // step budget, say) is what the refusal must report. With the sensitivities the refinement
  // needs at its first point, which this is.
  plan.closed_form_miss_m =
      (shot.Arrive(p[0], p[1], shot.NeedsSensitivities()).state.head<2>() - q.to).norm();
  if (auto reason = shot.BeyondReach(p[0], p[1])) {
    plan = Refused(PlanStatus::kUnreachable, *reason);
  } else {
    if (options.refine) plan.iterations = shot.Refine(p);
    const bool arrived = shot.Predict(p, &plan);
    shot.Conclude(p, arrived, &plan);
  }
  plan.simulations = shot.simulations();
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
