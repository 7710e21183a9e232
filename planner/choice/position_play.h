// Position play (step 2, with the lookahead: shot_choice.h): the best few screened pots planned
// again with a cue-ball target, the place the next shot looks easiest from, so that the choice
// weighs the same pot leaving the cue ball where the next is easy.
//
// Module: billiard::choice.
#pragma once

#include <vector>

#include "planner/choice/candidates.h"
#include "planner/choice/choice_options.h"
#include "sim/batch/thread_pool.h"
#include "sim/physics/parameters.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::choice {

// The best `options.position_plans` of `screened` (in the screening's order, those that potted
// at all) planned again with the cue ball sent within options.position_radius of the best
// place on the table without their object ball (CandidatePlacements); those that plan, each
// with its position_target, unscreened.
std::vector<Candidate> PositionCandidates(const table::TableGeometry& table,
                                          const physics::ModelParameters& params,
                                          const std::vector<table::SceneBall>& balls,
                                          std::vector<Candidate> screened,
                                          const ChoiceOptions& options, batch::ThreadPool& pool);

}  // namespace billiard::choice
