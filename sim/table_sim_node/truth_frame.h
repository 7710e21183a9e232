// What one frame of a session shows: the balls' true states, published on TABLE_TRUTH so that a
// session can be scored against them, and the balls the simulated camera renders
// (sim/render/table_renderer.h) into the CAMERA_IMAGE frame. A ball is its truth's id and its
// true state at any sim time: at rest, or following the table's simulation of a shot.
//
// Module: billiard::table_sim_node.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "lcmtypes/billiard/table_state_t.hpp"
#include "sim/physics/ball_state.h"
#include "sim/render/table_renderer.h"
#include "sim/table/scene.h"
#include "sim/table/table_simulation.h"

namespace billiard::table_sim_node {

// A ball on the table and its true state at any sim time.
struct TruthBall {
  int id;
  std::function<physics::BallState(double)> state;
};

// `balls` at rest where they are (their velocities and spins dropped).
std::vector<TruthBall> AtRest(const std::vector<table::SceneBall>& balls);

// The balls of `sim`, a shot struck at sim time `t_strike`, still on the table at sim time
// `now` (a pocketed ball is shown until its fall into the pocket begins); each its state at any
// later time, at rest after the simulation's end. They refer to `sim`, which must outlive them.
std::vector<TruthBall> OnTable(const table::TableSimulation& sim, double t_strike, double now);

// The TABLE_TRUTH message of `balls` at sim time `t`, stamped `utime`: each ball's position,
// velocity and spin, its class its number (the cue ball's CLASS_CUE) with full confidence, and
// no covariance.
table_state_t TruthMessage(const std::vector<TruthBall>& balls, double t, std::int64_t utime);

// The balls as the camera renders them: pool's colours, 9-15 striped.
std::vector<render::RenderBall> RenderedBalls(const std::vector<TruthBall>& balls);

}  // namespace billiard::table_sim_node
