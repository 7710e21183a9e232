#include "sim/table/ball_collision.h"

#include <algorithm>
#include <cmath>

namespace billiard::table {

using physics::BallState;
using physics::kVx;
using physics::kWx;
using physics::kX;

namespace {

// A solid ball's moment of inertia over m r^2.
constexpr double kInertiaFactor = 0.4;

Eigen::Vector3d Velocity3(const BallState& s) { return {s[kVx], s[kVx + 1], 0.0}; }
Eigen::Vector3d Spin3(const BallState& s) { return s.segment<3>(kWx); }

// The velocity of the point of `s` at offset `r` from its centre.
Eigen::Vector3d PointVelocity(const BallState& s, const Eigen::Vector3d& r) {
  return Velocity3(s) + Spin3(s).cross(r);
}

// `s` after the impulse `j` at offset `r` from its centre (the cloth takes the vertical part).
BallState Impelled(const BallState& s, const Eigen::Vector3d& j, const Eigen::Vector3d& r,
                   double mass, double radius) {
  BallState out = s;
  out.segment<2>(kVx) += j.head<2>() / mass;
  out.segment<3>(kWx) += r.cross(j) / (kInertiaFactor * mass * radius * radius);
  return out;
}

}  // namespace

double BallBallFriction(const physics::CollisionParameters& c, double slip_speed) {
  return c.ball_friction_a + c.ball_friction_b * std::exp(-c.ball_friction_c * slip_speed);
}

BallBallImpulse ResolveBallBallImpact(const BallState& a, const BallState& b,
                                      const physics::BallParameters& ball,
                                      const physics::CollisionParameters& collision) {
  BallBallImpulse out{a, b};
  const Eigen::Vector2d centres = b.segment<2>(kX) - a.segment<2>(kX);
  const Eigen::Vector3d n(centres.x() / centres.norm(), centres.y() / centres.norm(), 0.0);
  const double closing = (Velocity3(a) - Velocity3(b)).dot(n);
  if (!(closing > 0.0)) return out;

  const double m = ball.mass;
  const Eigen::Vector3d ra = ball.radius * n;
  const Eigen::Vector3d rb = -ra;
  const Eigen::Vector3d slip = PointVelocity(a, ra) - PointVelocity(b, rb);
  const Eigen::Vector3d tangential_slip = slip - slip.dot(n) * n;
  const double slip_speed = tangential_slip.norm();

  out.normal = 0.5 * (1.0 + collision.ball_restitution) * m * closing;
  out.friction_coefficient = BallBallFriction(collision, slip_speed);
  // The impulse that stops the slip: each contact point moves by 7 / (2 m) per unit impulse.
  const double sticking = m * slip_speed / 7.0;
  out.friction = std::min(out.friction_coefficient * out.normal, sticking);

  Eigen::Vector3d on_b = out.normal * n;
  if (slip_speed > 0.0) on_b += out.friction * tangential_slip / slip_speed;
  out.a = Impelled(a, -on_b, ra, m, ball.radius);
  out.b = Impelled(b, on_b, rb, m, ball.radius);
  return out;
}

}  // namespace billiard::table
