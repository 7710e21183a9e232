#include "planner/shot.h"

#include <cmath>
#include <exception>

#include "sim/physics/closed_form.h"

namespace billiard::planner {

namespace {

// The 5-DOF ball, which side spin and rolling resistance while sliding slow down differently
// from the closed form, is given kArrivalTimeFactor times the closed form's time to the final
// speed, plus kArrivalTimeMargin, to arrive.
constexpr double kArrivalTimeFactor = 3.0;
constexpr double kArrivalTimeMargin = 5.0;  // [s]

double ArrivalTimeLimit(const ShotRequest& q, const HeldSpin& held, const Launch& launch,
                        const physics::ModelParameters& params) {
  const physics::ClosedFormTrajectory closed_form(physics::ClosedFormParameters::From(params),
                                                  launch.State(held.speed, held.heading));
  return kArrivalTimeFactor * closed_form.TimeAtSpeed(q.final_speed) + kArrivalTimeMargin;
}

}  // namespace

physics::BallState Launch::State(double speed, double heading) const {
  const Eigen::Vector2d e(std::cos(heading), std::sin(heading));
  const double spin = k_ * speed / r_;  // about z x e
  return physics::MakeBallState(from_.x(), from_.y(), speed * e.x(), speed * e.y(), -spin * e.y() + along_ * e.x(),
                                spin * e.x() + along_ * e.y(), wz_);
}

Eigen::Matrix<double, 7, 2> Launch::Derivative(double speed, double heading) const {
  const Eigen::Vector2d e(std::cos(heading), std::sin(heading));
  const double kr = k_ / r_;
  Eigen::Matrix<double, 7, 2> d = Eigen::Matrix<double, 7, 2>::Zero();
  d.col(0) << 0, 0, e.x(), e.y(), -kr * e.y(), kr * e.x(), 0;
  d.col(1) << 0, 0, -speed * e.y(), speed * e.x(), -kr * speed * e.x() - along_ * e.y(),
      -kr * speed * e.y() + along_ * e.x(), 0;
  return d;
}

HeldSpin HoldTheSpin(const ShotRequest& q, const LaunchSolution& guess,
                     const physics::ModelParameters& params) {
  const double r = params.ball.radius;
  HeldSpin held;
  held.speed = guess.v0.norm();
  const Eigen::Vector2d e0 = guess.v0 / held.speed;
  held.heading = std::atan2(e0.y(), e0.x());
  held.spin_ratio = r * (e0.x() * guess.w0.y() - e0.y() * guess.w0.x()) / held.speed;
  held.speeds = physics::LaunchSpeedsFor(held.spin_ratio, q.side_spin, params);
  return held;
}

Shot::Shot(const ShotRequest& q, const HeldSpin& held, const physics::ModelParameters& params,
           const PlannerOptions& options)
    : q_(q),
      params_(params),
      options_(options),
      launch_(q.from, held.spin_ratio, q.side_spin, params.ball.radius, std::tan(options.elevation)),
      speeds_(held.speeds),
      t_max_(ArrivalTimeLimit(q, held, launch_, params)) {}

const physics::Arrival& Shot::Arrive(double speed, double heading, bool with_sensitivity) {
  for (const Run& run : runs_) {
    if (run.speed == speed && run.heading == heading &&
        (run.arrival.sensitivity || !with_sensitivity)) {
      return run.arrival;
    }
  }
  ++simulations_;
  runs_.push_back({speed, heading,
                   physics::SimulateArrival(params_, launch_.State(speed, heading), q_.final_speed,
                                            t_max_, options_.simulation, with_sensitivity)});
  return runs_.back().arrival;
}

bool Shot::Miss(double speed, double heading, Eigen::Vector2d* miss, Eigen::Matrix2d* jacobian) {
  try {
    const physics::Arrival& a = Arrive(speed, heading, jacobian != nullptr);
    *miss = a.state.head<2>() - q_.to;
    if (jacobian) *jacobian = a.sensitivity->topRows<2>() * launch_.Derivative(speed, heading);
  } catch (const std::exception&) {
    return false;
  }
  return true;
}

bool Shot::Close(const double launch[2]) {
  return (Arrive(launch[0], launch[1], false).state.head<2>() - q_.to).norm() <
         options_.miss_tolerance;
}

}  // namespace billiard::planner
