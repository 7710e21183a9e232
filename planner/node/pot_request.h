// MODE_POT, with pot::PlanPot (planner/pot/pot_planner.h). A pot is planned on the node's table
// (PlannerNodeOptions::table) among the balls of the latest TABLE_STATE, every ball its publisher
// knows of (one it no longer names is gone: pocketed, or lost by the estimator), each at rest
// where it was seen; the cue ball and the object ball are looked for there. The struck ball is
// the cue ball (id 0 of pot::PlanPot's scene, whatever the estimator calls it); the answer names
// the balls, in object_ball_id and the paths, by the table state's ids.
//
// Refused, with a status and a one-line reason: an object ball the table state does not have (by
// id, or by class at kMinClassConfidence) or that is the struck ball (STATUS_NO_SUCH_BALL), a
// cue-ball target off the playing surface (STATUS_OFF_TABLE), a ball moving faster than
// max_ball_speed (STATUS_INVALID), a pot planner that throws (STATUS_NOT_CONVERGED), and the pot
// planner's own refusals (no_such_pocket, invalid, blocked, too_thin, no_stroke,
// target_unreachable).
#pragma once

#include "lcmtypes/billiard/ball_state_t.hpp"
#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/shot_request_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "planner/node/planner_node_options.h"
#include "sim/physics/parameters.h"
#include "sim/table/table_geometry.h"

namespace billiard::planner_node {

// The pot of a checked MODE_POT request, struck at `cue` (whose state is fit to plan from), among
// the balls of `latest` on `table`, into `c` (the reply with the cue ball's id and start).
cue_command_t AnswerPot(const shot_request_t& q, const ball_state_t& cue,
                        const table_state_t& latest, const table::TableGeometry& table,
                        const physics::ModelParameters& params, const PlannerNodeOptions& options,
                        cue_command_t c);

}  // namespace billiard::planner_node
