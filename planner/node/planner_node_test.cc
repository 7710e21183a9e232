// The planner node over LCM: in-process on memq:// (one LCM shared by the node and the test), and
// build/bin/planner_node as it is started and stopped.
#include "planner/node/planner_node.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "lcmtypes/billiard/table_state_t.hpp"
#include "lcmtypes/names.h"
#include "lcmtypes/node/node_loop.h"
#include "sim/model_choice/model_choice.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/physics/ball_state.h"
#include "sim/table/table_simulation.h"
#include "tests/support/run_command.h"

namespace billiard::planner_node {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The message constants are declared without a definition (lcm-gen's C++98 output), so a test
// must not bind them to a reference: compare them as ints.
int Status(const cue_command_t& c) { return c.status; }
constexpr int kOk = cue_command_t::STATUS_OK;
constexpr int kInvalid = cue_command_t::STATUS_INVALID;
constexpr int kOffTable = cue_command_t::STATUS_OFF_TABLE;
constexpr int kNoBallState = cue_command_t::STATUS_NO_BALL_STATE;

ball_state_t Ball(int32_t id, double x, double y, double vx = 0.0, double vy = 0.0) {
  ball_state_t b{};
  b.ball_id = id;
  b.position[0] = x;
  b.position[1] = y;
  b.velocity[0] = vx;
  b.velocity[1] = vy;
  return b;
}

shot_request_t Request(int64_t id, int32_t ball, double x, double y,
                       int8_t spin = shot_request_t::SPIN_NATURAL) {
  shot_request_t q{};
  q.utime = 1'000'000 + 17 * id;
  q.request_id = id;
  q.ball_id = ball;
  q.target[0] = x;
  q.target[1] = y;
  q.spin = spin;
  return q;
}

class PlannerNodeTest : public ::testing::Test {
 protected:
  PlannerNodeTest() {
    // Unbounded: a burst's answers all arrive before the test handles the first.
    lcm_.subscribe(messages::kCueCommandChannel, &PlannerNodeTest::OnCommand, this)
        ->setQueueCapacity(0);
  }

  void OnCommand(const lcm::ReceiveBuffer*, const std::string&, const cue_command_t* c) {
    commands_.push_back(*c);
  }

  void PublishTable(const std::vector<ball_state_t>& balls, int64_t utime = 1'000'000) {
    table_state_t state{};
    state.utime = utime;
    state.num_balls = static_cast<int32_t>(balls.size());
    state.balls = balls;
    for (ball_state_t& b : state.balls) b.utime = utime;
    ASSERT_EQ(lcm_.publish(messages::kTableStateChannel, &state), 0);
  }

  // Runs the node as its main loop does until it has nothing left to do.
  void RunNode() {
    nodes::HandleUntilIdle(lcm_, [this] { return node_.Work(); });
  }

  // Publishes the request and runs the node: the answer, or nullopt if there is none.
  std::optional<cue_command_t> Ask(const shot_request_t& request) {
    EXPECT_EQ(lcm_.publish(messages::kShotRequestChannel, &request), 0);
    RunNode();
    for (auto c = commands_.rbegin(); c != commands_.rend(); ++c) {
      if (c->request_id == request.request_id) return *c;
    }
    return std::nullopt;
  }

  cue_command_t AskOk(const shot_request_t& request) {
    const auto answer = Ask(request);
    EXPECT_TRUE(answer) << "no answer to request " << request.request_id;
    if (!answer) return {};
    EXPECT_EQ(Status(*answer), kOk) << answer->reason;
    return *answer;
  }

  int LogLinesContaining(const std::string& text) const {
    int n = 0;
    for (const std::string& line : log_) n += line.find(text) != std::string::npos;
    return n;
  }

  lcm::LCM lcm_{"memq://"};
  const physics::ModelParameters params_ = params::LoadParameters("paper");
  std::vector<std::string> log_;
  std::vector<cue_command_t> commands_;
  PlannerNode node_{lcm_, params_, {}, [this](const std::string& line) { log_.push_back(line); }};
};

TEST_F(PlannerNodeTest, AnswersLikePlanShotCalledDirectly) {
  ASSERT_TRUE(lcm_.good());
  PublishTable({Ball(1, 0.6, 0.5), Ball(2, 2.0, 1.0)});
  shot_request_t q = Request(42, 1, 1.8, 0.9);
  q.final_speed = 0.2;
  q.side_spin = 5.0;
  const cue_command_t c = AskOk(q);
  EXPECT_EQ(c.request_id, 42);
  EXPECT_EQ(c.ball_id, 1);
  EXPECT_EQ(c.utime, q.utime);
  EXPECT_TRUE(c.reason.empty());

  planner::ShotRequest direct;
  direct.from = {0.6, 0.5};
  direct.to = {1.8, 0.9};
  direct.final_speed = 0.2;
  direct.side_spin = 5.0;
  const planner::ShotPlan plan = planner::PlanShot(direct, params_);
  ASSERT_EQ(plan.status, planner::PlanStatus::kOk) << plan.reason;
  // The same request, so the same numbers to the bit: the planner depends on nothing else.
  EXPECT_EQ(c.v0[0], plan.v0.x());
  EXPECT_EQ(c.v0[1], plan.v0.y());
  for (int i = 0; i < 3; ++i) EXPECT_EQ(c.w0[i], plan.w0[i]);
  EXPECT_EQ(c.cue_speed, plan.stroke.speed);
  EXPECT_EQ(c.heading, plan.stroke.heading);
  EXPECT_EQ(c.tip_side, plan.stroke.tip_side);
  EXPECT_EQ(c.tip_height, plan.stroke.tip_height);
  EXPECT_EQ(c.elevation, plan.stroke.elevation);
  EXPECT_EQ(c.iterations, plan.iterations);
  EXPECT_EQ(c.refined_miss_m, plan.refined_miss_m);
  EXPECT_EQ(c.closed_form_miss_m, plan.closed_form_miss_m);
  EXPECT_GT(c.cue_speed, 0.0);

  EXPECT_EQ(c.start[0], 0.6);
  EXPECT_EQ(c.start[1], 0.5);
  ASSERT_GE(c.num_path_points, 2);
  ASSERT_EQ(c.path.size(), static_cast<size_t>(c.num_path_points));
  EXPECT_NEAR(c.path.front()[0], 0.6, 1e-12);
  EXPECT_NEAR(c.path.front()[1], 0.5, 1e-12);
  EXPECT_NEAR(c.path.back()[0], c.predicted_final[0], 1e-12);
  EXPECT_NEAR(c.path.back()[1], c.predicted_final[1], 1e-12);
  EXPECT_LT(std::hypot(c.predicted_final[0] - 1.8, c.predicted_final[1] - 0.9), 1e-3);
  EXPECT_EQ(LogLinesContaining("request 42 (ball 1): ok"), 1);
}

TEST_F(PlannerNodeTest, MapsEverySpinChoiceToThePlannersRequest) {
  PublishTable({Ball(3, 0.4, 0.4)});
  const std::pair<int8_t, std::optional<planner::SpinStyle>> spins[] = {
      {shot_request_t::SPIN_NATURAL, planner::SpinStyle::kNatural},
      {shot_request_t::SPIN_STUN, planner::SpinStyle::kStun},
      {shot_request_t::SPIN_FOLLOW, planner::SpinStyle::kFollow},
      {shot_request_t::SPIN_DRAW, planner::SpinStyle::kDraw},
      {shot_request_t::SPIN_SLIDE, std::nullopt}};
  int64_t id = 100;
  for (const auto& [spin, style] : spins) {
    shot_request_t q = Request(++id, 3, 1.4, 0.7, spin);
    q.final_speed = 0.5;
    q.slide_length = 0.3;
    const auto answer = Ask(q);
    ASSERT_TRUE(answer) << int{spin};
    planner::ShotRequest direct;
    direct.from = {0.4, 0.4};
    direct.to = {1.4, 0.7};
    direct.final_speed = 0.5;
    if (style) {
      direct.style = *style;
    } else {
      direct.slide_length = 0.3;
    }
    const planner::ShotPlan plan = planner::PlanShot(direct, params_);
    EXPECT_EQ(answer->reason, plan.reason) << int{spin};
    EXPECT_EQ(answer->v0[0], plan.v0.x()) << int{spin};
    EXPECT_EQ(answer->w0[0], plan.w0.x()) << int{spin};
    EXPECT_EQ(answer->w0[1], plan.w0.y()) << int{spin};
    std::fprintf(stderr, "spin %d: %s, %d iterations, miss %.2e m (closed form %.2e m), %.0f us\n",
                 int{spin}, messages::CueCommandStatusName(answer->status).c_str(),
                 answer->iterations, answer->refined_miss_m, answer->closed_form_miss_m,
                 answer->solve_us);
  }
}

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

TEST_F(PlannerNodeTest, RefusesToPlanForAMovingBall) {
  PublishTable({Ball(1, 0.6, 0.5, 0.3, 0.1), Ball(2, 1.6, 0.5, 0.01, -0.02)});
  const auto moving = Ask(Request(1, 1, 1.0, 0.5));
  ASSERT_TRUE(moving);
  EXPECT_EQ(Status(*moving), kInvalid);
  EXPECT_NE(moving->reason.find("moving"), std::string::npos) << moving->reason;
  AskOk(Request(2, 2, 1.0, 0.5));  // below the 0.05 m/s default

  // A state with a NaN is dropped on arrival: there is no state of that ball to plan from.
  PublishTable({Ball(4, kNaN, 0.5)});
  const auto nan_state = Ask(Request(3, 4, 1.0, 0.5));
  ASSERT_TRUE(nan_state);
  EXPECT_EQ(Status(*nan_state), kNoBallState);
  EXPECT_EQ(LogLinesContaining("ball 4 has a non-finite position"), 1);
}

// A ball of a class, as the estimator would publish it.
ball_state_t Classed(int32_t id, double x, double y, int8_t ball_class, float confidence) {
  ball_state_t b = Ball(id, x, y);
  b.ball_class = ball_class;
  b.class_confidence = confidence;
  return b;
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

// A pot on the node's default table (pool-9ft) as the estimator names the balls: the cue ball
// is track 3 (by class), ball 5 a cut into the lower-left pocket, and a track 0 that is not the
// cue ball, out of the way.
class PlannerNodePotTest : public PlannerNodeTest {
 protected:
  static constexpr int32_t kCueTrack = 3, kObject = 5, kOther = 0;

  void PublishPotTable() {
    PublishTable({Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f),
                  Classed(kObject, 0.5, 0.3, 5, 0.9f), Classed(kOther, 2.0, 1.0, 9, 0.9f)});
  }

  static shot_request_t Pot(int64_t id, int32_t object, const std::string& pocket) {
    shot_request_t q = Request(id, shot_request_t::BALL_BY_CLASS, 0.0, 0.0);
    q.ball_class = ball_state_t::CLASS_CUE;
    q.mode = shot_request_t::MODE_POT;
    q.object_ball_id = object;
    q.pocket = pocket;
    return q;
  }

  // Ball `id`'s predicted path in the command, or nullptr.
  static const ball_path_t* PathOf(const cue_command_t& c, int32_t id) {
    for (const ball_path_t& p : c.ball_paths) {
      if (p.ball_id == id) return &p;
    }
    return nullptr;
  }

  const table::TableGeometry table_ = table::BuildTable(params::LoadTableSpec("pool-9ft"));
};

TEST_F(PlannerNodePotTest, APotPlannedFromTheTableStatePotsTheBallWhenSimulated) {
  PublishPotTable();
  const cue_command_t c = AskOk(Pot(1, kObject, "lower_left"));
  EXPECT_EQ(c.mode, shot_request_t::MODE_POT);
  EXPECT_EQ(c.ball_id, kCueTrack);
  EXPECT_EQ(c.object_ball_id, kObject);
  EXPECT_EQ(c.pocket, "lower_left");
  EXPECT_NE(c.kind, shot_request_t::KIND_ANY);
  EXPECT_GT(c.margin_deg[0], 0.0);
  EXPECT_GT(c.margin_deg[1], 0.0);
  EXPECT_LE(c.speed_window[0], c.cue_speed);
  EXPECT_GE(c.speed_window[1], c.cue_speed);
  EXPECT_EQ(c.start[0], 1.0);
  EXPECT_EQ(c.start[1], 0.45);
  // The paths by the table state's ids: the cue ball's (also in path) and ball 5's, which ends
  // in the pocket's corner; the ball out of the way does not move.
  const ball_path_t* cue_path = PathOf(c, kCueTrack);
  const ball_path_t* object_path = PathOf(c, kObject);
  ASSERT_TRUE(cue_path && object_path);
  EXPECT_EQ(PathOf(c, kOther), nullptr);
  EXPECT_EQ(cue_path->points, c.path);
  EXPECT_NEAR(cue_path->points.front()[0], 1.0, 1e-12);
  EXPECT_NEAR(object_path->points.back()[0] + object_path->points.back()[1], 0.0, 0.15);
  EXPECT_EQ(c.cue_rest[0], c.predicted_final[0]);
  EXPECT_EQ(LogLinesContaining("request 1 (ball 3, pot ball 5 in lower_left): ok"), 1);

  // The launch simulated by the table alone, with `simulate --scene`'s default motion: ball 5
  // drops in the lower-left pocket, the cue ball touches it first, stays on the table and rests
  // where the plan said.
  std::vector<table::SceneBall> scene = {
      {0, physics::MakeBallState(1.0, 0.45, c.v0[0], c.v0[1], c.w0[0], c.w0[1], c.w0[2])},
      {kObject, physics::MakeBallState(0.5, 0.3, 0, 0, 0, 0, 0)},
      {9, physics::MakeBallState(2.0, 1.0, 0, 0, 0, 0, 0)}};
  table::TableSimulationOptions motion;
  motion.five_dof = model_choice::TableMotion(params_);
  table::TableSimulation sim(table_, params_, scene, motion);
  sim.Run();
  EXPECT_EQ(sim.pocket(1).value_or("none"), "lower_left");
  EXPECT_FALSE(sim.pocket(0)) << "a scratch in " << *sim.pocket(0);
  EXPECT_FALSE(sim.pocket(2));
  for (const table::TableEvent& e : sim.events()) {
    if (e.type != table::EventType::kBallBall) continue;
    EXPECT_EQ(e.ball + e.other, kObject) << "the cue ball's first contact is ball 5";
    break;
  }
  EXPECT_NEAR(sim.State(0)[physics::kX], c.cue_rest[0], 1e-6);
  EXPECT_NEAR(sim.State(0)[physics::kY], c.cue_rest[1], 1e-6);
}

TEST_F(PlannerNodePotTest, APotWithACueBallTargetLeavesTheCueBallThere) {
  PublishPotTable();
  shot_request_t q = Pot(1, kObject, "lower_left");
  q.has_cue_target = 1;
  q.cue_target[0] = 0.9;
  q.cue_target[1] = 0.5;
  q.cue_radius = 0.05;
  const auto answer = Ask(q);
  ASSERT_TRUE(answer);
  ASSERT_EQ(Status(*answer), kOk) << answer->reason;
  EXPECT_LE(std::hypot(answer->cue_rest[0] - 0.9, answer->cue_rest[1] - 0.5), 0.05 + 1e-9);

  // Just past ball 9 from where the cue ball comes off ball 5: no stroke stops it there.
  q.request_id = 2;
  q.cue_target[0] = 2.0 + 0.06;
  q.cue_target[1] = 1.0;
  q.cue_radius = 0.0;
  const auto unreachable = Ask(q);
  ASSERT_TRUE(unreachable);
  EXPECT_EQ(Status(*unreachable), cue_command_t::STATUS_TARGET_UNREACHABLE) << unreachable->reason;
  EXPECT_EQ(unreachable->cue_speed, 0.0);
}

TEST_F(PlannerNodePotTest, BadPotRequestsAreRefusedWithAReasonAndTheNodeKeepsAnswering) {
  PublishPotTable();
  struct Case {
    shot_request_t request;
    int status;
    std::string says;
  };
  std::vector<Case> cases = {
      {Pot(1, 42, "lower_left"), cue_command_t::STATUS_NO_SUCH_BALL, "no ball 42"},
      {Pot(2, kCueTrack, "lower_left"), cue_command_t::STATUS_NO_SUCH_BALL, "struck"},
      {Pot(3, kObject, "nowhere"), cue_command_t::STATUS_NO_SUCH_POCKET, "nowhere"},
      {Pot(4, kObject, "lower_left"), kInvalid, "non-finite"},
      {Pot(5, kObject, "lower_left"), kOffTable, "off the pool-9ft"},
      {Pot(6, kObject, "lower_left"), kInvalid, "kind"},
      {Pot(7, shot_request_t::BALL_BY_CLASS, "lower_left"), cue_command_t::STATUS_NO_SUCH_BALL,
       "class 12"},
      {Pot(8, kObject, ""), kInvalid, "pocket"},
      {Pot(9, kObject, "lower_left"), kInvalid, "non-finite"},
  };
  cases[3].request.has_cue_target = 1;
  cases[3].request.cue_target[0] = kNaN;
  cases[4].request.has_cue_target = 1;
  cases[4].request.cue_target[0] = 5.0;
  cases[4].request.cue_target[1] = 0.5;
  cases[5].request.kind = 9;
  cases[6].request.object_ball_class = 12;
  cases[8].request.side_spin = kNaN;
  for (const Case& k : cases) {
    const auto answer = Ask(k.request);
    ASSERT_TRUE(answer) << "request " << k.request.request_id;
    EXPECT_EQ(Status(*answer), k.status)
        << "request " << k.request.request_id << ": " << answer->reason;
    EXPECT_NE(answer->reason.find(k.says), std::string::npos)
        << "request " << k.request.request_id << ": " << answer->reason;
    EXPECT_EQ(std::count(answer->reason.begin(), answer->reason.end(), '\n'), 0);
    EXPECT_EQ(answer->cue_speed, 0.0) << "request " << k.request.request_id;
    EXPECT_EQ(answer->num_ball_paths, 0) << "request " << k.request.request_id;
  }
  // A ball the latest table state does not name is gone (pocketed, or lost by the estimator),
  // though a point request could still strike it from where it was last seen.
  PublishTable({Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f)}, 1'100'000);
  shot_request_t later = Pot(10, kObject, "lower_left");
  later.utime = 1'100'000;
  const auto gone = Ask(later);
  ASSERT_TRUE(gone);
  EXPECT_EQ(Status(*gone), cue_command_t::STATUS_NO_SUCH_BALL) << gone->reason;
  EXPECT_NE(gone->reason.find("latest table state"), std::string::npos) << gone->reason;

  // Still answering: the same pot, planned, once the ball is seen again; and a point request.
  PublishTable({Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f),
                Classed(kObject, 0.5, 0.3, 5, 0.9f)},
               1'100'010);
  later.request_id = 11;
  later.utime = 1'100'010;
  AskOk(later);
  shot_request_t point = Request(12, kCueTrack, 1.5, 0.6);
  point.utime = 1'100'010;
  AskOk(point);
}

