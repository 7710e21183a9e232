// The camera node: the frames of a camera, a video file or a directory of images
// (frame_source.h) published as the estimator reads them.
//
//   CAMERA_IMAGE  image_t        each frame as the table simulator sends its own: one JPEG
//                                (PIXEL_FORMAT_MJPEG, lcmtypes/image_codec.h) at jpeg_quality,
//                                utime its capture time (frame_source.h)
//   NODE_STATUS   node_status_t  once a second (node_health.h): published counts the frames
//                                sent, dropped the frames that failed (an image that does not
//                                decode, a frame that cannot be encoded or sent), last_error the
//                                latest one's reason; the counters source_state (0 opening,
//                                1 running, 2 ended, 3 failed) and source_restarts (--loop);
//                                latency from a frame's read to its publication, queue_depth the
//                                frames read and not yet sent
//
// A camera's frames go out as they come. A file's are paced: one every 1/fps s of the wall
// clock, fps the command line's or else the file's own rate (kDefaultImageRate for images),
// falling behind no further than one frame (a slow machine plays slower, without a burst). The
// capture times are the recording's whatever the pace (frame_source.h).
//
// The source is read by FrameReader (frame_reader.h): the node never waits on it for more than
// kMaxWait, so that its status goes out while a camera stalls. How the source ended is said in
// one line (`log`) and in source_state; the node then goes on reporting its status until it is
// stopped, unless the command line asks it to exit (camera_node_command.h).
//
// Module: billiard::camera_node.
#pragma once

#include <chrono>
#include <functional>
#include <lcm/lcm-cpp.hpp>
#include <memory>
#include <optional>
#include <string>

#include "lcmtypes/node/node_health.h"
#include "tools/camera_node/frame_reader.h"
#include "tools/camera_node/frame_source.h"

namespace billiard::camera_node {

// The node's name in its log lines and NODE_STATUS.
inline constexpr char kNodeName[] = "camera_node";

// A source's state, as NODE_STATUS's counter source_state gives it.
enum class SourceState { kOpening = 0, kRunning = 1, kEnded = 2, kFailed = 3 };

// The longest the node waits in Work for the source.
inline constexpr auto kMaxWait = std::chrono::milliseconds(20);

struct CameraNodeOptions {
  int jpeg_quality = 90;  // 1..100, the table simulator's
  double fps = 0.0;       // a file's pace [Hz]; 0: its own rate
  bool paced = true;      // false: a file's frames as fast as they are read (in-process runs)
  ReaderOptions reader;
};

class CameraNode {
 public:
  using Log = std::function<void(const std::string& line)>;

  // Starts reading `source` (opened on the reader's thread) and publishes on `lcm`, which must
  // outlive the node; `log` gets the node's lines (stderr, prefixed, by default).
  CameraNode(lcm::LCM& lcm, std::unique_ptr<FrameSource> source, CameraNodeOptions options = {},
             Log log = nullptr);

  // Publishes the next frame when it is due and NODE_STATUS when due, waiting at most kMaxWait.
  // Returns whether frames may still come (node_loop.h: false once the source has ended).
  bool Work();

  SourceState state() const { return state_; }
  // How the source ended, "" while it runs.
  const std::string& end_reason() const { return end_reason_; }
  nodes::NodeHealth& health() { return health_; }

 private:
  // Takes what the reader found within `wait`: a frame is held until it is due.
  void TakeFromReader(Clock::duration wait);
  void Opened(const ReaderEvent& event);
  void Ended(SourceState state, const std::string& reason);
  // Publishes the held frame once it is due, waiting at most kMaxWait for that.
  void PublishWhenDue();
  void Publish(const ReaderEvent& frame);
  void FrameFailed(const std::string& why);

  lcm::LCM& lcm_;
  const CameraNodeOptions options_;
  Log log_;
  nodes::NodeHealth health_;
  FrameReader reader_;
  SourceState state_ = SourceState::kOpening;
  std::string end_reason_;
  bool live_ = false;
  Clock::duration interval_ = Clock::duration::zero();  // between a file's frames
  std::optional<ReaderEvent> held_;                     // a frame waiting for its time
  std::optional<Clock::time_point> next_due_;
};

}  // namespace billiard::camera_node
