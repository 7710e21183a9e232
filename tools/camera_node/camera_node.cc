#include "tools/camera_node/camera_node.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <iostream>
#include <thread>
#include <utility>

#include "lcmtypes/billiard/image_t.hpp"
#include "lcmtypes/image_codec.h"
#include "lcmtypes/names.h"

namespace billiard::camera_node {

namespace {

// The counters of NODE_STATUS this node adds.
constexpr char kSourceStateCounter[] = "source_state";
constexpr char kSourceRestartsCounter[] = "source_restarts";

std::string Hertz(double rate) {
  char text[32];
  std::snprintf(text, sizeof text, "%g Hz", rate);
  return text;
}

}  // namespace

CameraNode::CameraNode(lcm::LCM& lcm, std::unique_ptr<FrameSource> source,
                       CameraNodeOptions options, Log log)
    : lcm_(lcm),
      options_(options),
      log_(log ? std::move(log) : Log([](const std::string& line) {
        std::cerr << kNodeName << ": " << line << std::endl;
      })),
      health_(kNodeName, log_),
      reader_(std::move(source), options.reader) {
  health_.Set(kSourceStateCounter, static_cast<int>(state_));
  health_.Set(kSourceRestartsCounter, 0);
}

bool CameraNode::Work() {
  if (!held_ && (state_ == SourceState::kOpening || state_ == SourceState::kRunning)) {
    TakeFromReader(kMaxWait);
  }
  if (held_) PublishWhenDue();
  health_.Set(kSourceRestartsCounter, reader_.restarts());
  health_.SetQueueDepth(static_cast<int>(reader_.queued_frames()) + (held_ ? 1 : 0));
  health_.PublishIfDue(lcm_);
  return held_.has_value() || state_ == SourceState::kOpening || state_ == SourceState::kRunning;
}

void CameraNode::TakeFromReader(Clock::duration wait) {
  ReaderEvent event = reader_.Next(wait);
  switch (event.kind) {
    case ReaderEvent::Kind::kNone:
      return;
    case ReaderEvent::Kind::kOpened:
      return Opened(event);
    case ReaderEvent::Kind::kFrame:
      held_ = std::move(event);
      return;
    case ReaderEvent::Kind::kBadFrame:
      return FrameFailed(event.reason);
    case ReaderEvent::Kind::kEnded:
      return Ended(SourceState::kEnded, event.reason);
    case ReaderEvent::Kind::kFailed:
      return Ended(SourceState::kFailed, event.reason);
  }
}

void CameraNode::Opened(const ReaderEvent& event) {
  state_ = SourceState::kRunning;
  health_.Set(kSourceStateCounter, static_cast<int>(state_));
  live_ = event.live;
  const double pace = options_.fps > 0 ? options_.fps
                      : event.rate > 0 ? event.rate
                                       : kDefaultImageRate;
  interval_ = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1 / pace));
  std::string line = reader_.description() + " is open";
  if (live_) {
    line += event.rate > 0 ? " (" + Hertz(event.rate) + ")" : "";
  } else {
    line += options_.paced ? ", played at " + Hertz(pace) : ", played as fast as it is read";
  }
  log_(line);
}

void CameraNode::Ended(SourceState state, const std::string& reason) {
  state_ = state;
  end_reason_ = reason;
  health_.Set(kSourceStateCounter, static_cast<int>(state_));
  log_(reason);
  health_.Publish(lcm_);  // the end at once, not within the next second
}

void CameraNode::PublishWhenDue() {
  if (options_.paced && !live_) {
    const Clock::time_point now = Clock::now();
    if (!next_due_) next_due_ = now;
    if (now < *next_due_) {
      std::this_thread::sleep_for(std::min<Clock::duration>(*next_due_ - now, kMaxWait));
      if (Clock::now() < *next_due_) return;
    }
    // The next frame one interval on, but never more than one behind the clock: a slow
    // machine plays slower rather than in bursts.
    *next_due_ = std::max(*next_due_ + interval_, Clock::now() - interval_);
  }
  Publish(*held_);
  held_.reset();
}

void CameraNode::Publish(const ReaderEvent& frame) {
  try {
    const image_t message =
        messages::EncodeImage(frame.frame.image, frame.frame.utime, messages::ImageEncoding::kMjpeg,
                              options_.jpeg_quality);
    if (lcm_.publish(messages::kCameraImageChannel, &message) != 0) {
      return FrameFailed("publishing CAMERA_IMAGE failed");
    }
    health_.Published();
    health_.Latency(Clock::now() - frame.read_at);
  } catch (const std::exception& e) {
    FrameFailed(e.what());
  }
}

void CameraNode::FrameFailed(const std::string& why) { health_.Dropped(why); }

}  // namespace billiard::camera_node
