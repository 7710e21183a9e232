#include "sim/table_sim_node/table_sim_node.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "lcmtypes/billiard/shot_request_t.hpp"
#include "lcmtypes/image_codec.h"
#include "lcmtypes/message_checks.h"
#include "lcmtypes/names.h"
#include "lcmtypes/node/node_loop.h"
#include "lcmtypes/version.h"
#include "sim/model_choice/model_choice.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/scene_file.h"
#include "sim/params/table_specs.h"
#include "sim/physics/simulator.h"
#include "sim/table/rack.h"
#include "sim/table/table_simulation.h"

namespace billiard::table_sim_node {

namespace {

// The one ball of a session, as the truth names it.
constexpr int kCueBall = 0;

// The noise's generator: seeded from the seed and a stream number through seed_seq, so that it
// is independent of the targets' generator (seeded with the seed itself, whose targets it keeps
// as they were).
std::mt19937 NoiseStream(std::uint32_t seed) {
  std::seed_seq sequence{seed, std::uint32_t{1}};
  return std::mt19937(sequence);
}

// The table of the "break" scene, and the longest a whole-table session simulates.
constexpr char kBreakTable[] = "pool-9ft";
constexpr double kLongestScene = 120.0;  // [s]

// A track counts for a ball within this many ball radii of its centre: nearer it than to any
// ball touching it.
constexpr double kTrackGate = 1.0;

// The balls of options.scene on their table.
std::pair<table::TableGeometry, std::vector<table::SceneBall>> LoadSessionScene(
    const TableSimOptions& options, const physics::ModelParameters& params) {
  if (options.scene == "break") {
    table::TableGeometry geometry = table::BuildTable(params::LoadTableSpec(kBreakTable));
    auto balls =
        table::Rack(table::RackKind::kEightBall, geometry, params.ball.radius, options.seed);
    return {std::move(geometry), std::move(balls)};
  }
  const params::SceneFile scene = params::LoadScene(options.scene);
  if (params::ParameterHash(params::LoadParameters(scene.params)) !=
      params::ParameterHash(params)) {
    throw std::invalid_argument(options.scene + ": the scene's parameter set '" + scene.params +
                                "' is not the session's '" + params::ParameterSetLabel(params) +
                                "'");
  }
  table::TableGeometry geometry = table::BuildTable(params::LoadTableSpec(scene.table));
  if (std::abs(geometry.length - params.table.length) > 1e-9 ||
      std::abs(geometry.width - params.table.width) > 1e-9) {
    throw std::invalid_argument(options.scene + ": the " + geometry.name +
                                " table is not the size of the parameter set's, which the camera "
                                "sees");
  }
  for (const table::SceneBall& b : scene.balls) {
    if (b.state.tail<5>().norm() != 0.0) {
      throw std::invalid_argument(options.scene + ": ball " + std::to_string(b.id) +
                                  " moves; a session's scene starts at rest");
    }
  }
  return {std::move(geometry), scene.balls};
}

std::vector<table::SceneBall>::const_iterator Find(const std::vector<table::SceneBall>& balls,
                                                   int id) {
  return std::find_if(balls.begin(), balls.end(),
                      [id](const table::SceneBall& b) { return b.id == id; });
}

// The object ball nearest the cue ball (id 0, which must be there); throws std::invalid_argument
// naming `scene` when there is none.
const table::SceneBall& NearestObjectBall(const std::vector<table::SceneBall>& balls,
                                          const std::string& scene) {
  const Eigen::Vector2d cue_at = Find(balls, kCueBall)->state.head<2>();
  const table::SceneBall* object = nullptr;
  for (const table::SceneBall& b : balls) {
    if (b.id == kCueBall) continue;
    if (object == nullptr ||
        (b.state.head<2>() - cue_at).norm() < (object->state.head<2>() - cue_at).norm()) {
      object = &b;
    }
  }
  if (object == nullptr) throw std::invalid_argument(scene + ": no ball to strike at");
  return *object;
}

// Ball in hand: a placement on another ball moves toward the head rail in steps of this [m];
// a respotted ball is this far clear of the others [m].
constexpr double kPlacementStep = 1e-3;
constexpr double kPlacementClearance = 2e-3;
// A new rack's layout is shown this many settle times before its first shot: longer than the
// estimator coasts the last rack's tracks (estimator::TrackerOptions::max_coast).
constexpr int kNewLayoutSettles = 4;

// The name of the pocket nearest `at`.
std::string NearestPocket(const table::TableGeometry& table, const Eigen::Vector2d& at) {
  const auto nearest = std::min_element(table.pockets.begin(), table.pockets.end(),
                                        [&](const auto& a, const auto& b) {
                                          return (a.centre - at).norm() < (b.centre - at).norm();
                                        });
  return nearest->name;
}

// `balls` with the cue ball (id 0) back on the table: on the head spot (the middle of the head
// half, x = 1/4 length), or the nearest free place behind it toward the head rail.
std::vector<table::SceneBall> InTheKitchen(const table::TableGeometry& table, double radius,
                                           std::vector<table::SceneBall> balls) {
  const Eigen::Vector2d spot =
      table::FreeSpotFrom(table, radius, balls, {0.25 * table.length, 0.5 * table.width},
                          {-kPlacementStep, 0.0}, kPlacementClearance);
  return table::WithBallAt(std::move(balls), kCueBall, spot);
}

}  // namespace

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
      noise_rng_(NoiseStream(options.seed)),
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
  table_state_t truth{};
  truth.utime = utime;
  std::vector<render::RenderBall> shown;
  for (const TruthBall& ball : balls) {
    const physics::BallState x = ball.state(t);
    ball_state_t b{};  // the truth has no covariance
    b.utime = utime;
    b.ball_id = ball.id;
    b.ball_class = ball.id == kCueBall ? ball_state_t::CLASS_CUE : static_cast<int8_t>(ball.id);
    b.class_confidence = 1.0f;
    std::copy(x.data(), x.data() + 2, b.position);
    std::copy(x.data() + physics::kVx, x.data() + physics::kVx + 2, b.velocity);
    std::copy(x.data() + physics::kWx, x.data() + physics::kWx + 3, b.spin);
    truth.balls.push_back(b);
    const auto& state = ball.state;
    shown.push_back({ball.id, render::PoolBallColour(ball.id),
                     [state](double time) { return Eigen::Vector2d(state(time).head<2>()); },
                     render::PoolBallStriped(ball.id)});
  }
  truth.num_balls = static_cast<std::int32_t>(truth.balls.size());
  Publish(messages::kTableTruthChannel, truth);

