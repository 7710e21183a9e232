// table_sim_node: a session of shots through the estimator and planner nodes (table_sim_node.h);
// prints the summary as JSON on stdout, the shots as they go on stderr.
#include <CLI/CLI.hpp>
#include <string>

#include "sim/table_sim_node/session.h"

int main(int argc, char** argv) {
  CLI::App app{"table_sim_node: stands in for the robot and the camera, drives a session of shots"};
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return "table_sim_node: " + std::string(e.what()) + " (see --help)\n";
  });
  billiard::table_sim_node::SessionCommandLine line;
  billiard::table_sim_node::AddSessionOptions(app, &line);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  return billiard::table_sim_node::RunSessionCommand("table_sim_node", line);
}
