#include "estimator/node/estimator_node_command.h"

#include <iostream>
#include <memory>
#include <stdexcept>

#include "estimator/ball_model.h"
#include "estimator/identity_classifier.h"
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
  app.add_option("--ball-model", line->ball_model,
                 "The rig's look of its balls (billiard learn-balls): names the balls by it "
                 "instead of the hand-set colours");
  app.add_option("--identity", line->identity,
                 "rules | model: name the balls by the colours and shares, or by the classifier "
                 "fitted on rendered balls (billiard train-identity)")
      ->capture_default_str();
  app.add_option("--width", line->width, "Image width without --camera [px]")
      ->capture_default_str();
  app.add_option("--height", line->height, "Image height without --camera [px]")
      ->capture_default_str();
}

namespace {

// The detector's identity from a --ball-model file: its colours and shares, for the parameters'
// ball set (which the estimator names the balls of); std::invalid_argument for a model of
// another set.
estimator::EstimatorOptions WithBallModel(const std::string& path,
                                          const physics::ModelParameters& params) {
  estimator::EstimatorOptions options;
  if (path.empty()) return options;
  estimator::BallModel model;
  try {
    model = estimator::LoadBallModel(path);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("--ball-model: ") + e.what());
  }
  if (model.set != estimator::BallSetOf(params.name)) {
    throw std::invalid_argument("--ball-model: '" + path + "' is a model of " +
                                estimator::BallSetName(model.set) + " balls, --params " +
                                params.name + " has " +
                                estimator::BallSetName(estimator::BallSetOf(params.name)) +
                                " balls");
  }
  options.detector.identity = model.identity;
  return options;
}

}  // namespace

int RunEstimatorNodeCommand(const EstimatorNodeCommandLine& line) {
  physics::ModelParameters params;
  camera::CameraModel camera;
  estimator::EstimatorOptions options;
  try {
    params = params::LoadParameters(line.params);
    camera = line.camera.empty()
                 ? camera::CameraModel::Overhead(params.table, line.width, line.height)
                 : camera::LoadCameraModel(line.camera);
    options = WithBallModel(line.ball_model, params);
    if (line.identity != "rules" && line.identity != "model") {
      throw std::invalid_argument("--identity: '" + line.identity + "' is none of rules, model");
    }
    if (line.identity == "model") {
      options.detector.identity.classifier = estimator::BuiltinIdentityClassifier();
    }
    // A camera file is the rig's calibration: its table is used, never looked for.
    options.table_from_camera = !line.camera.empty();
  } catch (const std::invalid_argument& e) {
    std::cerr << "estimator_node: " << e.what() << std::endl;
    return 2;
  }
  return nodes::RunNodeUntilStopped("estimator_node", line.lcm_url, [&](lcm::LCM& lcm) {
    auto node = std::make_shared<EstimatorNode>(lcm, camera, params, options);
    std::cerr << "estimator_node: " << params::ParameterSetLabel(params) << " parameters, "
              << camera.width << "x" << camera.height << " camera, "
              << (line.ball_model.empty() ? "hand-set" : "'" + line.ball_model + "'")
              << " ball colours, identity by " << line.identity << ", LCM "
              << nodes::DescribeUrl(line.lcm_url) << std::endl;
    return [node] { return node->Work(); };
  });
}

}  // namespace billiard::estimator_node
