#include "tools/billiard/detected_scene.h"

#include <algorithm>
#include <set>
#include <sstream>

#include "sim/table/table_simulation.h"

namespace billiard::cli {

namespace {

// The first id after pool's fifteen numbers: of balls whose class is no pool number.
constexpr int kFirstOtherId = 16;
// Passes of moving touching balls apart: a cluster's pairs settle in a few.
constexpr int kSeparationPasses = 8;

// The ball's pool number (0 the cue ball), or -1.
int PoolId(estimator::BallClass c) {
  if (c == estimator::BallClass::kCue) return 0;
  const int value = static_cast<int>(c);
  return value >= 1 && value <= 15 ? value : -1;
}

std::vector<int> Ids(const std::vector<DetectedBall>& balls) {
  std::vector<int> ids(balls.size(), -1);
  std::set<int> taken;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const int id = PoolId(balls[i].ball_class);
    if (id >= 0 && taken.insert(id).second) ids[i] = id;
  }
  int next = kFirstOtherId;
  for (int& id : ids) {
    if (id >= 0) continue;
    while (taken.count(next)) ++next;
    id = next;
    taken.insert(next);
  }
  return ids;
}

std::string Position(const Eigen::Vector2d& xy) {
  std::ostringstream text;
  text.precision(3);
  text << std::fixed << "(" << xy.x() << ", " << xy.y() << ")";
  return text.str();
}

// Touching balls measured a little into each other, moved apart to touching.
void SeparateTouching(std::vector<table::SceneBall>* balls, double radius) {
  for (int pass = 0; pass < kSeparationPasses; ++pass) {
    for (std::size_t i = 0; i < balls->size(); ++i) {
      for (std::size_t j = i + 1; j < balls->size(); ++j) {
        auto a = (*balls)[i].state.head<2>(), b = (*balls)[j].state.head<2>();
        const Eigen::Vector2d d = b - a;
        const double overlap = 2 * radius - d.norm();
        if (overlap <= 0 || overlap > kSnapM || d.norm() == 0) continue;
        const Eigen::Vector2d push = 0.5 * overlap * d.normalized();
        a -= push;
        b += push;
      }
    }
  }
}

}  // namespace

params::SceneFile DetectedScene(const std::vector<DetectedBall>& balls,
                                const table::TableGeometry& table, const std::string& table_name,
                                const std::string& params_name, double radius,
                                std::vector<std::string>* notes) {
  params::SceneFile scene;
  scene.table = table_name;
  scene.params = params_name;
  const std::vector<int> ids = Ids(balls);
  const Eigen::Vector2d low(radius, radius), high(table.length - radius, table.width - radius);
  for (std::size_t i = 0; i < balls.size(); ++i) {
    Eigen::Vector2d xy = balls[i].xy;
    const Eigen::Vector2d on = xy.cwiseMax(low).cwiseMin(high);
    if (!table.OnSurface(xy, radius) && (on - xy).norm() <= kSnapM && table.OnSurface(on, radius)) {
      xy = on;
    }
    if (!table.OnSurface(xy, radius)) {
      notes->push_back("ball " + std::to_string(ids[i]) + " at " + Position(balls[i].xy) +
                       " is off the playing surface (in a pocket's jaws, on a rail): left out");
      continue;
    }
    scene.balls.push_back(table::AtRest(ids[i], xy.x(), xy.y()));
  }
  SeparateTouching(&scene.balls, radius);
  table::ValidateScene(table, radius, scene.balls);
  return scene;
}

}  // namespace billiard::cli
