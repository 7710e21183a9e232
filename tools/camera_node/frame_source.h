// Where camera_node's frames come from: a camera, a video file or a directory of images, each
// frame with its capture time. The three kinds are a file each (camera_source.h,
// video_file_source.h, image_directory_source.h); this header is what they share and the
// choice between them.
//
// A source is opened and read on FrameReader's thread (frame_reader.h), never on the node's: a
// camera or a GStreamer pipeline can block in its open or in a read for as long as it likes,
// and the reader's watchdog, not the source, decides that it has stalled.
//
// Capture times are microseconds since the epoch, as a camera's frames carry them: a camera's
// frame is stamped when it is handed over; a video's frame at the time of its opening plus the
// frame's own time in the video, so that the estimator sees the recording's motion whatever
// the pace it is played at; an image at the time of the opening plus its index over the rate.
//
// Module: billiard::camera_node (tools/camera_node/). lcmtypes/, lcmtypes/node/.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include <opencv2/core.hpp>

namespace billiard::camera_node {

// One frame as a source delivers it.
struct CapturedFrame {
  cv::Mat image;           // 8UC3 BGR
  std::int64_t utime = 0;  // capture time [us since the epoch]
};

// What one read of a source gives.
struct ReadResult {
  enum class Kind {
    kFrame,     // a frame
    kNoFrame,   // none this time (a camera between frames, or one that hiccups): read again
    kBadFrame,  // one frame that cannot be read (an image file that does not decode): counted
                // as failed, and the next read goes on
    kEnd,       // the source is played to its end: the last frame of a video, the last image
    kFailed,    // the source cannot go on: it does not open, it is cut short, it stalled
  };
  Kind kind = Kind::kNoFrame;
  CapturedFrame frame;  // with kFrame
  std::string reason;   // one line, with kBadFrame, kEnd and kFailed
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;

  // The source in a log line: "the camera /dev/video0", "the video 'break.avi'", ...
  virtual std::string Describe() const = 0;
  // Opens the source: "" when it is open, else why not (one line). Called once, before Read.
  virtual std::string Open() = 0;
  // The next frame, or why there is none. A camera's read blocks until its next frame.
  virtual ReadResult Read() = 0;
  // Plays the source again from its start after kEnd (--loop): false where it cannot (a
  // camera). The capture times go on after the last frame's, as a camera's clock would.
  virtual bool Restart() { return false; }
  // The rate the source says it has [Hz], 0 when it says none (known once it is open).
  virtual double FrameRate() const = 0;
  // Whether the source paces itself (a camera), or is to be played at a rate (files).
  virtual bool Live() const = 0;
};

// A source as the command line names it.
struct SourceSpec {
  enum class Kind { kDevice, kVideo, kImages };
  Kind kind = Kind::kVideo;
  // kDevice: /dev/videoN, a number N (for /dev/videoN), or a GStreamer pipeline ending in
  // appsink (any text with a '!'); kVideo: a video file; kImages: a directory.
  std::string path;
  // Asked of a camera (0: its own default); the images' rate (0: kDefaultImageRate).
  double fps = 0.0;
  int width = 0, height = 0;  // asked of a camera [px] (0: its own default)
};

// The wall clock [us since the epoch]: the capture times' clock.
std::int64_t WallUtime();

// The rate of a directory of images, which says none [Hz].
inline constexpr double kDefaultImageRate = 30.0;

// The source `spec` names, not yet open. Throws std::invalid_argument (one line) when its path
// is not there: a video or a directory that does not exist, a device path that does not.
std::unique_ptr<FrameSource> MakeFrameSource(const SourceSpec& spec);

// Keeps OpenCV's and FFmpeg's own log lines off stderr (a video cut short makes FFmpeg print a
// line per damaged packet, a file no backend reads a paragraph per backend tried), so that a
// source that fails says so in the node's one line. Leaves alone what the environment asks for
// (OPENCV_LOG_LEVEL, OPENCV_FFMPEG_LOGLEVEL). Call before the first source opens.
void QuietVideoBackends();

}  // namespace billiard::camera_node
