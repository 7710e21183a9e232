#include "tools/billiard/image_files.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "lcmtypes/image_codec.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

namespace {

// As large as a camera's photograph gets; a JPEG header announcing more is not believed (a few
// bytes can announce 65535 x 65535 pixels).
constexpr messages::DecodeLimits kImageFileLimits{16384, 16384};

// Whether the file at `path` starts with a JPEG's SOI marker (whatever its name says).
bool IsJpegFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char start[2] = {};
  return in.read(start, 2) && static_cast<std::uint8_t>(start[0]) == 0xFF &&
         static_cast<std::uint8_t>(start[1]) == 0xD8;
}

std::vector<std::uint8_t> ReadBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

cv::Mat ReadImage(const std::string& path) {
  // Checked first: OpenCV would add a warning line of its own about a missing file.
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw UsageError("cannot read an image from '" + path + "': no such file");
  }
  if (IsJpegFile(path)) {
    const messages::DecodedImage jpeg = messages::DecodeJpeg(ReadBytes(path), kImageFileLimits);
    if (!jpeg.ok) throw UsageError("cannot read an image from '" + path + "': " + jpeg.error);
    if (jpeg.image.channels() == 3) return jpeg.image;
    cv::Mat bgr;  // a gray JPEG, as cv::imread gives it in colour
    cv::cvtColor(jpeg.image, bgr, cv::COLOR_GRAY2BGR);
    return bgr;
  }
  const cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
  if (image.empty()) throw UsageError("cannot read an image from '" + path + "'");
  return image;
}

}  // namespace billiard::cli
