// Video files and frames for the camera node's tests: numbered frames that say which they are
// after a JPEG round trip, videos written with OpenCV's VideoWriter (MJPG in AVI, which Debian's
// OpenCV writes through FFmpeg), a copy cut short as an interrupted copy leaves it, and a file
// that is no video.
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

namespace billiard::camera_node::testing {

// Frame `index` of a numbered sequence: a white disc on a dark green field, its centre at
// x = kDiscStart + kDiscStep index px, mid-height. 8UC3.
inline constexpr int kDiscStart = 12;
inline constexpr int kDiscStep = 4;
cv::Mat NumberedFrame(int index, cv::Size size);

// The number of a NumberedFrame read back (through JPEG, a video codec, a resize-free round
// trip): from the centroid of its bright pixels; -1 when there are none.
int FrameNumber(const cv::Mat& frame);

// Frames 0 .. count - 1.
std::vector<cv::Mat> NumberedFrames(int count, cv::Size size);

// A writer of MJPG in an AVI at `fps`, frames of `size` (8UC3). Throws std::runtime_error when
// no backend of OpenCV's writes it.
cv::VideoWriter OpenMjpgWriter(const std::string& path, double fps, cv::Size size);

// Writes `frames` (8UC3, all of one size) with OpenMjpgWriter.
void WriteMjpgVideo(const std::string& path, const std::vector<cv::Mat>& frames, double fps);

// Writes the first `fraction` of the bytes of `from` into `to`.
void WriteCutShort(const std::string& from, const std::string& to, double fraction);

// Writes text that no video backend reads into `path`, under a video's name.
void WriteGarbage(const std::string& path);

}  // namespace billiard::camera_node::testing
