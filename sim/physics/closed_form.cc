#include "sim/physics/closed_form.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace billiard::physics {

ClosedFormParameters ClosedFormParameters::From(const ModelParameters& p) {
  return {p.ball.radius, p.ball.gravity, p.contact.mu, p.RollingResistance()};
}

ClosedFormTrajectory::ClosedFormTrajectory(const ClosedFormParameters& p, const BallState& initial)
    : p_(p), initial_(initial) {
  if (!(p.mu_slide > 0.0) || !(p.mu_roll >= 0.0) || !(p.radius > 0.0) || !(p.gravity > 0.0)) {
    throw std::invalid_argument("closed-form model needs mu_s > 0, mu_r >= 0, R > 0, g > 0");
  }
  // Slip of the contact point u = v + R z x w (eq. 1).
  const Eigen::Vector2d u0 = ClothSlip(initial, p.radius);
  const double slip = u0.norm();
  if (slip > 0.0) slip_direction_ = u0 / slip;
  slide_end_time_ = 2.0 * slip / (7.0 * p.mu_slide * p.gravity);
  slide_end_ = Sliding(slide_end_time_);

  const double v1 = slide_end_.segment<2>(kVx).norm();
  if (v1 > 0.0) roll_direction_ = slide_end_.segment<2>(kVx) / v1;
  if (v1 == 0.0) {
    stop_time_ = slide_end_time_;
  } else if (p.mu_roll > 0.0) {
    stop_time_ = slide_end_time_ + 7.0 * v1 / (5.0 * p.mu_roll * p.gravity);
  }
}

BallState ClosedFormTrajectory::Sliding(double t) const {
  const double decel = p_.mu_slide * p_.gravity;
  const double spin_rate = 2.5 * decel / p_.radius;
  BallState s = initial_;
  s.segment<2>(kX) +=
      initial_.segment<2>(kVx) * t - 0.5 * decel * t * t * slip_direction_;  // eq. 7
  s.segment<2>(kVx) -= decel * t * slip_direction_;                          // eq. 6
  s[kWx] -= spin_rate * t * slip_direction_.y();  // w0 + 5/2 mu_s g / R t (z x u_hat)
  s[kWy] += spin_rate * t * slip_direction_.x();
  return s;
}

BallState ClosedFormTrajectory::Rolling(double tau) const {
  const double decel = 5.0 / 7.0 * p_.mu_roll * p_.gravity;
  BallState s = slide_end_;
  s.segment<2>(kX) += slide_end_.segment<2>(kVx) * tau - 0.5 * decel * tau * tau * roll_direction_;
  s.segment<2>(kVx) -= decel * tau * roll_direction_;  // eq. 13
  // Rolling without slip: v = -R z x w.
  s[kWx] = -s[kVy] / p_.radius;
  s[kWy] = s[kVx] / p_.radius;
  return s;
}

double ClosedFormTrajectory::TimeAtSpeed(double speed) const {
  const Eigen::Vector2d v0 = initial_.segment<2>(kVx);
  if (v0.norm() <= speed) return 0.0;
  // Sliding: |v0 - mu_s g t u_hat|^2 = speed^2, the smaller root if it comes before t1.
  const double decel = p_.mu_slide * p_.gravity;
  const double along = v0.dot(slip_direction_);
  const double discriminant = along * along - (v0.squaredNorm() - speed * speed);
  if (discriminant >= 0.0) {
    const double t = (along - std::sqrt(discriminant)) / decel;
    if (t >= 0.0 && t <= slide_end_time_) return t;
  }
  const double v1 = slide_end_.segment<2>(kVx).norm();
  if (v1 <= speed) return slide_end_time_;
  if (p_.mu_roll == 0.0) return std::numeric_limits<double>::infinity();
  return slide_end_time_ + (v1 - speed) / (5.0 / 7.0 * p_.mu_roll * p_.gravity);
}

BallState ClosedFormTrajectory::At(double t) const {
  t = std::max(t, 0.0);
  if (t <= slide_end_time_) return Sliding(t);
  if (t < stop_time_) return Rolling(t - slide_end_time_);
  BallState rest = Rolling(stop_time_ - slide_end_time_);
  rest.segment<4>(kVx).setZero();  // exactly at rest, not a rounding residue; wz is kept
  return rest;
}

}  // namespace billiard::physics
