// Nine-ball, as the WPA Rules of Play (World Pool-Billiard Association) have it:
//  - "On each shot the first ball the cue ball contacts must be the lowest-numbered ball on the
//    table" (Nine-Ball, Object of the Game), the break too ("the breaker must strike the one
//    ball first", Break Shot);
//  - a legal break pots a ball or drives at least four numbered balls to the rail (Break Shot;
//    IllegalBreak);
//  - after the contact a ball is pocketed or a ball (the cue ball or a numbered one) meets a
//    rail (Standard Fouls, No Rail after Contact);
//  - a scratch (Cue Ball Scratch), a wrong first contact (Wrong Ball First) or none is a foul,
//    and after a foul the incoming player has the cue ball in hand anywhere on the table;
//  - the shot after the break may be declared a push-out (Push Out): no ball need be met and no
//    rail reached, a scratch is still a foul, a 9 potted is spotted, and the incoming player
//    takes the table or hands it back (Judgement::opponent_may_pass; rack_state.h);
//  - three fouls in a row without a legal shot between lose the rack (Three Consecutive Fouls;
//    counted by rack_state.h; the warning the referee gives before the third is not modelled);
//  - the 9 potted on a foul or a push-out is spotted: on the foot spot, or when that is taken on
//    the long string behind it, toward the foot rail, as near the spot as it is free (Nine-Ball,
//    Spotting Balls; General Rules, Spotting Balls);
//  - the rack is won by pocketing the 9 on a legal shot, the break's included (Object of the
//    Game); a rack with no object ball left (one racked without the 9) is over too.
// A stroke the cue cannot give is judged a miscue, a foul (the pocket games' fouls, ruleset.h).
//
// Module: billiard::rules.
#pragma once

#include <vector>

#include "sim/rules/ruleset.h"

namespace billiard::rules {

class NineBall final : public Ruleset {
 public:
  // The ball whose legal pot wins the rack, respotted when potted on a foul.
  static constexpr int kNine = 9;

  const char* Name() const override { return "nine-ball"; }
  // The lowest-numbered object ball alone (none when the table has none).
  std::vector<int> LegalTargets(const std::vector<table::SceneBall>& balls) const override;
  // No object ball left, or the 9 gone.
  bool RackOver(const std::vector<table::SceneBall>& balls) const override;
  Judgement Judge(const table::TableGeometry& table, const Shot& shot) const override;
  int FoulsThatLose() const override { return kFoulsThatLose; }
  bool PushOutAfterBreak() const override { return true; }

 private:
  static constexpr int kFoulsThatLose = 3;
};

// The foot spot of `table`: the middle of its foot half (x = 3/4 length, across the middle).
Eigen::Vector2d FootSpot(const table::TableGeometry& table);

}  // namespace billiard::rules
