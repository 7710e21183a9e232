#include "tools/camera_node/image_directory_source.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>
#include <utility>

#include <opencv2/imgcodecs.hpp>

namespace billiard::camera_node {

namespace fs = std::filesystem;

bool IsImageFile(const std::string& path) {
  static const std::set<std::string> kExtensions = {".png",  ".jpg", ".jpeg", ".bmp", ".tif",
                                                    ".tiff", ".pgm", ".ppm",  ".pnm", ".webp"};
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return kExtensions.count(extension) > 0;
}

ImageDirectorySource::ImageDirectorySource(std::string directory, double rate)
    : directory_(std::move(directory)), rate_(rate) {}

std::string ImageDirectorySource::Open() {
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory_, error)) {
    if (entry.is_regular_file(error) && IsImageFile(entry.path().string())) {
      files_.push_back(entry.path().string());
    }
  }
  if (error) return Describe() + " cannot be listed: " + error.message();
  if (files_.empty()) return Describe() + ": there are none";
  std::sort(files_.begin(), files_.end());
  origin_ = WallUtime();
  return "";
}

ReadResult ImageDirectorySource::Read() {
  ReadResult result;
  if (next_ == files_.size()) {
    result.kind = ReadResult::Kind::kEnd;
    result.reason = Describe() + " ended after " + std::to_string(files_.size()) + " images";
    return result;
  }
  const std::string& file = files_[next_++];
  result.frame.image = cv::imread(file, cv::IMREAD_COLOR);
  result.frame.utime = origin_ + std::llround(1e6 * static_cast<double>(played_++) / rate_);
  if (result.frame.image.empty()) {
    result.kind = ReadResult::Kind::kBadFrame;
    result.reason = "'" + file + "' is not an image that decodes";
    return result;
  }
  result.kind = ReadResult::Kind::kFrame;
  return result;
}

bool ImageDirectorySource::Restart() {
  next_ = 0;
  return true;
}

}  // namespace billiard::camera_node
