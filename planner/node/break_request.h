// MODE_BREAK, a game's break asked of the planner: the rack of the latest TABLE_STATE broken as
// `billiard match` breaks it (planner/game/break_search.h: the game's StoredBreak, found by Monte
// Carlo over the computational pool's noise on the gantry robot's ranges). The cue ball is
// placed on the head string where the break says (the answer's cue_placement, as with ball in
// hand) and struck at the rack's apex, the object ball the estimator sees nearest the head
// string. Refused: a ball moving (STATUS_NOT_AT_REST), a table without an object ball
// (STATUS_NO_SUCH_BALL).
#pragma once

#include "lcmtypes/billiard/ball_state_t.hpp"
#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/shot_request_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "planner/node/planner_node_options.h"
#include "sim/physics/parameters.h"
#include "sim/rules/rules.h"
#include "sim/table/table_geometry.h"

namespace billiard::planner_node {

// The game a checked request's `rules` names (shot_request_t::RULES_*).
rules::Rules RulesOf(const shot_request_t& q);

// The break of a checked MODE_BREAK request, the cue ball `cue`, on the balls of `latest` on
// `table`, into `c` (the reply with the cue ball's id).
cue_command_t AnswerBreak(const shot_request_t& q, const ball_state_t& cue,
                          const table_state_t& latest, const table::TableGeometry& table,
                          const physics::ModelParameters& params,
                          const PlannerNodeOptions& options, cue_command_t c);

}  // namespace billiard::planner_node
