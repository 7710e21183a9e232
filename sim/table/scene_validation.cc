#include "sim/table/scene_validation.h"

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sim/table/contact_search.h"

namespace billiard::table {

using physics::kX;

void ValidateScene(const TableGeometry& table, double radius, const std::vector<SceneBall>& balls) {
  std::set<int> ids;
  for (const SceneBall& b : balls) {
    const std::string name = "ball " + std::to_string(b.id);
    if (!b.state.allFinite()) throw std::invalid_argument(name + ": a state number is not finite");
    if (!(b.flight.height >= 0.0) || !std::isfinite(b.flight.height) ||
        !std::isfinite(b.flight.vertical_speed)) {
      throw std::invalid_argument(name + ": its flight is not a finite height of 0 or more");
    }
    if (b.id < 0) throw std::invalid_argument(name + ": ids are 0 (the cue ball) or more");
    if (!ids.insert(b.id).second) throw std::invalid_argument(name + ": the id is repeated");
    if (!table.OnSurface(b.state.segment<2>(kX), radius)) {
      std::ostringstream what;
      what << name << " at (" << b.state[kX] << ", " << b.state[kX + 1] << ") is off the "
           << table.name << " playing surface (or on a cushion or over a pocket)";
      throw std::invalid_argument(what.str());
    }
  }
  for (std::size_t i = 0; i < balls.size(); ++i) {
    for (std::size_t j = i + 1; j < balls.size(); ++j) {
      const double gap =
          (balls[i].state.segment<2>(kX) - balls[j].state.segment<2>(kX)).norm() - 2.0 * radius;
      if (gap < -kContactTolerance) {
        std::ostringstream what;
        what << "balls " << balls[i].id << " and " << balls[j].id << " overlap by " << -gap << " m";
        throw std::invalid_argument(what.str());
      }
    }
  }
}

std::vector<SceneBall> SettledScene(const TableGeometry& table, double radius,
                                    std::vector<SceneBall> balls, double max_overlap) {
  // Apart by a hair more than the overlap, so that the contact tolerance is not spent.
  constexpr double kClearance = 1e-9;  // [m]
  constexpr int kSweeps = 100;         // a row of touching balls settles in as many as it is long
  const Eigen::Vector2d middle(0.5 * table.length, 0.5 * table.width);
  const auto settle_on_surface = [&](SceneBall& b) {
    Eigen::Vector2d p = b.state.segment<2>(kX);
    const Eigen::Vector2d inward = (middle - p).normalized();
    const double step = max_overlap / 16.0;
    for (double moved = 0.0; !table.OnSurface(p, radius) && moved < max_overlap; moved += step) {
      p += step * inward;
    }
    b.state.segment<2>(kX) = p;
  };
  for (SceneBall& b : balls) {
    if (b.state.allFinite()) settle_on_surface(b);
  }
  for (int sweep = 0; sweep < kSweeps; ++sweep) {
    bool moved = false;
    for (std::size_t i = 0; i < balls.size(); ++i) {
      for (std::size_t j = i + 1; j < balls.size(); ++j) {
        Eigen::Vector2d d = balls[j].state.segment<2>(kX) - balls[i].state.segment<2>(kX);
        const double overlap = 2.0 * radius - d.norm();
        if (!(overlap > kContactTolerance) || overlap > max_overlap || !(d.norm() > 0.0)) continue;
        const Eigen::Vector2d half = 0.5 * (overlap + kClearance) * d.normalized();
        balls[i].state.segment<2>(kX) -= half;
        balls[j].state.segment<2>(kX) += half;
        moved = true;
      }
    }
    for (SceneBall& b : balls) {
      if (b.state.allFinite()) settle_on_surface(b);
    }
    if (!moved) break;
  }
  ValidateScene(table, radius, balls);
  return balls;
}

}  // namespace billiard::table
