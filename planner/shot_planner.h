// The shot planner: from where the ball is and where it must go, how to strike it.
//
//   1. closed-form inverse (closed_form_inverse.h): a straight shot under the sliding-then-rolling
//      model, exact for that model and centimetres off the 5-DOF ball on spin-heavy shots;
//   2. refinement against the 5-DOF simulation (approximate model by default): the unknowns are
//      the launch speed and heading, the spin choice (R w / v across the line, and the side spin
//      wz as asked) is held, and the residual is the miss at the target, where the simulated
//      speed falls to the requested value (or the ball comes to rest). Turning the heading turns
//      the whole path about the ball, so the refinement is Newton's method on the speed alone,
//      the heading following from where each run arrives; its derivative comes from forward
//      sensitivities integrated with the first simulation (sim/physics/sensitivity.h), and
//      later runs, without them, learn the curvature. Where that does not converge, Ceres
//      (Levenberg-Marquardt on speed and heading, a sensitivity run per iteration) finishes;
//   3. the cue stroke that gives that launch (sim/physics/cue_strike.h), within the robot's
//      limits, which also bound the refinement (tip offset, cue speed).
//
// PlanShot's steps, each in its file: the request checked and the closed form's launch (here),
// its spin held and the launch's simulations (shot.h), Newton's method on the speed
// (newton_aim.h), Ceres where that does not converge (ceres_polish.h), the bounds that decide
// reachability (reachability.h), and the plan predicted and judged (plan_assembly.h).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "planner/closed_form_inverse.h"
#include "sim/cue/clearance.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/physics/simulator.h"

namespace billiard::planner {

enum class PlanStatus {
  kOk,
  kInvalid,       // malformed request (non-finite numbers, negative speed, target = start), or
                  // a parameter set ValidateParameters refuses
  kOffTable,      // start or target outside the playing surface (ball centre within r of an edge)
  kUnreachable,   // no stroke within the robot's limits, or outside the model's validity
  kNotConverged,  // the refinement ended with a miss above the tolerance
  kCueBlocked,    // the robot's cue meets the rails, a ball or its body at every elevation it
                  // has (PlanShotForRobot, cue_planning.h)
};

// "ok", "invalid", "off_table", "unreachable", "not_converged", "cue_blocked".
std::string PlanStatusName(PlanStatus status);

// How the refinement gets the derivative of the miss with respect to the launch.
enum class JacobianMethod {
  // Forward sensitivities with the first simulation, then Newton's method on the speed (Ceres
  // with a sensitivity run per iteration where it does not converge); the default.
  kSensitivities,
  // Ceres alone, five simulations per point; kept to measure the difference.
  kCentralDifferences,
};

struct PlannerOptions {
  // The model the plan is refined against: the approximate 5-DOF model with RODAS4 by default.
  physics::SimulationOptions simulation = DefaultRefinementSimulation();
  // The refinement stops once the simulated miss is below this [m]; a plan whose miss stays
  // above `acceptable_miss` is refused as not converged. At 1 um, a tenth of the plans need a
  // correction more than at 2 um (a run without sensitivities, 50 us), and the plans land
  // within 1.3 um of the target when simulated at the simulator's 10x tighter default
  // tolerance, where they landed within 2 um.
  double miss_tolerance = 1e-6;
  double acceptable_miss = 1e-4;
  // Corrections of the launch, Newton's and Ceres' together.
  int max_iterations = 25;
  // The predicted path is sampled at this interval [s] (and at its ends).
  double path_sample_dt = 0.02;
  // Refine against the 5-DOF model; false: the closed-form inverse alone (its miss is still
  // measured against the 5-DOF simulation).
  bool refine = true;
  JacobianMethod jacobian = JacobianMethod::kSensitivities;
  // The cue's elevation the stroke is played at [rad], in [0, pi/2): the launch carries the spin
  // about the travel that side spin comes with at it (its swerve, Launch in shot.h), and the
  // stroke is the one at it (physics::StrokeFor). PlanShotForRobot (cue_planning.h) sets it to
  // what the robot's cue needs; 0, a level cue.
  double elevation = 0.0;

  static physics::SimulationOptions DefaultRefinementSimulation();
};

struct ShotPlan {
  PlanStatus status = PlanStatus::kInvalid;
  std::string reason;  // why not, when status != kOk; empty when ok

  Eigen::Vector2d v0 = Eigen::Vector2d::Zero();  // launch velocity [m/s]
  Eigen::Vector3d w0 = Eigen::Vector3d::Zero();  // launch spin [rad/s]
  physics::CueStroke stroke;

  // The simulated arrival of the planned launch: where its speed falls to the final speed (or it
  // stops), when, and the path there sampled every path_sample_dt.
  Eigen::Vector2d predicted_final = Eigen::Vector2d::Zero();
  double arrival_time = 0.0;
  std::vector<Eigen::Vector2d> predicted_path;

  double closed_form_miss_m = 0.0;  // the closed-form launch simulated with the 5-DOF model
  double refined_miss_m = 0.0;      // the plan simulated with the 5-DOF model
  double solve_us = 0.0;            // wall time of the whole plan
  int iterations = 0;               // corrections of the launch (Newton's and Ceres')
  int simulations = 0;              // 5-DOF simulations run for the plan
  double slide_length = 0.0;        // x1 of the closed-form solution [m]
  // The stroke's cue against a robot's (PlanShotForRobot): it clears, what comes nearest and how
  // near; none when no robot was given.
  std::optional<cue::CueClearance> clearance;
};

// Plans `request` on the table and ball of `params`. Never throws on a bad request: the status
// and reason say what is wrong.
ShotPlan PlanShot(const ShotRequest& request, const physics::ModelParameters& params,
                  const PlannerOptions& options = {});

}  // namespace billiard::planner
