#include "tools/camera_node/testing/video_files.h"

#include <cmath>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

namespace billiard::camera_node::testing {

namespace {

constexpr int kDiscRadius = 5;        // [px]
constexpr double kBrightLevel = 128;  // the disc's pixels are brighter than this in gray

}  // namespace

cv::Mat NumberedFrame(int index, cv::Size size) {
  cv::Mat frame(size, CV_8UC3, cv::Scalar(30, 90, 20));
  cv::circle(frame, {kDiscStart + kDiscStep * index, size.height / 2}, kDiscRadius,
             cv::Scalar(255, 255, 255), cv::FILLED, cv::LINE_AA);
  return frame;
}

int FrameNumber(const cv::Mat& frame) {
  cv::Mat gray, bright;
  cv::cvtColor(frame, gray, cv::COLOR_BGR2GRAY);
  cv::threshold(gray, bright, kBrightLevel, 255, cv::THRESH_BINARY);
  const cv::Moments m = cv::moments(bright, true);
  if (m.m00 == 0) return -1;
  return static_cast<int>(std::lround((m.m10 / m.m00 - kDiscStart) / kDiscStep));
}

std::vector<cv::Mat> NumberedFrames(int count, cv::Size size) {
  std::vector<cv::Mat> frames;
  for (int k = 0; k < count; ++k) frames.push_back(NumberedFrame(k, size));
  return frames;
}

cv::VideoWriter OpenMjpgWriter(const std::string& path, double fps, cv::Size size) {
  cv::VideoWriter writer(path, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), fps, size);
  if (!writer.isOpened()) throw std::runtime_error("no backend writes MJPG into " + path);
  return writer;
}

void WriteMjpgVideo(const std::string& path, const std::vector<cv::Mat>& frames, double fps) {
  cv::VideoWriter writer = OpenMjpgWriter(path, fps, frames.at(0).size());
  for (const cv::Mat& frame : frames) writer.write(frame);
}

void WriteCutShort(const std::string& from, const std::string& to, double fraction) {
  std::ifstream in(from, std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), {});
  std::ofstream(to, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(fraction * bytes.size()));
}

void WriteGarbage(const std::string& path) {
  std::ofstream(path) << "This is a shopping list, not a video: eggs, chalk, a new tip.\n";
}

}  // namespace billiard::camera_node::testing
