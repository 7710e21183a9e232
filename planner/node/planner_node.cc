#include "planner/node/planner_node.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "lcmtypes/message_checks.h"
#include "lcmtypes/names.h"
#include "planner/node/break_request.h"
#include "planner/node/choose_request.h"
#include "planner/players/players.h"
#include "planner/node/command_writing.h"
#include "planner/node/named_ball.h"
#include "planner/node/pot_request.h"
#include "planner/node/scene_at_rest.h"
#include "planner/node/to_point_request.h"
#include "sim/params/parameter_sets.h"

namespace billiard::planner_node {

namespace {

// The answer in one line of the log.
std::string Describe(const cue_command_t& c) {
  std::ostringstream line;
  line << "request " << c.request_id << " (ball " << c.ball_id;
  if (c.mode == shot_request_t::MODE_POT) {
    line << ", pot ball " << c.object_ball_id << " in " << c.pocket;
  }
  if (c.mode == shot_request_t::MODE_CHOOSE) {
    line << ", chose ball " << c.object_ball_id << " in " << c.pocket << " at p "
         << c.success_probability;
    if (c.safety) line << " (a safety)";
    if (c.has_cue_placement) {
      line << ", the cue ball placed at (" << c.cue_placement[0] << ", " << c.cue_placement[1]
           << ")";
    }
  }
  line << "): " << messages::CueCommandStatusName(c.status);
  if (c.status == cue_command_t::STATUS_OK && c.mode != shot_request_t::MODE_TO_POINT) {
    line << ": " << messages::PotKindName(c.kind) << ", cue " << c.cue_speed << " m/s, heading "
         << c.heading << " rad, margin " << c.margin_deg[0] << "/" << c.margin_deg[1]
         << " deg, cue ball rests at (" << c.cue_rest[0] << ", " << c.cue_rest[1] << "), "
         << c.solve_us << " us";
  } else if (c.status == cue_command_t::STATUS_OK) {
    line << ": cue " << c.cue_speed << " m/s, heading " << c.heading << " rad, miss "
         << c.refined_miss_m << " m, " << c.iterations << " iterations, " << c.solve_us << " us";
  } else {
    line << ": " << c.reason;
  }
  return line.str();
}

}  // namespace

PlannerNode::PlannerNode(lcm::LCM& lcm, physics::ModelParameters params, PlannerNodeOptions options,
                         Log log)
    : lcm_(lcm),
      params_(std::move(params)),
      options_(std::move(options)),
      table_(TableOf(options_)),
      log_(log ? std::move(log) : Log([](const std::string& line) {
        std::cerr << "planner_node: " << line << std::endl;
      })),
      health_("planner_node", log_),
      states_at_rest_(options_.rest_states),
      player_(players::MakePlayer(options_.player)),
      noise_learner_(options_.choice.noise) {
  health_.SetParameters(params::ParameterSetLabel(params_), params::ParameterHash(params_));
  table_state_subscription_ =
      lcm_.subscribe(messages::kTableStateChannel, &PlannerNode::OnTableState, this);
  shot_request_subscription_ =
      lcm_.subscribe(messages::kShotRequestChannel, &PlannerNode::OnShotRequest, this);
  // A burst arriving while a plan is computed waits in LCM's queue until the loop drains it into
  // ours (30 by default, beyond which LCM drops messages unseen); a request is about 100 bytes.
  shot_request_subscription_->setQueueCapacity(10000);
}

PlannerNode::~PlannerNode() {
  if (table_state_subscription_) lcm_.unsubscribe(table_state_subscription_);
  if (shot_request_subscription_) lcm_.unsubscribe(shot_request_subscription_);
}

cue_command_t PlannerNode::Answer(const shot_request_t& q) const {
  const cue_command_t reply = ReplyTo(q);
  if (std::string why = messages::Check(q); !why.empty()) {
    return Refusal(reply, cue_command_t::STATUS_INVALID, why);
  }
  const ball_state_t* ball = BallFor(q);
  if (ball == nullptr) {
    return Refusal(reply, cue_command_t::STATUS_NO_BALL_STATE,
                   q.ball_id == shot_request_t::BALL_BY_CLASS
                       ? "no table state has a ball of class " + std::to_string(q.ball_class) +
                             " with a confidence of " + std::to_string(kMinClassConfidence) +
                             " or more"
                       : "no table state has ball " + std::to_string(q.ball_id));
  }
  const ball_state_t& state = *ball;
  cue_command_t c = reply;
  c.ball_id = state.ball_id;
  std::copy(state.position, state.position + 2, c.start);
  if (auto unfit = UnfitToPlanFrom(q, state)) return Refusal(c, unfit->status, unfit->reason);
  if (q.mode == shot_request_t::MODE_POT) {
    return AnswerPot(q, state, *latest_table_, table_, params_, options_, std::move(c));
  }
  if (q.mode == shot_request_t::MODE_BREAK) {
    return AnswerBreak(q, state, *latest_table_, table_, params_, options_, std::move(c));
  }
  if (q.mode == shot_request_t::MODE_CHOOSE) {
    const players::Player* player = nullptr;
    try {
      player = &PlayerFor(q);
    } catch (const std::invalid_argument& e) {  // MakePlayer's: the name and the known ones
      return Refusal(c, cue_command_t::STATUS_INVALID, e.what());
    }
    if (!choice_pool_) choice_pool_ = std::make_unique<batch::ThreadPool>(options_.choice_threads);
    PlannerNodeOptions options = options_;
    options.choice.noise = noise_learner_.noise();
    return AnswerChoice(q, state, *latest_table_, table_, params_, options, *player,
                        *choice_pool_, std::move(c));
  }
  // The cue clears the balls on the table now: a remembered ball the estimator no longer sees
  // (pocketed, or of a rack cleared away) is no obstacle, though a request may still name it.
  return AnswerToPoint(q, state, OnTable(), table_, params_, options_, std::move(c));
}

const players::Player& PlannerNode::PlayerFor(const shot_request_t& q) const {
  if (q.player.empty()) return *player_;
  auto made = players_.find(q.player);
  if (made == players_.end()) made = players_.emplace(q.player, players::MakePlayer(q.player)).first;
  return *made->second;
}

std::vector<const ball_state_t*> PlannerNode::OnTable() const {
  if (!latest_table_) return {};
  return BallsOf(*latest_table_);
}

std::vector<const ball_state_t*> PlannerNode::Candidates(const shot_request_t& q) const {
  if (q.mode != shot_request_t::MODE_TO_POINT) return OnTable();
  std::vector<const ball_state_t*> balls;
  for (const auto& [id, b] : balls_) balls.push_back(&b);
  return balls;
}

std::optional<PlannerNode::Unfit> PlannerNode::UnfitToPlanFrom(const shot_request_t& q,
                                                               const ball_state_t& s) const {
  const double age = 1e-6 * static_cast<double>(q.utime - s.utime);
  if (std::abs(age) > options_.max_state_age) {
    std::ostringstream reason;
    reason << "the latest state of ball " << q.ball_id << " is " << std::abs(age) << " s "
           << (age > 0 ? "older" : "newer") << " than the request (at most "
           << options_.max_state_age << " s)";
    return Unfit{cue_command_t::STATUS_STALE_STATE, reason.str()};
  }
  if (std::string why = Moving(s, options_.max_ball_speed); !why.empty()) {
    return Unfit{cue_command_t::STATUS_NOT_AT_REST, std::move(why)};
  }
  return std::nullopt;
}

const ball_state_t* PlannerNode::BallFor(const shot_request_t& q) const {
  if (q.ball_id != shot_request_t::BALL_BY_CLASS) return Named(Candidates(q), q.ball_id, 0);
  // By class among the balls the estimator sees now: one it has lost (pocketed, or of a rack
  // cleared away) is no ball to strike, however sure it was of it.
  const std::vector<const ball_state_t*> seen = OnTable();
  // A choice is made on a whole rack, which has one cue ball: the likeliest, however unsure, or
  // when the estimator names none now, the ball it named the cue ball last.
  if (q.mode != shot_request_t::MODE_CHOOSE && q.mode != shot_request_t::MODE_BREAK) {
    return Named(seen, q.ball_id, q.ball_class);
  }
  if (const ball_state_t* likeliest = Named(seen, q.ball_id, q.ball_class, 0.0f)) return likeliest;
  const auto last = last_of_class_.find(q.ball_class);
  if (last == last_of_class_.end()) return nullptr;
  return Named(seen, last->second, 0);
}

std::int64_t PlannerNode::StateUtime(const shot_request_t& q) const {
  const ball_state_t* ball = BallFor(q);
  if (ball == nullptr) return -1;
  return q.mode == shot_request_t::MODE_TO_POINT ? ball->utime : latest_table_->utime;
}

void PlannerNode::OnTableState(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
  try {
    health_.Received();
    table_state_t state;
    if (std::string why = messages::DecodeChecked(rbuf->data, rbuf->data_size, state);
        !why.empty()) {
      return health_.Dropped(channel + ": " + why);
    }
    switch (state_clock_.Accept(state.utime)) {
      case nodes::MessageClock::Verdict::kNext:
        break;
      case nodes::MessageClock::Verdict::kDuplicate:
        return health_.Count("duplicate");
      case nodes::MessageClock::Verdict::kLate:
        return health_.Dropped(channel + ": utime " + std::to_string(state.utime) +
                               " is older than the latest, " +
                               std::to_string(state_clock_.latest()) + " (late or reordered)");
      case nodes::MessageClock::Verdict::kNewClock:
        // The publisher restarted: the old clock's balls and answers mean nothing now.
        health_.Count("clock_reset");
        log_(channel + ": a new clock at utime " + std::to_string(state.utime) +
             ": the balls known so far are forgotten");
        balls_.clear();
        latest_table_.reset();
        states_at_rest_ = options_.rest_states;
        last_of_class_.clear();
        answered_.clear();
        break;
    }
    for (const ball_state_t& ball : state.balls) balls_.insert_or_assign(ball.ball_id, ball);
    const std::vector<const ball_state_t*> seen = BallsOf(state);
    for (const ball_state_t& b : state.balls) {
      if (b.ball_class == ball_state_t::CLASS_UNKNOWN) continue;
      last_of_class_[b.ball_class] =
          Named(seen, shot_request_t::BALL_BY_CLASS, b.ball_class, 0.0f)->ball_id;
    }
    if (RecordsShots()) {
      std::vector<shot_fit::TrackSample> tracks;
      for (const ball_state_t& b : state.balls)
        tracks.push_back({b.ball_id, {b.position[0], b.position[1]}});
      shots_.State(state.utime, tracks);
    }
    NoteMotion(state);
    latest_table_ = std::move(state);
    latest_table_arrival_ = nodes::NodeHealth::Clock::now();
    while (balls_.size() > kMaxRememberedBalls) {
      balls_.erase(std::min_element(balls_.begin(), balls_.end(), [](const auto& a, const auto& b) {
        return a.second.utime < b.second.utime;
      }));
      health_.Count("forgotten_ball");
    }
  } catch (const std::exception& e) {
    health_.Dropped(channel + ": " + e.what());
  } catch (...) {
    health_.Dropped(channel + ": unknown exception");
  }
}

void PlannerNode::OnShotRequest(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
  const auto arrived = nodes::NodeHealth::Clock::now();
  try {
    health_.Received();
    shot_request_t request;
    // A request that decodes but fails Check is answered (invalid, with the reason): its sender
    // can be told. One that does not decode has no request_id to answer.
    if (std::string why = messages::Decode(rbuf->data, rbuf->data_size, request); !why.empty()) {
      return health_.Dropped(channel + ": " + why);
    }
    const auto* begin = static_cast<const std::uint8_t*>(rbuf->data);
    Bytes bytes(begin, begin + rbuf->data_size);
    for (const Waiting& w : waiting_) {
      if (w.bytes == bytes) {
        health_.Count("duplicate");
        return;
      }
    }
    const std::int64_t state_utime = StateUtime(request);
    for (const Answered& a : answered_) {
      if (a.request == bytes && a.state_utime == state_utime) {
        health_.Count("duplicate");
        return Publish(a.command, arrived);
      }
    }
    if (waiting_.size() >= static_cast<std::size_t>(options_.queue_capacity)) {
      cue_command_t busy = ReplyTo(request);
      busy.status = cue_command_t::STATUS_BUSY;
      busy.reason =
          "the planner's queue is full (" + std::to_string(waiting_.size()) + " requests waiting)";
      if (!refusing_busy_) log_("queue full: answering busy until it has room");
      refusing_busy_ = true;
      return Publish(busy, arrived);
    }
    waiting_.push_back({request, std::move(bytes), arrived});
    health_.SetQueueDepth(static_cast<int>(waiting_.size()));
  } catch (const std::exception& e) {
    health_.Dropped(channel + ": " + e.what());
  } catch (...) {
    health_.Dropped(channel + ": unknown exception");
  }
}

void PlannerNode::Publish(const cue_command_t& command,
                          nodes::NodeHealth::Clock::time_point arrived) {
  if (lcm_.publish(messages::kCueCommandChannel, &command) != 0) {
    return health_.Dropped(std::string(messages::kCueCommandChannel) +
                           ": publishing the answer to request " +
                           std::to_string(command.request_id) + " failed");
  }
  health_.Published();
  health_.Count(messages::CueCommandStatusName(command.status));
  health_.Latency(nodes::NodeHealth::Clock::now() - arrived);
}

void PlannerNode::IdentifyIfDue() {
  if (options_.identify_every <= 0) return;
  const std::vector<shot_fit::TrackedShot>& all = shots_.shots();
  if (all.size() < identified_shots_ + static_cast<std::size_t>(options_.identify_every)) return;
  identified_shots_ = all.size();
  const std::vector<shot_fit::TrackedShot> latest(
      all.end() - static_cast<std::ptrdiff_t>(std::min(all.size(), kIdentifyWindow)), all.end());
  try {
    if (!fit_pool_) fit_pool_ = std::make_unique<batch::ThreadPool>();
    shot_fit::FitOptions fit_options;
    fit_options.constants = options_.identify;
    const shot_fit::ShotsFit fit =
        shot_fit::FitShots(table_, params_, latest, fit_options, *fit_pool_);
    std::ostringstream line;
    line << "identified from " << fit.constant_shots << " of its latest " << latest.size()
         << " shots (median cue-ball RMSE " << 1e3 * fit.median_cue_rmse << " mm):";
    for (const shot_fit::ConstantFit& c : fit.constants) {
      line << " " << shot_fit::ConstantName(c.constant) << " " << c.prior;
      if (c.identifiable) {
        line << " -> " << c.value << " +- " << c.sd;
      } else {
        line << (c.at_bound ? " kept (its fit ran to its bound)" : " kept (not identifiable)");
      }
    }
    const std::string base = params_.name.substr(0, params_.name.rfind("-identified"));
    params_ = fit.params;
    params_.name = base + "-identified";
    health_.SetParameters(params::ParameterSetLabel(params_), params::ParameterHash(params_));
    health_.Count("identified");
    log_(line.str());
  } catch (const std::exception& e) {
    health_.Count("identification_failed");
    log_(std::string("identification failed, planning on with the constants so far: ") + e.what());
  }
}

void PlannerNode::LearnNoiseIfDue() {
  if (!options_.learn_noise) return;
  try {
    if (!noise_learner_.Learn(shots_.shots(), shots_.strike_utimes(), params_)) return;
    const shot_fit::NoiseFit& fit = *noise_learner_.fit();
    constexpr double kMicroDegree = 3.14159265358979323846 / 180.0 * 1e-6;
    health_.Set("learned_noise_launches", static_cast<std::int64_t>(fit.used.size()));
    health_.Set("learned_heading_udeg", std::llround(fit.heading.value / kMicroDegree));
    health_.Set("learned_speed_ppm", std::llround(1e6 * fit.speed.value));
    health_.Set("learned_tip_um", std::llround(1e6 * fit.tip.value));
    health_.Count("noise_learned");
    log_(noise_learner_.Describe());
  } catch (const std::exception& e) {
    health_.Count("noise_learning_failed");
    log_(std::string("noise learning failed, choosing on with the noise so far: ") + e.what());
  }
}

void PlannerNode::NoteMotion(const table_state_t& state) {
  if (std::string moving = MovingBall(state, options_.max_ball_speed); !moving.empty()) {
    last_motion_ = std::move(moving);
    states_at_rest_ = 0;
  } else if (states_at_rest_ < options_.rest_states) {
    ++states_at_rest_;
  }
}

std::string PlannerNode::TableNotAtRest() const {
  if (!latest_table_ || states_at_rest_ >= options_.rest_states) return "";
  if (states_at_rest_ == 0) return last_motion_;
  return "the table at rest for " + std::to_string(states_at_rest_) + " of " +
         std::to_string(options_.rest_states) + " states (" + last_motion_ + " before)";
}

bool PlannerNode::WaitedForRestTooLong(const Waiting& w) const {
  const double in_states = 1e-6 * static_cast<double>(latest_table_->utime - w.request.utime);
  // The clock counts only the time no state has come since the request: while states come, a
  // loop slower than real time (a busy machine) waits in their time, as its replay does.
  const auto stalled_since = std::max(w.arrived, latest_table_arrival_);
  const double stalled =
      std::chrono::duration<double>(nodes::NodeHealth::Clock::now() - stalled_since).count();
  return in_states >= options_.max_rest_wait || stalled >= options_.max_rest_wait;
}

void PlannerNode::AnswerOldest(const std::string& not_at_rest) {
  Waiting w = std::move(waiting_.front());
  waiting_.pop_front();
  health_.SetQueueDepth(static_cast<int>(waiting_.size()));
  if (RecordsShots()) shots_.Finish();  // the balls are at rest by the next request
  IdentifyIfDue();
  LearnNoiseIfDue();
  const auto never_at_rest = [&] {
    std::ostringstream reason;
    reason << "the table did not come to rest within " << options_.max_rest_wait
           << " s: " << not_at_rest;
    return Refusal(ReplyTo(w.request), cue_command_t::STATUS_NOT_AT_REST, reason.str());
  };
  const cue_command_t command = not_at_rest.empty() ? Answer(w.request) : never_at_rest();
  Publish(command, w.arrived);
  if (RecordsShots() && command.status == cue_command_t::STATUS_OK) {
    shots_.Strike(command.utime, command.ball_id);
  }
  if (options_.learn_noise) noise_learner_.Commanded(command);
  log_(Describe(command));
  answered_.push_back({std::move(w.bytes), StateUtime(w.request), command});
  if (answered_.size() > kRememberedAnswers) answered_.pop_front();
  if (refusing_busy_ && waiting_.empty()) {
    refusing_busy_ = false;
    log_("queue empty again: " + std::to_string(health_.counter("busy")) +
         " requests answered busy so far");
  }
}

bool PlannerNode::Work() {
  bool more = false;
  try {
    if (!waiting_.empty()) {
      const std::string not_at_rest = TableNotAtRest();
      const bool hold = !not_at_rest.empty() && !WaitedForRestTooLong(waiting_.front());
      if (hold && !holding_) {
        health_.Count("held_for_rest");
        log_("request " + std::to_string(waiting_.front().request.request_id) +
             " held until the table is at rest: " + not_at_rest);
      }
      holding_ = hold;
      if (!hold) AnswerOldest(not_at_rest);
      more = !waiting_.empty() && TableNotAtRest().empty();
    }
    health_.PublishIfDue(lcm_);
  } catch (const std::exception& e) {
    health_.Dropped(std::string("work: ") + e.what());
  } catch (...) {
    health_.Dropped("work: unknown exception");
  }
  return more;
}

}  // namespace billiard::planner_node
