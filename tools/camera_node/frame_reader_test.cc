// The reader's thread and watchdog, on scripted sources: what a source gives arrives in order,
// the reader stays at most a few frames ahead, and a source that gives nothing, blocks in a
// read or in its opening, or throws, ends with a reason within the stall timeout, never a hang.
#include "tools/camera_node/frame_reader.h"

#include <gtest/gtest.h>

#include <atomic>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace billiard::camera_node {
namespace {

using std::chrono::milliseconds;

constexpr auto kStall = milliseconds(200);

// A gate a scripted source can be held at until the test opens it (or for ever).
struct Gate {
  std::mutex mutex;
  std::condition_variable opened_cv;
  bool opened = false;
  void Wait() {
    std::unique_lock<std::mutex> lock(mutex);
    opened_cv.wait(lock, [this] { return opened; });
  }
  void Open() {
    std::lock_guard<std::mutex> lock(mutex);
    opened = true;
    opened_cv.notify_all();
  }
};

// Gives its script's reads in turn, then kNoFrame for ever; a read of kind kNoFrame with
// `blocked` set waits at the gate instead.
class ScriptedSource : public FrameSource {
 public:
  struct Step {
    ReadResult result;
    bool blocked = false;
  };
  ScriptedSource(std::vector<Step> script, std::shared_ptr<Gate> gate = nullptr,
                 bool open_blocks = false, std::string open_refusal = "")
      : script_(script.begin(), script.end()),
        gate_(std::move(gate)),
        open_blocks_(open_blocks),
        open_refusal_(std::move(open_refusal)) {}
  std::string Describe() const override { return "the script"; }
  std::string Open() override {
    if (open_blocks_) gate_->Wait();
    return open_refusal_;
  }
  ReadResult Read() override {
    ++reads;
    if (script_.empty()) return {};
    Step step = std::move(script_.front());
    script_.pop_front();
    if (step.blocked) gate_->Wait();
    return step.result;
  }
  bool Restart() override {
    ++restarts;
    script_ = {Frame(100)};
    return true;
  }
  double FrameRate() const override { return 12.0; }
  bool Live() const override { return false; }

  static Step Frame(std::int64_t utime) {
    Step s;
    s.result.kind = ReadResult::Kind::kFrame;
    s.result.frame.image = cv::Mat(2, 2, CV_8UC3, cv::Scalar::all(0));
    s.result.frame.utime = utime;
    return s;
  }
  static Step Said(ReadResult::Kind kind, const std::string& reason) {
    Step s;
    s.result.kind = kind;
    s.result.reason = reason;
    return s;
  }

  std::atomic<int> reads{0};
  std::atomic<int> restarts{0};