  const image_t image = messages::EncodeImage(
      renderer_.Render(shown, t), utime, messages::ImageEncoding::kMjpeg, options_.jpeg_quality);
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
  std::vector<TruthBall> still;
  for (const table::SceneBall& b : balls) {
    physics::BallState rest = b.state;
    rest.tail<5>().setZero();
    still.push_back({b.id, [rest](double) { return rest; }});
  }
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
                            status == cue_command_t::STATUS_BUSY;
    if (!time_cures || result.retries == options_.max_retries) return *command_;
    ++result.retries;
    health_.Count("shot_retried");
    log_("shot " + std::to_string(shot) + ": " + messages::CueCommandStatusName(status) + " (" +
         command_->reason + "), asking again");
  }
}

void TableSimNode::Track(const std::vector<TruthBall>& balls, double t,
                         const table_state_t& estimate) {
  const double gate = kTrackGate * params_.ball.radius;
  for (const TruthBall& ball : balls) {
    auto tracking = std::find_if(tracking_->balls.begin(), tracking_->balls.end(),
                                 [&](const BallTracking& b) { return b.id == ball.id; });
    if (tracking == tracking_->balls.end()) continue;
    const Eigen::Vector2d truth = ball.state(t).head<2>();
    double nearest = gate;
    const ball_state_t* track = nullptr;
    for (const ball_state_t& b : estimate.balls) {
      const double d = (Eigen::Vector2d(b.position[0], b.position[1]) - truth).norm();
      if (d < nearest) {
        nearest = d;
        track = &b;
      }
    }
    tracking->named_at_end = false;
    if (track == nullptr) {
      ++tracking->lost;
      continue;
    }
    const int8_t own_class = ball.id == kCueBall ? ball_state_t::CLASS_CUE
                                                 : static_cast<int8_t>(ball.id);
    if (track->ball_class == ball_state_t::CLASS_UNKNOWN) {
      ++tracking->unnamed;
    } else if (track->ball_class != own_class) {
      ++tracking->misnamed;
    } else {
      tracking->named_at_end = true;
    }
    const auto mapped = track_of_.find(ball.id);
    if (mapped != track_of_.end() && mapped->second != track->ball_id) {
      const bool another_balls =
          std::any_of(track_of_.begin(), track_of_.end(),
                      [&](const auto& entry) { return entry.second == track->ball_id; });
      ++(another_balls ? tracking_->swaps : tracking_->reacquired);
    }
    track_of_[ball.id] = track->ball_id;
    ++tracking->frames;
    tracking->sum_squared_error += nearest * nearest;
    tracking->max_error = std::max(tracking->max_error, nearest);
  }
}

