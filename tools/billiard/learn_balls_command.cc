#include "tools/billiard/learn_balls_command.h"

#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "estimator/ball_class.h"
#include "estimator/ball_detector.h"
#include "estimator/ball_identity.h"
#include "estimator/ball_model.h"
#include "sim/camera/camera_model.h"
#include "sim/params/parameter_sets.h"
#include "tools/billiard/detect_options.h"
#include "tools/billiard/command_line.h"
#include "tools/billiard/image_files.h"

namespace billiard::cli {

namespace {

struct LearnBallsArgs {
  std::string image, balls, calib, out, params = params::kDefaultParameterSet, ball_set;
  double ball_radius_px = 0;
  bool json = false;
};

// A number of a --balls entry, or the reason it is none.
double Coordinate(const nlohmann::json& entry, const char* key, std::size_t index) {
  const nlohmann::json& x = entry.at(key);
  if (!x.is_number() || !std::isfinite(x.get<double>())) {
    throw UsageError("--balls: entry " + std::to_string(index) + "'s \"" + key +
                     "\" must be a finite number");
  }
  return x.get<double>();
}

// Which ball an entry is: a class's name ("cue", "3", "red"), or a pool ball's number (0 the cue
// ball).
estimator::BallClass ClassOfEntry(const nlohmann::json& id, estimator::BallSet set,
                                  std::size_t index) {
  const std::string name = id.is_number_integer()
                               ? (id.get<int>() == 0 ? "cue" : std::to_string(id.get<int>()))
                               : id.is_string() ? id.get<std::string>()
                                                : "";
  if (const auto c = estimator::BallClassNamed(name, set)) return *c;
  throw UsageError("--balls: entry " + std::to_string(index) + "'s \"id\" " + id.dump() +
                   " is no ball of the " + estimator::BallSetName(set) + " set");
}

// The balls a --balls file places: in pixels ("u", "v"), or on the table ("x", "y" [m]) seen
// through the calibration at the ball's centre height.
std::vector<estimator::PlacedBall> ReadPlacedBalls(const std::string& path, estimator::BallSet set,
                                                   const std::optional<camera::CameraModel>& camera,
                                                   double ball_radius) {
  std::ifstream in(path);
  if (!in) throw UsageError("--balls: cannot read '" + path + "'");
  nlohmann::json list;
  try {
    list = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw UsageError("--balls: '" + path + "' is not valid JSON (" + e.what() + ")");
  }
  if (!list.is_array() || list.empty()) {
    throw UsageError("--balls: '" + path + "' must hold a list of {\"id\", \"u\", \"v\"} or " +
                     "{\"id\", \"x\", \"y\"}");
  }
  std::vector<estimator::PlacedBall> placed;
  std::map<estimator::BallClass, int> listed;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const nlohmann::json& e = list[i];
    const bool pixels = e.is_object() && e.contains("u") && e.contains("v");
    const bool on_table = e.is_object() && e.contains("x") && e.contains("y");
    if (!e.is_object() || !e.contains("id") || pixels == on_table) {
      throw UsageError("--balls: entry " + std::to_string(i) +
                       " must hold \"id\" and either \"u\", \"v\" [px] or \"x\", \"y\" [m]");
    }
    if (on_table && !camera) {
      throw UsageError("--balls: entry " + std::to_string(i) +
                       " is on the table (\"x\", \"y\"): give --calib, or pixels \"u\", \"v\"");
    }
    estimator::PlacedBall ball;
    ball.ball_class = ClassOfEntry(e.at("id"), set, i);
    if (++listed[ball.ball_class] > estimator::CountIn(set, ball.ball_class)) {
      throw UsageError("--balls: more balls " + estimator::BallClassName(ball.ball_class) +
                       " than the " + estimator::BallSetName(set) + " set holds");
    }
    ball.pixel = pixels ? Eigen::Vector2d(Coordinate(e, "u", i), Coordinate(e, "v", i))
                        : camera->Project(
                              {Coordinate(e, "x", i), Coordinate(e, "y", i), ball_radius});
    placed.push_back(ball);
  }
  return placed;
}

// How many of the balls found where they were placed `parameters` name right.
int NamedRight(const std::vector<estimator::BallLook>& looks,
               const std::vector<estimator::BallDetection>& balls,
               const std::vector<estimator::PlacedBall>& placed, const std::vector<int>& matched,
               estimator::BallSet set, const estimator::IdentityParameters& parameters) {
  const auto identities = estimator::NameBalls(looks, balls, set, parameters);
  int right = 0;
  for (std::size_t p = 0; p < placed.size(); ++p) {
    right += matched[p] >= 0 && identities[matched[p]].ball_class == placed[p].ball_class;
  }
  return right;
}

void RunLearnBalls(const LearnBallsArgs& args) {
  const physics::ModelParameters params = LoadParametersOption(args.params);
  const estimator::BallSet set = BallSetOption(args.ball_set, params);
  const std::optional<camera::CameraModel> camera = CalibrationOption(args.calib);
  RequireBallRadiusOption(args.ball_radius_px);
  const auto placed = ReadPlacedBalls(args.balls, set, camera, params.ball.radius);
  const cv::Mat image = ReadImage(args.image);
  if (camera) RequireCalibrationOfThisSize(*camera, image, args.calib);

  estimator::DetectorOptions options;
  options.ball_set = set;
  options.ball_radius_px = args.ball_radius_px;
  if (camera && options.ball_radius_px == 0) {
    options.ball_radius_px = estimator::ExpectedRadiusPx(*camera, params.ball.radius);
  }
  estimator::BallDetector detector(options);
  const auto balls = detector.Detect(image);
  if (!detector.failure().empty()) {
    throw Refused(detector.failure() + " in " + args.image + " (no model written)");
  }
  std::vector<int> matched;
  try {
    matched = estimator::MatchPlacedBalls(placed, balls);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--balls: ") + e.what());
  }
  nlohmann::json missing = nlohmann::json::array();
  for (std::size_t p = 0; p < placed.size(); ++p) {
    if (matched[p] >= 0) continue;
    const std::string name = estimator::BallClassName(placed[p].ball_class);
    missing.push_back(name);
    std::cerr << "billiard: warning: no ball found where ball " << name << " is placed ("
              << placed[p].pixel.x() << ", " << placed[p].pixel.y()
              << " px): its class keeps the hand-set colours" << std::endl;
  }
  if (missing.size() == placed.size()) {
    throw Refused("none of the " + std::to_string(placed.size()) + " balls of " + args.balls +
                  " was found where it is placed in " + args.image + " (no model written)");
  }
  const cv::Mat searched = detector.SearchedFrame(image);
  const estimator::BallModel model =
      estimator::LearnBallModel(searched, balls, placed, matched, set);
  std::ofstream out(args.out);
  out << estimator::BallModelJson(model) << "\n";
  if (!out) throw UsageError("--out: cannot write '" + args.out + "'");

  // The frame named again, by the model and by the hand-set colours: what the model learnt.
  const auto looks = estimator::LookAtBalls(searched, balls, set);
  const int found = static_cast<int>(placed.size() - missing.size());
  const int by_model = NamedRight(looks, balls, placed, matched, set, model.identity);
  const int by_hand = NamedRight(looks, balls, placed, matched, set, estimator::HandSetIdentity());
  if (args.json) {
    std::cout << nlohmann::json{{"placed", placed.size()},    {"learnt", found},
                                {"missing", missing},         {"named_right_model", by_model},
                                {"named_right_hand_set", by_hand}, {"out", args.out}}
                     .dump()
              << std::endl;
  } else {
    std::cerr << "learnt " << found << " of " << placed.size() << " balls; the model names "
              << by_model << " of them right, the hand-set colours " << by_hand
              << "; model written to " << args.out << "\n";
  }
}

}  // namespace

