#include "planner/closed_form_inverse.h"

#include <cmath>
#include <sstream>

namespace billiard::planner {

std::optional<SpinStyle> ParseSpinStyle(const std::string& name) {
  if (name == "stun") return SpinStyle::kStun;
  if (name == "follow") return SpinStyle::kFollow;
  if (name == "natural") return SpinStyle::kNatural;
  if (name == "draw") return SpinStyle::kDraw;
  return std::nullopt;
}

double SpinRatio(SpinStyle style) {
  switch (style) {
    case SpinStyle::kStun:
      return 0.0;
    case SpinStyle::kFollow:
      return 0.5;
    case SpinStyle::kNatural:
      return 1.0;
    case SpinStyle::kDraw:
      return -1.0;
  }
  return 1.0;
}

LaunchSolution InvertClosedForm(const ShotRequest& q, const physics::ClosedFormParameters& p) {
  LaunchSolution s;
  const double numbers[] = {q.from.x(),
                            q.from.y(),
                            q.to.x(),
                            q.to.y(),
                            q.final_speed,
                            q.side_spin,
                            q.slide_length.value_or(0.0)};
  for (double x : numbers) {
    if (!std::isfinite(x)) {
      s.reason = "request has a non-finite number";
      s.malformed = true;
      return s;
    }
  }
  if (q.final_speed < 0.0) {
    s.reason = "final speed must be >= 0";
    s.malformed = true;
    return s;
  }
  const double distance = (q.to - q.from).norm();
  if (distance == 0.0) {
    s.reason = "target is where the ball already is";
    s.malformed = true;
    return s;
  }
  const double mu_g = p.mu_slide * p.gravity;
  const double roll_decel = 5.0 / 7.0 * p.mu_roll * p.gravity;  // rolling phase, eq. 13
  const double v2 = q.final_speed;
  if (mu_g == 0.0 && roll_decel == 0.0) {
    s.reason = "without friction or rolling resistance the ball's speed never changes";
    return s;
  }
  if (roll_decel == 0.0 && v2 == 0.0) {
    s.reason = "without rolling resistance a rolling ball never stops";
    return s;
  }

  // Along the line: slip u0 = v0 - R w0 >= 0, slide t1 = 2 u0 / (7 mu g), v1 = v0 - 2 u0 / 7,
  // x1 = (2 u0 / (7 mu g)) (v0 - u0 / 7), then rolling: D - x1 = (v1^2 - v2^2) / (2 a_r).
  double v0 = 0.0, u0 = 0.0;
  bool arrives_sliding = false;
  if (q.slide_length) {
    const double x1 = *q.slide_length;
    if (x1 < 0.0 || x1 > distance) {
      s.reason = "slide length must lie between 0 and the distance to the target";
      s.malformed = true;
      return s;
    }
    if (x1 > 0.0 && mu_g == 0.0) {
      s.reason = "without sliding friction the ball cannot slide a finite length";
      return s;
    }
    if (roll_decel == 0.0) {
      // v1 = v2: the arrival is where the sliding ends (short of the target unless x1 is the
      // distance), and there the regularized 5-DOF speed only tends to v2.
      s.reason =
          "without rolling resistance the ball comes down to its final speed only as it "
          "stops sliding, and rolls on at it: give a spin style (draw or stun arrive "
          "still sliding)";
      return s;
    }
    const double v1 = std::sqrt(v2 * v2 + 2.0 * roll_decel * (distance - x1));
    // u0^2 + 7 v1 u0 - 49/2 mu g x1 = 0, the positive root.
    u0 = 0.5 * (-7.0 * v1 + std::sqrt(49.0 * v1 * v1 + 98.0 * mu_g * x1));
    v0 = v1 + 2.0 * u0 / 7.0;
  } else {
    // R w0 = k v0: D + v2^2 / (2 a_r) = v0^2 (2 (1-k)(6+k) / (49 mu g) + (5+2k)^2 / (98 a_r)).
    const double k = SpinRatio(q.style);
    if (k < 1.0 && mu_g == 0.0) {
      s.reason = "without sliding friction only a natural roll reaches a target";
      return s;
    }
    const double sliding = k < 1.0 ? 2.0 * (1.0 - k) * (6.0 + k) / (49.0 * mu_g) : 0.0;
    const double slide_fraction = (5.0 + 2.0 * k) * (5.0 + 2.0 * k) / 49.0;  // (v1 / v0)^2
    if (roll_decel == 0.0) {
      // No rolling resistance: the speed falls only while the ball slides (by mu g, the slip
      // stays on the line) and stays at v1 = (5 + 2k) v0 / 7 once it rolls, so the ball must
      // come down to v2 at the target while still sliding.
      if (k >= 1.0) {
        s.reason =
            "without rolling resistance a rolling ball keeps its speed: it never slows to "
            "the final speed (draw or stun make it slide)";
        return s;
      }
      v0 = std::sqrt(v2 * v2 + 2.0 * mu_g * distance);
      const double v1 = (5.0 + 2.0 * k) / 7.0 * v0;
      if (v1 >= v2) {
        std::ostringstream reason;
        reason.precision(3);
        reason << "without rolling resistance the ball slows only while it slides: with this "
                  "spin it rolls on at "
               << v1 << " m/s before the target and never slows to " << v2 << " m/s";
        s.reason = reason.str();
        return s;
      }
      arrives_sliding = true;
    } else {
      v0 = std::sqrt((distance + v2 * v2 / (2.0 * roll_decel)) /
                     (sliding + slide_fraction / (2.0 * roll_decel)));
    }
    u0 = (1.0 - k) * v0;
  }
  if (arrives_sliding) {
    s.slide_length = distance;
  } else {
    s.slide_length = u0 == 0.0 ? 0.0 : 2.0 * u0 / (7.0 * mu_g) * (v0 - u0 / 7.0);
  }
  if (s.slide_length > distance * (1.0 + 1e-12)) {
    s.reason = "the ball would still be sliding at the target: choose less spin or a slide length";
    return s;
  }
  const Eigen::Vector2d e = (q.to - q.from) / distance;
  const double spin = (v0 - u0) / p.radius;  // about z x e (topspin > 0)
  s.ok = true;
  s.v0 = v0 * e;
  s.w0 = Eigen::Vector3d(-e.y() * spin, e.x() * spin, q.side_spin);
  return s;
}

}  // namespace billiard::planner
