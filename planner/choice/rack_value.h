// The chance of winning the rack from a table, for the safeties' scale (safety.h): a run-out
// model, the rack as a race to pot one's remaining balls in one visit.
//
// The shooter has m balls to pot to win (RunLength: under nine-ball the object balls left, the 9
// last; under eight-ball their group's left and the 8). Their first shot pots with probability q,
// the table's own (the lookahead's closed form, lookahead.h); every later shot of the visit with
// `pot_rate`, the shots a player leaves itself by position play. A miss hands the table over,
// the incoming player's first shot potting with `arrival_chance` (what a miss leaves), their
// later ones with `pot_rate`, both players alike (the opponent valued as we value ourselves).
// The last pot wins.
//
// Nine-ball's race is one count: both players pot from the same balls. Let W_m(q) be the
// shooter's chance of winning with m left; then
//   W_0 = 1,  W_m(q) = q W_{m-1}(pot_rate) + (1 - q) (1 - A_m),  A_m = W_m(arrival_chance),
// and A_m, which appears on both sides of its own equation, solves in closed form:
//   A_m = (a W_{m-1}(pot_rate) + 1 - a) / (2 - a),  a = arrival_chance.
// Eight-ball's is two: each player pots its own group and then the 8, the shooter m balls, the
// other n. With V(m, n) = W(pot_rate; m, n) and U(m, n) = W(arrival_chance; m, n),
//   W(q; m, n) = q V(m - 1, n) + (1 - q) (1 - U(n, m)),  V(0, n) = U(0, n) = 1,
// and U(m, n), U(n, m) solve together, a 2 x 2 linear system, for each pair in order of m + n.
// The opponent may miss as we do: leaving them a poor shot is worth their chance of missing times
// ours from what they leave, not the whole rack, so a safety no longer pays where the pot it
// declines keeps the table often enough (safety.h).
//
// It counts the balls, not where they lie past the first shot: clusters, a ball without a
// pocket and the opponent playing safe in turn are outside it.
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

// The rates measured for `rules`' game under the computational-pool noise: ours-no-safety's
// against ours on seed 1 (`billiard match --game G --players ours,ours-no-safety --racks N
// --noise computational-pool --seed 1 --shots LOG`, then `billiard fit-run-out LOG --player 1`;
// docs/match.md, "The safeties' scale"). Nine-ball (and any other game; 100 racks, ours on the
// scale before this one): 272 of 331 shots after its own pot kept the table, 74 of 168 first
// shots after a miss. Eight-ball (each group's rules too; 200 racks, both players knowing the
// table's constants): 733 of 925 and 172 of 264; more balls to choose from leave a first shot
// more often.
RunOutRates MeasuredRunOutRates(rules::Rules rules);

// The balls the player shooting under `rules` must still pot to win on `balls` (the cue ball,
// id 0, aside): under nine-ball the object balls left; under eight-ball with a group its balls
// left and the 8, on an open table the smaller group's and the 8; 0 when the rack is over
// (rules::Ruleset::RackOver).
int RunLength(const std::vector<table::SceneBall>& balls, rules::Rules rules);

// The rack's race as it stands: the balls the shooter and the other player must pot, and whether
// they pot from the same balls (nine-ball) or each from its own group (eight-ball).
struct Race {
  int shooter = 0;
  int other = 0;
  bool shared = true;
};

// The race on `balls` for a shooter under `shooter` and an opponent under `other` (their
// RunLengths; shared unless under eight-ball).
Race RaceOf(const std::vector<table::SceneBall>& balls, rules::Rules shooter, rules::Rules other);

// W above: the chance that the player to shoot, with a first shot that pots with probability
// `first_shot`, wins `race`; 1 when the shooter has nothing left to pot, 0 when (two counts)
// the other has.
double RackWinChance(double first_shot, const Race& race, const RunOutRates& rates);

}  // namespace billiard::choice
