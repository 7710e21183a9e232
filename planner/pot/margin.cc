#include "planner/pot/margin.h"

#include <algorithm>
#include <cmath>

#include "planner/pot/cue_elevation.h"
#include "planner/pot/pace.h"

namespace billiard::pot {

Bracket Edge(const std::function<bool(double)>& pots, double x0, double guess, double limit,
             const EdgeSearch& how) {
  const double bracket = how.bracket;
  // A guess at x0 itself (a window of no width) brackets nothing: a small step toward the limit.
  if (!(std::abs(guess - x0) >= kSmallestEdge * std::abs(limit - x0))) {
    guess = x0 + kSmallestEdge * (limit - x0);
  }
  const auto at = [&](double fraction) {
    const double x = x0 + fraction * (guess - x0);
    return std::abs(x - x0) > std::abs(limit - x0) ? limit : x;
  };
  double in = x0, out = at(1.0 - bracket);
  if (pots(out)) {
    in = out;
    out = at(1.0 + bracket);
    if (!pots(out)) return {in, out};  // within the bracket
    double fraction = 1.0 + 4.0 * bracket;
    for (out = at(fraction); pots(out); out = at(fraction)) {  // further out until it misses
      in = out;
      if (out == limit) return {limit, limit};
      fraction *= 2.0;  // at() stops at the limit
    }
  } else if (pots(at(1.0 - 4.0 * bracket))) {  // short of the guess: a wider bracket first
    in = at(1.0 - 4.0 * bracket);
  }
  // To the resolution of the edge, or to 2^-halvings of the bracket where the edge is at x0;
  // and no further than adjacent doubles, whose midpoint rounds to one of them: a bracket a few
  // ulps wide (x0 at its limit, a pace already the cue's top speed) would otherwise be halved
  // forever, the same stroke played each time (cue_clearance_acceptance_test's seed 4719).
  const double floor = std::ldexp(std::abs(out - in), -how.halvings);
  while (std::abs(out - in) > std::max(how.resolution * std::abs(in - x0), floor)) {
    const double mid = 0.5 * (in + out);
    if (mid == in || mid == out) break;
    (pots(mid) ? in : out) = mid;
  }
  return {in, out};
}

double Margin(const Bracket& b, double centre) {
  const double in = std::abs(b.in - centre), out = std::abs(b.out - centre);
  const double margin = in / (1.0 - kMarginTolerance);
  return (1.0 + kMarginTolerance) * margin >= out - kSameHeading ? margin : in;
}

double PlayedMargin(const std::function<bool(double)>& pots, const Bracket& b, double centre) {
  const double margin = Margin(b, centre);
  const double side = b.out >= centre ? 1.0 : -1.0;
  const double beyond = centre + side * (1.0 + kMarginTolerance) * margin;
  if (margin <= 0.0 || std::abs(beyond - b.out) <= kSameHeading || !pots(beyond)) return margin;
  return std::abs(b.out - centre) / (1.0 + kMarginTolerance);
}

HeadingMargin HeadingMargins(SearchContext& search, const StrokeShape& shape, const Aimed& centre,
                             const Drop& window) {
  // Played to rest: the cue ball may scratch after K drops, as near an edge it may.
  const auto pots_heading = [&](double heading) {
    return search.Play(shape.At(heading), true).outcome.legal;
  };
  const double slope = std::isfinite(centre.slope) && std::abs(centre.slope) > 1e-9 ? centre.slope : 1.0;
  const double up = (slope > 0.0 ? window.hi - window.Middle() : window.Middle() - window.lo) / std::abs(slope);
  const double down = (slope > 0.0 ? window.Middle() - window.lo : window.hi - window.Middle()) / std::abs(slope);
  const Bracket left = Edge(pots_heading, centre.heading, centre.heading + up, centre.heading + 0.5 * M_PI,
                            kHeadingEdge);
  const Bracket right = Edge(pots_heading, centre.heading, centre.heading - down, centre.heading - 0.5 * M_PI,
                             kHeadingEdge);
  HeadingMargin margin;
  margin.left = PlayedMargin(pots_heading, left, centre.heading);
  margin.right = PlayedMargin(pots_heading, right, centre.heading);
  return margin;
}

SpeedWindow SpeedWindowAt(SearchContext& search, const StrokeShape& shape, double heading) {
  const auto pots_speed = [&](double speed) {
    StrokeShape s = shape;
    s.speed = speed;
    return search.Play(s.At(heading), false, false).outcome.legal;
  };
  const double top = TopCueSpeed(search, shape, heading);
  // The slowest: where the pace's fit brings K to the capture line at no speed; the fastest
  // often the cue's top speed.
  const double slowest = SlowestPottingSpeed(search.pace_fit(), shape.speed);
  SpeedWindow window;
  window.lo = Edge(pots_speed, shape.speed, std::max(kSlowestCue, slowest), kSlowestCue, kSpeedEdge).in;
  window.hi = pots_speed(top) ? top
                              : Edge(pots_speed, shape.speed, std::min(top, 1.25 * shape.speed), top,
                                     kSpeedEdge).in;
  return window;
}

}  // namespace billiard::pot
