// Image files as the commands read them (billiard detect, calibrate, bench-detect).
#pragma once

#include <opencv2/core.hpp>
#include <string>

namespace billiard::cli {

// The frame at `path`, in BGR. A JPEG is decoded as the estimator node decodes its frames
// (messages::DecodeJpeg), which refuses a corrupt or truncated one where OpenCV's decoder would
// hand back a damaged image; other formats by OpenCV. A missing, unreadable, damaged or empty
// image is the user's error (UsageError, with the reason).
cv::Mat ReadImage(const std::string& path);

}  // namespace billiard::cli
