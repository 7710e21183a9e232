// A rack between two players, refereed: what the rules keep from shot to shot. A ruleset judges
// a shot alone (ruleset.h); the rack's state says who is at the table, how many fouls each has
// made in a row, which group each shoots at (eight-ball), whether the table may be handed back
// after a push-out (nine-ball), and, when the rack is over, who won it and why. The players hold
// none of it: they are shown the constraints it gives (NextConstraints) and decide.
//
// The shape is pooltool's `ruleset/` (Kiefl 2024: a ruleset's state, the active player, advanced
// by each shot's judgement).
//
// Module: billiard::rules.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "sim/rules/rules.h"
#include "sim/rules/ruleset.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::rules {

struct RackState {
  Rules game = Rules::kNineBall;
  // Each player's ruleset: the game's, or under eight-ball its group's once taken.
  std::array<Rules, 2> rules = {Rules::kNineBall, Rules::kNineBall};
  int breaker = 0;
  int shooter = 0;  // the player at the table, 0 or 1
  int shots = 0;    // shots played in the rack, the break the first
  bool ball_in_hand = false;                // the next shot's
  std::array<int, 2> fouls_in_a_row = {0, 0};
  bool may_pass = false;  // the shooter may hand the table back (after the other's push-out)
  bool over = false;
  int winner = -1;  // with over: 0 or 1
  std::string reason;  // with over: why (the judgement's rack_reason, or the fouls in a row)
};

// A rack of `game` about to be broken by player `breaker`.
RackState NewRack(Rules game, int breaker);

// The ruleset the shooter plays under (its group's, under eight-ball).
const Ruleset& ShooterRules(const RackState& rack);

// What the next shot may do on `balls`: ball in hand, the legal first contacts (the shooter's
// group), whether it must call (eight-ball after the break), whether it may be a push-out (the
// shot after the break, nine-ball).
Constraints NextConstraints(const RackState& rack, const std::vector<table::SceneBall>& balls);

// `shot`, played by the shooter, judged by its ruleset, and the rack advanced: the fouls in a row
// counted (a legal shot clears them; as many as FoulsThatLose lose the rack), the rack's end and
// its winner, the group taken on an open table (the other player gets the other), the table to
// the other player when the visit ends.
Judgement Referee(const table::TableGeometry& table, const Shot& shot, RackState* rack);

// After a push-out the incoming player (the shooter, with may_pass) hands the table back: the
// player who pushed out shoots again, from where the balls lie (WPA Rules of Play, Push Out).
void PassBack(RackState* rack);

}  // namespace billiard::rules
