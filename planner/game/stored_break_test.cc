// The stored breaks are the ones the search found: each played again on the search's own racks
// (its samples from its seed, the computational pool's noise) gives the counts stored with it,
// and those found by the bounded search keep the scratch bound it holds breaks to.
#include <gtest/gtest.h>

#include "planner/game/break_search.h"
#include "sim/model_choice/model_choice.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/robots.h"
#include "sim/params/table_specs.h"

namespace billiard::game {
namespace {

TEST(StoredBreakTest, TheStoredFiguresReproduceAndKeepTheScratchBound) {
  const physics::ModelParameters params = params::LoadParameters("pool");
  const table::TableGeometry table =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  const cue::Robot gantry = params::LoadRobot("gantry");
  batch::ThreadPool pool(2);
  for (rules::Rules game : {rules::Rules::kNineBall, rules::Rules::kEightBall}) {
    const StoredSearch stored = StoredBreakSearch(game);
    ASSERT_GT(stored.options.samples, 0);
    EXPECT_EQ(stored.options.ranges.max_speed, gantry.speed.max);
    EXPECT_EQ(stored.options.ranges.max_tip_offset, gantry.max_tip_offset);
    const BreakSetting setting{table, params, game, params::LoadNoise("computational-pool"),
                               model_choice::TableMotion(params)};
    const BreakRates rates = EvaluateBreaks(setting, {stored.found}, stored.options.samples,
                                            stored.options.seed, pool)[0];
    EXPECT_EQ(rates.kept, stored.kept);
    EXPECT_EQ(rates.scratches, stored.scratches);
    if (stored.bounded) {
      EXPECT_TRUE(Feasible(rates, stored.options)) << ScratchBound(rates, stored.options.scratch_z);
    }
    EXPECT_EQ(StoredBreak(game).speed, stored.found.speed);
  }
}

}  // namespace
}  // namespace billiard::game
