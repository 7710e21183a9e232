#include "planner/pot/pace.h"

#include <gtest/gtest.h>

#include <cmath>

#include "planner/pot/testing/pot_fixture.h"

namespace billiard::pot {
namespace {

using table::SceneBall;

class PaceTest : public testing::PotFixture {
 protected:
  // A straight-in pot along the lower left corner pocket's diagonal, the cue ball 0.6 m behind K:
  // full ball, no throw, so one heading pots at every speed.
  PaceTest()
      : corner_(table_.PocketNamed("lower_left")->centre),
        along_(Eigen::Vector2d(1.0, 1.0).normalized()),
        balls_({table::AtRest(0, corner_.x() + 1.2 * along_.x(), corner_.y() + 1.2 * along_.y()),
                table::AtRest(3, corner_.x() + 0.6 * along_.x(), corner_.y() + 0.6 * along_.y())}) {}

  const Eigen::Vector2d corner_, along_;
  const std::vector<SceneBall> balls_;
};

// K's energy at the pocket grows with the cue ball's: the arrival speed with the cue speed; and
// it is less than the cue ball's at launch (an impact and the cloth only take energy).
TEST_F(PaceTest, TheArrivalSpeedGrowsWithTheCueSpeed) {
  SearchContext search = Search(balls_, 3, "lower_left");
  double last = 0.0;
  for (double speed : {0.8, 1.2, 1.6, 2.4, 3.2}) {
    const Played played = search.Play({speed, Angle(-along_), 0.0, 0.0, 0.0}, false, false);
    ASSERT_TRUE(played.arrival_speed) << speed;
    EXPECT_GT(*played.arrival_speed, last) << speed;
    EXPECT_LT(*played.arrival_speed, played.sim->StateAt(IndexOf(*played.sim, 0), 0.0).segment<2>(physics::kVx).norm())
        << speed;
    last = *played.arrival_speed;
  }
}

// The pace brings K to the pocket at the arrival speed asked, within kArrivalTolerance; a
// firmer arrival asks a faster stroke.
TEST_F(PaceTest, ThePaceArrivesAtTheArrivalSpeedAsked) {
  double previous_speed = 0.0;
  for (double arrival : {0.6, 1.0}) {
    PotOptions options;
    options.arrival_speed = arrival;
    SearchContext search = Search(balls_, 3, "lower_left", options);
    const Route route = Routes(search, ShotKind::kDirect).front().route;
    StrokeShape shape{kFirstCueSpeed, 0.0, 0.0, 0.0};
    std::optional<Aimed> aimed = AimAt(search, shape, Angle(-along_), Angle(-along_), false, 0.0);
    ASSERT_TRUE(aimed);
    ASSERT_FALSE(Pace(search, route, route.cue_aim, &shape, &*aimed, Angle(-along_))) << arrival;
    const Played played = search.Play(shape.At(aimed->heading), false, false);
    ASSERT_TRUE(played.arrival_speed);
    EXPECT_NEAR(*played.arrival_speed, arrival, kArrivalTolerance);
    EXPECT_GT(shape.speed, previous_speed);
    previous_speed = shape.speed;
  }
}

// K short of the pocket at the cue's top speed is refused.
TEST_F(PaceTest, APotThatFallsShortAtTheTopSpeedIsRefused) {
  physics::ModelParameters weak = params_;
  weak.cue.max_speed = 0.3;
  SearchContext search(table_, weak, balls_, 3, *table_.PocketNamed("lower_left"), {});
  const Route route = Routes(search, ShotKind::kDirect).front().route;
  StrokeShape shape{0.3, 0.0, 0.0, 0.0};
  std::optional<Aimed> aimed = AimAt(search, shape, Angle(-along_), Angle(-along_), false, 0.0);
  ASSERT_TRUE(aimed);
  const std::optional<Refusal> refused = Pace(search, route, route.cue_aim, &shape, &*aimed, Angle(-along_));
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, PotStatus::kNoStroke);
  EXPECT_EQ(refused->reason, "ball 3 does not reach lower_left at 0.3 m/s, the fastest stroke of the cue");
}

// a^2 = slope (v^2 - v0^2): the fit brings K to the capture line at no speed at v0.
TEST(SlowestPottingSpeed, IsWhereTheFitArrivesAtNoSpeed) {
  const PaceFit fit{0.5, 0.6};
  const double v0 = SlowestPottingSpeed(fit, 2.0);
  EXPECT_NEAR(fit.arrival * fit.arrival, fit.slope * (2.0 * 2.0 - v0 * v0), 1e-12);
  EXPECT_EQ(SlowestPottingSpeed({0.5, 5.0}, 2.0), 0.0) << "a fit that arrives at no speed above zero";
  EXPECT_EQ(SlowestPottingSpeed({}, 2.0), 0.8 * 2.0) << "no fit";
}

}  // namespace
}  // namespace billiard::pot
