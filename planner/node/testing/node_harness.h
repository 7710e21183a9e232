// The planner node driven over LCM in-process, for its tests: one memq:// LCM shared by the node
// and the test, the messages as an estimator and a robot would send them, and the node's answers
// and log lines collected. PlannerNodePotTest sets a pot table up as the estimator names its
// balls. Header-only, for the tests of planner/node/ alone.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "lcmtypes/billiard/ball_path_t.hpp"
#include "lcmtypes/billiard/ball_state_t.hpp"
#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/shot_request_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "lcmtypes/names.h"
#include "lcmtypes/node/node_loop.h"
#include "planner/node/planner_node.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/table/table_geometry.h"

namespace billiard::planner_node::testing {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The message constants are declared without a definition (lcm-gen's C++98 output), so a test
// must not bind them to a reference: compare them as ints.
inline int Status(const cue_command_t& c) { return c.status; }
constexpr int kOk = cue_command_t::STATUS_OK;
constexpr int kInvalid = cue_command_t::STATUS_INVALID;
constexpr int kOffTable = cue_command_t::STATUS_OFF_TABLE;
constexpr int kNoBallState = cue_command_t::STATUS_NO_BALL_STATE;

inline ball_state_t Ball(int32_t id, double x, double y, double vx = 0.0, double vy = 0.0) {
  ball_state_t b{};
  b.ball_id = id;
  b.position[0] = x;
  b.position[1] = y;
  b.velocity[0] = vx;
  b.velocity[1] = vy;
  return b;
}

inline shot_request_t Request(int64_t id, int32_t ball, double x, double y,
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

// A ball of a class, as the estimator would publish it.
inline ball_state_t Classed(int32_t id, double x, double y, int8_t ball_class, float confidence) {
  ball_state_t b = Ball(id, x, y);
  b.ball_class = ball_class;
  b.class_confidence = confidence;
  return b;
}

class PlannerNodeTest : public ::testing::Test {
 protected:
  explicit PlannerNodeTest(PlannerNodeOptions options = {})
      : node_{lcm_, params_, std::move(options),
              [this](const std::string& line) { log_.push_back(line); }} {
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
    return AnswerTo(request.request_id);
  }

  // The latest answer published to request `id`, nullopt if there is none (yet).
  std::optional<cue_command_t> AnswerTo(int64_t id) const {
    for (auto c = commands_.rbegin(); c != commands_.rend(); ++c) {
      if (c->request_id == id) return *c;
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
  PlannerNode node_;
};

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

  const table::TableGeometry table_ =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
};

}  // namespace billiard::planner_node::testing
