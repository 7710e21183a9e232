// The break, optimised by Monte Carlo over the execution noise and the rack.
//
// What: a break is where the cue ball sits on or behind the head string and how it is struck
// (`Break`).
// `EvaluateBreaks` plays each candidate on many seeded racks (table::Rack varies the tiny gaps
// between the balls and the order of the free balls by seed), each stroke perturbed by the
// table's noise, and counts what the referee says of it (`BreakRates`). `SearchBreak` looks for
// the break that keeps the table most often, within the robot's ranges (`BreakRanges`: its
// cue speed and tip offset, sim/params/robots/; behind the head string the cue is raised as
// little as the robot's cue needs to clear the head rail, cue::LeastClearingElevation).
//
// The objective: the most tables kept with few scratches. Only a legal break with a pot keeps
// the table (WPA Rules of Play, Break Shot; the computational pool's eight-ball the same): a
// legal break that pots nothing hands the opponent the balls where they lie, and a scratch (a
// foul, as is an illegal break) hands them ball in hand anywhere, which to a player who pots
// most shots from ball in hand is close to the rack. Breaking harder from the side pots more and
// scratches more, so the search maximises P(kept) subject to the scratch rate's upper Wilson
// (1927) bound, one-sided at `scratch_z` (1: 84 %), being `max_scratch` (5 %, issue 48's) or
// less: a break that only looks safe on the search's racks is not feasible. (At 95 %, 300 racks
// would demand 8 scratches or fewer, 2.7 %, where the breaks that pot half the racks lie near
// 4.5 %.) The search ranks breaks by the kept rate less ten times the bound's excess over
// `max_scratch` (a penalty: feasible breaks by their kept rate alone, infeasible ones walked
// toward the feasible keeping their pots), at equal scratching less. Feasible() says whether
// the break found keeps the bound.
// The earlier objective, P(kept) - P(scratch), priced a scratch at one kept table and let the
// nine-ball break scratch 7.5 %.
//
// The search: a coordinate search on grids (each parameter in turn swept over its grid with the
// others held, the best kept; `rounds` passes), then `refinements` passes of a compass search
// (Kolda, Lewis and Torczon 2003, "Optimization by direct search", SIAM Review): each
// parameter tried half the last step either side of the best, so that a break between the
// coarse grid's points (an eighth of a radius of aim apart, 1 m/s of speed) is reached. Every candidate
// is scored on the same seeded racks and noise draws (common random numbers: candidates differ
// by their strokes, not their luck).
// CueCard, winner of the 2008 Computer Olympiad, credits its win in part to an optimised break
// (Archibald, Altman and Shoham 2009, "Analysis of a winning computational billiards player",
// IJCAI); this is a search of that kind, run once per game and noise and kept as data
// (`StoredBreak`, with the figures it found them by, which a test plays again), since 60
// candidates on 300 racks take minutes on two cores.
//
// Sample s of a run seeded `seed` is rack s of a match seeded `seed` (match.h): its rack seeded
// SampleSeed(seed, s), its noise drawn as that rack's first shot's, so a break's figures here are
// the ones the match's breaks see. Deterministic: each sample's result stored at its index and
// counted in index order, whatever the thread count.
//
// Module: billiard::game.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "planner/choice/monte_carlo.h"
#include "sim/batch/thread_pool.h"
#include "sim/cue/robot.h"
#include "sim/params/execution_noise.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/rules/rules.h"
#include "sim/table/rack.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"
#include "sim/table/table_simulation.h"

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
  // cue level, or raised as little as the robot's cue needs to clear (BreakSetting::robot).
  double tip_height = 0.0;
  // The cue ball this far behind the head string, in the kitchen toward the head cushion [m].
  double behind = 0.0;
};

// The robot's ranges the search keeps within (cue::Robot's speed.max and max_tip_offset), and
// how deep in the kitchen it places the cue ball (0: on the head string only).
struct BreakRanges {
  double max_speed = 8.0;       // [m/s]
  double max_tip_offset = 0.5;  // a fraction of the ball radius
  double max_behind = 0.0;      // [m]
};

// Break `b` set up on `balls` (a rack): the cue ball placed on or behind the head string as `b`
// says (it becomes the first ball), and the stroke it plays, level. Throws std::invalid_argument
// when there is no object ball or the place is off the kitchen.
physics::CueStroke SetUpBreak(const table::TableGeometry& table, double ball_radius, const Break& b,
                              std::vector<table::SceneBall>* balls);

