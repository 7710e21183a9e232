#include "estimator/ball_tracker.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "estimator/assignment.h"

namespace billiard::estimator {

namespace {

// How much a detection's class disagrees with its track's: how much less likely the track holds
// the detection's class than its likeliest, times the detection's confidence; 0 when either is
// unknown. Two tracks whose identities a contact left even cost the same either way, so that
// their positions decide.
double ClassMismatch(const TrackedBall& track, const ClassEvidence& detection) {
  if (track.ball_class == BallClass::kUnknown || detection.ball_class == BallClass::kUnknown) {
    return 0.0;
  }
  double probability = 0.0;
  for (const ClassEvidence& c : track.class_belief) {
    if (c.ball_class == detection.ball_class) probability = c.confidence;
  }
  return (track.class_confidence - probability) * detection.confidence;
}

// How surely another track than `track` (an index of `tracks`) holds `detection`'s class, when the
// set has one ball of it (the cue ball, a numbered ball): the largest probability of the class on
// a confirmed other track, times the detection's confidence. A cue ball seen beside racked balls
// it cannot yet be told from by their tracks' beliefs is still the cue ball's track's.
double HeldByAnother(const std::vector<TrackedBall>& tracks, std::size_t track,
                     const ClassEvidence& detection, BallSet set) {
  if (detection.ball_class == BallClass::kUnknown || CountIn(set, detection.ball_class) != 1) {
    return 0.0;
  }
  double held = 0.0;
  for (std::size_t k = 0; k < tracks.size(); ++k) {
    if (k == track || !tracks[k].confirmed) continue;
    for (const ClassEvidence& c : tracks[k].class_belief) {
      if (c.ball_class == detection.ball_class) held = std::max(held, c.confidence);
    }
  }
  return held * detection.confidence;
}

// The track's class: its likeliest, unknown while no class is likelier than every other (a
// track no detection has yet named).
void TakeLikeliestClass(TrackedBall* track) {
  track->ball_class = BallClass::kUnknown;
  track->class_confidence = 0;
  double runner_up = 0;
  for (const ClassEvidence& c : track->class_belief) {
    if (c.confidence > track->class_confidence) {
      runner_up = track->class_confidence;
      track->ball_class = c.ball_class;
      track->class_confidence = c.confidence;
    } else {
      runner_up = std::max(runner_up, c.confidence);
    }
  }
  if (!(track->class_confidence > runner_up)) {
    track->ball_class = BallClass::kUnknown;
    track->class_confidence = 0;
  }
}

// Bayes' rule, with the detection's class as the evidence (the likelihood ratio at the top of
// ball_tracker.h).
void AddClassEvidence(const ClassEvidence& detection, TrackedBall* track) {
  if (detection.ball_class == BallClass::kUnknown || !(detection.confidence > 0)) return;
  const double ratio =
      std::min(1.0 / std::max(1.0 - detection.confidence, 0.0), kMaxClassLikelihoodRatio);
  double total = 0;
  for (ClassEvidence& c : track->class_belief) {
    if (c.ball_class == detection.ball_class) c.confidence *= ratio;
    total += c.confidence;
  }
  for (ClassEvidence& c : track->class_belief) c.confidence /= total;
  TakeLikeliestClass(track);
}

// A belief moved `weight` of the way to another (over the same classes in the same order).
std::vector<ClassEvidence> Blend(std::vector<ClassEvidence> belief,
                                 const std::vector<ClassEvidence>& toward, double weight) {
  for (std::size_t k = 0; k < belief.size(); ++k) {
    belief[k].confidence += weight * (toward[k].confidence - belief[k].confidence);
  }
  return belief;
}

// Whether two balls met over the last `dt`, their relative motion taken as straight: apart at its
// start, closing faster than `closing_speed`, their centres passing within `contact`. Balls still
// touching after they met, or pushed along in a cluster, have met once already.
bool Met(const TrackedBall& a, const TrackedBall& b, double dt, double contact,
         double closing_speed) {
  const Eigen::Vector2d end = a.position() - b.position();
  const Eigen::Vector2d travel = (a.velocity() - b.velocity()) * dt;
  const Eigen::Vector2d start = end - travel;
  if (start.norm() < contact || -start.dot(travel) <= closing_speed * dt * start.norm()) {
    return false;
  }
  const double s = std::min(-start.dot(travel) / travel.squaredNorm(), 1.0);
  return (start + s * travel).norm() < contact;
}

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

// Constant-acceleration transition and the white-jerk process noise over dt, per axis.
void Transition(double dt, double jerk_density, Matrix6* f, Matrix6* q) {
  Eigen::Matrix3d f1, q1;
  f1 << 1, dt, 0.5 * dt * dt, 0, 1, dt, 0, 0, 1;
  const double dt2 = dt * dt, dt3 = dt2 * dt;
  q1 << dt3 * dt2 / 20, dt2 * dt2 / 8, dt3 / 6, dt2 * dt2 / 8, dt3 / 3, dt2 / 2, dt3 / 6, dt2 / 2,
      dt;
  q1 *= jerk_density;
  // State order x, y, vx, vy, ax, ay: axis k holds entries k, k + 2, k + 4.
  f->setZero();
  q->setZero();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 2; ++k) {
        (*f)(2 * i + k, 2 * j + k) = f1(i, j);
        (*q)(2 * i + k, 2 * j + k) = q1(i, j);
      }
    }
  }
}

}  // namespace

