#include "tools/billiard/calibrate_command.h"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <optional>
#include <sstream>
#include <string>

#include "estimator/table_calibration.h"
#include "estimator/table_fallback.h"
#include "estimator/table_pose.h"
#include "sim/camera/camera_model.h"
#include "sim/params/parameter_sets.h"
#include "tools/billiard/command_line.h"
#include "tools/billiard/image_files.h"

namespace billiard::cli {

namespace {

struct CalibrateArgs {
  std::string image, out, params = params::kDefaultParameterSet, markers, corners;
  double margin = 0.1, height = 0.04, fx = 0;
  double max_reprojection_px = estimator::kMaxReprojectionPx;
  bool json = false, from_table = false;
};

std::string Pixels(double px) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(1) << px << " px";
  return text.str();
}

std::string PointList(const std::array<Eigen::Vector2d, 4>& points) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(0);
  for (const auto& m : points) text << " (" << m.x() << ", " << m.y() << ")";
  return text.str();
}

// A pose that does not reproject the markers where they were found is not the camera's: their
// table coordinates (the layout) are not where the photo shows them.
// The refusal says where the markers were found, and where they lie on the table the frame
// shows (estimator::MarkersOnTableSeen): a layout to try.
void RequireAMarkerFit(const estimator::CalibrationResult& result, double max_reprojection_px,
                       const cv::Mat& image, const physics::TableParameters& table,
                       double height) {
  if (result.rms_reprojection_px <= max_reprojection_px) return;
  std::ostringstream seen;
  const auto layout = estimator::MarkersOnTableSeen(image, result.points, table, height);
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
                PointList(result.points) + seen.str() +
                "; check --markers or --marker-margin and --params (no camera file written)");
}

// The table's corners do not make a rectangle of --params' table seen through a pinhole: the
// corners are not the playing surface's (another table's, the rails', a side found wrong), or
// the lens bends the cushions.
void RequireACornerFit(const estimator::CalibrationResult& result, double max_reprojection_px,
                       const std::string& whose) {
  if (result.rms_reprojection_px <= max_reprojection_px) return;
  throw Refused("calibration does not fit: " + whose + " reproject " +
                Pixels(result.rms_reprojection_px) + " (RMS) from where they are, above " +
                "--max-reprojection-px " + Pixels(max_reprojection_px) + "; corners at (u, v) [px]:" +
                PointList(result.points) +
                "; check --corners (in order around the table, the first side a long one) and "
                "--params (no camera file written)");
}

// --corners "x,y;x,y;x,y;x,y": in order around the table, the first side a long one.
estimator::TableCornerPixels GivenCorners(const std::string& text) {
  std::string numbers = text;
  std::replace(numbers.begin(), numbers.end(), ';', ',');
  const auto xy = ParseNumberList(numbers, 8, "--corners X1,Y1;X2,Y2;X3,Y3;X4,Y4");
  estimator::TableCornerPixels corners;
  for (int i = 0; i < 4; ++i) corners.pixels[i] = {xy[2 * i], xy[2 * i + 1]};
  return corners;
}

// What a calibration was fitted to, and how.
struct Calibration {
  estimator::CalibrationResult result;
  std::string from;  // "markers", "table" or "corners"
};

// The pose from the table's corners, found or given.
Calibration FromTheTable(const CalibrateArgs& args, const cv::Mat& image,
                         const physics::ModelParameters& params,
                         const camera::CameraModel& intrinsics, bool markers_looked_for) {
  std::optional<estimator::TableCornerPixels> corners;
  const std::string from = args.corners.empty() ? "table" : "corners";
  if (!args.corners.empty()) {
    corners = GivenCorners(args.corners);
  } else {
    std::string why;
    corners = estimator::FoundTableCorners(image, &why);
    if (!corners) {
      throw Refused(std::string(markers_looked_for ? "did not find all four corner markers nor "
                                                   : "did not find ") +
                    "the table in " + args.image + " (" + why +
                    "; give its corners with --corners; no camera file written)");
    }
  }
  const auto result = estimator::CalibrateFromCorners(
      *corners, image.size(), params.table, estimator::NoseHeight(params.ball.radius), intrinsics);
  if (!result) throw Refused("no camera pose puts the table's corners where they are in " + args.image);
  RequireACornerFit(*result, args.max_reprojection_px,
                    from == "table" ? "the table's corners found" : "the corners given");
  return {*result, from};
}

