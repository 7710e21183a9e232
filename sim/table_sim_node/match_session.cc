// TableSimNode's matches (RunGame with TableSimOptions::players): two players at one table, the
// planner answering for both. The rack is refereed as `billiard match` referees it
// (sim/rules/rack_state.h: whose turn, ball in hand, the fouls in a row, eight-ball's groups and
// calls), rack k broken by player k % 2 with the game's stored break (asked of the planner,
// shot_request_t::MODE_BREAK), and every other shot the choice of the player at the table, named
// in its request. What the table does with each stroke, and the estimator's view scored, are
// game_session.cc's.
#include <algorithm>

#include "lcmtypes/names.h"
#include "sim/rules/rack_state.h"
#include "sim/rules/rules.h"
#include "sim/table/rack.h"
#include "sim/table_sim_node/session_balls.h"
#include "sim/table_sim_node/table_sim_node.h"

namespace billiard::table_sim_node {

namespace {

// The planner's reason when a request names a player it has not (planner_node's PlayerFor).
constexpr char kUnknownPlayer[] = "unknown player";

// A ruleset as the request names it (shot_request_t::RULES_*).
int8_t RulesCode(rules::Rules r) { return messages::ShotRulesCode(rules::RulesName(r)); }

// What shot `shot` of the rack `state` is asks the planner: the game's break, or the shooter's
// choice under its own ruleset (its group's, under eight-ball), decided by `player`.
shot_request_t MatchRequest(const rules::RackState& state, const GameShot& shot,
                            const std::string& player) {
  if (!shot.break_shot) return ChoiceRequest(RulesCode(state.rules[state.shooter]), shot, player);
  shot_request_t ask{};
  ask.ball_id = shot_request_t::BALL_BY_CLASS;
  ask.ball_class = ball_state_t::CLASS_CUE;
  ask.mode = shot_request_t::MODE_BREAK;
  ask.rules = RulesCode(state.game);
  return ask;
}

// A shot the planner refused, judged: no stroke reached the ball (a miscue, a foul), so the
// table goes to the other player with ball in hand.
void JudgeRefusal(const rules::Constraints& constraints, const std::vector<table::SceneBall>& balls,
                  const Judge& judge, GameShot* shot) {
  rules::Shot refused;
  refused.constraints = constraints;
  refused.break_shot = shot->break_shot;
  refused.struck = false;
  refused.object_balls_left = static_cast<int>(rules::ObjectBalls(balls).size());
  const rules::Judgement judged = judge(refused);
  shot->foul = judged.foul;
  shot->foul_reason = judged.foul_reason;
}

}  // namespace

GameResult TableSimNode::PlayMatchRack(int rack, const table::TableGeometry& geometry, int* id) {
  const bool eight_ball = options_.game == "eight-ball";
  GameResult game;
  game.seed = options_.seed + static_cast<std::uint32_t>(rack);
  game.breaker = rack % 2;
  std::vector<table::SceneBall> balls =
      table::Rack(eight_ball ? table::RackKind::kEightBall : table::RackKind::kNineBall, geometry,
                  params_.ball.radius, game.seed);
  log_("rack " + std::to_string(rack) + " (" + options_.game + ", seed " +
       std::to_string(game.seed) + "), " + options_.players[game.breaker] + " breaks");
  for (int k = 0; k < kNewLayoutSettles; ++k) ShowAtRest(balls);
  rules::RackState state = rules::NewRack(
      eight_ball ? rules::Rules::kEightBall : rules::Rules::kNineBall, game.breaker);
  const Judge referee = [&](const rules::Shot& s) { return rules::Referee(geometry, s, &state); };
  int visit = 1;
  // shot_limit bounds the attempts, as a rack played alone does (PlayRack).
  for (int n = 0; n < options_.shot_limit && !state.over; ++n) {
    GameShot shot;
    shot.number = static_cast<int>(game.shots.size()) + 1;
    shot.visit = visit;
    shot.player = state.shooter;
    shot.break_shot = state.shots == 0;
    shot.ball_in_hand = state.ball_in_hand;
    const rules::Constraints constraints = rules::NextConstraints(state, balls);
    bool rack_over = false;
    shot = PlayGameShot((*id)++, shot, MatchRequest(state, shot, options_.players[state.shooter]),
                        constraints, referee, geometry, balls, &rack_over);
    if (shot.status == messages::CueCommandStatusName(cue_command_t::STATUS_NOT_AT_REST)) {
      health_.Count("shot_not_at_rest");
      continue;
    }
    if (shot.reason.rfind(kUnknownPlayer, 0) == 0) throw UnknownPlayer(shot.reason);
    if (shot.status != messages::CueCommandStatusName(cue_command_t::STATUS_OK)) {
      JudgeRefusal(constraints, balls, referee, &shot);
    }
    game.visits = visit;
    game.shots.push_back(shot);
    if (!state.over && state.shooter != shot.player) ++visit;
  }
  game.cleared = state.over;
  game.winner = state.over ? state.winner : -1;
  game.reason = state.over ? state.reason : "shot limit";
  game.break_and_run = state.over && state.winner == game.breaker &&
                       std::all_of(game.shots.begin(), game.shots.end(),
                                   [&](const GameShot& s) { return s.player == game.breaker; });
  log_("rack " + std::to_string(rack) + ": " +
       (game.winner < 0 ? std::string("undecided") : options_.players[game.winner] + " wins") +
       " (" + game.reason + ") in " + std::to_string(game.shots.size()) + " shots, " +
       std::to_string(game.visits) + " visits");
  return game;
}

}  // namespace billiard::table_sim_node