// The pot planner's own refusals go out with their status: a ball in the direct line, and a cut
// of 90 degrees.
TEST_F(PlannerNodePotTest, ThePotPlannersRefusalsGoOutWithTheirStatus) {
  // The cue ball square to the line from ball 5 to the pocket.
  PublishTable(
      {Classed(kCueTrack, 0.5 - 0.3 * 0.514, 0.3 + 0.3 * 0.857, ball_state_t::CLASS_CUE, 0.9f),
       Classed(kObject, 0.5, 0.3, 5, 0.9f)});
  shot_request_t thin = Pot(1, kObject, "lower_left");
  thin.kind = shot_request_t::KIND_DIRECT;
  const auto too_thin = Ask(thin);
  ASSERT_TRUE(too_thin);
  EXPECT_EQ(Status(*too_thin), cue_command_t::STATUS_TOO_THIN) << too_thin->reason;

  // Ball 7 in the line from ball 5 to the pocket.
  PublishTable({Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f),
                Classed(kObject, 0.5, 0.3, 5, 0.9f), Ball(7, 0.25, 0.15)},
               1'000'010);
  shot_request_t blocked = Pot(2, kObject, "lower_left");
  blocked.utime = 1'000'010;
  blocked.kind = shot_request_t::KIND_DIRECT;
  const auto in_the_way = Ask(blocked);
  ASSERT_TRUE(in_the_way);
  EXPECT_EQ(Status(*in_the_way), cue_command_t::STATUS_BLOCKED) << in_the_way->reason;
  EXPECT_NE(in_the_way->reason.find("ball 7"), std::string::npos) << in_the_way->reason;
}

