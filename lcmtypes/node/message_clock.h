// The order of one publisher's messages, by their utime. A node takes a message that is newer
// than the last it took, ignores the same one again, and drops an older one as late (delayed or
// reordered on the way) - unless the publisher has evidently started a new clock (a simulator or
// camera restarted, a log replayed from its start): the message is older by more than
// `reset_after`, or several late messages arrive in a row with nothing newer between them, each
// as new as the one before or newer: a restarted publisher going on from its new start, or a
// lockstep one sending its first message again until it is answered. A reordered or repeated
// message never makes such a run, since newer messages keep arriving around it. Then what the
// node knew of the old clock must be forgotten.
#pragma once

#include <cstdint>

namespace billiard::nodes {

class MessageClock {
 public:
  enum class Verdict { kNext, kDuplicate, kLate, kNewClock };

  // reset_after [s]; late_run: late messages in a row, none older than the one before, that make
  // a new clock.
  explicit MessageClock(double reset_after = 5.0, int late_run = 3)
      : reset_after_us_(static_cast<std::int64_t>(reset_after * 1e6)), late_run_(late_run) {}

  // The verdict on a message stamped `utime`; kNext and kNewClock make it the latest.
  Verdict Accept(std::int64_t utime);

  // The utime of the latest message taken, -1 before the first.
  std::int64_t latest() const { return latest_; }

 private:
  const std::int64_t reset_after_us_;
  const int late_run_;
  std::int64_t latest_ = -1;
  std::int64_t last_late_ = -1;
  int late_in_a_row_ = 0;
};

}  // namespace billiard::nodes
