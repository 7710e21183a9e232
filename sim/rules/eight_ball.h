// Eight-ball as the computational pool tournaments played it (the Computer Olympiads on
// FastFiz; Archibald, Altman and Shoham 2009; FastFiz's Rules.cpp, EightBallState): every shot
// after the break calls a ball and a pocket, and a pot counts only as called.
//  - The break: a legal break pots a ball or drives at least four object balls to a rail
//    (IllegalBreak; FastFiz counts rail contacts of any ball, the WPA four numbered balls, which
//    is what is counted here); a scratch or an illegal break is a foul. The 8 potted on the break
//    is spotted on the foot spot, and the break is judged on the rest. The table is open after
//    it.
//  - On an open table the cue ball may meet any ball but the 8 first and any ball but the 8 may
//    be called (FastFiz lets the 8 be met first; the World Standardized Rules do only as part of
//    a combination; here it is a foul, so that no call can be a shot at the 8). The first called
//    ball potted as called gives the shooter its group (1-7 the solids, 9-15 the stripes):
//    Judgement::group_ball, kept by rack_state.h.
//  - With a group, the first ball met must be of it; with the group cleared, the 8.
//  - After the contact a called ball potted as called, or a ball to a rail (FastFiz: a pot not
//    called does not save the shot from "no rail after contact").
//  - A foul (the pocket games', a wrong first contact, no rail) gives the incoming player ball
//    in hand anywhere on the table (FastFiz: TT_BALL_IN_HAND).
//  - The visit goes on after a called ball potted as called and no foul; anything else ends it.
//  - The 8 potted ends the rack: won when the group was cleared before the shot, the 8 called in
//    that pocket and no foul; lost otherwise (early, not as called, or on a foul; FastFiz loses
//    it early or on a foul, and the World Standardized Rules in a pocket not called).
// Not modelled: the decisions FastFiz offers after a foul on the break or the 8 on it (re-rack,
// or the opponent breaking): the incoming player takes the table with ball in hand, anywhere
// rather than behind the head string.
//
// One ruleset per group (EightBall(Group)), so that the legal targets and the lookahead's end of
// the rack follow from the balls alone: the choice plays the shooter's group's ruleset, and the
// rack's state (rack_state.h) says whose group is whose.
//
// Module: billiard::rules.
#pragma once

#include <vector>

#include "sim/rules/ruleset.h"

namespace billiard::rules {

// The group a player shoots at: none yet (an open table), the solids (1-7), the stripes (9-15).
enum class Group { kOpen, kSolids, kStripes };

// The group of ball `id`: kSolids for 1-7, kStripes for 9-15, kOpen for any other.
Group GroupOf(int id);
// The other of the two groups (kOpen for kOpen).
Group OtherGroup(Group group);

class EightBall final : public Ruleset {
 public:
  static constexpr int kEight = 8;

  explicit EightBall(Group group) : group_(group) {}
  Group group() const { return group_; }

  // "eight-ball" (open), "eight-ball-solids", "eight-ball-stripes".
  const char* Name() const override;
  // The group's balls on the table (open: every object ball but the 8); the 8 alone when none
  // is left.
  std::vector<int> LegalTargets(const std::vector<table::SceneBall>& balls) const override;
  // The 8 gone (or no object ball at all).
  bool RackOver(const std::vector<table::SceneBall>& balls) const override;
  Judgement Judge(const table::TableGeometry& table, const Shot& shot) const override;
  bool CallsShots() const override { return true; }

 private:
  Group group_;
};

}  // namespace billiard::rules
