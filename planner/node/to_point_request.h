// MODE_TO_POINT: one ball to a point. The request's ball, at its latest state, is planned to the
// target with the shot planner (planner/shot_planner.h) on the parameter set's table, with the
// request's spin choice, final speed and side spin; with the node's robot (PotOptions::robot,
// --robot), at the elevation its cue needs to clear the rails, the other balls of the latest
// states and its body (planner/cue_planning.h), refused STATUS_CUE_BLOCKED where none does.
#pragma once

#include <vector>

#include "lcmtypes/billiard/ball_state_t.hpp"
#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/shot_request_t.hpp"
#include "planner/node/planner_node_options.h"
#include "planner/shot_planner.h"
#include "sim/physics/parameters.h"
#include "sim/table/table_geometry.h"

namespace billiard::planner_node {

// The plan of a checked MODE_TO_POINT request for the ball at `ball` (whose state is fit to plan
// from) on `table`, the cue checked against the `seen` balls (the latest table state's, `ball`
// among them or not) where `options.pot.robot` is set, into `c` (the reply with the ball's id and start): the
// planner's status and reason, its measurements, and the stroke when ok; STATUS_NOT_CONVERGED
// when the planner throws.
cue_command_t AnswerToPoint(const shot_request_t& q, const ball_state_t& ball,
                            const std::vector<const ball_state_t*>& seen, const table::TableGeometry& table,
                            const physics::ModelParameters& params, const PlannerNodeOptions& options,
                            cue_command_t c);

}  // namespace billiard::planner_node
