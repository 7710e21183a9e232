// A rack played in simulation, shot by shot: the choice (shot_choice.h) decides, the table
// executes the chosen stroke with the robot's noise on the full model, the rules judge the
// outcome, and the next shot starts from where the balls rest. No camera: the choice sees the
// truth (the closed loop through the estimator is run_loop.sh's).
//
// A visit lasts while the shots pot legally; a shot that pots nothing ends it (the next visit
// plays on from the balls as they lie: one player alone at the table), a foul ends it with ball
// in hand (the cue ball placed by ChooseWithBallInHand). Under nine-ball a 9 potted on a foul
// comes back to the foot spot (WPA Rules of Play), or the nearest free place behind it on the
// long axis. A run-out is a rack cleared in its first visit.
//
// Deterministic: the execution noise of shot n is drawn from SampleSeed(seed + stream, n), its
// own stream, apart from the choice's samples; a seed plays the same game on any thread count.
//
// Module: billiard::choice.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "planner/choice/shot_choice.h"
#include "sim/table/rack.h"

namespace billiard::choice {

// Who decides: ours; ours without the lookahead (score p alone); the easiest-looking pot
// through the ghost ball (ChooseEasiestLooking).
enum class Policy { kOurs, kNoLookahead, kEasiestLooking };
const char* PolicyName(Policy policy);  // "ours", "no-lookahead", "easiest-looking"

struct GameOptions {
  ChoiceOptions choice;  // its noise is the one the choice assumes
  Policy policy = Policy::kOurs;
  params::ExecutionNoise execution = params::LoadNoise(params::kDefaultNoise);  // the table's
  std::uint64_t seed = 1;
  int shot_limit = 40;
  bool ball_in_hand = false;  // the first shot with ball in hand (a drill, or after a break foul)
  // The opening break instead: the cue ball from where it is, rolling at the nearest ball at
  // break_speed (the table simulator's break).
  bool break_shot = false;
  double break_speed = 5.0;  // [m/s]
  int placements = 3;        // ball in hand: places chosen among
  bool single_visit = false;  // stop when the first visit ends (a run-out drill)
};

struct ShotRecord {
  int number = 0;
  int visit = 1;
  bool break_shot = false;
  bool ball_in_hand = false;
  std::optional<Eigen::Vector2d> cue_placement;
  std::string status;  // the choice's ChoiceStatusName
  int ball = -1;       // the called ball and pocket, -1 and "" when none was called
  std::string pocket;
  std::string kind;
  double predicted = -1.0;  // the choice's probability, -1 when it has none
  bool likely = false;
  int first_contact = -1;
  std::vector<int> potted;  // object balls dropped, in id order
  bool called_potted = false;
  bool foul = false;
  std::string foul_reason;
  double decision_us = 0.0;
};

struct GameSummary {
  int shots = 0;
  int attempts = 0;  // shots that called a pot (the break is none)
  int pots = 0;      // of those, the called ball dropped legally
  int fouls = 0;
  int visits = 0;
  int balls_potted = 0;  // legally, the break's included
  bool cleared = false;
  bool run_out = false;
  double median_decision_us = 0.0;
  double pots_per_attempt() const { return attempts ? static_cast<double>(pots) / attempts : 0.0; }
};

struct GameRecord {
  std::vector<ShotRecord> shots;
  GameSummary summary;
  std::vector<table::SceneBall> final_balls;
};

// Plays `balls` (id 0 the cue ball, which may be absent when options.ball_in_hand) until the
// rack is cleared (no object ball left; nine-ball: the 9 potted legally) or shot_limit shots.
GameRecord PlayGame(const table::TableGeometry& table, const physics::ModelParameters& params,
                    std::vector<table::SceneBall> balls, const GameOptions& options,
                    batch::ThreadPool& pool);

// The layouts of the drills and benchmarks (sim/table/rack.h), where the table simulator
// places them too.
using table::SeededNineBallLayout;

}  // namespace billiard::choice
