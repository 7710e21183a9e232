#include "lcmtypes/node/message_clock.h"

#include <gtest/gtest.h>

namespace billiard::nodes {
namespace {

using Verdict = MessageClock::Verdict;

TEST(MessageClock, TakesNewerIgnoresRepeatsAndDropsLateMessages) {
  MessageClock clock;
  EXPECT_EQ(clock.Accept(1'000), Verdict::kNext);
  EXPECT_EQ(clock.Accept(2'000), Verdict::kNext);
  EXPECT_EQ(clock.Accept(2'000), Verdict::kDuplicate);
  EXPECT_EQ(clock.Accept(1'500), Verdict::kLate);
  EXPECT_EQ(clock.latest(), 2'000);
  EXPECT_EQ(clock.Accept(3'000), Verdict::kNext);
}

TEST(MessageClock, ReorderedStreamsNeverLookLikeANewClock) {
  // Every other pair swapped, over a long run: one late message at a time.
  MessageClock clock;
  int late = 0;
  for (std::int64_t k = 0; k < 1000; k += 2) {
    EXPECT_NE(clock.Accept(33'333 * (k + 1)), Verdict::kNewClock);
    late += clock.Accept(33'333 * k) == Verdict::kLate;
  }
  EXPECT_EQ(late, 500);
}

TEST(MessageClock, AFarJumpBackIsANewClock) {
  MessageClock clock(5.0);
  clock.Accept(20'000'000);
  EXPECT_EQ(clock.Accept(14'000'000), Verdict::kNewClock);
  EXPECT_EQ(clock.latest(), 14'000'000);
  EXPECT_EQ(clock.Accept(14'033'333), Verdict::kNext);
}

TEST(MessageClock, ARestartCloseToTheOldTimeIsANewClockAfterAFewMessages) {
  // The old session ended at 3 s; the new one starts again at 0 and is late three times in a
  // row, each newer than the one before.
  MessageClock clock(5.0, 3);
  clock.Accept(3'000'000);
  EXPECT_EQ(clock.Accept(0), Verdict::kLate);
  EXPECT_EQ(clock.Accept(33'333), Verdict::kLate);
  EXPECT_EQ(clock.Accept(66'667), Verdict::kNewClock);
  EXPECT_EQ(clock.Accept(100'000), Verdict::kNext);
}

TEST(MessageClock, ARestartedPublisherSendingItsFirstMessageAgainIsANewClock) {
  // A lockstep simulator restarted 3 s into the old session's clock waits for the answer to its
  // first frame and sends that same frame again and again: nothing newer ever comes.
  MessageClock clock(5.0, 3);
  clock.Accept(3'000'000);
  EXPECT_EQ(clock.Accept(0), Verdict::kLate);
  EXPECT_EQ(clock.Accept(0), Verdict::kLate);
  EXPECT_EQ(clock.Accept(0), Verdict::kNewClock);
  EXPECT_EQ(clock.latest(), 0);
  EXPECT_EQ(clock.Accept(0), Verdict::kDuplicate);
  EXPECT_EQ(clock.Accept(33'333), Verdict::kNext);
}

TEST(MessageClock, ALateDuplicateAmongNewerMessagesIsNoNewClock) {
  // A lossy link repeats an old frame while newer ones keep coming: late every time, never a
  // new clock.
  MessageClock clock(5.0, 3);
  for (std::int64_t k = 10; k < 100; ++k) {
    EXPECT_EQ(clock.Accept(33'333 * k), Verdict::kNext);
    EXPECT_EQ(clock.Accept(33'333 * (k - 5)), Verdict::kLate);
    EXPECT_EQ(clock.Accept(33'333 * (k - 5)), Verdict::kLate);
  }
}

TEST(MessageClock, LateMessagesOutOfOrderAmongThemselvesAreNoNewClock) {
  MessageClock clock(5.0, 3);
  clock.Accept(3'000'000);
  EXPECT_EQ(clock.Accept(2'900'000), Verdict::kLate);
  EXPECT_EQ(clock.Accept(2'800'000), Verdict::kLate);  // older than the last late: run restarts
  EXPECT_EQ(clock.Accept(2'850'000), Verdict::kLate);
  EXPECT_EQ(clock.Accept(2'700'000), Verdict::kLate);
}

}  // namespace
}  // namespace billiard::nodes
