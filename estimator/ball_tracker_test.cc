// The tracker on simulated shots (5-DOF model) observed with the detector's noise: accuracy
// against the ground truth, identities kept, stops and strikes followed.
#include "estimator/ball_tracker.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

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

// The constant-acceleration transition over dt and the noise a white jerk of density q adds,
// Q = q int_0^dt F(s) g g^T F(s)^T ds with g the jerk's input (0, 0, 1) per axis, in the
// tracker's state order (x, y, vx, vy, ax, ay). The integrand is a polynomial of degree 4 in s,
// which 3-point Gauss-Legendre integrates exactly.
void WhiteJerkModel(double dt, double q, Eigen::Matrix<double, 6, 6>* f,
                    Eigen::Matrix<double, 6, 6>* noise) {
  const auto axis_transition = [](double s) {
    Eigen::Matrix3d m;
    m << 1, s, 0.5 * s * s, 0, 1, s, 0, 0, 1;
    return m;
  };
  const double node = std::sqrt(0.6);
  const double nodes[] = {-node, 0.0, node}, weights[] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  Eigen::Matrix3d axis_noise = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 3; ++i) {
    const double s = 0.5 * dt * (1.0 + nodes[i]);
    const Eigen::Vector3d response = axis_transition(s).col(2);
    axis_noise += 0.5 * dt * weights[i] * q * response * response.transpose();
  }
  const Eigen::Matrix3d axis_f = axis_transition(dt);
  f->setZero();
  noise->setZero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 2; ++k) {
        (*f)(2 * i + k, 2 * j + k) = axis_f(i, j);
        (*noise)(2 * i + k, 2 * j + k) = axis_noise(i, j);
      }
    }
  }
}

// A sliding ball's friction is constant (seed 002, eqs. 6-7), so between frames the filter's
// prediction must be the constant-acceleration motion x + v dt + a dt^2 / 2 exactly, and its
// uncertainty must grow the longer it predicts without a detection.
TEST(BallTracker, PredictionIsTheConstantAccelerationMotion) {
  // Noise-free detections of a ball sliding at 1.08 m/s against its friction (mu g = 1.96 m/s^2
  // in the pool set), so that the filter holds a real acceleration.
  const Eigen::Vector2d x0(0.5, 0.4), v0(1.0, 0.4), a0 = -0.8 * v0.normalized() * 1.96;
  const auto truth = [&](double t) { return Eigen::Vector2d(x0 + v0 * t + 0.5 * a0 * t * t); };
  constexpr double kRate = 120.0;
  constexpr int kFrames = 24;
  BallTracker tracker(Pool());
  for (int f = 0; f < kFrames; ++f) ASSERT_TRUE(tracker.Update(f / kRate, {truth(f / kRate)}));
  ASSERT_EQ(tracker.tracks().size(), 1u);
  const TrackedBall start = tracker.tracks()[0];
  const double t0 = (kFrames - 1) / kRate;
  ASSERT_EQ(start.time, t0);
  const Eigen::Vector2d x = start.position(), v = start.velocity(), a = start.state.tail<2>();
  // The filter has found the motion, so a wrong a dt^2 term would show (1.6 cm after 0.2 s).
  ASSERT_LT((a - a0).norm(), 0.1 * a0.norm()) << a.transpose();

  double previous_position_variance = start.covariance(0, 0);
  double previous_velocity_variance = start.covariance(2, 2);
  for (double dt : {1.0 / kRate, 0.05, 0.1, 0.2}) {
    const Eigen::Vector2d expected = x + v * dt + 0.5 * a * dt * dt;
    // Exact up to rounding in metres.
    constexpr double kRounding = 1e-13;
    const std::vector<Eigen::Vector2d> predicted = tracker.Predict(t0 + dt);
    ASSERT_EQ(predicted.size(), 1u);
    EXPECT_LT((predicted[0] - expected).norm(), kRounding) << "dt = " << dt;
    // And near where the ball really is: the model is the ball's motion.
    EXPECT_LT((predicted[0] - truth(t0 + dt)).norm(), 1e-3) << "dt = " << dt;

    // A frame without a detection (within the coast time) advances the track by the same model.
    BallTracker coasting = tracker;
    ASSERT_TRUE(coasting.Update(t0 + dt, {}));
    ASSERT_EQ(coasting.tracks().size(), 1u);
    const TrackedBall& ahead = coasting.tracks()[0];
    EXPECT_EQ(ahead.time, t0 + dt);
    EXPECT_LT((ahead.position() - expected).norm(), kRounding) << "dt = " << dt;
    EXPECT_LT((ahead.velocity() - (v + a * dt)).norm(), kRounding) << "dt = " << dt;
    EXPECT_LT((ahead.state.tail<2>() - a).norm(), kRounding) << "dt = " << dt;
    EXPECT_EQ(ahead.hits, start.hits) << "no detection, no hit";

    // The covariance is the propagated one plus the jerk noise, so it grows with dt.
    Eigen::Matrix<double, 6, 6> f, noise;
    WhiteJerkModel(dt, TrackerOptions().jerk_density, &f, &noise);
    const Eigen::Matrix<double, 6, 6> propagated = f * start.covariance * f.transpose() + noise;
    EXPECT_LT((ahead.covariance - propagated).norm(), 1e-12 * propagated.norm())
        << "dt = " << dt << ":\n"
        << ahead.covariance << "\nexpected\n"
        << propagated;
    const double position_variance = ahead.covariance(0, 0);
    const double velocity_variance = ahead.covariance(2, 2);
    EXPECT_GT(position_variance, previous_position_variance) << "dt = " << dt;
    EXPECT_GT(velocity_variance, previous_velocity_variance) << "dt = " << dt;
    EXPECT_GT(ahead.covariance(1, 1), start.covariance(1, 1)) << "dt = " << dt;
    EXPECT_GT(ahead.covariance(3, 3), start.covariance(3, 3)) << "dt = " << dt;
    previous_position_variance = position_variance;
    previous_velocity_variance = velocity_variance;
  }
}

