// The tracker on simulated shots (5-DOF model) observed with the detector's noise: accuracy
// against the ground truth, identities kept, stops and strikes followed.
#include "estimator/ball_tracker.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>

#include "estimator/testing/shot_scenes.h"
#include "sim/physics/simulator.h"

namespace billiard::estimator {
namespace {

using shots::Errors;
using shots::Pool;
using shots::RandomScene;
using shots::Scene;

// Runs the tracker over the scene at `rate` Hz with Gaussian detector noise.
Errors Track(const Scene& s, double duration, double rate, double sigma, unsigned seed,
             double settle = 0.3) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  TrackerOptions options;
  options.measurement_sigma = sigma;
  BallTracker tracker(Pool(), options);
  Errors e;
  e.settle = settle;
  const int frames = static_cast<int>(duration * rate);
  for (int f = 0; f < frames; ++f) {
    const double t = f / rate;
    std::vector<Eigen::Vector2d> detections;
    for (std::size_t i = 0; i < s.rest.size(); ++i) {
      detections.push_back(s.At(i, t) + Eigen::Vector2d(noise(rng), noise(rng)));
    }
    EXPECT_TRUE(tracker.Update(t, detections));
    e.Add(s, t, tracker.tracks());
  }
  return e;
}

TEST(BallTracker, SixteenBallsThreeStruckAreTrackedWithoutSwapsWithinTheBounds) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const Scene s = RandomScene(16, 3, seed, 4.0);
    const Errors e = Track(s, 4.2, 120.0, 0.4e-3, seed);
    EXPECT_EQ(e.swaps, 0) << seed;
    EXPECT_EQ(e.lost, 0) << seed;
    EXPECT_LT(shots::Rmse(e.position), 0.5e-3) << seed;
    EXPECT_LT(shots::Rmse(e.velocity), 10e-3) << seed;
    EXPECT_LT(shots::Rmse(e.moving_velocity), 10e-3) << seed;
    std::fprintf(stderr, "seed %u: position RMSE %.3f mm, velocity RMSE %.2f mm/s\n", seed,
                 1e3 * shots::Rmse(e.position), 1e3 * shots::Rmse(e.velocity));
  }
}

TEST(BallTracker, ARollingBallStopsInsteadOfTurningBack) {
  // Rolling at 0.3 m/s with the pool set's 5/7 mu_r g = 0.07 m/s^2: it stops after 4.3 s.
  const physics::ModelParameters& p = Pool();
  const double r = p.ball.radius;
  const auto rolling =
      physics::Simulate(p, physics::MakeBallState(0.5, 0.6, 0.3, 0.0, 0.0, 0.3 / r, 0.0), 8.0)
          .trajectory;
  BallTracker tracker(p);
  for (int f = 0; f <= 8 * 120; ++f) {
    const double t = f / 120.0;
    ASSERT_TRUE(tracker.Update(t, {rolling->At(t).head<2>()}));
  }
  ASSERT_EQ(tracker.tracks().size(), 1u);
  const TrackedBall& ball = tracker.tracks()[0];
  EXPECT_LT((ball.position() - rolling->At(8.0).head<2>()).norm(), 1e-4);
  EXPECT_LT(ball.velocity().norm(), 1e-3);
  // Rolling spin is observed: w = z x v / r, with a finite variance; wz is not.
  EXPECT_LT(ball.BallCovariance(r)(5, 5), 1.0);
  EXPECT_EQ(ball.BallCovariance(r)(6, 6), kUnobservedSpinVariance);
}

TEST(BallTracker, TimeGoingBackIsRefusedAndChangesNothing) {
  BallTracker tracker(Pool());
  ASSERT_TRUE(tracker.Update(1.0, {{1.0, 0.5}}));
  const auto before = tracker.tracks();
  EXPECT_FALSE(tracker.Update(0.5, {{1.2, 0.5}}));
  ASSERT_EQ(tracker.tracks().size(), before.size());
  EXPECT_EQ(tracker.tracks()[0].state, before[0].state);
}

TEST(BallTracker, AnUnseenBallIsDroppedAfterTheCoastTime) {
  TrackerOptions options;
  options.max_coast = 0.2;
  BallTracker tracker(Pool(), options);
  for (int f = 0; f < 10; ++f) tracker.Update(f / 120.0, {{1.0, 0.5}, {2.0, 0.5}});
  for (int f = 10; f < 40; ++f) tracker.Update(f / 120.0, {{1.0, 0.5}});
  ASSERT_EQ(tracker.tracks().size(), 1u);
  EXPECT_LT((tracker.tracks()[0].position() - Eigen::Vector2d(1.0, 0.5)).norm(), 1e-9);
}

}  // namespace
}  // namespace billiard::estimator
