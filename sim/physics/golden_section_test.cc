#include "sim/physics/golden_section.h"

#include <gtest/gtest.h>

#include <cmath>

namespace billiard::physics {
namespace {

const auto kNarrow = [](double lo, double hi) { return hi - lo <= 1e-12; };

TEST(GoldenSectionTest, FindsTheLeastOfAParabolaAKinkAndAnEnd) {
  EXPECT_NEAR(
      GoldenSectionMinimum([](double x) { return (x - 0.3) * (x - 0.3); }, -1.0, 2.0, kNarrow), 0.3,
      1e-6);  // a smooth least: the values near it differ below rounding
  EXPECT_NEAR(GoldenSectionMinimum([](double x) { return std::abs(x - 0.7); }, 0.0, 1.0, kNarrow),
              0.7, 1e-12);
  EXPECT_NEAR(GoldenSectionMinimum([](double x) { return 2.0 * x; }, 0.0, 1.0, kNarrow), 0.0,
              1e-12);
  EXPECT_NEAR(GoldenSectionMinimum([](double x) { return -x; }, 0.0, 1.0, kNarrow), 1.0, 1e-12);
}

// Each step shrinks the bracket by the golden ratio with one evaluation: two to start, then one
// per factor of 0.618.
TEST(GoldenSectionTest, OneEvaluationPerGoldenStep) {
  int evaluations = 0;
  const auto counted = [&](double x) {
    ++evaluations;
    return std::abs(x - 0.25);
  };
  GoldenSectionMinimum(counted, 0.0, 1.0, [](double lo, double hi) { return hi - lo <= 1e-6; });
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  EXPECT_EQ(evaluations, 2 + static_cast<int>(std::ceil(std::log(1e-6) / std::log(golden))));
}

}  // namespace
}  // namespace billiard::physics
