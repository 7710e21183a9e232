// estimator_node: the vision estimator on LCM (estimator_node.h), until SIGINT or SIGTERM.
#include "estimator/node/estimator_node_command.h"
#include "lcmtypes/node/node_command_line.h"

int main(int argc, char** argv) {
  CLI::App app{"estimator_node: CAMERA_IMAGE frames in, tracked balls out as TABLE_STATE"};
  billiard::nodes::OneLineErrors(app, "estimator_node");
  billiard::nodes::VersionFlag(app, "estimator_node");
  billiard::estimator_node::EstimatorNodeCommandLine line;
  billiard::estimator_node::AddEstimatorNodeOptions(app, &line);
  if (auto status = billiard::nodes::ParseCommandLine(app, argc, argv)) return *status;
  return billiard::estimator_node::RunEstimatorNodeCommand(line);
}
