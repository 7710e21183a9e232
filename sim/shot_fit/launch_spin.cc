#include "sim/shot_fit/launch_spin.h"

#include <cmath>

namespace billiard::shot_fit {

namespace {

// The momentum about the contact point, m v + I w x n / R with I = 2/5 m R^2, shared as 5 : 2
// between the launch and the spin once the ball rolls.
constexpr double kLaunchShare = 5.0 / 7.0, kSpinShare = 2.0 / 7.0;

double RatioOf(const Eigen::Vector2d& v0, const Eigen::Vector2d& s0) {
  return s0.dot(v0) / v0.squaredNorm();
}

}  // namespace

Eigen::Vector2d RollingVelocity(const Eigen::Vector2d& v0, const Eigen::Vector2d& s0) {
  return kLaunchShare * v0 + kSpinShare * s0;
}

LaunchSpin SpinOf(const MeasuredLaunch& launch) {
  LaunchSpin out;
  const Eigen::Vector2d v0 = launch.velocity, v1 = launch.rolling;
  if (!launch.ok || !launch.launch_seen || !launch.rolling_seen || v0.squaredNorm() == 0.0) {
    return out;
  }
  out.spin_velocity = (v1 - kLaunchShare * v0) / kSpinShare;
  out.ratio = RatioOf(v0, out.spin_velocity);
  // q = 7/2 (v1 . v0) / |v0|^2 - 5/2: its gradient over (v0, v1), then the launch fit's
  // covariance carried through it.
  const double n2 = v0.squaredNorm();
  const double scale = 1.0 / kSpinShare;
  Eigen::Matrix<double, 4, 1> gradient;
  gradient.head<2>() = scale * (v1 / n2 - 2.0 * v1.dot(v0) * v0 / (n2 * n2));
  gradient.tail<2>() = scale * v0 / n2;
  const double variance = gradient.dot(launch.joint_covariance * gradient);
  // A covariance singular to rounding (a slide barely two frames long) tells nothing.
  out.seen = variance > 0.0 && std::isfinite(variance);
  out.ratio_sd = out.seen ? std::sqrt(variance) : 0.0;
  return out;
}

double SpinRatioOf(const physics::CueStroke& stroke, const physics::ModelParameters& p) {
  const physics::BallState launch = physics::StrikeBall(stroke, Eigen::Vector2d::Zero(), p);
  const Eigen::Vector2d v0 = launch.segment<2>(physics::kVx);
  const Eigen::Vector2d s0(p.ball.radius * launch[physics::kWy],
                           -p.ball.radius * launch[physics::kWx]);
  return RatioOf(v0, s0);
}

}  // namespace billiard::shot_fit