 private:
  std::deque<Step> script_;
  std::shared_ptr<Gate> gate_;
  const bool open_blocks_;
  const std::string open_refusal_;
};

ReaderOptions Options(bool loop = false) {
  ReaderOptions options;
  options.stall_timeout = kStall;
  options.loop = loop;
  return options;
}

// Every event until the end (kEnded or kFailed), each waited for up to a second.
std::vector<ReaderEvent> UntilTheEnd(FrameReader& reader) {
  std::vector<ReaderEvent> events;
  for (;;) {
    ReaderEvent e = reader.Next(std::chrono::seconds(1));
    if (e.kind == ReaderEvent::Kind::kNone) {
      ADD_FAILURE() << "no end within a second of the last event";
      return events;
    }
    events.push_back(e);
    if (e.kind == ReaderEvent::Kind::kEnded || e.kind == ReaderEvent::Kind::kFailed) {
      return events;
    }
  }
}

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

TEST(FrameReader, WhatTheSourceGivesArrivesInOrder) {
  using S = ScriptedSource;
  FrameReader reader(std::make_unique<S>(std::vector<S::Step>{
                         S::Frame(1), S::Said(ReadResult::Kind::kBadFrame, "frame 2 is damaged"),
                         S::Frame(3), S::Said(ReadResult::Kind::kEnd, "the script ended")}),
                     Options());
  EXPECT_EQ(reader.description(), "the script");
  const std::vector<ReaderEvent> events = UntilTheEnd(reader);
  ASSERT_EQ(events.size(), 5u);
  EXPECT_EQ(events[0].kind, ReaderEvent::Kind::kOpened);
  EXPECT_DOUBLE_EQ(events[0].rate, 12.0);
  EXPECT_FALSE(events[0].live);
  EXPECT_EQ(events[1].kind, ReaderEvent::Kind::kFrame);
  EXPECT_EQ(events[1].frame.utime, 1);
  EXPECT_EQ(events[2].kind, ReaderEvent::Kind::kBadFrame);
  EXPECT_EQ(events[2].reason, "frame 2 is damaged");
  EXPECT_EQ(events[3].frame.utime, 3);
  EXPECT_LE(events[1].read_at, events[3].read_at);
  EXPECT_EQ(events[4].kind, ReaderEvent::Kind::kEnded);
  EXPECT_EQ(events[4].reason, "the script ended");
  // After the end, nothing, at once.
  const Clock::time_point before = Clock::now();
  EXPECT_EQ(reader.Next(std::chrono::seconds(5)).kind, ReaderEvent::Kind::kNone);
  EXPECT_LT(Seconds(Clock::now() - before), 0.1);
}

TEST(FrameReader, TheReaderStaysAtMostTheQueueAhead) {
  using S = ScriptedSource;
  std::vector<S::Step> script;
  for (int k = 0; k < 10; ++k) script.push_back(S::Frame(k));
  auto source = std::make_unique<S>(script);
  S* watched = source.get();
  ReaderOptions options = Options();
  options.stall_timeout = std::chrono::seconds(10);
  FrameReader reader(std::move(source), options);
  ASSERT_EQ(reader.Next(std::chrono::seconds(1)).kind, ReaderEvent::Kind::kOpened);
  const Clock::time_point deadline = Clock::now() + std::chrono::seconds(2);
  while (reader.queued_frames() < options.max_queued_frames && Clock::now() < deadline) {
    std::this_thread::sleep_for(milliseconds(1));
  }
  std::this_thread::sleep_for(milliseconds(50));  // time to read further, were it to
  // Two frames queued, the third read and waiting for room.
  EXPECT_EQ(reader.queued_frames(), options.max_queued_frames);
  EXPECT_EQ(watched->reads, static_cast<int>(options.max_queued_frames) + 1);
  for (int k = 0; k < 10; ++k) {
    const ReaderEvent e = reader.Next(std::chrono::seconds(1));
    ASSERT_EQ(e.kind, ReaderEvent::Kind::kFrame);
    EXPECT_EQ(e.frame.utime, k);
  }
}

TEST(FrameReader, ASourceThatGivesNoFrameStalls) {
  using S = ScriptedSource;
  FrameReader reader(std::make_unique<S>(std::vector<S::Step>{S::Frame(1)}), Options());
  const Clock::time_point start = Clock::now();
  const std::vector<ReaderEvent> events = UntilTheEnd(reader);
  ASSERT_EQ(events.size(), 3u);
  EXPECT_EQ(events[1].kind, ReaderEvent::Kind::kFrame);
  EXPECT_EQ(events[2].kind, ReaderEvent::Kind::kFailed);
  EXPECT_EQ(events[2].reason, "the script gave no frame for 0.2 s: it stalled");
  EXPECT_GE(Seconds(Clock::now() - start), Seconds(kStall));
  EXPECT_LT(Seconds(Clock::now() - start), Seconds(kStall) + 0.5);
}

TEST(FrameReader, AReadThatNeverReturnsIsSeenByTheWatchdogAndLeftBehind) {
  using S = ScriptedSource;
  auto gate = std::make_shared<Gate>();
  S::Step stuck;
  stuck.blocked = true;
  const Clock::time_point start = Clock::now();
  {
    FrameReader reader(std::make_unique<S>(std::vector<S::Step>{S::Frame(1), stuck}, gate),
                       Options());
    const std::vector<ReaderEvent> events = UntilTheEnd(reader);
    ASSERT_EQ(events.size(), 3u);
    EXPECT_EQ(events[2].kind, ReaderEvent::Kind::kFailed);
    EXPECT_EQ(events[2].reason, "the script gave no frame for 0.2 s: it stalled");
    EXPECT_LT(Seconds(Clock::now() - start), Seconds(kStall) + 0.5);
  }
  // The reader went without waiting for the stuck read again.
  EXPECT_LT(Seconds(Clock::now() - start), Seconds(kStall) + 0.5);
  gate->Open();  // the abandoned thread ends with its read
}

TEST(FrameReader, AnOpeningThatNeverEndsIsSeenByTheWatchdog) {
  using S = ScriptedSource;
  auto gate = std::make_shared<Gate>();
  {
    FrameReader reader(std::make_unique<S>(std::vector<S::Step>{}, gate, /*open_blocks=*/true),
                       Options());
    const std::vector<ReaderEvent> events = UntilTheEnd(reader);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].kind, ReaderEvent::Kind::kFailed);
    EXPECT_EQ(events[0].reason, "the script did not open within 0.2 s");
  }
  gate->Open();
}

