#include "planner/node/command_writing.h"

#include <algorithm>
#include <utility>

#include "lcmtypes/message_checks.h"
#include "planner/node/message_conversions.h"

namespace billiard::planner_node {

cue_command_t ReplyTo(const shot_request_t& q) {
  cue_command_t c{};
  c.utime = q.utime;
  c.request_id = q.request_id;
  c.ball_id = q.ball_id;
  if (q.mode == shot_request_t::MODE_POT && messages::Check(q).empty()) {
    c.mode = q.mode;
    c.object_ball_id = q.object_ball_id;
    c.pocket = q.pocket;
    c.kind = q.kind;
  }
  if (q.mode == shot_request_t::MODE_CHOOSE && messages::Check(q).empty()) {
    c.mode = q.mode;
    c.object_ball_id = -1;
  }
  return c;
}

cue_command_t Refusal(cue_command_t c, int8_t status, std::string reason) {
  c.status = status;
  c.reason = std::move(reason);
  return c;
}

void WritePlan(const planner::ShotPlan& plan, cue_command_t* c) {
  std::copy(plan.v0.data(), plan.v0.data() + 2, c->v0);
  std::copy(plan.w0.data(), plan.w0.data() + 3, c->w0);
  c->num_path_points = static_cast<int32_t>(plan.predicted_path.size());
  c->path.reserve(plan.predicted_path.size());
  for (const Eigen::Vector2d& p : plan.predicted_path) c->path.push_back({p.x(), p.y()});
  c->predicted_final[0] = plan.predicted_final.x();
  c->predicted_final[1] = plan.predicted_final.y();
  c->closed_form_miss_m = plan.closed_form_miss_m;
  c->refined_miss_m = plan.refined_miss_m;
  c->solve_us = plan.solve_us;
  c->iterations = plan.iterations;
  c->status = ToMessageStatus(plan.status);
  if (plan.status == planner::PlanStatus::kOk) {
    c->cue_speed = plan.stroke.speed;
    c->heading = plan.stroke.heading;
    c->tip_side = plan.stroke.tip_side;
    c->tip_height = plan.stroke.tip_height;
    c->elevation = plan.stroke.elevation;
  } else {
    c->reason = plan.reason.empty() ? planner::PlanStatusName(plan.status) : plan.reason;
  }
}

void WritePot(const pot::PotPlan& plan, const std::unordered_map<int, int32_t>& message_id,
              cue_command_t* c) {
  c->status = ToMessageStatus(plan.status);
  if (plan.status != pot::PotStatus::kOk) {
    c->reason = plan.reason.empty() ? pot::PotStatusName(plan.status) : plan.reason;
    c->solve_us = plan.solve_us;
    return;
  }
  c->cue_speed = plan.stroke.speed;
  c->heading = plan.stroke.heading;
  c->tip_side = plan.stroke.tip_side;
  c->tip_height = plan.stroke.tip_height;
  c->elevation = plan.stroke.elevation;
  std::copy(plan.v0.data(), plan.v0.data() + 2, c->v0);
  std::copy(plan.w0.data(), plan.w0.data() + 3, c->w0);
  c->kind = ToMessageKind(plan.kind);
  c->margin_deg[0] = plan.margin_left_deg;
  c->margin_deg[1] = plan.margin_right_deg;
  c->speed_window[0] = plan.speed_lo;
  c->speed_window[1] = plan.speed_hi;
  c->cue_rest[0] = c->predicted_final[0] = plan.cue_rest.x();
  c->cue_rest[1] = c->predicted_final[1] = plan.cue_rest.y();
  c->solve_us = plan.solve_us;
  c->iterations = plan.simulations;
  for (const pot::BallPath& path : plan.paths) {
    ball_path_t out{};
    out.ball_id = message_id.at(path.id);
    for (const Eigen::Vector2d& p : path.points) out.points.push_back({p.x(), p.y()});
    out.num_points = static_cast<int32_t>(out.points.size());
    if (path.id == 0) c->path = out.points;
    c->ball_paths.push_back(std::move(out));
  }
  c->num_path_points = static_cast<int32_t>(c->path.size());
  c->num_ball_paths = static_cast<int32_t>(c->ball_paths.size());
}

void WriteStroke(const physics::CueStroke& stroke, cue_command_t* c) {
  c->cue_speed = stroke.speed;
  c->heading = stroke.heading;
  c->tip_side = stroke.tip_side;
  c->tip_height = stroke.tip_height;
  c->elevation = stroke.elevation;
  c->status = cue_command_t::STATUS_OK;
}

cue_command_t Sendable(const cue_command_t& c) {
  const std::string why = messages::Check(c);
  if (why.empty()) return c;
  const bool was_ok = c.status == cue_command_t::STATUS_OK;
  cue_command_t refused{};
  refused.utime = c.utime;
  refused.request_id = c.request_id;
  refused.ball_id = c.ball_id;
  refused.mode = c.mode;
  refused.object_ball_id = c.object_ball_id;
  refused.pocket = c.pocket;
  std::copy(c.start, c.start + 2, refused.start);
  return Refusal(refused, was_ok ? cue_command_t::STATUS_NOT_CONVERGED : c.status,
                 was_ok ? "the plan is not a valid command: " + why : c.reason);
}

}  // namespace billiard::planner_node
