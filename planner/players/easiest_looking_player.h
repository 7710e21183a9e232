// The easiest-looking pot, through the ghost ball (planner/choice/easiest_looking.h): the
// baseline of a player without the choice's estimates, with ball in hand the cue ball at the
// easiest-looking place.
//
// Module: billiard::players.
#pragma once

#include "planner/players/player.h"

namespace billiard::players {

class EasiestLooking final : public Player {
 public:
  const char* Name() const override { return "easiest-looking"; }
  choice::ChoiceResult Decide(const Turn& turn, const choice::ChoiceOptions& options,
                              batch::ThreadPool& pool) const override;
};

}  // namespace billiard::players
