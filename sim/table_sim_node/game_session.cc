// TableSimNode's games (RunGame, table_sim_node.h): racks played shot by shot, each shot chosen
// by the planner, executed, judged under nine-ball rules (sim/rules/nine_ball.h, the ruleset the
// planner's own games are judged by), and the estimator's
// view at each decision scored against the truth.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "lcmtypes/message_checks.h"
#include "lcmtypes/names.h"
#include "sim/params/table_specs.h"
#include "sim/rules/rules.h"
#include "sim/table/rack.h"
#include "sim/table/rail_contacts.h"
#include "sim/table_sim_node/session_balls.h"
#include "sim/table_sim_node/stroke_execution.h"
#include "sim/table_sim_node/table_sim_node.h"

namespace billiard::table_sim_node {

namespace {

// The called ball: the truth ball nearest the track the planner named, `called` where the
// estimate has no such track.
int CalledBall(const table_state_t& estimate, std::int32_t track_id,
               const std::vector<table::SceneBall>& balls, int called) {
  for (const ball_state_t& track : estimate.balls) {
    if (track.ball_id != track_id) continue;
    double nearest = 1e300;
    for (const table::SceneBall& b : balls) {
      const double d = std::hypot(track.position[0] - b.state[physics::kX],
                                  track.position[1] - b.state[physics::kY]);
      if (b.id != kCueBall && d < nearest) {
        nearest = d;
        called = b.id;
      }
    }
  }
  return called;
}

// Ball in hand: `balls` with the cue ball where the planner says, `asked`; on another ball (the
// estimator's error), the nearest free place toward the head rail. Where it went into *placed.
std::vector<table::SceneBall> WithCueBallPlaced(const table::TableGeometry& geometry, double radius,
                                                const std::vector<table::SceneBall>& balls,
                                                const Eigen::Vector2d& asked,
                                                Eigen::Vector2d* placed) {
  std::vector<table::SceneBall> others;
  for (const table::SceneBall& b : balls) {
    if (b.id != kCueBall) others.push_back(b);
  }
  *placed = table::FreeSpotFrom(geometry, radius, others, asked, {-kPlacementStep, 0.0}, 0.0);
  return table::WithBallAt(others, kCueBall, *placed);
}

// The log's line of a game shot played.
std::string GameShotLine(const GameShot& shot) {
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
  return line.str();
}

}  // namespace

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
    shot.misidentified += nearest->ball_class != TruthClass(b.id);
  }
  const int tracked = static_cast<int>(balls.size()) - shot.untracked;
  if (tracked > 0) shot.position_rms_mm = 1e3 * std::sqrt(sum / tracked);
}

shot_request_t ChoiceRequest(int8_t rules, const GameShot& shot, const std::string& player) {
  shot_request_t ask{};
  ask.ball_id = shot_request_t::BALL_BY_CLASS;
  ask.ball_class = ball_state_t::CLASS_CUE;
  ask.mode = shot_request_t::MODE_CHOOSE;
  ask.rules = rules;
  ask.ball_in_hand = shot.ball_in_hand ? 1 : 0;
  ask.player = player;
  ask.alone = player.empty() ? 1 : 0;
  return ask;
}

cue_command_t TableSimNode::RequestGameShot(int id, const GameShot& shot,
                                            const shot_request_t& ask,
                                            const std::vector<table::SceneBall>& balls) {
  ShotResult asked;
  if (shot.break_shot && ask.mode != shot_request_t::MODE_BREAK) {
    return RequestBreak(id, balls, asked);
  }
  return Request(id, balls, Find(balls, kCueBall)->state.head<2>(), ask, asked);
}