// The estimator's touching balls: ball 9, beside the object ball's line to the pocket, measured
// 0.5 mm into it. Settled apart, the pot is planned; a ball 5 mm into another is an impossible
// scene and refused.
TEST_F(PlannerNodePotTest, TouchingBallsSeenOverlappingAreSettledApart) {
  const double r = params_.ball.radius;
  const Eigen::Vector2d k(0.6, 0.3);
  const Eigen::Vector2d mouth = table_.PocketNamed("lower_left")->centre;
  const Eigen::Vector2d along = (mouth - k).normalized();
  const Eigen::Vector2d beside = k + (2 * r - 5e-4) * Eigen::Vector2d(-along.y(), along.x());
  PublishTable({Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f),
                Classed(kObject, k.x(), k.y(), 5, 0.9f), Classed(kOther, beside.x(), beside.y(), 9, 0.9f)});
  const cue_command_t c = AskOk(Pot(1, kObject, "lower_left"));
  EXPECT_EQ(c.object_ball_id, kObject);
  PublishTable({Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f),
                Classed(kObject, 0.6, 0.3, 5, 0.9f), Classed(kOther, 0.6, 0.3 + 2 * r - 5e-3, 9, 0.9f)},
               1'000'020);  // a later state: the node keeps the latest
  const auto answer = Ask(Pot(2, kObject, "lower_left"));
  ASSERT_TRUE(answer);
  EXPECT_EQ(Status(*answer), kInvalid);
  EXPECT_NE(answer->reason.find("overlap"), std::string::npos) << answer->reason;
}

