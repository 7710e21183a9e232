// Ours without the lookahead: the choice scoring each pot by its probability alone, p, not
// p (1 + v) (ChoiceOptions::lookahead off, so no position play either). `billiard bench-game`
// plays it to show what the lookahead adds.
//
// Module: billiard::players.
#pragma once

#include <vector>

#include "planner/players/ours_player.h"

namespace billiard::players {

class NoLookahead final : public Ours {
 public:
  const char* Name() const override { return "no-lookahead"; }
  choice::ChoiceResult Decide(const table::TableGeometry& table,
                              const physics::ModelParameters& params,
                              const std::vector<table::SceneBall>& balls,
                              const rules::Constraints& constraints,
                              const choice::ChoiceOptions& options,
                              batch::ThreadPool& pool) const override;
};

}  // namespace billiard::players
