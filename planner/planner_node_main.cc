// planner_node: the shot planner on LCM (planner_node.h), until SIGINT or SIGTERM.
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstring>
#include <iostream>
#include <lcm/lcm-cpp.hpp>
#include <stdexcept>
#include <string>

#include "parameters.h"
#include "planner_node.h"

namespace {

volatile std::sig_atomic_t stop_requested = 0;

void RequestStop(int) { stop_requested = 1; }

// Without SA_RESTART, so that the signal also ends the wait in handleTimeout at once.
void StopOn(int signal_number) {
  struct sigaction action {};
  action.sa_handler = RequestStop;
  sigemptyset(&action.sa_mask);
  sigaction(signal_number, &action, nullptr);
}

int Fail(const std::string& reason, int status) {
  std::cerr << "planner_node: " << reason << std::endl;
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  std::string lcm_url, params_name = "paper";
  billiard::planner::PlannerNodeOptions options;
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
  app.add_flag("--no-refine", no_refine, "Plan with the closed-form inverse alone");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (!(std::isfinite(options.max_ball_speed) && options.max_ball_speed >= 0.0)) {
    return Fail("--max-ball-speed must be a finite speed >= 0", 2);
  }
  options.planner.refine = !no_refine;
  billiard::ModelParameters params;
  try {
    params = billiard::LoadParameters(params_name);
  } catch (const std::invalid_argument& e) {
    return Fail(std::string("--params: ") + e.what(), 2);
  }

  StopOn(SIGINT);
  StopOn(SIGTERM);
  lcm::LCM lcm(lcm_url);
  const std::string url_name = lcm_url.empty() ? "the default URL" : "'" + lcm_url + "'";
  if (!lcm.good()) return Fail("cannot initialise LCM with " + url_name, 1);

  billiard::planner::PlannerNode node(lcm, params, options);
  std::cerr << "planner_node: " << params.name << " parameters, LCM " << url_name
            << ", answering " << billiard::planner::kShotRequestChannel << std::endl;
  while (!stop_requested) {
    errno = 0;
    if (lcm.handleTimeout(100) < 0 && errno != EINTR && !stop_requested) {
      return Fail(std::string("LCM stopped working") + (errno ? ": " : "") +
                      (errno ? std::strerror(errno) : ""), 1);
    }
  }
  std::cerr << "planner_node: stopped" << std::endl;
  return 0;
}
