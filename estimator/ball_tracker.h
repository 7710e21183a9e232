// Tracks every ball across camera frames: data association and one Kalman filter per ball.
//
// Process model: what a billiard ball does between two frames, not constant velocity.
//  - state (x, y, vx, vy, ax, ay): while a ball slides its friction force is constant (mu m g
//    against a slip direction that does not turn, Jaroukh 2019, eqs. 6-7), so constant
//    acceleration is its exact motion; while it rolls the acceleration is the small 5/7 mu_r g
//    against v;
//  - the jerk noise is that of rolling, and a maneuver test (the innovation's chi-square) opens
//    the acceleration to mu g when the phase changes (the cue strike, the end of sliding, a stop);
//  - a ball never reverses by friction: a prediction that would turn the velocity back stops the
//    ball instead, which is how a rolling ball ends;
//  - a prediction that would take the ball past a cushion's nose comes back off the cushion
//    (mirrored, the cushion's normal restitution), so that a ball refined near its prediction is
//    looked for where it bounced to, not in the rail.
// Association: the minimum-cost assignment (assignment.h) of detections to predicted positions,
// gated by how far the fastest ball moves in a frame, so that a ball struck next to others keeps
// its identity and balls passing close do not swap. A detection whose class (ball_identity.h)
// disagrees with its track's costs kClassMismatchRadii ball radii more, times the detection's
// confidence and how much less likely its class is on the track than the track's likeliest, and as
// much again times how surely another track holds its class where the set has one ball of it: two
// balls of different colours passing close keep their tracks, and the cue ball meeting a rack of
// balls no detection has yet told apart keeps its own. The association
// weighs the identities from before the frame's contacts: what decides who left an impact on
// which path is who came into it.
// Class: each track holds the probability of each class of the ball set (a discrete Bayes filter,
// the forward pass of a hidden Markov model over the ball's identity; Rabiner 1989), uniform when
// the track starts. A detection's class is evidence: a class given with confidence q is taken
// 1 / (1 - q) times likelier than another (the confidence is one less the ratio of the class's
// cost to the next best's, ball_identity.h), at most kMaxClassLikelihoodRatio. Between
// detections the identity can change without being seen:
//  - at a contact: two tracks whose balls meet (apart at the frame's start, approaching faster
//    than swap_speed, their closest approach within kContactRadii ball radii) may leave on each
//    other's paths, since the predictions from before an impact say nothing of after it; each takes
//    swap_at_contact of the other's probabilities (0.5: no telling which is which), so that the
//    next detections decide where a swap left a track on the wrong ball;
//  - slowly, at class_drift per second (a swap or a wrong class the tracker did not notice),
//    so that no history outweighs a few consistent detections.
// The track's class is the likeliest, its confidence that probability. Touching balls at rest (a
// rack) do not swap, nor blur each other's identities.
// Spin is observable only while rolling (w = z x v / r, about the horizontal); it is published with
// its variance, and with a variance of kUnobservedSpinVariance while sliding and for wz.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "estimator/ball_class.h"
#include "sim/physics/parameters.h"

