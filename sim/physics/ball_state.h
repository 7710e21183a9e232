// The state of a ball on the cloth and the quantities every model derives from it.
//
// Seven numbers in table coordinates (SI units): the centre position X, Y, the centre velocity
// vx, vy, and the angular velocity wx, wy, wz. The ball stays in contact with the cloth, so
// vz = 0 and the normal force is m g (Kudra et al. 2016, section 3.1).
#pragma once

#include <Eigen/Core>
#include <string>

namespace billiard::physics {

using BallState = Eigen::Matrix<double, 7, 1>;

// Index of each component inside BallState.
enum StateIndex : int { kX = 0, kY, kVx, kVy, kWx, kWy, kWz };

inline BallState MakeBallState(double x, double y, double vx, double vy, double wx, double wy,
                               double wz) {
  BallState s;
  s << x, y, vx, vy, wx, wy, wz;
  return s;
}

// Kinetic energy 1/2 m |v|^2 + 1/2 (2/5 m r^2) |w|^2 of a solid ball.
inline double KineticEnergy(const BallState& s, double mass, double radius) {
  const double translational = s.segment<2>(kVx).squaredNorm();
  const double rotational = 0.4 * radius * radius * s.segment<3>(kWx).squaredNorm();
  return 0.5 * mass * (translational + rotational);
}

// The slip of the ball's contact point with the cloth, u = v + r z x w = (vx - r wy, vy + r wx)
// (Kudra et al. 2016, section 3.1): zero when the ball rolls, and the direction of the cloth's
// sliding friction against it.
inline Eigen::Vector2d ClothSlip(const BallState& s, double radius) {
  return {s[kVx] - radius * s[kWy], s[kVy] + radius * s[kWx]};
}

// "X,Y,vx,vy,wx,wy,wz" with full precision, for messages and reports.
std::string FormatState(const BallState& s);

}  // namespace billiard::physics
