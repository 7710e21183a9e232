#include "planner/pot/testing/pot_layouts.h"

#include <algorithm>
#include <cmath>

#include "planner/pot/pot_geometry.h"
#include "sim/table/seeded_uniform.h"

namespace billiard::pot::testing {

namespace {

constexpr int kMaxPlacementTries = 10000;
// A pocket's rounded noses lie within this distance of its mouth's middle [m].
constexpr double kNearMouth = 0.15;

}  // namespace

PotLayout SeededPotLayout(const table::TableGeometry& table, double radius, std::uint64_t seed,
                          int min_balls, int max_balls) {
  table::SeededUniform random(seed);
  PotLayout layout;
  layout.seed = seed;
  const int n = min_balls + static_cast<int>(random.Below(static_cast<std::size_t>(max_balls - min_balls + 1)));
  const double margin = 2.0 * radius;  // from the cushion noses
  for (int tries = 0; static_cast<int>(layout.balls.size()) < n && tries < kMaxPlacementTries; ++tries) {
    const Eigen::Vector2d p(random.Between(margin, table.length - margin),
                            random.Between(margin, table.width - margin));
    const bool clear = std::all_of(layout.balls.begin(), layout.balls.end(), [&](const table::SceneBall& b) {
      return (b.state.head<2>() - p).norm() > 3.0 * radius;
    });
    if (!clear || !table.OnSurface(p, radius)) continue;
    const int id = static_cast<int>(layout.balls.size());
    layout.balls.push_back({id, physics::MakeBallState(p.x(), p.y(), 0, 0, 0, 0, 0)});
  }
  layout.request.ball = 1 + static_cast<int>(random.Below(layout.balls.size() - 1));
  layout.request.pocket = table.pockets[random.Below(table.pockets.size())].name;
  return layout;
}

bool StraightLineClear(const table::TableGeometry& table, double radius,
                       const std::vector<table::SceneBall>& balls, int object,
                       const std::string& pocket, double max_cut_deg) {
  Eigen::Vector2d cue = Eigen::Vector2d::Zero(), k = Eigen::Vector2d::Zero();
  for (const table::SceneBall& b : balls) {
    if (b.id == 0) cue = b.state.head<2>();
    if (b.id == object) k = b.state.head<2>();
  }
  const table::Pocket* p = table.PocketNamed(pocket);
  const Eigen::Vector2d departure = (p->centre - k).normalized();
  const Eigen::Vector2d ghost = GhostBall(k, departure, radius);
  if (CutAngle((ghost - cue).normalized(), departure) > max_cut_deg * M_PI / 180.0) return false;
  // The pocket's own jaws: a line to the mouth's middle that passes a rounded nose closer than
  // a ball's radius is closed by it (a side pocket seen from along the rail).
  for (const table::CushionPoint& nose : table.points) {
    if ((nose.centre - p->centre).norm() > kNearMouth) continue;
    const Eigen::Vector2d ab = p->centre - k;
    const double s = std::clamp((nose.centre - k).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    if ((k + s * ab - nose.centre).norm() < radius + nose.radius) return false;
  }
  return BallsAcross(balls, k, p->centre, 2.0 * radius, {0, object}).empty() &&
         BallsAcross(balls, cue, ghost, 2.0 * radius, {0, object}).empty();
}

}  // namespace billiard::pot::testing
