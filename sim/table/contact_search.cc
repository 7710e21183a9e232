#include "sim/table/contact_search.h"

namespace billiard::table {

using physics::BallState;
using physics::kVx;
using physics::kX;

Parabola ParabolaAt(const MotionSegment& s, double now) {
  const BallState state = s.At(now);
  return {state.segment<2>(kX), state.segment<2>(kVx), s.acceleration()};
}

Quartic DistanceSquaredMinus(const Parabola& q, double d) {
  return {q.p.squaredNorm() - d * d, 2.0 * q.p.dot(q.v), q.v.squaredNorm() + q.p.dot(q.a),
          q.v.dot(q.a), 0.25 * q.a.squaredNorm()};
}

Quartic AlongMinus(const Parabola& q, const Eigen::Vector2d& origin, const Eigen::Vector2d& n,
                   double offset) {
  return {(q.p - origin).dot(n) - offset, q.v.dot(n), 0.5 * q.a.dot(n), 0.0, 0.0};
}

double Derivative(const Quartic& c, double t) {
  return c[1] + t * (2.0 * c[2] + t * (3.0 * c[3] + t * 4.0 * c[4]));
}

Eigen::Vector2d PositionAt(const Parabola& q, double tau) {
  return q.p + q.v * tau + 0.5 * q.a * tau * tau;
}

double SafeStep(double gap, double closing, double accel) {
  if (!std::isfinite(gap)) return gap;
  const double speed = std::max(closing, 0.0);
  return 2.0 * gap / (speed + std::sqrt(speed * speed + 2.0 * accel * gap));
}

Clearance ElementClearance(const TableGeometry& table, double r, const BallState& s, EventType type,
                           std::size_t k) {
  const Eigen::Vector2d p = s.segment<2>(kX), v = s.segment<2>(kVx);
  const int index = static_cast<int>(k);
  switch (type) {
    case EventType::kBallCushion: {
      const CushionLine& line = table.lines[k];
      const double height = (p - line.a).dot(line.normal);
      const Eigen::Vector2d along = line.b - line.a;
      const double s_along = (p - line.a).dot(along) / along.squaredNorm();
      if (s_along < 0.0 || s_along > 1.0) {  // past an end: no nearer than the end
        const Eigen::Vector2d out = p - (s_along < 0.0 ? line.a : line.b);
        return {out.norm() - r, -v.dot(out) / out.norm(), type, index};
      }
      // Behind the nose line (the ball went through it) the gap is negative, so a search that
      // lands past the contact sees it; farther behind than a diameter is over a pocket.
      if (height < -2.0 * r) return {kInfinity, 0.0, type, index};
      return {height - r, -v.dot(line.normal), type, index};
    }
    case EventType::kBallJaw: {
      const Eigen::Vector2d out = p - table.points[k].centre;
      const double distance = out.norm();
      return {distance - r - table.points[k].radius, -v.dot(out) / distance, type, index};
    }
    case EventType::kBallPocket: {
      const Pocket& pocket = table.pockets[k];
      const Eigen::Vector2d along = pocket.capture_b - pocket.capture_a;
      const double s_along = (p - pocket.capture_a).dot(along) / along.squaredNorm();
      if (s_along < 0.0 || s_along > 1.0) return {kInfinity, 0.0, type, index};  // the jaws bound
      return {-(p - pocket.capture_a).dot(pocket.inward), v.dot(pocket.inward), type, index};
    }
    default:
      return {};
  }
}

Clearance BoundaryClearance(const TableGeometry& table, double r, const BallState& s,
                            double accel) {
  Clearance nearest, touching;
  double least = kInfinity;
  const auto consider = [&](EventType type, std::size_t count) {
    for (std::size_t k = 0; k < count; ++k) {
      const Clearance c = ElementClearance(table, r, s, type, k);
      if (!std::isfinite(c.gap)) continue;
      const double advance = Advance(c, accel);
      if (advance < least) {
        least = advance;
        nearest = c;
      }
      if (c.gap <= kContactTolerance && c.closing > kSlowImpact && touching.index < 0) {
        touching = c;
      }
    }
  };
  consider(EventType::kBallCushion, table.lines.size());
  consider(EventType::kBallJaw, table.points.size());
  consider(EventType::kBallPocket, table.pockets.size());
  return touching.index >= 0 ? touching : nearest;
}

}  // namespace billiard::table