TEST(FrameReader, ARefusedOpeningAndAFailureAreTheirOwnReasons) {
  using S = ScriptedSource;
  FrameReader refused(
      std::make_unique<S>(std::vector<S::Step>{}, nullptr, false, "the script is not there"),
      Options());
  std::vector<ReaderEvent> events = UntilTheEnd(refused);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, ReaderEvent::Kind::kFailed);
  EXPECT_EQ(events[0].reason, "the script is not there");

  FrameReader cut(std::make_unique<S>(std::vector<S::Step>{
                      S::Frame(1), S::Said(ReadResult::Kind::kFailed, "the script is cut")}),
                  Options(/*loop=*/true));
  events = UntilTheEnd(cut);
  ASSERT_EQ(events.size(), 3u);
  EXPECT_EQ(events[2].kind, ReaderEvent::Kind::kFailed);
  EXPECT_EQ(events[2].reason, "the script is cut");
  EXPECT_EQ(cut.restarts(), 0) << "a failure is not played again, even with loop";
}

TEST(FrameReader, ASourceThatThrowsFailsWithItsReasonOnOneLine) {
  class Throwing : public ScriptedSource {
   public:
    Throwing() : ScriptedSource({}) {}
    ReadResult Read() override { throw std::runtime_error("a backend's\nmany lines\n"); }
  };
  FrameReader reader(std::make_unique<Throwing>(), Options());
  const std::vector<ReaderEvent> events = UntilTheEnd(reader);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[1].reason, "the script failed: a backend's many lines");
}

TEST(FrameReader, LoopPlaysTheSourceAgainAtItsEnd) {
  using S = ScriptedSource;
  auto source = std::make_unique<S>(
      std::vector<S::Step>{S::Frame(1), S::Said(ReadResult::Kind::kEnd, "the script ended")});
  S* watched = source.get();
  FrameReader reader(std::move(source), Options(/*loop=*/true));
  std::vector<std::int64_t> utimes;
  while (utimes.size() < 2) {
    const ReaderEvent e = reader.Next(std::chrono::seconds(1));
    ASSERT_NE(e.kind, ReaderEvent::Kind::kNone);
    if (e.kind == ReaderEvent::Kind::kFrame) utimes.push_back(e.frame.utime);
  }
  EXPECT_EQ(utimes, (std::vector<std::int64_t>{1, 100}));
  EXPECT_EQ(watched->restarts, 1);
  EXPECT_EQ(reader.restarts(), 1);
}

}  // namespace
}  // namespace billiard::camera_node
