#include "planner/pot/margin.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "planner/pot/testing/pot_fixture.h"

namespace billiard::pot {
namespace {

using table::SceneBall;

// A window of headings that pot, its edges `lo` < 0 < `hi` about an aim at 0, with a gap
// [gap_lo, gap_hi) beyond `hi` where it pots again (none by default).
struct Window {
  double lo, hi, gap_lo = 1.0, gap_hi = 1.0;
  bool operator()(double x) const { return (x > lo && x < hi) || (x >= gap_lo && x < gap_hi); }
};

// The margin either side from each edge's guess, as the planner finds it.
double LeftMargin(const Window& pots, double guess) {
  return PlayedMargin(pots, Edge(pots, 0.0, guess, 0.5 * M_PI, kHeadingEdge), 0.0);
}
double RightMargin(const Window& pots, double guess) {
  return PlayedMargin(pots, Edge(pots, 0.0, -guess, -0.5 * M_PI, kHeadingEdge), 0.0);
}

// Whatever the guess, 0.9 of the margin pots and 1.1 of it misses.
TEST(Margin, NineTenthsOfItPotsAndElevenTenthsMisses) {
  const Window pots{-0.0071, 0.0123};
  for (double guess : {0.0123, 0.012, 0.0131, 0.004, 0.03, 1e-9}) {
    SCOPED_TRACE(guess);
    const double left = LeftMargin(pots, guess), right = RightMargin(pots, guess);
    EXPECT_TRUE(pots((1.0 - kMarginTolerance) * left));
    EXPECT_FALSE(pots((1.0 + kMarginTolerance) * left));
    EXPECT_TRUE(pots(-(1.0 - kMarginTolerance) * right));
    EXPECT_FALSE(pots(-(1.0 + kMarginTolerance) * right));
  }
}

// An edge inside the guess's bracket: the two headings played are the bracket's, and the
// margin is the guess.
TEST(Margin, AnEdgeInsideTheBracketIsTheGuess) {
  const Window pots{-0.01, 0.0123};
  const Bracket b = Edge(pots, 0.0, 0.012, 0.5 * M_PI, kHeadingEdge);
  EXPECT_NEAR(b.in, 0.9 * 0.012, 1e-15);
  EXPECT_NEAR(b.out, 1.1 * 0.012, 1e-15);
  EXPECT_NEAR(Margin(b, 0.0), 0.012, 1e-15);
}

// Beyond the bracket, bisection until the outside is within 1.2 times the inside.
TEST(Margin, AnEdgeFarFromItsGuessIsBisected) {
  const Window pots{-0.01, 0.0317};
  const Bracket b = Edge(pots, 0.0, 0.01, 0.5 * M_PI, kHeadingEdge);
  EXPECT_LT(b.in, 0.0317);
  EXPECT_GE(b.out, 0.0317);
  EXPECT_LE(b.out - b.in, kHeadingEdge.resolution * b.in);
}

// Where K drops again past a hole just outside the edge, the margin shrinks until 1.1 of it is
// a heading played that misses.
TEST(Margin, AHoleAtTheOutsideIsSteppedBack) {
  const Window pots{-0.01, 0.0123, 0.0128, 0.05};
  const Bracket b{0.011, 0.0125};  // in pots, out misses, 1.1 x in/0.9 pots again
  ASSERT_TRUE(pots(b.in));
  ASSERT_FALSE(pots(b.out));
  ASSERT_TRUE(pots(1.1 * Margin(b, 0.0)));
  const double margin = PlayedMargin(pots, b, 0.0);
  EXPECT_NEAR(margin, b.out / 1.1, 1e-15);
  EXPECT_TRUE(pots(0.9 * margin));
  EXPECT_FALSE(pots(1.1 * margin));
}

// A window that reaches the limit has its limit as the edge.
TEST(Margin, AWindowOpenToTheLimitEndsThere) {
  const Window pots{-0.01, 10.0};
  const Bracket b = Edge(pots, 0.0, 0.01, 0.5 * M_PI, kHeadingEdge);
  EXPECT_EQ(b.in, 0.5 * M_PI);
  EXPECT_EQ(b.out, 0.5 * M_PI);
}

// A bracket as narrow as doubles go: the pace already at the cue's top speed but for one ulp
// (cue_clearance_acceptance_test's seed 4719: 2.9241940608431896 against 2.92419406084319 m/s),
// where the midpoint of the two rounds onto one of them. The search ends on the two, each played
// once, and does not play the same stroke again and again (it did, without end: a guard here
// fails it after kPlays).
TEST(Margin, ABracketOfAdjacentDoublesEnds) {
  constexpr int kPlays = 100;
  const double x0 = 2.9241940608431896, limit = std::nextafter(x0, 4.0);
  for (const bool beyond_pots : {false, true}) {
    SCOPED_TRACE(beyond_pots);
    int plays = 0;
    const auto pots = [&](double x) {
      if (++plays > kPlays) throw std::runtime_error("the same bracket bisected without end");
      return x <= x0 || beyond_pots;
    };
    const Bracket b = Edge(pots, x0, limit, limit, kSpeedEdge);
    EXPECT_LE(plays, 3);
    EXPECT_EQ(b.in, beyond_pots ? limit : x0);
    EXPECT_EQ(b.out, limit);
  }
}

class MarginTest : public testing::PotFixture {};

// The margin is what the simulation says: turned to 0.9 of it either way the stroke still pots,
// to 1.1 it misses.
TEST_F(MarginTest, TheMarginIsTrueOnTheSimulation) {
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.6, 0.6), table::AtRest(1, 1.8, 0.9), table::AtRest(2, 1.2, 0.3)};
  const PotPlan plan = PlanPot(table_, params_, balls, {1, "upper_right", ShotKind::kDirect, {}});
  ASSERT_EQ(plan.status, PotStatus::kOk) << plan.reason;
  for (const auto& [fraction, pots] : {std::pair{0.9, true}, {1.1, false}}) {
    for (double side : {1.0, -1.0}) {
      physics::CueStroke s = plan.stroke;
      s.heading += side * fraction * (side > 0 ? plan.margin_left_deg : plan.margin_right_deg) * kDegree;
      const Outcome o = SimulateStroke(balls, s, plan.ball, plan.pocket);
      EXPECT_EQ(o.potted && o.first_contact == 1 && !o.scratch, pots) << fraction << " x " << side;
    }
  }
}

