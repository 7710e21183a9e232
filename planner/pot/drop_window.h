// Step 4 of a pot, the drop window: the directions in which K, leaving the cue ball's contact
// with its post-impact state, still drops in P.
//
// K's velocity and spin are turned about the vertical to each direction tried and K simulated
// among the still balls until its fate is decided (SearchContext::KsFate): it drops, or a rail
// turns it away from P's mouth (a rail that turns it toward P, a bank's or one K runs along into
// the jaws, decides nothing). The window is the one holding the first direction found to drop,
// scanning out from the route's line in steps of kWindowStep; each edge is found by stepping out
// by the half-width P's opening gives seen from K, then by bisection. The plan aims at the
// window's middle, not merely anywhere that drops.
#pragma once

#include <optional>

#include "planner/pot/search_context.h"

namespace billiard::pot {

// The drop window: searched this far either side of the route's line (a bank's rebound is off
// the mirror line by a few degrees), in steps of kWindowStep, its edges found to
// kWindowResolution [rad] (kCoarseWindowResolution before the pace is known), and no wider than
// kWidestWindow.
inline constexpr double kDirectScan = 3.0 * kDegree;
inline constexpr double kRailScan = 8.0 * kDegree;
inline constexpr double kWindowStep = 0.2 * kDegree;
inline constexpr double kWindowResolution = 1e-3;
inline constexpr double kCoarseWindowResolution = 1e-3;
inline constexpr double kWidestWindow = 20.0 * kDegree;
// The object ball's least speed in the first search of its drop window [m/s]: enough to reach
// any pocket.
inline constexpr double kReachSpeed = 3.0;

struct Drop {
  double lo = 0.0, hi = 0.0;  // directions of K's departure that drop [rad]
  double Middle() const { return 0.5 * (lo + hi); }
};

// Whether K, leaving the contact along `direction` with its post-impact speed and spin times
// `scale`, drops in P among the balls still on the table.
bool Drops(SearchContext& search, const Contact& c, double direction, double scale, bool truth = false);

// The factor that brings K's post-impact speed (and spin) up to `min_speed`.
double ReachScale(const Contact& c, double min_speed = kReachSpeed);

// The directions about `route_direction` in which K drops in P: the window containing the
// first direction found to drop, scanned out to `scan` either side, its edges to `resolution`.
// K leaves at least at `min_speed` (its speed and spin scaled up): before the pace is chosen,
// the window is that of a ball that gets there. A `hint` (the window found before, coarser)
// brackets each edge from the start.
std::optional<Drop> DropWindow(SearchContext& search, const Contact& c, double route_direction, double scan,
                               double min_speed, double resolution,
                               const std::optional<Drop>& hint = std::nullopt, bool truth = false);

}  // namespace billiard::pot
