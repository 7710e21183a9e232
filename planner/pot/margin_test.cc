#include "planner/pot/margin.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "planner/pot/testing/pot_fixture.h"

namespace billiard::pot {
namespace {

using table::SceneBall;

constexpr double kStep = kMarginGrid;

// Headings that pot: an open window (lo, hi) about an aim at 0, less the holes [from, to) in it
// (a scratch off a jaw), each heading asked for recorded.
struct Window {
  double lo, hi;
  std::vector<std::pair<double, double>> holes;
  std::vector<double>* asked = nullptr;
  bool operator()(double x) const {
    if (asked) asked->push_back(x);
    for (const auto& [from, to] : holes) {
      if (x >= from && x < to) return false;
    }
    return x > lo && x < hi;
  }
};

// The margin is the last grid step before the window's edge, each side on its own.
TEST(Margin, TheWalkEndsAtTheLastGridStepInsideTheWindow) {
  const Window pots{-2.5 * kStep, 7.3 * kStep, {}};
  EXPECT_NEAR(WalkedMargin(pots, 0.0, 1.0), 7.0 * kStep, 1e-15);
  EXPECT_NEAR(WalkedMargin(pots, 0.0, -1.0), 2.0 * kStep, 1e-15);
}

// A hole inside the window (headings that scratch) ends the margin where it begins, though K
// drops legally again beyond it; a hole of a fraction of a step between two grid headings is
// not one the grid plays.
TEST(Margin, TheWalkStopsAtTheFirstHole) {
  const Window pots{-20.0 * kStep, 20.0 * kStep, {{4.0 * kStep, 6.0 * kStep}, {-11.6 * kStep, -11.2 * kStep}}};
  EXPECT_NEAR(WalkedMargin(pots, 0.0, 1.0), 3.0 * kStep, 1e-15);
  EXPECT_NEAR(WalkedMargin(pots, 0.0, -1.0), 19.0 * kStep, 1e-15);
  const Window deeper{-20.0 * kStep, 20.0 * kStep, {{-13.0 * kStep, -12.5 * kStep}}};
  EXPECT_NEAR(WalkedMargin(deeper, 0.0, -1.0), 12.0 * kStep, 1e-15);
}

// The headings played are the grid's, from the aim outward, up to the first that fails: one
// simulation per step of the margin and one more.
TEST(Margin, TheWalkPlaysEachGridHeadingOnceOutwardFromTheAim) {
  std::vector<double> asked;
  const double aim = 0.3;
  const Window pots{aim - 1.0, aim + 4.5 * kStep, {}, &asked};
  EXPECT_NEAR(WalkedMargin(pots, aim, 1.0), 4.0 * kStep, 1e-15);
  ASSERT_EQ(asked.size(), 5u);
  for (std::size_t j = 0; j < asked.size(); ++j) EXPECT_NEAR(asked[j], aim + (j + 1.0) * kStep, 1e-15);
}

// A first step that misses (a fragile pot) is a margin of 0.
TEST(Margin, AFirstStepThatMissesIsNoMargin) {
  const Window pots{-0.4 * kStep, 3.0 * kStep, {}};
  EXPECT_EQ(WalkedMargin(pots, 0.0, -1.0), 0.0);
  EXPECT_NEAR(WalkedMargin(pots, 0.0, 1.0), 2.0 * kStep, 1e-15);
}

// A window that never closes is walked to the limit and no farther.
TEST(Margin, AWindowOpenToTheLimitEndsThere) {
  std::vector<double> asked;
  const Window pots{-10.0, 10.0, {}, &asked};
  EXPECT_NEAR(WalkedMargin(pots, 0.0, 1.0, kStep, 50.5 * kStep), 50.0 * kStep, 1e-15);
  EXPECT_EQ(asked.size(), 50u);
}

// Strided, the walk finds the same margin wherever the window has no hole narrower than a
// stride: every edge position, every stride, either side.
TEST(Margin, AStridedWalkFindsTheFullWalksMargin) {
  for (int edge = 0; edge <= 23; ++edge) {
    const Window pots{-(edge + 0.5) * kStep, (edge + 0.5) * kStep, {}};
    for (int stride : {1, 2, 4, 5, 8}) {
      SCOPED_TRACE(::testing::Message() << "edge " << edge << ", stride " << stride);
      EXPECT_NEAR(WalkedMargin(pots, 0.0, 1.0, kStep, kMarginLimit, stride), edge * kStep, 1e-15);
      EXPECT_NEAR(WalkedMargin(pots, 0.0, -1.0, kStep, kMarginLimit, stride), edge * kStep, 1e-15);
    }
  }
}

// A stride plays about n / stride headings out and log2(stride) at the edge instead of n + 1;
// every one on the grid.
TEST(Margin, AStridedWalkPlaysAStrideOutAndBisectsTheEdge) {
  std::vector<double> asked;
  const Window pots{-1.0, 41.5 * kStep, {}, &asked};
  EXPECT_NEAR(WalkedMargin(pots, 0.0, 1.0, kStep, kMarginLimit, 4), 41.0 * kStep, 1e-15);
  // 4, 8, .., 44 out (11), then 42 and 41 between 40 and 44 (2): 13 of the full walk's 42.
  EXPECT_EQ(asked.size(), 13u);
  for (double x : asked) EXPECT_NEAR(x / kStep, std::round(x / kStep), 1e-9) << "on the grid";
}

// A hole narrower than a stride between two headings it plays is stepped over (that is its
// cost); one a stride wide or wider always holds a heading it plays and ends the margin as the
// full walk's does.
TEST(Margin, AStridedWalkStepsOverOnlyAHoleNarrowerThanAStride) {
  const Window narrow{-1.0, 30.5 * kStep, {{5.0 * kStep, 7.0 * kStep}}};
  EXPECT_NEAR(WalkedMargin(narrow, 0.0, 1.0), 4.0 * kStep, 1e-15);
  EXPECT_NEAR(WalkedMargin(narrow, 0.0, 1.0, kStep, kMarginLimit, 4), 30.0 * kStep, 1e-15);
  for (int start = 1; start <= 12; ++start) {
    const Window wide{-1.0, 30.5 * kStep, {{start * kStep, (start + 4) * kStep}}};
    EXPECT_NEAR(WalkedMargin(wide, 0.0, 1.0, kStep, kMarginLimit, 4), (start - 1) * kStep, 1e-15)
        << "a hole from " << start << " steps";
  }
}

// A cap ends a wide window's walk, strided or not, on the grid's last heading within it.
TEST(Margin, ACappedWalkEndsAtTheCap) {
  std::vector<double> asked;
  const Window pots{-10.0, 10.0, {}, &asked};
  EXPECT_NEAR(WalkedMargin(pots, 0.0, -1.0, kStep, 50.5 * kStep, 4), 50.0 * kStep, 1e-15);
  EXPECT_EQ(asked.size(), 13u);  // 4, 8, .., 48, then 50
}

// A speed edge inside its guess's bracket: the two speeds played are the bracket's.
TEST(Margin, ASpeedEdgeInsideItsGuessBracketIsThatBracket) {
  const Window pots{0.0, 3.05, {}};
  const Bracket b = Edge(pots, 2.0, 3.0, 8.0, kSpeedEdge);
  EXPECT_NEAR(b.in, 2.0 + 0.9 * 1.0, 1e-15);
  EXPECT_NEAR(b.out, 2.0 + 1.1 * 1.0, 1e-15);
}

// Beyond the bracket, bisection until the outside is within 10 % of the inside's distance.
TEST(Margin, ASpeedEdgeFarFromItsGuessIsBisected) {
  const Window pots{0.0, 5.17, {}};
  const Bracket b = Edge(pots, 2.0, 3.0, 8.0, kSpeedEdge);
  EXPECT_LT(b.in, 5.17);
  EXPECT_GE(b.out, 5.17);
  EXPECT_LE(b.out - b.in, kSpeedEdge.resolution * (b.in - 2.0));
}

// A window that reaches the limit has its limit as the edge.
TEST(Margin, ASpeedWindowOpenToTheLimitEndsThere) {
  const Window pots{0.0, 10.0, {}};
  const Bracket b = Edge(pots, 2.0, 3.0, 8.0, kSpeedEdge);
  EXPECT_EQ(b.in, 8.0);
  EXPECT_EQ(b.out, 8.0);
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

// The margin is what the simulation says: every heading of the grid inside it pots legally, and
// the next one out on each side does not.
TEST_F(MarginTest, TheMarginIsTrueOnTheSimulation) {
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.6, 0.6), table::AtRest(1, 1.8, 0.9), table::AtRest(2, 1.2, 0.3)};
  const PotPlan plan = PlanPot(table_, params_, balls, {1, "upper_right", ShotKind::kDirect, {}});
  ASSERT_EQ(plan.status, PotStatus::kOk) << plan.reason;
  ASSERT_GT(plan.margin_left_deg + plan.margin_right_deg, 0.1);
  for (const auto& [side, margin] : {std::pair{1.0, plan.margin_left_deg}, {-1.0, plan.margin_right_deg}}) {
    const int steps = static_cast<int>(std::lround(margin * kDegree / kStep));
    EXPECT_NEAR(steps * kStep, margin * kDegree, 1e-12) << "a margin on the grid";
    for (int j = 1; j <= steps + 1; ++j) {
      physics::CueStroke s = plan.stroke;
      s.heading += side * j * kStep;
      const Outcome o = SimulateStroke(balls, s, plan.ball, plan.pocket);
      EXPECT_EQ(o.potted && o.first_contact == 1 && !o.scratch, j <= steps) << j << " steps x " << side;
    }
  }
}

// A plan's margin walked with a cap and a stride (as a choice ranks plans), then stated in full
// (StateMargins), is the margin the full walk plans: on a pot whose window is wider than the cap
// and on the scene's other side.
TEST_F(MarginTest, AStatedMarginIsTheFullWalks) {
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.6, 0.6), table::AtRest(1, 1.8, 0.9), table::AtRest(2, 1.2, 0.3)};
  const PotRequest request{1, "upper_right", ShotKind::kDirect, {}};
  const PotPlan full = PlanPot(table_, params_, balls, request);
  ASSERT_EQ(full.status, PotStatus::kOk) << full.reason;
  PotOptions ranking;
  ranking.margin_cap = 0.05 * kDegree;
  ranking.margin_stride = 4;
  PotPlan ranked = PlanPot(table_, params_, balls, request, ranking);
  ASSERT_EQ(ranked.status, PotStatus::kOk) << ranked.reason;
  ASSERT_GT(std::min(full.margin_left_deg, full.margin_right_deg), 0.05) << "the cap cuts it";
  EXPECT_NEAR(ranked.margin_left_deg, 0.05, 1e-9);
  EXPECT_NEAR(ranked.margin_right_deg, 0.05, 1e-9);
  EXPECT_LT(ranked.simulations, full.simulations);
  EXPECT_EQ(ranked.stroke.heading, full.stroke.heading) << "the margin changes no stroke";
  const int simulations = ranked.simulations;
  const int walked = StateMargins(table_, params_, balls, &ranked, ranking);
  EXPECT_EQ(ranked.margin_left_deg, full.margin_left_deg);
  EXPECT_EQ(ranked.margin_right_deg, full.margin_right_deg);
  EXPECT_EQ(walked, std::lround((full.margin_left_deg + full.margin_right_deg) / 0.01) + 2);
  EXPECT_EQ(ranked.simulations, simulations + walked);
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
