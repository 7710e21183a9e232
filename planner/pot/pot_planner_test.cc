#include "planner/pot/pot_planner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "planner/pot/testing/pot_fixture.h"
#include "planner/pot/testing/pot_layouts.h"

namespace billiard::pot {
namespace {

using table::SceneBall;

class PotPlannerTest : public testing::PotFixture {};

TEST_F(PotPlannerTest, ADirectCutPotsWhenItsLaunchIsSimulated) {
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.6, 0.6), table::AtRest(1, 1.8, 0.9), table::AtRest(2, 1.2, 0.3)};
  for (const char* pocket : {"upper_right", "lower_right", "upper_middle_not"}) {
    PotRequest request{1, pocket, ShotKind::kDirect, std::nullopt};
    const PotPlan plan = PlanPot(table_, params_, balls, request);
    if (std::string(pocket) == "upper_middle_not") {
      EXPECT_EQ(plan.status, PotStatus::kNoSuchPocket);
      continue;
    }
    SCOPED_TRACE(pocket);
    ExpectLegalPot(balls, plan);
    EXPECT_EQ(plan.kind, ShotKind::kDirect);
    EXPECT_GT(plan.margin_left_deg, 0.0);
    EXPECT_GT(plan.margin_right_deg, 0.0);
    EXPECT_LE(plan.speed_lo, plan.stroke.speed);
    EXPECT_GE(plan.speed_hi, plan.stroke.speed);
  }
}

// A straight-in shot along the corner pocket's diagonal: the table, the jaws and the balls are
// symmetric about that line, so the aim is along it and the margin the same either side.
TEST_F(PotPlannerTest, AStraightInShotAlongTheDiagonalAimsAlongItWithAnEvenMargin) {
  const Eigen::Vector2d corner = table_.PocketNamed("lower_left")->centre;
  const Eigen::Vector2d along = Eigen::Vector2d(1.0, 1.0).normalized();
  const Eigen::Vector2d k = corner + 0.6 * along, cue = corner + 1.2 * along;
  const std::vector<SceneBall> balls = {table::AtRest(0, cue.x(), cue.y()), table::AtRest(3, k.x(), k.y())};
  const PotPlan plan = PlanPot(table_, params_, balls, {3, "lower_left", ShotKind::kDirect, {}});
  ExpectLegalPot(balls, plan);
  EXPECT_NEAR(std::remainder(plan.stroke.heading - std::atan2(-along.y(), -along.x()), 2 * M_PI), 0.0, 1e-5);
  EXPECT_NEAR(plan.cut_deg, 0.0, 1e-3);
  EXPECT_NEAR(plan.margin_left_deg / plan.margin_right_deg, 1.0, 0.05);
}

// The table is symmetric about its long axis: the mirrored layout gets the mirrored plan.
TEST_F(PotPlannerTest, TheMirroredLayoutGetsTheMirroredPlan) {
  const double w = table_.width;
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.7, 0.45), table::AtRest(5, 1.6, 0.85), table::AtRest(7, 2.0, 0.3)};
  std::vector<SceneBall> mirrored = balls;
  for (SceneBall& b : mirrored) b.state.y() = w - b.state.y();
  const PotPlan plan = PlanPot(table_, params_, balls, {5, "upper_right", ShotKind::kDirect, {}});
  const PotPlan image = PlanPot(table_, params_, mirrored, {5, "lower_right", ShotKind::kDirect, {}});
  ASSERT_EQ(plan.status, PotStatus::kOk) << plan.reason;
  ASSERT_EQ(image.status, PotStatus::kOk) << image.reason;
  EXPECT_NEAR(std::remainder(plan.stroke.heading + image.stroke.heading, 2 * M_PI), 0.0, 1e-5);
  EXPECT_NEAR(plan.stroke.speed, image.stroke.speed, 1e-3 * plan.stroke.speed);
  EXPECT_NEAR(plan.margin_left_deg, image.margin_right_deg, 0.05 * plan.margin_left_deg);
  EXPECT_NEAR(plan.margin_right_deg, image.margin_left_deg, 0.05 * plan.margin_right_deg);
  EXPECT_NEAR(plan.cue_rest.x(), image.cue_rest.x(), 1e-3);
  EXPECT_NEAR(plan.cue_rest.y(), w - image.cue_rest.y(), 1e-3);
}

TEST_F(PotPlannerTest, ABlockedLineIsRefusedNamingTheBlocker) {
  // Ball 2 sits on the straight line from ball 1 to the lower right pocket.
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.5, 0.4), table::AtRest(1, 1.6, 0.7), table::AtRest(2, 2.05, 0.38)};
  const PotPlan direct = PlanPot(table_, params_, balls, {1, "lower_right", ShotKind::kDirect, {}});
  EXPECT_EQ(direct.status, PotStatus::kBlocked);
  EXPECT_NE(direct.reason.find("blocked by ball 2"), std::string::npos) << direct.reason;
  // Any kind: a kick off the lower rail makes the middle pocket the straight line cannot.
  const PotPlan any = PlanPot(table_, params_, balls, {1, "lower_middle", std::nullopt, {}});
  ExpectLegalPot(balls, any);
  EXPECT_EQ(any.kind, ShotKind::kKick);
  EXPECT_NE(any.why.find("direct: the cut is"), std::string::npos) << any.why;
}

