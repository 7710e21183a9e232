#include "planner/node/to_point_request.h"

#include <algorithm>
#include <cstdint>
#include <exception>
#include <string>
#include <unordered_map>
#include <vector>

#include "planner/cue_planning.h"
#include "planner/node/command_writing.h"
#include "planner/node/message_conversions.h"

namespace billiard::planner_node {

namespace {

// The balls the cue must clear besides the struck one, where they were last seen; one whose id
// is 0 (the struck ball is the cue's id 0) takes a free id.
std::vector<table::SceneBall> Others(const ball_state_t& struck, const std::vector<const ball_state_t*>& seen) {
  int32_t free_id = 1;
  for (const ball_state_t* b : seen) free_id = std::max(free_id, b->ball_id + 1);
  std::vector<table::SceneBall> others;
  for (const ball_state_t* b : seen) {
    if (b->ball_id == struck.ball_id) continue;
    others.push_back(table::AtRest(b->ball_id == 0 ? free_id : b->ball_id, b->position[0], b->position[1]));
  }
  return others;
}

}  // namespace

cue_command_t AnswerToPoint(const shot_request_t& q, const ball_state_t& ball,
                            const std::vector<const ball_state_t*>& seen, const table::TableGeometry& table,
                            const physics::ModelParameters& params, const PlannerNodeOptions& options,
                            cue_command_t c) {
  planner::ShotPlan plan;
  try {
    const planner::ShotRequest request = ToShotRequest(q, ball);
    plan = options.pot.robot ? planner::PlanShotForRobot(request, params, options.planner,
                                                         planner::CueSetting{*options.pot.robot, table, Others(ball, seen)})
                             : planner::PlanShot(request, params, options.planner);
  } catch (const std::exception& e) {
    return Refusal(c, cue_command_t::STATUS_NOT_CONVERGED,
                   std::string("planner failed: ") + e.what());
  }
  WritePlan(plan, &c);
  return Sendable(c);
}

}  // namespace billiard::planner_node
