// The three nodes in one process over memq://, as `billiard loop` runs them: sessions one after
// another against the same estimator and planner, each table simulator starting its clock at 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <lcm/lcm-cpp.hpp>
#include <string>
#include <vector>

#include "estimator/node/estimator_node.h"
#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/shot_request_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "lcmtypes/names.h"
#include "lcmtypes/node/node_health.h"
#include "lcmtypes/version.h"
#include "planner/node/command_writing.h"
#include "planner/node/planner_node.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/robots.h"
#include "sim/table_sim_node/session.h"
#include "sim/table_sim_node/table_sim_node.h"
#include "tests/support/quoted_figures.h"

namespace billiard {
namespace {

void Quiet(const std::string&) {}

// The nodes on memq:// with the pool set: the simulator's camera, the estimator, the planner.
struct Nodes {
  lcm::LCM lcm{"memq://"};
  physics::ModelParameters params = params::LoadParameters("pool");
  camera::CameraModel camera = table_sim_node::SessionCamera(params.table);
  estimator_node::EstimatorNode estimator{lcm, camera, params, {}, {}, Quiet};
  planner_node::PlannerNode planner{lcm, params, {}, Quiet};
};

// The estimator and the planner run inside the simulator's waits, as `billiard loop` runs them.
void WithTheNodes(table_sim_node::TableSimNode& node, estimator_node::EstimatorNode& estimator,
                  planner_node::PlannerNode& planner) {
  node.RunAlongside([&] {
    estimator.Work();
    return planner.Work();
  });
}

struct LatestTruth {
  std::int64_t utime = -1;
  void On(const lcm::ReceiveBuffer*, const std::string&, const table_state_t* m) {
    utime = m->utime;
  }
};

// A lockstep simulator restarted within the nodes' 5 s of clock memory sends its first frame
// again and again until the estimator answers: the estimator must see a new clock in that.
TEST(InProcessLoop, ASessionRestartingTheClockSoonAfterTheLastIsServed) {
  lcm::LCM lcm("memq://");
  const physics::ModelParameters params = params::LoadParameters("pool");
  const camera::CameraModel camera = table_sim_node::SessionCamera(params.table);
  estimator_node::EstimatorNode estimator(lcm, camera, params, {}, {}, Quiet);
  planner_node::PlannerNode planner(lcm, params, {}, Quiet);
  LatestTruth truth;
  lcm.subscribe(messages::kTableTruthChannel, &LatestTruth::On, &truth);

  table_sim_node::TableSimOptions options;
  options.shots = 1;
  options.reply_timeout = 3.0;
  // A short shot from the middle of the table: the session ends 3.2 s into its clock.
  options.start = {0.5 * params.table.length, 0.5 * params.table.width};
  options.target_margin = 0.5;
  options.min_distance = 0.15;
  for (int session = 0; session < 2; ++session) {
    table_sim_node::TableSimNode node(lcm, params, camera, options, Quiet);
    WithTheNodes(node, estimator, planner);
    const std::vector<table_sim_node::ShotResult> shots = node.Run();
    ASSERT_EQ(shots.size(), 1u);
    EXPECT_EQ(shots[0].status, "ok") << shots[0].reason;
    EXPECT_LT(shots[0].miss_m, 2e-3);
    if (session == 0) {
      ASSERT_LT(truth.utime, 5'000'000) << "the second session must start within 5 s of the "
                                           "first one's clock for this test to mean anything";
    }
  }
  EXPECT_EQ(estimator.health().counter("clock_reset"), 1);
}

// The table simulator's robot checks every stroke and says so in NODE_STATUS: the ball a
// millimetre off the lower rail, every target up the table, the point planner's stroke level,
// and a robot that cannot raise its cue: the cue lies across the rail. The shots session's point
// planner cannot raise its cue yet, so the stroke is counted cue_blocked_played and played
// (a pot or a game's stroke would be refused, cue_blocked).
TEST(InProcessLoop, TheSimulatorsRobotSaysWhichStrokeItsCueCannotMakeAndCountsIt) {
  Nodes n;
  table_sim_node::TableSimOptions options;
  options.robot = params::LoadRobot("gantry");
  options.robot->elevation.max = 0.0;
  options.start = {0.5 * n.params.table.length, n.params.ball.radius + 1e-3};
  options.shots = 1;
  options.target_margin = 0.4;
  options.reply_timeout = 3.0;
  table_sim_node::TableSimNode node(n.lcm, n.params, n.camera, options, Quiet);
  WithTheNodes(node, n.estimator, n.planner);
  const std::vector<table_sim_node::ShotResult> shots = node.Run();
  ASSERT_EQ(shots.size(), 1u);
  EXPECT_EQ(shots[0].status, "ok") << shots[0].reason;
  EXPECT_EQ(node.health().counter("cue_blocked_played"), 1);
  EXPECT_NE(node.health().last_error().find("lower rail"), std::string::npos) << node.health().last_error();
}

// A planner that never sees the table at rest (its answer to every request after its wait),
// announcing itself as the planner node does: the game asks again, and a shot still refused is
// played by nobody, so it is neither a shot nor a visit.
struct NeverAtRestPlanner {
  NeverAtRestPlanner(lcm::LCM& l, const physics::ModelParameters& params) : lcm(&l) {
    health.SetParameters(params::ParameterSetLabel(params), params::ParameterHash(params));
    lcm->subscribe(messages::kShotRequestChannel, &NeverAtRestPlanner::On, this);
  }
  lcm::LCM* lcm;
  nodes::NodeHealth health{"planner_node", Quiet};
  int answered = 0;
  void On(const lcm::ReceiveBuffer*, const std::string&, const shot_request_t* q) {
    cue_command_t c = planner_node::ReplyTo(*q);
    c.status = cue_command_t::STATUS_NOT_AT_REST;
    c.reason = "the table did not come to rest within 2 s: ball 3 is moving (4.0341 m/s)";
    lcm->publish(messages::kCueCommandChannel, &c);
    ++answered;
  }
};

TEST(InProcessLoop, AShotTheTableNeverRestedForIsNeitherAShotNorAVisit) {
  lcm::LCM lcm("memq://");
  const physics::ModelParameters params = params::LoadParameters("pool");
  const camera::CameraModel camera = table_sim_node::SessionCamera(params.table);
  estimator_node::EstimatorNode estimator(lcm, camera, params, {}, {}, Quiet);
  NeverAtRestPlanner planner(lcm, params);
  table_sim_node::TableSimOptions options;
  options.game = "drill";
  options.shot_limit = 2;
  options.max_retries = 1;
  options.reply_timeout = 3.0;
  table_sim_node::TableSimNode node(lcm, params, camera, options, Quiet);
  node.RunAlongside([&] {
    planner.health.PublishIfDue(lcm);
    return estimator.Work();
  });
  const std::vector<table_sim_node::GameResult> racks = node.RunGame();
  ASSERT_EQ(racks.size(), 1u);
  EXPECT_TRUE(racks[0].shots.empty());
  EXPECT_EQ(racks[0].visits, 0);
  EXPECT_FALSE(racks[0].cleared);
  // Each of the two attempts asked, refused, asked again once, refused again.
  EXPECT_EQ(planner.answered, 4);
  EXPECT_EQ(node.health().counter("shot_retried"), 2);
  EXPECT_EQ(node.health().counter("shot_not_at_rest"), 2);
}

// Started by hand with different sets, the nodes would plan and track one ball while the
// simulator moves another: the session is refused before the first shot, naming who differs.
// Shots to random targets from the table's middle, targets 0.5 m inside the cushions.
table_sim_node::TableSimOptions ShotsFromTheMiddle(const physics::ModelParameters& params,
                                                   int shots) {
  table_sim_node::TableSimOptions options;
  options.shots = shots;
  options.reply_timeout = 3.0;
  options.start = {0.5 * params.table.length, 0.5 * params.table.width};
  options.target_margin = 0.5;
  options.min_distance = 0.15;
  return options;
}

// The targets and the noise come from streams of their own: the robot's noise moves where the
// ball ends, never where it is sent.
TEST(InProcessLoop, NoiseLeavesTheTargetsAsTheyWere) {
  lcm::LCM lcm("memq://");
  const physics::ModelParameters params = params::LoadParameters("pool");
  const camera::CameraModel camera = table_sim_node::SessionCamera(params.table);
  estimator_node::EstimatorNode estimator(lcm, camera, params, {}, {}, Quiet);
  planner_node::PlannerNode planner(lcm, params, {}, Quiet);
  std::vector<std::vector<table_sim_node::ShotResult>> runs;
  for (const bool noise : {false, true}) {
    table_sim_node::TableSimOptions options = ShotsFromTheMiddle(params, 2);
    options.seed = 5;
    if (noise) options.noise = table_sim_node::RobotExecutionNoise();
    table_sim_node::TableSimNode node(lcm, params, camera, options, Quiet);
    WithTheNodes(node, estimator, planner);
    runs.push_back(node.Run());
    ASSERT_EQ(runs.back().size(), 2u);
  }
  for (std::size_t shot = 0; shot < 2; ++shot) {
    EXPECT_EQ(runs[0][shot].target, runs[1][shot].target) << "shot " << shot;
  }
  // The noise did something: the first shot, from the same place to the same target, ends
  // elsewhere.
  EXPECT_GT((runs[0][0].final_point - runs[1][0].final_point).norm(), 1e-5);
}

struct Commands {
  std::vector<cue_command_t> sent;
  void On(const lcm::ReceiveBuffer*, const std::string&, const cue_command_t* m) {
    sent.push_back(*m);
  }
};

// --spins natural,stun,follow,draw: the shots to random targets ask the spin styles in turn, and
// the planner strokes each at its own tip height (the rolling ball's 0.4 r above the centre, the
// stun's at it, the follow's between, the draw's below), each landing where it was sent. A name
// that is no style is the session's bad input.
TEST(InProcessLoop, TheShotsToTargetsTakeTheSpinStylesInTurn) {
  Nodes n;
  Commands commands;
  n.lcm.subscribe(messages::kCueCommandChannel, &Commands::On, &commands);
  table_sim_node::SessionCommandLine line;
  line.spins = "natural,stun,follow,draw";
  table_sim_node::TableSimOptions options = ShotsFromTheMiddle(n.params, 4);
  options.spins = table_sim_node::SessionOptions(line).spins;
  table_sim_node::TableSimNode node(n.lcm, n.params, n.camera, options, Quiet);
  WithTheNodes(node, n.estimator, n.planner);
  const std::vector<table_sim_node::ShotResult> shots = node.Run();
  ASSERT_EQ(shots.size(), 4u);
  for (const auto& shot : shots) {
    EXPECT_EQ(shot.status, "ok") << shot.reason;
    EXPECT_LT(shot.miss_m, 0.01) << shot.status;
  }
  while (n.lcm.handleTimeout(0) > 0) {
  }
  ASSERT_EQ(commands.sent.size(), 4u);
  const double r = n.params.ball.radius;
  EXPECT_NEAR(commands.sent[0].tip_height, 0.4 * r, 0.05 * r);
  EXPECT_NEAR(commands.sent[1].tip_height, 0.0, 0.05 * r);
  EXPECT_GT(commands.sent[2].tip_height, commands.sent[1].tip_height + 0.1 * r);
  EXPECT_LT(commands.sent[2].tip_height, commands.sent[0].tip_height - 0.1 * r);
  EXPECT_LT(commands.sent[3].tip_height, -0.2 * r);

  line.spins = "natural,twirl";
  EXPECT_THROW(table_sim_node::SessionOptions(line), std::invalid_argument);
}

// A table whose cloth slows a rolling ball four times less than the planner thinks (the plant's
// rolling resistance d a quarter of the set's) sends shots from the middle past the cushions the
// lone ball is simulated without: the ball drops. The session puts it back where it was struck
// from, counts it, and plays every shot; before, the planner refused every later shot
// (off_table) from where the ball fell.
TEST(InProcessLoop, ABallPocketedIsPutBackWhereItWasStruckFromAndTheSessionGoesOn) {
  Nodes n;
  const int kShots = 4;
  table_sim_node::TableSimOptions options = ShotsFromTheMiddle(n.params, kShots);
  options.plant = n.params;
  options.plant->contact.d *= 0.25;
  options.seed = 3;
  table_sim_node::TableSimNode node(n.lcm, n.params, n.camera, options, Quiet);
  WithTheNodes(node, n.estimator, n.planner);
  const std::vector<table_sim_node::ShotResult> shots = node.Run();
  ASSERT_EQ(shots.size(), static_cast<std::size_t>(kShots));
  int pocketed = 0;
  for (std::size_t k = 0; k < shots.size(); ++k) {
    const table_sim_node::ShotResult& shot = shots[k];
    const bool dropped = shot.status == table_sim_node::kPocketedStatus;
    ASSERT_TRUE(dropped || shot.status == "ok") << "shot " << k << ": " << shot.status << ", "
                                                << shot.reason;
    const physics::TableParameters& table = n.params.table;
    const bool on_rectangle = shot.final_point.x() > 0.0 && shot.final_point.x() < table.length &&
                              shot.final_point.y() > 0.0 && shot.final_point.y() < table.width;
    if (!on_rectangle) {
      EXPECT_TRUE(dropped) << "shot " << k << " ended off the table";
    }
    pocketed += dropped;
    if (k + 1 == shots.size()) continue;
    // The next shot starts where this one was struck from when it dropped, else where it rests.
    const Eigen::Vector2d next = dropped ? shot.from : shot.final_point;
    EXPECT_LT((shots[k + 1].from - next).norm(), 1e-12) << "shot " << k + 1;
  }
  EXPECT_GE(pocketed, 1) << "no ball dropped: the test means nothing";
  EXPECT_EQ(node.health().counter(table_sim_node::kPocketedStatus), pocketed);
}

TEST(InProcessLoop, ASessionIsRefusedWhileTheNodesRunOtherPhysics) {
  lcm::LCM lcm("memq://");
  const physics::ModelParameters pool = params::LoadParameters("pool");
  const physics::ModelParameters paper = params::LoadParameters("paper");
  const camera::CameraModel camera = table_sim_node::SessionCamera(pool.table);
  estimator_node::EstimatorNode estimator(lcm, camera, pool, {}, {}, Quiet);
  planner_node::PlannerNode planner(lcm, paper, {}, Quiet);
  table_sim_node::TableSimOptions options;
  options.shots = 1;
  table_sim_node::TableSimNode node(lcm, pool, camera, options, Quiet);
  WithTheNodes(node, estimator, planner);
  try {
    node.Run();
    FAIL() << "a session with a planner on the paper set ran";
  } catch (const table_sim_node::PeerMismatch& e) {
    const std::string why = e.what();
    EXPECT_NE(why.find("planner_node runs 'paper' (" + params::ParameterHash(paper) +
                       ") where the simulator runs 'pool' (" + params::ParameterHash(pool) + ")"),
              std::string::npos)
        << why;
    EXPECT_EQ(why.find("estimator_node"), std::string::npos) << why;
  }
}

// An estimator of another build (here a status as such a node sends it, announcing the same
// physics) may track otherwise: the session is refused before the first shot, naming it and
// both versions, while the planner of this build passes.
TEST(InProcessLoop, ASessionIsRefusedWhileANodeIsAnotherVersion) {
  lcm::LCM lcm("memq://");
  const physics::ModelParameters pool = params::LoadParameters("pool");
  const camera::CameraModel camera = table_sim_node::SessionCamera(pool.table);
  planner_node::PlannerNode planner(lcm, pool, {}, Quiet);
  nodes::NodeHealth other_build("estimator_node", Quiet);
  other_build.SetParameters(params::ParameterSetLabel(pool), params::ParameterHash(pool));
  node_status_t status = other_build.TakeStatus();
  status.version = "0.0.9";
  table_sim_node::TableSimOptions options;
  options.shots = 1;
  table_sim_node::TableSimNode node(lcm, pool, camera, options, Quiet);
  lcm.publish(messages::kNodeStatusChannel, &status);
  node.RunAlongside([&] { return planner.Work(); });
  try {
    node.Run();
    FAIL() << "a session with an estimator of version 0.0.9 ran";
  } catch (const table_sim_node::PeerMismatch& e) {
    const std::string why = e.what();
    EXPECT_NE(
        why.find(std::string("estimator_node is version 0.0.9 where the simulator is ") + kVersion),
        std::string::npos)
        << why;
    EXPECT_EQ(why.find("planner_node"), std::string::npos) << why;
    EXPECT_EQ(why.find(" runs '"), std::string::npos) << "the physics agrees: " << why;
  }
}

// A break through all three nodes: the planner sends the cue ball rolling into the rack's apex
// ball, the simulator plays every ball event by event, the estimator follows all sixteen.
table_sim_node::SceneResult Break(std::uint64_t seed) {
  lcm::LCM lcm("memq://");
  const physics::ModelParameters params = params::LoadParameters("pool");
  const camera::CameraModel camera = table_sim_node::SessionCamera(params.table);
  estimator_node::EstimatorNode estimator(lcm, camera, params, {}, {}, Quiet);
  planner_node::PlannerNode planner(lcm, params, {}, Quiet);
  table_sim_node::TableSimOptions options;
  options.scene = "break";
  options.seed = seed;
  table_sim_node::TableSimNode node(lcm, params, camera, options, Quiet);
  WithTheNodes(node, estimator, planner);
  return node.RunScene();
}

// Issue 27's acceptance: every ball tracked in every frame, the worst frame within 5 mm, no swaps,
// identities kept: every ball named right at the end, and misnamed in at most 1 % of its frames
// (a frame or two as two balls meet and share their identities; 2 to 9 % before the classes were
// read as soon as a track's was in doubt).
void ExpectEveryBallTrackedInEveryFrame(const table_sim_node::TrackingReport& tracking) {
  ASSERT_EQ(tracking.balls.size(), 16u);
  EXPECT_EQ(tracking.swaps, 0);
  int frames = 0, misnamed = 0;
  for (const table_sim_node::BallTracking& b : tracking.balls) {
    EXPECT_EQ(b.lost, 0) << "ball " << b.id;
    EXPECT_LE(b.max_error, 5e-3) << "ball " << b.id;
    EXPECT_TRUE(b.named_at_end) << "ball " << b.id;
    frames += b.frames;
    misnamed += b.misnamed + b.unnamed;
  }
  EXPECT_LE(misnamed, 0.01 * frames);
}

TEST(InProcessLoop, ABreakIsPlannedSimulatedAndTrackedBallByBall) {
  const table_sim_node::SceneResult scene = Break(1);
  EXPECT_EQ(scene.shot.status, "ok") << scene.shot.reason;
  // The cue ball meets the apex ball where the planner aimed it: plans are good to microns, so
  // the miss is the estimator's error on the cue ball at rest, held to its 0.5 mm.
  EXPECT_LT(scene.shot.miss_m, 0.5e-3);
  EXPECT_GT(scene.events, 50);
  ASSERT_EQ(scene.final_balls.size(), 16u);
  const table_sim_node::TrackingReport& tracking = scene.tracking;
  ASSERT_EQ(tracking.balls.size(), 16u);
  double sum = 0.0;
  int frames = 0;
  for (const table_sim_node::BallTracking& b : tracking.balls) {
    EXPECT_GT(b.frames, 200) << "ball " << b.id;  // tracked through most of the 10 s
    sum += b.sum_squared_error;
    frames += b.frames;
  }
  EXPECT_LT(std::sqrt(sum / frames), 3e-3);  // RMS over every ball and frame
  ExpectEveryBallTrackedInEveryFrame(tracking);

  // This is `run_loop.sh --scene break` (seed 1, lockstep): deterministic, so the figures
  // docs/closed-loop.md quotes for it are this run's.
  const nlohmann::json j = table_sim_node::SceneSummary(scene, "break");
  const nlohmann::json& t = j["tracking"];
  double worst_ball = 0.0;
  for (const auto& b : t["balls"]) worst_ball = std::max(worst_ball, b["rms_error_mm"].get<double>());
  const std::vector<std::string> quoted = testing::QuotedFigures(
      "docs/closed-loop.md",
      "the cue ball meets the apex ball ([0-9.]+) mm from the planned contact point [^;]*; "
      "([0-9]+) events; the estimator follows the 16 balls with ([0-9.]+) mm RMS error "
      "\\(([0-9.]+) mm for the worst ball, ([0-9]+) mm at worst in one frame[^)]*\\), "
      "(no|[0-9]+) swaps, ([0-9]+) tracks re-acquired and ([0-9]+) of");
  ASSERT_EQ(quoted.size(), 8u);
  EXPECT_EQ(quoted[0], testing::Quoted(1e3 * scene.shot.miss_m, 3));
  EXPECT_EQ(quoted[1], std::to_string(scene.events));
  EXPECT_EQ(quoted[2], testing::Quoted(t["rms_error_mm"].get<double>(), 2));
  EXPECT_EQ(quoted[3], testing::Quoted(worst_ball, 1));
  EXPECT_EQ(quoted[4], testing::Quoted(t["max_error_mm"].get<double>(), 0));
  EXPECT_EQ(quoted[5], "no");  // the swaps, checked above
  EXPECT_EQ(quoted[6], std::to_string(tracking.reacquired));
  EXPECT_EQ(quoted[7], std::to_string(t["lost_ball_frames"].get<int>()));
}

// Seed 4's rack has the black in its middle scoring just below sure on its first frame (its
// creases merged at the votes' resolution), where it went unpublished for two frames.
TEST(InProcessLoop, ABreakWhoseBlackIsDoubtedOnItsFirstFrameIsTrackedThroughout) {
  ExpectEveryBallTrackedInEveryFrame(Break(4).tracking);
}

}  // namespace
}  // namespace billiard
