#include "bench/detection_suite.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <random>
#include <stdexcept>

#include "bench/format.h"
#include "sim/camera/camera_model.h"
#include "sim/params/table_specs.h"
#include "sim/render/table_renderer.h"
#include "sim/table/rack.h"

namespace billiard::bench {

namespace {

constexpr int kWidth = 1280, kHeight = 720;
constexpr int kScatteredBalls = 16;
// A touching pair's gap, and the least gap between other balls [m].
constexpr double kTouchingGap = 0.0002, kLeastGap = 0.002;


struct View {
  const char* name;
  bool overhead;
  camera::CameraModel camera;
};

std::vector<View> Views(const physics::TableParameters& table) {
  const Eigen::Vector3d middle(0.5 * table.length, 0.5 * table.width, 0.0);
  const double elevation = 35.0 * M_PI / 180.0, distance = 2.0;
  return {{"overhead", true,
           camera::CameraModel::Overhead(table, kWidth, kHeight, 2.5, 0.92,
                                         {-0.05, 0.01, 0.0, 0.0, 0.0})},
          {"side", false,
           camera::CameraModel::LookingAt(
               middle + distance * Eigen::Vector3d(0, -std::cos(elevation), std::sin(elevation)),
               middle, kWidth, kHeight, 1.2)},
          {"end", false,
           camera::CameraModel::LookingAt(
               middle + Eigen::Vector3d(-0.5 * table.length - 1.2, 0, 1.6), middle, kWidth,
               kHeight, 0.9)}};
}

bool Free(const std::vector<Eigen::Vector2d>& placed, const Eigen::Vector2d& p, double least) {
  return std::none_of(placed.begin(), placed.end(),
                      [&](const Eigen::Vector2d& q) { return (q - p).norm() < least; });
}

// 16 balls at rest: two touching pairs, two against a cushion, the rest anywhere apart.
std::vector<Eigen::Vector2d> Scattered(const physics::TableParameters& table, double r,
                                       std::mt19937& rng) {
  std::uniform_real_distribution<double> x(r, table.length - r), y(r, table.width - r);
  std::uniform_real_distribution<double> angle(0.0, 2 * M_PI);
  std::vector<Eigen::Vector2d> placed;
  const double apart = 2 * r + kLeastGap;
  while (placed.size() < 4) {  // two touching pairs
    const Eigen::Vector2d a(x(rng), y(rng));
    const double t = angle(rng);
    const Eigen::Vector2d b = a + (2 * r + kTouchingGap) * Eigen::Vector2d(std::cos(t), std::sin(t));
    if (b.x() < r || b.y() < r || b.x() > table.length - r || b.y() > table.width - r) continue;
    if (!Free(placed, a, apart) || !Free(placed, b, apart)) continue;
    placed.push_back(a);
    placed.push_back(b);
  }
  while (placed.size() < 6) {  // two against a cushion
    const Eigen::Vector2d p(x(rng), placed.size() == 4 ? r : table.width - r);
    if (Free(placed, p, apart)) placed.push_back(p);
  }
  while (placed.size() < static_cast<std::size_t>(kScatteredBalls)) {
    const Eigen::Vector2d p(x(rng), y(rng));
    if (Free(placed, p, apart)) placed.push_back(p);
  }
  return placed;
}

}  // namespace

const std::vector<SuiteCloth>& SuiteCloths() {
  // The renderer's green, a broadcast blue, navy, burgundy and grey; the cushion a little darker.
  static const std::vector<SuiteCloth> cloths = {{"green", {60, 110, 30}, {48, 88, 24}},
                                                 {"blue", {200, 140, 40}, {165, 115, 32}},
                                                 {"navy", {90, 45, 25}, {72, 36, 20}},
                                                 {"burgundy", {45, 30, 140}, {36, 24, 112}},
                                                 {"grey", {175, 175, 170}, {140, 140, 136}}};
  return cloths;
}

std::vector<Eigen::Vector2d> SceneBalls(const physics::ModelParameters& params, bool rack,
                                        std::uint32_t rack_seed, std::mt19937* rng) {
  if (!rack) return Scattered(params.table, params.ball.radius, *rng);
  const table::TableGeometry geometry =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  std::vector<Eigen::Vector2d> balls;
  for (const auto& b : table::Rack(table::RackKind::kEightBall, geometry, params.ball.radius,
                                   rack_seed)) {
    balls.push_back(b.state.head<2>());
  }
  return balls;
}

std::vector<render::RenderBall> PoolBalls(const std::vector<Eigen::Vector2d>& balls) {
  std::vector<render::RenderBall> shown;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const int id = static_cast<int>(i % 16);
    shown.push_back(render::RenderBall::AtRest(id, render::PoolBallColour(id), balls[i]));
  }
  return shown;
}

