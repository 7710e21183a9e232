#include "planner/game/game_json.h"

#include <cmath>

namespace billiard::game {

namespace {

nlohmann::json PointOrNull(const std::optional<Eigen::Vector2d>& p) {
  return p ? nlohmann::json{p->x(), p->y()} : nlohmann::json(nullptr);
}

nlohmann::json SummaryJson(const GameSummary& m) {
  return {{"shots", m.shots},
          {"attempts", m.attempts},
          {"pots", m.pots},
          {"pots_per_attempt", m.pots_per_attempt()},
          {"fouls", m.fouls},
          {"visits", m.visits},
          {"balls_potted", m.balls_potted},
          {"balls_per_visit", m.visits ? double(m.balls_potted) / m.visits : 0.0},
          {"cleared", m.cleared},
          {"run_out", m.run_out},
          {"end", GameEndName(m.end)},
          {"end_reason", m.end_reason},
          {"median_decision_us", m.median_decision_us}};
}

}  // namespace

nlohmann::json CueStrokeJson(const physics::CueStroke& stroke) {
  return {{"speed", stroke.speed},
          {"heading", stroke.heading},
          {"tip_side", stroke.tip_side},
          {"tip_height", stroke.tip_height},
          {"elevation", stroke.elevation}};
}

nlohmann::json ClearanceJson(const cue::CueClearance& clearance) {
  nlohmann::json j = {{"clears", clearance.clears}, {"nearest", clearance.what}};
  if (clearance.nearest == cue::Obstacle::kBall) j["ball"] = clearance.ball;
  j["distance"] = std::isfinite(clearance.distance) ? nlohmann::json(clearance.distance)
                                                    : nlohmann::json(nullptr);
  if (std::isfinite(clearance.distance)) j["along"] = clearance.along;
  return j;
}

nlohmann::json ShotJson(const ShotRecord& s) {
  nlohmann::json j;
  j["shot"] = s.number;
  j["visit"] = s.visit;
  j["player"] = s.player;
  j["break"] = s.break_shot;
  j["ball_in_hand"] = s.ball_in_hand;
  j["cue_placement"] = PointOrNull(s.cue_placement);
  j["status"] = s.status;
  j["reason"] = s.reason;
  j["ball"] = s.ball;
  j["pocket"] = s.pocket;
  j["kind"] = s.kind;
  j["predicted"] = s.predicted;
  j["likely"] = s.likely;
  j["safety"] = s.safety;
  j["attempt_win"] = s.attempt_win;
  j["safety_win"] = s.safety_win;
  j["cue"] = s.stroke ? CueStrokeJson(*s.stroke) : nlohmann::json(nullptr);
  if (s.stroke && s.clearance) j["cue"]["clearance"] = ClearanceJson(*s.clearance);
  j["first_contact"] = s.first_contact;
  j["potted"] = s.potted;
  j["called_potted"] = s.called_potted;
  j["foul"] = s.foul;
  j["foul_reason"] = s.foul_reason;
  j["decision_us"] = s.decision_us;
  return j;
}

nlohmann::json GameJson(const GameRecord& game) {
  nlohmann::json shots = nlohmann::json::array();
  for (const ShotRecord& s : game.shots) shots.push_back(ShotJson(s));
  nlohmann::json left = nlohmann::json::array();
  for (const table::SceneBall& b : game.final_balls) left.push_back(b.id);
  return {{"shots", shots}, {"summary", SummaryJson(game.summary)}, {"balls_left", left}};
}

}  // namespace billiard::game
