#include "sim/rules/rack_state.h"

#include "sim/rules/eight_ball.h"

namespace billiard::rules {

namespace {

Rules RulesOfGroup(Group group) {
  switch (group) {
    case Group::kSolids: return Rules::kEightBallSolids;
    case Group::kStripes: return Rules::kEightBallStripes;
    case Group::kOpen: return Rules::kEightBall;
  }
  return Rules::kEightBall;
}

int Other(int player) { return 1 - player; }

// The rack's end: `winner` won it, for `reason`.
void End(int winner, std::string reason, RackState* rack) {
  rack->over = true;
  rack->winner = winner;
  rack->reason = std::move(reason);
}

// The fouls in a row of the shooter after `j`, and the rack lost when they reach the limit.
void CountFouls(const Judgement& j, int limit, RackState* rack) {
  int& fouls = rack->fouls_in_a_row[rack->shooter];
  fouls = j.foul ? fouls + 1 : 0;
  if (limit > 0 && fouls >= limit) {
    End(Other(rack->shooter), std::to_string(limit) + " fouls in a row", rack);
  }
}

}  // namespace

RackState NewRack(Rules game, int breaker) {
  RackState rack;
  rack.game = game;
  rack.rules = {game, game};
  rack.breaker = rack.shooter = breaker;
  return rack;
}

const Ruleset& ShooterRules(const RackState& rack) {
  return RulesetOf(rack.rules[rack.shooter]);
}

Constraints NextConstraints(const RackState& rack, const std::vector<table::SceneBall>& balls) {
  const Ruleset& ruleset = ShooterRules(rack);
  Constraints c;
  c.ball_in_hand = rack.ball_in_hand;
  c.legal_targets = ruleset.LegalTargets(balls);
  c.call_required = ruleset.CallsShots() && rack.shots > 0;
  c.push_out_allowed = ruleset.PushOutAfterBreak() && rack.shots == 1;
  return c;
}

Judgement Referee(const table::TableGeometry& table, const Shot& shot, RackState* rack) {
  const Ruleset& ruleset = ShooterRules(*rack);
  const Judgement j = ruleset.Judge(table, shot);
  ++rack->shots;
  rack->may_pass = false;
  rack->ball_in_hand = j.ball_in_hand;
  CountFouls(j, ruleset.FoulsThatLose(), rack);
  if (rack->over) return j;
  if (j.rack_over) {
    End(j.shooter_wins ? rack->shooter : Other(rack->shooter), j.rack_reason, rack);
    return j;
  }
  if (j.group_ball >= 0) {
    const Group taken = GroupOf(j.group_ball);
    rack->rules[rack->shooter] = RulesOfGroup(taken);
    rack->rules[Other(rack->shooter)] = RulesOfGroup(OtherGroup(taken));
  }
  if (j.turn_over) {
    rack->shooter = Other(rack->shooter);
    rack->may_pass = j.opponent_may_pass;
  }
  return j;
}

void PassBack(RackState* rack) {
  rack->shooter = Other(rack->shooter);
  rack->may_pass = false;
}

}  // namespace billiard::rules
