#include "tools/billiard/loop_command.h"

#include <memory>
#include <stdexcept>
#include <string>

#include "estimator/node/estimator_node.h"
#include "planner/node/planner_node.h"
#include "sim/params/robots.h"
#include "sim/params/scene_file.h"
#include "sim/params/table_specs.h"
#include "sim/table_sim_node/session.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

namespace {

// The estimator and the planner on the session's LCM: handling a frame publishes the estimator's
// state, handling a request the planner's command, inside the simulator's waits. The planner
// pots on the scene file's table (the default table for the break and the shots) and identifies
// the table every `identify_every` shots (0: never), and learns its noise with `learn_noise`, for
// the table simulator's robot.
std::function<bool()> EstimatorAndPlanner(lcm::LCM& lcm, const physics::ModelParameters& params,
                                          const camera::CameraModel& camera,
                                          const table_sim_node::SessionCommandLine& line,
                                          int identify_every, bool learn_noise) {
  const std::string& scene = line.options.scene;
  auto estimator = std::make_shared<estimator_node::EstimatorNode>(lcm, camera, params);
  planner_node::PlannerNodeOptions options;
  options.identify_every = identify_every;
  options.learn_noise = learn_noise;
  try {
    options.pot.robot = params::LoadRobot(line.robot);
  } catch (const std::invalid_argument&) {
    // The session refuses the robot itself, with its reason.
  }
  if (!scene.empty() && scene != "break") {
    try {
      options.table = table::BuildTable(params::LoadTableSpec(params::LoadScene(scene).table));
    } catch (const std::invalid_argument&) {
      // The session refuses the scene itself, with its reason.
    }
  }
  auto planner = std::make_shared<planner_node::PlannerNode>(lcm, params, options);
  return [estimator, planner] {
    estimator->Work();
    return planner->Work();
  };
}

}  // namespace

void AddLoopCommand(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "loop",
      "The closed loop in one process (estimator, planner and table simulator on "
      "memq://); the summary as JSON on stdout, as table_sim_node prints it");
  auto line = std::make_shared<table_sim_node::SessionCommandLine>();
  table_sim_node::AddSessionOptions(*cmd, line.get());
  auto identify_every = std::make_shared<int>(0);
  cmd->add_option("--identify-every", *identify_every,
                  "The planner identifies the sliding friction and the rolling resistance every "
                  "N shots from its own tracked shots (0: never)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  auto learn_noise = std::make_shared<bool>(false);
  cmd->add_flag("--learn-noise", *learn_noise,
                "The planner learns the robot's execution noise from its own strokes and "
                "chooses for it (planner_node --learn-noise)");
  cmd->callback([line, identify_every, learn_noise] {
    line->lcm_url = "memq://";
    const auto nodes = [line, identify_every, learn_noise](
                           lcm::LCM& lcm, const physics::ModelParameters& params,
                           const camera::CameraModel& camera) {
      return EstimatorAndPlanner(lcm, params, camera, *line, *identify_every, *learn_noise);
    };
    const int status = table_sim_node::RunSessionCommand("billiard loop", *line, nodes);
    if (status != 0) throw ExitStatus(status);
  });
}

}  // namespace billiard::cli
