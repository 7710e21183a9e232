// The throw of the ball-ball impact against Alciatore's published figures for pool balls.
//
// The figures are Alciatore's summary rules of thumb (from his throw experiments and the TP A.14
// analysis, "Throw" series, Billiards Digest 2006-2007, Part XI, June 2007: "everything you ever
// wanted to know about throw"), as he states them on billiards.colostate.edu:
//  - tutorial "Adjusting Aim for Throw" (billiards.colostate.edu/tutorial/throw.html), items 4
//    and 6: the maximum throw comes with slow stun shots close to and thicker than a half-ball
//    hit; slow roll shots throw about half the maximum; the maximum throw is generally about 1 inch
//    per foot of cue-ball travel, about 5 degrees; throw is small on fast shots and smaller with
//    top or bottom spin.
//  - summary "Squirt, swerve, and throw effects" (billiards.colostate.edu/faq/sidespin/aim/
//    effects/): maximum cut-induced throw (no side spin) with slow speed at about a half-ball hit;
//    maximum spin-induced throw with slow speed and about 50% side spin.
// 100% english is the tip half a radius off centre (the usual maximum, pool.json's
// max_tip_offset); english throws the object ball to the side opposite the english (left english
// throws it right: Wikipedia, "Cue sports techniques", Throw).
// "Slow", "medium" and "fast" are the 1, 3 and 7 mph of TP A.14's throw plots (0.447, 1.341 and
// 3.129 m/s, as reproduced from TP A.14 in tailuge/billiards, src/diagram/throwplot.ts).
//
// Each figure is a rounded statement, so each test accepts what rounds to it: "about 5 degrees"
// is 4.5-5.5 degrees; "about half" is nearer 1/2 than 1/4 or 3/4 (0.375-0.625); "about a
// half-ball hit" is nearer the half-ball hit (cut 30 degrees) than the quarter- or three-quarter-
// ball hit (cuts 48.6 and 14.5 degrees), i.e. cut 22.0-38.7 degrees; "about 50%" is 37.5-62.5%.
// Throw is positive when the object ball is turned towards the cue ball's path (cut shots) or
// away from the side of the english (straight shots), the directions all sources give.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/params/parameter_sets.h"
#include "sim/physics/cue_strike.h"
#include "sim/table/ball_collision.h"

