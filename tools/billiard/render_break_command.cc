#include "tools/billiard/render_break_command.h"

#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "sim/camera/camera_model.h"
#include "tools/billiard/command_line.h"
#include "tools/camera_node/testing/break_video.h"

namespace billiard::cli {

namespace {

struct RenderBreakArgs {
  std::string out, camera_out;
  camera_node::testing::BreakVideoOptions video;
};

// The last frame's balls and their true centres, and what the video holds.
nlohmann::json Summary(const RenderBreakArgs& args, const camera_node::testing::BreakVideo& v) {
  nlohmann::json balls = nlohmann::json::array();
  for (const auto& [id, centre] : v.truth.back()) {
    balls.push_back({{"id", id}, {"x", centre.x()}, {"y", centre.y()}});
  }
  return {{"video", args.out},
          {"frames", v.truth.size()},
          {"fps", v.fps},
          {"width", args.video.width},
          {"height", args.video.height},
          {"seed", args.video.seed},
          {"balls_at_end", balls}};
}

void Run(const RenderBreakArgs& args) {
  if (args.video.at_rest >= args.video.duration) {
    throw UsageError("--at-rest must be shorter than --duration");
  }
  if (!std::ofstream(args.out)) throw UsageError("cannot write the video '" + args.out + "'");
  const camera_node::testing::BreakVideo video =
      camera_node::testing::WriteBreakVideo(args.out, args.video);
  if (!args.camera_out.empty()) {
    std::ofstream camera(args.camera_out);
    camera << camera::CameraModelJson(video.camera) << "\n";
    if (!camera) throw UsageError("cannot write the camera model '" + args.camera_out + "'");
  }
  std::cout << Summary(args, video).dump() << std::endl;
}

}  // namespace

void AddRenderBreakCommand(CLI::App& app) {
  auto args = std::make_shared<RenderBreakArgs>();
  CLI::App* cmd = app.add_subcommand(
      "render-break",
      "A seeded eight-ball break filmed by the table simulator's overhead camera, written as a "
      "video (MJPG in AVI) for camera_node and run_loop.sh --camera; the balls' true places at "
      "the end as JSON on stdout");
  cmd->add_option("--out", args->out, "The video file (.avi)")->required();
  cmd->add_option("--camera-out", args->camera_out,
                  "Write the camera model of the frames (billiard calibrate's JSON)");
  cmd->add_option("--seed", args->video.seed, "The break's seed (its aim and tip error)")
      ->capture_default_str();
  cmd->add_option("--width", args->video.width, "Frame width [px]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--height", args->video.height, "Frame height [px]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--fps", args->video.fps, "Frames a second")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--duration", args->video.duration, "Length of the video [s]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->add_option("--at-rest", args->video.at_rest, "The rack shown still before the strike [s]")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
