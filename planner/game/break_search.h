// The break, optimised by Monte Carlo over the execution noise and the rack.
//
// What: a break is where the cue ball sits on the head string and how it is struck (`Break`).
// `EvaluateBreaks` plays each candidate on many seeded racks (table::Rack varies the tiny gaps
// between the balls and the order of the free balls by seed), each stroke perturbed by the
// table's noise, and counts what the referee says of it (`BreakRates`). `SearchBreak` looks for
// the break that keeps the table most often, within the robot's ranges (`BreakRanges`: its
// cue speed and tip offset, sim/params/robots/).
//
// The objective is P(the breaker keeps the table) - P(scratch). Only a legal break with a pot
// keeps the table (WPA Rules of Play, Break Shot; the computational pool's eight-ball the same):
// a legal break that pots nothing hands the opponent the balls where they lie, and a scratch (a
// foul, as is an illegal break) hands them ball in hand anywhere, which to a player who pots
// most shots from ball in hand is close to the rack. So a kept table scores 1, a dry break 0 and
// a scratch -1; at an equal score the lower scratch rate wins. The kept rate alone would rank a
// break that pots one rack more in a hundred and scratches five more above it.
//
// The search: a coordinate search on grids (each parameter in turn swept over its grid with the
// others held, the best kept; `rounds` passes), every candidate scored on the same seeded racks
// and noise draws (common random numbers: candidates differ by their strokes, not their luck).
// CueCard, winner of the 2008 Computer Olympiad, credits its win in part to an optimised break
// (Archibald, Altman and Shoham 2009, "Analysis of a winning computational billiards player",
// IJCAI); this is a search of that kind, run once per game and noise and kept as data
// (`StoredBreak`), since 60 candidates on 200 racks take minutes on two cores.
//
// Sample s of a run seeded `seed` is rack s of a match seeded `seed` (match.h): its rack seeded
// SampleSeed(seed, s), its noise drawn as that rack's first shot's, so a break's figures here are
// the ones the match's breaks see. Deterministic: each sample's result stored at its index and
// counted in index order, whatever the thread count.
//
// Module: billiard::game.
#pragma once

#include <cstdint>
#include <vector>

#include "planner/choice/monte_carlo.h"
#include "sim/batch/thread_pool.h"
#include "sim/params/execution_noise.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/rules/rules.h"
#include "sim/table/rack.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::game {

// A break. The defaults are the table simulator's break (the cue ball on the head spot rolling
// full at the apex ball at 5 m/s), the one every rack was broken with before the search.
struct Break {
  // The cue ball's centre on the head string (x = length / 4), this far from the table's long
  // axis (+y) [m].
  double cue_offset = 0.0;
  // The cue's heading at the apex ball (the object ball nearest the head string) offset across
  // the line of centres by this fraction of a ball radius (+: toward +y of the line); 0 full.
  double aim = 0.0;
  double speed = 5.0;  // the cue's speed at impact [m/s]
  // The tip above the ball's centre, a fraction of the ball radius (< 0 draw, > 0 follow); the
  // cue level.
  double tip_height = 0.0;
};

// The robot's ranges the search keeps within (cue::Robot's speed.max and max_tip_offset).
struct BreakRanges {
  double max_speed = 8.0;       // [m/s]
  double max_tip_offset = 0.5;  // a fraction of the ball radius
};

// Break `b` set up on `balls` (a rack): the cue ball placed on the head string as `b` says (it
// becomes the first ball), and the stroke it plays. Throws std::invalid_argument when there is
// no object ball.
physics::CueStroke SetUpBreak(const table::TableGeometry& table, double ball_radius, const Break& b,
                              std::vector<table::SceneBall>* balls);

// How often a break did what, over `samples` racks.
struct BreakRates {
  int samples = 0;
  int legal = 0;      // judged legal by the game's rules
  int potted = 0;     // an object ball dropped, legal or not
  int kept = 0;       // legal and an object ball dropped: the breaker stays at the table
  int scratches = 0;  // the cue ball dropped
  // The search's objective: the kept rate less the scratch rate (the header's).
  double objective() const {
    return samples ? static_cast<double>(kept - scratches) / samples : 0.0;
  }
};

// What the search plays on: the game (nine-ball or eight-ball), its rack, the table's noise.
struct BreakSetting {
  const table::TableGeometry& table;
  const physics::ModelParameters& params;
  rules::Rules game = rules::Rules::kNineBall;
  params::ExecutionNoise noise;
  choice::Motion motion;  // the table's (model_choice::TableMotion)
};

// The rack a game is broken from (nine-ball's diamond, eight-ball's triangle).
table::RackKind RackKindOf(rules::Rules game);

// Each of `breaks` played on racks [0, samples) of `seed`, in one batch on `pool`.
std::vector<BreakRates> EvaluateBreaks(const BreakSetting& setting,
                                       const std::vector<Break>& breaks, int samples,
                                       std::uint64_t seed, batch::ThreadPool& pool);

struct BreakSearchOptions {
  BreakRanges ranges;
  int samples = 200;  // racks each candidate is played on
  int rounds = 2;     // passes over the parameters
  std::uint64_t seed = 1;
};

struct BreakSearchResult {
  Break best;
  BreakRates rates;    // the best's, on the search's own racks
  int candidates = 0;  // breaks evaluated
};

// The coordinate search from `start` (the header's): cue_offset over the middle 70 % of the
// head string, aim within half a radius of full, speed from 4 m/s to the robot's most, tip
// height over the robot's range, in 5 to 9 steps each.
BreakSearchResult SearchBreak(const BreakSetting& setting, const Break& start,
                              const BreakSearchOptions& options, batch::ThreadPool& pool);

// The break SearchBreak found for `game` under the computational pool's noise on the gantry
// robot's ranges, kept as data (docs/match.md gives the command that finds it again); the
// default Break for any other game.
Break StoredBreak(rules::Rules game);

}  // namespace billiard::game
