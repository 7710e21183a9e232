#include "planner/choice/second_level.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "planner/choice/scene_balls.h"
#include "planner/choice/screening.h"
#include "planner/choice/testing/choice_test.h"

namespace billiard::choice {
namespace {

// The gap left between the cue ball and each ball boxing it in [m].
constexpr double kBoxGap = 0.002;
// The cut of the easy next pot [deg].
constexpr double kEasyCutDeg = 15.0;

class SecondLevelTest : public testing::ChoiceTest {
 protected:
  // Nine-ball, direct next pots, the robot's noise.
  static ChoiceOptions NineBall() {
    ChoiceOptions options;
    options.rules = Rules::kNineBall;
    return options;
  }
  // The 9, out of the way of every pot these tests play (the rack is not over while it stays).
  table::SceneBall Nine() const { return table::AtRest(9, 0.25 * table_.length, 0.2 * table_.width); }

  // An easy next pot: the 1 0.3 m from the upper right corner on its diagonal, the cue ball
  // 0.4 m from it on a line kEasyCutDeg off the diagonal (a dead-straight pot this short follows
  // the ball in: a scratch the planner refuses).
  std::vector<table::SceneBall> EasyNext() const {
    std::vector<table::SceneBall> balls = StraightPot(0.3, 0.4);
    const Eigen::Vector2d o = Position(balls[1]);
    const Eigen::Vector2d back = Eigen::Rotation2Dd(kEasyCutDeg * M_PI / 180) * (Position(balls[0]) - o);
    balls[0] = table::AtRest(0, o.x() + back.x(), o.y() + back.y());
    balls.push_back(Nine());
    return balls;
  }
  // No next pot: the cue ball boxed in by six balls, 60 degrees apart, kBoxGap off it. A line
  // leaving the cue ball between two of them passes each within (2r + gap) sin 30 < 2r of its
  // centre, so no straight path leaves the box: no direct pot of the 1 plans.
  std::vector<table::SceneBall> BoxedIn() const {
    std::vector<table::SceneBall> balls = EasyNext();
    const Eigen::Vector2d c(0.5 * table_.length, 0.5 * table_.width);
    balls[0] = table::AtRest(0, c.x(), c.y());
    const double d = 2 * params_.ball.radius + kBoxGap;
    for (int k = 0; k < 6; ++k) {
      const double a = k * M_PI / 3;
      balls.push_back(table::AtRest(2 + k, c.x() + d * std::cos(a), c.y() + d * std::sin(a)));
    }
    return balls;
  }
  // `samples` potting executions leaving `rest`, then `misses` that did not pot.
  static std::vector<Execution> Leaving(const std::vector<table::SceneBall>& rest, int samples,
                                        int misses = 0) {
    std::vector<Execution> executions(samples + misses);
    for (int s = 0; s < samples; ++s) {
      executions[s].potted = true;
      executions[s].rest = rest;
    }
    return executions;
  }
};

// Truth by geometry: a dead-straight short pot drops under the robot's noise, a boxed-in cue
// ball has no straight path, a rack without its 9 is over.
TEST_F(SecondLevelTest, PlansTheNextShot) {
  batch::ThreadPool pool(2);
  const ChoiceOptions options = NineBall();
  const NextShotValue easy = PlanNextShot(table_, params_, EasyNext(), options, pool);
  EXPECT_GT(easy.value, 0.9);
  EXPECT_GT(easy.simulations, 0);
  EXPECT_EQ(PlanNextShot(table_, params_, BoxedIn(), options, pool).value, 0.0);
  std::vector<table::SceneBall> over = EasyNext();
  over.pop_back();  // the 9
  EXPECT_EQ(PlanNextShot(table_, params_, over, options, pool).value, 1.0);
}

// Two equal pots (every execution pots), one leaving the easy next pot, one leaving none: the
// second level values the first near 1 and the second 0, so p (1 + v) prefers the first.
TEST_F(SecondLevelTest, PrefersThePotThatLeavesAnEasyNextShot) {
  batch::ThreadPool pool(2);
  const int samples = 8;
  std::vector<Execution> executions = Leaving(BoxedIn(), samples);
  const std::vector<Execution> easy = Leaving(EasyNext(), samples);
  executions.insert(executions.end(), easy.begin(), easy.end());
  const SecondLevel planned =
      PlanNextShots(table_, params_, executions, 2, samples, NineBall(), pool);
  ASSERT_EQ(planned.next_shot_values.size(), 2u);
  EXPECT_EQ(planned.next_shot_values[0], 0.0);
  EXPECT_GT(planned.next_shot_values[1], 0.9);
  const Tally boxed{Binomial(samples, samples), planned.next_shot_values[0]};
  const Tally open{Binomial(samples, samples), planned.next_shot_values[1]};
  EXPECT_GT(Score(open, true), Score(boxed, true));
}

// A candidate's v is the mean over its potting executions: half leaving the easy shot, half the
// box, is half the easy one's; its misses count for nothing; one that never pots is worth 0.
TEST_F(SecondLevelTest, TheValueIsTheMeanOverThePottingExecutions) {
  batch::ThreadPool pool(2);
  const int samples = 8;
  std::vector<Execution> mixed = Leaving(EasyNext(), 3, 1);
  const std::vector<Execution> boxed = Leaving(BoxedIn(), 3, 1);
  mixed.insert(mixed.end(), boxed.begin(), boxed.end());
  const std::vector<Execution> none(samples);
  std::vector<Execution> executions = Leaving(EasyNext(), samples);
  executions.insert(executions.end(), mixed.begin(), mixed.end());
  executions.insert(executions.end(), none.begin(), none.end());
  const SecondLevel planned =
      PlanNextShots(table_, params_, executions, 3, samples, NineBall(), pool);
  ASSERT_EQ(planned.next_shot_values.size(), 3u);
  EXPECT_GT(planned.next_shot_values[0], 0.9);
  EXPECT_NEAR(planned.next_shot_values[1], 0.5 * planned.next_shot_values[0], 1e-12);
  EXPECT_EQ(planned.next_shot_values[2], 0.0);
}

// Tables whose balls lie within the radius of the first's share its cluster, across candidates
// (the cache); a cue ball further off, or another set of balls, starts a new one.
TEST_F(SecondLevelTest, ClustersTablesThatAreAlike) {
  std::vector<table::SceneBall> near = EasyNext(), far = EasyNext(), fewer = EasyNext();
  near[0].state[physics::kX] += 0.03;
  far[0].state[physics::kX] -= 0.2;
  fewer.pop_back();
  std::vector<Execution> executions = Leaving(EasyNext(), 1);
  for (const auto& rest : {near, far, fewer}) {
    const std::vector<Execution> one = Leaving(rest, 1);
    executions.insert(executions.end(), one.begin(), one.end());
  }
  executions.push_back(Execution{});  // a miss
  executions.push_back(executions.front());
  const Outcomes outcomes = ClusterOutcomes(executions, 2, 3, 0.1);
  EXPECT_EQ(outcomes.states.size(), 3u);
  EXPECT_EQ(outcomes.cluster_of[0], (std::vector<int>{0, 0, 1}));
  EXPECT_EQ(outcomes.cluster_of[1], (std::vector<int>{2, -1, 0}));
}

// Position play's target: of a place boxed in and an open one, the open one, wherever listed;
// comparing one place alone, the first.
TEST_F(SecondLevelTest, PositionPlayAimsWhereTheNextShotIsBest) {
  batch::ThreadPool pool(2);
  const std::vector<table::SceneBall> boxed = BoxedIn();
  const Eigen::Vector2d box = Position(boxed[0]);
  const Eigen::Vector2d open = Position(EasyNext()[0]);
  ChoiceOptions options = NineBall();
  EXPECT_EQ(BestPlaceForNext(table_, params_, boxed, {box, open}, options, pool), open);
  EXPECT_EQ(BestPlaceForNext(table_, params_, boxed, {open, box}, options, pool), open);
  options.position_places = 1;
  EXPECT_EQ(BestPlaceForNext(table_, params_, boxed, {box, open}, options, pool), box);
}

// The same values on one thread or two.
TEST_F(SecondLevelTest, SameValuesOnOneThreadOrTwo) {
  const int samples = 4;
  std::vector<table::SceneBall> moved = EasyNext();
  moved[0].state[physics::kY] -= 0.3;
  std::vector<Execution> executions = Leaving(moved, samples);
  const std::vector<Execution> easy = Leaving(EasyNext(), samples);
  executions.insert(executions.end(), easy.begin(), easy.end());
  ChoiceOptions options = NineBall();
  options.noise = params::LoadNoise("computational-pool");
  options.next_kinds = {pot::ShotKind::kDirect, pot::ShotKind::kBank};
  batch::ThreadPool one(1), two(2);
  const SecondLevel a = PlanNextShots(table_, params_, executions, 2, samples, options, one);
  const SecondLevel b = PlanNextShots(table_, params_, executions, 2, samples, options, two);
  ASSERT_EQ(a.next_shot_values.size(), 2u);
  EXPECT_GT(a.next_shot_values[1], 0.0);
  EXPECT_EQ(a.next_shot_values, b.next_shot_values);
  EXPECT_EQ(a.simulations, b.simulations);
}

}  // namespace
}  // namespace billiard::choice
