#include "tools/billiard/detect_command.h"

#include <array>
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
#include "estimator/table_fallback.h"
#include "estimator/table_finder.h"
#include "lcmtypes/image_codec.h"
#include "sim/camera/camera_model.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/scene_file.h"
#include "sim/params/table_specs.h"
#include "tools/billiard/command_line.h"
#include "tools/billiard/detect_options.h"
#include "tools/billiard/detected_scene.h"
#include "tools/billiard/image_files.h"
#include "tools/billiard/scene_commands.h"

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
  std::string identity = "rules", identity_model;
  std::string scene_out;
  std::string table = params::kDefaultTable;
  double ball_radius_px = 0;
  bool json = false;
};

nlohmann::json Points(const std::array<Eigen::Vector2d, 4>& corners) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& c : corners) list.push_back({c.x(), c.y()});
  return list;
}

// The lens the table was found through (lens_estimate.h): k1 at its assumed focal length about
// its centre; k1 = 0 for a pinhole.
nlohmann::json LensJson(const estimator::RadialLens& lens) {
  if (lens.IsPinhole()) return {{"k1", 0.0}};
  return {{"k1", lens.k1},
          {"focal_px", lens.focal_px},
          {"centre", {lens.centre.x(), lens.centre.y()}}};
}

// The table the balls were looked for on, as JSON (null where only the cloth was found); with a
// calibration, how far the playing surface's corners found in the frame (independently of the
// calibration, null where none is found) are from where the calibration puts them [px].
nlohmann::json TableJson(const estimator::BallDetector& detector, const cv::Mat& image,
                         const std::optional<camera::CameraModel>& camera,
                         const physics::ModelParameters& params) {
  if (!detector.knows_table()) return nullptr;
  const estimator::TableRegion& table = *detector.table();
  nlohmann::json j = {{"corners", Points(table.corners)},
                      {"cloth_corners", Points(table.cloth_corners)},
                      {"from", estimator::TableOriginName(table.origin)},
                      {"view", estimator::TableViewName(table.view)},
                      {"depth_ratio", table.depth_ratio},
                      {"side_fit_rms_px", table.side_fit_rms_px},
                      {"lens", LensJson(table.lens)},
                      {"side_out_of_frame", table.side_out_of_frame}};
  if (camera) {
    const estimator::TableSearch found = estimator::FindTable(image);
    j["calibration_disagreement_px"] =
        found.table ? nlohmann::json(estimator::CalibrationDisagreementPx(*found.table, *camera,
                                                                          params.table))
                    : nlohmann::json(nullptr);
  }
  return j;
}

// Which part of the table the cloth alone shows: each edge of the frame the cloth runs out
// through, with the share of the edge it takes.
nlohmann::json ClothAtFrameEdgesJson(const estimator::TableRegion& cloth) {
  const std::array<double, 4> shares = estimator::ClothAtFrameEdges(cloth);
  nlohmann::json edges = nlohmann::json::object();
  for (std::size_t i = 0; i < shares.size(); ++i) edges[estimator::kFrameEdges[i]] = shares[i];
  return edges;
}

nlohmann::json BallsJson(const std::vector<estimator::BallDetection>& balls,
                         const std::optional<camera::CameraModel>& camera,
                         const physics::ModelParameters& params) {
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
  return list;
}

// --scene-out: the balls on the table as a scene (detected_scene.h); refused (exit 3, nothing
// written) when they make none.
void WriteScene(const DetectArgs& args, const std::vector<estimator::BallDetection>& balls,
                const camera::CameraModel& camera, const physics::ModelParameters& params) {
  std::vector<DetectedBall> detected;
  for (const auto& b : balls) {
    detected.push_back({camera.Unproject(b.pixel, params.ball.radius).head<2>(), b.ball_class});
  }
  const table::TableGeometry table = LoadTableOption(args.table);
  std::vector<std::string> notes;
  params::SceneFile scene;
  try {
    scene = DetectedScene(detected, table, args.table, args.params, params.ball.radius, &notes);
  } catch (const std::invalid_argument& e) {
    throw Refused(std::string("the balls found make no scene: ") + e.what() +
                  " (no scene written)");
  }
  for (const auto& note : notes) std::cerr << "billiard: --scene-out: " << note << std::endl;
  std::ofstream out(args.scene_out);
  if (!(out << params::SceneJson(scene) << "\n")) {
    throw UsageError("--scene-out: cannot write '" + args.scene_out + "'");
  }
}

// The detector's options: the balls' set, and the calibration's ball radius and table.
estimator::DetectorOptions OptionsFor(const DetectArgs& args, const physics::ModelParameters& params,
                                      const std::optional<camera::CameraModel>& camera,
                                      const cv::Mat& image) {
  estimator::DetectorOptions options;
  options.ball_set = BallSetOption(args.ball_set, params);
  if (!args.ball_model.empty()) UseBallModel(args.ball_model, args.ball_set, &options);
  options.identity.classifier = IdentityOption(args.identity, args.identity_model);
  options.ball_radius_px = args.ball_radius_px;
  if (!camera) return options;
  RequireCalibrationOfThisSize(*camera, image, args.calib);
  const double predicted_px = estimator::ExpectedRadiusPx(*camera, params.ball.radius);
  WarnIfTheBallRadiusDisagrees(predicted_px, image);
  if (options.ball_radius_px == 0) options.ball_radius_px = predicted_px;
  options.calibrated = estimator::CalibratedTable{*camera, params.table,
                                                  estimator::NoseHeight(params.ball.radius)};
  return options;
}

