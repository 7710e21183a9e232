// A frame source read on a thread of its own, with a watchdog: the node that takes the frames
// is never held by the source, and a source that stops or stalls ends with a reason instead of
// a hang.
//
// The thread opens the source, then reads it frame after frame into a short queue, waiting for
// room while the node is behind (a video is not read ahead of its playing; a camera's own
// buffers hold what comes meanwhile). The node takes what the thread found, in order: that the
// source opened (with its rate), frames, frames that failed, and finally how the source ended.
//
// Stalls: while the thread waits for the source (in its Open, in a Read, or between reads that
// give no frame), the time since it began to wait is watched. Past `stall_timeout` the source
// has failed: "gave no frame for 5.0 s". A read that gives nothing is retried by the thread and
// seen by it; a read that never returns (a camera unplugged under some drivers, a GStreamer
// pipeline that waits for ever) is seen by the watchdog in Next, and the thread is abandoned
// where it is: it owns the source, and ends with it whenever its read returns (or with the
// process).
//
// Module: billiard::camera_node.
#pragma once

#include <chrono>
#include <cstddef>
#include <memory>
#include <string>
#include <thread>

#include "tools/camera_node/frame_source.h"

namespace billiard::camera_node {

using Clock = std::chrono::steady_clock;

// What the reader found, in the order it found it.
struct ReaderEvent {
  enum class Kind {
    kNone,      // nothing within the wait
    kOpened,    // the source is open: `rate`, `live`
    kFrame,     // `frame`, read at `read_at`
    kBadFrame,  // a frame that failed: `reason`
    kEnded,     // played to its end: `reason`
    kFailed,    // cannot go on (did not open, cut short, stalled): `reason`
  };
  Kind kind = Kind::kNone;
  CapturedFrame frame;
  Clock::time_point read_at;
  std::string reason;
  double rate = 0.0;  // [Hz]
  bool live = false;
};

struct ReaderOptions {
  Clock::duration stall_timeout = std::chrono::seconds(5);
  bool loop = false;                  // play the source again from its start at its end
  std::size_t max_queued_frames = 2;  // read ahead of the node by at most this many
};

class FrameReader {
 public:
  // Starts the thread, which opens `source` at once.
  FrameReader(std::unique_ptr<FrameSource> source, ReaderOptions options);
  // Stops the thread: joined when it stops within the stall timeout, else left to end with its
  // stuck read.
  ~FrameReader();
  FrameReader(const FrameReader&) = delete;
  FrameReader& operator=(const FrameReader&) = delete;

  // The next thing the reader found, waiting up to `wait` for one; kNone when there was none.
  // After kEnded or kFailed, always kNone.
  ReaderEvent Next(Clock::duration wait);

  std::size_t queued_frames() const;
  long restarts() const;  // times the source was played again (loop)
  const std::string& description() const { return description_; }

  struct Shared;  // between the node's thread and the reader's (frame_reader.cc)

 private:
  const std::string description_;
  const ReaderOptions options_;
  std::shared_ptr<Shared> shared_;
  std::thread thread_;
};

}  // namespace billiard::camera_node
