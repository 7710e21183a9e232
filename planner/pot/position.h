// Step 7 of a pot, position play: the cue speed and tip height (follow > 0, draw < 0) that pot K
// and leave the cue ball at a target.
//
// Without side spin first, then with half the largest side offset either way (it turns the cue
// ball off the rails and throws K, so it reaches rest points that speed and follow or draw alone
// do not). For each, a 5 x 5 grid of cue speeds and tip heights, each aimed at the drop window's
// middle and played to rest on the search; Gauss-Newton with a Levenberg-Marquardt step (speed
// and tip often move the rest point along one line: a cue ball rolling at contact whatever the
// tip) from the three nearest rest points in turn (the rest point jumps where the cue ball's path
// meets a cushion or a ball); then corrected on the truth with the search's Jacobian.
#pragma once

#include <optional>

#include "planner/pot/aim.h"
#include "planner/pot/drop_window.h"
#include "planner/pot/pot_planner.h"
#include "planner/pot/search_context.h"

namespace billiard::pot {

// The stroke for `target`: `shape` (its speed, tip height and side) and `aimed` (the search's aim
// at `drop`'s middle) moved to it, `truth_aim` set to the truth's aim whose rest met the target;
// a refusal (kTargetUnreachable) saying how near the cue ball came where none does.
std::optional<Refusal> Position(SearchContext& search, const CueTarget& target, StrokeShape* shape, Aimed* aimed,
                                const Drop& drop, std::optional<Aimed>* truth_aim);

}  // namespace billiard::pot
