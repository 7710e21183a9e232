#include "planner/node/to_point_request.h"

#include <exception>
#include <string>

#include "planner/node/command_writing.h"
#include "planner/node/message_conversions.h"

namespace billiard::planner_node {

cue_command_t AnswerToPoint(const shot_request_t& q, const ball_state_t& ball,
                            const physics::ModelParameters& params,
                            const planner::PlannerOptions& options, cue_command_t c) {
  planner::ShotPlan plan;
  try {
    plan = planner::PlanShot(ToShotRequest(q, ball), params, options);
  } catch (const std::exception& e) {
    return Refusal(c, cue_command_t::STATUS_NOT_CONVERGED,
                   std::string("planner failed: ") + e.what());
  }
  WritePlan(plan, &c);
  return Sendable(c);
}

}  // namespace billiard::planner_node
