// planner_node: the shot planner on LCM (planner_node.h), until SIGINT or SIGTERM.
#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>
#include <lcm/lcm-cpp.hpp>
#include <stdexcept>
#include <string>

#include "lcmtypes/names.h"
#include "lcmtypes/node/node_loop.h"
#include "planner/node/planner_node.h"
#include "sim/params/parameter_sets.h"
#include "sim/physics/parameters.h"

namespace {

int Fail(const std::string& reason, int status) {
  std::cerr << "planner_node: " << reason << std::endl;
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  std::string lcm_url, params_name = "paper";
  billiard::planner_node::PlannerNodeOptions options;
  bool no_refine = false;
  CLI::App app{"planner_node: answers SHOT_REQUEST with CUE_COMMAND from the latest TABLE_STATE"};
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return "planner_node: " + std::string(e.what()) + " (see --help)\n";
  });
  app.add_option("--lcm-url", lcm_url,
                 "LCM URL, e.g. udpm://239.255.76.67:7667?ttl=0 (default: $LCM_DEFAULT_URL, else "
                 "LCM's default)");
  app.add_option("--params", params_name, "paper | pool | path to a JSON parameter file")
      ->capture_default_str();
  app.add_option("--max-ball-speed", options.max_ball_speed,
                 "Refuse to plan for a ball faster than this [m/s]")
      ->capture_default_str();
  app.add_option("--max-state-age", options.max_state_age,
                 "Refuse to plan from a ball state further than this from the request in time [s]")
      ->capture_default_str();
  app.add_option("--queue-capacity", options.queue_capacity,
                 "Requests waiting to be planned; more are answered busy")
      ->capture_default_str();
  app.add_flag("--no-refine", no_refine, "Plan with the closed-form inverse alone");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (!(std::isfinite(options.max_ball_speed) && options.max_ball_speed >= 0.0)) {
    return Fail("--max-ball-speed must be a finite speed >= 0", 2);
  }
  if (!(std::isfinite(options.max_state_age) && options.max_state_age > 0.0)) {
    return Fail("--max-state-age must be a finite time > 0", 2);
  }
  if (options.queue_capacity < 1) return Fail("--queue-capacity must be at least 1", 2);
  options.planner.refine = !no_refine;
  billiard::physics::ModelParameters params;
  try {
    params = billiard::params::LoadParameters(params_name);
  } catch (const std::invalid_argument& e) {
    return Fail(std::string("--params: ") + e.what(), 2);
  }

  billiard::nodes::StopOnSignals();
  lcm::LCM lcm(lcm_url);
  const std::string url_name = billiard::nodes::DescribeUrl(lcm_url);
  if (!lcm.good()) return Fail("cannot initialise LCM with " + url_name, 1);

  billiard::planner_node::PlannerNode node(lcm, params, options);
  std::cerr << "planner_node: " << params.name << " parameters, LCM " << url_name << ", answering "
            << billiard::messages::kShotRequestChannel << std::endl;
  return billiard::nodes::HandleUntilStopped(lcm, "planner_node", [&node] { return node.Work(); });
}