Eigen::Matrix<double, 7, 1> TrackedBall::BallState(double radius) const {
  Eigen::Matrix<double, 7, 1> s;
  const Eigen::Vector2d v = velocity();
  s << state[0], state[1], v.x(), v.y(), -v.y() / radius, v.x() / radius, 0.0;
  return s;
}

Eigen::Matrix<double, 7, 7> TrackedBall::BallCovariance(double radius) const {
  Eigen::Matrix<double, 7, 7> c = Eigen::Matrix<double, 7, 7>::Zero();
  c.topLeftCorner<4, 4>() = covariance.topLeftCorner<4, 4>();
  // Rolling (acceleration well below the sliding mu g): w_xy = z x v / r.
  const bool rolling = state.tail<2>().norm() < 0.3;
  if (rolling) {
    Eigen::Matrix<double, 2, 4> j = Eigen::Matrix<double, 2, 4>::Zero();
    j(0, 3) = -1.0 / radius;
    j(1, 2) = 1.0 / radius;
    c.block<2, 4>(4, 0) = j * covariance.topLeftCorner<4, 4>();
    c.block<4, 2>(0, 4) = c.block<2, 4>(4, 0).transpose();
    c.block<2, 2>(4, 4) = j * covariance.topLeftCorner<4, 4>() * j.transpose();
  } else {
    c(4, 4) = c(5, 5) = kUnobservedSpinVariance;
  }
  c(6, 6) = kUnobservedSpinVariance;
  return c;
}

BallTracker::BallTracker(const physics::ModelParameters& params, TrackerOptions options)
    : params_(params), options_(options) {
  const std::vector<BallClass> classes = ClassesIn(options_.ball_set);
  for (BallClass c : classes) uniform_belief_.push_back({c, 1.0 / classes.size()});
}

std::vector<std::vector<ClassEvidence>> BallTracker::IdentitiesAfterContacts(double dt) const {
  const double contact = kContactRadii * params_.ball.radius;
  std::vector<std::vector<ClassEvidence>> mixed;
  for (const TrackedBall& a : tracks_) {
    std::vector<const TrackedBall*> met;
    for (const TrackedBall& b : tracks_) {
      if (&a != &b && Met(a, b, dt, contact, options_.swap_speed)) met.push_back(&b);
    }
    // Each ball met leaves `swap_at_contact` of a chance to be on this track; several at once
    // share it, up to an even chance among all of them.
    const double n = static_cast<double>(met.size());
    std::vector<ClassEvidence> belief = a.class_belief;
    for (const TrackedBall* b : met) {
      belief = Blend(belief, b->class_belief, 2.0 * options_.swap_at_contact / (n + 1.0));
    }
    mixed.push_back(std::move(belief));
  }
  return mixed;
}

