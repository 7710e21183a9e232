#include "sim/rules/rules.h"

#include "sim/rules/any.h"
#include "sim/rules/eight_ball.h"
#include "sim/rules/nine_ball.h"

namespace billiard::rules {

namespace {

constexpr Rules kEveryRules[] = {Rules::kAny, Rules::kNineBall, Rules::kEightBall,
                                 Rules::kEightBallSolids, Rules::kEightBallStripes};

}  // namespace

const Ruleset& RulesetOf(Rules rules) {
  static const AnyBall any;
  static const NineBall nine_ball;
  static const EightBall open(Group::kOpen), solids(Group::kSolids), stripes(Group::kStripes);
  switch (rules) {
    case Rules::kAny: return any;
    case Rules::kNineBall: return nine_ball;
    case Rules::kEightBall: return open;
    case Rules::kEightBallSolids: return solids;
    case Rules::kEightBallStripes: return stripes;
  }
  return any;
}

bool IsEightBall(Rules rules) {
  return rules == Rules::kEightBall || rules == Rules::kEightBallSolids ||
         rules == Rules::kEightBallStripes;
}

const char* RulesName(Rules rules) { return RulesetOf(rules).Name(); }

std::optional<Rules> ParseRules(const std::string& name) {
  for (Rules rules : kEveryRules) {
    if (name == RulesName(rules)) return rules;
  }
  return std::nullopt;
}

std::vector<int> LegalTargets(Rules rules, const std::vector<table::SceneBall>& balls) {
  return RulesetOf(rules).LegalTargets(balls);
}

}  // namespace billiard::rules
