#include "tools/camera_node/frame_reader.h"

#include <algorithm>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <exception>
#include <mutex>
#include <utility>

namespace billiard::camera_node {

// What the two threads share, under `mutex`; the source is the reader thread's alone.
struct FrameReader::Shared {
  explicit Shared(std::unique_ptr<FrameSource> s) : source(std::move(s)) {}

  std::mutex mutex;
  std::condition_variable changed;
  std::unique_ptr<FrameSource> source;
  std::deque<ReaderEvent> events;
  std::size_t frames_queued = 0;
  bool opened = false;
  bool stop = false;      // the node is done with the reader
  bool over = false;      // the source's end is decided: nothing more is queued
  bool finished = false;  // the thread has returned
  bool waiting_for_room = false;
  Clock::time_point waiting_since = Clock::now();  // for the source, since
  long restarts = 0;
};

namespace {

using Shared = FrameReader::Shared;

// A read that gives no frame is tried again this much later: a camera between frames answers
// the next read, one that fails answers at once, and the retries must not spin a core.
constexpr auto kNoFrameRetry = std::chrono::milliseconds(5);

// The source's end, queued after what came before it; the first end decided is the one.
void Finish(Shared& s, ReaderEvent::Kind kind, std::string reason) {
  if (s.over) return;
  s.over = true;
  ReaderEvent end;
  end.kind = kind;
  end.reason = std::move(reason);
  s.events.push_back(std::move(end));
  s.changed.notify_all();
}

bool Stalled(const Shared& s, Clock::time_point now, Clock::duration timeout) {
  return !s.over && !s.waiting_for_room && now - s.waiting_since > timeout;
}

std::string StallReason(const Shared& s, const std::string& description, Clock::duration timeout) {
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.1f s", std::chrono::duration<double>(timeout).count());
  return s.opened ? description + " gave no frame for " + seconds + ": it stalled"
                  : description + " did not open within " + seconds;
}

// An exception's text on one line (OpenCV's end in a newline).
std::string OneLine(const std::string& text) {
  std::string line = text;
  std::replace(line.begin(), line.end(), '\n', ' ');
  while (!line.empty() && line.back() == ' ') line.pop_back();
  return line;
}

// Queues what one read gave; false when the thread is to stop.
bool Hand(Shared& s, ReadResult read, const ReaderOptions& options,
          const std::string& description) {
  std::unique_lock<std::mutex> lock(s.mutex);
  if (s.over || s.stop) return false;
  const Clock::time_point now = Clock::now();
  ReaderEvent event;
  switch (read.kind) {
    case ReadResult::Kind::kFrame:
      s.waiting_for_room = true;
      s.changed.wait(lock, [&] { return s.stop || s.frames_queued < options.max_queued_frames; });
      s.waiting_for_room = false;
      if (s.stop) return false;
      event.kind = ReaderEvent::Kind::kFrame;
      event.frame = std::move(read.frame);
      event.read_at = now;
      ++s.frames_queued;
      break;
    case ReadResult::Kind::kBadFrame:
      event.kind = ReaderEvent::Kind::kBadFrame;
      event.reason = std::move(read.reason);
      break;
    case ReadResult::Kind::kNoFrame:
      if (Stalled(s, now, options.stall_timeout)) {
        Finish(s, ReaderEvent::Kind::kFailed, StallReason(s, description, options.stall_timeout));
        return false;
      }
      lock.unlock();
      std::this_thread::sleep_for(kNoFrameRetry);
      return true;
    case ReadResult::Kind::kEnd:
      if (options.loop) {
        lock.unlock();
        const bool restarted = s.source->Restart();
        lock.lock();
        if (restarted) {
          ++s.restarts;
          s.waiting_since = Clock::now();
          return true;
        }
        read.reason += "; it cannot be played again";
      }
      Finish(s, ReaderEvent::Kind::kEnded, std::move(read.reason));
      return false;
    case ReadResult::Kind::kFailed:
      Finish(s, ReaderEvent::Kind::kFailed, std::move(read.reason));
      return false;
  }
  s.events.push_back(std::move(event));
  s.waiting_since = Clock::now();
  s.changed.notify_all();
  return true;
}

// Opens the source and queues that it opened, or how it failed; false when it did not open.
bool OpenSource(Shared& s) {
  const std::string refused = s.source->Open();
  std::lock_guard<std::mutex> lock(s.mutex);
  if (!refused.empty()) {
    Finish(s, ReaderEvent::Kind::kFailed, refused);
    return false;
  }
  if (s.over) return false;  // the watchdog gave up on the opening
  s.opened = true;
  ReaderEvent opened;
  opened.kind = ReaderEvent::Kind::kOpened;
  opened.rate = s.source->FrameRate();
  opened.live = s.source->Live();
  s.events.push_back(std::move(opened));
  s.waiting_since = Clock::now();
  s.changed.notify_all();
  return true;
}

// The reader thread: the source opened, then read until its end, a stall, or the node's stop.
void ReadSource(const std::shared_ptr<Shared>& shared, const ReaderOptions& options,
                const std::string& description) {
  Shared& s = *shared;
  try {
    if (OpenSource(s)) {
      while (Hand(s, s.source->Read(), options, description)) {
      }
    }
  } catch (const std::exception& e) {
    std::lock_guard<std::mutex> lock(s.mutex);
    Finish(s, ReaderEvent::Kind::kFailed, description + " failed: " + OneLine(e.what()));
  }
  std::lock_guard<std::mutex> lock(s.mutex);
  s.finished = true;
  s.changed.notify_all();
}

}  // namespace

FrameReader::FrameReader(std::unique_ptr<FrameSource> source, ReaderOptions options)
    : description_(source->Describe()),
      options_(options),
      shared_(std::make_shared<Shared>(std::move(source))) {
  thread_ = std::thread(ReadSource, shared_, options_, description_);
}

FrameReader::~FrameReader() {
  Shared& s = *shared_;
  std::unique_lock<std::mutex> lock(s.mutex);
  s.stop = true;
  s.changed.notify_all();
  // A read the watchdog gave up on is not waited for again.
  const bool finished = (s.over && !s.finished) ? false
                                                : s.changed.wait_for(lock, options_.stall_timeout,
                                                                     [&] { return s.finished; });
  lock.unlock();
  if (finished) {
    thread_.join();
  } else {
    thread_.detach();
  }
}

ReaderEvent FrameReader::Next(Clock::duration wait) {
  Shared& s = *shared_;
  std::unique_lock<std::mutex> lock(s.mutex);
  const Clock::time_point deadline = Clock::now() + wait;
  while (s.events.empty()) {
    const Clock::time_point now = Clock::now();
    if (Stalled(s, now, options_.stall_timeout)) {
      Finish(s, ReaderEvent::Kind::kFailed, StallReason(s, description_, options_.stall_timeout));
      break;
    }
    if (now >= deadline || s.finished) return {};
    const bool watching = !s.over && !s.waiting_for_room;
    s.changed.wait_until(
        lock, watching ? std::min(deadline, s.waiting_since + options_.stall_timeout) : deadline);
  }
  ReaderEvent event = std::move(s.events.front());
  s.events.pop_front();
  if (event.kind == ReaderEvent::Kind::kFrame) {
    --s.frames_queued;
    s.changed.notify_all();
  }
  return event;
}

std::size_t FrameReader::queued_frames() const {
  std::lock_guard<std::mutex> lock(shared_->mutex);
  return shared_->frames_queued;
}

long FrameReader::restarts() const {
  std::lock_guard<std::mutex> lock(shared_->mutex);
  return shared_->restarts;
}

}  // namespace billiard::camera_node
