// A scene: the balls on a table at one instant, each with its id (0 is the cue ball).
#pragma once

#include "sim/physics/ball_state.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/hop.h"
#include "sim/physics/parameters.h"

namespace billiard::table {

struct SceneBall {
  SceneBall() = default;
  explicit SceneBall(int ball_id) : id(ball_id) {}
  // Ball `ball_id` in `ball_state`, on the cloth unless `ball_flight` is airborne.
  SceneBall(int ball_id, const physics::BallState& ball_state,
            const physics::Flight& ball_flight = {})
      : id(ball_id), state(ball_state), flight(ball_flight) {}

  int id = 0;
  physics::BallState state = physics::BallState::Zero();
  // Off the cloth at the scene's instant: a ball an elevated cue has just struck leaves it at
  // physics::LaunchUpSpeed (Struck).
  physics::Flight flight;
};

// Ball `id` at rest at (x, y).
inline SceneBall AtRest(int id, double x, double y) {
  SceneBall ball{id};
  ball.state.head<2>() = Eigen::Vector2d(x, y);
  return ball;
}

// Ball `id` as `stroke` leaves it from `position`: its launch (physics::StrikeBall) and, for an
// elevated cue, its hop.
inline SceneBall Struck(int id, const physics::CueStroke& stroke, const Eigen::Vector2d& position,
                        const physics::ModelParameters& params) {
  SceneBall ball{id, physics::StrikeBall(stroke, position, params)};
  ball.flight.vertical_speed = physics::LaunchUpSpeed(stroke, ball.state);
  return ball;
}

}  // namespace billiard::table
