// The balls of a table session as the truth names them: the cue ball is id 0, an object ball's
// id is its number (the class the estimator should publish it with). Finding them, the object
// ball the cue ball is rolled into at a break, what a game shot left on the table and dropped,
// and the cue ball put back in the kitchen after a scratch.
//
// Module: billiard::table_sim_node.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"
#include "sim/table/table_simulation.h"

namespace billiard::table_sim_node {

// The cue ball, as the truth names it.
inline constexpr int kCueBall = 0;

// Ball in hand: a placement on another ball moves toward the head rail in steps of this [m];
// a respotted ball is this far clear of the others [m].
inline constexpr double kPlacementStep = 1e-3;
inline constexpr double kPlacementClearance = 2e-3;

// The class the estimator should publish ball `id` with: its number, the cue ball's
// ball_state_t::CLASS_CUE.
std::int8_t TruthClass(int id);

// Ball `id` of `balls`, balls.end() when it is not there.
std::vector<table::SceneBall>::const_iterator Find(const std::vector<table::SceneBall>& balls,
                                                   int id);

// The object ball nearest the cue ball (id 0, which must be there); throws std::invalid_argument
// naming `scene` when there is none.
const table::SceneBall& NearestObjectBall(const std::vector<table::SceneBall>& balls,
                                          const std::string& scene);

// The name of the pocket nearest `at`.
std::string NearestPocket(const table::TableGeometry& table, const Eigen::Vector2d& at);

// What the table did with a game shot: the balls left at rest, the object balls dropped
// (ascending) and the pocket of each, whether the cue ball dropped, and whether the ball
// `called` dropped in `pocket`.
struct TableOutcome {
  std::vector<table::SceneBall> rest;
  std::vector<int> potted;
  std::vector<std::string> pockets;
  bool scratch = false;
  bool called_potted = false;
};

// The outcome of `sim`, played to rest, calling ball `called` in `called_pocket`. A ball come
// to rest past a pocket's mouth line hangs there in the model, where a real one would drop
// (table::TableGeometry::PocketPastMouth): it drops in that pocket, as in the planner's own
// games (choice::PlayToRest). A ball frozen to a rail stays.
TableOutcome OutcomeOf(const table::TableSimulation& sim, const table::TableGeometry& geometry,
                       int called, const std::string& called_pocket);

// `balls` with the cue ball (id 0) back on the table: on the head spot (the middle of the head
// half, x = 1/4 length), or the nearest free place behind it toward the head rail.
std::vector<table::SceneBall> InTheKitchen(const table::TableGeometry& table, double radius,
                                           std::vector<table::SceneBall> balls);

}  // namespace billiard::table_sim_node
