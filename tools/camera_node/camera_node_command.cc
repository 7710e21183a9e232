#include "tools/camera_node/camera_node_command.h"

#include <chrono>
#include <iostream>
#include <lcm/lcm-cpp.hpp>
#include <stdexcept>
#include <thread>

#include "lcmtypes/node/node_loop.h"
#include "tools/camera_node/camera_node.h"

namespace billiard::camera_node {

namespace {

// How long the node rests between status reports once its source has ended.
constexpr auto kIdleWait = std::chrono::milliseconds(100);

CameraNodeOptions OptionsOf(const CameraNodeCommandLine& line) {
  CameraNodeOptions options;
  options.jpeg_quality = line.jpeg_quality;
  options.fps = line.fps;
  options.reader.loop = line.loop;
  options.reader.stall_timeout = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(line.stall_timeout));
  return options;
}

}  // namespace

void AddCameraNodeOptions(CLI::App& app, CameraNodeCommandLine* line) {
  CLI::Option_group* source =
      app.add_option_group("source", "Where the frames come from (exactly one)");
  source->add_option("--device", line->device,
                     "A camera: /dev/videoN, N, or a GStreamer pipeline ending in appsink");
  source->add_option("--video", line->video, "A video file (any format OpenCV's backends read)");
  source->add_option("--images", line->images,
                     "A directory of images, played in the order of their names");
  source->require_option(1);
  app.add_option("--fps", line->fps,
                 "Frames per second: asked of a camera; a file's pace (default: its own rate, "
                 "30 for images) and the images' capture interval")
      ->check(CLI::PositiveNumber);
  app.add_option("--width", line->width, "Frame width asked of a camera [px]")
      ->check(CLI::PositiveNumber);
  app.add_option("--height", line->height, "Frame height asked of a camera [px]")
      ->check(CLI::PositiveNumber);
  app.add_option("--jpeg-quality", line->jpeg_quality, "JPEG quality of the frames sent")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  app.add_option("--stall-timeout", line->stall_timeout,
                 "A source that gives no frame for this long has failed [s]")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_flag("--loop", line->loop, "Play a video or the images again at their end");
  app.add_flag("--exit-at-end", line->exit_at_end,
               "Exit when the source ends (0 at its end, 1 when it failed) instead of staying up");
  app.add_option("--lcm-url", line->lcm_url,
                 "LCM URL (default: $LCM_DEFAULT_URL, else LCM's default)");
}

SourceSpec SourceOf(const CameraNodeCommandLine& line) {
  SourceSpec spec;
  spec.kind = !line.device.empty()  ? SourceSpec::Kind::kDevice
              : !line.video.empty() ? SourceSpec::Kind::kVideo
                                    : SourceSpec::Kind::kImages;
  spec.path = !line.device.empty() ? line.device : !line.video.empty() ? line.video : line.images;
  spec.fps = line.fps;
  spec.width = line.width;
  spec.height = line.height;
  return spec;
}

int RunCameraNodeCommand(const CameraNodeCommandLine& line) {
  // First: a signal that comes while the source opens (a camera can take seconds) stops the node
  // as a node is stopped, not by the signal's default.
  nodes::StopOnSignals();
  std::unique_ptr<FrameSource> source;
  try {
    source = MakeFrameSource(SourceOf(line));
  } catch (const std::invalid_argument& e) {
    std::cerr << kNodeName << ": " << e.what() << std::endl;
    return 2;
  }
  QuietVideoBackends();
  // The node only publishes: no message loop, and no receive buffer to advise on.
  lcm::LCM lcm(line.lcm_url);
  if (!lcm.good()) {
    std::cerr << kNodeName << ": cannot initialise LCM with " << nodes::DescribeUrl(line.lcm_url)
              << std::endl;
    return 1;
  }
  CameraNode node(lcm, std::move(source), OptionsOf(line));
  while (!nodes::StopRequested()) {
    if (node.Work()) continue;
    if (line.exit_at_end) return node.state() == SourceState::kFailed ? 1 : 0;
    std::this_thread::sleep_for(kIdleWait);
  }
  std::cerr << kNodeName << ": stopped" << std::endl;
  return 0;
}

}  // namespace billiard::camera_node
