// The chance of winning the rack from a table, for the safeties' scale (safety.h): a run-out
// model, the rack as a race to pot one's remaining balls in one visit.
//
// The shooter has m balls to pot to win (RunLength: under nine-ball the object balls left, the 9
// last; under eight-ball their group's left and the 8). Their first shot pots with probability q,
// the table's own (the lookahead's closed form, lookahead.h); every later shot of the visit with
// `pot_rate`, the shots a player leaves itself by position play. A miss hands the table over,
// the incoming player's first shot potting with `arrival_chance` (what a miss leaves), their
// later ones with `pot_rate`, both players alike (the opponent valued as we value ourselves).
// The last pot wins. Let W_m(q) be the shooter's chance of winning; then
//   W_0 = 1,  W_m(q) = q W_{m-1}(pot_rate) + (1 - q) (1 - A_m),  A_m = W_m(arrival_chance),
// and A_m, which appears on both sides of its own equation, solves in closed form:
//   A_m = (a W_{m-1}(pot_rate) + 1 - a) / (2 - a),  a = arrival_chance.
// The opponent may miss as we do: leaving them a poor shot is worth their chance of missing times
// ours from what they leave (A_m), not the whole rack, so a safety no longer pays where the pot
// it declines keeps the table often enough (safety.h).
//
// It counts the balls, not where they lie past the first shot: clusters, a ball without a
// pocket and the opponent playing safe in turn are outside it, and the race a miss hands over is
// taken as long as the shooter's (under eight-ball the groups' may differ).
//
// The rates are those of a player that attempts every shot (ours-no-safety), measured on its
// shots in a match (`billiard fit-run-out`, planner/game/run_out_fit.h). W is then the value of
// always attempting, and playing a safety only where it beats the attempt on that value is one
// step of policy improvement (Howard 1960), the on-line improvement Tesauro and Galperin (1996)
// made of a backgammon player by its own rollouts: a step that, on exact values, cannot do worse
// than the policy it starts from.
//
// Module: billiard::choice.
#pragma once

#include <vector>

#include "sim/rules/rules.h"
#include "sim/table/scene.h"

namespace billiard::choice {

// The run-out model's two rates.
struct RunOutRates {
  double pot_rate = 1.0;        // a shot after one's own pot keeps the table
  double arrival_chance = 1.0;  // the first shot after the opponent's miss keeps it
};

// The rates measured for `rules`' game under the computational-pool noise: ours-no-safety's in
// 100 racks against ours (at nine-ball ours on the scale before this one, at eight-ball on this;
// `billiard match --game G --players ours,ours-no-safety --racks 100
// --noise computational-pool --seed 1 --shots LOG`, then `billiard fit-run-out LOG --player 1`;
// docs/match.md, "The safeties' scale"). Nine-ball (and any other game): 272 of 331 shots after
// its own pot kept the table, 74 of 168 first shots after a miss. Eight-ball (each group's
// rules too): 368 of 486 and 98 of 167; more balls to choose from leave a first shot more often.
RunOutRates MeasuredRunOutRates(rules::Rules rules);

// The balls the player shooting under `rules` must still pot to win on `balls` (the cue ball,
// id 0, aside): under nine-ball the object balls left; under eight-ball with a group its balls
// left and the 8, on an open table the smaller group's and the 8; 0 when the rack is over
// (rules::Ruleset::RackOver).
int RunLength(const std::vector<table::SceneBall>& balls, rules::Rules rules);

// W_m(q) above: the chance that the player to shoot, with `balls_to_pot` balls to pot and a
// first shot that pots with probability `first_shot`, wins the rack; 1 when balls_to_pot <= 0.
double RackWinChance(double first_shot, int balls_to_pot, const RunOutRates& rates);

}  // namespace billiard::choice