// What `detect` found (`j`, its JSON) as a person reads it: the table and how it was had, then a
// line a ball: its class and sureness, where it is in the image and, calibrated, on the table.
void PrintDetections(const nlohmann::json& j, const std::string& image) {
  constexpr double kUsPerMs = 1000.0;
  std::cerr << "detect: " << j["balls"].size() << " balls in " << image << " (radius "
            << Fixed(j["radius_px"].get<double>(), 1) << " px, "
            << Fixed(j["detect_us"].get<double>() / kUsPerMs, 0) << " ms)\n";
  const nlohmann::json& table = j["table"];
  if (table.is_null()) {
    std::cerr << "  table   not found (" << j["no_table"].get<std::string>()
              << "): the balls on the cloth, in image coordinates only\n";
    for (const auto& [edge, share] : j["cloth_at_frame_edges"].items()) {
      if (share.get<double>() > 0) {
        std::cerr << "  cloth   runs out of the frame along " << Fixed(100 * share.get<double>(), 0)
                  << " % of the frame's " << edge << " edge\n";
      }
    }
  } else {
    std::cerr << "  table   " << table["view"].get<std::string>() << " view ("
              << table["from"].get<std::string>() << "), its sides fitted to "
              << Fixed(table["side_fit_rms_px"].get<double>(), 1) << " px RMS";
    const double k1 = table["lens"]["k1"].get<double>();
    if (k1 != 0.0) std::cerr << ", through a lens of k1 " << Fixed(k1, 3);
    const int cut = table["side_out_of_frame"].get<int>();
    if (cut >= 0) {
      std::cerr << ", side " << cut << " beyond the frame (placed by the table's proportions)";
    }
    std::cerr << "\n";
  }
  for (const nlohmann::json& b : j["balls"]) {
    std::cerr << "  " << b["class"].get<std::string>() << " ("
              << Fixed(b["class_confidence"].get<double>(), 2) << ") at "
              << Fixed(b["u"].get<double>(), 1) << ", " << Fixed(b["v"].get<double>(), 1) << " px";
    if (b.contains("x")) {
      std::cerr << " = " << Fixed(b["x"].get<double>(), 3) << ", " << Fixed(b["y"].get<double>(), 3)
                << " m";
    }
    std::cerr << ", score " << Fixed(b["score"].get<double>(), 2) << "\n";
  }
}

void RunDetect(const DetectArgs& args) {
  const physics::ModelParameters params = LoadParametersOption(args.params);
  const std::optional<camera::CameraModel> camera = CalibrationOption(args.calib);
  RequireBallRadiusOption(args.ball_radius_px);
  if (!args.scene_out.empty() && !camera) {
    throw UsageError("--scene-out: needs --calib (a scene is in table coordinates)");
  }
  const cv::Mat image = ReadImage(args.image);
  estimator::BallDetector detector(OptionsFor(args, params, camera, image));
  const auto start = std::chrono::steady_clock::now();
  const auto balls = detector.Detect(image);
  const double us =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
  // No cloth either: the frame's answer is no, and why.
  if (!detector.table()) throw Refused(detector.failure() + " in " + args.image);
  // No table but its cloth: the balls on it, in image coordinates, and why no table.
  if (!detector.knows_table()) {
    std::cerr << "billiard: warning: " << detector.failure() << " in " << args.image
              << ": the balls on the cloth, in image coordinates only" << std::endl;
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
  if (!args.scene_out.empty()) WriteScene(args, balls, *camera, params);
  const nlohmann::json list = BallsJson(balls, camera, params);
  const nlohmann::json table = TableJson(detector, image, camera, params);
  nlohmann::json j = {
      {"balls", list}, {"table", table}, {"radius_px", detector.radius_px()}, {"detect_us", us}};
  if (!detector.knows_table()) {
    j["no_table"] = detector.failure();
    j["cloth_at_frame_edges"] = ClothAtFrameEdgesJson(*detector.table());
  }
  if (args.json) {
    std::cout << j.dump() << std::endl;
  } else {
    PrintDetections(j, args.image);
  }
}

}  // namespace

void AddDetectCommand(CLI::App& app) {
  auto args = std::make_shared<DetectArgs>();
  CLI::App* cmd = app.add_subcommand("detect", "Find the balls in a camera frame");
  cmd->add_option("image", args->image, "Image file (PNG, JPEG, ...)")->required();
  cmd->add_option("--calib", args->calib,
                  "Camera JSON (billiard calibrate): adds table x, y, sets the ball radius and "
                  "the table (never looked for: an arm across it is no matter)");
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
  AddIdentityOptions(cmd, &args->identity, &args->identity_model);
  cmd->add_option("--overlay", args->overlay,
                  "Also write the frame with the table and the detections drawn on it (PNG or "
                  "JPEG)");
  cmd->add_option("--scene-out", args->scene_out,
                  "With --calib: also write the balls as a scene JSON (as simulate --scene, "
                  "plan-pot --scene, choose-shot --scene read), ids from their classes");
  cmd->add_option("--table", args->table, "The table the scene of --scene-out names")
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args] { RunDetect(*args); });
}

}  // namespace billiard::cli
