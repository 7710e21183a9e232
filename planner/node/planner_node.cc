#include "planner/node/planner_node.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <iostream>
#include <map>
#include <sstream>
#include <utility>

#include "lcmtypes/billiard/table_state_t.hpp"
#include "lcmtypes/message_checks.h"
#include "lcmtypes/names.h"
#include "planner/choice/ball_in_hand.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/physics/ball_state.h"

namespace billiard::planner_node {

namespace {

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
  }
  return cue_command_t::STATUS_INVALID;
}

// shot_request_t's KIND_ constants and the pot planner's kinds (KIND_ANY: none).
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

// The ball `id` names among `balls`; with shot_request_t::BALL_BY_CLASS, the one of
// `ball_class` the estimator is surest of, at least kMinClassConfidence. Ties by id: the answer
// must not depend on the balls' order. nullptr when there is none.
const ball_state_t* Named(const std::vector<const ball_state_t*>& balls, int32_t id,
                          int8_t ball_class, float min_confidence = kMinClassConfidence) {
  const ball_state_t* surest = nullptr;
  for (const ball_state_t* ball : balls) {
    if (id != shot_request_t::BALL_BY_CLASS) {
      if (ball->ball_id == id) return ball;
      continue;
    }
    if (ball->ball_class != ball_class || ball->class_confidence < min_confidence) continue;
    if (surest == nullptr || ball->class_confidence > surest->class_confidence ||
        (ball->class_confidence == surest->class_confidence && ball->ball_id < surest->ball_id)) {
      surest = ball;
    }
  }
  return surest;
}

table::TableGeometry TableOf(const PlannerNodeOptions& options) {
  return options.table ? *options.table
                       : table::BuildTable(params::LoadTableSpec(kDefaultPotTable));
}

}  // namespace

std::unordered_map<int32_t, int> BallNumbers(const table_state_t& table, int32_t cue) {
  constexpr int kHighestNumber = 15;
  std::vector<const ball_state_t*> balls;
  for (const ball_state_t& b : table.balls) balls.push_back(&b);
  std::sort(balls.begin(), balls.end(),
            [](const ball_state_t* a, const ball_state_t* b) { return a->ball_id < b->ball_id; });
  // Each number's surest claimant: first among the confident, then, for the numbers still
  // free, among the others (a faint stripe is still likelier its own number than any other).
  std::map<int, const ball_state_t*> claimant;
  std::unordered_map<int32_t, int> number;
  for (const bool confident : {true, false}) {
    std::map<int, const ball_state_t*> surest;
    for (const ball_state_t* b : balls) {
      if (b->ball_id == cue || number.count(b->ball_id) || b->ball_class < 1 ||
          b->ball_class > kHighestNumber || claimant.count(b->ball_class) ||
          (b->class_confidence >= kMinClassConfidence) != confident) {
        continue;
      }
      const ball_state_t*& s = surest[b->ball_class];
      if (s == nullptr || b->class_confidence > s->class_confidence) s = b;
    }
    for (const auto& [n, b] : surest) {
      claimant[n] = b;
      number[b->ball_id] = n;
    }
  }
  number[cue] = 0;
  int free = 1;
  for (const ball_state_t* b : balls) {
    if (number.count(b->ball_id)) continue;
    while (free <= kHighestNumber && claimant.count(free)) ++free;
    number[b->ball_id] = free++;
  }
  return number;
}

