// estimator_node: the vision estimator on LCM (estimator_node.h), until SIGINT or SIGTERM.
#include <CLI/CLI.hpp>
#include <iostream>
#include <lcm/lcm-cpp.hpp>
#include <stdexcept>
#include <string>

#include "estimator/node/estimator_node.h"
#include "lcmtypes/node/node_loop.h"
#include "sim/camera/camera_model.h"
#include "sim/params/parameter_sets.h"
#include "sim/physics/parameters.h"

int main(int argc, char** argv) {
  std::string lcm_url, params_name = "pool", camera_path;
  int width = 1280, height = 720;
  CLI::App app{"estimator_node: CAMERA_IMAGE frames in, tracked balls out as TABLE_STATE"};
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return "estimator_node: " + std::string(e.what()) + " (see --help)\n";
  });
  app.add_option("--lcm-url", lcm_url, "LCM URL (default: $LCM_DEFAULT_URL, else LCM's default)");
  app.add_option("--params", params_name, "paper | pool | path to a JSON parameter file")
      ->capture_default_str();
  app.add_option("--camera", camera_path,
                 "Camera model JSON (billiard calibrate); default: the overhead camera of the "
                 "table simulator at --width x --height");
  app.add_option("--width", width, "Image width without --camera [px]")->capture_default_str();
  app.add_option("--height", height, "Image height without --camera [px]")->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  billiard::physics::ModelParameters params;
  billiard::camera::CameraModel camera;
  try {
    params = billiard::params::LoadParameters(params_name);
    camera = camera_path.empty()
                 ? billiard::camera::CameraModel::Overhead(params.table, width, height)
                 : billiard::camera::LoadCameraModel(camera_path);
  } catch (const std::invalid_argument& e) {
    std::cerr << "estimator_node: " << e.what() << std::endl;
    return 2;
  }
  billiard::nodes::StopOnSignals();
  lcm::LCM lcm(lcm_url);
  if (!lcm.good()) {
    std::cerr << "estimator_node: cannot initialise LCM with "
              << billiard::nodes::DescribeUrl(lcm_url) << std::endl;
    return 1;
  }
  billiard::estimator_node::EstimatorNode node(lcm, camera, params);
  std::cerr << "estimator_node: " << params.name << " parameters, " << camera.width << "x"
            << camera.height << " camera, LCM " << billiard::nodes::DescribeUrl(lcm_url)
            << std::endl;
  return billiard::nodes::HandleUntilStopped(lcm, "estimator_node",
                                             [&node] { return node.Work(); });
}
