// The inverse of the closed-form sliding-then-rolling model (Jaroukh 2019, eqs. 17-28) in 2D: the
// launch velocity and spin that bring a ball from `from` to `to`, where its speed has fallen to
// `final_speed` (0: it stops there).
//
// A straight shot: v0 along the line to the target and the spin about the horizontal axis across
// it, so the slip stays on the line. The free choice the seed leaves open (its x1) is the spin:
// either the slide length x1 directly, or a style fixing R w0 / v0 (stun 0, follow 1/2, natural 1,
// draw -1). Valid for v0 >= R w0 >= -5/2 v0 (no reversal). Without rolling resistance the speed
// falls only while the ball slides, so it must arrive at v2 > 0 still sliding (a draw or stun
// style; a slide length or a natural roll cannot). Side spin wz is passed through: the
// closed form has no pivot friction or swerve, which is why the planner refines against 5-DOF.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "sim/physics/closed_form.h"

namespace billiard::planner {

enum class SpinStyle { kStun, kFollow, kNatural, kDraw };

// "stun", "follow", "natural", "draw"; std::nullopt otherwise.
std::optional<SpinStyle> ParseSpinStyle(const std::string& name);
// R w0 / v0 of a style.
double SpinRatio(SpinStyle style);

struct ShotRequest {
  Eigen::Vector2d from = Eigen::Vector2d::Zero(), to = Eigen::Vector2d::Zero();
  double final_speed = 0.0;            // at the target [m/s]
  std::optional<double> slide_length;  // x1 [m]; when absent, `style` fixes the spin
  SpinStyle style = SpinStyle::kNatural;
  double side_spin = 0.0;  // wz [rad/s]
};

struct LaunchSolution {
  bool ok = false;
  std::string reason;      // why not, when !ok
  bool malformed = false;  // refused because the request itself is malformed, not out of reach
  Eigen::Vector2d v0 = Eigen::Vector2d::Zero();
  Eigen::Vector3d w0 = Eigen::Vector3d::Zero();
  double slide_length = 0.0;  // x1 of the solution (the distance, if it arrives still sliding)
};

LaunchSolution InvertClosedForm(const ShotRequest& request, const physics::ClosedFormParameters& p);

}  // namespace billiard::planner
