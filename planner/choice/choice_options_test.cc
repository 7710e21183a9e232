#include "planner/choice/choice_options.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace billiard::choice {
namespace {

// The defaults are the ones the README's named steps and docs/planning.md describe.
TEST(ChoiceOptionsTest, DefaultsAreTheDocumentedOnes) {
  const ChoiceOptions o;
  EXPECT_EQ(o.rules, Rules::kAny);
  EXPECT_EQ(o.noise.name, params::LoadNoise(params::kDefaultNoise).name);
  EXPECT_EQ(o.screen_samples, 16);
  EXPECT_EQ(o.samples, 64);
  EXPECT_EQ(o.finalists, 4);
  EXPECT_EQ(o.confirm_samples, 256);
  EXPECT_EQ(o.placements, 3);
  EXPECT_TRUE(o.lookahead);
  EXPECT_EQ(o.likely, 0.5);
  EXPECT_EQ(o.kinds.size(), 4u);  // direct, bank, kick, curve
}

// The confirmation's binomial standard error, sqrt(p (1 - p) / n), is largest at p = 0.5: at
// the default n it is the 0.03 the comment gives, to the hundredth.
TEST(ChoiceOptionsTest, TheConfirmationsErrorIsWithinThreeHundredths) {
  const ChoiceOptions o;
  double worst = 0.0;
  for (double p = 0.0; p <= 1.0; p += 0.01) {
    worst = std::max(worst, std::sqrt(p * (1 - p) / o.confirm_samples));
  }
  EXPECT_NEAR(worst, 0.5 / std::sqrt(o.confirm_samples), 1e-12);
  EXPECT_EQ(std::round(100 * worst), 3);
}

}  // namespace
}  // namespace billiard::choice
