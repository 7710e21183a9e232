// bench-constants at ctest size: a few seeded banks, kicks and direct pots chosen with the pool
// set's constants drawn, executed on tables drawn from the same uncertainty.
#include "bench/constants_calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace billiard::bench {
namespace {

ConstantsCalibrationOptions Small() {
  ConstantsCalibrationOptions o;
  o.layouts = 6;
  o.tables = 24;
  o.samples = 16;
  o.confirm_samples = 128;
  return o;
}

// Over every execution of the banks and kicks, the choice's mean prediction is the rate the
// drawn tables pot at, to the sampling error of a few shots: each shot's executions share its
// geometry, so the error is that of the choices (at most 0.5 / sqrt(choices)), not of the
// executions.
TEST(ConstantsCalibration, BanksAndKicksPredictTheRateOfDrawnTables) {
  const nlohmann::json j = ConstantsCalibrationJson(RunConstantsCalibration(Small()));
  const nlohmann::json& bk = j["banks_and_kicks"];
  const int choices = bk["choices"].get<int>();
  ASSERT_GE(choices, 6);
  const double tolerance = 2 * 0.5 / std::sqrt(choices);
  EXPECT_NEAR(bk["mean_predicted_sampled"].get<double>(), bk["measured"].get<double>(), tolerance)
      << bk.dump();
  EXPECT_EQ(bk["executions"].get<int>(), choices * Small().tables);
}

// The same figures on one thread as on two.
TEST(ConstantsCalibration, IsIndependentOfTheThreadCount) {
  ConstantsCalibrationOptions o = Small();
  o.layouts = 2;
  o.kinds = {pot::ShotKind::kBank};
  o.threads = 1;
  const nlohmann::json one = ConstantsCalibrationJson(RunConstantsCalibration(o));
  o.threads = 2;
  nlohmann::json two = ConstantsCalibrationJson(RunConstantsCalibration(o));
  EXPECT_EQ(one["kinds"], two["kinds"]);
}

TEST(ConstantsCalibration, RefusesASetWithoutUncertainty) {
  ConstantsCalibrationOptions o = Small();
  o.params = "paper";
  EXPECT_THROW(RunConstantsCalibration(o), std::invalid_argument);
}

}  // namespace
}  // namespace billiard::bench
