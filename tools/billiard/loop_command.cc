#include "tools/billiard/loop_command.h"

#include <memory>

#include "estimator/node/estimator_node.h"
#include "planner/node/planner_node.h"
#include "sim/table_sim_node/session.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

namespace {

// The estimator and the planner on the session's LCM: handling a frame publishes the estimator's
// state, handling a request the planner's command, inside the simulator's waits.
std::function<bool()> EstimatorAndPlanner(lcm::LCM& lcm, const physics::ModelParameters& params,
                                          const camera::CameraModel& camera) {
  auto estimator = std::make_shared<estimator_node::EstimatorNode>(lcm, camera, params);
  auto planner = std::make_shared<planner_node::PlannerNode>(lcm, params);
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
  cmd->callback([line] {
    line->lcm_url = "memq://";
    const int status =
        table_sim_node::RunSessionCommand("billiard loop", *line, EstimatorAndPlanner);
    if (status != 0) throw ExitStatus(status);
  });
}

}  // namespace billiard::cli
