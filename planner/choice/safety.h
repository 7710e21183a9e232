// Safeties: when no pot is likely enough, a defensive stroke, chosen against the best attempt
// on one scale, the chance of winning the rack.
//
// The candidates (SafetyStrokes) hit a legal ball: headings to it over a grid of thicknesses
// (the cue ball's line passing the object ball's centre at 0, +-0.3, +-0.6 and +-0.85 of a ball's
// width to either side) and speeds (0.7 to 2.6 m/s, soft rolls to two-rail strokes), level and
// without spin; under eight-ball at most the kSafetyTargets legal balls nearest the cue ball.
// Each is played with the noise by the choice's Monte Carlo machinery (monte_carlo.h: the same
// seeds, the results by index): first `safety_screen_samples` times on the closed form, then the
// best `safety_finalists` `safety_samples` times on the full model the table runs, with the best
// attempt's own stroke judged alike on the same seeds.
//
// The scale, execution by execution (WinChance): the rack's run-out model (rack_value.h). The
// player to shoot from a table wins with W_m(q): q its best pot as our own screening sees it
// (BestNextShotValue: the straight ghost-ball estimate of lookahead.h over its legal balls; with
// ball in hand the best place of placements.h), the race as it stands (RaceOf: the balls each
// player has left to pot), the later shots and the other player's visits at the rates measured
// for the game. Then
//   - the stroke fouls (no stroke, a scratch, a wrong or no first contact, no ball to a rail or
//     into a pocket after contact): the opponent has ball in hand, we win 1 - W(q_hand);
//   - we keep the table (the attempt's called ball potted legally; under nine-ball any legal
//     pot): we win W(q_us) on the table left (1 when the rack is won);
//   - else the opponent shoots from the table left: we win 1 - W(q_opp).
// A safety potting the 8 under eight-ball (uncalled) loses the rack: 0.
// The attempt so scored is p W(q_us) + (1 - p) (1 - W(q_opp) or 1 - W(q_hand)); a safety is
// (1 - f)(1 - W(q_opp)) + f (1 - W(q_hand)), f its foul rate. The higher is played.
// The scale it replaced, V = q (whoever pots next wins the rack: the run-out model with both
// rates 1), priced a safety's effect on the opponent at the whole rack, as if their miss were our
// win; ours played 167 safeties in 100 nine-ball racks and won 44 of them against the same
// chooser without safeties (docs/match.md, "The safeties' scale").
//
// When: only when the best attempt's confirmed probability is below `safety_below` (0.6) or no
// pot plans. Above it the attempt wins at least 0.6 W(q_us) and keeps the table 60 % of the time,
// while a safety hands it over every time: on this scale a safety beats it only when the
// attempt's misses leave an easy shot and its pots a hard one, rare where a pot is that likely.
// The search costs about what the choice does (some 300 full-model executions), so skipping it
// keeps the decisions within the budget (median 1 s, p95 4 s).
//
// This is the safety search the computational-pool winners ran beside their pot search (the
// FastFiz client's agent configuration scores safeties on fouls and losses; Archibald, Altman
// and Shoham 2009, CueCard), here valued by the lookahead's own closed form.
//
// Deterministic: execution s of every stroke draws its noise from SampleSeed(seed + stream, s),
// results by index, sums in order: the same verdict on any thread count.
//
// Module: billiard::choice.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "planner/choice/choice_options.h"
#include "planner/choice/choice_result.h"
#include "planner/choice/monte_carlo.h"
#include "sim/batch/thread_pool.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/rules/rules.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::choice {

// Under eight-ball, the safeties aim at this many legal balls, the nearest the cue ball.
inline constexpr int kSafetyTargets = 2;

// The legal ball a safety stroke aims at, with the stroke.
struct SafetyCandidate {
  int target = -1;
  physics::CueStroke stroke;
};

// The candidate safeties of `balls` under `rules` on `table` (the grid above), in target,
// thickness, speed order; none when the cue ball is missing or touches its target. A target that
// another ball hides from the cue ball (across its straight line) is also kicked at off each
// cushion, one kick a cushion and speed: the heading about the mirror's that meets it first
// without noise on `params`' closed form, in the middle of the headings that do. A player
// snookered on the legal ball kicks at it rather than foul for sure.
std::vector<SafetyCandidate> SafetyStrokes(const table::TableGeometry& table,
                                           const physics::ModelParameters& params,
                                           const std::vector<table::SceneBall>& balls,
                                           rules::Rules rules);

// `candidates` as `robot`'s cue can make them: each raised to the elevation its cue needs
// (cue::ElevationFor, the pots' margin included) and slowed where that elevation would hop the
// ball beyond what the table's motion covers at its pace (to cue::HopFreeSpeed within
// cue::TableMaxHop, as the pots' pace is held), dropped where
// no elevation in the robot's range clears, as a pot would be refused. Without a robot, the
// candidates as they are (level).
std::vector<SafetyCandidate> MakeableByCue(const table::TableGeometry& table,
                                           const physics::ModelParameters& params,
                                           const std::vector<table::SceneBall>& balls,
                                           const std::optional<cue::Robot>& robot,
                                           std::vector<SafetyCandidate> candidates);

// The rules the opponent shoots under when we shoot under `rules`: under eight-ball with groups,
// the other group; else the same.
rules::Rules OpponentRules(rules::Rules rules);

// An attempt's call: its ball and pocket.
struct Call {
  int ball = -1;
  std::string pocket;
};

// Our chance of winning the rack after `result`, a stroke played from `before` under
// options.rules, by the model above. `call`: the attempt's, nothing for a safety.
double WinChance(const table::TableGeometry& table, double radius,
                 const std::vector<table::SceneBall>& before, const StrokeResult& result,
                 const std::optional<Call>& call, const ChoiceOptions& options);

// Whether `result` fouls under `rules` from `before`: no stroke, a scratch, a first contact not
// a legal ball, or no ball potted and none to a rail after the contact.
bool Fouls(const std::vector<table::SceneBall>& before, const StrokeResult& result,
           rules::Rules rules);

// The best safety of `balls` (the highest mean WinChance of the finalists on the full model),
// nothing when no candidate exists; the simulations run added to `simulations` when given.
std::optional<SafetyStroke> BestSafety(const table::TableGeometry& table,
                                       const physics::ModelParameters& params,
                                       const std::vector<table::SceneBall>& balls,
                                       const ChoiceOptions& options, batch::ThreadPool& pool,
                                       int* simulations = nullptr);

// The choice `result` (made on `balls` with `options`) weighed against the best safety when its
// chosen pot's reported probability is below options.safety_below or nothing planned:
// result->safety set, with the reason, when the safety's chance of winning is the higher.
void ConsiderSafety(const table::TableGeometry& table, const physics::ModelParameters& params,
                    const std::vector<table::SceneBall>& balls, const ChoiceOptions& options,
                    batch::ThreadPool& pool, ChoiceResult* result);

}  // namespace billiard::choice
