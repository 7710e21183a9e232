#include "sim/physics/cue_strike.h"

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "sim/physics/golden_section.h"

namespace billiard::physics {

namespace {

// The cue axis c and the unit vectors of the tip offset plane: right (horizontal, the direction
// the tip end is free to move in) and up.
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

// The impact's inverse masses in the directions of the impulse, the cue axis c and the tip end's
// sideways direction n, for the contact point P = b - sqrt(r^2 - b^2) c. The ball's is
// (7/2 - 5/2 p p^T) / m at P (p = P / r: v_P = J / m + (P x J / I) x P); the cue adds 1 / M along
// c and the end mass 1 / m_e along n.
struct TipContact {
  double axial = 0.0;     // 1 / M + (1 + 5/2 q^2) / m
  double coupling = 0.0;  // 5/2 q_n sqrt(1 - q^2) / m
  double side = 0.0;      // 1 / m_e + (1 + 5/2 (1 - q_n^2)) / m
  // -J_n / J_c: with the tip end moving with the ball's contact point along n (TP A.31).
  double SquirtRatio() const { return coupling / side; }
};

// `side` = b . n / r, `offset` = |b| / r.
TipContact ContactAt(double side, double offset, const ModelParameters& p) {
  const double m = p.ball.mass;
  TipContact k;
  k.axial = 1.0 / p.cue.mass + (1.0 + 2.5 * offset * offset) / m;
  k.coupling = 2.5 * side * std::sqrt(1.0 - offset * offset) / m;
  k.side = 1.0 / p.cue.end_mass + (1.0 + 2.5 * (1.0 - side * side)) / m;
  return k;
}

// The largest |J_n / J_c| of any contact: 5/2 |q_n| sqrt(1 - q^2) <= 5/4 and the side inverse
// mass is above (1 + m / m_e) / m.
double MaxSquirtRatio(const ModelParameters& p) {
  return 1.25 / (1.0 + p.ball.mass / p.cue.end_mass);
}

double MomentOfInertia(const ModelParameters& p) {
  return 0.4 * p.ball.mass * p.ball.radius * p.ball.radius;
}

// The root of f in [lo, hi], f(lo) >= 0 >= f(hi), to within `tolerance` or the last bit of the
// double. The Illinois variant of regula falsi (Dowell and Jarratt 1971): superlinear on the
// smooth functions here (a dozen evaluations where bisection to the last bit takes sixty, and
// the launch range nests one search in another), with a bisection step whenever a step fails to
// halve the bracket, so it never does worse than about twice bisection.
double Bisect(const std::function<double(double)>& f, double lo, double hi,
              double tolerance = 0.0) {
  double f_lo = f(lo), f_hi = f(hi);
  if (f_lo == 0.0) return lo;
  if (f_hi == 0.0) return hi;
  int side = 0;  // which end stayed last time: -1 lo, +1 hi
  double width = hi - lo;
  for (;;) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi || hi - lo <= tolerance) return mid;
    double x = lo + f_lo / (f_lo - f_hi) * (hi - lo);
    const bool halved = hi - lo <= 0.5 * width;
    if (!(x > lo && x < hi) || !halved) x = mid;
    width = hi - lo;
    const double fx = f(x);
    if (fx == 0.0) return x;
    if (fx > 0.0) {
      lo = x, f_lo = fx;
      if (side == -1) f_hi *= 0.5;  // the hi end stays again: halve its weight (Illinois)
      side = -1;
    } else {
      hi = x, f_hi = fx;
      if (side == +1) f_lo *= 0.5;
      side = +1;
    }
  }
}

// Far below the last bit of any heading near pi: a squirt angle this close to its root (near
// zero, where doubles are dense) changes no launch.
constexpr double kAngleResolution = 1e-18;

std::string Format(double value) {
  std::ostringstream s;
  s.precision(4);
  s << value;
  return s.str();
}

StrokeSolution Refusal(std::string reason) {
  StrokeSolution s;
  s.reason = std::move(reason);
  return s;
}

