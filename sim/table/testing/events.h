// Table events written by hand for the tests of what is read off a stroke's events (the rails
// after contact, a scratch's path): the truth by construction.
#pragma once

#include "sim/table/table_simulation.h"

namespace billiard::table::testing {

// An event of `type` for ball `ball` (and `other`, for a ball-ball impact).
inline TableEvent Event(EventType type, int ball, int other = -1) {
  TableEvent e;
  e.type = type;
  e.ball = ball;
  e.other = other;
  return e;
}

}  // namespace billiard::table::testing
