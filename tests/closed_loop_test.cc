// The closed loop as a user runs it: launch_scripts/run_loop.sh starts the three node binaries
// as separate processes over UDP multicast (inside a private network namespace when one can be
// made) and prints the session's summary.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/image_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "lcmtypes/testing/recorded_logs.h"
#include "tests/support/quoted_figures.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

namespace {

using billiard::messages::testing::ChannelCounts;
using billiard::messages::testing::CopyWithOneMessageAltered;
using billiard::testing::CommandResult;
using billiard::testing::RunCommand;
using billiard::testing::TempDir;

nlohmann::json RunLoop(const std::string& args) {
  const CommandResult r =
      RunCommand(std::string("bash ") + RUN_LOOP_SCRIPT + " --no-build --json " + args);
  EXPECT_EQ(r.status, 0) << args;
  return nlohmann::json::parse(r.out, nullptr, false);
}

// Records a lockstep run of `shots` into `log`; false (the caller skips) where the machine has no
// multicast and the loop ran in one process, recording nothing.
bool RecordRun(const std::string& log, int shots, const std::string& more_args = "") {
  const nlohmann::json run =
      RunLoop("--shots " + std::to_string(shots) + " --seed 7 --log " + log + " " + more_args);
  EXPECT_TRUE(run.is_object());
  return std::filesystem::exists(log);
}

CommandResult Replay(const std::string& log) {
  return RunCommand(std::string("bash ") + REPLAY_SCRIPT + " " + log + " --json");
}

// Twenty shots to targets (seed 1), the README's main command before it played a rack: lockstep
// is deterministic, so the figures docs/closed-loop.md quotes for it are what this run gives.
TEST(ClosedLoop, TwentyLockstepShotsWithoutNoiseLandWithinMillimetresAsTheManualSays) {
  const nlohmann::json s = RunLoop("--shots 20 --seed 1 --noise off");
  ASSERT_TRUE(s.is_object());
  ASSERT_EQ(s["shots"].size(), 20u);
  for (const auto& shot : s["shots"]) EXPECT_EQ(shot["status"], "ok") << shot;
  EXPECT_LT(s["median_miss_m"].get<double>(), 2e-3);
  EXPECT_LT(s["max_miss_m"].get<double>(), 5e-3);
  const std::vector<std::string> quoted = billiard::testing::QuotedFigures(
      "docs/closed-loop.md",
      "Measured, 20 shots, seed 1, lockstep, noise off, pool parameters [^:]*: every shot "
      "planned, median miss ([0-9.]+) mm, worst ([0-9.]+) mm");
  ASSERT_EQ(quoted.size(), 2u);
  EXPECT_EQ(quoted[0], billiard::testing::Quoted(1e3 * s["median_miss_m"].get<double>(), 2));
  EXPECT_EQ(quoted[1], billiard::testing::Quoted(1e3 * s["max_miss_m"].get<double>(), 2));
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

// The pots of a committed scene (tests/data/), played by run_loop.sh through the three nodes.
nlohmann::json PlayPots(const std::string& scene, const std::string& pots,
                        const std::string& more_args = "") {
  const nlohmann::json s = RunLoop("--scene " + std::string(POT_SCENES_DIR) + "/" + scene + " " +
                                   pots + " " + more_args);
  EXPECT_TRUE(s.is_object()) << scene;
  return s.is_object() ? s["scene"]["pots"] : nlohmann::json::array();
}

// Each pot as the planner planned it from the estimator's view of the rendered frames, executed
// by the table simulator with the robot's noise: ball K drops in pocket P, the cue
// ball touches it first and stays on the table, and rests near the plan's rest (the noise moves
// it by centimetres: 1 % of the cue speed alone is 2 % of the cue ball's run).
TEST(ClosedLoop, PotsOnCommittedScenesDropThroughAllThreeNodesWithTheRobotsNoise) {
  const struct {
    const char* scene;
    int ball;
    const char* pocket;
  } scenes[] = {{"pot_cut_corner.json", 5, "lower_left"},
                {"pot_side_pocket.json", 3, "lower_middle"}};
  for (const auto& k : scenes) {
    const std::string pot = std::to_string(k.ball) + ":" + k.pocket;
    const nlohmann::json pots = PlayPots(k.scene, "--pot " + pot, "--noise on --seed 1");
    ASSERT_EQ(pots.size(), 1u) << k.scene;
    const nlohmann::json& p = pots[0];
    EXPECT_EQ(p["status"], "ok") << k.scene << ": " << p;
    EXPECT_TRUE(p["potted"].get<bool>()) << k.scene << ": " << p;
    EXPECT_EQ(p["dropped"], k.pocket) << p;
    EXPECT_FALSE(p["scratch"].get<bool>()) << p;
    EXPECT_EQ(p["first_contact"], k.ball) << p;
    EXPECT_GT(p["margin_deg"][0].get<double>(), 0.0) << p;
    EXPECT_LT(p["cue_rest_error_m"].get<double>(), 0.25) << p;
  }
  // Without the noise the cue ball rests where the plan said, but for the estimator's error in
  // the balls' positions (a millimetre or two, turned by the cut).
  const nlohmann::json quiet = PlayPots("pot_cut_corner.json", "--pot 5:lower_left", "--noise off");
  ASSERT_EQ(quiet.size(), 1u);
  EXPECT_TRUE(quiet[0]["potted"].get<bool>()) << quiet[0];
  EXPECT_LT(quiet[0]["cue_rest_error_m"].get<double>(), 0.03) << quiet[0];
}

// Seeded layouts (billiard pot-layout --clear --max-cut 60, one per seed, not picked by hand):
// each pot as planned from the estimator's view drops, without the noise, through the three nodes.
TEST(ClosedLoop, PotsOnSeededLayoutsDropThroughAllThreeNodes) {
  for (int seed = 1; seed <= 3; ++seed) {
    const nlohmann::json s = RunLoop("--scene seeded --noise off --seed " + std::to_string(seed));
    ASSERT_TRUE(s.is_object()) << seed;
    const nlohmann::json& pots = s["scene"]["pots"];
    ASSERT_EQ(pots.size(), 1u) << seed;
    EXPECT_EQ(pots[0]["status"], "ok") << seed << ": " << pots[0];
    EXPECT_TRUE(pots[0]["potted"].get<bool>()) << seed << ": " << pots[0];
    EXPECT_FALSE(pots[0]["scratch"].get<bool>()) << pots[0];
  }
}

// `billiard loop` (the three nodes in one process, what run_loop.sh falls back to without
// multicast) plays the same pot to the same bits: its planner pots on the scene's table too.
TEST(ClosedLoop, APotInOneProcessIsThePotOfThreeProcesses) {
  const std::string scene = std::string(POT_SCENES_DIR) + "/pot_side_pocket.json";
  const nlohmann::json processes = PlayPots("pot_side_pocket.json", "--pot 3:lower_middle");
  const CommandResult r = RunCommand(std::string(BILLIARD_BIN) + " loop --scene " + scene +
                                     " --pot 3:lower_middle 2>/dev/null");
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json one = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_TRUE(one.is_object()) << r.out;
  const nlohmann::json& pot = one["scene"]["pots"][0];
  ASSERT_EQ(processes.size(), 1u);
  EXPECT_TRUE(pot["potted"].get<bool>()) << pot;
  for (const char* field : {"status", "kind", "margin_deg", "speed_window", "planned_cue_rest",
                            "cue_rest", "dropped"}) {
    EXPECT_EQ(pot[field], processes[0][field]) << field;
  }
}

// Bad pot requests are refused with the planner's reason, nothing moves, and the planner goes on
// to plan the next pot of the session.
TEST(ClosedLoop, BadPotRequestsAreRefusedAndThePlannerGoesOnToPotTheNext) {
  const nlohmann::json pots =
      PlayPots("pot_cut_corner.json", "--pot 42:lower_left --pot 5:nowhere --pot 5:lower_left");
  ASSERT_EQ(pots.size(), 3u) << pots;
  EXPECT_EQ(pots[0]["status"], "no_such_ball") << pots[0];
  EXPECT_NE(pots[0]["reason"].get<std::string>().find("42"), std::string::npos) << pots[0];
  EXPECT_EQ(pots[1]["status"], "no_such_pocket") << pots[1];
  EXPECT_NE(pots[1]["reason"].get<std::string>().find("nowhere"), std::string::npos) << pots[1];
  for (int i : {0, 1}) {
    EXPECT_FALSE(pots[i]["potted"].get<bool>()) << pots[i];
    EXPECT_EQ(pots[i]["first_contact"], nullptr) << "the cue moved: " << pots[i];
  }
  EXPECT_EQ(pots[2]["status"], "ok") << pots[2];
  EXPECT_TRUE(pots[2]["potted"].get<bool>()) << pots[2];

  // A pot without a scene, or not K:P, is a usage error.
  for (const char* args : {"--pot 5:lower_left", "--scene break --pot 5:lower_left"}) {
    const CommandResult r =
        RunCommand(std::string("bash ") + RUN_LOOP_SCRIPT + " --no-build " + args, true);
    EXPECT_EQ(r.status, 2) << args << ": " << r.out;
    EXPECT_NE(r.out.find("--pot needs --scene FILE"), std::string::npos) << r.out;
  }
  const CommandResult bad =
      RunCommand(std::string("bash ") + RUN_LOOP_SCRIPT + " --no-build " + "--scene " +
                     POT_SCENES_DIR + "/pot_cut_corner.json --pot five:lower_left",
                 true);
  EXPECT_EQ(bad.status, 2) << bad.out;
  EXPECT_NE(bad.out.find("--pot 'five:lower_left' is not K:P"), std::string::npos) << bad.out;
}

// A nine-ball drill through the three nodes (two shots of seed 1): the table simulator places
// the seeded layout and renders it, the estimator sees and names the balls, the planner chooses
// from its view with the cue ball in hand, and the table executes the choice with the robot's
// noise and judges it. Recorded, the game replays to the same choices bit for bit.
TEST(ClosedLoop, ANineBallDrillIsPlayedThroughTheThreeNodesAndReplays) {
  const TempDir dir;
  const std::string log = dir / "game.lcm";
  const nlohmann::json s = RunLoop("--game drill --shot-limit 2 --seed 1 --log " + log);
  ASSERT_TRUE(s.is_object());
  const nlohmann::json& rack = s["game"]["racks"][0];
  ASSERT_EQ(rack["shots"].size(), 2u) << rack;
  const nlohmann::json& first = rack["shots"][0];
  EXPECT_TRUE(first["ball_in_hand"].get<bool>()) << first;
  EXPECT_EQ(first["status"], "ok") << first;
  EXPECT_TRUE(first.contains("cue_placement")) << first;
  // The truth's lowest ball, called and hit first: the estimator named the balls right.
  EXPECT_EQ(first["called"]["ball"], 1) << first;
  EXPECT_EQ(first["first_contact"], 1) << first;
  for (const nlohmann::json& shot : rack["shots"]) {
    EXPECT_EQ(shot["estimator"]["misidentified"], 0) << shot;
    EXPECT_EQ(shot["estimator"]["untracked"], 0) << shot;
    EXPECT_LT(shot["estimator"]["position_max_mm"].get<double>(), 3.0) << shot;
    EXPECT_GT(shot["decision_ms"].get<double>(), 0.0) << shot;
  }
  const nlohmann::json& g = s["game"]["summary"];
  EXPECT_EQ(g["racks"], 1);
  EXPECT_EQ(g["shots"], 2);
  EXPECT_EQ(g["decisions"], 2);
  if (!std::filesystem::exists(log)) {
    GTEST_SKIP() << "no multicast here: the loop ran in one process and recorded nothing";
  }
  const CommandResult r = Replay(log);
  EXPECT_EQ(r.status, 0) << r.out;
  const nlohmann::json replay = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_TRUE(replay.is_object()) << r.out;
  EXPECT_TRUE(replay["identical"].get<bool>()) << replay;
  // A choice takes longer than the simulator's retry interval: its request goes again, and the
  // planner answers each copy (from memory), so there are more answers than shots.
  EXPECT_GE(replay["cue_commands"]["recorded"].get<int>(), 2) << replay;
}

// A match through the three nodes (issue 48): two racks of two shots between two players, rack k
// broken by player k % 2 with the stored break (the planner places the cue ball), each choice
// asked naming the player at the table, the table refereeing by sim/rules. Recorded, the match
// replays to the same strokes bit for bit.
TEST(ClosedLoop, AMatchAlternatesBreaksAndTurnsBetweenTwoPlayersAndReplays) {
  const TempDir dir;
  const std::string log = dir / "match.lcm";
  const nlohmann::json s = RunLoop(
      "--game nine-ball --players ours,easiest-looking --racks 2 --shot-limit 2 --log " + log);
  ASSERT_TRUE(s.is_object());
  const std::string names[2] = {"ours", "easiest-looking"};
  std::map<std::string, int> attempts, fouls, won;
  for (int k = 0; k < 2; ++k) {
    const nlohmann::json& rack = s["game"]["racks"][k];
    EXPECT_EQ(rack["breaker"], names[k]) << rack;
    const nlohmann::json& shots = rack["shots"];
    ASSERT_FALSE(shots.empty()) << rack;
    EXPECT_TRUE(shots[0]["break"].get<bool>() && shots[0].contains("cue_placement")) << rack;
    EXPECT_EQ(shots[0]["player"], names[k]) << rack;
    // After the break the rules say who shoots: the breaker only after a legal break that
    // potted, and with ball in hand only after a foul.
    if (shots.size() == 2) {
      const bool kept = !shots[0]["foul"].get<bool>() && !shots[0]["potted"].empty();
      EXPECT_EQ(shots[1]["player"], names[kept ? k : 1 - k]) << rack;
      EXPECT_EQ(shots[1]["ball_in_hand"], shots[0]["foul"]) << rack;
    }
    for (const nlohmann::json& shot : shots) {
      attempts[shot["player"]] += shot.contains("called");
      fouls[shot["player"]] += shot["foul"].get<bool>();
    }
    if (!rack["winner"].is_null()) ++won[rack["winner"]];
  }
  const nlohmann::json& players = s["game"]["players"];
  ASSERT_EQ(players.size(), 2u) << players;
  for (int k = 0; k < 2; ++k) {
    const nlohmann::json& p = players[k];
    EXPECT_EQ(p["name"], names[k]) << p;
    EXPECT_EQ(p["attempts"], attempts[names[k]]) << p;
    EXPECT_EQ(p["fouls"], fouls[names[k]]) << p;
    EXPECT_EQ(p["racks_won"], won[names[k]]) << p;
    EXPECT_LE(p["interval95"][0], p["win_rate"]) << p;
    EXPECT_GE(p["interval95"][1], p["win_rate"]) << p;
  }
  if (!std::filesystem::exists(log)) GTEST_SKIP() << "no multicast here: nothing recorded";
  const CommandResult r = Replay(log);
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("\"identical\":true"), std::string::npos) << r.out;
}

TEST(ClosedLoop, CtrlCStopsEveryProcess) {
  // Ctrl-C reaches the whole process group of the script (setsid gives it one of its own).
  const std::string script =
      std::string("setsid bash ") + RUN_LOOP_SCRIPT +
      " --no-build --shots 20 >/dev/null 2>&1 & "
      "group=$!; sleep 3; kill -INT -- -$group; wait $group; echo \"exit $?\"; sleep 1; "
      "pgrep -g $group >/dev/null && echo orphans || echo clean";
  const billiard::testing::CommandResult r =
      billiard::testing::RunCommand("bash -c '" + script + "'");
  EXPECT_EQ(r.out, "exit 130\nclean\n");
}

TEST(ClosedLoop, ARecordedRunReplaysToTheSameCommandsAndDecodesInJava) {
  const TempDir dir;
  const std::string log = dir / "run.lcm";
  if (!RecordRun(log, 2)) {
    GTEST_SKIP() << "no multicast here: the loop ran in one process and recorded nothing";
  }
  // A relative path names a file in the caller's directory, not in the repository.
  const CommandResult r =
      RunCommand("cd " + dir.path() + " && bash " + REPLAY_SCRIPT + " run.lcm --json");
  EXPECT_EQ(r.status, 0) << r.out;
  const nlohmann::json replay = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_TRUE(replay.is_object()) << r.out;
  EXPECT_TRUE(replay["identical"].get<bool>()) << replay;
  EXPECT_EQ(replay["clock"], "lockstep") << replay;
  EXPECT_EQ(replay["cue_commands"]["recorded"], 2) << replay;
  EXPECT_GT(replay["table_states"]["recorded"].get<int>(), 50) << replay;

  // The log decodes with the Java classes lcm-gen makes from the same .lcm files.
  const CommandResult java =
      RunCommand(std::string("java -cp ") + JAVA_CLASSPATH + " DecodeLog " + log);
  ASSERT_EQ(java.status, 0) << java.out;
  const nlohmann::json decoded = nlohmann::json::parse(java.out, nullptr, false);
  ASSERT_TRUE(decoded.is_object()) << java.out;
  EXPECT_EQ(decoded["CUE_COMMAND"], 2) << decoded;
  EXPECT_EQ(decoded["SHOT_REQUEST"], 2) << decoded;
  EXPECT_EQ(decoded["TABLE_STATE"], replay["table_states"]["recorded"]) << decoded;
  EXPECT_EQ(decoded["CAMERA_IMAGE"], decoded["TABLE_STATE"]) << decoded;
}

// What runs is what is installed: every node process of a run announces in NODE_STATUS the
// version `billiard --version` prints (read back from the log by `billiard node-status`).
TEST(ClosedLoop, EveryNodeAnnouncesTheVersionTheToolPrints) {
  const TempDir dir;
  const std::string log = dir / "light.lcm";
  if (!RecordRun(log, 1, "--log-frames none")) {
    GTEST_SKIP() << "no multicast here: the loop ran in one process and recorded nothing";
  }
  const CommandResult version = RunCommand(std::string(BILLIARD_BIN) + " --version");
  ASSERT_EQ(version.status, 0) << version.out;
  ASSERT_EQ(version.out.rfind("billiard ", 0), 0u) << version.out;
  const std::string expected = version.out.substr(9, version.out.find('\n') - 9);
  const CommandResult r = RunCommand(std::string(BILLIARD_BIN) + " node-status " + log);
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json status = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_TRUE(status.is_object()) << r.out;
  std::vector<std::string> nodes;
  for (const nlohmann::json& process : status["processes"]) {
    nodes.push_back(process["node"]);
    EXPECT_EQ(process["version"], expected) << process;
  }
  std::sort(nodes.begin(), nodes.end());
  EXPECT_EQ(nodes, (std::vector<std::string>{"estimator_node", "planner_node", "table_sim_node"}));
}

TEST(ClosedLoop, ALogThatCannotBeWrittenFailsBeforeTheNodesStart) {
  // A directory that is not there is not made (lcm-logger would make it): a mistyped path is
  // said at once.
  const TempDir dir;
  const std::string log = dir / "missing/run.lcm";
  const CommandResult r =
      RunCommand(std::string("bash ") + RUN_LOOP_SCRIPT + " --no-build --json --log " + log, true);
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_EQ(r.out, "run_loop: cannot write the log '" + log + "': No such file or directory\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
}

TEST(ClosedLoop, ALogThatRecordsNothingFailsTheRun) {
  // /dev/full opens for writing, and every write to it fails.
  const CommandResult r = RunCommand(
      std::string("bash ") + RUN_LOOP_SCRIPT + " --no-build --shots 1 --log /dev/full", true);
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("run_loop: the log '/dev/full'"), std::string::npos) << r.out;
}

TEST(ClosedLoop, ARelativeLogPathNamesAFileInTheCallersDirectory) {
  const TempDir dir;
  const std::string name = "closed_loop_test_relative.lcm";
  const std::filesystem::path in_repository =
      std::filesystem::path(RUN_LOOP_SCRIPT).parent_path().parent_path() / name;
  const CommandResult r = RunCommand("cd " + dir.path() + " && bash " + RUN_LOOP_SCRIPT +
                                     " --no-build --json --shots 1 --log " + name);
  EXPECT_EQ(r.status, 0) << r.out;
  if (std::filesystem::remove(in_repository)) FAIL() << "the log landed in the repository";
  if (!std::filesystem::exists(dir / name)) {
    GTEST_SKIP() << "no multicast here: the loop ran in one process and recorded nothing";
  }
  EXPECT_EQ(ChannelCounts(dir / name)["CUE_COMMAND"], 1);
}

TEST(ClosedLoop, ALogWithoutFramesHoldsTheRestAndSaysItCannotBeReplayed) {
  const TempDir dir;
  if (!RecordRun(dir / "light.lcm", 1, "--log-frames none")) {
    GTEST_SKIP() << "no multicast here: the loop ran in one process and recorded nothing";
  }
  std::map<std::string, int> counts = ChannelCounts(dir / "light.lcm");
  EXPECT_EQ(counts.count("CAMERA_IMAGE"), 0u);
  EXPECT_GT(counts["TABLE_STATE"], 50);
  EXPECT_GT(counts["TABLE_TRUTH"], 50);
  EXPECT_EQ(counts["CUE_COMMAND"], 1);
  EXPECT_GT(counts["NODE_STATUS"], 0);
  std::fprintf(stderr, "a 1-shot log without frames: %ju bytes\n",
               static_cast<std::uintmax_t>(std::filesystem::file_size(dir / "light.lcm")));

  const CommandResult r =
      RunCommand(std::string("bash ") + REPLAY_SCRIPT + " " + (dir / "light.lcm"), true);
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_NE(r.out.find("no CAMERA_IMAGE"), std::string::npos) << r.out;
}

TEST(ClosedLoop, AReplayNamesTheFirstMessageAndFieldThatDiffer) {
  const TempDir dir;
  const std::string log = dir / "run.lcm";
  if (!RecordRun(log, 1)) {
    GTEST_SKIP() << "no multicast here: the loop ran in one process and recorded nothing";
  }
  std::fprintf(stderr, "a 1-shot log with frames: %ju bytes\n",
               static_cast<std::uintmax_t>(std::filesystem::file_size(log)));
  double recorded_y = 0.0;
  const auto move_the_ball = [&recorded_y](billiard::table_state_t& m) {
    ASSERT_GT(m.num_balls, 0);
    recorded_y = m.balls[0].position[1] += 1e-4;
  };
  CopyWithOneMessageAltered<billiard::table_state_t>(log, dir / "state.lcm", "TABLE_STATE", 12,
                                                     move_the_ball);
  CommandResult r = Replay(dir / "state.lcm");
  EXPECT_EQ(r.status, 3) << r.out;
  nlohmann::json replay = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_TRUE(replay.is_object()) << r.out;
  const nlohmann::json& state = replay["first_difference"];
  EXPECT_EQ(state["channel"], "TABLE_STATE") << replay;
  EXPECT_EQ(state["index"], 12) << replay;
  EXPECT_EQ(state["field"], "balls[0].position[1]") << replay;
  EXPECT_EQ(state["recorded"], recorded_y) << replay;
  EXPECT_NEAR(state["replayed"].get<double>(), recorded_y - 1e-4, 1e-12) << replay;
  EXPECT_GT(state["utime"].get<std::int64_t>(), 0) << replay;
  EXPECT_EQ(replay["table_states"]["identical"].get<int>() + 1,
            replay["table_states"]["recorded"].get<int>())
      << replay;

  CopyWithOneMessageAltered<billiard::cue_command_t>(
      log, dir / "command.lcm", "CUE_COMMAND", 0,
      [](billiard::cue_command_t& m) { m.heading += 1e-3; });
  r = RunCommand(std::string("bash ") + REPLAY_SCRIPT + " " + (dir / "command.lcm"), true);
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_NE(r.out.find("first difference: CUE_COMMAND 0 (utime "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("): heading: recorded "), std::string::npos) << r.out;
}

// A message the nodes had but the logger lost (lockstep waits for the estimator, not for the
// logger, and UDP multicast promises no delivery; so a 10-rack match's log lost a frame while the
// planner decided): the replay names the lost message, not the estimator's states after it,
// which looked a frame out of step.
TEST(ClosedLoop, AReplayNamesAMessageTheLogLost) {
  using billiard::messages::testing::UtimeOf;
  const TempDir dir;
  const std::string log = dir / "run.lcm";
  if (!RecordRun(log, 1)) {
    GTEST_SKIP() << "no multicast here: the loop ran in one process and recorded nothing";
  }
  constexpr int kLost = 20;  // a frame past the table's learning, before the shot
  const std::int64_t frame = UtimeOf<billiard::image_t>(log, "CAMERA_IMAGE", kLost);
  ASSERT_GT(frame, 0);
  billiard::messages::testing::CopyWithAFrameLost(log, dir / "frame.lcm", frame);
  CommandResult r = Replay(dir / "frame.lcm");
  EXPECT_EQ(r.status, 3) << r.out;
  nlohmann::json replay = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_TRUE(replay.is_object()) << r.out;
  EXPECT_EQ(replay["lost_frames"], 1) << replay;
  EXPECT_EQ(replay["first_difference"]["channel"], "CAMERA_IMAGE") << replay;
  EXPECT_EQ(replay["first_difference"]["utime"], frame) << replay;
  EXPECT_GE(replay["first_difference"]["index"].get<int>(), kLost) << replay;
  EXPECT_NE(replay["first_difference"].value("reason", "").find("lcm-logger lost it"),
            std::string::npos)
      << replay;
  // Every state before it replays bit for bit: the first that differs is the lost frame's.
  EXPECT_EQ(replay["table_states"]["first_difference"]["utime"], frame) << replay;

  const std::int64_t state = UtimeOf<billiard::table_state_t>(log, "TABLE_STATE", kLost);
  billiard::messages::testing::CopyWithOneMessageLost(log, dir / "state.lcm", "TABLE_STATE", kLost);
  r = Replay(dir / "state.lcm");
  EXPECT_EQ(r.status, 3) << r.out;
  replay = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_TRUE(replay.is_object()) << r.out;
  EXPECT_EQ(replay["lost_frames"], 0) << replay;
  EXPECT_EQ(replay["lost_states"], 1) << replay;
  EXPECT_EQ(replay["first_difference"]["channel"], "TABLE_STATE") << replay;
  EXPECT_EQ(replay["first_difference"]["index"], kLost) << replay;
  EXPECT_EQ(replay["first_difference"]["utime"], state) << replay;
  EXPECT_NE(replay["first_difference"].value("reason", "").find("lcm-logger lost it"),
            std::string::npos)
      << replay;
}

TEST(ClosedLoop, ARealtimeLogIsReportedAsNotReplayableBitForBit) {
  const TempDir dir;
  const std::string log = dir / "realtime.lcm";
  if (!RecordRun(log, 1, "--realtime")) {
    GTEST_SKIP() << "no multicast here: the loop ran in one process and recorded nothing";
  }
  const CommandResult r = Replay(log);
  EXPECT_EQ(r.status, 3) << r.out;
  const nlohmann::json replay = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_TRUE(replay.is_object()) << r.out;
  EXPECT_EQ(replay["clock"], "realtime") << replay;
  EXPECT_NE(replay.value("reason", "").find("not replayable bit for bit"), std::string::npos)
      << replay;
}

}  // namespace
