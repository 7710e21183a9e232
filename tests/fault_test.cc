// Faults the loop must survive, through the real binaries: its nodes killed and started again
// mid-run, a new session with a new clock, a burst of 10,000 shot requests
// (launch_scripts/fault_drill.sh), and a lossy link between the table and the nodes.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_command.h"

namespace {

void ExpectEveryShotLands(const nlohmann::json& session, const std::string& name) {
  ASSERT_TRUE(session.contains("shots")) << name << ": " << session;
  for (const auto& shot : session["shots"]) {
    EXPECT_EQ(shot["status"], "ok") << name << ": " << shot;
    EXPECT_LT(shot["miss_m"].get<double>(), 5e-3) << name << ": " << shot;
  }
}

TEST(FaultDrill, KilledNodesRestartedMidRunAndABurstOfRequests) {
  // Started from outside the repository by a relative path, as a user may: the script must
  // find itself again after it changes directory.
  const std::string elsewhere = ::testing::TempDir();
  const std::string script =
      std::filesystem::relative(FAULT_DRILL_SCRIPT, elsewhere).string();
  const billiard::testing::CommandResult r = billiard::testing::RunCommand(
      "cd " + elsewhere + " && bash " + script + " --no-build --shots 6");
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json drill = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_TRUE(drill.is_object()) << r.out;
  if (drill.contains("skipped")) GTEST_SKIP() << drill["skipped"];

  // The sessions go on through the kills; the one after the killed session starts a new clock.
  ExpectEveryShotLands(drill["session1"], "session 1");
  ASSERT_EQ(drill["session1"]["shots"].size(), 6u);
  ExpectEveryShotLands(drill["session3"], "session 3");
  ASSERT_EQ(drill["session3"]["shots"].size(), 3u);

  // An estimator that stopped leaves a state the planner must not act on.
  EXPECT_EQ(drill["stale"]["statuses"], nlohmann::json({{"stale_state", 20}})) << drill["stale"];

  // Every request of the burst answered, from a queue that stays bounded, in bounded memory.
  const nlohmann::json& burst = drill["burst"];
  EXPECT_EQ(burst["unanswered"], 0) << burst;
  EXPECT_EQ(burst["answered_twice"], 0) << burst;
  EXPECT_EQ(burst["statuses"].value("ok", 0) + burst["statuses"].value("busy", 0), 10000) << burst;
  EXPECT_GE(burst["statuses"].value("ok", 0), 32) << "the queue's worth is planned";
  const nlohmann::json& rss = drill["planner_rss_kb"];
  EXPECT_LT(rss["after_burst"].get<int>() - rss["before_burst"].get<int>(), 16 * 1024) << rss;
  // What the first burst took, the second mostly reuses: the allocator settles within a few
  // bursts (12.2, 12.4, 13.0, 13.0, 13.0 MB over five here); a leak of 200 bytes or more a
  // request would add 2 MB a burst.
  EXPECT_LT(rss["after_second_burst"].get<int>() - rss["after_burst"].get<int>(), 2048) << rss;
  EXPECT_EQ(drill["second_burst"]["unanswered"], 0) << drill["second_burst"];

  // Each node process reported its health and saw the new clocks. Nothing was refused but the
  // late messages that tell a new clock close to the old one (two before the third makes it).
  int estimators = 0, planners = 0, clock_resets = 0;
  for (const auto& p : drill["nodes"]) {
    estimators += p["node"] == "estimator_node";
    planners += p["node"] == "planner_node";
    const int resets = p["counters"].value("clock_reset", 0);
    if (p["node"] == "estimator_node") clock_resets += resets;
    EXPECT_LE(p["dropped"].get<int>(), 2 * resets) << p;
    EXPECT_LE(p["max_queue_depth"].get<int>(), 32) << p;
  }
  EXPECT_EQ(estimators, 2) << drill["nodes"];
  EXPECT_EQ(planners, 2) << drill["nodes"];
  EXPECT_GE(clock_resets, 1) << drill["nodes"];
}

TEST(LossyLink, FramesDroppedReorderedAndRepeatedStillLandEveryShot) {
  const billiard::testing::CommandResult r = billiard::testing::RunCommand(
      std::string(BILLIARD_BIN) +
      " loop --shots 4 --seed 2 --drop-frames 0.1 --reorder-frames 0.05 --duplicate 0.05");
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json s = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_TRUE(s.is_object()) << r.out;
  ASSERT_EQ(s["shots"].size(), 4u) << s;
  ExpectEveryShotLands(s, "lossy link");
  EXPECT_LT(s["max_miss_m"].get<double>(), 3e-3) << s;
  const nlohmann::json& c = s["counters"];
  EXPECT_GT(c.value("frame_dropped", 0), 0) << c;
  EXPECT_GT(c.value("frame_reordered", 0), 0) << c;
  EXPECT_GT(c.value("frame_duplicated", 0), 0) << c;
  EXPECT_EQ(s["dropped"], 0) << s;
}

}  // namespace