void AddLearnBallsCommand(CLI::App& app) {
  auto args = std::make_shared<LearnBallsArgs>();
  CLI::App* cmd = app.add_subcommand(
      "learn-balls", "Learn this camera's and light's look of every ball from a frame of them");
  cmd->add_option("image", args->image, "Image file (PNG, JPEG, ...)")->required();
  cmd->add_option("--balls", args->balls,
                  "JSON list of the balls in the frame: {\"id\": \"cue\" | \"1\" | \"red\" ..., "
                  "\"u\", \"v\" [px]} or {\"id\", \"x\", \"y\" [m on the table, with --calib]}")
      ->required();
  cmd->add_option("--out", args->out, "The model JSON file to write (detect --ball-model)")
      ->required();
  cmd->add_option("--calib", args->calib,
                  "Camera JSON (billiard calibrate): places \"x\", \"y\" and sets the ball radius");
  cmd->add_option("--ball-radius-px", args->ball_radius_px,
                  "Expected ball radius [px] (default: from --calib, else estimated)");
  cmd->add_option("--params", args->params, "paper | pool | JSON file: the balls")
      ->capture_default_str();
  cmd->add_option("--ball-set", args->ball_set,
                  "pool | snooker | carom | blackball: the balls' classes (default: --params' set)");
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args] { RunLearnBalls(*args); });
}

}  // namespace billiard::cli
