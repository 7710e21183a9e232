// Ours: the choice (planner/choice/shot_choice.h), Monte Carlo over the robot's noise with the
// one-shot lookahead (as ChoiceOptions::lookahead says), and with ball in hand the cue ball
// placed where it scores best (ball_in_hand.h).
//
// With safeties ("ours"): when the best pot's probability is below
// ChoiceOptions::safety_below, or nothing plans, the best safety weighed against it on the
// chance of winning the rack (planner/choice/safety.h), and played when that is the higher;
// not with ball in hand (a placement is chosen for a pot), nor in a rack played alone
// (Turn::alone: no opponent to leave a hard shot). "ours-no-safety": the round-3
// chooser a match measures the new player against (issue 48): without safeties and with one
// level (below).
//
// Two levels: the lookahead's next shot planned on the outcomes (planner/choice/second_level.h)
// and position play aimed where it is best. "ours-one-level": "ours" with the next shot valued
// in closed form instead (the chooser before the second level), kept to measure what it adds.
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
  // "ours" with the lookahead and safeties; "no-lookahead" without either.
  explicit Ours(bool lookahead = true)
      : Ours(lookahead, lookahead, lookahead ? "ours" : "no-lookahead") {}
  // The player named `name`, with or without the lookahead and safeties ("ours-no-safety"),
  // its lookahead's next shot planned (the second level) or in closed form ("ours-one-level").
  Ours(bool lookahead, bool safeties, const char* name, bool two_level = true)
      : lookahead_(lookahead), safeties_(safeties), two_level_(two_level), name_(name) {}
  const char* Name() const override { return name_; }
  choice::ChoiceResult Decide(const Turn& turn, const choice::ChoiceOptions& options,
                              batch::ThreadPool& pool) const override;

 private:
  bool lookahead_;
  bool safeties_;
  bool two_level_;
  const char* name_;
};

}  // namespace billiard::players
