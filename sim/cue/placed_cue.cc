#include "sim/cue/placed_cue.h"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

namespace billiard::cue {

PlacedCue PlaceCue(const Eigen::Vector2d& ball_centre, double ball_radius,
                   const physics::CueStroke& stroke, const CueShape& shape) {
  for (double v : {ball_centre.x(), ball_centre.y(), ball_radius, stroke.heading, stroke.elevation,
                   stroke.tip_side, stroke.tip_height}) {
    if (!std::isfinite(v)) throw std::invalid_argument("cue placement has a non-finite number");
  }
  const double offset_squared =
      stroke.tip_side * stroke.tip_side + stroke.tip_height * stroke.tip_height;
  if (!(offset_squared < ball_radius * ball_radius)) {
    throw std::invalid_argument("tip offset must be smaller than the ball radius");
  }
  // The stroke's frame: the axis c (forward and down), its horizontal right n and its up u.
  const Eigen::Vector3d heading(std::cos(stroke.heading), std::sin(stroke.heading), 0.0);
  const Eigen::Vector3d axis =
      std::cos(stroke.elevation) * heading - std::sin(stroke.elevation) * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d right = heading.cross(Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d up = right.cross(axis);

  const Eigen::Vector3d offset = stroke.tip_side * right + stroke.tip_height * up;
  const Eigen::Vector3d centre(ball_centre.x(), ball_centre.y(), ball_radius);
  PlacedCue cue;
  cue.tip = centre + offset - std::sqrt(ball_radius * ball_radius - offset_squared) * axis;
  cue.back = -axis;
  cue.shape = shape;
  return cue;
}

}  // namespace billiard::cue
