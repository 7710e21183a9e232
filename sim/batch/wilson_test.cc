#include "sim/batch/wilson.h"

#include <gtest/gtest.h>

#include <cmath>

namespace billiard::batch {
namespace {

// Newcombe (1998, Statistics in Medicine 17: 857-872), table I, method 3 (the Wilson score
// interval): 81 of 263 gives 0.2553 to 0.3662; 15 of 148, 0.0624 to 0.1605; 0 of 20, 0 to
// 0.1611; 1 of 29, 0.0061 to 0.1718.
TEST(WilsonTest, NewcombesPublishedIntervals) {
  const struct { int k, n; double lo, hi; } cases[] = {
      {81, 263, 0.2553, 0.3662}, {15, 148, 0.0624, 0.1605}, {0, 20, 0.0, 0.1611},
      {1, 29, 0.0061, 0.1718}};
  for (const auto& c : cases) {
    const Interval i = WilsonInterval(c.k, c.n);
    EXPECT_NEAR(i.lo, c.lo, 1e-4) << c.k << "/" << c.n;
    EXPECT_NEAR(i.hi, c.hi, 1e-4) << c.k << "/" << c.n;
  }
}

// k and n - k swap the interval about 1/2; it holds k/n.
TEST(WilsonTest, SymmetricAndHoldsTheProportion) {
  for (int k = 0; k <= 12; ++k) {
    const Interval i = WilsonInterval(k, 12), j = WilsonInterval(12 - k, 12);
    EXPECT_NEAR(i.lo, 1 - j.hi, 1e-12);
    EXPECT_NEAR(i.hi, 1 - j.lo, 1e-12);
    EXPECT_LE(i.lo, k / 12.0);
    EXPECT_GE(i.hi, k / 12.0);
  }
}

TEST(WilsonTest, NoTrialsIsTheWholeRange) {
  const Interval i = WilsonInterval(0, 0);
  EXPECT_EQ(i.lo, 0.0);
  EXPECT_EQ(i.hi, 1.0);
}

}  // namespace
}  // namespace billiard::batch
