// table_sim_node: a session of shots through the estimator and planner nodes (table_sim_node.h);
// prints the summary as JSON on stdout, the shots as they go on stderr.
#include "lcmtypes/node/node_command_line.h"
#include "sim/table_sim_node/session.h"

int main(int argc, char** argv) {
  CLI::App app{"table_sim_node: stands in for the robot and the camera, drives a session of shots"};
  billiard::nodes::OneLineErrors(app, "table_sim_node");
  billiard::nodes::VersionFlag(app, "table_sim_node");
  billiard::table_sim_node::SessionCommandLine line;
  billiard::table_sim_node::AddSessionOptions(app, &line);
  if (auto status = billiard::nodes::ParseCommandLine(app, argc, argv)) return *status;
  return billiard::table_sim_node::RunSessionCommand("table_sim_node", line);
}
