// table_sim_node: a session of shots through the estimator and planner nodes (table_sim_node.h);
// prints the summary as JSON on stdout, the shots as they go on stderr.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>
#include <lcm/lcm-cpp.hpp>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "camera_model.h"
#include "estimator_node.h"
#include "node_loop.h"
#include "parameters.h"
#include "planner_node.h"
#include "table_sim_node.h"

int main(int argc, char** argv) {
  std::string lcm_url, params_name = "pool", noise = "off";
  billiard::TableSimOptions options;
  bool realtime = false, in_process = false;
  CLI::App app{"table_sim_node: stands in for the robot and the camera, drives a session of shots"};
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return "table_sim_node: " + std::string(e.what()) + " (see --help)\n";
  });
  app.add_option("--lcm-url", lcm_url, "LCM URL (default: $LCM_DEFAULT_URL, else LCM's default)");
  app.add_option("--params", params_name, "paper | pool | path to a JSON parameter file")
      ->capture_default_str();
  app.add_option("--shots", options.shots, "Shots to random targets")->capture_default_str();
  app.add_option("--seed", options.seed, "Seed of the targets and the noise")->capture_default_str();
  app.add_option("--noise", noise, "Execution noise of the robot: on (speed 1 %, heading 0.1 deg, "
                                   "tip 0.5 mm) or off")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  app.add_option("--camera-rate", options.camera_rate, "Frames per second")->capture_default_str();
  app.add_flag("--realtime", realtime, "Real time instead of lockstep");
  billiard::FaultInjection& faults = options.faults;
  app.add_option("--drop-frames", faults.drop_frames,
                 "Fault injection: probability a frame is lost")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--reorder-frames", faults.reorder_frames,
                 "Fault injection: probability a frame is sent after the next")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--duplicate", faults.duplicate,
                 "Fault injection: probability a frame or a request is sent twice")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--fault-seed", faults.seed, "Seed of the fault injection")->capture_default_str();
  app.add_option("--reply-timeout", options.reply_timeout,
                 "Longest wait for the estimator or the planner [s]")
      ->capture_default_str();
  app.add_flag("--in-process", in_process,
               "Run the estimator and planner nodes in this process on LCM's in-memory provider "
               "(where the nodes cannot talk over UDP multicast)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (options.shots < 1 || !(options.camera_rate > 0.0) || !(options.reply_timeout > 0.0)) {
    std::cerr << "table_sim_node: --shots, --camera-rate and --reply-timeout must be positive"
              << std::endl;
    return 2;
  }
  if (faults.drop_frames + faults.reorder_frames + faults.duplicate > 1.0) {
    std::cerr << "table_sim_node: the fault probabilities add up to more than 1" << std::endl;
    return 2;
  }
  options.lockstep = !realtime;
  if (noise == "on") options.noise = {0.01, 0.1 * M_PI / 180.0, 0.5e-3};
  billiard::ModelParameters params;
  try {
    params = billiard::LoadParameters(params_name);
  } catch (const std::invalid_argument& e) {
    std::cerr << "table_sim_node: --params: " << e.what() << std::endl;
    return 2;
  }
  billiard::nodes::StopOnSignals();
  if (in_process) lcm_url = "memq://";
  lcm::LCM lcm(lcm_url);
  if (!lcm.good()) {
    std::cerr << "table_sim_node: cannot initialise LCM" << std::endl;
    return 1;
  }
  const auto start = std::chrono::steady_clock::now();
  const billiard::CameraModel camera = billiard::CameraModel::Overhead(params.table, 1280, 720);
  // In one process the nodes answer inside the simulator's waits: handling a frame publishes the
  // estimator's state, handling a request the planner's command.
  std::unique_ptr<billiard::estimator::EstimatorNode> estimator;
  std::unique_ptr<billiard::planner::PlannerNode> planner;
  if (in_process) {
    estimator = std::make_unique<billiard::estimator::EstimatorNode>(lcm, camera, params);
    planner = std::make_unique<billiard::planner::PlannerNode>(lcm, params);
  }
  billiard::TableSimNode node(lcm, params, camera, options);
  if (in_process) {
    node.RunAlongside([&] {
      estimator->Work();
      return planner->Work();
    });
  }
  std::vector<billiard::ShotResult> shots;
  try {
    shots = node.Run();
  } catch (const std::runtime_error& e) {
    std::cerr << "table_sim_node: " << e.what() << std::endl;
    return billiard::nodes::StopRequested() ? 130 : 1;
  }
  nlohmann::json j;
  std::vector<double> misses;
  for (const billiard::ShotResult& s : shots) {
    nlohmann::json shot = {{"target", {s.target.x(), s.target.y()}},
                           {"final", {s.final_point.x(), s.final_point.y()}},
                           {"miss_m", s.miss_m},
                           {"plan_ms", s.plan_ms},
                           {"status", s.status},
                           {"retries", s.retries}};
    if (!s.reason.empty()) shot["reason"] = s.reason;
    j["shots"].push_back(shot);
    misses.push_back(s.miss_m);
  }
  std::sort(misses.begin(), misses.end());
  const std::size_t n = misses.size();
  j["median_miss_m"] = n % 2 ? misses[n / 2] : 0.5 * (misses[n / 2 - 1] + misses[n / 2]);
  j["max_miss_m"] = misses.back();
  double mean = 0.0, spread = 0.0;
  for (double m : misses) mean += m / n;
  for (double m : misses) spread += (m - mean) * (m - mean) / n;
  j["mean_miss_m"] = mean;
  j["stddev_miss_m"] = std::sqrt(spread);
  const billiard::node_status_t health = node.health().TakeStatus();
  for (int i = 0; i < health.num_counters; ++i) {
    j["counters"][health.counter_names[i]] = health.counter_values[i];
  }
  j["received"] = health.received;
  j["dropped"] = health.dropped;
  j["wall_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << j.dump() << std::endl;
  return 0;
}
