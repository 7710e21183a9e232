#include "sim/table_sim_node/stroke_execution.h"

#include <cmath>
#include <sstream>

#include "sim/cue/clearance.h"
#include "sim/model_choice/model_choice.h"
#include "sim/table_sim_node/session_balls.h"

namespace billiard::table_sim_node {

std::mt19937 NoiseStream(std::uint32_t seed) {
  std::seed_seq sequence{seed, std::uint32_t{1}};
  return std::mt19937(sequence);
}

StrokeExecution::StrokeExecution(const params::ExecutionNoise& noise, double ball_radius,
                                 std::uint32_t seed)
    : noise_(noise), ball_radius_(ball_radius), random_(NoiseStream(seed)) {}

physics::CueStroke Commanded(const cue_command_t& command) {
  return {command.cue_speed, command.heading, command.tip_side, command.tip_height, command.elevation};
}

physics::CueStroke StrokeExecution::Executed(const cue_command_t& command) {
  std::normal_distribution<double> unit(0.0, 1.0);
  const physics::CueStroke commanded = Commanded(command);
  const physics::CueStroke executed =
      params::Perturbed(commanded, noise_, ball_radius_, [&] { return unit(random_); });
  ++strokes_;
  if (commanded.speed > 0) speed_squares_ += std::pow(executed.speed / commanded.speed - 1.0, 2);
  heading_squares_ += std::pow(executed.heading - commanded.heading, 2);
  tip_squares_ += std::pow(executed.tip_side - commanded.tip_side, 2) +
                  std::pow(executed.tip_height - commanded.tip_height, 2);
  return executed;
}

DrawnNoise StrokeExecution::Drawn() const {
  if (strokes_ == 0) return {};
  return {strokes_, std::sqrt(speed_squares_ / strokes_), std::sqrt(heading_squares_ / strokes_),
          std::sqrt(tip_squares_ / (2.0 * strokes_))};
}

std::string Unmakeable(const cue::Robot& robot, const table::TableGeometry& geometry, double ball_radius,
                       const std::vector<table::SceneBall>& balls, const physics::CueStroke& stroke) {
  if (std::string outside = cue::OutsideRanges(robot, stroke, ball_radius); !outside.empty()) return outside;
  const cue::CueClearance c = cue::Clearance(geometry, ball_radius, balls, kCueBall, stroke, robot);
  if (c.clears) return "";
  std::ostringstream why;
  why.precision(3);
  why << "the " << robot.name << "'s cue at " << stroke.elevation * 180.0 / M_PI << " deg meets " << c.what
      << " (" << -c.distance * 1e3 << " mm into it)";
  return why.str();
}

std::vector<table::SceneBall> StrokeExecution::Struck(const std::vector<table::SceneBall>& balls,
                                                      const cue_command_t& command,
                                                      const physics::ModelParameters& plant) {
  std::vector<table::SceneBall> struck = balls;
  if (command.status == cue_command_t::STATUS_OK) {
    const physics::CueStroke stroke = Executed(command);
    for (table::SceneBall& b : struck) {
      if (b.id == kCueBall) b = table::Struck(b.id, stroke, b.state.head<2>(), plant);
    }
  }
  return struck;
}

table::TableSimulationOptions SceneMotion(const physics::ModelParameters& plant) {
  table::TableSimulationOptions motion;
  motion.five_dof = model_choice::TableMotion(plant);
  return motion;
}

table::TableSimulation PlayedToRest(const table::TableGeometry& geometry,
                                    const physics::ModelParameters& plant,
                                    const std::vector<table::SceneBall>& struck,
                                    const table::TableSimulationOptions& motion) {
  table::TableSimulation sim(geometry, plant, struck, motion);
  sim.Run(kLongestScene);
  return sim;
}

}  // namespace billiard::table_sim_node
