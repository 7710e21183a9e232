#include "sim/physics/hop.h"

#include <algorithm>
#include <cmath>

namespace billiard::physics {

bool Airborne(const Flight& flight, double gravity) { return Apex(flight, gravity) > kSettledHop; }

double Apex(const Flight& flight, double gravity) {
  const double rise = std::max(0.0, flight.vertical_speed);
  return flight.height + rise * rise / (2.0 * gravity);
}

double TimeToLand(const Flight& flight, double gravity) {
  const double v = flight.vertical_speed;
  const double h = std::max(0.0, flight.height);
  return (v + std::sqrt(v * v + 2.0 * gravity * h)) / gravity;
}

Flight FlightAfter(const Flight& flight, double t, double gravity) {
  const double height = flight.height + flight.vertical_speed * t - 0.5 * gravity * t * t;
  return {std::max(0.0, height), flight.vertical_speed - gravity * t};
}

Landing LandOnBed(const BallState& s, double landing_speed, const ModelParameters& p) {
  const double r = p.ball.radius;
  Landing out{s, {}};
  const Eigen::Vector2d slip = ClothSlip(s, r);
  if (slip.norm() > 0.0) {
    // The friction impulse per unit mass: Coulomb's share of the normal one, or what stops the
    // slip (du = -7/2 F / m along the slip).
    const double normal = (1.0 + kBedRestitution) * landing_speed;
    const double friction = std::min(p.contact.mu * normal, 2.0 / 7.0 * slip.norm());
    const Eigen::Vector2d along = slip.normalized();
    out.state.segment<2>(kVx) -= friction * along;
    // dw = r x F / I with r = -r z: 5/2 F / (m r) (z x along).
    const double spin = 2.5 * friction / r;
    out.state[kWx] -= spin * along.y();
    out.state[kWy] += spin * along.x();
  }
  const Flight rebound{0.0, kBedRestitution * landing_speed};
  if (Airborne(rebound, p.ball.gravity)) out.rebound = rebound;
  return out;
}

double LaunchUpSpeed(const CueStroke& stroke, const BallState& launch) {
  const Eigen::Vector2d along(std::cos(stroke.heading), std::sin(stroke.heading));
  const double down = std::max(0.0, launch.segment<2>(kVx).dot(along)) * std::tan(stroke.elevation);
  return kBedRestitution * down;
}

}  // namespace billiard::physics