render::RenderOptions SuiteRenderOptions(const SuiteCloth& cloth, std::uint64_t seed) {
  render::RenderOptions options;
  options.cloth = cloth.bed;
  options.cushion = cloth.cushion;
  options.exposure_s = 0.0;
  options.noise_sigma = 2.0;
  options.seed = seed;
  return options;
}

LabelledFrame LabelBalls(const std::string& name, const camera::CameraModel& camera,
                         bool overhead, const std::vector<Eigen::Vector2d>& balls, double r,
                         const std::vector<bool>& hidden) {
  LabelledFrame frame;
  frame.file = name + ".png";
  frame.view = overhead ? "overhead" : "oblique";
  frame.source = "billiard bench-detect (sim/render)";
  std::vector<double> radii;
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const Eigen::Vector3d centre(balls[i].x(), balls[i].y(), r);
    const Eigen::Vector2d pixel = camera.Project(centre);
    const double depth = (camera.rotation * centre + camera.translation).z();
    const bool in_view = pixel.x() >= 0 && pixel.y() >= 0 && pixel.x() < camera.width &&
                         pixel.y() < camera.height;
    const bool ignored = !in_view || (i < hidden.size() && hidden[i]);
    (ignored ? frame.ignored : frame.balls).push_back(pixel);
    radii.push_back(camera.fx * r / depth);
  }
  std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
  frame.radius_px = radii[radii.size() / 2];
  return frame;
}

std::vector<LabelledFrame> RenderDetectionSuite(const physics::ModelParameters& params,
                                                std::uint32_t seed) {
  std::vector<LabelledFrame> frames;
  std::mt19937 rng(seed);
  int scene = 0;
  for (const SuiteCloth& cloth : SuiteCloths()) {
    for (const View& view : Views(params.table)) {
      for (const bool rack : {false, true}) {
        const std::vector<Eigen::Vector2d> balls = SceneBalls(params, rack, seed + scene, &rng);
        const render::TableRenderer renderer(view.camera, params,
                                             SuiteRenderOptions(cloth, seed + scene));
        LabelledFrame frame = LabelBalls(
            std::string(cloth.name) + "-" + view.name + (rack ? "-rack" : "-scattered"),
            view.camera, view.overhead, balls, params.ball.radius);
        frame.source = "billiard bench-detect --synthetic (sim/render)";
        frame.image = renderer.Render(PoolBalls(balls), 0.0);
        frames.push_back(std::move(frame));
        ++scene;
      }
    }
  }
  return frames;
}

void WriteLabelledSet(const std::vector<LabelledFrame>& frames, const std::string& directory) {
  std::filesystem::create_directories(directory);
  nlohmann::json labels = {{"_source",
                            "Rendered by the simulator's renderer (sim/render/table_renderer.h): "
                            "ball centres are the exact projections of the balls' centres."}};
  for (const LabelledFrame& f : frames) {
    const std::string path = directory + "/" + f.file;
    if (!cv::imwrite(path, f.image)) throw std::runtime_error("cannot write '" + path + "'");
    nlohmann::json balls = nlohmann::json::array(), ignored = nlohmann::json::array();
    for (const auto& b : f.balls) balls.push_back({b.x(), b.y()});
    for (const auto& b : f.ignored) ignored.push_back({b.x(), b.y()});
    labels[f.file] = {{"balls", balls},
                      {"ignore", ignored},
                      {"ball_radius_px", f.radius_px},
                      {"view", f.view},
                      {"source", f.source}};
  }
  OpenForWriting(directory + "/labels.json") << labels.dump(1) << "\n";
}

}  // namespace billiard::bench
