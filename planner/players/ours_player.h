// Ours: the choice (planner/choice/shot_choice.h), Monte Carlo over the robot's noise with the
// one-shot lookahead (as ChoiceOptions::lookahead says), and with ball in hand the cue ball
// placed where it scores best (ball_in_hand.h).
//
// "ours-no-safety": ours without safeties; the same player as "ours" until safeties exist.
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
  explicit Ours(bool lookahead = true) : Ours(lookahead, lookahead ? "ours" : "no-lookahead") {}
  // `name` for the same player under another name: "ours-no-safety", the player a match with
  // safeties is measured against (issue 48), the same as "ours" until ours plays safeties.
  Ours(bool lookahead, const char* name) : lookahead_(lookahead), name_(name) {}
  const char* Name() const override { return name_; }
  choice::ChoiceResult Decide(const Turn& turn, const choice::ChoiceOptions& options,
                              batch::ThreadPool& pool) const override;

 private:
  bool lookahead_;
  const char* name_;
};

}  // namespace billiard::players