void BallTracker::Advance(TrackedBall& t, double time) const {
  const double dt = time - t.time;
  if (dt <= 0.0) return;
  Matrix6 f, q;
  Transition(dt, options_.jerk_density, &f, &q);
  const Eigen::Vector2d v0 = t.velocity();
  Vector6 s = f * t.state;
  // Friction stops a ball, it never turns it back.
  const Eigen::Vector2d v1 = s.segment<2>(2);
  if (v0.squaredNorm() > 0.0 && v1.dot(v0) < 0.0) {
    const Eigen::Vector2d a = t.state.tail<2>();
    const double stop = std::clamp(-v0.dot(a) > 0.0 ? v0.squaredNorm() / -v0.dot(a) : dt, 0.0, dt);
    s.head<2>() = t.state.head<2>() + v0 * stop + 0.5 * a * stop * stop;
    s.tail<4>().setZero();
  }
  t.covariance = f * t.covariance * f.transpose() + q;
  BounceOffTheCushions(t.state, &s, &t.covariance);
  t.state = s;
  t.time = time;
}

void BallTracker::BounceOffTheCushions(const Eigen::Matrix<double, 6, 1>& before,
                                       Eigen::Matrix<double, 6, 1>* after,
                                       Eigen::Matrix<double, 6, 6>* covariance) const {
  const double r = params_.ball.radius, e = params_.collision.cushion_restitution;
  const double size[2] = {params_.table.length, params_.table.width};
  for (int k = 0; k < 2; ++k) {
    const double lo = r, hi = size[k] - r;
    Vector6& x = *after;
    double limit;
    if (x[k] < lo && before[k] >= lo && x[k + 2] < 0) {
      limit = lo;
    } else if (x[k] > hi && before[k] <= hi && x[k + 2] > 0) {
      limit = hi;
    } else {
      continue;
    }
    // Mirrored at the nose, the part of the path past it shortened by the restitution; the
    // acceleration (friction against the motion) turns with the velocity.
    x[k] = limit + e * (limit - x[k]);
    x[k + 2] *= -e;
    x[k + 4] *= -1.0;
    Vector6 j = Vector6::Ones();
    j[k] = j[k + 2] = -e;
    j[k + 4] = -1.0;
    *covariance = j.asDiagonal() * *covariance * j.asDiagonal();
  }
}

void BallTracker::Correct(TrackedBall& t, const Eigen::Vector2d& measured) const {
  const double r2 = options_.measurement_sigma * options_.measurement_sigma;
  const Eigen::Vector2d innovation = measured - t.position();
  const auto chi2 = [&] {
    const Eigen::Matrix2d s = t.covariance.topLeftCorner<2, 2>() + r2 * Eigen::Matrix2d::Identity();
    return innovation.dot(s.ldlt().solve(innovation));
  };
  const double surprise = chi2();
  if (surprise > options_.maneuver_chi2) {
    // A phase change: the acceleration opens to the sliding friction, and the velocity as far as
    // the innovation needs. A gradual one (the end of sliding, a stop) is then learnt over the
    // next frames. A jump (a strike, a collision, a cushion: beyond jump_chi2) has moved the ball
    // by the velocity's change times the time since it was last seen, so the position opens with
    // the velocity, fully correlated: the ball is where it is seen, moving as fast as it had to
    // go there. Opening the velocity alone left a long-still ball's tight position to follow by
    // a fraction of the jump (a racked ball 25 mm behind itself after the break at 30 Hz); the
    // jump's model for every maneuver would take a false alarm's noise over a 120 Hz frame for a
    // change of 0.2 m/s.
    const double dt = std::max(t.time - t.last_seen, 1e-3);
    const double mu_g = params_.contact.mu * params_.ball.gravity;
    const double change = innovation.squaredNorm() / (dt * dt);  // velocity variance [m^2/s^2]
    const Eigen::Matrix2d i2 = Eigen::Matrix2d::Identity();
    if (surprise > options_.jump_chi2) {
      t.covariance.block<2, 2>(0, 0) += change * dt * dt * i2;
      t.covariance.block<2, 2>(0, 2) += change * dt * i2;
      t.covariance.block<2, 2>(2, 0) += change * dt * i2;
    }
    t.covariance.block<2, 2>(2, 2) += change * i2;
    t.covariance.block<2, 2>(4, 4) += mu_g * mu_g * i2;
  }
  const Eigen::Matrix2d s = t.covariance.topLeftCorner<2, 2>() + r2 * Eigen::Matrix2d::Identity();
  const Eigen::Matrix<double, 6, 2> gain =
      t.covariance.leftCols<2>() * s.inverse();  // P H^T S^-1, H = [I 0 0]
  t.state += gain * innovation;
  // Joseph form: stays symmetric positive definite through the stiff maneuver updates.
  Matrix6 i_kh = Matrix6::Identity();
  i_kh.leftCols<2>() -= gain;
  t.covariance = i_kh * t.covariance * i_kh.transpose() + r2 * gain * gain.transpose();
}

