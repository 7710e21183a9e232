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
// a doubtful one waits for its hits, or for its first sure detection (a ball in the middle of a
// rack, whose outline shows more clearly from one frame's noise to the next).
TEST(BallTracker, ASureDetectionIsPublishedFromItsFirstFrame) {
  const TrackerOptions options;
  ASSERT_GE(options.hits_to_confirm, 3);
  BallTracker tracker(Pool(), options);
  const ClassEvidence sure{BallClass::kUnknown, 0.0, options.sure_score};
  const ClassEvidence doubtful{BallClass::kUnknown, 0.0, 0.99 * options.sure_score};
  const std::vector<Eigen::Vector2d> balls = {{1.0, 0.5}, {2.0, 0.8}, {1.5, 0.3}};
  ASSERT_TRUE(tracker.Update(0.0, balls, {sure, doubtful, doubtful}));
  ASSERT_EQ(tracker.tracks().size(), 3u);
  EXPECT_TRUE(tracker.tracks()[0].confirmed);
  EXPECT_FALSE(tracker.tracks()[1].confirmed);
  EXPECT_FALSE(tracker.tracks()[2].confirmed);
  ASSERT_TRUE(tracker.Update(1.0 / 30, balls, {sure, sure, doubtful}));
  EXPECT_TRUE(tracker.tracks()[1].confirmed) << "at its first sure detection";
  EXPECT_FALSE(tracker.tracks()[2].confirmed) << "doubted twice";
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
// each track on its ball.
TEST(BallTracker, ClassesKeepBallsOfDifferentColoursOnTheirTracks) {
  TrackerOptions options;
  options.hits_to_confirm = 1;
  BallTracker tracker(Pool(), options);
  const ClassEvidence three{PoolBall(3), 0.8}, cue{BallClass::kCue, 0.9};
  const Eigen::Vector2d a(1.0, 0.500), b(1.0, 0.530);  // track 0 the 3, track 1 the cue ball
  for (int f = 0; f < 5; ++f) ASSERT_TRUE(tracker.Update(f / 120.0, {a, b}, {three, cue}));
  // The 3 seen to the right and up, the cue ball to the left and down: by distance, 9.5 mm less
  // in all if track 0 took the cue ball's detection.
  ASSERT_TRUE(tracker.Update(5 / 120.0, {{0.98, 0.512}, {1.02, 0.520}}, {cue, three}));
  ASSERT_EQ(tracker.tracks().size(), 2u);
  EXPECT_GT(tracker.tracks()[0].position().x(), 1.0) << "the 3's track took the cue ball";
  EXPECT_LT(tracker.tracks()[1].position().x(), 1.0) << "the cue track took the 3";
  EXPECT_EQ(tracker.tracks()[0].ball_class, PoolBall(3));
  EXPECT_EQ(tracker.tracks()[1].ball_class, BallClass::kCue);
  for (const TrackedBall& track : tracker.tracks()) {
    EXPECT_GT(track.class_confidence, 0.75);
    EXPECT_LE(track.class_confidence, 1.0);
  }
}

// The class is Bayes' rule over the set's 16 classes, from a uniform start: a detection of class
// k at confidence q makes k 1 / (1 - q) times likelier. Two detections of the 3 at 0.8 (5x each)
// and one of the cue ball at 0.9 (10x) leave the 3 at 25 / (25 + 10 + 14), the cue ball at 10 /
// 49 and each of the other 14 classes at 1 / 49. A track no detection has named is unknown.
TEST(BallTracker, TheClassIsTheBayesPosteriorOfTheDetectionsClasses) {
  TrackerOptions options;
  options.hits_to_confirm = 1;
  options.class_drift = 0.0;
  BallTracker tracker(Pool(), options);
  const ClassEvidence three{PoolBall(3), 0.8}, cue{BallClass::kCue, 0.9}, unnamed{};
  ASSERT_TRUE(tracker.Update(0.0, {{1.0, 0.5}}, {unnamed}));
  EXPECT_EQ(tracker.tracks()[0].ball_class, BallClass::kUnknown);
  EXPECT_EQ(tracker.tracks()[0].class_confidence, 0.0);
  ASSERT_TRUE(tracker.Update(0.01, {{1.0, 0.5}}, {three}));
  ASSERT_TRUE(tracker.Update(0.02, {{1.0, 0.5}}, {three}));
  ASSERT_TRUE(tracker.Update(0.03, {{1.0, 0.5}}, {cue}));
  const TrackedBall& track = tracker.tracks()[0];
  EXPECT_EQ(track.ball_class, PoolBall(3));
  EXPECT_NEAR(track.class_confidence, 25.0 / 49.0, 1e-12);
  ASSERT_EQ(track.class_belief.size(), 16u);
  double total = 0;
  for (const ClassEvidence& c : track.class_belief) {
    const double expected = c.ball_class == PoolBall(3)       ? 25.0 / 49.0
                            : c.ball_class == BallClass::kCue ? 10.0 / 49.0
                                                              : 1.0 / 49.0;
    EXPECT_NEAR(c.confidence, expected, 1e-12) << BallClassName(c.ball_class);
    total += c.confidence;
  }
  EXPECT_NEAR(total, 1.0, 1e-12);
}

// A ball named the 5 for a minute, then seen as the cue ball (a swap the tracker did not notice):
// with the drift h = 1 - exp(-0.02/s x 1 s) between detections a second apart, a detection at
// 0.9 (10x) makes the cue ball's odds against the 5 about (h / 16) 10^n after n of them, so the
// track is the cue ball from the third (log10(16 / h) = 2.9), and a single odd detection among
// the 5's changes nothing.
TEST(BallTracker, ConsistentDetectionsOutweighAnyHistoryWithinAFewFrames) {
  TrackerOptions options;
  options.hits_to_confirm = 1;
  BallTracker tracker(Pool(), options);
  const ClassEvidence five{PoolBall(5), 0.9}, cue{BallClass::kCue, 0.9};
  double t = 0;
  for (; t < 60.0; t += 1.0) ASSERT_TRUE(tracker.Update(t, {{1.0, 0.5}}, {five}));
  ASSERT_TRUE(tracker.Update(t, {{1.0, 0.5}}, {cue}));
  t += 1.0;
  ASSERT_TRUE(tracker.Update(t, {{1.0, 0.5}}, {five}));
  t += 1.0;
  EXPECT_EQ(tracker.tracks()[0].ball_class, PoolBall(5));
  EXPECT_GT(tracker.tracks()[0].class_confidence, 0.99);
  for (int n = 1; n <= 3; ++n, t += 1.0) {
    ASSERT_TRUE(tracker.Update(t, {{1.0, 0.5}}, {cue}));
    EXPECT_EQ(tracker.tracks()[0].ball_class, n < 3 ? PoolBall(5) : BallClass::kCue) << n;
  }
}

// The cue ball rolling at 3 m/s from (0.3, 0.6), struck at 0.5 s, into the 5 at rest, full and
// stunned, `frames_to_impact` frames of 30 Hz after the strike: the cue ball stops where it meets
// the 5, which leaves at 3 m/s.
struct StunShot {
  static constexpr double kRate = 30.0, kSpeed = 3.0, kStrike = 0.5;
  explicit StunShot(double frames_to_impact)
      : impact(kStrike + frames_to_impact / kRate),
        impact_frame(static_cast<int>(std::ceil(impact * kRate))),
        object(cue_start.x() + kSpeed * (impact - kStrike) + 2.0 * Pool().ball.radius, 0.6) {}
  Eigen::Vector2d Cue(double t) const {
    return cue_start +
           Eigen::Vector2d(kSpeed * std::clamp(t - kStrike, 0.0, impact - kStrike), 0.0);
  }
  Eigen::Vector2d Object(double t) const {
    return object + Eigen::Vector2d(kSpeed * std::max(0.0, t - impact), 0.0);
  }
  const double impact;
  const int impact_frame;
  const Eigen::Vector2d cue_start{0.3, 0.6};
  const Eigen::Vector2d object;
};

// The track nearest `x`.
const TrackedBall& TrackAt(const BallTracker& tracker, const Eigen::Vector2d& x) {
  const TrackedBall* nearest = &tracker.tracks().front();
  for (const TrackedBall& t : tracker.tracks()) {
    if ((t.position() - x).norm() < (nearest->position() - x).norm()) nearest = &t;
  }
  return *nearest;
}

// The stun shot met a tenth of a frame after a frame. The cue ball's track expects it 100 mm on
// and takes the 5's detection (about 57 mm from it, the 5's track 57 mm from the cue ball's: 114
// mm in all against 180): the swap the closed loop showed, which motion alone cannot tell. The
// contact blurs both tracks' identities, so that the detector's next classes name them right at
// once.
TEST(BallTracker, AContactLeavesTheIdentitiesToTheNextDetections) {
  constexpr double kSigma = 0.4e-3;
  const StunShot shot(6.1);
  const ClassEvidence cue{BallClass::kCue, 0.95}, five{PoolBall(5), 0.95};
  for (double swap : {0.0, 0.5}) {
    TrackerOptions options;
    options.measurement_sigma = kSigma;
    options.swap_at_contact = swap;
    BallTracker tracker(Pool(), options);
    std::mt19937 rng(3);
    std::normal_distribution<double> noise(0.0, kSigma);
    const auto seen = [&](const Eigen::Vector2d& x) {
      return Eigen::Vector2d(x + Eigen::Vector2d(noise(rng), noise(rng)));
    };
    // Named in every frame until the strike, and once more, as by a full detection, 5 frames
    // after the impact.
    int cue_track = -1;
    for (int f = 0; f <= shot.impact_frame + 5; ++f) {
      const double t = f / StunShot::kRate;
      const bool named = t < StunShot::kStrike || f == shot.impact_frame + 5;
      ASSERT_TRUE(tracker.Update(
          t, {seen(shot.Cue(t)), seen(shot.Object(t))},
          named ? std::vector<ClassEvidence>{cue, five} : std::vector<ClassEvidence>{}));
      if (f == 0) cue_track = TrackAt(tracker, shot.Cue(t)).id;
      // The scene is the swap it claims: from the impact the cue ball's track follows the 5.
      if (f == shot.impact_frame) {
        ASSERT_EQ(TrackAt(tracker, shot.Object(t)).id, cue_track) << "no swap: nothing tested";
      }
    }
    ASSERT_EQ(tracker.tracks().size(), 2u);
    const double t = (shot.impact_frame + 5) / StunShot::kRate;
    const TrackedBall& on_cue = TrackAt(tracker, shot.Cue(t));
    const TrackedBall& on_five = TrackAt(tracker, shot.Object(t));
    // Without the contact's doubt, the tracks' history outweighs a detection; with it, the cue
    // ball is 10 (an even chance times 20) against the 5's 0.5 and the drift's share of the
    // other 14.
    if (swap == 0.0) {
      EXPECT_EQ(on_cue.ball_class, PoolBall(5));
      continue;
    }
    EXPECT_EQ(on_cue.ball_class, BallClass::kCue);
    EXPECT_GT(on_cue.class_confidence, 0.94);
    EXPECT_EQ(on_five.ball_class, PoolBall(5));
    EXPECT_GT(on_five.class_confidence, 0.94);
  }
}

// The stun shot met 0.65 of a frame before a frame, every frame named: by distance the tracks
// would cross at the impact (the cue ball's track expects it 65 mm on, 57 mm + 8 mm: 130 mm in all
// against 114), by the classes seen they do not. The identities weighed are those from before
// the contact, which the contact then blurs: who came into the impact decides who left it on
// which path.
TEST(BallTracker, TheClassesSeenBeforeAContactDecideWhoLeavesItOnWhichPath) {
  const StunShot shot(6.35);
  const ClassEvidence cue{BallClass::kCue, 0.95}, five{PoolBall(5), 0.95};
  BallTracker tracker(Pool());
  int cue_track = -1, five_track = -1;
  for (int f = 0; f <= shot.impact_frame + 3; ++f) {
    const double t = f / StunShot::kRate;
    ASSERT_TRUE(tracker.Update(t, {shot.Cue(t), shot.Object(t)}, {cue, five}));
    if (f == 0) {
      cue_track = TrackAt(tracker, shot.Cue(t)).id;
      five_track = TrackAt(tracker, shot.Object(t)).id;
    }
    EXPECT_EQ(TrackAt(tracker, shot.Cue(t)).id, cue_track) << "frame " << f;
    EXPECT_EQ(TrackAt(tracker, shot.Object(t)).id, five_track) << "frame " << f;
  }
  EXPECT_EQ(TrackAt(tracker, shot.Cue(shot.impact + 0.1)).ball_class, BallClass::kCue);
  EXPECT_EQ(TrackAt(tracker, shot.Object(shot.impact + 0.1)).ball_class, PoolBall(5));
}

// A rack: fifteen balls touching at rest, named once a second, and a ball rolling past it 3 radii
// from its nearest ball: no identity is blurred by balls that touch without moving, nor by one
// that passes without touching.
TEST(BallTracker, TouchingBallsAtRestAndABallPassingByKeepTheirIdentities) {
  constexpr double kRate = 30.0;
  const double r = Pool().ball.radius;
  std::vector<Eigen::Vector2d> rack;
  for (int row = 0; row < 5; ++row) {
    for (int k = 0; k <= row; ++k) {
      rack.push_back({1.9 + row * std::sqrt(3.0) * r, 0.635 + (2 * k - row) * r});
    }
  }
  std::vector<ClassEvidence> named;
  for (int number = 1; number <= 15; ++number) named.push_back({PoolBall(number), 0.6});
  named.push_back({BallClass::kCue, 0.9});
  // The cue ball along the rack's lowest balls, 3 radii below their centres.
  const double below = 0.635 - 4 * r - 3 * r;
  BallTracker tracker(Pool());
  for (int f = 0; f <= 3 * kRate; ++f) {
    const double t = f / kRate;
    std::vector<Eigen::Vector2d> seen = rack;
    seen.push_back({1.5 + 0.4 * t, below});
    ASSERT_TRUE(tracker.Update(
        t, seen, f % static_cast<int>(kRate) == 0 ? named : std::vector<ClassEvidence>{}));
  }
  ASSERT_EQ(tracker.tracks().size(), 16u);
  for (std::size_t i = 0; i < tracker.tracks().size(); ++i) {
    const TrackedBall& track = tracker.tracks()[i];
    EXPECT_EQ(track.ball_class, named[i].ball_class) << i;
    // Four detections at 0.6 (2.5x each) against fifteen other classes: 39 / (39 + 15), less the
    // drift.
    EXPECT_GT(track.class_confidence, 0.7) << i;
  }
}

}  // namespace
}  // namespace billiard::estimator
