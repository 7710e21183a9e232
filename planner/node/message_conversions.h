// The planners' statuses, kinds and requests in the messages' terms and back: shot_request_t's
// SPIN_ and KIND_ constants, cue_command_t's STATUS_ constants.
#pragma once

#include <cstdint>
#include <optional>

#include "lcmtypes/billiard/ball_state_t.hpp"
#include "lcmtypes/billiard/shot_request_t.hpp"
#include "planner/pot/pot_planner.h"
#include "planner/shot_planner.h"

namespace billiard::planner_node {

// cue_command_t's STATUS_ of a point plan's status, and of a pot's.
int8_t ToMessageStatus(planner::PlanStatus status);
int8_t ToMessageStatus(pot::PotStatus status);

// shot_request_t's KIND_ constants and the pot planner's kinds (KIND_ANY: none).
std::optional<pot::ShotKind> ToShotKind(int8_t kind);
int8_t ToMessageKind(pot::ShotKind kind);

// The planner's request for the ball at `s`, with the message's spin choice (messages::Check has
// made sure it is one of the five).
planner::ShotRequest ToShotRequest(const shot_request_t& q, const ball_state_t& s);

}  // namespace billiard::planner_node
