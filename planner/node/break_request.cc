#include "planner/node/break_request.h"

#include <string>
#include <unordered_map>
#include <vector>

#include "lcmtypes/names.h"
#include "planner/game/break_search.h"
#include "planner/node/command_writing.h"
#include "planner/node/scene_at_rest.h"

namespace billiard::planner_node {

rules::Rules RulesOf(const shot_request_t& q) {
  return rules::ParseRules(messages::ShotRulesName(q.rules)).value_or(rules::Rules::kAny);
}

cue_command_t AnswerBreak(const shot_request_t& q, const ball_state_t& cue,
                          const table_state_t& latest, const table::TableGeometry& table,
                          const physics::ModelParameters& params,
                          const PlannerNodeOptions& options, cue_command_t c) {
  c.mode = shot_request_t::MODE_BREAK;
  std::unordered_map<int, int32_t> message_id;
  std::string moving;
  // The break needs no numbers, only which ball is the cue ball: the others keep their ids.
  auto balls = SceneAtRest(
      latest, options.max_ball_speed, cue.ball_id, [](int32_t id) { return id + 1; },
      &message_id, &moving);
  if (!balls) return Refusal(c, cue_command_t::STATUS_NOT_AT_REST, moving);
  if (balls->size() < 2) {
    return Refusal(c, cue_command_t::STATUS_NO_SUCH_BALL, "no object ball to break");
  }
  const physics::CueStroke stroke = game::SetUpBreak(
      table, params.ball.radius, game::StoredBreak(RulesOf(q)), &*balls);
  const table::SceneBall& placed = balls->front();
  c.has_cue_placement = 1;
  c.start[0] = c.cue_placement[0] = placed.state[physics::kX];
  c.start[1] = c.cue_placement[1] = placed.state[physics::kY];
  WriteStroke(stroke, &c);
  return Sendable(c);
}

}  // namespace billiard::planner_node
