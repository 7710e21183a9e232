#include "sim/table_sim_node/session_balls.h"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <utility>

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

TableOutcome OutcomeOf(const table::TableSimulation& sim, const table::TableGeometry& geometry,
                       int called, const std::string& called_pocket) {
  TableOutcome outcome;
  std::vector<std::pair<int, std::string>> dropped;
  for (std::size_t i = 0; i < sim.ball_count(); ++i) {
    std::optional<std::string> pocket = sim.pocket(i);
    const table::Pocket* hanging = geometry.PocketPastMouth(sim.State(i).head<2>());
    if (!pocket && hanging) pocket = hanging->name;
    if (!pocket) {
      outcome.rest.push_back({sim.id(i), sim.State(i)});
    } else if (sim.id(i) == kCueBall) {
      outcome.scratch = true;
    } else {
      dropped.emplace_back(sim.id(i), *pocket);
      if (sim.id(i) == called && *pocket == called_pocket) outcome.called_potted = true;
    }
  }
  std::sort(dropped.begin(), dropped.end());
  for (const auto& [ball, pocket] : dropped) {
    outcome.potted.push_back(ball);
    outcome.pockets.push_back(pocket);
  }
  return outcome;
}

std::vector<table::SceneBall> InTheKitchen(const table::TableGeometry& table, double radius,
                                           std::vector<table::SceneBall> balls) {
  const Eigen::Vector2d spot =
      table::FreeSpotFrom(table, radius, balls, {0.25 * table.length, 0.5 * table.width},
                          {-kPlacementStep, 0.0}, kPlacementClearance);
  return table::WithBallAt(std::move(balls), kCueBall, spot);
}

}  // namespace billiard::table_sim_node