TEST_F(PlannerNodePotTest, APotAmongMovingBallsIsRefused) {
  PublishTable({Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f),
                Classed(kObject, 0.5, 0.3, 5, 0.9f), Ball(7, 2.0, 1.0, 0.4, 0.0)});
  const auto answer = Ask(Pot(1, kObject, "lower_left"));
  ASSERT_TRUE(answer);
  EXPECT_EQ(Status(*answer), kInvalid);
  EXPECT_NE(answer->reason.find("ball 7 is moving"), std::string::npos) << answer->reason;
}

// "Choose and play" on the pot table: the cue ball by class, under nine-ball rules.
shot_request_t Choose(int64_t id, bool ball_in_hand,
                      int8_t rules = shot_request_t::RULES_NINE_BALL) {
  shot_request_t q = Request(id, shot_request_t::BALL_BY_CLASS, 0.0, 0.0);
  q.ball_class = ball_state_t::CLASS_CUE;
  q.mode = shot_request_t::MODE_CHOOSE;
  q.rules = rules;
  q.ball_in_hand = ball_in_hand ? 1 : 0;
  return q;
}

// The chosen stroke played from `cue` by the table alone, without noise, with `simulate
// --scene`'s motion: the pocket ball 5 (scene id kObject) drops in, "" if none, and whether the
// cue ball's first contact is ball 5 and it stays on the table.
struct Played {
  std::string pocket;
  bool first_contact_5 = false;
  bool scratch = true;
};
Played PlayChosen(const table::TableGeometry& table, const physics::ModelParameters& params,
                  const cue_command_t& c, const Eigen::Vector2d& cue) {
  std::vector<table::SceneBall> scene = {
      {0, physics::MakeBallState(cue.x(), cue.y(), c.v0[0], c.v0[1], c.w0[0], c.w0[1], c.w0[2])},
      {5, physics::MakeBallState(0.5, 0.3, 0, 0, 0, 0, 0)},
      {9, physics::MakeBallState(2.0, 1.0, 0, 0, 0, 0, 0)}};
  table::TableSimulationOptions motion;
  motion.five_dof = model_choice::TableMotion(params);
  table::TableSimulation sim(table, params, scene, motion);
  sim.Run();
  Played played;
  played.pocket = sim.pocket(1).value_or("");
  played.scratch = sim.pocket(0).has_value();
  for (const table::TableEvent& e : sim.events()) {
    if (e.type != table::EventType::kBallBall) continue;
    played.first_contact_5 = e.ball + e.other == 5;
    break;
  }
  return played;
}

