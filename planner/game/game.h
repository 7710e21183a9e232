// A rack played in simulation, shot by shot: a player (planner/players/) decides, the table
// executes the chosen stroke with the robot's noise on the full model, the rules
// (sim/rules/, the ruleset of ChoiceOptions::rules) judge the outcome, and the next shot starts
// from where the balls rest. No camera: the player sees the truth (the closed loop through the
// estimator is run_loop.sh's).
//
// A visit lasts while the shots pot legally; a shot that pots nothing ends it (the next visit
// plays on from the balls as they lie: one player alone at the table), a foul ends it with ball
// in hand (the player places the cue ball). When nothing plans, the player's fallback (a stroke
// that hits the first legal ball full) is played and judged like any other, so a rack goes on
// to its end or the shot limit; the summary says which. The balls the rules put back (under
// nine-ball a 9 potted on a foul, to the foot spot or the nearest free place behind it on the
// long axis) go back before the next shot. A ball the simulation leaves at rest with its centre
// past a pocket's mouth line drops into that pocket (TableGeometry::OnSurface: a real one
// would; a scene with it hanging there is not one a player can be asked about). A run-out is a
// rack cleared in its first visit.
//
// Deterministic: the execution noise of shot n is drawn from SampleSeed(seed + stream, n), its
// own stream, apart from the player's samples (seeded SampleSeed(choice seed, n)); a seed plays
// the same game on any thread count.
//
// Module: billiard::game.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planner/choice/choice_options.h"
#include "planner/choice/monte_carlo.h"
#include "planner/players/player.h"
#include "planner/players/players.h"
#include "sim/batch/thread_pool.h"
#include "sim/params/execution_noise.h"
#include "sim/physics/parameters.h"
#include "sim/table/rack.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::game {

struct GameOptions {
  choice::ChoiceOptions choice;  // its noise is the one the player assumes, its rules the game's
  std::shared_ptr<const players::Player> player = players::MakePlayer("ours");
  params::ExecutionNoise execution = params::LoadNoise(params::kDefaultNoise);  // the table's
  std::uint64_t seed = 1;
  int shot_limit = 40;
  bool ball_in_hand = false;  // the first shot with ball in hand (a drill, or after a break foul)
  // The opening break instead: the cue ball from where it is, rolling at the nearest ball at
  // break_speed (the table simulator's break).
  bool break_shot = false;
  double break_speed = 5.0;  // [m/s]
  bool single_visit = false;  // stop when the first visit ends (a run-out drill)
};

struct ShotRecord {
  int number = 0;
  int visit = 1;
  bool break_shot = false;
  bool ball_in_hand = false;
  std::optional<Eigen::Vector2d> cue_placement;
  std::string status;  // the choice's ChoiceStatusName
  std::string reason;  // the choice's reason when it is not ok (why nothing planned)
  int ball = -1;       // the called ball and pocket, -1 and "" when none was called
  std::string pocket;
  std::string kind;
  double predicted = -1.0;  // the choice's probability, -1 when it has none
  bool likely = false;
  // The stroke commanded (the break's, the chosen pot's or the fallback), none when there was
  // none; its cue's clearance where the robot's was checked (pot::PotPlan::clearance).
  std::optional<physics::CueStroke> stroke;
  std::optional<cue::CueClearance> clearance;
  int first_contact = -1;
  std::vector<int> potted;  // object balls dropped, in id order
  bool called_potted = false;
  bool foul = false;
  std::string foul_reason;
  double decision_us = 0.0;
};

// Why a game ended.
enum class GameEnd {
  kCleared,    // the rules say the rack is over
  kShotLimit,  // GameOptions::shot_limit shots played
  kVisitOver,  // GameOptions::single_visit and the first visit ended
  kNoStroke,   // the player had no stroke to play (an invalid scene): GameSummary::end_reason
};
const char* GameEndName(GameEnd end);  // "cleared", "shot_limit", "visit_over", "no_stroke"

struct GameSummary {
  int shots = 0;
  int attempts = 0;  // shots that called a pot (the break is none)
  int pots = 0;      // of those, the called ball dropped legally
  int fouls = 0;
  int visits = 0;
  int balls_potted = 0;  // legally, the break's included
  bool cleared = false;
  bool run_out = false;
  GameEnd end = GameEnd::kShotLimit;
  std::string end_reason;  // with kNoStroke: the choice's status and reason
  double median_decision_us = 0.0;
  double pots_per_attempt() const { return attempts ? static_cast<double>(pots) / attempts : 0.0; }
};

struct GameRecord {
  std::vector<ShotRecord> shots;
  GameSummary summary;
  std::vector<table::SceneBall> final_balls;
};

// Plays `balls` (id 0 the cue ball, which may be absent when options.ball_in_hand) until the
// rules say the rack is over (no object ball left; nine-ball: the 9 potted legally) or
// shot_limit shots.
GameRecord PlayGame(const table::TableGeometry& table, const physics::ModelParameters& params,
                    std::vector<table::SceneBall> balls, const GameOptions& options,
                    batch::ThreadPool& pool);

// Every ball of `result.rest` resting with its centre past a pocket's mouth line (the line
// TableGeometry::OnSurface does not let a placed ball cross) moved into that pocket: an object
// ball into `pocketed` (after the simulation's own), the cue ball a scratch.
void DropHangingBalls(const table::TableGeometry& table, choice::StrokeResult* result);

// The layouts of the drills and benchmarks (sim/table/rack.h), where the table simulator
// places them too.
using table::SeededNineBallLayout;

}  // namespace billiard::game