// The stroke that launches v0 and w0, its tip offset and cue speed not yet held to the robot's
// limits.
StrokeSolution SolveStroke(const Eigen::Vector2d& v0, const Eigen::Vector3d& w0,
                           const ModelParameters& p, double free_slope) {
  if (!v0.allFinite() || !w0.allFinite()) {
    return Refusal("launch velocity or spin has a non-finite number");
  }
  if (!(free_slope >= 0.0 && std::isfinite(free_slope))) return Refusal("the cue's slope must be finite and >= 0");
  const double speed = v0.norm();
  if (speed == 0.0) return Refusal("a cue stroke cannot leave the ball without velocity");
  const double r = p.ball.radius, m = p.ball.mass;

  // Step 1, the impulse: m v0 and the vertical part the table took. w0 = P x J / I is
  // perpendicular to J, which fixes that part (and the elevation) where there is side spin: a
  // level cue without spin about the travel. Without side spin any part is, and `free_slope` is.
  const Eigen::Vector3d e(v0.x() / speed, v0.y() / speed, 0.0);
  double along = w0.dot(e);
  if (std::abs(along) <= 1e-12 * w0.norm()) along = 0.0;
  if (along != 0.0 && !(w0.z() != 0.0 && along / w0.z() > 0.0)) {
    return Refusal("spin about the direction of travel that a cue from above cannot give");
  }
  const double forward = m * speed;
  const double down = along != 0.0 ? forward * along / w0.z() : w0.z() == 0.0 ? forward * free_slope : 0.0;
  const Eigen::Vector3d impulse = forward * e - down * Eigen::Vector3d::UnitZ();

  // Step 2, the contact point: P x J = I w0, |P| = r, behind the ball's centre.
  const Eigen::Vector3d across = MomentOfInertia(p) / impulse.squaredNorm() * impulse.cross(w0);
  if (across.norm() >= r) return Refusal("needs a tip offset beyond the edge of the ball");
  const Eigen::Vector3d contact =
      across - std::sqrt(r * r - across.squaredNorm()) * impulse.normalized();

  // Step 3, the squirt angle alpha from the cue's heading to the launch heading: J = J_c c + J_n n
  // with J_n = -SquirtRatio J_c, where turning the cue by alpha off the launch turns n and c and
  // with them P's offsets. Per unit J_c the residual SquirtRatio - (-J_n / J_c) falls from >= 0
  // to <= 0 across the angles where -J_n / J_c = +-MaxSquirtRatio.
  const double launch_heading = std::atan2(v0.y(), v0.x());
  const auto frame_at = [&](double alpha) {
    return FrameOf(launch_heading - alpha, std::atan2(down, forward * std::cos(alpha)));
  };
  const auto residual = [&](double alpha) {
    const CueFrame f = frame_at(alpha);
    const double side = contact.dot(f.right), offset = std::hypot(side, contact.dot(f.up));
    return ContactAt(side / r, offset / r, p).SquirtRatio() +
           impulse.dot(f.right) / impulse.dot(f.axis);
  };
  const double ratio_max = MaxSquirtRatio(p), slope = down / forward;
  const double bound = std::asin(
      std::min(1.0, ratio_max * std::sqrt((1.0 + slope * slope) / (1.0 + ratio_max * ratio_max))));
  if (residual(-bound) < 0.0 || residual(bound) > 0.0) {
    return Refusal("no cue elevation below the vertical gives this spin with its squirt");
  }
  const double alpha = Bisect(residual, -bound, bound, kAngleResolution);

  // Step 4, the stroke: heading, elevation, the offsets of P, and the cue speed of TP A.30's
  // restitution along the axis, (1 + e) V = (1 / M + K_cc) J_c + K_cn J_n.
  const CueFrame f = frame_at(alpha);
  StrokeSolution s;
  s.stroke.heading = std::remainder(launch_heading - alpha, 2.0 * M_PI);
  s.stroke.elevation = std::atan2(down, forward * std::cos(alpha));
  s.stroke.tip_side = contact.dot(f.right);
  s.stroke.tip_height = contact.dot(f.up);
  const double offset = std::hypot(s.stroke.tip_side, s.stroke.tip_height) / r;
  const TipContact k = ContactAt(s.stroke.tip_side / r, offset, p);
  s.stroke.speed = (k.axial * impulse.dot(f.axis) + k.coupling * impulse.dot(f.right)) /
                   (1.0 + p.cue.tip_restitution);
  s.ok = true;
  return s;
}

}  // namespace