namespace billiard::table {
namespace {

using physics::BallState;
using physics::kVx;
using physics::kVy;
using physics::MakeBallState;

constexpr double kDegree = M_PI / 180.0;
constexpr double kMph = 0.44704;  // [m/s]
constexpr double kSlow = 1.0 * kMph, kMedium = 3.0 * kMph, kFast = 7.0 * kMph;

// "About 5 degrees", "about half", "about a half-ball hit", "about 50%", as rounded statements.
constexpr double kMaximumThrowLow = 4.5 * kDegree, kMaximumThrowHigh = 5.5 * kDegree;
constexpr double kHalfLow = 0.375, kHalfHigh = 0.625;
const double kNearHalfBallLow = std::asin(0.375), kNearHalfBallHigh = std::asin(0.625);

physics::ModelParameters Pool() { return params::LoadParameters("pool"); }

// The cue ball (spin `w`) sliding along +x at `speed` meets an object ball at rest at the cut
// `cut` (line of centres at -cut); the throw is the object ball's heading off that line, towards
// the cue ball's path.
double CutThrow(const physics::ModelParameters& p, double cut, double speed,
                const Eigen::Vector3d& w) {
  const double r = p.ball.radius;
  const BallState cue = MakeBallState(0, 0, speed, 0, w.x(), w.y(), w.z());
  const BallState object =
      MakeBallState(2 * r * std::cos(cut), -2 * r * std::sin(cut), 0, 0, 0, 0, 0);
  const BallState after = ResolveBallBallImpact(cue, object, p.ball, p.collision).b;
  return std::atan2(after[kVy], after[kVx]) + cut;
}

double StunThrow(const physics::ModelParameters& p, double cut, double speed) {
  return CutThrow(p, cut, speed, Eigen::Vector3d::Zero());
}

// Top spin (> 0) or back spin (< 0) as the ratio R wy / v; 1 is natural roll.
double TopSpinThrow(const physics::ModelParameters& p, double cut, double speed, double ratio) {
  return CutThrow(p, cut, speed, {0.0, ratio * speed / p.ball.radius, 0.0});
}

// A straight-in shot at `speed` with `english` (1 = 100%: the tip max_tip_offset r to the right
// of centre, level cue at the centre's height), the spin as the project's cue model gives it; the
// throw is the object ball's heading to the left of the shot line.
double SpinThrow(const physics::ModelParameters& p, double english, double speed) {
  physics::CueStroke stroke;
  stroke.speed = 1.0;
  stroke.tip_side = english * p.cue.max_tip_offset * p.ball.radius;
  BallState cue = physics::StrikeBall(stroke, {0.0, 0.0}, p);
  cue.tail<5>() *= speed / cue[kVx];  // speed and spin both scale with the cue speed
  const BallState object = MakeBallState(2 * p.ball.radius, 0, 0, 0, 0, 0, 0);
  const BallState after = ResolveBallBallImpact(cue, object, p.ball, p.collision).b;
  return std::atan2(after[kVy], after[kVx]);
}

struct Peak {
  double at = 0.0, value = -1.0;
};

template <typename F>
Peak PeakOver(double from, double to, double step, F&& f) {
  Peak peak;
  for (double x = from; x <= to + 1e-12; x += step) {
    const double value = f(x);
    if (value > peak.value) peak = {x, value};
  }
  return peak;
}

Peak StunPeak(const physics::ModelParameters& p, double speed) {
  return PeakOver(0.5 * kDegree, 89.5 * kDegree, 0.5 * kDegree,
                  [&](double cut) { return StunThrow(p, cut, speed); });
}

TEST(BallBallThrow, SlowStunThrowPeaksNearAHalfBallHitAtAboutFiveDegrees) {
  const auto p = Pool();
  const Peak peak = StunPeak(p, kSlow);
  EXPECT_GE(peak.at, kNearHalfBallLow) << peak.at / kDegree;
  EXPECT_LE(peak.at, kNearHalfBallHigh) << peak.at / kDegree;
  EXPECT_GE(peak.value, kMaximumThrowLow) << peak.value / kDegree;
  EXPECT_LE(peak.value, kMaximumThrowHigh) << peak.value / kDegree;
  // No cut angle, speed or top spin throws more than the slow stun shot's maximum.
  for (double speed : {kSlow, kMedium, kFast}) {
    for (double cut_degrees = 1.0; cut_degrees < 90.0; cut_degrees += 1.0) {
      for (double ratio : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
        EXPECT_LE(TopSpinThrow(p, cut_degrees * kDegree, speed, ratio), peak.value + 1e-12)
            << speed << " m/s, cut " << cut_degrees << ", spin ratio " << ratio;
      }
    }
  }
}

TEST(BallBallThrow, StunThrowFallsOffFullerAndThinnerThanItsPeak) {
  const auto p = Pool();
  for (double speed : {kSlow, kMedium, kFast}) {
    const Peak peak = StunPeak(p, speed);
    // Rising to the peak and falling after it, a single hump.
    for (double cut = 0.5 * kDegree; cut + 0.5 * kDegree <= peak.at; cut += 0.5 * kDegree) {
      EXPECT_LT(StunThrow(p, cut, speed), StunThrow(p, cut + 0.5 * kDegree, speed))
          << speed << " m/s, cut " << cut / kDegree;
    }
    for (double cut = peak.at; cut + 0.5 * kDegree < 90.0 * kDegree; cut += 0.5 * kDegree) {
      EXPECT_GT(StunThrow(p, cut, speed), StunThrow(p, cut + 0.5 * kDegree, speed))
          << speed << " m/s, cut " << cut / kDegree;
    }
  }
}

TEST(BallBallThrow, HeadOnStunHitIsNotThrownAndNearlyFullHitsBarely) {
  const auto p = Pool();
  for (double speed : {kSlow, kMedium, kFast}) {
    EXPECT_EQ(StunThrow(p, 0.0, speed), 0.0);
    EXPECT_LT(StunThrow(p, 1.0 * kDegree, speed), 0.2 * kDegree);
  }
}

TEST(BallBallThrow, StunThrowIsLessAtFasterSpeedsOnceTheBallsSlipThroughout) {
  // Slipping throughout, the throw is atan(mu_b(v sin c)), and mu_b falls with the slip speed.
  // Fuller than that the contact points stop slipping during the impact: then the throw is
  // atan(2 tan c / (7 (1 + e))) (TP A.14), the same at every speed.
  const auto p = Pool();
  const double e = p.collision.ball_restitution;
  for (double cut_degrees : {2.0, 5.0, 10.0}) {
    const double cut = cut_degrees * kDegree;
    const double sticking = std::atan(2 * std::tan(cut) / (7 * (1 + e)));
    for (double speed : {kSlow, kMedium, kFast}) {
      EXPECT_NEAR(StunThrow(p, cut, speed), sticking, 1e-12) << speed << " m/s, " << cut_degrees;
    }
  }
  for (double cut_degrees = 30.0; cut_degrees < 90.0; cut_degrees += 5.0) {
    const double cut = cut_degrees * kDegree;
    EXPECT_GT(StunThrow(p, cut, kSlow), StunThrow(p, cut, kMedium)) << cut_degrees;
    EXPECT_GT(StunThrow(p, cut, kMedium), StunThrow(p, cut, kFast)) << cut_degrees;
  }
  const double slow = StunPeak(p, kSlow).value, medium = StunPeak(p, kMedium).value;
  const double fast = StunPeak(p, kFast).value;
  EXPECT_GT(slow, medium);
  EXPECT_GT(medium, fast);
}

TEST(BallBallThrow, FollowAndDrawLowerTheThrowAndASlowRollShotThrowsAboutHalfTheMaximum) {
  const auto p = Pool();
  for (double speed : {kSlow, kMedium, kFast}) {
    for (double cut_degrees = 10.0; cut_degrees < 90.0; cut_degrees += 10.0) {
      const double cut = cut_degrees * kDegree;
      const double stun = StunThrow(p, cut, speed);
      EXPECT_LT(TopSpinThrow(p, cut, speed, 1.0), stun) << speed << " m/s, " << cut_degrees;
      EXPECT_LT(TopSpinThrow(p, cut, speed, -1.0), stun) << speed << " m/s, " << cut_degrees;
      EXPECT_GT(TopSpinThrow(p, cut, speed, 1.0), 0.0) << speed << " m/s, " << cut_degrees;
    }
  }
  // The rule of thumb's "slow roll shot" is the half-ball hit it names for the maximum. Thinner,
  // the vertical slip R wy cos c fades and the roll shot's throw rises towards the stun shot's
  // (TP A.14's equations give the same): 0.82 of the maximum at a cut of 89.5 degrees.
  const double maximum = StunPeak(p, kSlow).value;
  const double roll = TopSpinThrow(p, 30.0 * kDegree, kSlow, 1.0);
  EXPECT_GE(roll / maximum, kHalfLow) << roll / kDegree << " of " << maximum / kDegree;
  EXPECT_LE(roll / maximum, kHalfHigh) << roll / kDegree << " of " << maximum / kDegree;
}

TEST(BallBallThrow, SideSpinThrowsAStraightShotAwayFromTheEnglishMostNearFiftyPercent) {
  const auto p = Pool();
  const auto english_peak = [&](double speed) {
    return PeakOver(0.01, 1.0, 0.01, [&](double english) { return SpinThrow(p, english, speed); });
  };
  const Peak slow = english_peak(kSlow);
  EXPECT_GE(slow.at, kHalfLow) << slow.at;
  EXPECT_LE(slow.at, kHalfHigh) << slow.at;
  EXPECT_LE(slow.value, StunPeak(p, kSlow).value + 1e-12);  // within the maximum throw
  EXPECT_GT(slow.value, english_peak(kMedium).value);
  EXPECT_GT(english_peak(kMedium).value, english_peak(kFast).value);
  // Right english throws the object ball left, left english right; no english, no throw.
  for (double english : {0.25, 0.5, 1.0}) {
    EXPECT_GT(SpinThrow(p, english, kSlow), 0.0) << english;
    EXPECT_NEAR(SpinThrow(p, -english, kSlow), -SpinThrow(p, english, kSlow), 1e-12) << english;
  }
  EXPECT_EQ(SpinThrow(p, 0.0, kSlow), 0.0);
}

}  // namespace
}  // namespace billiard::table
