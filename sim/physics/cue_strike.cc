#include "sim/physics/cue_strike.h"

#include <Eigen/Geometry>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace billiard::physics {

namespace {

// The cue axis c and the unit vectors of the tip offset plane: right (horizontal) and up.
struct CueFrame {
  Eigen::Vector3d axis, right, up;
};

CueFrame FrameOf(double heading, double elevation) {
  const Eigen::Vector3d e(std::cos(heading), std::sin(heading), 0.0);
  CueFrame f;
  f.axis = std::cos(elevation) * e - std::sin(elevation) * Eigen::Vector3d::UnitZ();
  f.right = e.cross(Eigen::Vector3d::UnitZ());
  f.up = f.right.cross(f.axis);
  return f;
}

// Impulse per unit cue speed for a tip offset |b| (Alciatore 2004, TP A.30). The tip meets the
// ball's effective mass at the contact, 1 / m_eff = 1 / m + b^2 / I = (1 + 5/2 q^2) / m, so
// J = (1 + e) V / (1 / M + 1 / m_eff) = (1 + e) M m V / (m + M (1 + 5/2 q^2)).
double ImpulsePerCueSpeed(double offset, const ModelParameters& p) {
  const double m = p.ball.mass, big_m = p.cue.mass, q = offset / p.ball.radius;
  return (1.0 + p.cue.tip_restitution) * big_m * m / (m + big_m * (1.0 + 2.5 * q * q));
}

std::string Format(double value) {
  std::ostringstream s;
  s.precision(4);
  s << value;
  return s.str();
}

}  // namespace

BallState StrikeBall(const CueStroke& stroke, const Eigen::Vector2d& position,
                     const ModelParameters& p) {
  const double r = p.ball.radius;
  for (double v : {stroke.speed, stroke.heading, stroke.tip_side, stroke.tip_height,
                   stroke.elevation, position.x(), position.y()}) {
    if (!std::isfinite(v)) throw std::invalid_argument("cue stroke has a non-finite number");
  }
  if (stroke.speed < 0.0) throw std::invalid_argument("cue speed must be >= 0");
  if (stroke.elevation < 0.0 || stroke.elevation >= M_PI / 2) {
    throw std::invalid_argument("cue elevation must lie in [0, pi/2)");
  }
  const double offset = std::hypot(stroke.tip_side, stroke.tip_height);
  if (offset >= r) throw std::invalid_argument("tip offset must be smaller than the ball radius");

  const CueFrame f = FrameOf(stroke.heading, stroke.elevation);
  const Eigen::Vector3d b = stroke.tip_side * f.right + stroke.tip_height * f.up;
  const double impulse = ImpulsePerCueSpeed(offset, p) * stroke.speed;
  const Eigen::Vector3d v = impulse / p.ball.mass * f.axis;
  const Eigen::Vector3d w = 5.0 * impulse / (2.0 * p.ball.mass * r * r) * b.cross(f.axis);
  return MakeBallState(position.x(), position.y(), v.x(), v.y(), w.x(), w.y(), w.z());
}

StrokeSolution StrokeFor(const Eigen::Vector2d& v0, const Eigen::Vector3d& w0,
                         const ModelParameters& p) {
  StrokeSolution s;
  if (!v0.allFinite() || !w0.allFinite()) {
    s.reason = "launch velocity or spin has a non-finite number";
    return s;
  }
  const double speed = v0.norm();
  if (speed == 0.0) {
    s.reason = "a cue stroke cannot leave the ball without velocity";
    return s;
  }
  const Eigen::Vector3d e(v0.x() / speed, v0.y() / speed, 0.0);
  // w0 must be perpendicular to the cue axis (b x c is): cos(el) (w0 . e) = sin(el) wz.
  double along = w0.dot(e);
  if (std::abs(along) <= 1e-12 * w0.norm()) along = 0.0;
  if (along != 0.0 && !(w0.z() != 0.0 && along / w0.z() > 0.0)) {
    s.reason = "spin about the direction of travel that a cue from above cannot give";
    return s;
  }
  const double elevation = along == 0.0 ? 0.0 : std::atan(along / w0.z());
  const double heading = std::atan2(v0.y(), v0.x());
  const CueFrame f = FrameOf(heading, elevation);

  const double r = p.ball.radius, m = p.ball.mass;
  const double impulse = m * speed / std::cos(elevation);
  const Eigen::Vector3d b = f.axis.cross(w0) * (2.0 * m * r * r / (5.0 * impulse));
  const double offset = b.norm();
  if (offset > p.cue.max_tip_offset * r * (1.0 + 1e-12)) {
    s.reason = "needs a tip offset of " + Format(offset / r) + " r, beyond the " +
               Format(p.cue.max_tip_offset) + " r that does not miscue";
    return s;
  }
  const double cue_speed = impulse / ImpulsePerCueSpeed(offset, p);
  if (cue_speed > p.cue.max_speed) {
    s.reason = "needs a cue speed of " + Format(cue_speed) + " m/s, beyond the robot's " +
               Format(p.cue.max_speed) + " m/s";
    return s;
  }
  s.ok = true;
  s.stroke = {cue_speed, heading, b.dot(f.right), b.dot(f.up), elevation};
  return s;
}

LaunchSpeedRange LaunchSpeedsFor(double spin_ratio, double side_spin, const ModelParameters& p) {
  // A level stroke at speed s gives |w| = 5 s |b| / (2 r^2), so the offset fraction is
  // q = |b| / r = 2/5 sqrt(k^2 + (r wz / s)^2).
  const double r = p.ball.radius, m = p.ball.mass, big_m = p.cue.mass;
  const double k2 = spin_ratio * spin_ratio, rw2 = r * r * side_spin * side_spin;
  const double q_max = 2.5 * p.cue.max_tip_offset;  // in units of 2/5
  LaunchSpeedRange range{0.0, -1.0};
  if (k2 > q_max * q_max) return range;
  range.min = std::sqrt(rw2 / (q_max * q_max - k2));
  // The cue speed (TP A.30, 5/2 q^2 = 0.4 (k^2 + (r wz / s)^2)) is
  // V = [s (m + M (1 + 0.4 k^2)) + 0.4 M r^2 wz^2 / s] / ((1 + e) M); V = max_speed is a
  // quadratic in s whose larger root is the fastest launch.
  const double a = m + big_m * (1.0 + 0.4 * k2), b = 0.4 * big_m * rw2;
  const double c = (1.0 + p.cue.tip_restitution) * big_m * p.cue.max_speed;
  const double discriminant = c * c - 4.0 * a * b;
  if (discriminant < 0.0) return range;
  range.max = (c + std::sqrt(discriminant)) / (2.0 * a);
  return range;
}

}  // namespace billiard::physics