// Every frame, one ball at rest; frame k (from 1) is the k-th detection of it.
void ExpectConfirmedFromFrame(int hits_to_confirm) {
  TrackerOptions options;
  options.hits_to_confirm = hits_to_confirm;
  options.max_coast = 0.1;
  BallTracker tracker(Pool(), options);
  const Eigen::Vector2d ball(1.0, 0.5), flicker(2.0, 0.8);
  constexpr double kRate = 120.0;
  int frame = 0;
  const auto time = [&] { return frame / kRate; };
  for (int seen = 1; seen <= hits_to_confirm + 3; ++seen, ++frame) {
    ASSERT_TRUE(tracker.Update(time(), {ball}));
    ASSERT_EQ(tracker.tracks().size(), 1u);
    const TrackedBall& t = tracker.tracks()[0];
    EXPECT_EQ(t.id, 0);
    // (hits stops counting once the track is confirmed.)
    if (seen <= hits_to_confirm) {
      EXPECT_EQ(t.hits, seen);
    }
    EXPECT_EQ(t.confirmed, seen >= hits_to_confirm)
        << "seen " << seen << " times, confirmed after " << hits_to_confirm;
  }
  // Something seen one time too few, then gone (a reflection, a hand): never a ball, and dropped
  // once it has coasted out.
  for (int seen = 1; seen < hits_to_confirm; ++seen, ++frame) {
    ASSERT_TRUE(tracker.Update(time(), {ball, flicker}));
    ASSERT_EQ(tracker.tracks().size(), 2u);
    EXPECT_FALSE(tracker.tracks()[1].confirmed) << "flicker seen " << seen << " times";
  }
  const double gone = time();
  for (; time() <= gone + 2 * options.max_coast; ++frame) {
    ASSERT_TRUE(tracker.Update(time(), {ball}));
    for (const TrackedBall& t : tracker.tracks()) {
      EXPECT_TRUE(t.id == 0 || !t.confirmed) << "the flicker became ball " << t.id;
    }
  }
  ASSERT_EQ(tracker.tracks().size(), 1u);
  EXPECT_EQ(tracker.tracks()[0].id, 0);
  EXPECT_TRUE(tracker.tracks()[0].confirmed);
}

TEST(BallTracker, ATrackIsConfirmedAtExactlyTheConfiguredDetection) {
  EXPECT_EQ(TrackerOptions().hits_to_confirm, 3) << "the default the estimator publishes with";
  for (int hits : {1, 2, 3, 5}) {
    SCOPED_TRACE("hits_to_confirm = " + std::to_string(hits));
    ExpectConfirmedFromFrame(hits);
  }
}

// A detection the detector is sure of (score at least sure_score) is a ball from its first frame;
// a doubtful one waits for its hits.
TEST(BallTracker, ASureDetectionIsPublishedFromItsFirstFrame) {
  const TrackerOptions options;
  BallTracker tracker(Pool(), options);
  const ClassEvidence sure{BallClass::kUnknown, 0.0, options.sure_score};
  const ClassEvidence doubtful{BallClass::kUnknown, 0.0, 0.99 * options.sure_score};
  ASSERT_TRUE(tracker.Update(0.0, {{1.0, 0.5}, {2.0, 0.8}}, {sure, doubtful}));
  ASSERT_EQ(tracker.tracks().size(), 2u);
  EXPECT_TRUE(tracker.tracks()[0].confirmed);
  EXPECT_FALSE(tracker.tracks()[1].confirmed);
}

