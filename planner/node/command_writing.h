// The answer to a SHOT_REQUEST written into its cue_command_t: its ids before anything is
// planned, a refusal, a point plan's or a pot's results, and the last check that what goes out
// passes the receiver's checks. A refused command cannot move the cue: its stroke fields stay
// zero.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>

#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/shot_request_t.hpp"
#include "planner/pot/pot_planner.h"
#include "planner/shot_planner.h"
#include "sim/physics/cue_strike.h"

namespace billiard::planner_node {

// The answer to `q` before anything is planned: its ids and the request's utime, so that the
// answer is a function of the messages alone; a pot's ball, pocket and kind when the request
// passes its checks (those of one that does not may be anything).
cue_command_t ReplyTo(const shot_request_t& q);

// `c` refused with `status` and the one-line `reason`.
cue_command_t Refusal(cue_command_t c, int8_t status, std::string reason);

// The plan into the command. The planner's measurements go out with a refusal too (a
// not-converged plan's miss says by how much); the stroke only with an ok plan, so that a
// refused command cannot move the cue.
void WritePlan(const planner::ShotPlan& plan, cue_command_t* c);

// The pot into the command, the balls named by the table state's ids (`message_id` of each of
// the scene's ids). The stroke, like a point plan's, only with an ok plan.
void WritePot(const pot::PotPlan& plan, const std::unordered_map<int, int32_t>& message_id,
              cue_command_t* c);

// A stroke decided without a plan to write (a safety, a choice's fallback, a break) into the
// command, which it makes ok.
void WriteStroke(const physics::CueStroke& stroke, cue_command_t* c);

// What goes out must pass the receiver's checks, or the answer is lost: a refusal keeps its
// status without the measurements, and an ok that fails them is no ok.
cue_command_t Sendable(const cue_command_t& c);

}  // namespace billiard::planner_node
