// The planner node's message loop over LCM, in-process on memq:// (one LCM shared by the node and
// the test): the table states it keeps, the requests it queues, refuses and answers again, what
// it survives; and build/bin/planner_node as it is started and stopped. Each request mode is
// tested beside its handler (to_point_request_test.cc, pot_request_test.cc,
// choose_request_test.cc).
#include "planner/node/planner_node.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "lcmtypes/billiard/table_state_t.hpp"
#include "lcmtypes/names.h"
#include "planner/node/testing/node_harness.h"
#include "tests/support/run_command.h"

namespace billiard::planner_node::testing {
namespace {

TEST_F(PlannerNodeTest, RefusesWithAReasonAndKeepsAnswering) {
  PublishTable({Ball(1, 0.6, 0.5)});
  struct Case {
    shot_request_t request;
    int status;
  };
  std::vector<Case> cases = {
      {Request(1, 1, 5.0, 0.5), kOffTable},
      {Request(2, 9, 1.0, 0.5), kNoBallState},
      {Request(3, 1, kNaN, 0.5), kInvalid},
      {Request(4, 1, 1.0, 0.5, 9), kInvalid},
      {Request(5, 1, 1.0, 0.5, shot_request_t::SPIN_SLIDE), kInvalid},
      {Request(6, 1, 1.0, 0.5), kInvalid},
      {Request(7, 1, 1.0, 0.5), kInvalid},
  };
  cases[4].request.slide_length = kNaN;
  cases[5].request.final_speed = std::numeric_limits<double>::infinity();
  cases[6].request.side_spin = -kNaN;
  for (const Case& k : cases) {
    const auto answer = Ask(k.request);
    ASSERT_TRUE(answer) << "request " << k.request.request_id;
    EXPECT_EQ(Status(*answer), k.status)
        << "request " << k.request.request_id << ": " << answer->reason;
    EXPECT_FALSE(answer->reason.empty()) << "request " << k.request.request_id;
    EXPECT_EQ(answer->request_id, k.request.request_id);
    // A refused command cannot move the cue.
    for (double x : {answer->cue_speed, answer->heading, answer->tip_side, answer->tip_height,
                     answer->elevation}) {
      EXPECT_EQ(x, 0.0) << "request " << k.request.request_id;
    }
  }
  EXPECT_EQ(LogLinesContaining("request 1 (ball 1): off_table"), 1);
  EXPECT_EQ(LogLinesContaining("request 2 (ball 9): no_ball_state"), 1);

  // slide_length means nothing without SPIN_SLIDE: a NaN there is no reason to refuse.
  shot_request_t q = Request(8, 1, 1.0, 0.5);
  q.slide_length = kNaN;
  AskOk(q);
}

// A loop whose estimator lags behind its frames asks while the states still show the last shot's
// balls rolling: the request is held, unanswered, until the table has been at rest for
// rest_states states, and planned from where the balls came to rest.
TEST_F(PlannerNodeTest, APlanWaitsForTheTableAtRest) {
  const PlannerNodeOptions defaults;
  ASSERT_EQ(defaults.rest_states, 3);
  // Ball 2 is below the 0.05 m/s threshold (the estimator's noise on a ball at rest), ball 1 not.
  PublishTable({Ball(1, 0.6, 0.5, 0.3, 0.1), Ball(2, 1.6, 0.5, 0.01, -0.02)}, 990'000);
  EXPECT_FALSE(Ask(Request(1, 2, 1.0, 0.5))) << "answered while ball 1 rolls";
  EXPECT_FALSE(Ask(Request(2, 1, 1.0, 0.5))) << "answered while ball 1 rolls";
  EXPECT_EQ(LogLinesContaining("request 1 held until the table is at rest: ball 1 is moving"), 1);
  // Ball 1 slows, then stops at (0.8, 0.55): at rest for one state, then two, then three.
  PublishTable({Ball(1, 0.7, 0.53, 0.06, 0.0), Ball(2, 1.6, 0.5)}, 1'000'000);
  const std::vector<int64_t> at_rest = {1'010'000, 1'020'000, 1'030'000};
  for (std::size_t n = 0; n < at_rest.size(); ++n) {
    EXPECT_FALSE(AnswerTo(1)) << "answered after " << n << " states at rest";
    PublishTable({Ball(1, 0.8, 0.55, 0.001, 0.0), Ball(2, 1.6, 0.5)}, at_rest[n]);
    RunNode();
  }
  const auto first = AnswerTo(1);
  const auto second = AnswerTo(2);
  ASSERT_TRUE(first && second);
  EXPECT_EQ(Status(*first), kOk) << first->reason;
  EXPECT_EQ(Status(*second), kOk) << second->reason;
  // Planned from the state at rest, not from where ball 1 was seen rolling.
  EXPECT_EQ(second->start[0], 0.8);
  EXPECT_EQ(second->start[1], 0.55);
  EXPECT_EQ(node_.health().counter("held_for_rest"), 1);
  // A table never seen moving is at rest from its first state.
  AskOk(Request(3, 2, 1.0, 0.4));
}

TEST_F(PlannerNodeTest, ATableThatNeverRestsIsRefusedNotAtRestAfterTheWait) {
  const double wait = PlannerNodeOptions{}.max_rest_wait;
  const shot_request_t q = Request(1, 1, 1.0, 0.5);
  PublishTable({Ball(1, 0.6, 0.5, 0.3, 0.0)}, q.utime);
  EXPECT_FALSE(Ask(q));
  // Still rolling just short of the wait (in the states' time), then past it.
  const auto micros = [](double s) { return static_cast<int64_t>(1e6 * s); };
  PublishTable({Ball(1, 0.9, 0.5, 0.2, 0.0)}, q.utime + micros(wait) - 1);
  RunNode();
  EXPECT_FALSE(AnswerTo(1));
  PublishTable({Ball(1, 1.1, 0.5, 0.1, 0.0)}, q.utime + micros(wait));
  RunNode();
  const auto refused = AnswerTo(1);
  ASSERT_TRUE(refused);
  EXPECT_EQ(Status(*refused), cue_command_t::STATUS_NOT_AT_REST);
  EXPECT_EQ(messages::CueCommandStatusName(refused->status), "not_at_rest");
  EXPECT_NE(refused->reason.find("did not come to rest within 2 s: ball 1 is moving (0.1 m/s"),
            std::string::npos)
      << refused->reason;
  EXPECT_EQ(refused->cue_speed, 0.0);
  // The node answers on once the table rests.
  for (int n = 1; n <= 3; ++n) PublishTable({Ball(1, 1.1, 0.5)}, q.utime + micros(wait) + n);
  shot_request_t later = Request(2, 1, 1.5, 0.5);
  later.utime = q.utime + micros(wait) + 3;
  AskOk(later);
}

// A loop slower than real time (a busy machine): the states keep coming, their time advancing a
// tenth of the clock's. The request is held in the states' time, as a replay of the loop's log
// would hold it, however long the clock runs; once the states stop, the clock refuses it.
TEST(PlannerNodeRestWait, ALoopSlowerThanRealTimeWaitsInTheStatesTimeUntilTheStatesStop) {
  lcm::LCM lcm("memq://");
  std::vector<cue_command_t> commands;
  struct Collect {
    std::vector<cue_command_t>* commands;
    void On(const lcm::ReceiveBuffer*, const std::string&, const cue_command_t* c) {
      commands->push_back(*c);
    }
  } collect{&commands};
  lcm.subscribe(messages::kCueCommandChannel, &Collect::On, &collect)->setQueueCapacity(0);
  PlannerNodeOptions options;
  options.max_rest_wait = 0.5;  // [s], so that the test's clock runs past it in a second
  const physics::ModelParameters params = params::LoadParameters("paper");
  PlannerNode node(lcm, params, options, [](const std::string&) {});
  const auto run = [&] { nodes::HandleUntilIdle(lcm, [&] { return node.Work(); }); };
  const auto publish_rolling = [&](int64_t utime) {
    table_state_t state{};
    state.utime = utime;
    state.balls = {Ball(1, 0.6, 0.5, 0.3, 0.0)};
    state.balls[0].utime = utime;
    state.num_balls = 1;
    ASSERT_EQ(lcm.publish(messages::kTableStateChannel, &state), 0);
  };
  const shot_request_t q = Request(1, 1, 1.0, 0.5);
  publish_rolling(q.utime);
  ASSERT_EQ(lcm.publish(messages::kShotRequestChannel, &q), 0);
  run();
  constexpr int kStates = 60;
  constexpr auto kFrame = std::chrono::milliseconds(20);  // 1.2 s of clock, 0.12 s of states
  for (int n = 1; n <= kStates; ++n) {
    std::this_thread::sleep_for(kFrame);
    publish_rolling(q.utime + n * 2'000);
    run();
  }
  EXPECT_TRUE(commands.empty()) << "answered " << messages::CueCommandStatusName(commands[0].status)
                                << " while the states came: " << commands[0].reason;
  std::this_thread::sleep_for(std::chrono::duration<double>(options.max_rest_wait));
  run();
  ASSERT_EQ(commands.size(), 1u) << "not refused once the states stopped";
  EXPECT_EQ(Status(commands[0]), cue_command_t::STATUS_NOT_AT_REST) << commands[0].reason;
}

TEST_F(PlannerNodeTest, ABallStateThatDoesNotDecodeIsNoStateToPlanFrom) {
  // A state with a NaN is dropped on arrival: there is no state of that ball to plan from.
  PublishTable({Ball(4, kNaN, 0.5)});
  const auto nan_state = Ask(Request(3, 4, 1.0, 0.5));
  ASSERT_TRUE(nan_state);
  EXPECT_EQ(Status(*nan_state), kNoBallState);
  EXPECT_EQ(LogLinesContaining("ball 4 has a non-finite position"), 1);
}

TEST_F(PlannerNodeTest, ABallAskedForByClassIsTheOneTheEstimatorIsSurestOf) {
  PublishTable({Classed(1, 0.6, 0.5, ball_state_t::CLASS_CUE, 0.55f),
                Classed(2, 1.6, 0.7, ball_state_t::CLASS_CUE, 0.9f), Classed(3, 1.0, 0.3, 8, 0.95f),
                Classed(4, 0.4, 0.8, ball_state_t::CLASS_RED, 0.3f)});
  shot_request_t q = Request(1, shot_request_t::BALL_BY_CLASS, 1.2, 0.6);
  q.ball_class = ball_state_t::CLASS_CUE;
  const cue_command_t cue = AskOk(q);
  EXPECT_EQ(cue.ball_id, 2);  // the surer of the two cue balls
  EXPECT_EQ(cue.start[0], 1.6);
  q.request_id = 2;
  q.ball_class = 8;
  EXPECT_EQ(AskOk(q).ball_id, 3);
  // Not sure enough (a red at 0.3), or none of the class: no ball state to plan from.
  for (const int8_t missing : {ball_state_t::CLASS_RED, ball_state_t::CLASS_PINK}) {
    q.request_id += 1;
    q.ball_class = missing;
    const auto none = Ask(q);
    ASSERT_TRUE(none);
    EXPECT_EQ(Status(*none), kNoBallState);
    EXPECT_NE(none->reason.find("class"), std::string::npos) << none->reason;
  }
  // A request by class with no class is invalid.
  q.request_id += 1;
  q.ball_class = ball_state_t::CLASS_UNKNOWN;
  const auto unknown = Ask(q);
  ASSERT_TRUE(unknown);
  EXPECT_EQ(Status(*unknown), kInvalid);
}

TEST_F(PlannerNodeTest, KeepsTheLatestStateOfEachBall) {
  PublishTable({Ball(1, 0.6, 0.5), Ball(2, 2.0, 1.0)});
  PublishTable({Ball(1, 0.7, 0.4)}, 1'500'000);  // ball 2 not seen this time
  const cue_command_t one = AskOk(Request(1, 1, 1.5, 0.6));
  EXPECT_EQ(one.start[0], 0.7);
  EXPECT_EQ(one.start[1], 0.4);
  const cue_command_t two = AskOk(Request(2, 2, 1.5, 0.6));
  EXPECT_EQ(two.start[0], 2.0);
  EXPECT_EQ(two.start[1], 1.0);
}

TEST_F(PlannerNodeTest, SurvivesPayloadsThatDoNotDecode) {
  const std::string garbage = "this is not an LCM message";
  lcm_.publish(messages::kShotRequestChannel, garbage.data(),
               static_cast<unsigned>(garbage.size()));
  lcm_.publish(messages::kTableStateChannel, garbage.data(), static_cast<unsigned>(garbage.size()));

  // A request cut short, and one with bytes after it.
  const shot_request_t request = Request(1, 1, 1.0, 0.5);
  std::vector<uint8_t> bytes(request.getEncodedSize() + 3);
  ASSERT_EQ(request.encode(bytes.data(), 0, static_cast<int>(bytes.size())),
            request.getEncodedSize());
  lcm_.publish(messages::kShotRequestChannel, bytes.data(), request.getEncodedSize() - 1);
  lcm_.publish(messages::kShotRequestChannel, bytes.data(), static_cast<unsigned>(bytes.size()));

  // Table states whose ball count lies: the decoder would size its vector from it.
  table_state_t state{};
  state.num_balls = 1;
  state.balls = {Ball(1, 0.6, 0.5)};
  std::vector<uint8_t> table(state.getEncodedSize());
  ASSERT_EQ(state.encode(table.data(), 0, static_cast<int>(table.size())),
            static_cast<int>(table.size()));
  for (uint32_t count : {0xffffffffu, 100'000'000u}) {
    for (int i = 0; i < 4; ++i) table[16 + i] = static_cast<uint8_t>(count >> (24 - 8 * i));
    lcm_.publish(messages::kTableStateChannel, table.data(), static_cast<unsigned>(table.size()));
  }

  // None of that was taken for a request or a ball.
  const auto answer = Ask(Request(2, 1, 1.0, 0.5));
  ASSERT_TRUE(answer);
  EXPECT_EQ(Status(*answer), kNoBallState);
  EXPECT_EQ(commands_.size(), 1u);
  EXPECT_EQ(LogLinesContaining("dropped"), 6);

  PublishTable({Ball(1, 0.6, 0.5)});
  AskOk(Request(3, 1, 1.0, 0.5));
}

TEST_F(PlannerNodeTest, NeverActsOnAStaleState) {
  PublishTable({Ball(1, 0.6, 0.5)}, 1'000'000);
  shot_request_t late = Request(1, 1, 1.5, 0.6);
  late.utime = 2'500'000;  // the estimator has said nothing for 1.5 s
  const auto stale = Ask(late);
  ASSERT_TRUE(stale);
  EXPECT_EQ(Status(*stale), cue_command_t::STATUS_STALE_STATE) << stale->reason;
  EXPECT_NE(stale->reason.find("1.5 s older"), std::string::npos) << stale->reason;
  EXPECT_EQ(stale->cue_speed, 0.0);

  PublishTable({Ball(1, 0.6, 0.5)}, 2'400'000);
  late.request_id = 2;
  AskOk(late);
}

TEST_F(PlannerNodeTest, DropsLateStatesAndForgetsAnOldClock) {
  PublishTable({Ball(1, 0.7, 0.4)}, 12'000'000);
  PublishTable({Ball(1, 0.6, 0.5)}, 11'900'000);  // arrives late: the ball is not back there
  PublishTable({Ball(1, 0.7, 0.4)}, 12'000'000);  // the same state again
  shot_request_t q = Request(1, 1, 1.5, 0.6);
  q.utime = 12'000'000;
  EXPECT_EQ(AskOk(q).start[0], 0.7);
  EXPECT_EQ(LogLinesContaining("older than the latest"), 1);
  EXPECT_EQ(node_.health().counter("duplicate"), 1);

  // The estimator restarted with its clock near zero: a new session, not a late message.
  PublishTable({Ball(3, 1.0, 1.0)}, 100'000);
  q.request_id = 2;
  q.utime = 100'000;
  EXPECT_EQ(Status(*Ask(q)), kNoBallState) << "ball 1 belonged to the old clock";
  EXPECT_EQ(node_.health().counter("clock_reset"), 1);
}

TEST_F(PlannerNodeTest, ARequestSentAgainGetsTheSameAnswerWithoutPlanningAgain) {
  PublishTable({Ball(1, 0.6, 0.5)});
  const shot_request_t q = Request(1, 1, 1.5, 0.6);
  const cue_command_t first = AskOk(q);
  const cue_command_t again = AskOk(q);
  EXPECT_EQ(again.solve_us, first.solve_us) << "planned again";
  EXPECT_EQ(node_.health().counter("duplicate"), 1);
  EXPECT_EQ(commands_.size(), 2u);

  // Once the ball's state has changed the same request is a new question.
  PublishTable({Ball(1, 0.6, 0.55)}, 1'000'010);
  EXPECT_NE(AskOk(q).start[1], first.start[1]);
  EXPECT_EQ(node_.health().counter("duplicate"), 1);
}

TEST_F(PlannerNodeTest, ABurstIsAnsweredInFullFromABoundedQueue) {
  // The latency figures of the statuses the node publishes meanwhile (its first at once).
  struct Latencies {
    long count = 0;
    void On(const lcm::ReceiveBuffer*, const std::string&, const node_status_t* s) {
      count += s->latency_count;
    }
  } published_latencies;
  lcm_.subscribe(messages::kNodeStatusChannel, &Latencies::On, &published_latencies);
  PublishTable({Ball(1, 0.6, 0.5)});
  constexpr int kBurst = 10000;
  for (int id = 0; id < kBurst; ++id) {
    const shot_request_t q = Request(id, 1, 1.5, 0.6 + 1e-6 * id);
    ASSERT_EQ(lcm_.publish(messages::kShotRequestChannel, &q), 0);
  }
  // Everything has arrived before the first plan: the queue takes what it holds, the rest is
  // refused at once, and nothing goes unanswered.
  while (lcm_.handleTimeout(0) > 0) {
  }
  const int capacity = PlannerNodeOptions{}.queue_capacity;
  EXPECT_EQ(node_.health().counter("busy"), kBurst - capacity);
  RunNode();
  std::vector<int> answers(kBurst, 0);
  int ok = 0, busy = 0;
  for (const cue_command_t& c : commands_) {
    ++answers.at(c.request_id);
    ok += Status(c) == kOk;
    busy += Status(c) == cue_command_t::STATUS_BUSY;
  }
  EXPECT_EQ(std::count(answers.begin(), answers.end(), 1), kBurst) << "each answered once";
  EXPECT_EQ(ok, capacity);
  EXPECT_EQ(busy, kBurst - capacity);
  const node_status_t status = node_.health().TakeStatus();
  EXPECT_EQ(status.queue_depth, 0);
  EXPECT_EQ(status.published, kBurst);
  EXPECT_EQ(published_latencies.count + status.latency_count, kBurst);
  EXPECT_GT(status.latency_max_us, status.latency_p50_us);
  EXPECT_EQ(LogLinesContaining("queue full"), 1) << "one line, not one per refusal";
}

TEST(PlannerNodeBinary, StopsCleanlyOnSigintAndSigterm) {
  for (const char* signal : {"INT", "TERM"}) {
    const auto r =
        billiard::testing::RunCommand(std::string("timeout --preserve-status -s ") + signal +
                                          " 1 " PLANNER_NODE_BIN + " --lcm-url memq://",
                                      true);
    EXPECT_EQ(r.status, 0) << signal << ": " << r.out;
    EXPECT_NE(r.out.find("planner_node: stopped"), std::string::npos) << signal << ": " << r.out;
  }
}

TEST(PlannerNodeBinary, BadStartExitsNonZeroWithAOneLineReason) {
  const auto bad_url =
      billiard::testing::RunCommand(PLANNER_NODE_BIN " --lcm-url nosuchprovider://x", true);
  EXPECT_EQ(bad_url.status, 1) << bad_url.out;
  EXPECT_NE(bad_url.out.find("planner_node: cannot initialise LCM with 'nosuchprovider://x'\n"),
            std::string::npos)
      << bad_url.out;
  // A table that does not load, and one of another size than the parameter set's.
  for (const char* args : {" --params no-such-set", " --max-ball-speed nan", " --frobnicate",
                           " --table no-such-table", " --table snooker-12ft", " --rest-states 0",
                           " --max-rest-wait -1"}) {
    const auto r = billiard::testing::RunCommand(PLANNER_NODE_BIN + std::string(args), true);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << args << ": " << r.out;
  }
}

// A planner started by hand where the kernel caps the receive buffer below what its URL asks
// loses most of a burst unseen (billiard burst: 3,000-6,500 of 10,000 on a stock kernel); it says
// so at once, with what to run.
TEST(PlannerNodeBinary, SaysWhenTheKernelGrantsASmallerReceiveBufferThanItsUrlAsks) {
  const auto r = billiard::testing::RunCommand(
      "timeout --preserve-status -s INT 1 " PLANNER_NODE_BIN
      " --lcm-url 'udpm://239.255.76.67:7667?ttl=0&recv_buf_size=2000000000'",
      true);
  EXPECT_NE(r.out.find("sysctl -w net.core.rmem_max=2000000000"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace billiard::planner_node::testing
