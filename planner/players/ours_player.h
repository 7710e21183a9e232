// Ours: the choice (planner/choice/shot_choice.h), Monte Carlo over the robot's noise with the
// one-shot lookahead (as ChoiceOptions::lookahead says), and with ball in hand the cue ball
// placed where it scores best (ball_in_hand.h).
//
// Module: billiard::players.
#pragma once

#include <vector>

#include "planner/players/player.h"

namespace billiard::players {

class Ours : public Player {
 public:
  const char* Name() const override { return "ours"; }
  choice::ChoiceResult Decide(const table::TableGeometry& table,
                              const physics::ModelParameters& params,
                              const std::vector<table::SceneBall>& balls,
                              const rules::Constraints& constraints,
                              const choice::ChoiceOptions& options,
                              batch::ThreadPool& pool) const override;
};

}  // namespace billiard::players
