// A scene: the balls on a table at one instant, each with its id (0 is the cue ball).
#pragma once

#include "sim/physics/ball_state.h"

namespace billiard::table {

struct SceneBall {
  int id = 0;
  physics::BallState state = physics::BallState::Zero();
};

}  // namespace billiard::table
