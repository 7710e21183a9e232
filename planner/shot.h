// The shot once its spin is held: the launch as speed and heading (the two unknowns of the
// refinement, shot_planner.h), the launch speeds the cue gives with that spin, and the 5-DOF
// simulations that say where a launch arrives, each launch simulated once.
//
// The closed form's launch (closed_form_inverse.h) fixes the spin: R w / v across the line to the
// target, and the side spin wz asked. The refinement keeps both and varies the speed s and the
// heading theta alone. Its steps read the shot through this class: Aim (newton_aim.h), Polish
// (ceres_polish.h), BeyondReach (reachability.h), Predict and Conclude (plan_assembly.h).
#pragma once

#include <Eigen/Core>
#include <deque>

#include "planner/closed_form_inverse.h"
#include "planner/shot_planner.h"
#include "sim/physics/ball_state.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/physics/simulator.h"

namespace billiard::planner {

// The launch of a straight shot as the refinement parametrises it: speed s along the heading
// theta, spin across the line R w = k s, side spin wz held; and, for a cue raised to the slope
// t = tan(elevation) (PlannerOptions::elevation), the spin about the travel wz t that its side
// spin comes with: the impulse tilted down by t is perpendicular to the spin it gives
// (w = P x J / I), so w . e = wz t (physics::StrokeFor). Without side spin an elevated cue gives
// the level launch (the table takes the rest).
class Launch {
 public:
  Launch(const Eigen::Vector2d& from, double spin_ratio, double side_spin, double radius, double slope = 0.0)
      : from_(from), k_(spin_ratio), wz_(side_spin), r_(radius), along_(side_spin * slope) {}

  physics::BallState State(double speed, double heading) const;

  // d State / d (speed, heading).
  Eigen::Matrix<double, 7, 2> Derivative(double speed, double heading) const;

 private:
  Eigen::Vector2d from_;
  double k_, wz_, r_;
  double along_;  // the spin about the travel [rad/s]
};

// Step 2 of PlanShot: the closed form's launch as the refinement parametrises it, the spin it
// chose held, and the launch speeds the cue gives with that spin (LaunchSpeedsFor).
struct HeldSpin {
  double speed = 0.0, heading = 0.0;  // the closed form's launch, where the refinement starts
  double spin_ratio = 0.0;            // its R w / v across the line
  physics::LaunchSpeedRange speeds;   // with the side spin asked; min > max when no stroke gives it
};
HeldSpin HoldTheSpin(const ShotRequest& q, const LaunchSolution& guess,
                     const physics::ModelParameters& params);

// The shot once its spin is fixed: the launch as speed and heading, their bounds, and the
// simulations that measure where it arrives. Holds references to the request, the parameters
// and the options, which must outlive it.
class Shot {
 public:
  // The shot of `q` with the spin `held` (whose speeds must not be empty), its runs given a time
  // to arrive from the closed form's (kArrivalTimeFactor in shot.cc). Throws as
  // ClosedFormTrajectory does.
  Shot(const ShotRequest& q, const HeldSpin& held, const physics::ModelParameters& params,
       const PlannerOptions& options);

  // Where a launch at (speed, heading) arrives (its speed down to the final speed, or at rest),
  // with d state / d initial state there when `with_sensitivity`. Each launch is simulated once:
  // the refinement starts from the closed-form launch, already simulated for its miss, and ends
  // on the launch that becomes the plan, whose prediction reads that run again (a run with
  // sensitivities has the same states as one without). Throws as SimulateArrival does.
  const physics::Arrival& Arrive(double speed, double heading, bool with_sensitivity);

  // Whether the refinement takes its Jacobian from the sensitivities, so that a first simulation
  // should carry them.
  bool NeedsSensitivities() const {
    return options_.refine && options_.jacobian == JacobianMethod::kSensitivities;
  }

  // The miss at the target (arrival minus target) of a launch, and, when `jacobian` is not null,
  // its derivative with respect to (speed, heading) from the sensitivities; false when the
  // simulation fails (Ceres then shrinks its step).
  bool Miss(double speed, double heading, Eigen::Vector2d* miss, Eigen::Matrix2d* jacobian);

  // Whether the run of a launch already simulated is within the miss tolerance.
  bool Close(const double launch[2]);

  int simulations() const { return simulations_; }

  const ShotRequest& request() const { return q_; }
  const physics::ModelParameters& params() const { return params_; }
  const PlannerOptions& options() const { return options_; }
  const Launch& launch() const { return launch_; }
  const physics::LaunchSpeedRange& speeds() const { return speeds_; }

 private:
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

}  // namespace billiard::planner
