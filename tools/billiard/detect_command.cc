#include "tools/billiard/detect_command.h"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <sstream>
#include <vector>

#include "estimator/ball_class.h"
#include "estimator/ball_detector.h"
#include "estimator/detection_overlay.h"
#include "estimator/table_calibration.h"
#include "lcmtypes/image_codec.h"
#include "sim/camera/camera_model.h"
#include "sim/params/parameter_sets.h"
#include "tools/billiard/detect_options.h"
#include "tools/billiard/command_line.h"
#include "tools/billiard/image_files.h"

namespace billiard::cli {

namespace {

std::string Pixels(double px) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(1) << px << " px";
  return text.str();
}

// Says on stderr when the ball radius the calibration and --params predict is not that of the
// balls in the frame: the calibration is of another table or camera position, its markers' table
// coordinates are off by a scale, or --params has other balls. The detector, looking for balls
// of the predicted size, then misses some or all of them.
void WarnIfTheBallRadiusDisagrees(double predicted_px, const cv::Mat& image) {
  estimator::BallDetector measuring;  // given no radius, it measures the balls' radius
  measuring.LearnTable(image);
  const double measured_px = measuring.radius_px();
  if (measured_px <= 0) return;  // nothing ball-like: the count of balls found says so
  if (std::abs(predicted_px - measured_px) <= estimator::kMaxBallRadiusMismatch * measured_px) {
    return;
  }
  std::cerr << "billiard: warning: the calibration and --params predict a ball radius of "
            << Pixels(predicted_px) << ", the balls in the frame measure " << Pixels(measured_px)
            << " (more than " << std::lround(100 * estimator::kMaxBallRadiusMismatch)
            << " % apart): is the calibration of this table, camera and ball size?" << std::endl;
}

struct DetectArgs {
  std::string image, calib, params = params::kDefaultParameterSet, overlay, ball_set, ball_model;
  double ball_radius_px = 0;
  bool json = false;
};

nlohmann::json Points(const std::array<Eigen::Vector2d, 4>& corners) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& c : corners) list.push_back({c.x(), c.y()});
  return list;
}

// The table found, as JSON; with a calibration, how far its playing surface's corners are from
// where the calibration puts them [px].
nlohmann::json TableJson(const estimator::TableRegion& table,
                         const std::optional<camera::CameraModel>& camera,
                         const physics::ModelParameters& params) {
  nlohmann::json j = {{"corners", Points(table.corners)},
                      {"cloth_corners", Points(table.cloth_corners)},
                      {"view", estimator::TableViewName(table.view)},
                      {"depth_ratio", table.depth_ratio},
                      {"side_fit_rms_px", table.side_fit_rms_px}};
  if (camera) {
    j["calibration_disagreement_px"] =
        estimator::CalibrationDisagreementPx(table, *camera, params.table);
  }
  return j;
}

void RunDetect(const DetectArgs& args) {
  const physics::ModelParameters params = LoadParametersOption(args.params);
  const std::optional<camera::CameraModel> camera = CalibrationOption(args.calib);
  RequireBallRadiusOption(args.ball_radius_px);
  estimator::DetectorOptions options;
  options.ball_set = BallSetOption(args.ball_set, params);
  if (!args.ball_model.empty()) UseBallModel(args.ball_model, args.ball_set, &options);
  const cv::Mat image = ReadImage(args.image);
  if (camera) RequireCalibrationOfThisSize(*camera, image, args.calib);

  options.ball_radius_px = args.ball_radius_px;
  if (camera) {
    const double predicted_px = estimator::ExpectedRadiusPx(*camera, params.ball.radius);
    WarnIfTheBallRadiusDisagrees(predicted_px, image);
    if (options.ball_radius_px == 0) options.ball_radius_px = predicted_px;
  }
  estimator::BallDetector detector(options);
  const auto start = std::chrono::steady_clock::now();
  const auto balls = detector.Detect(image);
  const double us =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
  // No table, or nothing on it the size of a ball: the frame's answer is no, and why.
  if (!detector.failure().empty()) {
    throw Refused(detector.failure() + " in " + args.image);
  }
  // An empty table is an answer, but not one to give silently.
  if (balls.empty()) {
    std::cerr << "billiard: warning: no balls found in " << args.image << std::endl;
  }
  if (!args.overlay.empty()) {
    cv::Mat overlay = estimator::DetectionOverlay(image, balls);
    estimator::DrawTable(*detector.table(), &overlay);
    if (!cv::imwrite(args.overlay, overlay)) {
      throw UsageError("--overlay: cannot write '" + args.overlay +
                       "' (an image file: .png, .jpg)");
    }
  }
  nlohmann::json list = nlohmann::json::array();
  for (const auto& b : balls) {
    nlohmann::json j = {{"u", b.pixel.x()},
                        {"v", b.pixel.y()},
                        {"radius_px", b.radius_px},
                        {"score", b.score},
                        {"class", estimator::BallClassName(b.ball_class)},
                        {"class_confidence", b.class_confidence}};
    if (camera) {
      const Eigen::Vector3d p = camera->Unproject(b.pixel, params.ball.radius);
      j["x"] = p.x();
      j["y"] = p.y();
    }
    list.push_back(j);
  }
  const nlohmann::json table = TableJson(*detector.table(), camera, params);
  if (args.json) {
    std::cout << nlohmann::json{{"balls", list},
                                {"table", table},
                                {"radius_px", detector.radius_px()},
                                {"detect_us", us}}
                     .dump()
              << std::endl;
  } else {
    std::cerr << balls.size() << " balls in " << args.image << " (radius " << detector.radius_px()
              << " px, " << us << " us); table " << table.dump() << "\n";
    for (const auto& j : list) std::cerr << "  " << j.dump() << "\n";
  }
}

