#include "sim/rules/rules.h"

#include <gtest/gtest.h>

namespace billiard::rules {
namespace {

TEST(RulesTest, NamesRoundTrip) {
  for (Rules rules : {Rules::kAny, Rules::kNineBall, Rules::kEightBall, Rules::kEightBallSolids,
                      Rules::kEightBallStripes}) {
    EXPECT_EQ(ParseRules(RulesName(rules)), rules);
    EXPECT_STREQ(RulesetOf(rules).Name(), RulesName(rules));
  }
  EXPECT_STREQ(RulesName(Rules::kNineBall), "nine-ball");
  EXPECT_STREQ(RulesName(Rules::kAny), "any");
  EXPECT_STREQ(RulesName(Rules::kEightBall), "eight-ball");
  EXPECT_FALSE(ParseRules("snooker"));
  EXPECT_FALSE(ParseRules("Nine-Ball"));
}

TEST(RulesTest, LegalTargetsAreTheGamesOwn) {
  std::vector<table::SceneBall> balls(4);
  balls[1].id = 6;
  balls[2].id = 2;
  balls[3].id = 9;
  EXPECT_EQ(LegalTargets(Rules::kAny, balls), (std::vector<int>{2, 6, 9}));
  EXPECT_EQ(LegalTargets(Rules::kNineBall, balls), (std::vector<int>{2}));
  EXPECT_EQ(LegalTargets(Rules::kEightBall, balls), (std::vector<int>{2, 6, 9}));
  EXPECT_EQ(LegalTargets(Rules::kEightBallStripes, balls), (std::vector<int>{9}));
}

TEST(RulesTest, EightBallIsTheOpenTableAndEitherGroup) {
  EXPECT_TRUE(IsEightBall(Rules::kEightBall));
  EXPECT_TRUE(IsEightBall(Rules::kEightBallSolids));
  EXPECT_TRUE(IsEightBall(Rules::kEightBallStripes));
  EXPECT_FALSE(IsEightBall(Rules::kNineBall));
  EXPECT_FALSE(IsEightBall(Rules::kAny));
}

TEST(RulesTest, OneRulesetPerGame) {
  EXPECT_EQ(&RulesetOf(Rules::kNineBall), &RulesetOf(Rules::kNineBall));
  EXPECT_NE(&RulesetOf(Rules::kNineBall), &RulesetOf(Rules::kAny));
}

}  // namespace
}  // namespace billiard::rules
