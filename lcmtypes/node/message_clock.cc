#include "lcmtypes/node/message_clock.h"

namespace billiard::nodes {

MessageClock::Verdict MessageClock::Accept(std::int64_t utime) {
  if (utime == latest_) return Verdict::kDuplicate;
  if (utime > latest_) {
    latest_ = utime;
    late_in_a_row_ = 0;
    return Verdict::kNext;
  }
  // The same late message again counts too: a lockstep publisher that restarted sends its first
  // message again until it is answered, and nothing newer comes meanwhile.
  late_in_a_row_ = late_in_a_row_ > 0 && utime >= last_late_ ? late_in_a_row_ + 1 : 1;
  last_late_ = utime;
  if (latest_ - utime > reset_after_us_ || late_in_a_row_ >= late_run_) {
    latest_ = utime;
    late_in_a_row_ = 0;
    return Verdict::kNewClock;
  }
  return Verdict::kLate;
}

}  // namespace billiard::nodes
