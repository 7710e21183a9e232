// Ball in hand: the cue ball (if any) lifted and placed where the choice scores best. The places
// are CandidatePlacements' (placements.h: the best-looking behind each legal target for each
// pocket), the best `ChoiceOptions::placements` of them chosen among by the choice's steps 1-4
// (shot_choice.h); only the placement chosen is confirmed (step 5), so its reported
// probability is no best of several.
//
// Module: billiard::choice.
#pragma once

#include <vector>

#include "planner/choice/choice_options.h"
#include "planner/choice/choice_result.h"
#include "sim/batch/thread_pool.h"
#include "sim/physics/parameters.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::choice {

// The choice with the cue ball in hand: ChoiceResult::cue_placement is where it goes. When no
// place looks pottable, the cue ball where it is, or at the head spot when it was lifted.
ChoiceResult ChooseWithBallInHand(const table::TableGeometry& table,
                                  const physics::ModelParameters& params,
                                  const std::vector<table::SceneBall>& balls,
                                  const ChoiceOptions& options, batch::ThreadPool& pool);

}  // namespace billiard::choice