TEST_F(PlannerNodePotTest, AChoiceUnderNineBallRulesPlaysTheLowestBallAndPotsItWhenSimulated) {
  PublishPotTable();
  const cue_command_t c = AskOk(Choose(1, false));
  EXPECT_EQ(c.mode, shot_request_t::MODE_CHOOSE);
  EXPECT_EQ(c.ball_id, kCueTrack);
  EXPECT_EQ(c.object_ball_id, kObject) << "the 5 is the lowest: the 9 may not be hit first";
  EXPECT_FALSE(c.pocket.empty());
  EXPECT_EQ(c.has_cue_placement, 0);
  EXPECT_GT(c.success_probability, 0.5);
  EXPECT_GT(c.probability_stderr, 0.0);
  EXPECT_EQ(c.start[0], 1.0);
  const Played played = PlayChosen(table_, params_, c, {1.0, 0.45});
  EXPECT_EQ(played.pocket, c.pocket);
  EXPECT_TRUE(played.first_contact_5);
  EXPECT_FALSE(played.scratch);

  // Ball in hand: the cue ball placed clear of the others, the stroke planned from there.
  const cue_command_t h = AskOk(Choose(2, true));
  ASSERT_EQ(h.has_cue_placement, 1);
  EXPECT_EQ(h.start[0], h.cue_placement[0]);
  EXPECT_EQ(h.start[1], h.cue_placement[1]);
  const Eigen::Vector2d placed(h.cue_placement[0], h.cue_placement[1]);
  EXPECT_TRUE(table_.OnSurface(placed, params_.ball.radius));
  for (const Eigen::Vector2d& other : {Eigen::Vector2d(0.5, 0.3), Eigen::Vector2d(2.0, 1.0)}) {
    EXPECT_GE((placed - other).norm(), 2 * params_.ball.radius);
  }
  EXPECT_EQ(h.object_ball_id, kObject);
  EXPECT_GE(h.success_probability, c.success_probability - 2 * c.probability_stderr)
      << "the cue ball anywhere is no worse than where it was";
  const Played from_hand = PlayChosen(table_, params_, h, placed);
  EXPECT_EQ(from_hand.pocket, h.pocket);
  EXPECT_FALSE(from_hand.scratch);
  // The same request again, on the same table: the same answer, for a log to replay.
  EXPECT_EQ(node_.Answer(Choose(2, true)).heading, h.heading);
}

