// The look of the balls against the set a pool player knows (WPA's ball colours): the cue ball
// white, 1-8 solids, 9-15 white with the band of the solid eight below.
#include "plot/ball_look.h"

#include <gtest/gtest.h>

namespace billiard::plot {
namespace {

constexpr Rgb kWhite{1, 1, 1};

TEST(BallLook, TheCueBallIsWhiteAndPlain) {
  EXPECT_EQ(LookOf(0).body, kWhite);
  EXPECT_FALSE(LookOf(0).band);
  EXPECT_FALSE(DashedPath(0));
}

TEST(BallLook, StripesAreWhiteWithTheBandOfTheirSolid) {
  for (int solid = 1; solid <= 7; ++solid) {
    const BallLook stripe = LookOf(solid + 8);
    EXPECT_FALSE(LookOf(solid).band) << solid;
    ASSERT_TRUE(stripe.band) << solid + 8;
    EXPECT_EQ(stripe.body, kWhite);
    EXPECT_EQ(*stripe.band, LookOf(solid).body) << solid + 8;
    // Told apart: the stripe's path dashed, in the same colour.
    EXPECT_TRUE(DashedPath(solid + 8));
    EXPECT_FALSE(DashedPath(solid));
    EXPECT_EQ(PathColour(solid + 8), PathColour(solid));
  }
  EXPECT_FALSE(LookOf(8).band);  // the 8 is a solid
}

TEST(BallLook, EverySolidHasItsOwnColour) {
  for (int a = 1; a <= 8; ++a) {
    for (int b = a + 1; b <= 8; ++b) EXPECT_FALSE(LookOf(a).body == LookOf(b).body) << a << ", " << b;
  }
  EXPECT_FALSE(LookOf(1).body == kWhite);
}

TEST(BallLook, TheSetRepeatsPastFifteen) {
  EXPECT_EQ(LookOf(16).body, LookOf(1).body);
  EXPECT_EQ(*LookOf(24).band, *LookOf(9).band);
}

// Snooker's seven colours are plain balls, each its own colour, none the cue ball's white.
TEST(BallLook, SnookerBallsArePlainAndApart) {
  const SnookerBall all[] = {SnookerBall::kRed,  SnookerBall::kYellow, SnookerBall::kGreen,
                             SnookerBall::kBrown, SnookerBall::kBlue, SnookerBall::kPink,
                             SnookerBall::kBlack};
  for (SnookerBall a : all) {
    EXPECT_FALSE(SnookerLookOf(a).band);
    EXPECT_FALSE(SnookerLookOf(a).body == kWhite);
    for (SnookerBall b : all) {
      if (a != b) EXPECT_FALSE(SnookerLookOf(a).body == SnookerLookOf(b).body);
    }
  }
}

}  // namespace
}  // namespace billiard::plot
