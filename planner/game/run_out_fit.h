// The run-out model's two rates (planner/choice/rack_value.h) measured on a match's shot log
// (`billiard match --shots FILE`, a RackJson line a rack): how often a player keeps the table
// on a shot after its own pot, and on its first shot after the other player's miss.
//
// A shot keeps the table when the same player shoots next, or, the rack's last, when its player
// won the rack. Counted, for the player named:
//   - continuing: shots after its own shot that kept the table (the break's next shot aside: a
//     break leaves no position played for);
//   - arriving: shots after the other player's shot that was no foul (a miss, or a safety: the
//     table as it was left, not ball in hand).
// A safety counts as a shot that did not keep the table: the rates are the player's own, its
// safeties and all, the model's "pots" being visits that go on. The rack's last shot of an
// undecided rack (the shot limit) is not counted.
//
// Beside the rates, the scale's calibration: where the player weighed a safety against its best
// attempt (the shot's "attempt_win" and "safety_win"), the estimated chance of winning of the
// stroke it played, summed, and how many of those racks it won. On a calibrated scale the two
// agree: the racks are the truth the estimates answer to.
//
// Module: billiard::game.
#pragma once

#include <nlohmann/json.hpp>

namespace billiard::game {

struct RunOutCounts {
  int continuing = 0;
  int continuing_kept = 0;
  int arriving = 0;
  int arriving_kept = 0;
  // The weighed decisions, by what was played: how many, their estimates' sum, the racks won.
  struct Weighed {
    int count = 0;
    double estimated = 0.0;
    int won = 0;
  };
  Weighed safeties;
  Weighed attempts;
};

// Adds the shots of `player` (0 or 1) in `rack` (match_summary.h's RackJson) to `counts`.
void CountRunOut(const nlohmann::json& rack, int player, RunOutCounts* counts);

}  // namespace billiard::game
