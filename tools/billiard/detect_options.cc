#include "tools/billiard/detect_options.h"

#include <stdexcept>

#include "estimator/ball_model.h"
#include "estimator/identity_classifier.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

namespace {

std::string ImageSize(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

}  // namespace

std::optional<camera::CameraModel> CalibrationOption(const std::string& path) {
  if (path.empty()) return std::nullopt;
  try {
    return camera::LoadCameraModel(path);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--calib: ") + e.what());
  }
}

void RequireCalibrationOfThisSize(const camera::CameraModel& camera, const cv::Mat& image,
                                  const std::string& calib) {
  if (camera.width == image.cols && camera.height == image.rows) return;
  throw UsageError("--calib: '" + calib + "' calibrates " + ImageSize(camera.width, camera.height) +
                   " frames, the image is " + ImageSize(image.cols, image.rows));
}

void RequireBallRadiusOption(double radius_px) {
  RequireFinite(radius_px, "--ball-radius-px");
  if (radius_px < 0) throw UsageError("--ball-radius-px: must be positive");
}

estimator::BallSet BallSetOption(const std::string& name, const physics::ModelParameters& params) {
  if (name.empty()) return estimator::BallSetOf(params.name);
  if (const auto set = estimator::BallSetNamed(name)) return *set;
  throw UsageError("--ball-set: '" + name + "' is none of " + estimator::kBallSetNames);
}

void UseBallModel(const std::string& path, const std::string& ball_set_option,
                  estimator::DetectorOptions* options) {
  estimator::BallModel model;
  try {
    model = estimator::LoadBallModel(path);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--ball-model: ") + e.what());
  }
  if (!ball_set_option.empty() && estimator::BallSetNamed(ball_set_option) != model.set) {
    throw UsageError("--ball-model: '" + path + "' is a model of " +
                     estimator::BallSetName(model.set) + " balls, --ball-set says " +
                     ball_set_option);
  }
  options->ball_set = model.set;
  options->identity = model.identity;
}

std::shared_ptr<const estimator::IdentityClassifier> IdentityOption(const std::string& mode,
                                                                    const std::string& model_path) {
  if (mode == "rules") {
    if (!model_path.empty()) throw UsageError("--identity-model needs --identity model");
    return nullptr;
  }
  if (mode != "model") {
    throw UsageError("--identity: '" + mode + "' is none of " + kIdentityModes);
  }
  if (model_path.empty()) return estimator::BuiltinIdentityClassifier();
  try {
    return std::make_shared<const estimator::IdentityClassifier>(
        estimator::IdentityClassifier::Load(model_path));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--identity-model: ") + e.what());
  }
}

void AddIdentityOptions(CLI::App* command, std::string* mode, std::string* model_path) {
  command
      ->add_option("--identity", *mode,
                   "rules | model: name the balls by the hand-set colours and shares, or by the "
                   "classifier fitted on rendered balls (billiard train-identity)")
      ->capture_default_str();
  command->add_option("--identity-model", *model_path,
                      "The classifier's file for --identity model (default: the built-in one)");
}

}  // namespace billiard::cli
