#include "table_sim_node.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "billiard/shot_request_t.hpp"
#include "estimator_node.h"
#include "image_codec.h"
#include "node_loop.h"
#include "planner_node.h"
#include "simulator.h"

namespace billiard {

namespace {

using estimator::kCameraImageChannel;
using planner::kCueCommandChannel;
using planner::kShotRequestChannel;
using planner::kTableStateChannel;
constexpr char kTableTruthChannel[] = "TABLE_TRUTH";
constexpr int kCueBall = 0;

}  // namespace

TableSimNode::TableSimNode(lcm::LCM& lcm, const ModelParameters& params, const CameraModel& camera,
                           TableSimOptions options, Log log)
    : lcm_(lcm),
      params_(params),
      options_(options),
      renderer_(camera, params),
      log_(log ? std::move(log) : Log([](const std::string& line) {
        std::cerr << "table_sim_node: " << line << std::endl;
      })),
      rng_(options.seed),
      ball_(options.start) {
  subscriptions_.push_back(lcm_.subscribe(kTableStateChannel, &TableSimNode::OnTableState, this));
  subscriptions_.push_back(lcm_.subscribe(kCueCommandChannel, &TableSimNode::OnCueCommand, this));
}

TableSimNode::~TableSimNode() {
  for (lcm::Subscription* s : subscriptions_) lcm_.unsubscribe(s);
}

void TableSimNode::OnTableState(const lcm::ReceiveBuffer*, const std::string&,
                                const table_state_t* m) {
  states_.push_back(*m);
}

void TableSimNode::OnCueCommand(const lcm::ReceiveBuffer*, const std::string&,
                                const cue_command_t* m) {
  commands_.push_back(*m);
}

std::int64_t TableSimNode::Utime(double t) const { return std::llround(t * 1e6); }

void TableSimNode::WaitFor(const std::function<bool()>& done, const std::string& what) {
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration<double>(options_.reply_timeout);
  while (!done()) {
    if (nodes::StopRequested()) throw std::runtime_error("stopped by a signal");
    if (std::chrono::steady_clock::now() > deadline) {
      throw std::runtime_error("no " + what + " within " + std::to_string(options_.reply_timeout) +
                               " s");
    }
    lcm_.handleTimeout(20);
  }
}

void TableSimNode::Frame(const std::function<BallState(double)>& state, double t) {
  const std::int64_t utime = Utime(t);
  const BallState x = state(t);
  table_state_t truth{};
  truth.utime = utime;
  ball_state_t b{};  // the truth has no covariance
  b.utime = utime;
  b.ball_id = kCueBall;
  std::copy(x.data(), x.data() + 2, b.position);
  std::copy(x.data() + kVx, x.data() + kVx + 2, b.velocity);
  std::copy(x.data() + kWx, x.data() + kWx + 3, b.spin);
  truth.balls.push_back(b);
  truth.num_balls = 1;
  lcm_.publish(kTableTruthChannel, &truth);

  const RenderBall ball{kCueBall, PoolBallColour(kCueBall),
                        [&state](double time) { return Eigen::Vector2d(state(time).head<2>()); }};
  const image_t image =
      EncodeImage(renderer_.Render({ball}, t), utime, ImageEncoding::kMjpeg, options_.jpeg_quality);
  if (!options_.lockstep) {
    static const auto wall_start = std::chrono::steady_clock::now();
    std::this_thread::sleep_until(wall_start + std::chrono::duration<double>(t));
  }
  lcm_.publish(kCameraImageChannel, &image);
  if (options_.lockstep) {
    WaitFor([&] { return !states_.empty() && states_.back().utime == utime; },
            "TABLE_STATE for the frame at utime " + std::to_string(utime));
  } else {
    while (lcm_.handleTimeout(0) > 0) {
    }
  }
}

CueStroke TableSimNode::WithNoise(CueStroke stroke) {
  std::normal_distribution<double> unit(0.0, 1.0);
  const ExecutionNoise& n = options_.noise;
  stroke.speed *= 1.0 + n.speed * unit(rng_);
  stroke.heading += n.heading * unit(rng_);
  stroke.tip_side += n.tip_offset * unit(rng_);
  stroke.tip_height += n.tip_offset * unit(rng_);
  // A tip pushed past the ball's edge would miscue: keep it on the ball.
  const double offset = std::hypot(stroke.tip_side, stroke.tip_height);
  const double limit = 0.95 * params_.ball.radius;
  if (offset > limit) {
    stroke.tip_side *= limit / offset;
    stroke.tip_height *= limit / offset;
  }
  return stroke;
}

std::vector<ShotResult> TableSimNode::Run() {
  const double frame_dt = 1.0 / options_.camera_rate;
  const TableParameters& table = params_.table;
  std::uniform_real_distribution<double> x(options_.target_margin,
                                           table.length - options_.target_margin);
  std::uniform_real_distribution<double> y(options_.target_margin,
                                           table.width - options_.target_margin);
  std::vector<ShotResult> results;
  for (int shot = 0; shot < options_.shots; ++shot) {
    const Eigen::Vector2d rest = ball_;
    const BallState rest_state = MakeBallState(rest.x(), rest.y(), 0, 0, 0, 0, 0);
    const auto at_rest = [&rest_state](double) { return rest_state; };
    for (double shown = 0.0; shown < options_.settle_time; shown += frame_dt) {
      Frame(at_rest, time_);
      time_ += frame_dt;
    }
    // The estimator names balls by its tracks: ask for the one it sees nearest the ball.
    WaitFor([&] { return !states_.empty() && states_.back().num_balls > 0; },
            "TABLE_STATE with the ball");
    const table_state_t& seen = states_.back();
    int ball_id = seen.balls[0].ball_id;
    double nearest = 1e300;
    for (const ball_state_t& b : seen.balls) {
      const double d = std::hypot(b.position[0] - rest.x(), b.position[1] - rest.y());
      if (d < nearest) {
        nearest = d;
        ball_id = b.ball_id;
      }
    }

    ShotResult result;
    do {
      result.target = {x(rng_), y(rng_)};
    } while ((result.target - rest).norm() < options_.min_distance);
    shot_request_t request{};
    request.utime = Utime(time_);
    request.request_id = shot;
    request.ball_id = ball_id;
    request.target[0] = result.target.x();
    request.target[1] = result.target.y();
    request.spin = shot_request_t::SPIN_NATURAL;
    lcm_.publish(kShotRequestChannel, &request);
    WaitFor([&] { return !commands_.empty() && commands_.back().request_id == shot; },
            "CUE_COMMAND for request " + std::to_string(shot));
    const cue_command_t command = commands_.back();
    result.status = planner::CueCommandStatusName(command.status);
    result.reason = command.reason;
    result.plan_ms = 1e-3 * command.solve_us;
    if (command.status != cue_command_t::STATUS_OK) {
      result.final_point = rest;
      result.miss_m = (rest - result.target).norm();
      log_("shot " + std::to_string(shot) + " refused: " + result.status + ", " + result.reason);
      results.push_back(result);
      continue;
    }

    const CueStroke stroke = WithNoise({command.cue_speed, command.heading, command.tip_side,
                                        command.tip_height, command.elevation});
    const BallState launch = StrikeBall(stroke, rest, params_);
    const Arrival arrival = SimulateArrival(params_, launch, 0.0, 120.0);
    const double t_strike = time_;
    const auto trajectory = arrival.trajectory;
    const Eigen::Vector2d final_point = arrival.state.head<2>();
    const auto moving = [t_strike, trajectory, &arrival](double t) -> BallState {
      return t - t_strike >= arrival.time ? arrival.state : trajectory->At(t - t_strike);
    };
    for (; time_ - t_strike < arrival.time; time_ += frame_dt) Frame(moving, time_);
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
  return results;
}

}  // namespace billiard