TEST_F(PlannerNodePotTest, BadChoiceRequestsAreRefusedWithAReasonAndTheNodeKeepsAnswering) {
  PublishPotTable();
  shot_request_t rules = Choose(1, false, 7);
  shot_request_t in_hand = Choose(2, false);
  in_hand.ball_in_hand = 2;
  for (const auto& [request, says] : {std::pair{rules, "rules"}, {in_hand, "ball_in_hand"}}) {
    const auto answer = Ask(request);
    ASSERT_TRUE(answer);
    EXPECT_EQ(Status(*answer), kInvalid);
    EXPECT_NE(answer->reason.find(says), std::string::npos) << answer->reason;
    EXPECT_EQ(answer->cue_speed, 0.0);
  }
  // A table of the cue ball alone has nothing to play; one with a ball moving is no table yet.
  PublishTable({Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f)}, 1'000'100);
  const auto empty = Ask(Choose(3, false));
  ASSERT_TRUE(empty);
  EXPECT_EQ(Status(*empty), cue_command_t::STATUS_NO_SUCH_BALL) << empty->reason;
  PublishTable(
      {Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f), Ball(7, 2.0, 1.0, 0.4, 0.0)},
      1'000'200);
  const auto moving = Ask(Choose(4, false));
  ASSERT_TRUE(moving);
  EXPECT_EQ(Status(*moving), kInvalid);
  EXPECT_NE(moving->reason.find("ball 7 is moving"), std::string::npos) << moving->reason;
  PublishTable({Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f),
                Classed(kObject, 0.5, 0.3, 5, 0.9f), Classed(kOther, 2.0, 1.0, 9, 0.9f)},
               1'000'300);
  EXPECT_EQ(AskOk(Choose(5, false)).object_ball_id, kObject);
}

