#include "tools/camera_node/frame_source.h"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <opencv2/core/utils/logger.hpp>

#include "tools/camera_node/camera_source.h"
#include "tools/camera_node/image_directory_source.h"
#include "tools/camera_node/video_file_source.h"

namespace billiard::camera_node {

namespace {

namespace fs = std::filesystem;

// FFmpeg's AV_LOG_PANIC: only what is about to abort the process.
constexpr char kFfmpegPanicOnly[] = "0";

// The path that `device` names: a number N is /dev/videoN; a pipeline or a path is itself.
std::string DevicePath(const std::string& device) {
  if (!device.empty() && device.find_first_not_of("0123456789") == std::string::npos) {
    return "/dev/video" + device;
  }
  return device;
}

}  // namespace

std::int64_t WallUtime() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::unique_ptr<FrameSource> MakeFrameSource(const SourceSpec& spec) {
  std::error_code error;
  switch (spec.kind) {
    case SourceSpec::Kind::kDevice: {
      const std::string device = DevicePath(spec.path);
      if (!IsGStreamerPipeline(device) && !fs::exists(device, error)) {
        throw std::invalid_argument("no camera at '" + device + "'");
      }
      return std::make_unique<CameraSource>(device, spec.fps, spec.width, spec.height);
    }
    case SourceSpec::Kind::kVideo:
      if (!fs::is_regular_file(spec.path, error)) {
        throw std::invalid_argument("no video file at '" + spec.path + "'");
      }
      if (!std::ifstream(spec.path).good()) {
        throw std::invalid_argument("cannot read the video file '" + spec.path + "'");
      }
      return std::make_unique<VideoFileSource>(spec.path);
    case SourceSpec::Kind::kImages:
      if (!fs::is_directory(spec.path, error)) {
        throw std::invalid_argument("no directory of images at '" + spec.path + "'");
      }
      return std::make_unique<ImageDirectorySource>(spec.path,
                                                    spec.fps > 0 ? spec.fps : kDefaultImageRate);
  }
  throw std::invalid_argument("no such kind of frame source");
}

void QuietVideoBackends() {
  if (!std::getenv("OPENCV_LOG_LEVEL")) {
    cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
  }
  // Read by OpenCV when its FFmpeg backend first opens a file; overwrite = 0 keeps the caller's.
  setenv("OPENCV_FFMPEG_LOGLEVEL", kFfmpegPanicOnly, 0);
}

}  // namespace billiard::camera_node
