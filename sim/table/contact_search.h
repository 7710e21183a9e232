// When two bodies on the table meet: the contact searches of the event loop
// (`sim/table/table_simulation.h`), and the thresholds that tell a contact from a touch.
//
// A closed-form ball's centre moves on a parabola, so a contact is the first root of a
// polynomial in time, closing (FirstCrossing on `sim/table/polynomial_roots.h`): ball-ball a
// quartic, a cushion's nose line or a capture line a quadratic, a jaw's rounded nose a quartic.
// A 5-DOF ball's path is no polynomial: its contacts are found by conservative advancement
// (FirstContactByAdvancement), safe steps from the bound on how fast it can move, so none is
// skipped either. Touching bodies are judged over a short horizon: closing by their speeds or
// by their accelerations is an event at once, parting or grazing is none.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <utility>

#include "sim/physics/ball_state.h"
#include "sim/table/ball_motion.h"
#include "sim/table/polynomial_roots.h"
#include "sim/table/table_geometry.h"
#include "sim/table/table_simulation.h"

namespace billiard::table {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Two balls, or a ball and a cushion, this close are in contact: a root found to double
// precision puts them within about 1e-15 m, and a scene may place balls frozen together.
inline constexpr double kContactTolerance = 1e-9;  // [m]

// Touching bodies closing slower than this are not closing by their speed but, if at all, by
// their accelerations (a ball pushed by its own spin into one it touches).
inline constexpr double kContactSpeed = 1e-9;  // [m/s]

// Impacts slower than this are pushes, not collisions: their energy (below 1e-9 J) is nothing,
// and met as collisions they would part the bodies for a few nanoseconds each, millions of times
// while one drives the other.
inline constexpr double kSlowImpact = 1e-4;  // [m/s]

// Touching bodies that will close within this time are an event now: a root so near is within
// the rounding of the contact polynomial and could not be told from the contact itself.
inline constexpr double kContactHorizon = 1e-6;  // [s]

// The motion of a ball over tau = t - now: p(tau) = p + v tau + 1/2 a tau^2.
struct Parabola {
  Eigen::Vector2d p, v, a;
};

// A closed-form segment's motion from `now` on.
Parabola ParabolaAt(const MotionSegment& s, double now);

// |q(tau)|^2 - d^2 for q(tau) = p + v tau + 1/2 a tau^2, lowest order first.
Quartic DistanceSquaredMinus(const Parabola& q, double d);

// (q(tau) - origin) . n - offset, a quadratic.
Quartic AlongMinus(const Parabola& q, const Eigen::Vector2d& origin, const Eigen::Vector2d& n,
                   double offset);

// p'(t).
double Derivative(const Quartic& p, double t);

// q(tau).
Eigen::Vector2d PositionAt(const Parabola& q, double tau);

// The first tau in [0, window] where f reaches 0 while decreasing (`sign` = -1; +1: while
// increasing) faster than kContactSpeed (a root where the bodies graze, or touch and part, is
// none) and `accept` holds. At f(0) within `contact` of 0 (touching) or past it (overlapping)
// the way it moves is the slope at kContactHorizon (or the window's end, where a motion
// changes): touching bodies that close within it faster than kContactSpeed (f' = `speed_scale`
// times the closing speed), by their speed or their accelerations, are an event at once, so none
// passes through another. An f that is identically zero (a ball rolling along a cushion it
// touches, or two balls held together) keeps its bodies touching: no event.
template <typename Accept>
double FirstCrossing(const Quartic& f, double window, double sign, double contact,
                     double speed_scale, const Accept& accept) {
  if (sign * f[0] >= -contact) {
    const double slope = Derivative(f, std::min(kContactHorizon, window));
    if (sign * slope > speed_scale * kContactSpeed && accept(0.0)) return 0.0;
  }
  if (std::all_of(f.begin(), f.end(), [](double c) { return c == 0.0; })) return kInfinity;
  double first = kInfinity;
  std::array<double, 4> roots;
  const int n = RootsInInterval(f, 0.0, window, &roots);
  for (int k = 0; k < n; ++k) {
    if (sign * Derivative(f, roots[k]) > speed_scale * kContactSpeed && accept(roots[k])) {
      first = roots[k];
      break;
    }
  }
  // Touching or overlapping (a 5-DOF push's allowance) and parting: the event is where they turn
  // to close again (faster than kContactSpeed within kContactHorizon, as at the start: held
  // bodies, whose closing is rounding, do not turn) while still touching or overlapping: f may
  // never reach 0 from above, and no root would ever show it.
  if (sign * f[0] >= -contact) {
    const Quartic slope{f[1], 2.0 * f[2], 3.0 * f[3], 4.0 * f[4], 0.0};
    if (std::any_of(slope.begin(), slope.end(), [](double c) { return c != 0.0; })) {
      const int m = RootsInInterval(slope, 0.0, std::min(window, first), &roots);
      for (int k = 0; k < m; ++k) {
        const double later = std::min(roots[k] + kContactHorizon, window);
        if (sign * Derivative(f, later) > speed_scale * kContactSpeed &&
            sign * Evaluate(f, roots[k]) >= -contact && accept(roots[k])) {
          return roots[k];
        }
      }
    }
  }
  return first;
}

// Conservative advancement, for motions that are no polynomial (the 5-DOF model): a clearance
// whose bodies close at `closing` now can close no faster than closing + accel t (`accel` the
// bound on their relative acceleration: the distance between convex bodies has a second
// derivative of at least minus that), so no contact comes sooner than the root of
// closing t + accel t^2 / 2 = gap. A clearance that opens (closing < 0) is taken as still.
double SafeStep(double gap, double closing, double accel);

// How far a 5-DOF ball pressed against a body by its accelerations alone (side spin curving it
// into a ball it rolls past) may overlap it before the push is met: a push closes at no speed,
// so a search that stepped by the closing speed alone would step by nanoseconds while the
// bodies touch; it steps by the time this overlap takes to fill.
inline constexpr double kPushOverlap = 1e-7;  // [m]

// Overlapping bodies closing faster than this are a contact at once (FirstContactByAdvancement).
// Above kContactSpeed, so that the rounding of a held contact's closing is none.
inline constexpr double kChatterClosing = 1e-7;  // [m/s]

// Touching bodies that are not closing are passed by at least this long a step.
inline constexpr double kSmallestAdvance = 1e-9;  // [s]

// The clearance of a ball to a contact at one instant: the gap, how fast it closes, what it is.
struct Clearance {
  double gap = std::numeric_limits<double>::infinity();
  double closing = 0.0;
  EventType type = EventType::kBallBall;
  int index = -1;
};

// The safe advance from clearance c: overlapping already, the time to close by the contact
// tolerance, so that the search meets the bodies as they turn to close, slower than an impact
// (not from an overlap deeper each time); touching and not (yet) closing, the time the overlap
// allowed takes to fill (at least half of it, so that a push sliding along at full overlap is
// passed too); else the safe step to the contact.
inline double Advance(const Clearance& c, double accel) {
  if (c.gap < -kContactTolerance) {
    return std::max(SafeStep(kContactTolerance, c.closing, accel), kSmallestAdvance);
  }
  if (c.gap <= kContactTolerance) {
    const double room = std::max(c.gap + kPushOverlap, 0.5 * kPushOverlap);
    return std::max(SafeStep(room, c.closing, accel), kSmallestAdvance);
  }
  return SafeStep(c.gap, c.closing, accel);
}

// The most safe steps one search by advancement takes: near a contact each step closes a fixed
// part of the clearance, and a landing try ends most searches within a few dozen; a ball that
// slides along a body it touches steps by the time kPushOverlap takes to fill, and its search
// goes on from where it stopped (Advancement::resume) so that no one search grows without bound.
inline constexpr int kMaxAdvances = 10000;

struct Advancement {
  double time = kInfinity;  // of the contact (kInfinity: none up to the end)
  Clearance at;             // the contact met
  bool resume = false;      // no contact up to `time`, where the search stopped: go on from there
};

// The first time in [t0, t1] at which the clearance falls to kContactTolerance while closing
// faster than kSlowImpact, or to -kPushOverlap while closing at all, by safe steps (`clearance`
// returns the contact whose Advance is the least). Where that contact's closing speed promises
// it within reach, a try at twice the time it would take: when that lands past it, bisected back
// onto it (on that contact's own clearance, `element(t, c)`), and taken once safe steps over all
// contacts find none sooner.
template <typename ClearanceAt, typename ElementAt>
Advancement FirstContactByAdvancement(const ClearanceAt& clearance, const ElementAt& element,
                                      double accel, double t0, double t1, bool land = true) {
  // Overlapping already and closing at all: at once, or a ball chattering against one it drives
  // (each impact met where the last left the overlap, just above kSlowImpact) would ratchet the
  // overlap on.
  const auto contact = [](const Clearance& c) {
    return (c.gap <= kContactTolerance && c.closing > kSlowImpact) ||
           (c.gap <= -kPushOverlap && c.closing > kContactSpeed) ||
           (c.gap < -kContactTolerance && c.closing > kChatterClosing);
  };
  double t = t0;
  for (int step = 0; step < kMaxAdvances; ++step) {
    const Clearance c = clearance(t);
    if (contact(c)) return {t, c, false};
    const double reach = t + 2.0 * c.gap / c.closing;
    if (land && c.gap > kContactTolerance && c.closing > 0.0 && reach <= t1 &&
        element(reach, c).gap <= kContactTolerance) {
      double lo = t, hi = reach;
      while (hi - lo > 1e-13 * std::max(1.0, hi)) {
        const double mid = 0.5 * (lo + hi);
        (element(mid, c).gap > kContactTolerance ? lo : hi) = mid;
      }
      const Clearance at = element(hi, c);
      if (contact(at)) {
        const Advancement sooner =
            FirstContactByAdvancement(clearance, element, accel, t, lo, /*land=*/false);
        return sooner.time <= lo ? sooner : Advancement{hi, at, false};
      }
    }
    t += Advance(c, accel);
    if (t > t1) return {};
  }
  return {t, {}, true};
}

// The clearance of a ball of radius r in state s to one cushion line, jaw or capture line (an
// infinite gap where that one cannot be met: beside a capture line, far behind a cushion).
Clearance ElementClearance(const TableGeometry& table, double r, const physics::BallState& s,
                           EventType type, std::size_t k);

// The cushion, jaw or capture line of a ball of radius r in state s whose Advance (with `accel`)
// is the least (or the first one it touches while closing).
Clearance BoundaryClearance(const TableGeometry& table, double r, const physics::BallState& s,
                            double accel);

}  // namespace billiard::table
