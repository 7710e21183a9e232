#include "planner/choice/placements.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <optional>

#include "planner/choice/lookahead.h"
#include "planner/choice/scene_balls.h"
#include "sim/rules/rules.h"

namespace billiard::choice {

namespace {

// A placed cue ball stays this far clear of the other balls [m].
constexpr double kPlacementClearance = 2e-3;
constexpr double kDegree = M_PI / 180.0;

}  // namespace

std::vector<Placement> CandidatePlacements(const table::TableGeometry& table, double radius,
                                           const std::vector<table::SceneBall>& balls,
                                           const ChoiceOptions& options) {
  constexpr double kBackDistances[] = {0.15, 0.3, 0.5};       // [m] behind the ghost ball
  constexpr double kCutAngles[] = {0.0, 15.0, -15.0, 30.0, -30.0};  // [deg]
  std::vector<table::SceneBall> others;
  for (const table::SceneBall& b : balls) {
    if (b.id != 0) others.push_back(b);
  }
  std::vector<Placement> best;
  for (int ball : rules::LegalTargets(options.rules, others)) {
    const Eigen::Vector2d object = Position(*FindBall(others, ball));
    for (const table::Pocket& pocket : table.pockets) {
      const Eigen::Vector2d to_pocket = (pocket.centre - object).normalized();
      std::optional<Placement> top;
      for (double back : kBackDistances) {
        for (double cut : kCutAngles) {
          const Eigen::Vector2d approach =
              Eigen::Rotation2Dd(cut * kDegree) * to_pocket;
          const Eigen::Vector2d place = object - 2 * radius * to_pocket - back * approach;
          if (!table.OnSurface(place, radius)) continue;
          const bool clear = std::all_of(others.begin(), others.end(), [&](const auto& b) {
            return (Position(b) - place).norm() >= 2 * radius + kPlacementClearance;
          });
          if (!clear) continue;
          const double estimate = EasyPotEstimate(radius, WithCueBallAt(others, place), ball,
                                                  pocket, options.noise);
          if (!top || estimate > top->estimate) top = Placement{place, estimate};
        }
      }
      if (top && top->estimate > 0) best.push_back(*top);
    }
  }
  std::stable_sort(best.begin(), best.end(),
                   [](const Placement& a, const Placement& b) { return a.estimate > b.estimate; });
  return best;
}

}  // namespace billiard::choice
