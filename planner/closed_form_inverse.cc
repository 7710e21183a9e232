#include "planner/closed_form_inverse.h"

#include <cmath>
#include <optional>
#include <sstream>
#include <utility>

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

namespace {

LaunchSolution Refused(std::string reason, bool malformed = false) {
  LaunchSolution s;
  s.reason = std::move(reason);
  s.malformed = malformed;
  return s;
}

// Step 1: a request the inverse can read (finite numbers, a final speed >= 0, a target away from
// the ball); the malformed refusal otherwise.
std::optional<LaunchSolution> CheckRequest(const ShotRequest& q) {
  const double numbers[] = {q.from.x(),
                            q.from.y(),
                            q.to.x(),
                            q.to.y(),
                            q.final_speed,
                            q.side_spin,
                            q.slide_length.value_or(0.0)};
  for (double x : numbers) {
    if (!std::isfinite(x)) return Refused("request has a non-finite number", true);
  }
  if (q.final_speed < 0.0) return Refused("final speed must be >= 0", true);
  if ((q.to - q.from).norm() == 0.0) return Refused("target is where the ball already is", true);
  return std::nullopt;
}

// How the ball slows: mu g while it slides, 5/7 mu_r g once it rolls (eq. 13).
struct Decelerations {
  double mu_g = 0.0, roll_decel = 0.0;
};

Decelerations DecelerationsOf(const physics::ClosedFormParameters& p) {
  return {p.mu_slide * p.gravity, 5.0 / 7.0 * p.mu_roll * p.gravity};
}

// Step 2: a table on which the ball can slow to the final speed `v2` at all.
std::optional<LaunchSolution> CheckFriction(const Decelerations& a, double v2) {
  if (a.mu_g == 0.0 && a.roll_decel == 0.0) {
    return Refused("without friction or rolling resistance the ball's speed never changes");
  }
  if (a.roll_decel == 0.0 && v2 == 0.0) {
    return Refused("without rolling resistance a rolling ball never stops");
  }
  return std::nullopt;
}

// Step 3, along the line: slip u0 = v0 - R w0 >= 0, slide t1 = 2 u0 / (7 mu g),
// v1 = v0 - 2 u0 / 7, x1 = (2 u0 / (7 mu g)) (v0 - u0 / 7), then rolling:
// D - x1 = (v1^2 - v2^2) / (2 a_r). The launch speed v0 and slip u0 that meet the target, and
// whether the ball arrives there still sliding.
struct AlongTheLine {
  double v0 = 0.0, u0 = 0.0;
  bool arrives_sliding = false;
};

// Step 3a: the launch that slides for `x1` of the `distance` and arrives at `v2`; the refusal
// when there is none.
std::optional<LaunchSolution> LaunchForSlideLength(double x1, double distance, double v2,
                                                   const Decelerations& a, AlongTheLine* line) {
  const double mu_g = a.mu_g, roll_decel = a.roll_decel;
  if (x1 < 0.0 || x1 > distance) {
    return Refused("slide length must lie between 0 and the distance to the target", true);
  }
  if (x1 > 0.0 && mu_g == 0.0) {
    return Refused("without sliding friction the ball cannot slide a finite length");
  }
  if (roll_decel == 0.0) {
    // v1 = v2: the arrival is where the sliding ends (short of the target unless x1 is the
    // distance), and there the regularized 5-DOF speed only tends to v2.
    return Refused(
        "without rolling resistance the ball comes down to its final speed only as it "
        "stops sliding, and rolls on at it: give a spin style (draw or stun arrive "
        "still sliding)");
  }
  const double v1 = std::sqrt(v2 * v2 + 2.0 * roll_decel * (distance - x1));
  // u0^2 + 7 v1 u0 - 49/2 mu g x1 = 0, the positive root.
  line->u0 = 0.5 * (-7.0 * v1 + std::sqrt(49.0 * v1 * v1 + 98.0 * mu_g * x1));
  line->v0 = v1 + 2.0 * line->u0 / 7.0;
  return std::nullopt;
}

// Step 3b: the launch with R w0 = k v0 that arrives at `v2` after the `distance`; the refusal
// when there is none.
std::optional<LaunchSolution> LaunchForStyle(double k, double distance, double v2,
                                             const Decelerations& a, AlongTheLine* line) {
  const double mu_g = a.mu_g, roll_decel = a.roll_decel;
  // D + v2^2 / (2 a_r) = v0^2 (2 (1-k)(6+k) / (49 mu g) + (5+2k)^2 / (98 a_r)).
  if (k < 1.0 && mu_g == 0.0) {
    return Refused("without sliding friction only a natural roll reaches a target");
  }
  const double sliding = k < 1.0 ? 2.0 * (1.0 - k) * (6.0 + k) / (49.0 * mu_g) : 0.0;
  const double slide_fraction = (5.0 + 2.0 * k) * (5.0 + 2.0 * k) / 49.0;  // (v1 / v0)^2
  double v0 = 0.0;
  if (roll_decel == 0.0) {
    // No rolling resistance: the speed falls only while the ball slides (by mu g, the slip
    // stays on the line) and stays at v1 = (5 + 2k) v0 / 7 once it rolls, so the ball must
    // come down to v2 at the target while still sliding.
    if (k >= 1.0) {
      return Refused(
          "without rolling resistance a rolling ball keeps its speed: it never slows to "
          "the final speed (draw or stun make it slide)");
    }
    v0 = std::sqrt(v2 * v2 + 2.0 * mu_g * distance);
    const double v1 = (5.0 + 2.0 * k) / 7.0 * v0;
    if (v1 >= v2) {
      std::ostringstream reason;
      reason.precision(3);
      reason << "without rolling resistance the ball slows only while it slides: with this "
                "spin it rolls on at "
             << v1 << " m/s before the target and never slows to " << v2 << " m/s";
      return Refused(reason.str());
    }
    line->arrives_sliding = true;
  } else {
    v0 = std::sqrt((distance + v2 * v2 / (2.0 * roll_decel)) /
                   (sliding + slide_fraction / (2.0 * roll_decel)));
  }
  line->v0 = v0;
  line->u0 = (1.0 - k) * v0;
  return std::nullopt;
}

// Step 4: the launch in the plane, along the line to the target with the spin across it and the
// side spin asked; refused when the ball would still slide at the target.
LaunchSolution LaunchOnTheTable(const ShotRequest& q, const physics::ClosedFormParameters& p,
                                double distance, const Decelerations& a, const AlongTheLine& line) {
  const double mu_g = a.mu_g, v0 = line.v0, u0 = line.u0;
  LaunchSolution s;
  if (line.arrives_sliding) {
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

}  // namespace

LaunchSolution InvertClosedForm(const ShotRequest& q, const physics::ClosedFormParameters& p) {
  if (auto refusal = CheckRequest(q)) return *refusal;
  const double distance = (q.to - q.from).norm();
  const Decelerations a = DecelerationsOf(p);
  if (auto refusal = CheckFriction(a, q.final_speed)) return *refusal;
  AlongTheLine line;
  const std::optional<LaunchSolution> refusal =
      q.slide_length ? LaunchForSlideLength(*q.slide_length, distance, q.final_speed, a, &line)
                     : LaunchForStyle(SpinRatio(q.style), distance, q.final_speed, a, &line);
  if (refusal) return *refusal;
  return LaunchOnTheTable(q, p, distance, a, line);
}

}  // namespace billiard::planner
