#include "planner_node.h"

#include <cmath>
#include <exception>
#include <iostream>
#include <sstream>
#include <utility>

#include "billiard/table_state_t.hpp"

namespace billiard::planner {

namespace {

int8_t ToMessageStatus(PlanStatus status) {
  switch (status) {
    case PlanStatus::kOk: return cue_command_t::STATUS_OK;
    case PlanStatus::kInvalid: return cue_command_t::STATUS_INVALID;
    case PlanStatus::kOffTable: return cue_command_t::STATUS_OFF_TABLE;
    case PlanStatus::kUnreachable: return cue_command_t::STATUS_UNREACHABLE;
    case PlanStatus::kNotConverged: return cue_command_t::STATUS_NOT_CONVERGED;
  }
  return cue_command_t::STATUS_INVALID;
}

// Decodes the whole payload: trailing bytes mean the sender's type is not ours.
template <class Message>
bool Decode(const lcm::ReceiveBuffer& rbuf, Message& message) {
  return message.decode(rbuf.data, 0, static_cast<int>(rbuf.data_size)) ==
         static_cast<int>(rbuf.data_size);
}

// table_state_t's decoder sizes its vector from the ball count in the payload before it reads a
// ball, so a corrupt count would allocate gigabytes (or throw) first: the count is checked
// against the payload size before decoding. Layout: hash (8), utime (8), num_balls (4, big-endian).
bool BallCountFitsPayload(const lcm::ReceiveBuffer& rbuf) {
  constexpr int64_t kHeader = 8 + 8 + 4;
  if (rbuf.data_size < kHeader) return true;  // too short: the decoder refuses it
  const auto* b = static_cast<const uint8_t*>(rbuf.data) + 16;
  const auto count = static_cast<int32_t>(uint32_t{b[0]} << 24 | uint32_t{b[1]} << 16 |
                                          uint32_t{b[2]} << 8 | uint32_t{b[3]});
  const int64_t ball_size = ball_state_t{}._getEncodedSizeNoHash();
  return count >= 0 && kHeader + count * ball_size <= int64_t{rbuf.data_size};
}

std::string Describe(const cue_command_t& c) {
  std::ostringstream line;
  line << "request " << c.request_id << " (ball " << c.ball_id
       << "): " << CueCommandStatusName(c.status);
  if (c.status == cue_command_t::STATUS_OK) {
    line << ": cue " << c.cue_speed << " m/s, heading " << c.heading << " rad, miss "
         << c.refined_miss_m << " m, " << c.iterations << " iterations, " << c.solve_us << " us";
  } else {
    line << ": " << c.reason;
  }
  return line.str();
}

}  // namespace

std::string CueCommandStatusName(int8_t status) {
  switch (status) {
    case cue_command_t::STATUS_OK: return "ok";
    case cue_command_t::STATUS_INVALID: return "invalid";
    case cue_command_t::STATUS_OFF_TABLE: return "off_table";
    case cue_command_t::STATUS_UNREACHABLE: return "unreachable";
    case cue_command_t::STATUS_NOT_CONVERGED: return "not_converged";
    case cue_command_t::STATUS_NO_BALL_STATE: return "no_ball_state";
  }
  return "status " + std::to_string(status);
}

PlannerNode::PlannerNode(lcm::LCM& lcm, ModelParameters params, PlannerNodeOptions options,
                         Log log)
    : lcm_(lcm),
      params_(std::move(params)),
      options_(std::move(options)),
      log_(log ? std::move(log) : Log([](const std::string& line) {
        std::cerr << "planner_node: " << line << std::endl;
      })) {
  table_state_subscription_ = lcm_.subscribe(kTableStateChannel, &PlannerNode::OnTableState, this);
  shot_request_subscription_ =
      lcm_.subscribe(kShotRequestChannel, &PlannerNode::OnShotRequest, this);
}

PlannerNode::~PlannerNode() {
  if (table_state_subscription_) lcm_.unsubscribe(table_state_subscription_);
  if (shot_request_subscription_) lcm_.unsubscribe(shot_request_subscription_);
}

cue_command_t PlannerNode::Answer(const shot_request_t& q) const {
  cue_command_t c{};
  c.utime = q.utime;
  c.request_id = q.request_id;
  c.ball_id = q.ball_id;
  const auto refuse = [&c](int8_t status, std::string reason) {
    c.status = status;
    c.reason = std::move(reason);
    return c;
  };

  ShotRequest request;
  switch (q.spin) {
    case shot_request_t::SPIN_NATURAL: request.style = SpinStyle::kNatural; break;
    case shot_request_t::SPIN_STUN: request.style = SpinStyle::kStun; break;
    case shot_request_t::SPIN_FOLLOW: request.style = SpinStyle::kFollow; break;
    case shot_request_t::SPIN_DRAW: request.style = SpinStyle::kDraw; break;
    case shot_request_t::SPIN_SLIDE: request.slide_length = q.slide_length; break;
    default:
      return refuse(cue_command_t::STATUS_INVALID,
                    "unknown spin value " + std::to_string(q.spin) + " (0-4, see shot_request_t)");
  }
  // slide_length means something only with SPIN_SLIDE, so only then must it be a number.
  const bool finite = std::isfinite(q.target[0]) && std::isfinite(q.target[1]) &&
                      std::isfinite(q.final_speed) && std::isfinite(q.side_spin) &&
                      (!request.slide_length || std::isfinite(*request.slide_length));
  if (!finite) return refuse(cue_command_t::STATUS_INVALID, "request has a non-finite number");

  const auto ball = balls_.find(q.ball_id);
  if (ball == balls_.end()) {
    return refuse(cue_command_t::STATUS_NO_BALL_STATE,
                  "no table state has ball " + std::to_string(q.ball_id));
  }
  const ball_state_t& s = ball->second;
  c.start[0] = s.position[0];
  c.start[1] = s.position[1];
  for (double x : {s.position[0], s.position[1], s.velocity[0], s.velocity[1]}) {
    if (!std::isfinite(x)) {
      return refuse(cue_command_t::STATUS_INVALID,
                    "the latest state of ball " + std::to_string(q.ball_id) +
                        " has a non-finite position or velocity");
    }
  }
  const double speed = std::hypot(s.velocity[0], s.velocity[1]);
  if (speed > options_.max_ball_speed) {
    std::ostringstream reason;
    reason << "ball " << q.ball_id << " is moving (" << speed << " m/s, more than "
           << options_.max_ball_speed << " m/s)";
    return refuse(cue_command_t::STATUS_INVALID, reason.str());
  }

  request.from = {s.position[0], s.position[1]};
  request.to = {q.target[0], q.target[1]};
  request.final_speed = q.final_speed;
  request.side_spin = q.side_spin;
  ShotPlan plan;
  try {
    plan = PlanShot(request, params_, options_.planner);
  } catch (const std::exception& e) {
    return refuse(cue_command_t::STATUS_NOT_CONVERGED, std::string("planner failed: ") + e.what());
  }

  // The planner's measurements go out with a refusal too (a not-converged plan's miss says by how
  // much); the stroke only with an ok plan, so that a refused command cannot move the cue.
  for (int i = 0; i < 2; ++i) c.v0[i] = plan.v0[i];
  for (int i = 0; i < 3; ++i) c.w0[i] = plan.w0[i];
  c.num_path_points = static_cast<int32_t>(plan.predicted_path.size());
  c.path.reserve(plan.predicted_path.size());
  for (const Eigen::Vector2d& p : plan.predicted_path) c.path.push_back({p.x(), p.y()});
  c.predicted_final[0] = plan.predicted_final.x();
  c.predicted_final[1] = plan.predicted_final.y();
  c.closed_form_miss_m = plan.closed_form_miss_m;
  c.refined_miss_m = plan.refined_miss_m;
  c.solve_us = plan.solve_us;
  c.iterations = plan.iterations;
  c.status = ToMessageStatus(plan.status);
  if (plan.status == PlanStatus::kOk) {
    c.cue_speed = plan.stroke.speed;
    c.heading = plan.stroke.heading;
    c.tip_side = plan.stroke.tip_side;
    c.tip_height = plan.stroke.tip_height;
    c.elevation = plan.stroke.elevation;
  } else {
    c.reason = plan.reason.empty() ? PlanStatusName(plan.status) : plan.reason;
  }
  return c;
}

void PlannerNode::OnTableState(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
  try {
    table_state_t state;
    if (!BallCountFitsPayload(*rbuf) || !Decode(*rbuf, state)) {
      log_(channel + ": dropped " + std::to_string(rbuf->data_size) +
           " bytes that do not decode as table_state_t");
      return;
    }
    for (const ball_state_t& ball : state.balls) balls_.insert_or_assign(ball.ball_id, ball);
  } catch (const std::exception& e) {
    try { log_(channel + ": dropped a message: " + e.what()); } catch (...) {}
  } catch (...) {
    try { log_(channel + ": dropped a message: unknown exception"); } catch (...) {}
  }
}

void PlannerNode::OnShotRequest(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
  try {
    shot_request_t request;
    if (!Decode(*rbuf, request)) {
      log_(channel + ": dropped " + std::to_string(rbuf->data_size) +
           " bytes that do not decode as shot_request_t");
      return;
    }
    const cue_command_t command = Answer(request);
    if (lcm_.publish(kCueCommandChannel, &command) != 0) {
      log_(std::string(kCueCommandChannel) + ": publishing the answer to request " +
           std::to_string(command.request_id) + " failed");
      return;
    }
    log_(Describe(command));
  } catch (const std::exception& e) {
    try { log_(channel + ": dropped a message: " + e.what()); } catch (...) {}
  } catch (...) {
    try { log_(channel + ": dropped a message: unknown exception"); } catch (...) {}
  }
}

}  // namespace billiard::planner
