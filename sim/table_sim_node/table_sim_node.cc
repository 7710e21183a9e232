#include "sim/table_sim_node/table_sim_node.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "lcmtypes/billiard/shot_request_t.hpp"
#include "lcmtypes/image_codec.h"
#include "lcmtypes/message_checks.h"
#include "lcmtypes/names.h"
#include "lcmtypes/node/node_loop.h"
#include "lcmtypes/version.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/physics/simulator.h"
#include "sim/table_sim_node/session_balls.h"

namespace billiard::table_sim_node {

TableSimNode::TableSimNode(lcm::LCM& lcm, const physics::ModelParameters& params,
                           const camera::CameraModel& camera, TableSimOptions options, Log log)
    : lcm_(lcm),
      params_(params),
      plant_(options.plant.value_or(params)),
      options_(options),
      renderer_(camera, plant_),
      log_(log ? std::move(log) : Log([](const std::string& line) {
        std::cerr << "table_sim_node: " << line << std::endl;
      })),
      health_("table_sim_node", log_),
      target_rng_(options.seed),
      execution_(options.noise, params.ball.radius, options.seed),
      fault_rng_(options.faults.seed),
      ball_(options.start) {
  subscriptions_.push_back(
      lcm_.subscribe(messages::kTableStateChannel, &TableSimNode::OnTableState, this));
  subscriptions_.push_back(
      lcm_.subscribe(messages::kCueCommandChannel, &TableSimNode::OnCueCommand, this));
  // A busy planner answers a burst all at once; no answer may be lost in LCM's queue.
  subscriptions_.back()->setQueueCapacity(10000);
  subscriptions_.push_back(
      lcm_.subscribe(messages::kNodeStatusChannel, &TableSimNode::OnNodeStatus, this));
  health_.SetParameters(params::ParameterSetLabel(params_), params::ParameterHash(params_));
}

TableSimNode::~TableSimNode() {
  for (lcm::Subscription* s : subscriptions_) lcm_.unsubscribe(s);
}

template <class Message>
std::optional<Message> TableSimNode::Receive(const lcm::ReceiveBuffer* rbuf,
                                             const std::string& channel) {
  health_.Received();
  Message message;
  if (std::string why = messages::DecodeChecked(rbuf->data, rbuf->data_size, message);
      !why.empty()) {
    health_.Dropped(channel + ": " + why);
    return std::nullopt;
  }
  return message;
}

void TableSimNode::OnTableState(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
  if (auto state = Receive<table_state_t>(rbuf, channel)) state_ = std::move(state);
}

void TableSimNode::OnCueCommand(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
  if (auto command = Receive<cue_command_t>(rbuf, channel)) command_ = std::move(command);
}

void TableSimNode::OnNodeStatus(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
  if (auto status = Receive<node_status_t>(rbuf, channel)) {
    const auto peer = std::find(kSessionPeers.begin(), kSessionPeers.end(), status->node);
    if (peer != kSessionPeers.end()) peers_.insert_or_assign(status->node, std::move(*status));
  }
}

void TableSimNode::AwaitPeersOfTheSameBuildAndPhysics() {
  WaitFor([&] { return peers_.size() == kSessionPeers.size(); },
          "NODE_STATUS of the estimator_node and the planner_node", nullptr);
  const std::string hash = params::ParameterHash(params_);
  const std::string label = params::ParameterSetLabel(params_);
  std::string disagreeing;
  const auto add = [&](const std::string& what) {
    disagreeing += (disagreeing.empty() ? "" : "; ") + what;
  };
  for (const auto& [name, status] : peers_) {
    if (status.params_hash != hash) {
      add(name + " runs '" + status.params + "' (" + status.params_hash +
          ") where the simulator runs '" + label + "' (" + hash + ")");
    }
    // Another build may plan or track otherwise with the same numbers.
    if (status.version != kVersion) {
      add(name + " is version " + status.version + " where the simulator is " + kVersion);
    }
  }
  if (!disagreeing.empty()) {
    throw PeerMismatch(
        "the nodes run other physics or another version than the simulator: " + disagreeing +
        "; start every node from the same build with the same --params");
  }
}

template <class Message>
void TableSimNode::Publish(const char* channel, const Message& message) {
  if (lcm_.publish(channel, &message) == 0) {
    health_.Published();
  } else {
    health_.Dropped(std::string(channel) + ": publishing failed");
  }
}

std::int64_t TableSimNode::Utime(double t) const { return std::llround(t * 1e6); }

void TableSimNode::WaitFor(const std::function<bool()>& done, const std::string& what,
                           const std::function<void()>& resend) {
  using Clock = std::chrono::steady_clock;
  const auto seconds = [](double s) {
    return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
  };
  const Clock::time_point deadline = Clock::now() + seconds(options_.reply_timeout);
  Clock::time_point next_resend = Clock::now() + seconds(options_.retry_interval);
  bool more_work = false;
  while (!done()) {
    if (nodes::StopRequested()) throw std::runtime_error("stopped by a signal");
    const Clock::time_point now = Clock::now();
    if (now > deadline) {
      throw std::runtime_error("no " + what + " within " + std::to_string(options_.reply_timeout) +
                               " s");
    }
    if (resend && now > next_resend) {
      health_.Count("resent");
      resend();
      next_resend = now + seconds(options_.retry_interval);
    }
    lcm_.handleTimeout(more_work ? 0 : 20);
    more_work = alongside_ && alongside_();
    health_.PublishIfDue(lcm_);
  }
}

void TableSimNode::Frame(const std::vector<TruthBall>& balls, double t) {
  const std::int64_t utime = Utime(t);
  Publish(messages::kTableTruthChannel, TruthMessage(balls, t, utime));
  const image_t image =
      messages::EncodeImage(renderer_.Render(RenderedBalls(balls), t), utime,
                            messages::ImageEncoding::kMjpeg, options_.jpeg_quality);
  if (!options_.lockstep) {
    static const auto wall_start = std::chrono::steady_clock::now();
    std::this_thread::sleep_until(wall_start + std::chrono::duration<double>(t));
  }

  // One fault at most per frame, drawn whether or not faults are on so that turning one on does
  // not move where the others fall.
  const FaultInjection& f = options_.faults;
  const double draw = std::uniform_real_distribution<double>(0.0, 1.0)(fault_rng_);
  if (draw < f.drop_frames) {
    health_.Count("frame_dropped");
    return;
  }
  if (draw < f.drop_frames + f.reorder_frames && !held_frame_) {
    health_.Count("frame_reordered");
    held_frame_ = image;
    return;
  }
  Publish(messages::kCameraImageChannel, image);
  if (held_frame_) {
    Publish(messages::kCameraImageChannel, *held_frame_);
    held_frame_.reset();
  }
  if (draw >= f.drop_frames + f.reorder_frames &&
      draw < f.drop_frames + f.reorder_frames + f.duplicate) {
    health_.Count("frame_duplicated");
    Publish(messages::kCameraImageChannel, image);
  }
  if (options_.lockstep) {
    WaitFor([&] { return state_ && state_->utime == utime; },
            "TABLE_STATE for the frame at utime " + std::to_string(utime),
            [&] { Publish(messages::kCameraImageChannel, image); });
    if (tracking_) Track(balls, t, *state_);
  } else {
    while (lcm_.handleTimeout(0) > 0) {
    }
    if (alongside_) alongside_();
    health_.PublishIfDue(lcm_);
  }
}

void TableSimNode::ShowAtRest(const std::vector<table::SceneBall>& balls) {
  const std::vector<TruthBall> still = AtRest(balls);
  const double frame_dt = 1.0 / options_.camera_rate;
  for (double shown = 0.0; shown < options_.settle_time; shown += frame_dt) {
    Frame(still, time_);
    time_ += frame_dt;
  }
}

std::optional<std::int32_t> TableSimNode::NearestTrack(const Eigen::Vector2d& at) const {
  std::optional<std::int32_t> track;
  double nearest = 1e300;
  for (const ball_state_t& b : state_->balls) {
    const double d = std::hypot(b.position[0] - at.x(), b.position[1] - at.y());
    if (d < nearest) {
      nearest = d;
      track = b.ball_id;
    }
  }
  return track;
}

cue_command_t TableSimNode::Request(int shot, const std::vector<table::SceneBall>& shown,
                                    const Eigen::Vector2d& ball, const shot_request_t& ask,
                                    ShotResult& result,
                                    const std::optional<Eigen::Vector2d>& object) {
  for (;;) {
    ShowAtRest(shown);
    WaitFor([&] { return state_ && state_->num_balls > 0; }, "TABLE_STATE with the ball", nullptr);
    shot_request_t request = ask;
    request.utime = Utime(time_);
    request.request_id = shot;
    // The estimator names balls by its tracks: ask for the one it sees nearest the ball.
    if (request.ball_id != shot_request_t::BALL_BY_CLASS) request.ball_id = *NearestTrack(ball);
    if (object) request.object_ball_id = NearestTrack(*object).value_or(request.object_ball_id);
    Publish(messages::kShotRequestChannel, request);
    if (std::uniform_real_distribution<double>(0.0, 1.0)(fault_rng_) < options_.faults.duplicate) {
      health_.Count("request_duplicated");
      Publish(messages::kShotRequestChannel, request);
    }
    const auto answered = [&] {
      return command_ && command_->request_id == shot && command_->utime == request.utime;
    };
    WaitFor(answered, "CUE_COMMAND for request " + std::to_string(shot),
            [&] { Publish(messages::kShotRequestChannel, request); });
    const int8_t status = command_->status;
    const bool time_cures = status == cue_command_t::STATUS_NO_BALL_STATE ||
                            status == cue_command_t::STATUS_STALE_STATE ||
                            status == cue_command_t::STATUS_BUSY ||
                            status == cue_command_t::STATUS_NOT_AT_REST;
    if (!time_cures || result.retries == options_.max_retries) return *command_;
    ++result.retries;
    health_.Count("shot_retried");
    log_("shot " + std::to_string(shot) + ": " + messages::CueCommandStatusName(status) + " (" +
         command_->reason + "), asking again");
  }
}

std::vector<ShotResult> TableSimNode::Run() {
  AwaitPeersOfTheSameBuildAndPhysics();
  const double frame_dt = 1.0 / options_.camera_rate;
  const physics::TableParameters& table = params_.table;
  // The robot's cue is checked on the break table's cushions and rails, at the parameter set's size.
  table::TableSpec spec = params::LoadTableSpec(params::kDefaultTable);
  spec.length = table.length;
  spec.width = table.width;
  const table::TableGeometry shots_table = table::BuildTable(spec);
  std::uniform_real_distribution<double> x(options_.target_margin,
                                           table.length - options_.target_margin);
  std::uniform_real_distribution<double> y(options_.target_margin,
                                           table.width - options_.target_margin);
  health_.Set(messages::kRealtimeClockSetting, options_.lockstep ? 0 : 1);
  health_.Publish(lcm_);
  std::vector<ShotResult> results;
  for (int shot = 0; shot < options_.shots; ++shot) {
    const Eigen::Vector2d rest = ball_;
    ShotResult result;
    result.from = rest;
    do {
      result.target = {x(target_rng_), y(target_rng_)};
    } while ((result.target - rest).norm() < options_.min_distance);
    shot_request_t ask{};
    ask.target[0] = result.target.x();
    ask.target[1] = result.target.y();
    ask.spin = options_.spins[static_cast<std::size_t>(shot) % options_.spins.size()];
    const std::vector<table::SceneBall> alone{{kCueBall, physics::MakeBallState(rest.x(), rest.y(), 0, 0, 0, 0, 0)}};
    const cue_command_t command = Request(shot, alone, rest, ask, result);
    result.status = messages::CueCommandStatusName(command.status);
    result.reason = command.reason;
    result.plan_ms = 1e-3 * command.solve_us;
    // The point planner cannot raise its cue yet (its elevation is the spin's, StrokeFor): a
    // stroke the robot cannot make is said and counted, and played all the same.
    RobotRefuses(shots_table, alone, command, false);
    if (command.status != cue_command_t::STATUS_OK) {
      result.final_point = rest;
      result.miss_m = (rest - result.target).norm();
      log_("shot " + std::to_string(shot) + " refused: " + result.status + ", " + result.reason);
      results.push_back(result);
      continue;
    }

    const physics::BallState launch =
        physics::StrikeBall(execution_.Executed(command), rest, plant_);
    const physics::Arrival arrival = physics::SimulateArrival(plant_, launch, 0.0, 120.0);
    const double t_strike = time_;
    const auto trajectory = arrival.trajectory;
    const Eigen::Vector2d final_point = arrival.state.head<2>();
    const auto moving = [t_strike, trajectory, &arrival](double t) -> physics::BallState {
      return t - t_strike >= arrival.time ? arrival.state : trajectory->At(t - t_strike);
    };
    for (; time_ - t_strike < arrival.time; time_ += frame_dt) Frame({{kCueBall, moving}}, time_);
    result.final_point = final_point;
    result.miss_m = (final_point - result.target).norm();
    std::ostringstream line;
    line.precision(4);
    line << "shot " << shot << ": target (" << result.target.x() << ", " << result.target.y()
         << "), rests at (" << final_point.x() << ", " << final_point.y() << "), miss "
         << 1e3 * result.miss_m << " mm, plan " << result.plan_ms << " ms";
    log_(line.str());
    ball_ = PutBackIfPocketed(shots_table, result) ? rest : final_point;
    results.push_back(result);
  }
  health_.PublishIfDue(lcm_);
  return results;
}

bool TableSimNode::PutBackIfPocketed(const table::TableGeometry& geometry, ShotResult& result) {
  // The lone ball is simulated without cushions (physics::SimulateArrival), so a ball that
  // comes to rest off the playing surface, or hanging past a pocket's mouth, is one a real table
  // would have dropped: named by the pocket nearest where it ended. The planner refuses a ball
  // off the surface (off_table), so left there it would end the session.
  if (geometry.OnSurface(result.final_point, params_.ball.radius)) return false;
  result.status = kPocketedStatus;
  result.reason = NearestPocket(geometry, result.final_point);
  health_.Count(kPocketedStatus);
  // Put back where it was struck from, as a shot is taken again: a place on the surface that
  // the estimator saw the ball at rest, the same whatever the noise did, and one that keeps the
  // session's walk of starts and targets (the targets' stream draws each target against it).
  // The foot spot the rules respot an object ball on would send every such shot from one place.
  const std::vector<table::SceneBall> back{
      {kCueBall, physics::MakeBallState(result.from.x(), result.from.y(), 0, 0, 0, 0, 0)}};
  for (int k = 0; k < kNewLayoutSettles; ++k) ShowAtRest(back);
  log_("the ball dropped in " + result.reason + ": put back where it was struck from");
  return true;
}

bool TableSimNode::RobotRefuses(const table::TableGeometry& geometry, const std::vector<table::SceneBall>& balls,
                                const cue_command_t& command, bool refuse) {
  if (command.status != cue_command_t::STATUS_OK || !options_.robot) return false;
  const std::string why = Unmakeable(*options_.robot, geometry, params_.ball.radius, balls, Commanded(command));
  if (why.empty()) return false;
  health_.Refused(refuse ? "cue_blocked" : "cue_blocked_played",
                  "CUE_COMMAND " + std::to_string(command.request_id) + ": " + why + (refuse ? "" : ", played"));
  return refuse;
}

table::TableSimulation TableSimNode::PlayOut(const table::TableGeometry& geometry,
                                             const std::vector<table::SceneBall>& balls,
                                             const cue_command_t& command,
                                             const table::TableSimulationOptions& motion) {
  cue_command_t played = command;
  if (RobotRefuses(geometry, balls, command)) played.status = cue_command_t::STATUS_CUE_BLOCKED;
  table::TableSimulation sim =
      PlayedToRest(geometry, plant_, execution_.Struck(balls, played, plant_), motion);
  const double t_strike = time_;
  const double frame_dt = 1.0 / options_.camera_rate;
  const double last_event = sim.events().empty() ? 0.0 : sim.events().back().time;
  for (; time_ - t_strike <= last_event + options_.settle_time; time_ += frame_dt)
    Frame(OnTable(sim, t_strike, time_), time_);
  return sim;
}

cue_command_t TableSimNode::RequestBreak(int id, const std::vector<table::SceneBall>& balls,
                                         ShotResult& result) {
  const Eigen::Vector2d cue_at = Find(balls, kCueBall)->state.head<2>();
  const table::SceneBall& object = NearestObjectBall(balls, options_.scene);
  // The target: the cue ball's centre at contact.
  const Eigen::Vector2d to_object = object.state.head<2>() - cue_at;
  result.target = object.state.head<2>() - 2.0 * params_.ball.radius * to_object.normalized();
  shot_request_t ask{};
  // The robot strikes the cue ball, which the estimator tells from the others by its colours.
  ask.ball_id = shot_request_t::BALL_BY_CLASS;
  ask.ball_class = ball_state_t::CLASS_CUE;
  ask.target[0] = result.target.x();
  ask.target[1] = result.target.y();
  ask.final_speed = options_.break_speed;
  ask.spin = shot_request_t::SPIN_NATURAL;
  return Request(id, balls, cue_at, ask, result);
}

}  // namespace billiard::table_sim_node