namespace billiard::estimator {

inline constexpr double kUnobservedSpinVariance = 1e6;  // [(rad/s)^2]
inline constexpr double kClassMismatchRadii = 1.0;
// A detection's class confidence is read as a likelihood ratio of at most this: no single frame
// makes a track certain.
inline constexpr double kMaxClassLikelihoodRatio = 100.0;
// Balls whose centres pass within this many radii have touched (2), or nearly: near enough that
// the association may have crossed their tracks.
inline constexpr double kContactRadii = 2.2;

// What a detection says of which ball it is (ball_identity.h), and how sure the detector is that
// it is a ball at all (BallDetection::score; 0 when not given).
struct ClassEvidence {
  BallClass ball_class = BallClass::kUnknown;
  double confidence = 0;
  double score = 0;
};

struct TrackerOptions {
  double measurement_sigma = 0.5e-3;  // detector's position noise on the table [m]
  double max_speed = 8.0;             // fastest ball, for the association gate [m/s]
  double min_gate = 0.01;             // association gate for a ball at rest [m]
  int hits_to_confirm = 3;            // detections before a track is published, unless
  double sure_score = 0.8;            // its first detection scores this (published at once)
  double max_coast = 0.3;             // a track unseen for longer is dropped [s]
  double maneuver_chi2 = 13.8;        // innovation test (2 dof, 0.1 %) that opens the acceleration
  double jump_chi2 = 100.0;           // and beyond it (10 sigma) a jump: the position opens too
  // Jerk noise density [m^2/s^5]: a rolling ball's acceleration, 5/7 mu_r g against v, only
  // turns with v, and a ball at rest has none; the phase changes are left to the maneuver test.
  double jerk_density = 0.005;
  // Identity (the class filter above): the set whose classes a track may be, how much of each
  // other's identity two balls take when they meet, faster than what relative speed [m/s], and
  // the drift of an identity unobserved [1/s].
  BallSet ball_set = BallSet::kPool;
  double swap_at_contact = 0.5;
  double swap_speed = 0.05;
  double class_drift = 0.02;
};

struct TrackedBall {
  int id = 0;
  double time = 0.0;                  // of the state [s]
  Eigen::Matrix<double, 6, 1> state;  // x, y, vx, vy, ax, ay
  Eigen::Matrix<double, 6, 6> covariance;
  int hits = 0;
  double last_seen = 0.0;
  bool confirmed = false;
  BallClass ball_class = BallClass::kUnknown;
  double class_confidence = 0;
  std::vector<ClassEvidence> class_belief;  // the probability of each class of the ball set

  Eigen::Vector2d position() const { return state.head<2>(); }
  Eigen::Vector2d velocity() const { return state.segment<2>(2); }
  // The 7-vector and 7x7 covariance of ball_state_t (X, Y, vx, vy, wx, wy, wz).
  Eigen::Matrix<double, 7, 1> BallState(double radius) const;
  Eigen::Matrix<double, 7, 7> BallCovariance(double radius) const;
};

class BallTracker {
 public:
  BallTracker(const physics::ModelParameters& params, TrackerOptions options = {});

  // Advances the tracks to `time` and updates them with the balls detected then (table
  // positions at the ball-centre height) and, when given (one per detection), their classes.
  // Returns false, changing nothing, if time goes back.
  bool Update(double time, const std::vector<Eigen::Vector2d>& detections,
              const std::vector<ClassEvidence>& classes = {});

  // Where each track expects its ball at `time` (for a detector that searches near predictions).
  std::vector<Eigen::Vector2d> Predict(double time) const;

  // Every track, confirmed or not; publish the confirmed ones.
  const std::vector<TrackedBall>& tracks() const { return tracks_; }

 private:
  void Advance(TrackedBall& track, double time) const;
  // A prediction from `before` that crossed a cushion's nose (the ball's centre a radius from
  // the playing surface's edge) comes back off it with the cushion's restitution.
  void BounceOffTheCushions(const Eigen::Matrix<double, 6, 1>& before,
                            Eigen::Matrix<double, 6, 1>* after,
                            Eigen::Matrix<double, 6, 6>* covariance) const;
  void Correct(TrackedBall& track, const Eigen::Vector2d& measured) const;
  // Each track's identity once the contacts over the `dt` before its current (advanced) state
  // have mixed it with the balls it met (see the top of the file).
  std::vector<std::vector<ClassEvidence>> IdentitiesAfterContacts(double dt) const;

  physics::ModelParameters params_;
  TrackerOptions options_;
  std::vector<ClassEvidence> uniform_belief_;  // a new track's: every class of the set alike
  std::vector<TrackedBall> tracks_;
  int next_id_ = 0;
  double time_ = -1e300;
};

}  // namespace billiard::estimator
