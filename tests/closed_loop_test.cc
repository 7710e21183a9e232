// The closed loop as a user runs it: launch_scripts/run_loop.sh starts the three node binaries
// as separate processes over UDP multicast (inside a private network namespace when one can be
// made) and prints the session's summary.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_command.h"

namespace {

nlohmann::json RunLoop(const std::string& args) {
  const billiard::testing::CommandResult r = billiard::testing::RunCommand(
      std::string("bash ") + RUN_LOOP_SCRIPT + " --no-build --json " + args);
  EXPECT_EQ(r.status, 0) << args;
  return nlohmann::json::parse(r.out, nullptr, false);
}

TEST(ClosedLoop, TwentyLockstepShotsWithoutNoiseLandWithinMillimetres) {
  const nlohmann::json s = RunLoop("--shots 20 --seed 3 --noise off");
  ASSERT_TRUE(s.is_object());
  ASSERT_EQ(s["shots"].size(), 20u);
  for (const auto& shot : s["shots"]) EXPECT_EQ(shot["status"], "ok") << shot;
  EXPECT_LT(s["median_miss_m"].get<double>(), 2e-3);
  EXPECT_LT(s["max_miss_m"].get<double>(), 5e-3);
}

TEST(ClosedLoop, LockstepRunsReplayTheSameShots) {
  // Same seed, same bytes: the lockstep clock makes the session deterministic.
  const nlohmann::json a = RunLoop("--shots 2 --seed 5 --noise on");
  const nlohmann::json b = RunLoop("--shots 2 --seed 5 --noise on");
  ASSERT_TRUE(a.is_object() && b.is_object());
  ASSERT_EQ(a["shots"].size(), 2u);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(a["shots"][i]["final"], b["shots"][i]["final"]);
    EXPECT_EQ(a["shots"][i]["target"], b["shots"][i]["target"]);
  }
  EXPECT_GT(a["stddev_miss_m"].get<double>(), 0.0);
}

TEST(ClosedLoop, CtrlCStopsEveryProcess) {
  // Ctrl-C reaches the whole process group of the script (setsid gives it one of its own).
  const std::string script =
      std::string("setsid bash ") + RUN_LOOP_SCRIPT + " --no-build --shots 20 >/dev/null 2>&1 & "
      "group=$!; sleep 3; kill -INT -- -$group; wait $group; echo \"exit $?\"; sleep 1; "
      "pgrep -g $group >/dev/null && echo orphans || echo clean";
  const billiard::testing::CommandResult r =
      billiard::testing::RunCommand("bash -c '" + script + "'");
  EXPECT_EQ(r.out, "exit 130\nclean\n");
}

TEST(ClosedLoop, ARecordedRunReplaysToTheSameCommandsAndDecodesInJava) {
  char dir[] = "/tmp/closed_loop_XXXXXX";
  ASSERT_NE(mkdtemp(dir), nullptr);
  const std::string log = std::string(dir) + "/run.lcm";
  const nlohmann::json run = RunLoop("--shots 2 --seed 7 --log " + log);
  ASSERT_TRUE(run.is_object());
  if (!std::filesystem::exists(log)) {
    GTEST_SKIP() << "no multicast here: the loop ran in one process and recorded nothing";
  }
  const billiard::testing::CommandResult r =
      billiard::testing::RunCommand(std::string("bash ") + REPLAY_SCRIPT + " " + log + " --json");
  EXPECT_EQ(r.status, 0) << r.out;
  const nlohmann::json replay = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_TRUE(replay.is_object()) << r.out;
  EXPECT_TRUE(replay["identical"].get<bool>()) << replay;
  EXPECT_EQ(replay["cue_commands"]["recorded"], 2) << replay;
  EXPECT_GT(replay["table_states"]["recorded"].get<int>(), 50) << replay;

  // The log decodes with the Java classes lcm-gen makes from the same .lcm files.
  const billiard::testing::CommandResult java = billiard::testing::RunCommand(
      std::string("java -cp ") + JAVA_CLASSPATH + " DecodeLog " + log);
  ASSERT_EQ(java.status, 0) << java.out;
  const nlohmann::json decoded = nlohmann::json::parse(java.out, nullptr, false);
  ASSERT_TRUE(decoded.is_object()) << java.out;
  EXPECT_EQ(decoded["CUE_COMMAND"], 2) << decoded;
  EXPECT_EQ(decoded["SHOT_REQUEST"], 2) << decoded;
  EXPECT_EQ(decoded["TABLE_STATE"], replay["table_states"]["recorded"]) << decoded;
  EXPECT_EQ(decoded["CAMERA_IMAGE"], decoded["TABLE_STATE"]) << decoded;
  std::filesystem::remove_all(dir);
}

}  // namespace
