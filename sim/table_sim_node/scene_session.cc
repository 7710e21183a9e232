// TableSimNode's whole-table sessions (RunScene, table_sim_node.h): the break, or pots in turn,
// and the estimator's tracks scored against the truth ball by ball.
#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "lcmtypes/message_checks.h"
#include "lcmtypes/names.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/scene_file.h"
#include "sim/params/table_specs.h"
#include "sim/table/rack.h"
#include "sim/table_sim_node/session_balls.h"
#include "sim/table_sim_node/stroke_execution.h"
#include "sim/table_sim_node/table_sim_node.h"

namespace billiard::table_sim_node {

namespace {

// A track counts for a ball within this many ball radii of its centre: nearer it than to any
// ball touching it.
constexpr double kTrackGate = 1.0;

// The balls of options.scene on their table.
std::pair<table::TableGeometry, std::vector<table::SceneBall>> LoadSessionScene(
    const TableSimOptions& options, const physics::ModelParameters& params) {
  if (options.scene == "break") {
    table::TableGeometry geometry = table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
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

}  // namespace

SceneResult TableSimNode::RunScene() {
  AwaitPeersOfTheSameBuildAndPhysics();
  auto [geometry, balls] = LoadSessionScene(options_, params_);
  if (Find(balls, kCueBall) == balls.end())
    throw std::invalid_argument(options_.scene + ": no cue ball (id 0)");
  NearestObjectBall(balls, options_.scene);

  health_.Set(messages::kRealtimeClockSetting, options_.lockstep ? 0 : 1);
  health_.Publish(lcm_);
  tracking_ = TrackingReport{};
  for (const table::SceneBall& b : balls) tracking_->balls.push_back({b.id});
  SceneResult result =
      options_.pots.empty() ? PlayBreak(geometry, balls) : PlayPots(geometry, balls);
  health_.PublishIfDue(lcm_);
  return result;
}

SceneResult TableSimNode::PlayPots(const table::TableGeometry& geometry,
                                   std::vector<table::SceneBall>& balls) {
  SceneResult result;
  for (std::size_t k = 0; k < options_.pots.size(); ++k) {
    result.pots.push_back(PlayPot(static_cast<int>(k), options_.pots[k], geometry, balls, result));
    if (Find(balls, kCueBall) == balls.end()) {
      log_("the cue ball is off the table: the pots after " + std::to_string(k) +
           " are not played");
      break;
    }
  }
  result.shot = result.pots.back().shot;
  result.tracking = *std::exchange(tracking_, std::nullopt);
  return result;
}

SceneResult TableSimNode::PlayBreak(const table::TableGeometry& geometry,
                                    const std::vector<table::SceneBall>& balls) {
  SceneResult result;
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
  result.tracking = *std::exchange(tracking_, std::nullopt);
  std::ostringstream line;
  line.precision(4);
  line << "break: " << result.events << " events, cue ball meets the first ball "
       << 1e3 * result.shot.miss_m << " mm from the contact point, " << result.tracking.swaps
       << " swaps";
  log_(line.str());
  return result;
}

cue_command_t TableSimNode::RequestPot(int id, const PotShot& pot,
                                       const std::vector<table::SceneBall>& balls,
                                       PotResult& result) {
  const Eigen::Vector2d cue_at = Find(balls, kCueBall)->state.head<2>();
  std::optional<Eigen::Vector2d> object;
  if (Find(balls, pot.ball) != balls.end()) object = Find(balls, pot.ball)->state.head<2>();
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
  return command;
}

PotResult TableSimNode::PlayPot(int id, const PotShot& pot, const table::TableGeometry& geometry,
                                std::vector<table::SceneBall>& balls, SceneResult& scene) {
  PotResult result;
  result.asked = pot;
  const cue_command_t command = RequestPot(id, pot, balls, result);
  const table::TableSimulation sim = PlayOut(geometry, balls, command, SceneMotion(plant_));
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
    const int8_t own_class = TruthClass(ball.id);
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

}  // namespace billiard::table_sim_node