// The numbers a choice knows the balls by, from the estimator's classes and the rack's one of
// each: the surer of two yellows is the 1, a faint 9 is still the 9, the other yellow takes the
// lowest number nobody claims, an unknown ball the next.
TEST(BallNumbers, AreTheClassesWithOneOfEachNumber) {
  table_state_t t{};
  t.balls = {Classed(10, 0.5, 0.5, ball_state_t::CLASS_CUE, 0.9f),
             Classed(11, 1.0, 0.5, 1, 0.6f),
             Classed(12, 1.5, 0.5, 1, 0.9f),
             Classed(13, 2.0, 0.5, 9, 0.2f),
             Classed(14, 2.0, 1.0, ball_state_t::CLASS_UNKNOWN, 0.0f),
             Classed(15, 0.5, 1.0, 2, 0.8f)};
  t.num_balls = static_cast<int32_t>(t.balls.size());
  const auto n = BallNumbers(t, 10);
  EXPECT_EQ(n.at(10), 0);
  EXPECT_EQ(n.at(12), 1);
  EXPECT_EQ(n.at(13), 9);
  EXPECT_EQ(n.at(15), 2);
  EXPECT_EQ(n.at(11), 3);
  EXPECT_EQ(n.at(14), 4);
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
                           " --table no-such-table", " --table snooker-12ft"}) {
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
}  // namespace billiard::planner_node
