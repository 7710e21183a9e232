// The fixture of the pot planner's tests: the 9-ft pool table and the "pool" parameter set they
// are written for, balls at rest on it, a pot's search context there, and what `billiard simulate
// --scene` makes of a stroke (its default motion and cushion), independently of the planner's
// own check.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <string>
#include <vector>

#include "planner/pot/pot_planner.h"
#include "planner/pot/search_context.h"
#include "sim/model_choice/model_choice.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/table/scene.h"
#include "sim/table/table_simulation.h"

namespace billiard::pot::testing {

class PotFixture : public ::testing::Test {
 protected:
  PotFixture()
      : table_(table::BuildTable(params::LoadTableSpec(params::kDefaultTable))),
        params_(params::LoadParameters("pool")) {}

  // The search context of the pot of ball `object` into `pocket` among `balls`.
  SearchContext Search(const std::vector<table::SceneBall>& balls, int object, const std::string& pocket,
                       const PotOptions& options = {}) const {
    return SearchContext(table_, params_, balls, object, *table_.PocketNamed(pocket), options);
  }

  struct Outcome {
    bool potted = false;
    int first_contact = -1;
    bool scratch = false;
    Eigen::Vector2d cue_rest = Eigen::Vector2d::Zero();
    double departure = 0.0, normal = 0.0;  // K's direction after the first contact, and the line
                                           // of centres there [rad]
    Eigen::Vector2d cue_at_contact = Eigen::Vector2d::Zero();  // where the cue ball was then
  };

  // The scene with the cue ball launched at v0, w0 (in `flight`), simulated as `simulate --scene`
  // does.
  Outcome Simulate(std::vector<table::SceneBall> balls, const Eigen::Vector2d& v0,
                   const Eigen::Vector3d& w0, int k, const std::string& pocket,
                   const physics::Flight& flight = {}) const {
    std::size_t cue = 0, object = 0;
    for (std::size_t i = 0; i < balls.size(); ++i) {
      if (balls[i].id == 0) cue = i;
      if (balls[i].id == k) object = i;
    }
    balls[cue].state.segment<2>(physics::kVx) = v0;
    balls[cue].state.segment<3>(physics::kWx) = w0;
    balls[cue].flight = flight;
    table::TableSimulationOptions options;
    options.five_dof = model_choice::TableMotion(params_);
    table::TableSimulation sim(table_, params_, balls, options);
    sim.Run();
    Outcome o;
    for (const table::TableEvent& e : sim.events()) {
      if (e.type == table::EventType::kBallBall && (e.ball == 0 || e.other == 0)) {
        o.first_contact = e.ball == 0 ? e.other : e.ball;
        const Eigen::Vector2d after = sim.StateAt(object, e.time).segment<2>(physics::kVx);
        const Eigen::Vector2d line = sim.StateAt(object, e.time).head<2>() - sim.StateAt(cue, e.time).head<2>();
        o.departure = std::atan2(after.y(), after.x());
        o.normal = std::atan2(line.y(), line.x());
        o.cue_at_contact = sim.StateAt(cue, e.time).head<2>();
        break;
      }
    }
    o.potted = sim.pocket(object) && *sim.pocket(object) == pocket;
    o.scratch = sim.pocket(cue).has_value();
    o.cue_rest = sim.State(cue).head<2>();
    return o;
  }

  Outcome SimulatePlan(const std::vector<table::SceneBall>& balls, const PotPlan& plan) const {
    return Simulate(balls, plan.v0, plan.w0, plan.ball, plan.pocket, plan.flight);
  }

  // The stroke struck from the cue ball (the first of `balls`) where it is.
  Outcome SimulateStroke(const std::vector<table::SceneBall>& balls, const physics::CueStroke& stroke, int k,
                         const std::string& pocket) const {
    const table::SceneBall cue = table::Struck(0, stroke, balls.front().state.head<2>(), params_);
    return Simulate(balls, cue.state.segment<2>(physics::kVx), cue.state.segment<3>(physics::kWx),
                    k, pocket, cue.flight);
  }

  void ExpectLegalPot(const std::vector<table::SceneBall>& balls, const PotPlan& plan) const {
    ASSERT_EQ(plan.status, PotStatus::kOk) << plan.reason;
    const Outcome o = SimulatePlan(balls, plan);
    EXPECT_TRUE(o.potted) << "ball " << plan.ball << " does not drop in " << plan.pocket;
    EXPECT_EQ(o.first_contact, plan.ball);
    EXPECT_FALSE(o.scratch);
    EXPECT_NEAR((o.cue_rest - plan.cue_rest).norm(), 0.0, 1e-9) << "the plan's rest is the truth's";
  }

  table::TableGeometry table_;
  physics::ModelParameters params_;
};

}  // namespace billiard::pot::testing