Calibration Calibrate(const CalibrateArgs& args, const cv::Mat& image,
                      const physics::ModelParameters& params,
                      const camera::CameraModel& intrinsics) {
  const bool markers = args.corners.empty() && !args.from_table;
  if (markers) {
    estimator::MarkerLayout layout =
        estimator::MarkerLayout::AroundTable(params.table, args.margin, args.height);
    if (!args.markers.empty()) {
      const auto xy = ParseNumberList(args.markers, 8, "--markers X1,Y1,...,X4,Y4");
      for (int i = 0; i < 4; ++i) layout.centres[i] = {xy[2 * i], xy[2 * i + 1], args.height};
    }
    if (const auto result = estimator::CalibrateTable(image, layout, intrinsics)) {
      RequireAMarkerFit(*result, args.max_reprojection_px, image, params.table, args.height);
      return {*result, "markers"};
    }
    // No markers: the table's own corners, unless a layout was asked for.
    if (!args.markers.empty()) {
      throw Refused("did not find all four corner markers in " + args.image +
                    " (no camera file written)");
    }
  }
  return FromTheTable(args, image, params, intrinsics, markers);
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
  if (!args.corners.empty()) GivenCorners(args.corners);  // bad input before the image is read
  const cv::Mat image = ReadImage(args.image);
  camera::CameraModel intrinsics;
  if (args.fx > 0) {
    intrinsics.fx = intrinsics.fy = args.fx;
    intrinsics.cx = 0.5 * (image.cols - 1);
    intrinsics.cy = 0.5 * (image.rows - 1);
  }
  const Calibration c = Calibrate(args, image, params, intrinsics);
  std::ofstream out(args.out);
  out << camera::CameraModelJson(c.result.camera) << "\n";
  if (!out) throw UsageError("--out: cannot write '" + args.out + "'");
  nlohmann::json points = nlohmann::json::array();
  for (const auto& m : c.result.points) points.push_back({m.x(), m.y()});
  if (args.json) {
    nlohmann::json j = {{"from", c.from},
                        {c.from == "markers" ? "markers" : "corners", points},
                        {"fx", c.result.camera.fx},
                        {"k1", c.result.camera.distortion[0]},
                        {"rms_reprojection_px", c.result.rms_reprojection_px},
                        {"out", args.out}};
    std::cout << j.dump() << std::endl;
  } else {
    std::cerr << (c.from == "markers" ? "markers " : "table corners ") << points.dump()
              << ", reprojection RMS " << c.result.rms_reprojection_px << " px, fx "
              << c.result.camera.fx << " px, k1 " << c.result.camera.distortion[0]
              << "; camera written to " << args.out << "\n";
  }
}

}  // namespace

void AddCalibrateCommand(CLI::App& app) {
  auto args = std::make_shared<CalibrateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "calibrate",
      "The camera pose over the table: from the four corner markers in a frame, else from the "
      "table's corners (found, or --corners)");
  cmd->add_option("image", args->image, "Image file")->required();
  cmd->add_option("--out", args->out, "Camera JSON file to write")->required();
  cmd->add_option("--params", args->params, "paper | pool | JSON file: the table and ball size")
      ->capture_default_str();
  cmd->add_option("--marker-margin", args->margin,
                  "Marker centres this far [m] outside each playing-surface corner, diagonally")
      ->capture_default_str();
  cmd->add_option("--markers", args->markers,
                  "The markers' table X,Y [m], image order: top-left, top-right, bottom-right, "
                  "bottom-left (instead of --marker-margin)");
  cmd->add_option("--marker-height", args->height, "Marker height above the cloth [m]")
      ->capture_default_str();
  cmd->add_option("--corners", args->corners,
                  "Without markers: the playing surface's corners (where the cushions' noses "
                  "meet) 'u,v;u,v;u,v;u,v' [px], in order around the table, the first side a long "
                  "one (instead of the table found)");
  cmd->add_flag("--from-table", args->from_table,
                "Fit the pose to the table found in the frame even where markers are");
  cmd->add_option("--fx", args->fx,
                  "Focal length [px] (default: with markers, the image width; from the table, "
                  "fitted to its corners)");
  cmd->add_option("--max-reprojection-px", args->max_reprojection_px,
                  "Refuse a pose that reprojects the markers or corners further than this [px, "
                  "RMS] from where they are (exit 3, as when neither is found)")
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args] { RunCalibrate(*args); });
}

}  // namespace billiard::cli
