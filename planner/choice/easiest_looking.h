// The baseline that looks easiest: what a player without the choice's estimates plays. The
// legal target and pocket of the best EasyPotEstimate (lookahead.h: the shortest, least cut
// clear line) planned as a direct pot and aimed through the ghost ball (pot::GhostBallHeading:
// throw not corrected), its probability not estimated. With ball in hand, the cue ball at the
// easiest-looking place (placements.h). `billiard bench-game` plays it against the choice.
//
// Module: billiard::choice.
#pragma once

#include <vector>

#include "planner/choice/choice_options.h"
#include "planner/choice/choice_result.h"
#include "sim/physics/parameters.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::choice {

// The easiest-looking pot on `balls` under options.rules (options.noise its heading spread):
// the one candidate, its screen_probability and score the estimate, likely when that is at
// least options.likely; kNoPlan with the fallback when no direct pot of a legal ball plans.
ChoiceResult ChooseEasiestLooking(const table::TableGeometry& table,
                                  const physics::ModelParameters& params,
                                  const std::vector<table::SceneBall>& balls,
                                  const ChoiceOptions& options, bool ball_in_hand);

}  // namespace billiard::choice