// A ball still for a second, then struck at 2 m/s between two frames at 30 Hz (it moves 67 mm
// a frame): the track is where the ball is seen from the first frame it moves, and keeps up.
// Opening only the velocity at the jump left the still ball's tight position to move by a
// fraction of it (33 mm behind in the first frame).
TEST(BallTracker, AStillBallStruckIsWhereItIsSeenFromItsFirstMovingFrame) {
  constexpr double kRate = 30.0, kStrike = 1.0, kSpeed = 2.0, kSigma = 0.4e-3;
  const Eigen::Vector2d start(0.6, 0.6), heading = Eigen::Vector2d(1.0, 0.3).normalized();
  const auto truth = [&](double t) {
    return Eigen::Vector2d(start + heading * kSpeed * std::max(0.0, t - kStrike));
  };
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, kSigma);
  TrackerOptions options;
  options.measurement_sigma = kSigma;
  BallTracker tracker(Pool(), options);
  for (int f = 0; f / kRate < kStrike + 0.5; ++f) {
    const double t = f / kRate;
    ASSERT_TRUE(tracker.Update(t, {truth(t) + Eigen::Vector2d(noise(rng), noise(rng))}));
    ASSERT_EQ(tracker.tracks().size(), 1u) << "t = " << t;
    EXPECT_LT((tracker.tracks()[0].position() - truth(t)).norm(), 2e-3) << "t = " << t;
  }
}

// A ball rolling at 1 m/s into the far end's cushion, seen at 30 Hz: the frame after the bounce
// is predicted off the cushion (mirrored, the cushion's restitution), near where the ball is, not
// past the nose in the rail (where the refinement near the prediction would outline the cushion).
TEST(BallTracker, ABallIsPredictedOffTheCushionItBouncesFrom) {
  const physics::ModelParameters& p = Pool();
  const double r = p.ball.radius, e = p.collision.cushion_restitution;
  const double nose = p.table.length - r, speed = 1.0, kRate = 30.0;
  const double bounce = 0.5;  // [s], the time the ball reaches the nose
  const auto truth = [&](double t) {
    const double x = t < bounce ? nose - speed * (bounce - t) : nose - e * speed * (t - bounce);
    return Eigen::Vector2d(x, 0.6);
  };
  BallTracker tracker(p);
  int f = 0;
  for (; (f + 1) / kRate < bounce; ++f) ASSERT_TRUE(tracker.Update(f / kRate, {truth(f / kRate)}));
  const double next = (f + 1) / kRate;
  const std::vector<Eigen::Vector2d> predicted = tracker.Predict(next);
  ASSERT_EQ(predicted.size(), 1u);
  EXPECT_LE(predicted[0].x(), nose);
  EXPECT_LT((predicted[0] - truth(next)).norm(), 3e-3)
      << "predicted " << predicted[0].transpose() << ", the ball at " << truth(next).transpose();
}

// Two balls of different colours side by side, then detected where the nearer pairing by
// position alone would give each track the other's detection (a jolt, a blur): the classes keep
// each track on its ball. Each track's class is the one its detections were mostly given, surer
// the more often.
TEST(BallTracker, ClassesKeepBallsOfDifferentColoursOnTheirTracks) {
  TrackerOptions options;
  options.hits_to_confirm = 1;
  BallTracker tracker(Pool(), options);
  const ClassEvidence red{BallClass::kRed, 0.8}, cue{BallClass::kCue, 0.9};
  const Eigen::Vector2d a(1.0, 0.500), b(1.0, 0.530);  // track 0 red, track 1 cue
  for (int f = 0; f < 5; ++f) ASSERT_TRUE(tracker.Update(f / 120.0, {a, b}, {red, cue}));
  // The red ball seen to the right and up, the cue ball to the left and down: by distance, 9.5 mm
  // less in all if track 0 took the cue ball's detection.
  ASSERT_TRUE(tracker.Update(5 / 120.0, {{0.98, 0.512}, {1.02, 0.520}}, {cue, red}));
  ASSERT_EQ(tracker.tracks().size(), 2u);
  EXPECT_GT(tracker.tracks()[0].position().x(), 1.0) << "the red track took the cue ball";
  EXPECT_LT(tracker.tracks()[1].position().x(), 1.0) << "the cue track took the red ball";
  EXPECT_EQ(tracker.tracks()[0].ball_class, BallClass::kRed);
  EXPECT_EQ(tracker.tracks()[1].ball_class, BallClass::kCue);
  for (const TrackedBall& track : tracker.tracks()) {
    EXPECT_GT(track.class_confidence, 0.75);
    EXPECT_LE(track.class_confidence, 1.0);
  }
  // A track that has been given two classes is less sure of the one it keeps.
  BallTracker doubtful(Pool(), options);
  ASSERT_TRUE(doubtful.Update(0.0, {{1.0, 0.5}}, {red}));
  ASSERT_TRUE(doubtful.Update(0.01, {{1.0, 0.5}}, {red}));
  ASSERT_TRUE(doubtful.Update(0.02, {{1.0, 0.5}}, {cue}));
  EXPECT_EQ(doubtful.tracks()[0].ball_class, BallClass::kRed);
  EXPECT_NEAR(doubtful.tracks()[0].class_confidence, 1.6 / (1.0 + 1.6 + 0.9), 1e-12);
}

}  // namespace
}  // namespace billiard::estimator