// A straight-in pot: struck at the cue's top speed it still drops, and at the window's slowest
// K only just reaches the pocket.
TEST_F(MarginTest, AStraightInPotsSpeedWindowRunsFromACreepToTheTopSpeed) {
  const Eigen::Vector2d corner = table_.PocketNamed("lower_left")->centre;
  const Eigen::Vector2d along = Eigen::Vector2d(1.0, 1.0).normalized();
  const Eigen::Vector2d k = corner + 0.6 * along, cue = corner + 1.2 * along;
  SearchContext search = Search({table::AtRest(0, cue.x(), cue.y()), table::AtRest(3, k.x(), k.y())}, 3, "lower_left");
  const StrokeShape shape{1.5, 0.0, 0.0, 0.0};
  const SpeedWindow window = SpeedWindowAt(search, shape, Angle(-along));
  EXPECT_EQ(window.hi, params_.cue.max_speed);
  EXPECT_LT(window.lo, 0.5 * shape.speed);
  EXPECT_GE(window.lo, 0.05);
  const Played slowest = search.Play(StrokeShape{window.lo, 0.0, 0.0, 0.0}.At(Angle(-along)), false, false);
  ASSERT_TRUE(slowest.outcome.potted);
  EXPECT_LT(*slowest.arrival_speed, 0.3);
}

}  // namespace
}  // namespace billiard::pot