namespace {

std::string Describe(const cue_command_t& c) {
  std::ostringstream line;
  line << "request " << c.request_id << " (ball " << c.ball_id;
  if (c.mode == shot_request_t::MODE_POT) {
    line << ", pot ball " << c.object_ball_id << " in " << c.pocket;
  }
  if (c.mode == shot_request_t::MODE_CHOOSE) {
    line << ", chose ball " << c.object_ball_id << " in " << c.pocket << " at p "
         << c.success_probability;
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

// The answer to `q` before anything is planned: its ids and the request's utime, so that the
// answer is a function of the messages alone; a pot's ball, pocket and kind when the request
// passes its checks (those of one that does not may be anything).
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

// The planner's request for the ball at `s`, with the message's spin choice (messages::Check has
// made sure it is one of the five).
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

// The plan into the command. The planner's measurements go out with a refusal too (a
// not-converged plan's miss says by how much); the stroke only with an ok plan, so that a
// refused command cannot move the cue.
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

// The pot into the command, the balls named by the table state's ids (`message_id` of each of
// the scene's ids). The stroke, like a point plan's, only with an ok plan.
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

// What goes out must pass the receiver's checks, or the answer is lost: a refusal keeps its
// status without the measurements, and an ok that fails them is no ok.
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
      health_("planner_node", log_) {
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
  if (q.mode == shot_request_t::MODE_POT) return AnswerPot(q, state, std::move(c));
  if (q.mode == shot_request_t::MODE_CHOOSE) return AnswerChoice(q, state, std::move(c));
  planner::ShotPlan plan;
  try {
    plan = planner::PlanShot(ToShotRequest(q, state), params_, options_.planner);
  } catch (const std::exception& e) {
    return Refusal(c, cue_command_t::STATUS_NOT_CONVERGED,
                   std::string("planner failed: ") + e.what());
  }
  WritePlan(plan, &c);
  return Sendable(c);
}

cue_command_t PlannerNode::AnswerPot(const shot_request_t& q, const ball_state_t& cue,
                                     cue_command_t c) const {
  const ball_state_t* object = ObjectBallFor(q);
  if (object == nullptr) {
    std::ostringstream reason;
    reason << "no ball "
           << (q.object_ball_id == shot_request_t::BALL_BY_CLASS
                   ? "of class " + std::to_string(q.object_ball_class) + " with a confidence of " +
                         std::to_string(kMinClassConfidence) + " or more"
                   : std::to_string(q.object_ball_id))
           << " in the latest table state";
    return Refusal(c, cue_command_t::STATUS_NO_SUCH_BALL, reason.str());
  }
  c.object_ball_id = object->ball_id;
  if (object->ball_id == cue.ball_id) {
    return Refusal(c, cue_command_t::STATUS_NO_SUCH_BALL,
                   "ball " + std::to_string(cue.ball_id) + " is the ball struck, not one to pot");
  }
  pot::PotRequest request;
  request.pocket = q.pocket;
  request.kind = ToShotKind(q.kind);
  if (q.has_cue_target) {
    const Eigen::Vector2d point(q.cue_target[0], q.cue_target[1]);
    if (!table_.OnSurface(point, params_.ball.radius)) {
      std::ostringstream reason;
      reason << "the cue-ball target (" << point.x() << ", " << point.y() << ") is off the "
             << table_.name << " table's playing surface";
      return Refusal(c, cue_command_t::STATUS_OFF_TABLE, reason.str());
    }
    request.cue_target = pot::CueTarget{point, q.cue_radius};
  }
  // The scene: the cue ball id 0, the others by their ids (one that is 0 takes a free id).
  int32_t free_id = 1;
  for (const ball_state_t& b : latest_table_->balls) free_id = std::max(free_id, b.ball_id + 1);
  std::unordered_map<int, int32_t> message_id;
  std::string moving;
  const auto balls = SceneAtRest(
      cue.ball_id, [&](int32_t id) { return id == 0 ? free_id : id; }, &message_id, &moving);
  if (!balls) return Refusal(c, cue_command_t::STATUS_INVALID, moving);
  for (const auto& [scene_id, id] : message_id) {
    if (id == object->ball_id) request.ball = scene_id;
  }
  pot::PotPlan plan;
  try {
    plan = pot::PlanPot(table_, params_, *balls, request, options_.pot);
  } catch (const std::exception& e) {
    return Refusal(c, cue_command_t::STATUS_NOT_CONVERGED,
                   std::string("pot planner failed: ") + e.what());
  }
  WritePot(plan, message_id, &c);
  return Sendable(c);
}

std::optional<std::vector<table::SceneBall>> PlannerNode::SceneAtRest(
    int32_t cue_track, const std::function<int(int32_t)>& scene_id,
    std::unordered_map<int, int32_t>* message_id, std::string* moving) const {
  std::vector<table::SceneBall> balls;
  for (const ball_state_t& b : latest_table_->balls) {
    const double speed = std::hypot(b.velocity[0], b.velocity[1]);
    if (speed > options_.max_ball_speed) {
      std::ostringstream reason;
      reason << "ball " << b.ball_id << " is moving (" << speed << " m/s, more than "
             << options_.max_ball_speed << " m/s)";
      *moving = reason.str();
      return std::nullopt;
    }
    const int id = b.ball_id == cue_track ? 0 : scene_id(b.ball_id);
    (*message_id)[id] = b.ball_id;
    balls.push_back({id, physics::MakeBallState(b.position[0], b.position[1], 0, 0, 0, 0, 0)});
  }
  // By id, so that the plan does not depend on the publisher's order.
  std::sort(balls.begin(), balls.end(),
            [](const table::SceneBall& a, const table::SceneBall& b) { return a.id < b.id; });
  return balls;
}

cue_command_t PlannerNode::AnswerChoice(const shot_request_t& q, const ball_state_t& cue,
                                        cue_command_t c) const {
  const std::unordered_map<int32_t, int> number = BallNumbers(*latest_table_, cue.ball_id);
  std::unordered_map<int, int32_t> message_id;
  std::string moving;
  auto balls = SceneAtRest(
      cue.ball_id, [&](int32_t id) { return number.at(id); }, &message_id, &moving);
  if (!balls) return Refusal(c, cue_command_t::STATUS_INVALID, moving);
  // An object ball seen further over a pocket's mouth or into a cushion than settling moves one
  // is dropping (the estimator's last frames of it): no ball to play.
  balls->erase(std::remove_if(balls->begin(), balls->end(),
                              [&](const table::SceneBall& b) {
                                return b.id != 0 &&
                                       !table_.OnSurface(
                                           b.state.head<2>(),
                                           params_.ball.radius - options_.pot.settle_overlap);
                              }),
               balls->end());
  choice::ChoiceOptions options = options_.choice;
  options.rules =
      q.rules == shot_request_t::RULES_NINE_BALL ? choice::Rules::kNineBall : choice::Rules::kAny;
  options.seed = choice::SampleSeed(options_.choice.seed, static_cast<std::uint64_t>(q.request_id));
  options.pot = options_.pot;
  choice::ChoiceResult result;
  try {
    // What the camera saw, touching balls settled apart as a pot's are.
    *balls = table::SettledScene(table_, params_.ball.radius, std::move(*balls),
                                 options_.pot.settle_overlap);
    if (!choice_pool_) choice_pool_ = std::make_unique<batch::ThreadPool>(options_.choice_threads);
    result = q.ball_in_hand
                 ? choice::ChooseWithBallInHand(table_, params_, *balls, options, *choice_pool_)
                 : choice::ChooseShot(table_, params_, *balls, options, *choice_pool_);
  } catch (const std::exception& e) {
    return Refusal(c, cue_command_t::STATUS_INVALID, std::string("no choice: ") + e.what());
  }
  switch (result.status) {
    case choice::ChoiceStatus::kInvalid:
      return Refusal(c, cue_command_t::STATUS_INVALID, result.reason);
    case choice::ChoiceStatus::kNoTarget:
      return Refusal(c, cue_command_t::STATUS_NO_SUCH_BALL, result.reason);
    case choice::ChoiceStatus::kOk:
    case choice::ChoiceStatus::kNoPlan:
      break;
  }
  if (result.cue_placement) {
    c.has_cue_placement = 1;
    c.start[0] = c.cue_placement[0] = result.cue_placement->x();
    c.start[1] = c.cue_placement[1] = result.cue_placement->y();
  }
  if (const choice::Candidate* chosen = result.chosen()) {
    WritePot(chosen->plan, message_id, &c);
    c.object_ball_id = message_id.at(chosen->plan.ball);
    c.pocket = chosen->plan.pocket;
    c.success_probability = chosen->reported().probability;
    c.probability_stderr = chosen->reported().stderr_;
  } else {  // kNoPlan: the fallback, which at least hits the first legal ball
    const physics::CueStroke& s = *result.fallback;
    c.cue_speed = s.speed;
    c.heading = s.heading;
    c.tip_side = s.tip_side;
    c.tip_height = s.tip_height;
    c.elevation = s.elevation;
    c.status = cue_command_t::STATUS_OK;
  }
  c.solve_us = result.decision_us;
  c.iterations = result.simulations;
  return Sendable(c);
}

const ball_state_t* PlannerNode::ObjectBallFor(const shot_request_t& q) const {
  return Named(Candidates(q), q.object_ball_id, q.object_ball_class);
}

std::vector<const ball_state_t*> PlannerNode::Candidates(const shot_request_t& q) const {
  std::vector<const ball_state_t*> balls;
  if (q.mode == shot_request_t::MODE_POT || q.mode == shot_request_t::MODE_CHOOSE) {
    if (latest_table_) {
      for (const ball_state_t& b : latest_table_->balls) balls.push_back(&b);
    }
  } else {
    for (const auto& [id, b] : balls_) balls.push_back(&b);
  }
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
  const double speed = std::hypot(s.velocity[0], s.velocity[1]);
  if (speed > options_.max_ball_speed) {
    std::ostringstream reason;
    reason << "ball " << q.ball_id << " is moving (" << speed << " m/s, more than "
           << options_.max_ball_speed << " m/s)";
    return Unfit{cue_command_t::STATUS_INVALID, reason.str()};
  }
  return std::nullopt;
}

const ball_state_t* PlannerNode::BallFor(const shot_request_t& q) const {
  if (q.ball_id != shot_request_t::BALL_BY_CLASS) return Named(Candidates(q), q.ball_id, 0);
  // By class among the balls the estimator sees now: one it has lost (pocketed, or of a rack
  // cleared away) is no ball to strike, however sure it was of it.
  std::vector<const ball_state_t*> seen;
  if (latest_table_) {
    for (const ball_state_t& b : latest_table_->balls) seen.push_back(&b);
  }
  // A choice is made on a whole rack, which has one cue ball: the likeliest, however unsure, or
  // when the estimator names none now, the ball it named the cue ball last.
  if (q.mode != shot_request_t::MODE_CHOOSE) return Named(seen, q.ball_id, q.ball_class);
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
        last_of_class_.clear();
        answered_.clear();
        break;
    }
    for (const ball_state_t& ball : state.balls) balls_.insert_or_assign(ball.ball_id, ball);
    std::vector<const ball_state_t*> seen;
    for (const ball_state_t& b : state.balls) seen.push_back(&b);
    for (const ball_state_t& b : state.balls) {
      if (b.ball_class == ball_state_t::CLASS_UNKNOWN) continue;
      last_of_class_[b.ball_class] =
          Named(seen, shot_request_t::BALL_BY_CLASS, b.ball_class, 0.0f)->ball_id;
    }
    if (options_.identify_every > 0) {
      std::vector<shot_fit::TrackSample> tracks;
      for (const ball_state_t& b : state.balls)
        tracks.push_back({b.ball_id, {b.position[0], b.position[1]}});
      shots_.State(state.utime, tracks);
    }
    latest_table_ = std::move(state);
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
  shots_.Finish();
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
    log_(std::string("identification failed, planning on with the constants so far: ") +
         e.what());
  }
}

bool PlannerNode::Work() {
  try {
    if (!waiting_.empty()) {
      Waiting w = std::move(waiting_.front());
      waiting_.pop_front();
      health_.SetQueueDepth(static_cast<int>(waiting_.size()));
      IdentifyIfDue();
      const cue_command_t command = Answer(w.request);
      Publish(command, w.arrived);
      if (options_.identify_every > 0 && command.status == cue_command_t::STATUS_OK) {
        shots_.Strike(command.utime, command.ball_id);
      }
      log_(Describe(command));
      answered_.push_back({std::move(w.bytes), StateUtime(w.request), command});
      if (answered_.size() > kRememberedAnswers) answered_.pop_front();
      if (refusing_busy_ && waiting_.empty()) {
        refusing_busy_ = false;
        log_("queue empty again: " + std::to_string(health_.counter("busy")) +
             " requests answered busy so far");
      }
    }
    health_.PublishIfDue(lcm_);
  } catch (const std::exception& e) {
    health_.Dropped(std::string("work: ") + e.what());
  } catch (...) {
    health_.Dropped("work: unknown exception");
  }
  return !waiting_.empty();
}

}  // namespace billiard::planner_node
