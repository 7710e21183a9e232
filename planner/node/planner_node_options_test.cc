// The table a node plans pots on: the one given, else the default, which must be the size of the
// default parameter set's table (the point planner's bounds are that table's).
#include "planner/node/planner_node_options.h"

#include <gtest/gtest.h>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"

namespace billiard::planner_node {
namespace {

TEST(TableOf, WithoutATableIsTheDefaultParameterSetsSize) {
  const table::TableGeometry table = TableOf({});
  const physics::ModelParameters params = params::LoadParameters(params::kDefaultParameterSet);
  EXPECT_EQ(table.name, table::BuildTable(params::LoadTableSpec(params::kDefaultTable)).name);
  EXPECT_NEAR(table.length, params.table.length, 1e-9);
  EXPECT_NEAR(table.width, params.table.width, 1e-9);
}

TEST(TableOf, IsTheTableGiven) {
  PlannerNodeOptions options;
  options.table = table::BuildTable(params::LoadTableSpec("snooker-12ft"));
  EXPECT_EQ(TableOf(options).name, options.table->name);
  EXPECT_NE(TableOf(options).length, TableOf({}).length);
}

}  // namespace
}  // namespace billiard::planner_node
