// launch_scripts/spy.sh as a user runs it: its headless check finds every message type of
// lcmtypes/*.lcm in lcm-spy's type database, with the fingerprint the C++ nodes send, and it
// answers --help and a bad command line as every script does.
#include <gtest/gtest.h>

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "lcmtypes/billiard/ball_path_t.hpp"
#include "lcmtypes/billiard/ball_state_t.hpp"
#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/image_t.hpp"
#include "lcmtypes/billiard/node_status_t.hpp"
#include "lcmtypes/billiard/shot_request_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "tests/support/run_command.h"

namespace {

namespace fs = std::filesystem;
using billiard::testing::CommandResult;
using billiard::testing::RunCommand;

const std::string kSpy = std::string("bash ") + SPY_SCRIPT;

// The fingerprint as the check prints it: 16 hex digits of the 64-bit hash.
template <typename Message>
std::string Fingerprint() {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016" PRIx64, static_cast<uint64_t>(Message::getHash()));
  return hex;
}

nlohmann::json Check(const std::string& build_dir, int expected_status) {
  const CommandResult r = RunCommand(kSpy + " --check --build-dir " + build_dir);
  EXPECT_EQ(r.status, expected_status) << r.out;
  return nlohmann::json::parse(r.out, nullptr, false);
}

// What a command prints on stderr alone.
CommandResult Stderr(const std::string& args) {
  return RunCommand("(" + kSpy + " " + args + " 2>&1 >/dev/null)");
}

TEST(Spy, CheckFindsEveryProjectType) {
  const nlohmann::json check = Check(BUILD_DIR, 0);
  ASSERT_TRUE(check.is_object());
  EXPECT_EQ(check["missing"], nlohmann::json::array()) << check;
  int types = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(LCM_TYPES_DIR)) {
    if (entry.path().extension() != ".lcm") continue;
    ++types;
    EXPECT_TRUE(check["decoded"].contains("billiard." + entry.path().stem().string())) << check;
  }
  EXPECT_EQ(types, 7);
  EXPECT_EQ(check["decoded"].size(), static_cast<size_t>(types)) << check;
}

TEST(Spy, CheckFingerprintsAreTheOnesTheNodesSend) {
  // lcm-spy picks the decoder by the message's first 8 bytes: a jar out of date with the .lcm
  // files would decode nothing the C++ nodes publish.
  const nlohmann::json check = Check(BUILD_DIR, 0);
  ASSERT_TRUE(check.is_object());
  const nlohmann::json& decoded = check["decoded"];
  EXPECT_EQ(decoded["billiard.ball_path_t"], Fingerprint<billiard::ball_path_t>());
  EXPECT_EQ(decoded["billiard.ball_state_t"], Fingerprint<billiard::ball_state_t>());
  EXPECT_EQ(decoded["billiard.cue_command_t"], Fingerprint<billiard::cue_command_t>());
  EXPECT_EQ(decoded["billiard.image_t"], Fingerprint<billiard::image_t>());
  EXPECT_EQ(decoded["billiard.node_status_t"], Fingerprint<billiard::node_status_t>());
  EXPECT_EQ(decoded["billiard.shot_request_t"], Fingerprint<billiard::shot_request_t>());
  EXPECT_EQ(decoded["billiard.table_state_t"], Fingerprint<billiard::table_state_t>());
}

TEST(Spy, CheckFailsWhenTheJarLacksTheTypes) {
  // A build tree whose types jar is a valid jar without them (LCM's own).
  char dir[] = "/tmp/spy_test_XXXXXX";
  ASSERT_NE(mkdtemp(dir), nullptr);
  const fs::path java = fs::path(dir) / "lcmtypes" / "java";
  fs::create_directories(java);
  fs::copy(fs::path(BUILD_DIR) / "lcmtypes" / "java" / "helpers", java / "helpers");
  fs::copy_file("/usr/share/java/lcm.jar", java / "billiard_lcmtypes.jar");

  const nlohmann::json check = Check(dir, 1);
  fs::remove_all(dir);
  ASSERT_TRUE(check.is_object());
  EXPECT_EQ(check["decoded"], nlohmann::json::object()) << check;
  EXPECT_EQ(check["missing"].size(), 7u) << check;
}

TEST(Spy, CheckWithoutABuildSaysSoInOneLine) {
  const CommandResult r = Stderr("--check --build-dir /nonexistent");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("build.sh"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find('\n'), r.out.size() - 1) << r.out;
}

TEST(Spy, HelpExitsZero) {
  const CommandResult r = RunCommand(kSpy + " --help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("--check"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--lcm-url"), std::string::npos) << r.out;
}

TEST(Spy, BadCommandLinesExitTwoWithOneLine) {
  for (const std::string args : {"--bogus", "--lcm-url", "extra"}) {
    const CommandResult r = Stderr(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_FALSE(r.out.empty()) << args;
    EXPECT_EQ(r.out.find('\n'), r.out.size() - 1) << args << ": " << r.out;
  }
}

}  // namespace
