#include "planner/pot/drop_window.h"

#include <gtest/gtest.h>

#include <cmath>

#include "planner/pot/testing/pot_fixture.h"

namespace billiard::pot {
namespace {

using table::SceneBall;

class DropWindowTest : public testing::PotFixture {
 protected:
  // K `distance` from the lower left corner pocket on its diagonal, the cue ball 0.6 m behind it,
  // struck full: K's contact state as it leaves along the diagonal, toward the pocket.
  Contact StraightIn(SearchContext* search) const {
    const Contact c = search->FirstContact({2.0, Diagonal(), 0.0, 0.0, 0.0}, false);
    EXPECT_EQ(c.ball, 3);
    EXPECT_NEAR(Wrap(c.departure - Diagonal()), 0.0, 1e-12);
    return c;
  }
  SearchContext StraightInSearch(double distance) const {
    const Eigen::Vector2d corner = table_.PocketNamed("lower_left")->centre;
    const Eigen::Vector2d k = corner - distance * Unit(Diagonal()), cue = k - 0.6 * Unit(Diagonal());
    return Search({table::AtRest(0, cue.x(), cue.y()), table::AtRest(3, k.x(), k.y())}, 3, "lower_left");
  }
  static double Diagonal() { return Angle(Eigen::Vector2d(-1.0, -1.0)); }
};

// The table, its corner pocket's jaws and K's state are symmetric about the pocket's diagonal:
// so is the window, to its resolution.
TEST_F(DropWindowTest, AStraightInBallsWindowIsSymmetricAboutThePocketsLine) {
  SearchContext search = StraightInSearch(0.6);
  const Contact c = StraightIn(&search);
  const std::optional<Drop> drop = DropWindow(search, c, Diagonal(), kDirectScan, 0.0, kWindowResolution);
  ASSERT_TRUE(drop);
  EXPECT_LT(drop->lo, Diagonal());
  EXPECT_GT(drop->hi, Diagonal());
  EXPECT_NEAR(drop->Middle(), Diagonal(), kWindowResolution);
  EXPECT_NEAR(drop->hi - Diagonal(), Diagonal() - drop->lo, kWindowResolution);
  // Its edges: inside drops, a resolution beyond does not.
  EXPECT_TRUE(Drops(search, c, drop->lo, 1.0));
  EXPECT_TRUE(Drops(search, c, drop->hi, 1.0));
  EXPECT_FALSE(Drops(search, c, drop->lo - kWindowResolution, 1.0));
  EXPECT_FALSE(Drops(search, c, drop->hi + kWindowResolution, 1.0));
}

// The pocket's opening seen from K: twice as far, about half as wide a window.
TEST_F(DropWindowTest, AFartherBallHasANarrowerWindow) {
  SearchContext near_search = StraightInSearch(0.4), far_search = StraightInSearch(0.8);
  const std::optional<Drop> near = DropWindow(near_search, StraightIn(&near_search), Diagonal(), kDirectScan, 0.0,
                                              kWindowResolution);
  const std::optional<Drop> far = DropWindow(far_search, StraightIn(&far_search), Diagonal(), kDirectScan, 0.0,
                                             kWindowResolution);
  ASSERT_TRUE(near && far);
  const double ratio = (near->hi - near->lo) / (far->hi - far->lo);
  EXPECT_GT(ratio, 1.5);
  EXPECT_LT(ratio, 2.5);
}

// A ball in the pocket's mouth: K turned off it stops the window there.
TEST_F(DropWindowTest, ABallInTheWayClosesTheWindowOnItsSide) {
  SearchContext open = StraightInSearch(0.6);
  const std::optional<Drop> clear = DropWindow(open, StraightIn(&open), Diagonal(), kDirectScan, 0.0, kWindowResolution);
  ASSERT_TRUE(clear);
  const Eigen::Vector2d corner = table_.PocketNamed("lower_left")->centre;
  const Eigen::Vector2d beside = corner - 0.3 * Unit(Diagonal()) + 0.065 * Unit(Diagonal() + M_PI / 2.0);
  std::vector<SceneBall> balls = open.balls();
  balls.push_back(table::AtRest(5, beside.x(), beside.y()));
  SearchContext blocked_search = Search(balls, 3, "lower_left");
  const std::optional<Drop> blocked =
      DropWindow(blocked_search, StraightIn(&blocked_search), Diagonal(), kDirectScan, 0.0, kWindowResolution);
  ASSERT_TRUE(blocked);
  EXPECT_LT(blocked->hi, clear->hi - 2.0 * kWindowResolution) << "closed on ball 5's side";
  EXPECT_NEAR(blocked->lo, clear->lo, kWindowResolution) << "open on the other";
}

TEST_F(DropWindowTest, TheReachScaleBringsKUpToTheLeastSpeed) {
  Contact c;
  c.object_after = physics::MakeBallState(0, 0, 0.6, 0.8, 0, 0, 0);  // 1 m/s
  EXPECT_EQ(ReachScale(c), kReachSpeed);
  EXPECT_EQ(ReachScale(c, 0.5), 1.0) << "never slowed";
  c.object_after.segment<2>(physics::kVx).setZero();
  EXPECT_EQ(ReachScale(c), 1.0) << "a still ball stays still";
}

}  // namespace
}  // namespace billiard::pot