struct CalibrateArgs {
  std::string image, out, params = params::kDefaultParameterSet, markers;
  double margin = 0.1, height = 0.04, fx = 0;
  double max_reprojection_px = estimator::kMaxReprojectionPx;
  bool json = false;
};

// A pose that does not reproject the markers where they were found is not the camera's: their
// table coordinates (the layout) are not where the photo shows them.
// The refusal says where the markers were found, and where they lie on the table the frame
// shows (estimator::MarkersOnTableSeen): a layout to try.
void RequireAFit(const estimator::CalibrationResult& result, double max_reprojection_px,
                 const cv::Mat& image, const physics::TableParameters& table, double height) {
  if (result.rms_reprojection_px <= max_reprojection_px) return;
  std::ostringstream found, seen;
  found << std::fixed << std::setprecision(0);
  for (const auto& m : result.markers) found << " (" << m.x() << ", " << m.y() << ")";
  const auto layout = estimator::MarkersOnTableSeen(image, result.markers, table, height);
  if (layout) {
    seen << std::fixed << std::setprecision(3) << "; on the table this frame shows they lie at "
         << "about --markers=";
    for (int i = 0; i < 4; ++i) {
      seen << (i ? "," : "") << layout->centres[i].x() << "," << layout->centres[i].y();
    }
  }
  throw Refused("calibration does not fit: the markers reproject " +
                Pixels(result.rms_reprojection_px) + " (RMS) from where they were found, above " +
                "--max-reprojection-px " + Pixels(max_reprojection_px) +
                "; markers found at (u, v) [px] (top-left, top-right, bottom-right, bottom-left):" +
                found.str() + seen.str() +
                "; check --markers or --marker-margin and --params (no camera file written)");
}

void RunCalibrate(const CalibrateArgs& args) {
  const physics::ModelParameters params = LoadParametersOption(args.params);
  for (const auto& [value, what] :
       {std::pair{args.margin, "--marker-margin"}, std::pair{args.height, "--marker-height"},
        std::pair{args.fx, "--fx"}, std::pair{args.max_reprojection_px, "--max-reprojection-px"}}) {
    RequireFinite(value, what);
  }
  if (args.fx < 0) throw UsageError("--fx: must be positive");
  if (args.max_reprojection_px <= 0) throw UsageError("--max-reprojection-px: must be positive");
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
  // A frame that does not show the markers is an answer about the frame, not a failure.
  if (!result) {
    throw Refused("did not find all four corner markers in " + args.image +
                  " (no camera file written)");
  }
  RequireAFit(*result, args.max_reprojection_px, image, params.table, args.height);
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
  cmd->add_option("--ball-set", args->ball_set,
                  "pool | snooker | carom | blackball (English pool's reds and yellows): the balls' "
                  "classes (default: --params' set)");
  cmd->add_option("--ball-model", args->ball_model,
                  "This rig's look of its balls (billiard learn-balls): names the balls by it "
                  "instead of the hand-set colours; its ball set unless --ball-set");
  cmd->add_option("--overlay", args->overlay,
                  "Also write the frame with the table and the detections drawn on it (PNG or "
                  "JPEG)");
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
  cmd->add_option("--max-reprojection-px", args->max_reprojection_px,
                  "Refuse a pose that reprojects the markers further than this [px, RMS] from "
                  "where they were found (exit 3, as when the four markers are not found)")
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args] { RunCalibrate(*args); });
}

}  // namespace billiard::cli