GameShot TableSimNode::PlayGameShot(int id, GameShot shot, const shot_request_t& ask,
                                    const rules::Constraints& constraints, const Judge& judge,
                                    const table::TableGeometry& geometry,
                                    std::vector<table::SceneBall>& balls, bool* rack_over) {
  const double radius = params_.ball.radius;
  const cue_command_t command = RequestGameShot(id, shot, ask, balls);
  ScoreEstimate(balls, shot);
  shot.status = messages::CueCommandStatusName(command.status);
  shot.reason = command.reason;
  shot.decision_ms = 1e-3 * command.solve_us;
  if (command.status != cue_command_t::STATUS_OK) {
    log_("shot " + std::to_string(shot.number) + " refused: " + shot.status + ", " + shot.reason);
    return shot;
  }
  if (!shot.break_shot && command.object_ball_id >= 0) {
    shot.called = CalledBall(*state_, command.object_ball_id, balls, shot.called);
    shot.pocket = command.pocket;
    shot.kind = messages::PotKindName(command.kind);
    shot.predicted = command.success_probability;
  }
  shot.safety = command.safety != 0;
  rules::Shot played;
  played.constraints = constraints;
  played.break_shot = shot.break_shot;
  played.call = {shot.called, shot.pocket};
  if (command.has_cue_placement) {
    Eigen::Vector2d placed;
    balls = WithCueBallPlaced(geometry, radius, balls,
                              {command.cue_placement[0], command.cue_placement[1]}, &placed);
    shot.cue_placement = placed;
  }
  const table::TableSimulation sim = PlayOut(geometry, balls, command, SceneMotion(plant_));
  shot.first_contact = table::FirstBallMet(sim.events(), kCueBall);
  TableOutcome outcome = OutcomeOf(sim, geometry, shot.called, shot.pocket);
  shot.potted = outcome.potted;
  played.first_contact = shot.first_contact;
  played.to_rail_after_contact = table::BallsToRailAfterFirstContact(sim.events(), kCueBall);
  played.potted = outcome.potted;
  played.pockets = outcome.pockets;
  played.scratch = outcome.scratch;
  played.object_balls_left = static_cast<int>(rules::ObjectBalls(outcome.rest).size());
  const rules::Judgement judged = judge(played);
  shot.foul = judged.foul;
  shot.foul_reason = judged.foul_reason;
  shot.called_potted = outcome.called_potted && judged.legal();
  *rack_over = judged.rack_over;
  rules::PlaceRespotted(geometry, radius, judged.respots, kPlacementStep, kPlacementClearance,
                        &outcome.rest);
  if (outcome.scratch) outcome.rest = InTheKitchen(geometry, radius, std::move(outcome.rest));
  balls = std::move(outcome.rest);
  log_(GameShotLine(shot));
  return shot;
}

GameResult TableSimNode::PlayRack(int rack, const table::TableGeometry& geometry, int* id) {
  const double radius = params_.ball.radius;
  GameResult game;
  game.seed = options_.seed + static_cast<std::uint32_t>(rack);
  const bool drill = options_.game == "drill";
  std::vector<table::SceneBall> balls =
      drill
          ? InTheKitchen(geometry, radius, table::SeededNineBallLayout(geometry, radius, game.seed))
          : table::Rack(table::RackKind::kNineBall, geometry, radius, game.seed);
  log_("rack " + std::to_string(rack) + " (" + options_.game + ", seed " +
       std::to_string(game.seed) + ")");
  // The new layout shown until the estimator has forgotten the last one's balls.
  for (int k = 0; k < kNewLayoutSettles; ++k) ShowAtRest(balls);
  bool ball_in_hand = drill, rack_over = false;
  int visit = 1;
  // Alone at the table, every shot judged by nine-ball's ruleset: the visit's end is the next
  // one's start, and nobody's fouls in a row end the rack.
  const rules::Ruleset& nine_ball = rules::RulesetOf(rules::Rules::kNineBall);
  const Judge judge = [&](const rules::Shot& s) { return nine_ball.Judge(geometry, s); };
  // shot_limit bounds the attempts: a request the planner held past its wait for the table to
  // rest (its retries too) played nothing, so it is neither a shot nor a visit.
  for (int n = 0; n < options_.shot_limit; ++n) {
    GameShot shot;
    shot.number = static_cast<int>(game.shots.size()) + 1;
    shot.visit = visit;
    shot.break_shot = !drill && game.shots.empty();
    shot.ball_in_hand = ball_in_hand;
    shot = PlayGameShot((*id)++, shot, ChoiceRequest(shot_request_t::RULES_NINE_BALL, shot, ""),
                        {ball_in_hand, nine_ball.LegalTargets(balls)}, judge, geometry, balls,
                        &rack_over);
    if (shot.status == messages::CueCommandStatusName(cue_command_t::STATUS_NOT_AT_REST)) {
      health_.Count("shot_not_at_rest");
      continue;
    }
    game.visits = visit;
    game.shots.push_back(shot);
    if (rack_over) {
      game.cleared = true;
      break;
    }
    ball_in_hand = shot.foul;
    if (shot.foul || shot.potted.empty()) ++visit;
  }
  log_("rack " + std::to_string(rack) + (game.cleared ? " cleared" : " not cleared") + " in " +
       std::to_string(game.shots.size()) + " shots, " + std::to_string(game.visits) + " visits");
  return game;
}

std::vector<GameResult> TableSimNode::RunGame() {
  AwaitPeersOfTheSameBuildAndPhysics();
  const table::TableGeometry geometry =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  health_.Set(messages::kRealtimeClockSetting, options_.lockstep ? 0 : 1);
  health_.Publish(lcm_);
  std::vector<GameResult> games;
  int id = 0;  // request ids, unique over the session
  for (int rack = 0; rack < options_.racks; ++rack) {
    games.push_back(options_.players.empty() ? PlayRack(rack, geometry, &id)
                                             : PlayMatchRack(rack, geometry, &id));
  }
  health_.PublishIfDue(lcm_);
  return games;
}

}  // namespace billiard::table_sim_node
