// MODE_CHOOSE, "choose and play", with the choice of planner/choice/shot_choice.h. A choice is
// made among the balls of the latest TABLE_STATE as a pot is (pot_request.h), on the node's
// table, under the request's rules, with ball in hand when the request says so (the cue ball
// lifted and placed: the answer's cue_placement). The balls are named by the estimator's classes
// (BallNumbers: the rules need the numbers) and the answer names them back by the table state's
// ids. Its noise samples are seeded by PlannerNodeOptions::choice.seed and the request_id, so
// that a logged run replays to the same choice. An object ball seen further over a pocket's mouth
// (or into a cushion) than pot.settle_overlap is taken for dropping and left out. When no pot
// plans, the answer is ok with object_ball_id -1 and the choice's fallback stroke (the first
// legal ball hit full). Refused: a ball moving (STATUS_INVALID), a table without an object ball
// (STATUS_NO_SUCH_BALL), and what the choice refuses or throws (STATUS_INVALID).
//
// The choice is the player's (planner/players/player.h, PlannerNodeOptions::player): it is shown
// the balls and the rules' constraints (the cue ball in hand or not, the legal first contacts).
#pragma once

#include "lcmtypes/billiard/ball_state_t.hpp"
#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/shot_request_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "planner/node/planner_node_options.h"
#include "planner/players/player.h"
#include "sim/batch/thread_pool.h"
#include "sim/physics/parameters.h"
#include "sim/table/table_geometry.h"

namespace billiard::planner_node {

// The choice of a checked MODE_CHOOSE request, the cue ball `cue` (whose state is fit to plan
// from), among the balls of `latest` on `table`, decided by `player` with its samples run on
// `pool`, into `c` (the reply with the cue ball's id and start).
cue_command_t AnswerChoice(const shot_request_t& q, const ball_state_t& cue,
                           const table_state_t& latest, const table::TableGeometry& table,
                           const physics::ModelParameters& params,
                           const PlannerNodeOptions& options, const players::Player& player,
                           batch::ThreadPool& pool, cue_command_t c);

}  // namespace billiard::planner_node
