// Ours: the choice (planner/choice/shot_choice.h), Monte Carlo over the robot's noise with the
// one-shot lookahead (as ChoiceOptions::lookahead says), and with ball in hand the cue ball
// placed where it scores best (ball_in_hand.h).
//
// Ours(false), "no-lookahead": the same choice scoring each pot by its probability alone, p
// rather than p (1 + v) (the lookahead off whatever the options say, and with it position
// play). `billiard bench-game` plays it to show what the lookahead adds.
//
// Module: billiard::players.
#pragma once

#include "planner/players/player.h"

namespace billiard::players {

class Ours final : public Player {
 public:
  explicit Ours(bool lookahead = true) : lookahead_(lookahead) {}
  const char* Name() const override { return lookahead_ ? "ours" : "no-lookahead"; }
  choice::ChoiceResult Decide(const Turn& turn, const choice::ChoiceOptions& options,
                              batch::ThreadPool& pool) const override;

 private:
  bool lookahead_;
};

}  // namespace billiard::players
