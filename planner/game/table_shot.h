// One shot on the table, the steps a rack played alone (game.h), a match (match.h) and the
// break's search (break_search.h) share: the player's decision (its call recorded, the cue
// ball placed when in hand), the stroke executed with the table's noise and played to rest (balls hanging past a
// pocket's mouth dropped), and what the referee is shown of it (rules::Shot).
//
// Module: billiard::game.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "planner/choice/choice_options.h"
#include "planner/choice/monte_carlo.h"
#include "planner/players/player.h"
#include "sim/batch/thread_pool.h"
#include "sim/cue/clearance.h"
#include "sim/params/execution_noise.h"
#include "sim/physics/parameters.h"
#include "sim/rules/ruleset.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"
#include "sim/table/table_simulation.h"

namespace billiard::game {

// The table's noise draws from its own stream (seed + kExecutionStream), apart from the
// players' samples, which use the seed itself.
inline constexpr std::uint64_t kExecutionStream = 0x6578656375746521ull;
// A ball the rules put back stays this far clear of the others [m] ...
inline constexpr double kRespotClearance = 2e-3;
// ... moved along its direction in steps of this [m] until it is (rules::PlaceRespotted).
inline constexpr double kRespotStep = 5e-3;

struct ShotRecord {
  int number = 0;
  int visit = 1;
  int player = 0;  // in a match, who shot it (0 or 1)
  bool break_shot = false;
  bool ball_in_hand = false;
  std::optional<Eigen::Vector2d> cue_placement;
  std::string status;  // the choice's ChoiceStatusName
  std::string reason;  // the choice's reason when it is not ok (why nothing planned)
  int ball = -1;       // the called ball and pocket, -1 and "" when none was called
  std::string pocket;
  std::string kind;
  double predicted = -1.0;  // the choice's probability, -1 when it has none
  bool safety = false;      // a safety played (planner/choice/safety.h): no call
  // Where the decision weighed a safety against its best attempt (planner/choice/safety.h): each
  // one's estimated chance of winning the rack (the safety's whether played or not), -1 when
  // not weighed (the safety's -1 too when no safety could be played).
  double attempt_win = -1.0;
  double safety_win = -1.0;
  bool likely = false;
  // The stroke commanded (the break's, the chosen pot's, the safety's or the fallback), none when
  // there was none; its cue's clearance where the robot's was checked (pot::PotPlan::clearance).
  std::optional<physics::CueStroke> stroke;
  std::optional<cue::CueClearance> clearance;
  int first_contact = -1;
  std::vector<int> potted;  // object balls dropped, in id order
  bool called_potted = false;
  bool foul = false;
  std::string foul_reason;
  double decision_us = 0.0;
};

// `player`'s stroke for the shot `turn` shows, its samples seeded `seed`: the cue ball placed
// first (in `balls`) when the player says where, the decision and the call recorded in `rec`;
// none when there is nothing to play.
std::optional<physics::CueStroke> PlayerStroke(const players::Player& player,
                                               const players::Turn& turn,
                                               choice::ChoiceOptions options, std::uint64_t seed,
                                               batch::ThreadPool& pool,
                                               std::vector<table::SceneBall>* balls,
                                               ShotRecord* rec);

// `stroke` perturbed by `noise` (its normal draws from SampleSeed(seed, 0) on), played to rest
// on `motion`, the balls hanging past a pocket's mouth dropped (choice::PlayToRest); the
// simulation's events copied to `events` when it is given (PlayToRest).
choice::StrokeResult ExecuteWithNoise(const table::TableGeometry& table,
                                      const physics::ModelParameters& params,
                                      const std::vector<table::SceneBall>& balls,
                                      const physics::CueStroke& stroke,
                                      const params::ExecutionNoise& noise, std::uint64_t seed,
                                      const choice::Motion& motion,
                                      std::vector<table::TableEvent>* events = nullptr);

// What the referee sees of `result`, played under `constraints` with the call of `rec` (its
// ball and pocket): the potted balls in id order with their pockets.
rules::Shot ShotOf(const rules::Constraints& constraints, const ShotRecord& rec,
                   const choice::StrokeResult& result);

}  // namespace billiard::game