// Seeded layouts whose straight line is blocked (bench-pot's seeds 2047 and 2042): a bank and a
// kick, asked for by kind.
TEST_F(PotPlannerTest, BanksAndKicksPotWhenTheirLaunchIsSimulated) {
  for (const auto& [seed, kind] : {std::pair{std::uint64_t{2047}, ShotKind::kBank}, {2042, ShotKind::kKick}}) {
    const testing::PotLayout layout = testing::SeededPotLayout(table_, params_.ball.radius, seed);
    PotRequest request = layout.request;
    request.kind = kind;
    const PotPlan plan = PlanPot(table_, params_, layout.balls, request);
    SCOPED_TRACE(ShotKindName(kind));
    ExpectLegalPot(layout.balls, plan);
    EXPECT_EQ(plan.kind, kind);
    EXPECT_GE(plan.rail, 0);
    const auto rail_events = std::count_if(plan.events.begin(), plan.events.end(), [&](const table::TableEvent& e) {
      return e.type == table::EventType::kBallCushion && e.ball == (kind == ShotKind::kBank ? plan.ball : 0) &&
             e.cushion == plan.rail;
    });
    EXPECT_GE(rail_events, 1) << "the route's rail is met";
  }
}

// A bank's margin walked only to a cap (as the choice ranks plans) is told as at least the cap,
// not as the margin: the walk stopped there. Walked in full, the margin itself.
TEST_F(PotPlannerTest, ABanksWhySaysACappedMarginIsAtLeastTheCap) {
  const testing::PotLayout layout = testing::SeededPotLayout(table_, params_.ball.radius, 2047);
  PotRequest request = layout.request;
  request.kind = ShotKind::kBank;
  const PotPlan full = PlanPot(table_, params_, layout.balls, request);
  ASSERT_EQ(full.status, PotStatus::kOk) << full.reason;
  EXPECT_EQ(full.why.find("at least"), std::string::npos) << full.why;
  PotOptions ranking;
  ranking.margin_cap = 0.02 * kDegree;
  const PotPlan capped = PlanPot(table_, params_, layout.balls, request, ranking);
  ASSERT_EQ(capped.status, PotStatus::kOk) << capped.reason;
  EXPECT_NE(capped.why.find("the widest margin (at least 0.02 deg)"), std::string::npos)
      << capped.why;
}

TEST_F(PotPlannerTest, BadRequestsAreRefusedWithAReason) {
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.6, 0.6), table::AtRest(1, 1.8, 0.9)};
  const auto refused = [&](const PotRequest& r, PotStatus status) {
    const PotPlan plan = PlanPot(table_, params_, balls, r);
    EXPECT_EQ(plan.status, status) << PotStatusName(plan.status) << ": " << plan.reason;
    EXPECT_FALSE(plan.reason.empty());
    EXPECT_EQ(plan.reason.find('\n'), std::string::npos);
  };
  refused({9, "upper_right", std::nullopt, {}}, PotStatus::kNoSuchBall);
  refused({0, "upper_right", std::nullopt, {}}, PotStatus::kNoSuchBall);
  refused({1, "upper_centre", std::nullopt, {}}, PotStatus::kNoSuchPocket);
  refused({1, "upper_right", std::nullopt, CueTarget{{NAN, 0.5}, 0.0}}, PotStatus::kInvalid);
  refused({1, "upper_right", std::nullopt, CueTarget{{5.0, 0.5}, 0.0}}, PotStatus::kTargetUnreachable);
  // Backwards: the pocket behind the object ball as the cue ball sees it.
  refused({1, "lower_left", ShotKind::kDirect, {}}, PotStatus::kTooThin);
  std::vector<SceneBall> nan_scene = balls;
  nan_scene[1].state.x() = NAN;
  const PotPlan plan = PlanPot(table_, params_, nan_scene, {1, "upper_right", std::nullopt, {}});
  EXPECT_EQ(plan.status, PotStatus::kInvalid);
  const std::vector<SceneBall> no_cue = {table::AtRest(1, 1.8, 0.9)};
  EXPECT_EQ(PlanPot(table_, params_, no_cue, {1, "upper_right", std::nullopt, {}}).status, PotStatus::kInvalid);
}

// Every ok plan of seeded layouts pots legally when its launch is simulated on its own.
TEST_F(PotPlannerTest, SeededLayoutsPlanOnlyPotsThatDrop) {
  int ok = 0;
  for (std::uint64_t seed = 100; seed < 120; ++seed) {
    const testing::PotLayout layout = testing::SeededPotLayout(table_, params_.ball.radius, seed, 2, 8);
    const PotPlan plan = PlanPot(table_, params_, layout.balls, layout.request);
    if (plan.status != PotStatus::kOk) continue;
    ++ok;
    SCOPED_TRACE(seed);
    ExpectLegalPot(layout.balls, plan);
  }
  EXPECT_GE(ok, 8);
}

}  // namespace
}  // namespace billiard::pot