std::vector<Eigen::Vector2d> BallTracker::Predict(double time) const {
  std::vector<Eigen::Vector2d> predicted;
  for (TrackedBall t : tracks_) {
    Advance(t, time);
    predicted.push_back(t.position());
  }
  return predicted;
}

bool BallTracker::Update(double time, const std::vector<Eigen::Vector2d>& detections,
                         const std::vector<ClassEvidence>& classes) {
  if (time < time_) return false;
  const double dt = tracks_.empty() ? 0.0 : time - time_;
  time_ = time;
  const double drift = 1.0 - std::exp(-options_.class_drift * dt);
  for (TrackedBall& t : tracks_) {
    Advance(t, time);
    t.class_belief = Blend(t.class_belief, uniform_belief_, drift);
  }
  std::vector<std::vector<ClassEvidence>> after_contacts = IdentitiesAfterContacts(dt);
  const auto class_of = [&](std::size_t j) {
    return j < classes.size() ? classes[j] : ClassEvidence{};
  };

  // Cost: distance to the prediction, and a disagreeing class; no pair beyond how far a ball can
  // move in the frame.
  const double gate = options_.min_gate + options_.max_speed * dt;
  Eigen::MatrixXd cost(tracks_.size(), detections.size());
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    for (std::size_t j = 0; j < detections.size(); ++j) {
      cost(i, j) = (detections[j] - tracks_[i].position()).norm() +
                   (ClassMismatch(tracks_[i], class_of(j)) +
                    HeldByAnother(tracks_, i, class_of(j), options_.ball_set)) *
                       kClassMismatchRadii * params_.ball.radius;
    }
  }
  const std::vector<int> assigned = AssignMinimumCost(cost, gate);
  std::vector<bool> used(detections.size(), false);
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    tracks_[i].class_belief = std::move(after_contacts[i]);
    TakeLikeliestClass(&tracks_[i]);
    if (assigned[i] < 0) continue;
    TrackedBall& t = tracks_[i];
    Correct(t, detections[assigned[i]]);
    AddClassEvidence(class_of(assigned[i]), &t);
    used[assigned[i]] = true;
    t.last_seen = time;
    t.confirmed = t.confirmed || ++t.hits >= options_.hits_to_confirm ||
                  class_of(assigned[i]).score >= options_.sure_score;
  }
  tracks_.erase(
      std::remove_if(tracks_.begin(), tracks_.end(),
                     [&](const TrackedBall& t) { return time - t.last_seen > options_.max_coast; }),
      tracks_.end());

  // A new ball: at rest until seen moving, its velocity open to anything a cue gives.
  const double r2 = options_.measurement_sigma * options_.measurement_sigma;
  const double mu_g = params_.contact.mu * params_.ball.gravity;
  for (std::size_t j = 0; j < detections.size(); ++j) {
    if (used[j]) continue;
    TrackedBall t;
    t.id = next_id_++;
    t.time = t.last_seen = time;
    t.state << detections[j], 0, 0, 0, 0;
    t.covariance = Matrix6::Zero();
    t.covariance.diagonal() << r2, r2, 1.0, 1.0, mu_g * mu_g, mu_g * mu_g;
    t.hits = 1;
    // A sure ball is published from its first frame (a doubted one from its first sure frame,
    // above): the hits guard against what flickers (a highlight, a cue tip), not against a ball
    // the detector has no doubt about.
    t.confirmed = options_.hits_to_confirm <= 1 || class_of(j).score >= options_.sure_score;
    t.class_belief = uniform_belief_;
    AddClassEvidence(class_of(j), &t);
    tracks_.push_back(t);
  }
  return true;
}

}  // namespace billiard::estimator
