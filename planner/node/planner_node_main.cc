// planner_node: the shot planner on LCM (planner_node.h), until SIGINT or SIGTERM.
#include "lcmtypes/node/node_command_line.h"
#include "planner/node/planner_node_command.h"

int main(int argc, char** argv) {
  CLI::App app{"planner_node: answers SHOT_REQUEST with CUE_COMMAND from the latest TABLE_STATE"};
  billiard::nodes::OneLineErrors(app, "planner_node");
  billiard::nodes::VersionFlag(app, "planner_node");
  billiard::planner_node::PlannerNodeCommandLine line;
  billiard::planner_node::AddPlannerNodeOptions(app, &line);
  if (auto status = billiard::nodes::ParseCommandLine(app, argc, argv)) return *status;
  return billiard::planner_node::RunPlannerNodeCommand(line);
}
