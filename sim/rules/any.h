// Any ball: the cue ball may hit any object ball first and pot any; the fouls are the pocket
// games' own (ruleset.h: a miscue, a scratch, no contact), each giving ball in hand; nothing is
// respotted; the rack is over when no object ball is left. Not a game of the rule books: the
// drills' and the choice's default, where which ball is played is the player's alone.
//
// Module: billiard::rules.
#pragma once

#include <vector>

#include "sim/rules/ruleset.h"

namespace billiard::rules {

class AnyBall final : public Ruleset {
 public:
  const char* Name() const override { return "any"; }
  // Every object ball.
  std::vector<int> LegalTargets(const std::vector<table::SceneBall>& balls) const override;
  // No object ball left.
  bool RackOver(const std::vector<table::SceneBall>& balls) const override;
  Judgement Judge(const table::TableGeometry& table, const Shot& shot) const override;
};

}  // namespace billiard::rules
