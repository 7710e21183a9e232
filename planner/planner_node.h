// The planner node: answers every SHOT_REQUEST with a CUE_COMMAND planned (shot_planner.h) from
// the latest TABLE_STATE.
//
//   TABLE_STATE   table_state_t    keeps the latest state received of each ball_id (a message
//                                  naming some balls leaves the others as they were)
//   SHOT_REQUEST  shot_request_t   one cue_command_t per request, ok or refused
//   CUE_COMMAND   cue_command_t    utime, request_id and ball_id of the request
//
// The answer depends only on the messages received, never on the clock: its utime is the
// request's, so a logged run replays to the same commands (all but solve_us, the planning wall
// time the message carries by design).
//
// Refusals (status != STATUS_OK, the reason in words, the stroke fields zero; the plan fields say
// what the planner measured, zero when it did not run):
//   STATUS_INVALID        an unknown spin value, a non-finite number in the request or in the
//                         ball's state, a ball moving faster than max_ball_speed
//   STATUS_NO_BALL_STATE  no table state received has that ball_id
//   STATUS_NOT_CONVERGED  also when the planner throws (an integrator giving up): the request
//                         gets an answer all the same
//   the others            PlanShot's status (shot_planner.h)
//
// A node never dies on a message: a payload that does not decode is logged and dropped, and every
// handler catches what it throws. One log line per event: each answer, each dropped message.
#pragma once

#include <cstdint>
#include <functional>
#include <lcm/lcm-cpp.hpp>
#include <string>
#include <unordered_map>

#include "billiard/ball_state_t.hpp"
#include "billiard/cue_command_t.hpp"
#include "billiard/shot_request_t.hpp"
#include "parameters.h"
#include "shot_planner.h"

namespace billiard::planner {

inline constexpr char kTableStateChannel[] = "TABLE_STATE";
inline constexpr char kShotRequestChannel[] = "SHOT_REQUEST";
inline constexpr char kCueCommandChannel[] = "CUE_COMMAND";

struct PlannerNodeOptions {
  PlannerOptions planner;
  // A ball faster than this [m/s] is still moving: a plan from where it is now would start from
  // the wrong place, so the request is refused. The default is above an estimator's noise on a
  // ball at rest and below any ball that will roll on for more than a few millimetres.
  double max_ball_speed = 0.05;
};

// "ok", "invalid", "off_table", "unreachable", "not_converged", "no_ball_state"; "status N"
// for a value the message does not define.
std::string CueCommandStatusName(int8_t status);

class PlannerNode {
 public:
  using Log = std::function<void(const std::string& line)>;

  // Subscribes on `lcm`, which must outlive the node; `log` gets one line per event (stderr by
  // default).
  PlannerNode(lcm::LCM& lcm, ModelParameters params, PlannerNodeOptions options = {},
              Log log = nullptr);
  ~PlannerNode();  // unsubscribes
  PlannerNode(const PlannerNode&) = delete;
  PlannerNode& operator=(const PlannerNode&) = delete;

  // The answer to `request` from the states received so far: what the node publishes.
  cue_command_t Answer(const shot_request_t& request) const;

 private:
  // Raw handlers: the node decodes the payload itself so that a failure is logged its way.
  void OnTableState(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  void OnShotRequest(const lcm::ReceiveBuffer* rbuf, const std::string& channel);

  lcm::LCM& lcm_;
  const ModelParameters params_;
  const PlannerNodeOptions options_;
  const Log log_;
  std::unordered_map<int32_t, ball_state_t> balls_;
  lcm::Subscription* table_state_subscription_ = nullptr;
  lcm::Subscription* shot_request_subscription_ = nullptr;
};

}  // namespace billiard::planner