physics::CueStroke TableSimNode::WithNoise(physics::CueStroke stroke) {
  std::normal_distribution<double> unit(0.0, 1.0);
  return params::Perturbed(stroke, options_.noise, params_.ball.radius,
                           [&] { return unit(noise_rng_); });
}

std::vector<ShotResult> TableSimNode::Run() {
  AwaitPeersOfTheSameBuildAndPhysics();
  const double frame_dt = 1.0 / options_.camera_rate;
  const physics::TableParameters& table = params_.table;
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
    do {
      result.target = {x(target_rng_), y(target_rng_)};
    } while ((result.target - rest).norm() < options_.min_distance);
    shot_request_t ask{};
    ask.target[0] = result.target.x();
    ask.target[1] = result.target.y();
    ask.spin = shot_request_t::SPIN_NATURAL;
    const cue_command_t command =
        Request(shot, {{kCueBall, physics::MakeBallState(rest.x(), rest.y(), 0, 0, 0, 0, 0)}}, rest,
                ask, result);
    result.status = messages::CueCommandStatusName(command.status);
    result.reason = command.reason;
    result.plan_ms = 1e-3 * command.solve_us;
    if (command.status != cue_command_t::STATUS_OK) {
      result.final_point = rest;
      result.miss_m = (rest - result.target).norm();
      log_("shot " + std::to_string(shot) + " refused: " + result.status + ", " + result.reason);
      results.push_back(result);
      continue;
    }

    const physics::CueStroke stroke =
        WithNoise({command.cue_speed, command.heading, command.tip_side, command.tip_height,
                   command.elevation});
    const physics::BallState launch = physics::StrikeBall(stroke, rest, plant_);
    const physics::Arrival arrival = physics::SimulateArrival(plant_, launch, 0.0, 120.0);
    const double t_strike = time_;
    const auto trajectory = arrival.trajectory;
    const Eigen::Vector2d final_point = arrival.state.head<2>();
    const auto moving = [t_strike, trajectory, &arrival](double t) -> physics::BallState {
      return t - t_strike >= arrival.time ? arrival.state : trajectory->At(t - t_strike);
    };
    for (; time_ - t_strike < arrival.time; time_ += frame_dt) Frame({{kCueBall, moving}}, time_);
    ball_ = final_point;
    result.final_point = final_point;
    result.miss_m = (final_point - result.target).norm();
    std::ostringstream line;
    line.precision(4);
    line << "shot " << shot << ": target (" << result.target.x() << ", " << result.target.y()
         << "), rests at (" << final_point.x() << ", " << final_point.y() << "), miss "
         << 1e3 * result.miss_m << " mm, plan " << result.plan_ms << " ms";
    log_(line.str());
    results.push_back(result);
  }
  health_.PublishIfDue(lcm_);
  return results;
}

