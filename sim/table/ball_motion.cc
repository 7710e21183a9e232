#include "sim/table/ball_motion.h"

#include <algorithm>
#include <cmath>

namespace billiard::table {

using physics::BallState;
using physics::kVx;
using physics::kVy;
using physics::kWx;
using physics::kWy;
using physics::kWz;
using physics::kX;

namespace {

// Below these a state is taken as its phase's limit: a slip of 1e-10 m/s closes in 0.1 ns of
// sliding, a speed of 1e-10 m/s moves a ball by an atom's width before rolling resistance stops
// it. The phase ends are set exactly (At), so the thresholds only meet a caller's rounding.
constexpr double kRollingSlip = 1e-10;  // [m/s]
constexpr double kStillSpeed = 1e-10;   // [m/s]
constexpr double kStillSpin = 1e-9;     // [rad/s]

// Ms for pure spin on a uniformly slipping disk (physics notes, section 1).
constexpr double kPivotMoment = 3.0 * M_PI / 16.0;

// The 5-DOF model's friction force stays within mu m g (|T| <= 1 for the integral model, eq. 16;
// the approximation, eq. 17, within a few per cent of it): the bound on its acceleration, with
// a margin.
constexpr double kFiveDofAccelerationMargin = 1.5;

double Sign(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }

}  // namespace

const char* PhaseName(MotionPhase phase) {
  switch (phase) {
    case MotionPhase::kSliding:
      return "sliding";
    case MotionPhase::kRolling:
      return "rolling";
    case MotionPhase::kSpinning:
      return "spinning";
    case MotionPhase::kStationary:
      return "stationary";
    case MotionPhase::kFiveDof:
      return "5-dof";
    case MotionPhase::kAirborne:
      return "airborne";
  }
  return "unknown";
}

ClothParameters ClothParameters::From(const physics::ModelParameters& p) {
  const double r = p.ball.radius;
  return {r, p.ball.gravity, p.contact.mu, p.RollingResistance(),
          2.5 * p.ball.gravity * p.contact.patch_radius * p.contact.mu * kPivotMoment / (r * r)};
}

MotionPhase PhaseOf(const BallState& s, double radius) {
  if (ClothSlip(s, radius).norm() > kRollingSlip) return MotionPhase::kSliding;
  if (s.segment<2>(kVx).norm() > kStillSpeed) return MotionPhase::kRolling;
  return std::abs(s[kWz]) > kStillSpin ? MotionPhase::kSpinning : MotionPhase::kStationary;
}

void MotionSegment::StopSpinAt() {
  const double spin = std::abs(start_[kWz]);
  spin_stop_ = cloth_.spin_decel > 0.0
                   ? spin / cloth_.spin_decel
                   : (spin > 0.0 ? std::numeric_limits<double>::infinity() : 0.0);
}

MotionSegment::MotionSegment(const ClothParameters& cloth, double start_time,
                             const BallState& state)
    : cloth_(cloth), phase_(PhaseOf(state, cloth.radius)), start_time_(start_time), start_(state) {
  StopSpinAt();
  const Eigen::Vector2d v = velocity();
  const Eigen::Vector2d u = ClothSlip(state, cloth.radius);
  double duration = std::numeric_limits<double>::infinity();
  switch (phase_) {
    case MotionPhase::kSliding:
      slip_direction_ = u.normalized();
      acceleration_ = -cloth.mu_slide * cloth.gravity * slip_direction_;
      duration = 2.0 * u.norm() / (7.0 * cloth.mu_slide * cloth.gravity);  // Jaroukh 2019, eq. 8
      break;
    case MotionPhase::kRolling: {
      const double decel = 5.0 / 7.0 * cloth.mu_roll * cloth.gravity;
      acceleration_ = -decel * v.normalized();
      if (decel > 0.0) duration = v.norm() / decel;
      break;
    }
    case MotionPhase::kSpinning:
      duration = spin_stop_;
      break;
    default:
      start_.segment<4>(kVx).setZero();
      start_[kWz] = 0.0;
      break;
  }
  end_time_ = start_time + duration;
  max_acceleration_ = acceleration_.norm();
}

MotionSegment::MotionSegment(const ClothParameters& cloth, double start_time,
                             const BallState& state, const Eigen::Vector2d& acceleration,
                             double longest)
    : cloth_(cloth),
      phase_(PhaseOf(state, cloth.radius)),
      start_time_(start_time),
      start_(state),
      acceleration_(acceleration),
      held_(true) {
  StopSpinAt();
  double duration = longest;
  if (phase_ == MotionPhase::kSliding) {
    const Eigen::Vector2d u = ClothSlip(state, cloth.radius);
    slip_direction_ = u.normalized();
    // u' = a + r z x w' = a - 5/2 mu_s g u_hat: the slip is least where u . u' = 0.
    const Eigen::Vector2d slip_rate =
        acceleration - 2.5 * cloth.mu_slide * cloth.gravity * slip_direction_;
    if (u.dot(slip_rate) < 0.0) duration = std::min(duration, -u.dot(slip_rate) / slip_rate.squaredNorm());
  } else if (phase_ != MotionPhase::kRolling && acceleration.norm() > 0.0) {
    phase_ = MotionPhase::kRolling;  // set moving from rest by the contact forces
  }
  const Eigen::Vector2d v = velocity();
  const double along = v.dot(acceleration);
  if (along < 0.0) {
    // Rolling, the speed is least where v . a = 0 (past it the rolling resistance, taken along
    // the first direction, would drive the ball); sliding, the velocity turns from its first
    // direction where v . v0 = 0 (past it a cushion's friction would drive the ball).
    duration = std::min(duration, phase_ == MotionPhase::kRolling
                                      ? -along / acceleration.squaredNorm()
                                      : -v.squaredNorm() / along);
  }
  if (phase_ == MotionPhase::kSpinning) duration = std::min(duration, spin_stop_);
  end_time_ = start_time + duration;
  max_acceleration_ = acceleration_.norm();
}

MotionSegment::MotionSegment(const ClothParameters& cloth, double start_time,
                             const BallState& state, const physics::Flight& flight)
    : cloth_(cloth),
      phase_(MotionPhase::kAirborne),
      start_time_(start_time),
      end_time_(start_time + physics::TimeToLand(flight, cloth.gravity)),
      start_(state),
      flight_(flight) {}

physics::Flight MotionSegment::FlightAt(double t) const {
  if (phase_ != MotionPhase::kAirborne) return {};
  const double tau = std::clamp(t - start_time_, 0.0, end_time_ - start_time_);
  return physics::FlightAfter(flight_, tau, cloth_.gravity);
}

MotionSegment::MotionSegment(const physics::ModelParameters& params,
                             const physics::SimulationOptions& options, double start_time,
                             const BallState& state, double horizon)
    : cloth_(ClothParameters::From(params)),
      phase_(MotionPhase::kFiveDof),
      start_time_(start_time),
      start_(state) {
  physics::SimulationOptions rest_switched = options;
  rest_switched.rest_switch = true;
  const physics::SimulationResult run = physics::Simulate(params, state, horizon, rest_switched);
  trajectory_ = run.trajectory;
  const bool rested = run.rest_time >= 0.0;
  end_time_ = start_time + (rested ? run.rest_time : horizon);
  end_ = trajectory_->At(end_time_ - start_time);
  if (rested) end_.segment<4>(kVx).setZero();
  max_acceleration_ = kFiveDofAccelerationMargin * params.contact.mu * params.ball.gravity;
}

BallState MotionSegment::At(double t) const {
  const double tau = std::clamp(t - start_time_, 0.0, end_time_ - start_time_);
  if (trajectory_) return t >= end_time_ ? end_ : trajectory_->At(tau);
  BallState s = start_;
  s.segment<2>(kX) += velocity() * tau + 0.5 * acceleration_ * tau * tau;
  s.segment<2>(kVx) += acceleration_ * tau;
  if (phase_ == MotionPhase::kAirborne) return s;  // no cloth: the spin keeps
  s[kWz] -= Sign(start_[kWz]) * cloth_.spin_decel * std::min(tau, spin_stop_);
  if (tau >= spin_stop_) s[kWz] = 0.0;
  const bool at_end = t >= end_time_ && !held_;  // a held motion ends where the forces change
  switch (phase_) {
    case MotionPhase::kSliding: {
      // dw_xy/dt = 5/2 mu_s g / r (z x u_hat); at the end the contact rolls, exactly.
      const double rate = 2.5 * cloth_.mu_slide * cloth_.gravity / cloth_.radius * tau;
      s[kWx] -= rate * slip_direction_.y();
      s[kWy] += rate * slip_direction_.x();
      if (at_end) {
        s[kWx] = -s[kVy] / cloth_.radius;
        s[kWy] = s[kVx] / cloth_.radius;
      }
      break;
    }
    case MotionPhase::kRolling:
      if (at_end) s.segment<2>(kVx).setZero();
      s[kWx] = -s[kVy] / cloth_.radius;
      s[kWy] = s[kVx] / cloth_.radius;
      break;
    case MotionPhase::kSpinning:
    case MotionPhase::kStationary:
      s.segment<4>(kVx).setZero();
      break;
    case MotionPhase::kFiveDof:  // returned above
    case MotionPhase::kAirborne:
      break;
  }
  return s;
}

}  // namespace billiard::table
