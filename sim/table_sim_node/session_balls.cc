#include "sim/table_sim_node/session_balls.h"

#include <algorithm>
#include <stdexcept>

#include "lcmtypes/billiard/ball_state_t.hpp"
#include "sim/table/rack.h"

namespace billiard::table_sim_node {

std::int8_t TruthClass(int id) {
  return id == kCueBall ? ball_state_t::CLASS_CUE : static_cast<int8_t>(id);
}

std::vector<table::SceneBall>::const_iterator Find(const std::vector<table::SceneBall>& balls,
                                                   int id) {
  return std::find_if(balls.begin(), balls.end(),
                      [id](const table::SceneBall& b) { return b.id == id; });
}

const table::SceneBall& NearestObjectBall(const std::vector<table::SceneBall>& balls,
                                          const std::string& scene) {
  const Eigen::Vector2d cue_at = Find(balls, kCueBall)->state.head<2>();
  const table::SceneBall* object = nullptr;
  for (const table::SceneBall& b : balls) {
    if (b.id == kCueBall) continue;
    if (object == nullptr ||
        (b.state.head<2>() - cue_at).norm() < (object->state.head<2>() - cue_at).norm()) {
      object = &b;
    }
  }
  if (object == nullptr) throw std::invalid_argument(scene + ": no ball to strike at");
  return *object;
}

std::string NearestPocket(const table::TableGeometry& table, const Eigen::Vector2d& at) {
  const auto nearest = std::min_element(table.pockets.begin(), table.pockets.end(),
                                        [&](const auto& a, const auto& b) {
                                          return (a.centre - at).norm() < (b.centre - at).norm();
                                        });
  return nearest->name;
}

std::vector<table::SceneBall> InTheKitchen(const table::TableGeometry& table, double radius,
                                           std::vector<table::SceneBall> balls) {
  const Eigen::Vector2d spot =
      table::FreeSpotFrom(table, radius, balls, {0.25 * table.length, 0.5 * table.width},
                          {-kPlacementStep, 0.0}, kPlacementClearance);
  return table::WithBallAt(std::move(balls), kCueBall, spot);
}

}  // namespace billiard::table_sim_node
