#include "planner/pot/pot_planner.h"

#include <gtest/gtest.h>

#include "planner/pot/testing/pot_layouts.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"

namespace billiard::pot {
namespace {

TEST(PotPlanner, Placeholder) {}

}  // namespace
}  // namespace billiard::pot
