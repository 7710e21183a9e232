// The names the nodes agree on: the LCM channels, and the words for the statuses a message
// carries. Every node and tool takes them from here, so that no node includes another to learn
// where to publish.
#pragma once

#include <cstdint>
#include <string>

namespace billiard::messages {

// Channels and the messages they carry (lcmtypes/*.lcm).
inline constexpr char kCameraImageChannel[] = "CAMERA_IMAGE";  // image_t, the camera's frames
inline constexpr char kTableStateChannel[] = "TABLE_STATE";    // table_state_t, the estimator's
inline constexpr char kTableTruthChannel[] = "TABLE_TRUTH";    // table_state_t, the simulator's
inline constexpr char kShotRequestChannel[] = "SHOT_REQUEST";  // shot_request_t, to the planner
inline constexpr char kCueCommandChannel[] = "CUE_COMMAND";    // cue_command_t, the planner's
inline constexpr char kNodeStatusChannel[] = "NODE_STATUS";    // node_status_t, every node's

// table_sim_node's setting among its NODE_STATUS counters: 1 when its frames go by the wall clock
// (--realtime), 0 in lockstep. It is published before the first frame, so that a recorded log
// says whether it can be replayed bit for bit (only a lockstep run can: its order of messages is
// the same every run).
inline constexpr char kRealtimeClockSetting[] = "realtime_clock";

// "ok", "invalid", "off_table", "unreachable", "not_converged", "no_ball_state", "stale_state",
// "busy", and the pot's "no_such_ball", "no_such_pocket", "blocked", "too_thin", "no_stroke",
// "target_unreachable" (cue_command_t's STATUS_*, the pot's words as planner/pot names them),
// "not_at_rest" (the table never came to rest while the request waited);
// "status N" for a value the message does not define.
std::string CueCommandStatusName(std::int8_t status);

// "any", "direct", "bank", "kick", "curve" (shot_request_t's KIND_*, as planner/pot names them);
// "kind N" for a value the message does not define.
std::string PotKindName(std::int8_t kind);

// "any", "nine-ball", "eight-ball", "eight-ball-solids", "eight-ball-stripes" (shot_request_t's
// RULES_*, as sim/rules names the rulesets); "" for a value the message does not define.
std::string ShotRulesName(std::int8_t rules);
// The RULES_* constant of one of those names, -1 for any other.
std::int8_t ShotRulesCode(const std::string& name);

}  // namespace billiard::messages
