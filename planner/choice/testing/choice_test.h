// The fixture the choice's tests (and the players' and the game's) share: the pool parameter
// set (its constants exact) on a 9-ft pool table, balls placed where asked, a dead-straight pot, a direct plan, a
// noise of heading error alone, a quick choice, and two choices compared.
//
// Module: billiard::choice (test code).
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <string>
#include <vector>

#include "planner/choice/choice_options.h"
#include "planner/choice/choice_result.h"
#include "planner/pot/pot_planner.h"
#include "sim/params/execution_noise.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/physics/parameters.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::choice::testing {

class ChoiceTest : public ::testing::Test {
 protected:
  ChoiceTest()
      : params_(ExactPool()),
        table_(table::BuildTable(params::LoadTableSpec(params::kDefaultTable))) {}

  // The pool set with its constants taken as exact (no uncertainty drawn): the choice's tests
  // judge what the robot's noise does; monte_carlo_test.cc judges the constants' draws.
  static physics::ModelParameters ExactPool() {
    physics::ModelParameters p = params::LoadParameters("pool");
    p.uncertainty = {};
    return p;
  }

  // The cue ball and ball 1 on the upper right corner pocket's diagonal, `object_back` and
  // `object_back + cue_back` from the pocket: a dead-straight pot.
  std::vector<table::SceneBall> StraightPot(double object_back, double cue_back) const {
    const Eigen::Vector2d corner = table_.PocketNamed("upper_right")->centre;
    const Eigen::Vector2d in = Eigen::Vector2d(1, 1).normalized();
    const Eigen::Vector2d o = corner - object_back * in, c = o - cue_back * in;
    return {table::AtRest(0, c.x(), c.y()), table::AtRest(1, o.x(), o.y())};
  }
  // StraightPot(0.5, 0.5) and ball 2 in the open: two balls to choose between.
  std::vector<table::SceneBall> TwoBalls() const {
    std::vector<table::SceneBall> balls = StraightPot(0.5, 0.5);
    balls.push_back(table::AtRest(2, 1.2, 0.5));
    return balls;
  }
  pot::PotPlan Plan(const std::vector<table::SceneBall>& balls, int ball,
                    const std::string& pocket) const {
    pot::PotRequest r;
    r.ball = ball;
    r.pocket = pocket;
    r.kind = pot::ShotKind::kDirect;
    return pot::PlanPot(table_, params_, balls, r);
  }
  static params::ExecutionNoise HeadingNoise(double deg) {
    params::ExecutionNoise n;
    n.heading = deg * M_PI / 180.0;
    return n;
  }

  // A choice of few samples and direct pots alone, for tests that run whole choices.
  static ChoiceOptions QuickChoice() {
    ChoiceOptions options;
    options.samples = 8;
    options.screen_samples = 4;
    options.finalists = 2;
    options.confirm_samples = 16;
    options.kinds = {pot::ShotKind::kDirect};
    return options;
  }
  // The same choice: the same status, placement and candidates, scored and estimated alike.
  static void ExpectSameChoice(const ChoiceResult& a, const ChoiceResult& b) {
    EXPECT_EQ(a.status, b.status);
    EXPECT_EQ(a.cue_placement, b.cue_placement);
    ASSERT_EQ(a.candidates.size(), b.candidates.size());
    for (std::size_t i = 0; i < a.candidates.size(); ++i) {
      EXPECT_EQ(a.candidates[i].plan.ball, b.candidates[i].plan.ball) << i;
      EXPECT_EQ(a.candidates[i].plan.pocket, b.candidates[i].plan.pocket) << i;
      EXPECT_EQ(a.candidates[i].plan.stroke.heading, b.candidates[i].plan.stroke.heading) << i;
      EXPECT_EQ(a.candidates[i].score, b.candidates[i].score) << i;
      EXPECT_EQ(a.candidates[i].confirmed.successes, b.candidates[i].confirmed.successes) << i;
    }
  }

  physics::ModelParameters params_;
  table::TableGeometry table_;
};

}  // namespace billiard::choice::testing
