#include "sim/batch/simulate_batch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "sim/physics/testing/test_support.h"

namespace billiard::batch {
namespace {

using physics::BallState;

// 100 seeded shots on the paper's ball: speeds 0.2-3 m/s, any heading, spin across the line and
// side spin up to what a cue gives, 8 s each.
std::vector<BatchShot> SeededShots() {
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> speed(0.2, 3.0), angle(-M_PI, M_PI), unit(-1.0, 1.0);
  const double r = 0.02;
  std::vector<BatchShot> shots;
  for (int i = 0; i < 100; ++i) {
    const double v = speed(rng), heading = angle(rng);
    const double w_roll = unit(rng) * 2.5 * v / r, wz = unit(rng) * 2.5 * v / r;
    shots.push_back(
        {physics::MakeBallState(0, 0, v * std::cos(heading), v * std::sin(heading),
                                -w_roll * std::sin(heading), w_roll * std::cos(heading), wz),
         8.0});
  }
  return shots;
}

TEST(SimulateBatch, BitIdenticalOnOneTwoAndFourThreadsAndToSimulate) {
  const physics::ModelParameters p = physics::testing::PaperParameters();
  const std::vector<BatchShot> shots = SeededShots();
  const physics::SimulationOptions options;
  std::vector<BallState> sequential;
  for (const BatchShot& s : shots) {
    sequential.push_back(physics::Simulate(p, s.initial, s.t_end, options).final_state);
  }
  for (int threads : {1, 2, 4}) {
    const auto results = SimulateBatch(p, shots, options, threads);
    ASSERT_EQ(results.size(), shots.size());
    for (std::size_t i = 0; i < shots.size(); ++i) {
      ASSERT_TRUE(results[i].ok()) << "shot " << i << ": " << results[i].error;
      // Bit for bit: equality of doubles, not a tolerance.
      EXPECT_EQ(results[i].value->final_state, sequential[i])
          << "shot " << i << ", " << threads << " threads";
    }
  }
}

TEST(SimulateBatch, AFailingShotSaysWhyAndTheOthersComplete) {
  const physics::ModelParameters p = physics::testing::PaperParameters();
  std::vector<BatchShot> shots = SeededShots();
  shots.resize(10);
  shots[4].initial[physics::kVx] = std::numeric_limits<double>::quiet_NaN();
  shots[7].t_end = -1.0;
  ThreadPool pool(2);
  const auto results = SimulateBatch(p, shots, {}, pool);
  for (std::size_t i = 0; i < shots.size(); ++i) {
    if (i == 4 || i == 7) {
      EXPECT_FALSE(results[i].ok()) << i;
      EXPECT_NE(results[i].error.find(i == 4 ? "non-finite" : "end time"), std::string::npos)
          << results[i].error;
    } else {
      ASSERT_TRUE(results[i].ok()) << i << ": " << results[i].error;
      EXPECT_EQ(results[i].value->final_state,
                physics::Simulate(p, shots[i].initial, shots[i].t_end).final_state);
    }
  }
}

}  // namespace
}  // namespace billiard::batch
