#include "planner/pot/truth.h"

#include <gtest/gtest.h>

#include <cmath>

#include "planner/pot/lone_path.h"
#include "planner/pot/testing/pot_fixture.h"

namespace billiard::pot {
namespace {

using table::SceneBall;

class TruthTest : public testing::PotFixture {
 protected:
  TruthTest() : balls_({table::AtRest(0, 0.6, 0.6), table::AtRest(1, 1.8, 0.9), table::AtRest(2, 1.2, 0.3)}), search_(Search(balls_, 1, "upper_right")) {
    route_ = Routes(search_, ShotKind::kDirect).front().route;
    search_.SearchAmong(NearRoute(search_, route_), false);
  }

  // The search's aim at the middle of K's drop window on its direct route (steps 1, 2 and 4).
  void AimOnTheSearch() {
    const double line = Angle(route_.object_aim - Eigen::Vector2d(1.8, 0.9));
    std::optional<Aimed> aimed = AimAt(search_, shape_, FirstHeading(search_, route_, shape_, route_.cue_aim), line,
                                       false, 0.0);
    ASSERT_TRUE(aimed);
    const std::optional<Drop> drop = DropWindow(search_, aimed->contact, line, kDirectScan, 0.0, kWindowResolution);
    ASSERT_TRUE(drop);
    drop_ = *drop;
    aimed = AimAt(search_, shape_, aimed->heading, drop_.Middle(), false, aimed->slope);
    ASSERT_TRUE(aimed);
    aimed_ = *aimed;
  }

  const std::vector<SceneBall> balls_;
  SearchContext search_;
  Route route_;
  const StrokeShape shape_{1.5, 0.0, 0.0, 0.0};
  Aimed aimed_;
  Drop drop_;
};

// The search's plan re-aimed on the truth pots legally, as `simulate --scene` replays it, and K
// leaves along the window's middle there too.
TEST_F(TruthTest, TheSearchsPlanReaimedOnTheTruthPotsLegally) {
  AimOnTheSearch();
  const std::variant<TruthShot, Refusal> truth = PlayOnTheTruth(search_, route_, shape_, aimed_, drop_, std::nullopt);
  ASSERT_TRUE(std::holds_alternative<TruthShot>(truth)) << std::get<Refusal>(truth).reason;
  const TruthShot& shot = std::get<TruthShot>(truth);
  EXPECT_TRUE(shot.played.outcome.legal);
  EXPECT_EQ(shot.stroke.heading, shot.aimed.heading);
  EXPECT_NEAR(Wrap(shot.aimed.contact.departure - shot.window.Middle()), 0.0, kAimAccepted);
  EXPECT_NE(shot.aimed.heading, aimed_.heading) << "the truth meets K a little differently";
  const Outcome replay = SimulateStroke(balls_, shot.stroke, 1, "upper_right");
  EXPECT_TRUE(replay.potted);
  EXPECT_EQ(replay.first_contact, 1);
  EXPECT_FALSE(replay.scratch);
  EXPECT_NEAR((replay.cue_rest - shot.played.outcome.cue_rest).norm(), 0.0, 1e-9);
}

// What the plan says of the truth's shot: its launch is the stroke's, and each moving ball's path
// runs from where it lay to where it rests or drops.
TEST_F(TruthTest, TheShotsDescriptionFollowsEachMovingBall) {
  AimOnTheSearch();
  const std::variant<TruthShot, Refusal> truth = PlayOnTheTruth(search_, route_, shape_, aimed_, drop_, std::nullopt);
  ASSERT_TRUE(std::holds_alternative<TruthShot>(truth));
  const TruthShot& shot = std::get<TruthShot>(truth);
  PotPlan plan;
  DescribeShot(shot, 0.02, &plan);
  const physics::BallState launch = physics::StrikeBall(shot.stroke, {0.6, 0.6}, params_);
  EXPECT_NEAR((plan.v0 - launch.segment<2>(physics::kVx)).norm(), 0.0, 1e-12);
  EXPECT_EQ(plan.departure, shot.window.Middle());
  EXPECT_GT(plan.cut_deg, 0.0);
  EXPECT_LT(plan.cut_deg, 80.0);
  EXPECT_FALSE(plan.events.empty());
  ASSERT_GE(plan.paths.size(), 2u);
  for (const BallPath& path : plan.paths) {
    ASSERT_GE(path.points.size(), 2u);
    const Eigen::Vector2d start = balls_[static_cast<std::size_t>(path.id)].state.head<2>();
    EXPECT_NEAR((path.points.front() - start).norm(), 0.0, 1e-12) << path.id;
  }
  EXPECT_EQ(plan.paths.front().id, 0);
  EXPECT_NEAR((plan.paths.front().points.back() - plan.cue_rest).norm(), 0.0, 1e-12);
  const table::Pocket& pocket = *table_.PocketNamed("upper_right");
  ASSERT_EQ(plan.paths[1].id, 1);
  const Eigen::Vector2d dropped = plan.paths[1].points.back();
  EXPECT_NEAR((dropped - pocket.capture_a).dot(pocket.inward), 0.0, 1e-9) << "K ends on the capture line";
}

// Position play's truth aim is played as it is, not aimed again.
TEST_F(TruthTest, APlacedAimIsPlayedAsItIs) {
  AimOnTheSearch();
  const std::optional<Aimed> placed = AimAt(search_, shape_, aimed_.heading, drop_.Middle(), true, aimed_.slope);
  ASSERT_TRUE(placed);
  Aimed turned = *placed;
  turned.heading += 1e-4;
  const std::variant<TruthShot, Refusal> truth = PlayOnTheTruth(search_, route_, shape_, aimed_, drop_, turned);
  ASSERT_TRUE(std::holds_alternative<TruthShot>(truth));
  EXPECT_EQ(std::get<TruthShot>(truth).stroke.heading, turned.heading);
}

TEST_F(TruthTest, AnIllegalOutcomeIsToldInWords) {
  PotOutcome o;
  EXPECT_EQ(Illegal(search_, o), "the cue ball touches no ball");
  o.first_contact = 2;
  EXPECT_EQ(Illegal(search_, o), "the cue ball touches ball 2 first");
  o.first_contact = 1;
  o.cue_pocket = "upper_middle";
  EXPECT_EQ(Illegal(search_, o), "the cue ball follows into upper_middle (a scratch)");
  o.cue_pocket.reset();
  EXPECT_EQ(Illegal(search_, o), "ball 1 does not drop in upper_right");
}

}  // namespace
}  // namespace billiard::pot