// How often a break did what, over `samples` racks.
struct BreakRates {
  int samples = 0;
  int legal = 0;      // judged legal by the game's rules
  int potted = 0;     // an object ball dropped, legal or not
  int kept = 0;       // legal and an object ball dropped: the breaker stays at the table
  int scratches = 0;  // the cue ball dropped
  // Racks the break could not be played on (the cue ball's place off the kitchen, no elevation
  // the robot's cue clears at): counted as breaks that kept nothing, and said, with the first
  // reason, so that a rate of 0 is never a failure in disguise.
  int failed = 0;
  std::string first_failure;
};

// What the search plays on: the game (nine-ball or eight-ball), its rack, the table's noise.
struct BreakSetting {
  const table::TableGeometry& table;
  const physics::ModelParameters& params;
  rules::Rules game = rules::Rules::kNineBall;
  params::ExecutionNoise noise;
  choice::Motion motion;  // the table's (model_choice::TableMotion)
  // When given, each break's cue is raised to the least elevation at which this robot's cue
  // clears the balls and rails (cue::LeastClearingElevation: a cue ball deep in the kitchen puts
  // a level cue into the head rail); a break no elevation clears is played as nothing (not
  // kept). None: every break level.
  const cue::Robot* robot = nullptr;
};

// The rack a game is broken from (nine-ball's diamond, eight-ball's triangle).
table::RackKind RackKindOf(rules::Rules game);

// What one break did on one rack.
struct BreakOutcome {
  bool legal = false;   // judged legal
  bool potted = false;  // an object ball dropped
  bool scratch = false;
};

// Break `b` on rack `sample` of `seed`, judged as the rack's first shot (the header's sample);
// the simulation's events copied to `events` when it is given.
BreakOutcome PlayBreak(const BreakSetting& setting, const Break& b, std::uint64_t seed,
                       std::size_t sample, std::vector<table::TableEvent>* events = nullptr);

// Each of `breaks` played on racks [0, samples) of `seed`, in one batch on `pool`.
std::vector<BreakRates> EvaluateBreaks(const BreakSetting& setting,
                                       const std::vector<Break>& breaks, int samples,
                                       std::uint64_t seed, batch::ThreadPool& pool);

struct BreakSearchOptions {
  BreakRanges ranges;
  int samples = 200;  // racks each candidate is played on
  int rounds = 2;     // passes over the parameters on their coarse grids
  // Passes after the rounds on finer grids about the best: refinement k tries each parameter
  // the coarse step / 2^k either side (the compass search's halving step).
  int refinements = 0;
  std::uint64_t seed = 1;
  double max_scratch = 0.05;  // the scratch rate's bound a feasible break keeps within
  double scratch_z = 1.0;     // the normal quantile of the one-sided bound (84 %)
};

// The upper Wilson bound of `r`'s scratch rate at `z`.
double ScratchBound(const BreakRates& r, double z);

// Whether `r`'s scratch bound is options.max_scratch or less.
bool Feasible(const BreakRates& r, const BreakSearchOptions& options);

// Whether `a` breaks better than `b` (on the same racks), as the header ranks them.
bool BreaksBetter(const BreakRates& a, const BreakRates& b, const BreakSearchOptions& options);

struct BreakSearchResult {
  Break best;
  BreakRates rates;    // the best's, on the search's own racks
  int candidates = 0;  // breaks evaluated
};

// The coordinate search from `start` (the header's): cue_offset over the middle 70 % of the
// head string, aim within half a radius of full, speed from 4 m/s to the robot's most, tip
// height over the robot's range, the place behind the head string to ranges.max_behind (when
// it is > 0), in 5 to 9 steps each; then options.refinements passes on
// finer steps about the best, within the same ranges.
BreakSearchResult SearchBreak(const BreakSetting& setting, const Break& start,
                              const BreakSearchOptions& options, batch::ThreadPool& pool);

// A break SearchBreak found, and what it found it by: its racks (samples from seed) and counts.
struct StoredSearch {
  Break found;
  BreakSearchOptions options;  // ranges, samples, rounds, seed and the scratch bound
  Break start;                 // where the coordinate search started
  int kept = 0;                // on the search's racks
  int scratches = 0;
  bool bounded = true;  // found by the bounded search above (false: by an earlier objective)
};

// The search that found `game`'s break under the computational pool's noise on the gantry
// robot's ranges (docs/match.md gives the command that runs it again); for any other game the
// default Break, found by no search (samples 0).
StoredSearch StoredBreakSearch(rules::Rules game);

// StoredBreakSearch(game).found.
Break StoredBreak(rules::Rules game);

}  // namespace billiard::game
