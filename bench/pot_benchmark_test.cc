// The pot benchmark's acceptance figures on a smaller run than the committed one
// (docs/benchmarks/pot_report.md): every ok plan pots when simulated on its own, the clear
// straight lines are planned, and every heading of the 0.01-degree grid inside the margin pots
// while the first past it misses.
#include "bench/pot_benchmark.h"

#include <gtest/gtest.h>

namespace billiard::bench {
namespace {

TEST(PotBenchmark, PlansPotThatDropAndMarginsThatHold) {
  PotBenchmarkOptions options;
  options.layouts = 80;
  options.margin_checks = 25;
  options.position_targets = 4;
  const PotBenchmarkResult result = RunPotBenchmark(options);
  const nlohmann::json s = PotSummaryJson(result);
  ASSERT_GT(s["truth"]["ok"].get<int>(), 30);
  EXPECT_EQ(s["truth"]["verified"], s["truth"]["ok"]);
  EXPECT_GE(s["coverage"]["fraction"].get<double>(), 0.95);
  EXPECT_GT(s["coverage"]["blocked_made"].get<int>(), 0);
  const int of = s["margin"]["of"].get<int>();
  EXPECT_EQ(of, 50);
  EXPECT_EQ(s["margin"]["inner_pot"].get<int>(), of);
  EXPECT_EQ(s["margin"]["outer_miss"].get<int>(), of);
  for (const PositionRun& p : result.positions) {
    if (p.plan.status == pot::PotStatus::kOk) {
      EXPECT_TRUE(p.legal);
      EXPECT_LT(p.rest_error_m, 0.01);
    }
  }
}

}  // namespace
}  // namespace billiard::bench
