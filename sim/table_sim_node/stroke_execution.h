// The robot's execution of the planner's CUE_COMMAND on the simulated table: the commanded
// stroke with the robot's execution noise (sim/params/execution_noise.h), the cue ball struck
// by it (the cue strike model, sim/physics/cue_strike.h: Alciatore 2004, TP A.30-A.31), and
// the table's motion to rest.
//
// The noise comes from a stream of its own, seeded from the session's seed through seed_seq
// (NoiseStream), so that turning it on leaves the session's random targets as they were and a
// run with noise differs from one without by the noise alone; the same seed executes the same
// commands the same way.
//
// Module: billiard::table_sim_node.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "lcmtypes/billiard/cue_command_t.hpp"
#include "sim/cue/robot.h"
#include "sim/params/execution_noise.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"
#include "sim/table/table_simulation.h"

namespace billiard::table_sim_node {

// The longest a whole-table shot is simulated [s].
inline constexpr double kLongestScene = 120.0;

// The noise's generator: seeded from the seed and a stream number through seed_seq, so that it
// is independent of the targets' generator (seeded with the seed itself, whose targets it keeps
// as they were).
std::mt19937 NoiseStream(std::uint32_t seed);

// The noise the robot drew, over the strokes it executed: the root mean square of each error
// (the executed stroke against the commanded one, the tip's limit applied), about zero as the
// noise is drawn. What a run's learned noise (shot_fit/execution_noise_fit.h) is to be held
// against: a few dozen strokes draw spreads some per cent off the noise's own.
struct DrawnNoise {
  int strokes = 0;
  double speed_fraction = 0.0;  // of the commanded speed
  double heading = 0.0;         // [rad]
  double tip = 0.0;             // each tip offset, side and height pooled [m]
};

class StrokeExecution {
 public:
  // `noise` on balls of `ball_radius` (the tip offsets' scale), drawn from NoiseStream(seed).
  StrokeExecution(const params::ExecutionNoise& noise, double ball_radius, std::uint32_t seed);

  // The stroke `command` asks for as the robot executes it, with the noise (one draw per call).
  physics::CueStroke Executed(const cue_command_t& command);

  // The noise drawn by Executed so far.
  DrawnNoise Drawn() const;

  // `balls` with the cue ball (id 0) struck by the executed stroke on a table of `plant`'s
  // physics; as they are when the command is a refusal (no draw then).
  std::vector<table::SceneBall> Struck(const std::vector<table::SceneBall>& balls,
                                       const cue_command_t& command,
                                       const physics::ModelParameters& plant);

 private:
  params::ExecutionNoise noise_;
  double ball_radius_;
  std::mt19937 random_;
  // The sums of the drawn errors' squares: speed fraction, heading, tip side and height.
  int strokes_ = 0;
  double speed_squares_ = 0.0, heading_squares_ = 0.0, tip_squares_ = 0.0;
};

// The stroke `command` asks for, as commanded (no noise).
physics::CueStroke Commanded(const cue_command_t& command);

// Why `robot` cannot make `stroke` on the cue ball (id 0) of `balls` (of radius `ball_radius`) on
// `geometry`, as FastFiz's TableState::isPhysicallyPossible refuses a shot (Archibald et al.
// 2010): the stroke outside the robot's ranges (cue::OutsideRanges), or its cue meeting a ball,
// the cloth, a rail or the robot's own body (cue::Clearance); empty when it can. The commanded
// stroke is checked, not the noise's draw: the robot refuses what it is told, and the planner's
// elevation margin (planner/pot/cue_elevation.h) is what keeps the executions clear.
std::string Unmakeable(const cue::Robot& robot, const table::TableGeometry& geometry, double ball_radius,
                       const std::vector<table::SceneBall>& balls, const physics::CueStroke& stroke);

// The motion `billiard simulate --scene` runs by default, which the planner checks its pots
// against: the closed form alone would leave a cue ball that slides off a cut centimetres from
// where the 5-DOF model does.
table::TableSimulationOptions SceneMotion(const physics::ModelParameters& plant);

// `struck` on `geometry` with `plant`'s physics and `motion`, simulated to rest (at most
// kLongestScene).
table::TableSimulation PlayedToRest(const table::TableGeometry& geometry,
                                    const physics::ModelParameters& plant,
                                    const std::vector<table::SceneBall>& struck,
                                    const table::TableSimulationOptions& motion);

}  // namespace billiard::table_sim_node
