#include "planner/node/message_conversions.h"

#include "lcmtypes/billiard/cue_command_t.hpp"

namespace billiard::planner_node {

int8_t ToMessageStatus(planner::PlanStatus status) {
  switch (status) {
    case planner::PlanStatus::kOk:
      return cue_command_t::STATUS_OK;
    case planner::PlanStatus::kInvalid:
      return cue_command_t::STATUS_INVALID;
    case planner::PlanStatus::kOffTable:
      return cue_command_t::STATUS_OFF_TABLE;
    case planner::PlanStatus::kUnreachable:
      return cue_command_t::STATUS_UNREACHABLE;
    case planner::PlanStatus::kNotConverged:
      return cue_command_t::STATUS_NOT_CONVERGED;
    case planner::PlanStatus::kCueBlocked:
      return cue_command_t::STATUS_CUE_BLOCKED;
  }
  return cue_command_t::STATUS_INVALID;
}

int8_t ToMessageStatus(pot::PotStatus status) {
  switch (status) {
    case pot::PotStatus::kOk:
      return cue_command_t::STATUS_OK;
    case pot::PotStatus::kInvalid:
      return cue_command_t::STATUS_INVALID;
    case pot::PotStatus::kNoSuchBall:
      return cue_command_t::STATUS_NO_SUCH_BALL;
    case pot::PotStatus::kNoSuchPocket:
      return cue_command_t::STATUS_NO_SUCH_POCKET;
    case pot::PotStatus::kBlocked:
      return cue_command_t::STATUS_BLOCKED;
    case pot::PotStatus::kTooThin:
      return cue_command_t::STATUS_TOO_THIN;
    case pot::PotStatus::kNoStroke:
      return cue_command_t::STATUS_NO_STROKE;
    case pot::PotStatus::kTargetUnreachable:
      return cue_command_t::STATUS_TARGET_UNREACHABLE;
    case pot::PotStatus::kCueBlocked:
      return cue_command_t::STATUS_CUE_BLOCKED;
  }
  return cue_command_t::STATUS_INVALID;
}

std::optional<pot::ShotKind> ToShotKind(int8_t kind) {
  switch (kind) {
    case shot_request_t::KIND_DIRECT:
      return pot::ShotKind::kDirect;
    case shot_request_t::KIND_BANK:
      return pot::ShotKind::kBank;
    case shot_request_t::KIND_KICK:
      return pot::ShotKind::kKick;
    case shot_request_t::KIND_CURVE:
      return pot::ShotKind::kCurve;
  }
  return std::nullopt;
}

int8_t ToMessageKind(pot::ShotKind kind) {
  switch (kind) {
    case pot::ShotKind::kDirect:
      return shot_request_t::KIND_DIRECT;
    case pot::ShotKind::kBank:
      return shot_request_t::KIND_BANK;
    case pot::ShotKind::kKick:
      return shot_request_t::KIND_KICK;
    case pot::ShotKind::kCurve:
      return shot_request_t::KIND_CURVE;
  }
  return shot_request_t::KIND_ANY;
}

planner::ShotRequest ToShotRequest(const shot_request_t& q, const ball_state_t& s) {
  planner::ShotRequest request;
  switch (q.spin) {
    case shot_request_t::SPIN_NATURAL:
      request.style = planner::SpinStyle::kNatural;
      break;
    case shot_request_t::SPIN_STUN:
      request.style = planner::SpinStyle::kStun;
      break;
    case shot_request_t::SPIN_FOLLOW:
      request.style = planner::SpinStyle::kFollow;
      break;
    case shot_request_t::SPIN_DRAW:
      request.style = planner::SpinStyle::kDraw;
      break;
    default:
      request.slide_length = q.slide_length;
      break;  // SPIN_SLIDE
  }
  request.from = {s.position[0], s.position[1]};
  request.to = {q.target[0], q.target[1]};
  request.final_speed = q.final_speed;
  request.side_spin = q.side_spin;
  return request;
}

}  // namespace billiard::planner_node
