// A scene: the balls on a table at one instant, each with its id (0 is the cue ball).
#pragma once

#include "sim/physics/ball_state.h"

namespace billiard::table {

struct SceneBall {
  int id = 0;
  physics::BallState state = physics::BallState::Zero();
};

// Ball `id` at rest at (x, y).
inline SceneBall AtRest(int id, double x, double y) {
  SceneBall ball{id};
  ball.state.head<2>() = Eigen::Vector2d(x, y);
  return ball;
}

}  // namespace billiard::table
