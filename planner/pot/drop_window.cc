#include "planner/pot/drop_window.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace billiard::pot {

using physics::BallState;
using table::SceneBall;
using table::TableSimulation;

bool Drops(SearchContext& search, const Contact& c, double direction, double scale, bool truth) {
  std::vector<SceneBall> balls = c.others;
  BallState object = Rotated(c.object_after, Wrap(direction - c.departure));
  object.tail<5>() *= scale;
  balls.push_back({search.object_id(), object});
  std::unique_ptr<TableSimulation> sim = search.Simulation(balls, truth);
  sim->RunUntil(search.KsFate(*sim));
  const std::optional<std::string>& dropped = sim->pocket(balls.size() - 1);
  return dropped && *dropped == search.pocket().name;
}

double ReachScale(const Contact& c, double min_speed) {
  const double speed = c.object_after.segment<2>(physics::kVx).norm();
  return speed > 0.0 ? std::max(1.0, min_speed / speed) : 1.0;
}

std::optional<Drop> DropWindow(SearchContext& search, const Contact& c, double route_direction, double scan,
                               double min_speed, double resolution, const std::optional<Drop>& hint,
                               bool truth) {
  const double scale = ReachScale(c, min_speed);
  const auto drops = [&](double direction) { return Drops(search, c, direction, scale, truth); };
  // The half-width of the window a straight path would have: the capture line's half-length
  // less a ball's radius, seen from where K leaves.
  const table::Pocket& pocket = search.pocket();
  const double capture = 0.5 * (pocket.capture_b - pocket.capture_a).norm();
  const double guess = std::max(kWindowStep, (capture - search.radius()) / (pocket.centre - c.object_at).norm());
  std::optional<double> inside;
  for (double d = 0.0; d <= scan && !inside; d += kWindowStep) {
    for (double sign : {1.0, -1.0}) {
      if (drops(route_direction + sign * d)) {
        inside = route_direction + sign * d;
        break;
      }
      if (d == 0.0) break;
    }
  }
  if (!inside) return std::nullopt;
  const auto edge = [&](double sign) {
    double in = *inside, out = in;
    if (hint) {
      // The hint's edge, a coarse step either side of it.
      const double near = (sign > 0.0 ? hint->hi : hint->lo);
      const double a = near - sign * kCoarseWindowResolution, b = near + sign * kCoarseWindowResolution;
      if ((a - in) * sign > 0.0 && drops(a)) in = a;
      out = drops(b) ? in : b;
    }
    if (out == in) {
      // Out from the inside, first by the half-width the pocket's opening would give seen
      // from K, then growing.
      double step = 0.8 * guess;
      out = in + sign * step;
      while (drops(out)) {
        in = out;
        step = std::max(0.5 * guess, 0.5 * std::abs(out - *inside));
        out = in + sign * step;
        if (std::abs(out - *inside) > kWidestWindow) return in;
      }
    }
    while (std::abs(out - in) > resolution) {
      const double mid = 0.5 * (in + out);
      (drops(mid) ? in : out) = mid;
    }
    return in;
  };
  Drop drop;
  drop.lo = edge(-1.0);
  drop.hi = edge(1.0);
  return drop;
}

}  // namespace billiard::pot
