#include "tools/billiard/detect_command.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <optional>

#include "estimator/ball_detector.h"
#include "estimator/table_calibration.h"
#include "sim/camera/camera_model.h"
#include "sim/params/parameter_sets.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

namespace {

// The frame at `path`; a missing, unreadable or empty image is the user's error.
cv::Mat ReadImage(const std::string& path) {
  // Checked first: OpenCV would add a warning line of its own about a missing file.
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw UsageError("cannot read an image from '" + path + "': no such file");
  }
  const cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
  if (image.empty()) throw UsageError("cannot read an image from '" + path + "'");
  return image;
}

struct DetectArgs {
  std::string image, calib, params = params::kDefaultParameterSet;
  double ball_radius_px = 0;
  bool json = false;
};

void RunDetect(const DetectArgs& args) {
  const physics::ModelParameters params = LoadParametersOption(args.params);
  std::optional<camera::CameraModel> camera;
  if (!args.calib.empty()) {
    try {
      camera = camera::LoadCameraModel(args.calib);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--calib: ") + e.what());
    }
  }
  RequireFinite(args.ball_radius_px, "--ball-radius-px");
  if (args.ball_radius_px < 0) throw UsageError("--ball-radius-px: must be positive");
  const cv::Mat image = ReadImage(args.image);

  estimator::DetectorOptions options;
  options.ball_radius_px = args.ball_radius_px;
  if (options.ball_radius_px == 0 && camera) {
    options.ball_radius_px = estimator::ExpectedRadiusPx(*camera, params.ball.radius);
  }
  estimator::BallDetector detector(options);
  const auto start = std::chrono::steady_clock::now();
  const auto balls = detector.Detect(image);
  const double us =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();

  nlohmann::json list = nlohmann::json::array();
  for (const auto& b : balls) {
    nlohmann::json j = {{"u", b.pixel.x()}, {"v", b.pixel.y()}, {"radius_px", b.radius_px},
                        {"score", b.score}};
    if (camera) {
      const Eigen::Vector3d p = camera->Unproject(b.pixel, params.ball.radius);
      j["x"] = p.x();
      j["y"] = p.y();
    }
    list.push_back(j);
  }
  if (args.json) {
    std::cout << nlohmann::json{{"balls", list}, {"radius_px", detector.radius_px()},
                                {"detect_us", us}}
                     .dump()
              << std::endl;
  } else {
    std::cerr << balls.size() << " balls in " << args.image << " (radius " << detector.radius_px()
              << " px, " << us << " us)\n";
    for (const auto& j : list) std::cerr << "  " << j.dump() << "\n";
  }
}

struct CalibrateArgs {
  std::string image, out, params = params::kDefaultParameterSet, markers;
  double margin = 0.1, height = 0.04, fx = 0;
  bool json = false;
};

void RunCalibrate(const CalibrateArgs& args) {
  const physics::ModelParameters params = LoadParametersOption(args.params);
  for (const auto& [value, what] : {std::pair{args.margin, "--marker-margin"},
                                    std::pair{args.height, "--marker-height"},
                                    std::pair{args.fx, "--fx"}}) {
    RequireFinite(value, what);
  }
  if (args.fx < 0) throw UsageError("--fx: must be positive");
  const cv::Mat image = ReadImage(args.image);
  camera::CameraModel intrinsics;
  if (args.fx > 0) {
    intrinsics.fx = intrinsics.fy = args.fx;
    intrinsics.cx = 0.5 * (image.cols - 1);
    intrinsics.cy = 0.5 * (image.rows - 1);
  }
  estimator::MarkerLayout layout =
      estimator::MarkerLayout::AroundTable(params.table, args.margin, args.height);
  if (!args.markers.empty()) {
    const auto xy = ParseNumberList(args.markers, 8, "--markers X1,Y1,...,X4,Y4");
    for (int i = 0; i < 4; ++i) layout.centres[i] = {xy[2 * i], xy[2 * i + 1], args.height};
  }
  const auto result = estimator::CalibrateTable(image, layout, intrinsics);
  if (!result) throw std::runtime_error("did not find all four corner markers in " + args.image);
  std::ofstream out(args.out);
  out << camera::CameraModelJson(result->camera) << "\n";
  if (!out) throw UsageError("--out: cannot write '" + args.out + "'");
  nlohmann::json markers = nlohmann::json::array();
  for (const auto& m : result->markers) markers.push_back({m.x(), m.y()});
  if (args.json) {
    std::cout << nlohmann::json{{"markers", markers},
                                {"rms_reprojection_px", result->rms_reprojection_px},
                                {"out", args.out}}
                     .dump()
              << std::endl;
  } else {
    std::cerr << "markers " << markers.dump() << ", reprojection RMS "
              << result->rms_reprojection_px << " px; camera written to " << args.out << "\n";
  }
}

}  // namespace

void AddDetectCommand(CLI::App& app) {
  auto args = std::make_shared<DetectArgs>();
  CLI::App* cmd = app.add_subcommand("detect", "Find the balls in a camera frame");
  cmd->add_option("image", args->image, "Image file (PNG, JPEG, ...)")->required();
  cmd->add_option("--calib", args->calib,
                  "Camera JSON (billiard calibrate): adds table x, y and sets the ball radius");
  cmd->add_option("--ball-radius-px", args->ball_radius_px,
                  "Expected ball radius [px] (default: from --calib, else estimated)");
  cmd->add_option("--params", args->params, "paper | pool | JSON file: the ball radius")
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args] { RunDetect(*args); });
}

void AddCalibrateCommand(CLI::App& app) {
  auto args = std::make_shared<CalibrateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "calibrate", "The camera pose over the table from the four corner markers in a frame");
  cmd->add_option("image", args->image, "Image file")->required();
  cmd->add_option("--out", args->out, "Camera JSON file to write")->required();
  cmd->add_option("--params", args->params, "paper | pool | JSON file: the table size")
      ->capture_default_str();
  cmd->add_option("--marker-margin", args->margin,
                  "Marker centres this far [m] outside each playing-surface corner, diagonally")
      ->capture_default_str();
  cmd->add_option("--markers", args->markers,
                  "The markers' table X,Y [m], image order: top-left, top-right, bottom-right, "
                  "bottom-left (instead of --marker-margin)");
  cmd->add_option("--marker-height", args->height, "Marker height above the cloth [m]")
      ->capture_default_str();
  cmd->add_option("--fx", args->fx, "Focal length guess [px] (default: the image width)");
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args] { RunCalibrate(*args); });
}

}  // namespace billiard::cli
