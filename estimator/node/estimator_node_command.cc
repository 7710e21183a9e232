#include "estimator/node/estimator_node_command.h"

#include <iostream>
#include <memory>
#include <stdexcept>

#include "estimator/node/estimator_node.h"
#include "lcmtypes/node/node_loop.h"
#include "sim/camera/camera_model.h"
#include "sim/params/parameter_sets.h"

namespace billiard::estimator_node {

void AddEstimatorNodeOptions(CLI::App& app, EstimatorNodeCommandLine* line) {
  app.add_option("--lcm-url", line->lcm_url,
                 "LCM URL (default: $LCM_DEFAULT_URL, else LCM's default)");
  app.add_option("--params", line->params, "paper | pool | path to a JSON parameter file")
      ->capture_default_str();
  app.add_option("--camera", line->camera,
                 "Camera model JSON (billiard calibrate): the rig's calibration, whose table the "
                 "balls are looked for on (never looked for itself); default: the overhead camera "
                 "of the table simulator at --width x --height, the table found in the frames");
  app.add_option("--width", line->width, "Image width without --camera [px]")
      ->capture_default_str();
  app.add_option("--height", line->height, "Image height without --camera [px]")
      ->capture_default_str();
}

int RunEstimatorNodeCommand(const EstimatorNodeCommandLine& line) {
  physics::ModelParameters params;
  camera::CameraModel camera;
  try {
    params = params::LoadParameters(line.params);
    camera = line.camera.empty()
                 ? camera::CameraModel::Overhead(params.table, line.width, line.height)
                 : camera::LoadCameraModel(line.camera);
  } catch (const std::invalid_argument& e) {
    std::cerr << "estimator_node: " << e.what() << std::endl;
    return 2;
  }
  return nodes::RunNodeUntilStopped("estimator_node", line.lcm_url, [&](lcm::LCM& lcm) {
    estimator::EstimatorOptions options;
    // A camera file is the rig's calibration: its table is used, never looked for.
    options.table_from_camera = !line.camera.empty();
    auto node = std::make_shared<EstimatorNode>(lcm, camera, params, options);
    std::cerr << "estimator_node: " << params::ParameterSetLabel(params) << " parameters, "
              << camera.width << "x" << camera.height << " camera, LCM "
              << nodes::DescribeUrl(line.lcm_url) << std::endl;
    return [node] { return node->Work(); };
  });
}

}  // namespace billiard::estimator_node