table::TableSimulation TableSimNode::PlayOut(const table::TableGeometry& geometry,
                                             const std::vector<table::SceneBall>& balls,
                                             const cue_command_t& command,
                                             const table::TableSimulationOptions& motion) {
  std::vector<table::SceneBall> struck = balls;
  if (command.status == cue_command_t::STATUS_OK) {
    const physics::CueStroke stroke =
        WithNoise({command.cue_speed, command.heading, command.tip_side, command.tip_height,
                   command.elevation});
    for (table::SceneBall& b : struck) {
      if (b.id == kCueBall) b.state = physics::StrikeBall(stroke, b.state.head<2>(), plant_);
    }
  }
  table::TableSimulation sim(geometry, plant_, struck, motion);
  sim.Run(kLongestScene);
  const double t_strike = time_;
  const double frame_dt = 1.0 / options_.camera_rate;
  const double last_event = sim.events().empty() ? 0.0 : sim.events().back().time;
  for (; time_ - t_strike <= last_event + options_.settle_time; time_ += frame_dt) {
    const double since = time_ - t_strike;
    std::vector<TruthBall> on_table;
    for (std::size_t i = 0; i < sim.ball_count(); ++i) {
      if (sim.pocket(i) && since >= sim.segments(i).back().start_time()) continue;
      on_table.push_back({sim.id(i), [&sim, i, t_strike](double t) {
                            return sim.StateAt(i, std::min(t - t_strike, sim.time()));
                          }});
    }
    Frame(on_table, time_);
  }
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

PotResult TableSimNode::PlayPot(int id, const PotShot& pot, const table::TableGeometry& geometry,
                                std::vector<table::SceneBall>& balls, SceneResult& scene) {
  PotResult result;
  result.asked = pot;
  const auto find = [&](int ball) {
    return std::find_if(balls.begin(), balls.end(),
                        [ball](const table::SceneBall& b) { return b.id == ball; });
  };
  const Eigen::Vector2d cue_at = find(kCueBall)->state.head<2>();
  std::optional<Eigen::Vector2d> object;
  if (find(pot.ball) != balls.end()) object = find(pot.ball)->state.head<2>();
  shot_request_t ask{};
  ask.ball_id = shot_request_t::BALL_BY_CLASS;
  ask.ball_class = ball_state_t::CLASS_CUE;
  ask.mode = shot_request_t::MODE_POT;
  ask.object_ball_id = pot.ball;  // the track nearest it when the scene has the ball
  ask.pocket = pot.pocket;
  const cue_command_t command = Request(id, balls, cue_at, ask, result.shot, object);
  result.shot.status = messages::CueCommandStatusName(command.status);
  result.shot.reason = command.reason;
  result.shot.plan_ms = 1e-3 * command.solve_us;
  result.shot.target = {command.cue_rest[0], command.cue_rest[1]};
  if (command.status == cue_command_t::STATUS_OK) {
    result.kind = messages::PotKindName(command.kind);
    result.margin_left_deg = command.margin_deg[0];
    result.margin_right_deg = command.margin_deg[1];
    result.speed_lo = command.speed_window[0];
    result.speed_hi = command.speed_window[1];
  } else {
    result.shot.target = cue_at;
    log_("pot " + std::to_string(id) + " of ball " + std::to_string(pot.ball) + " in " +
         pot.pocket + " refused: " + result.shot.status + ", " + result.shot.reason);
  }
  // The motion `billiard simulate --scene` runs by default, which the planner checks its pots
  // against: the closed form alone would leave a cue ball that slides off a cut centimetres from
  // where the 5-DOF model does.
  table::TableSimulationOptions motion;
  motion.five_dof = model_choice::TableMotion(plant_);
  const table::TableSimulation sim = PlayOut(geometry, balls, command, motion);
  result.first_contact = table::FirstBallMet(sim.events(), kCueBall);
  balls.clear();
  scene.final_balls.clear();
  scene.pockets.clear();
  for (std::size_t i = 0; i < sim.ball_count(); ++i) {
    const std::string pocket = sim.pocket(i).value_or("");
    if (sim.id(i) == pot.ball) result.dropped = pocket;
    if (sim.id(i) == kCueBall) {
      result.scratch = !pocket.empty();
      result.shot.final_point = sim.State(i).head<2>();
    }
    scene.final_balls.push_back({sim.id(i), sim.State(i)});
    scene.pockets.push_back(pocket);
    if (pocket.empty()) balls.push_back({sim.id(i), sim.State(i)});
  }
  result.potted = !result.dropped.empty() && result.dropped == pot.pocket;
  result.shot.miss_m = (result.shot.final_point - result.shot.target).norm();
  scene.events += static_cast<int>(sim.events().size());
  std::ostringstream line;
  line.precision(4);
  line << "pot " << id << ": ball " << pot.ball << " in " << pot.pocket << ": "
       << result.shot.status;
  if (command.status == cue_command_t::STATUS_OK) {
    line << ", " << result.kind << ", " << (result.potted ? "potted" : "missed")
         << (result.scratch ? ", scratch" : "") << ", the cue ball rests "
         << 1e3 * result.shot.miss_m << " mm from the plan's rest";
  }
  log_(line.str());
  return result;
}

SceneResult TableSimNode::RunScene() {
  AwaitPeersOfTheSameBuildAndPhysics();
  auto [geometry, balls] = LoadSessionScene(options_, params_);
  const auto cue = std::find_if(balls.begin(), balls.end(),
                                [](const table::SceneBall& b) { return b.id == kCueBall; });
  if (cue == balls.end()) throw std::invalid_argument(options_.scene + ": no cue ball (id 0)");
  NearestObjectBall(balls, options_.scene);

  health_.Set(messages::kRealtimeClockSetting, options_.lockstep ? 0 : 1);
  health_.Publish(lcm_);
  tracking_ = TrackingReport{};
  for (const table::SceneBall& b : balls) tracking_->balls.push_back({b.id});
  SceneResult result;
  if (!options_.pots.empty()) {
    for (std::size_t k = 0; k < options_.pots.size(); ++k) {
      result.pots.push_back(
          PlayPot(static_cast<int>(k), options_.pots[k], geometry, balls, result));
      if (std::none_of(balls.begin(), balls.end(),
                       [](const table::SceneBall& b) { return b.id == kCueBall; })) {
        log_("the cue ball is off the table: the pots after " + std::to_string(k) +
             " are not played");
        break;
      }
    }
    result.shot = result.pots.back().shot;
    result.tracking = *tracking_;
    tracking_.reset();
    health_.PublishIfDue(lcm_);
    return result;
  }

  const cue_command_t command = RequestBreak(0, balls, result.shot);
  result.shot.status = messages::CueCommandStatusName(command.status);
  result.shot.reason = command.reason;
  result.shot.plan_ms = 1e-3 * command.solve_us;
  if (command.status != cue_command_t::STATUS_OK) {
    log_("the break refused: " + result.shot.status + ", " + result.shot.reason);
  }
  const table::TableSimulation sim = PlayOut(geometry, balls, command, {});
  // The miss: the cue ball's centre where it first meets a ball, against the contact point.
  result.shot.final_point = sim.State(0).head<2>();
  for (const table::TableEvent& e : sim.events()) {
    if (e.type == table::EventType::kBallBall && (e.ball == kCueBall || e.other == kCueBall)) {
      for (std::size_t i = 0; i < sim.ball_count(); ++i) {
        if (sim.id(i) == kCueBall) result.shot.final_point = sim.StateAt(i, e.time).head<2>();
      }
      break;
    }
  }
  result.shot.miss_m = (result.shot.final_point - result.shot.target).norm();
  for (std::size_t i = 0; i < sim.ball_count(); ++i) {
    result.final_balls.push_back({sim.id(i), sim.State(i)});
    result.pockets.push_back(sim.pocket(i).value_or(""));
  }
  result.events = static_cast<int>(sim.events().size());
  result.tracking = *tracking_;
  tracking_.reset();
  std::ostringstream line;
  line.precision(4);
  line << "break: " << result.events << " events, cue ball meets the first ball "
       << 1e3 * result.shot.miss_m << " mm from the contact point, " << result.tracking.swaps
       << " swaps";
  log_(line.str());
  health_.PublishIfDue(lcm_);
  return result;
}

void TableSimNode::ScoreEstimate(const std::vector<table::SceneBall>& balls, GameShot& shot) const {
  double sum = 0.0;
  for (const table::SceneBall& b : balls) {
    const ball_state_t* nearest = nullptr;
    double d = 1e300;
    for (const ball_state_t& track : state_->balls) {
      const double e = std::hypot(track.position[0] - b.state[physics::kX],
                                  track.position[1] - b.state[physics::kY]);
      if (e < d) {
        d = e;
        nearest = &track;
      }
    }
    if (nearest == nullptr || d > params_.ball.radius) {
      ++shot.untracked;
      continue;
    }
    sum += d * d;
    shot.position_max_mm = std::max(shot.position_max_mm, 1e3 * d);
    const int8_t truth = b.id == kCueBall ? ball_state_t::CLASS_CUE : static_cast<int8_t>(b.id);
    shot.misidentified += nearest->ball_class != truth;
  }
  const int tracked = static_cast<int>(balls.size()) - shot.untracked;
  if (tracked > 0) shot.position_rms_mm = 1e3 * std::sqrt(sum / tracked);
}

GameShot TableSimNode::PlayGameShot(int id, GameShot shot, const table::TableGeometry& geometry,
                                    std::vector<table::SceneBall>& balls, bool* nine_legal) {
  const double radius = params_.ball.radius;
  const Eigen::Vector2d cue_at = Find(balls, kCueBall)->state.head<2>();
  ShotResult asked;
  cue_command_t command;
  if (shot.break_shot) {
    command = RequestBreak(id, balls, asked);
  } else {
    shot_request_t ask{};
    ask.ball_id = shot_request_t::BALL_BY_CLASS;
    ask.ball_class = ball_state_t::CLASS_CUE;
    ask.mode = shot_request_t::MODE_CHOOSE;
    ask.rules = shot_request_t::RULES_NINE_BALL;
    ask.ball_in_hand = shot.ball_in_hand ? 1 : 0;
    command = Request(id, balls, cue_at, ask, asked);
  }
  ScoreEstimate(balls, shot);
  shot.status = messages::CueCommandStatusName(command.status);
  shot.reason = command.reason;
  shot.decision_ms = 1e-3 * command.solve_us;
  if (command.status != cue_command_t::STATUS_OK) {
    log_("shot " + std::to_string(shot.number) + " refused: " + shot.status + ", " + shot.reason);
    return shot;
  }
  // The called ball: the truth ball nearest the track the planner named.
  if (!shot.break_shot && command.object_ball_id >= 0) {
    for (const ball_state_t& track : state_->balls) {
      if (track.ball_id != command.object_ball_id) continue;
      double nearest = 1e300;
      for (const table::SceneBall& b : balls) {
        const double d = std::hypot(track.position[0] - b.state[physics::kX],
                                    track.position[1] - b.state[physics::kY]);
        if (b.id != kCueBall && d < nearest) {
          nearest = d;
          shot.called = b.id;
        }
      }
    }
    shot.pocket = command.pocket;
    shot.kind = messages::PotKindName(command.kind);
    shot.predicted = command.success_probability;
  }
  const int lowest = std::accumulate(balls.begin(), balls.end(), 99, [](int low, const auto& b) {
    return b.id == kCueBall ? low : std::min(low, b.id);
  });
  // Ball in hand: the robot places the cue ball where the planner says; on another ball (the
  // estimator's error), the nearest free place toward the head rail.
  if (command.has_cue_placement) {
    std::vector<table::SceneBall> others;
    for (const table::SceneBall& b : balls) {
      if (b.id != kCueBall) others.push_back(b);
    }
    const Eigen::Vector2d placed = table::FreeSpotFrom(
        geometry, radius, others, {command.cue_placement[0], command.cue_placement[1]},
        {-kPlacementStep, 0.0}, 0.0);
    shot.cue_placement = placed;
    balls = table::WithBallAt(others, kCueBall, placed);
  }
  table::TableSimulationOptions motion;
  motion.five_dof = model_choice::TableMotion(plant_);
  const table::TableSimulation sim = PlayOut(geometry, balls, command, motion);
  shot.first_contact = table::FirstBallMet(sim.events(), kCueBall);
  bool scratch = false;
  std::vector<table::SceneBall> rest;
  for (std::size_t i = 0; i < sim.ball_count(); ++i) {
    std::optional<std::string> pocket = sim.pocket(i);
    // A ball come to rest over a pocket's mouth hangs there in the model, where a real one
    // would drop (table::TableGeometry::OnSurface): it drops in that pocket.
    const Eigen::Vector2d at = sim.State(i).head<2>();
    if (!pocket && !geometry.OnSurface(at, radius)) pocket = NearestPocket(geometry, at);
    if (!pocket) {
      rest.push_back({sim.id(i), sim.State(i)});
    } else if (sim.id(i) == kCueBall) {
      scratch = true;
    } else {
      shot.potted.push_back(sim.id(i));
      if (sim.id(i) == shot.called && *pocket == shot.pocket) shot.called_potted = true;
    }
  }
  std::sort(shot.potted.begin(), shot.potted.end());
  // Nine-ball's fouls (WPA Rules of Play), as choice::PlayGame judges them.
  if (scratch) {
    shot.foul_reason = "scratch";
  } else if (shot.first_contact < 0) {
    shot.foul_reason = "no contact";
  } else if (!shot.break_shot && shot.first_contact != lowest) {
    shot.foul_reason = "first contact " + std::to_string(shot.first_contact) + ", not the lowest " +
                       std::to_string(lowest);
  }
  shot.foul = !shot.foul_reason.empty();
  shot.called_potted = shot.called_potted && !shot.foul;
  const bool nine = std::find(shot.potted.begin(), shot.potted.end(), 9) != shot.potted.end();
  *nine_legal = nine && !shot.foul;
  if (nine && shot.foul) {
    table::SceneBall spotted{9, physics::BallState::Zero()};
    spotted.state.head<2>() =
        table::FreeSpotFrom(geometry, radius, rest, {0.75 * geometry.length, 0.5 * geometry.width},
                            {kPlacementStep, 0.0}, kPlacementClearance);
    rest.push_back(spotted);
  }
  if (scratch) rest = InTheKitchen(geometry, radius, std::move(rest));
  balls = std::move(rest);
  std::ostringstream line;
  line.precision(3);
  line << "shot " << shot.number << (shot.break_shot ? " (break)" : "") << ": ";
  if (shot.called >= 0) {
    line << "ball " << shot.called << " in " << shot.pocket << " at p " << shot.predicted << ", ";
  }
  line << (shot.potted.empty() ? "nothing" : std::to_string(shot.potted.size()) + " ball(s)")
       << " potted" << (shot.called_potted ? " (the called one)" : "")
       << (shot.foul ? ", foul: " + shot.foul_reason : "") << "; estimator rms "
       << shot.position_rms_mm << " mm";
  log_(line.str());
  return shot;
}

std::vector<GameResult> TableSimNode::RunGame() {
  AwaitPeersOfTheSameBuildAndPhysics();
  const table::TableGeometry geometry = table::BuildTable(params::LoadTableSpec(kBreakTable));
  const double radius = params_.ball.radius;
  health_.Set(messages::kRealtimeClockSetting, options_.lockstep ? 0 : 1);
  health_.Publish(lcm_);
  std::vector<GameResult> games;
  int id = 0;  // request ids, unique over the session
  for (int rack = 0; rack < options_.racks; ++rack) {
    GameResult game;
    game.seed = options_.seed + static_cast<std::uint32_t>(rack);
    const bool drill = options_.game == "drill";
    std::vector<table::SceneBall> balls =
        drill ? InTheKitchen(geometry, radius,
                             table::SeededNineBallLayout(geometry, radius, game.seed))
              : table::Rack(table::RackKind::kNineBall, geometry, radius, game.seed);
    log_("rack " + std::to_string(rack) + " (" + options_.game + ", seed " +
         std::to_string(game.seed) + ")");
    // The new layout shown until the estimator has forgotten the last one's balls.
    for (int k = 0; k < kNewLayoutSettles; ++k) ShowAtRest(balls);
    bool ball_in_hand = drill, new_visit = true, nine_legal = false;
    int visit = 1;
    for (int n = 0; n < options_.shot_limit; ++n) {
      if (new_visit) game.visits = visit;
      GameShot shot;
      shot.number = n + 1;
      shot.visit = visit;
      shot.break_shot = !drill && n == 0;
      shot.ball_in_hand = ball_in_hand;
      shot = PlayGameShot(id++, shot, geometry, balls, &nine_legal);
      game.shots.push_back(shot);
      const bool object_balls_left = std::any_of(
          balls.begin(), balls.end(), [](const table::SceneBall& b) { return b.id != kCueBall; });
      if (nine_legal || !object_balls_left) {
        game.cleared = true;
        break;
      }
      ball_in_hand = shot.foul;
      new_visit = shot.foul || shot.potted.empty();
      if (new_visit) ++visit;
    }
    log_("rack " + std::to_string(rack) + (game.cleared ? " cleared" : " not cleared") + " in " +
         std::to_string(game.shots.size()) + " shots, " + std::to_string(game.visits) + " visits");
    games.push_back(std::move(game));
  }
  health_.PublishIfDue(lcm_);
  return games;
}

}  // namespace billiard::table_sim_node
