#include "planner/node/pot_request.h"

#include <algorithm>
#include <exception>
#include <optional>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "planner/node/command_writing.h"
#include "planner/node/message_conversions.h"
#include "planner/node/named_ball.h"
#include "planner/node/scene_at_rest.h"
#include "planner/pot/pot_planner.h"

namespace billiard::planner_node {

namespace {

// Why a pot has no object ball: `q`'s is not in the latest table state.
std::string NoObjectBall(const shot_request_t& q) {
  std::ostringstream reason;
  reason << "no ball "
         << (q.object_ball_id == shot_request_t::BALL_BY_CLASS
                 ? "of class " + std::to_string(q.object_ball_class) + " with a confidence of " +
                       std::to_string(kMinClassConfidence) + " or more"
                 : std::to_string(q.object_ball_id))
         << " in the latest table state";
  return reason.str();
}

// The pot planner's request for `q` into `request` (all but the object ball's scene id); why
// not, when its cue-ball target is off the playing surface of `table`.
std::optional<std::string> ReadPotRequest(const shot_request_t& q,
                                          const table::TableGeometry& table, double radius,
                                          pot::PotRequest* request) {
  request->pocket = q.pocket;
  request->kind = ToShotKind(q.kind);
  if (q.has_cue_target) {
    const Eigen::Vector2d point(q.cue_target[0], q.cue_target[1]);
    if (!table.OnSurface(point, radius)) {
      std::ostringstream reason;
      reason << "the cue-ball target (" << point.x() << ", " << point.y() << ") is off the "
             << table.name << " table's playing surface";
      return reason.str();
    }
    request->cue_target = pot::CueTarget{point, q.cue_radius};
  }
  return std::nullopt;
}

}  // namespace

cue_command_t AnswerPot(const shot_request_t& q, const ball_state_t& cue,
                        const table_state_t& latest, const table::TableGeometry& table,
                        const physics::ModelParameters& params, const PlannerNodeOptions& options,
                        cue_command_t c) {
  const ball_state_t* object = Named(BallsOf(latest), q.object_ball_id, q.object_ball_class);
  if (object == nullptr) return Refusal(c, cue_command_t::STATUS_NO_SUCH_BALL, NoObjectBall(q));
  c.object_ball_id = object->ball_id;
  if (object->ball_id == cue.ball_id) {
    return Refusal(c, cue_command_t::STATUS_NO_SUCH_BALL,
                   "ball " + std::to_string(cue.ball_id) + " is the ball struck, not one to pot");
  }
  pot::PotRequest request;
  if (auto off = ReadPotRequest(q, table, params.ball.radius, &request)) {
    return Refusal(c, cue_command_t::STATUS_OFF_TABLE, *off);
  }
  std::unordered_map<int, int32_t> message_id;
  std::string moving;
  const auto balls = StruckScene(latest, cue, options.max_ball_speed, &message_id, &moving);
  if (!balls) return Refusal(c, cue_command_t::STATUS_NOT_AT_REST, moving);
  for (const auto& [scene_id, id] : message_id) {
    if (id == object->ball_id) request.ball = scene_id;
  }
  pot::PotPlan plan;
  try {
    plan = pot::PlanPot(table, params, *balls, request, options.pot);
  } catch (const std::exception& e) {
    return Refusal(c, cue_command_t::STATUS_NOT_CONVERGED,
                   std::string("pot planner failed: ") + e.what());
  }
  WritePot(plan, message_id, &c);
  return Sendable(c);
}

}  // namespace billiard::planner_node