double SquirtAngle(double tip_side, const ModelParameters& p) {
  const double q = tip_side / p.ball.radius;
  if (!(std::abs(q) < 1.0)) {
    throw std::invalid_argument("tip offset must be smaller than the ball radius");
  }
  return std::atan(ContactAt(q, std::abs(q), p).SquirtRatio());
}

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
  const double offset = std::hypot(stroke.tip_side, stroke.tip_height) / r;
  if (offset >= 1.0) throw std::invalid_argument("tip offset must be smaller than the ball radius");

  const CueFrame f = FrameOf(stroke.heading, stroke.elevation);
  const Eigen::Vector3d b = stroke.tip_side * f.right + stroke.tip_height * f.up;
  // [axial coupling; coupling side] [J_c; J_n] = [(1 + e) V; 0].
  const TipContact k = ContactAt(stroke.tip_side / r, offset, p);
  const double squirt = k.SquirtRatio();
  const double axial =
      (1.0 + p.cue.tip_restitution) * stroke.speed / (k.axial - k.coupling * squirt);
  const double side = -squirt * axial;
  const Eigen::Vector3d impulse = axial * f.axis + side * f.right;
  // The moment P x J of the impulse, P = b - sqrt(r^2 - b^2) c, with c x J = J_n c x n (none,
  // exactly, without a side offset).
  const Eigen::Vector3d moment =
      b.cross(impulse) - r * std::sqrt(1.0 - offset * offset) * side * f.axis.cross(f.right);
  const Eigen::Vector3d v = impulse / p.ball.mass;
  const Eigen::Vector3d w = moment / MomentOfInertia(p);
  return MakeBallState(position.x(), position.y(), v.x(), v.y(), w.x(), w.y(), w.z());
}

StrokeSolution StrokeFor(const Eigen::Vector2d& v0, const Eigen::Vector3d& w0,
                         const ModelParameters& p, double free_slope) {
  StrokeSolution s = SolveStroke(v0, w0, p, free_slope);
  if (!s.ok) return s;
  const double offset = std::hypot(s.stroke.tip_side, s.stroke.tip_height) / p.ball.radius;
  if (offset > p.cue.max_tip_offset * (1.0 + 1e-12)) {
    return Refusal("needs a tip offset of " + Format(offset) + " r, beyond the " +
                   Format(p.cue.max_tip_offset) + " r that does not miscue");
  }
  if (s.stroke.speed > p.cue.max_speed) {
    return Refusal("needs a cue speed of " + Format(s.stroke.speed) + " m/s, beyond the robot's " +
                   Format(p.cue.max_speed) + " m/s");
  }
  return s;
}

LaunchSpeedRange LaunchSpeedsFor(double spin_ratio, double side_spin, const ModelParameters& p) {
  const double r = p.ball.radius, q_max = p.cue.max_tip_offset;
  LaunchSpeedRange range{0.0, -1.0};
  // A level launch at speed s along x: the tip meets the ball 2/5 k r above its centre and
  // (2/5) r wz / s to the right of the launch line (w = P x J / I, J = m s x).
  const double height = 0.4 * std::abs(spin_ratio);
  if (height > q_max || (height == q_max && side_spin != 0.0)) return range;

  // The slowest launch: the tip at max_tip_offset, turned by its squirt angle off the launch line.
  if (side_spin != 0.0) {
    const double side = std::sqrt(q_max * q_max - height * height);
    const double axial = std::sqrt(1.0 - q_max * q_max);
    const double alpha = std::atan(ContactAt(side, q_max, p).SquirtRatio());
    const double off_line = side * std::cos(alpha) - axial * std::sin(alpha);
    range.min = 0.4 * r * std::abs(side_spin) / off_line;
  }

  // The cue speed V(s) falls, then rises (the offset, then the speed, costs it). The ball's
  // energy is at most the cue's, so V(s) >= s sqrt(m / M): V = max_speed below
  // max_speed sqrt(M / m). When the slowest launch already needs more than max_speed, the range
  // starts where V, past its lowest, comes down to max_speed.
  const auto cue_speed = [&](double s) {
    const StrokeSolution stroke = SolveStroke({s, 0.0}, {0.0, spin_ratio * s / r, side_spin}, p, 0.0);
    return stroke.ok ? stroke.stroke.speed : INFINITY;
  };
  const auto above_max = [&](double s) { return cue_speed(s) - p.cue.max_speed; };
  const double fastest = p.cue.max_speed * std::sqrt(p.cue.mass / p.ball.mass);
  double lo = range.min;
  if (lo > 0.0 && above_max(lo) > 0.0) {
    lo = GoldenSectionMinimum(cue_speed, lo, fastest,
                              [](double a, double b) { return b - a <= 1e-12 * b; });
    if (above_max(lo) > 0.0) return LaunchSpeedRange{0.0, -1.0};
    range.min = Bisect(above_max, range.min, lo);
  }
  range.max = Bisect([&](double s) { return -above_max(s); }, lo, fastest);
  return range;
}

}  // namespace billiard::physics
