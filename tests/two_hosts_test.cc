// The loop on two hosts of a LAN (launch_scripts/two_hosts.sh: two network namespaces joined by
// a virtual Ethernet pair, the planner on one, the estimator and the table simulator on the
// other): every shot lands, and, lockstep being deterministic, each is the very shot the loop
// plays on one host (run_loop.sh, same shots and seed).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/run_command.h"

namespace {

nlohmann::json JsonOf(const std::string& command) {
  const billiard::testing::CommandResult r = billiard::testing::RunCommand(command);
  EXPECT_EQ(r.status, 0) << command;
  return nlohmann::json::parse(r.out, nullptr, false);
}

TEST(TwoHosts, EveryShotLandsAsOnOneHost) {
  const nlohmann::json two =
      JsonOf(std::string("bash ") + TWO_HOSTS_SCRIPT + " --no-build --shots 3");
  ASSERT_TRUE(two.is_object());
  if (two.contains("skipped")) GTEST_SKIP() << two["skipped"];
  const nlohmann::json one =
      JsonOf(std::string("bash ") + RUN_LOOP_SCRIPT + " --no-build --json --shots 3");
  ASSERT_EQ(two["shots"].size(), 3u);
  ASSERT_EQ(one["shots"].size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const nlohmann::json& a = two["shots"][k];
    const nlohmann::json& b = one["shots"][k];
    EXPECT_EQ(a["status"], "ok") << a;
    EXPECT_LT(a["miss_m"].get<double>(), 5e-3) << a;
    EXPECT_EQ(a["target"], b["target"]) << k;
    EXPECT_EQ(a["final"], b["final"]) << k;  // bit for bit
    EXPECT_EQ(a["miss_m"], b["miss_m"]) << k;
  }
}

}  // namespace
