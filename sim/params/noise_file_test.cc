#include "sim/params/noise_file.h"

#include <gtest/gtest.h>

#include <cmath>

namespace billiard::params {
namespace {

constexpr double kDegree = M_PI / 180.0;

// A noise written in the files' form reads back as itself: every spread in its unit.
TEST(NoiseFileTest, FormattedNoiseReadsBackAsItself) {
  ExecutionNoise noise = LoadNoise("computational-pool");
  noise.name = "learned";
  noise.speed = 0.0226;
  noise.heading = 0.238 * kDegree;
  noise.tip_offset = 0.8e-3;
  const ExecutionNoise back = ParseNoise(FormatNoise(noise), "back.json");
  EXPECT_EQ(back.name, "learned");
  EXPECT_EQ(back.source, noise.source);
  EXPECT_NEAR(back.speed, 0.0226, 1e-15);
  EXPECT_NEAR(back.speed_absolute, 0.075, 1e-15);
  EXPECT_NEAR(back.heading, 0.238 * kDegree, 1e-15);
  EXPECT_NEAR(back.tip_offset, 0.8e-3, 1e-15);
  EXPECT_NEAR(back.elevation, 0.1 * kDegree, 1e-15);
}

}  // namespace
}  // namespace billiard::params
