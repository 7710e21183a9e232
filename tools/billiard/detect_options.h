// The options of the commands that find the balls in a frame (`billiard detect`, `billiard
// learn-balls`): the camera's calibration (--calib), the balls' radius (--ball-radius-px), which
// balls the frame holds (--ball-set) and how they look (--ball-model, estimator/ball_model.h).
#pragma once

#include <CLI/CLI.hpp>
#include <opencv2/core.hpp>
#include <memory>
#include <optional>
#include <string>

#include "estimator/ball_class.h"
#include "estimator/ball_detector.h"
#include "sim/camera/camera_model.h"
#include "sim/physics/parameters.h"

namespace billiard::cli {

// The camera of a --calib option (`billiard calibrate`'s JSON `path`), none when it is empty;
// UsageError with the reason for a file that is not one.
std::optional<camera::CameraModel> CalibrationOption(const std::string& path);

// A calibration maps the pixels of its own camera's frames: of another image size, it is another
// camera's (or the frame was scaled), and every position it gave would be wrong. UsageError
// naming `calib` (the file) then.
void RequireCalibrationOfThisSize(const camera::CameraModel& camera, const cv::Mat& image,
                                  const std::string& calib);

// UsageError unless a --ball-radius-px option is finite and not negative (0: measured).
void RequireBallRadiusOption(double radius_px);

// The ball set of a --ball-set option: the set it names, or --params' set when it is empty;
// UsageError for a name that is no set.
estimator::BallSet BallSetOption(const std::string& name, const physics::ModelParameters& params);

// The detector's ball set and identity from the model file of a --ball-model option (`path`):
// its set and its colours and shares. UsageError, with the reason, for a file that is not a
// model, or a --ball-set (`ball_set_option`, empty when not given) that names another set.
void UseBallModel(const std::string& path, const std::string& ball_set_option,
                  estimator::DetectorOptions* options);

// The classifier of an --identity option (`mode`): none for "rules" (the colours and shares
// decide), for "model" the file of --identity-model (`model_path`) or, where it is empty, the
// built-in one (estimator/identity_classifier.h). UsageError for another mode, or a file that is
// not a model.
inline constexpr const char* kIdentityModes = "rules, model";
std::shared_ptr<const estimator::IdentityClassifier> IdentityOption(const std::string& mode,
                                                                    const std::string& model_path);
// Adds --identity and --identity-model to `command`, read into `mode` and `model_path`.
void AddIdentityOptions(CLI::App* command, std::string* mode, std::string* model_path);

}  // namespace billiard::cli
