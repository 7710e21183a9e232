// The pool numbers a choice (MODE_CHOOSE) knows the balls of a table state by: the nine-ball
// rules need the numbers, the estimator gives classes with a confidence, and a rack has one ball
// of each number.
#pragma once

#include <cstdint>
#include <unordered_map>

#include "lcmtypes/billiard/table_state_t.hpp"

namespace billiard::planner_node {

// The pool numbers a choice knows the balls of `table` by, by their table state ids: the cue ball
// `cue` 0; every other ball the number (1-15) its class names at kMinClassConfidence or more, the
// surer (then the lower id) when two claim one; then, of the numbers left, those named by less
// confident classes, as surely; the rest take the numbers no ball claims (a rack has one of
// each), ascending, in the order of their ids, and 16 up when those run out.
std::unordered_map<int32_t, int> BallNumbers(const table_state_t& table, int32_t cue);

}  // namespace billiard::planner_node
