#include "planner/pot/position.h"

#include <gtest/gtest.h>

#include "planner/pot/testing/pot_fixture.h"

namespace billiard::pot {
namespace {

using table::SceneBall;

class PositionTest : public testing::PotFixture {
 protected:
  const std::vector<SceneBall> balls_ = {table::AtRest(0, 0.6, 0.6), table::AtRest(1, 1.8, 0.9), table::AtRest(2, 1.2, 0.3)};

  // Where the pot played with more pace (an arrival speed of 1 m/s at the pocket, not 0.6) leaves
  // the cue ball: a target it can reach by construction.
  Eigen::Vector2d Reachable() const {
    PotOptions firmer;
    firmer.arrival_speed = 1.0;
    const PotPlan firm = PlanPot(table_, params_, balls_, {1, "upper_right", ShotKind::kDirect, {}}, firmer);
    EXPECT_EQ(firm.status, PotStatus::kOk) << firm.reason;
    return firm.cue_rest;
  }
};

TEST_F(PositionTest, PositionPlayStopsTheCueBallAtTheTarget) {
  const Eigen::Vector2d target = Reachable();
  const PotPlan plan = PlanPot(table_, params_, balls_, {1, "upper_right", ShotKind::kDirect, CueTarget{target, 0.0}});
  ExpectLegalPot(balls_, plan);
  EXPECT_LT((plan.cue_rest - target).norm(), 0.01);
}

// A target with a radius is met anywhere within it.
TEST_F(PositionTest, ATargetsRadiusIsItsTolerance) {
  const Eigen::Vector2d target = Reachable() + Eigen::Vector2d(0.03, 0.0);
  const PotPlan plan = PlanPot(table_, params_, balls_, {1, "upper_right", ShotKind::kDirect, CueTarget{target, 0.05}});
  ExpectLegalPot(balls_, plan);
  EXPECT_LE((plan.cue_rest - target).norm(), 0.05);
}

// A corner the cue ball cannot be left in from this pot: refused, saying how near it came, with
// side spin tried too.
TEST_F(PositionTest, AnUnreachableTargetSaysHowNearTheCueBallCame) {
  const PotPlan far = PlanPot(table_, params_, balls_, {1, "upper_right", ShotKind::kDirect, CueTarget{{0.1, 1.2}, 0.0}});
  EXPECT_EQ(far.status, PotStatus::kTargetUnreachable) << far.reason;
  EXPECT_NE(far.reason.find("the cue ball stops at best "), std::string::npos) << far.reason;
  EXPECT_NE(far.reason.find("(with side spin too)"), std::string::npos) << far.reason;
}

}  // namespace
}  // namespace billiard::pot
