#include "planner/pot/margin.h"

#include <algorithm>
#include <cmath>

#include "planner/pot/cue_elevation.h"
#include "planner/pot/pace.h"

namespace billiard::pot {

double WalkedMargin(const std::function<bool(double)>& pots, double centre, double side, double step,
                    double limit, int stride) {
  // Each heading from the grid's own multiple of `step` (not a running sum, which drifts).
  const auto pots_at = [&](int steps) { return pots(centre + side * steps * step); };
  int last = 0;  // the grid's last heading within the limit
  while ((last + 1) * step <= limit) ++last;
  int in = 0;    // the farthest heading known to pot, as every one before it on the way out
  int out = -1;  // the first heading played past it that does not
  while (out < 0 && in < last) {
    const int next = std::min(in + std::max(stride, 1), last);
    (pots_at(next) ? in : out) = next;
  }
  // The edge between them, where a stride stepped past it.
  while (out > in + 1) {
    const int mid = in + (out - in) / 2;
    (pots_at(mid) ? in : out) = mid;
  }
  return in * step;
}

HeadingMargin HeadingMargins(SearchContext& search, const StrokeShape& shape, double centre) {
  // Played to rest on the truth: a scratch after K drops is no legal pot.
  const auto pots_heading = [&](double heading) { return search.Play(shape.At(heading), true).outcome.legal; };
  const PotOptions& options = search.options();
  const double limit = options.margin_cap.value_or(kMarginLimit);
  return {WalkedMargin(pots_heading, centre, 1.0, kMarginGrid, limit, options.margin_stride),
          WalkedMargin(pots_heading, centre, -1.0, kMarginGrid, limit, options.margin_stride)};
}

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
