// MODE_TO_POINT: one ball to a point. The request's ball, at its latest state, is planned to the
// target with the shot planner (planner/shot_planner.h) on the parameter set's table, with the
// request's spin choice, final speed and side spin.
#pragma once

#include "lcmtypes/billiard/ball_state_t.hpp"
#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/shot_request_t.hpp"
#include "planner/shot_planner.h"
#include "sim/physics/parameters.h"

namespace billiard::planner_node {

// The plan of a checked MODE_TO_POINT request for the ball at `ball` (whose state is fit to plan
// from), into `c` (the reply with the ball's id and start): the planner's status and reason, its
// measurements, and the stroke when ok; STATUS_NOT_CONVERGED when the planner throws.
cue_command_t AnswerToPoint(const shot_request_t& q, const ball_state_t& ball,
                            const physics::ModelParameters& params,
                            const planner::PlannerOptions& options, cue_command_t c);

}  // namespace billiard::planner_node
