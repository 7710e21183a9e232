#include "planner/node/planner_node_options.h"

#include "sim/params/table_specs.h"

namespace billiard::planner_node {

table::TableGeometry TableOf(const PlannerNodeOptions& options) {
  return options.table ? *options.table
                       : table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
}

}  // namespace billiard::planner_node
