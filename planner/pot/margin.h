// Step 6 of a pot, the margin: how far the cue may turn either way, and between which cue speeds
// it may play, and K still drop legally.
//
// Each heading edge is found on the truth, each heading played to rest (the cue ball may scratch
// after K drops, as near an edge it may): bracketed kMarginTolerance either side of the drop
// window's edge mapped through d departure / d heading, else by bisection until the heading that
// misses is within 1.2 times the turn of the one that pots. The margin is that potting turn / 0.9:
// 0.9 of it is a heading played that pots, 1.1 of it the one played that misses where the edge
// was in the first bracket, else played too; where it pots (a hole in the window near a jaw), the
// margin is the missing turn / 1.1 (what the acceptance checks, and no more: the edges are not
// located to a few per cent). The speed window is the search's, to 10 %, at the search's aim.
#pragma once

#include <functional>

#include "planner/pot/aim.h"
#include "planner/pot/drop_window.h"
#include "planner/pot/search_context.h"

namespace billiard::pot {

// The heading margin is what the truth says to kMarginTolerance: 1 - kMarginTolerance of it pots
// and 1 + kMarginTolerance misses. Each edge is bracketed between a heading that pots and one
// that misses, kHeadingEdge.bracket either side of the edge predicted, and where the prediction is off
// by bisection until the outside is within kHeadingEdge.resolution of the inside (beyond the inside by
// less than (1 + 0.1) / (1 - 0.1) = 1.22: a margin lies between them, 0.9 of it inside, 1.1 of
// it outside). The bracket about the prediction is as wide as the tolerance, so that where the
// edge lies in it the margin's 1 - and 1 + kMarginTolerance are the two headings played. The
// speed window more coarsely (it is what the robot's speed may be off by, not what it aims with).
inline constexpr double kMarginTolerance = 0.1;
// Headings closer than this are the same heading played [rad].
inline constexpr double kSameHeading = 1e-12;
// An edge's search: the bracket about its prediction, the resolution the bisection goes to and
// how often at most it halves (an edge at the aim itself). A speed edge at the plan's own speed
// (a fragile pot) is told to 1/64 of its bracket, a heading edge, which the margin is, to 1/4096.
struct EdgeSearch {
  double bracket, resolution;
  int halvings;
};
inline constexpr EdgeSearch kHeadingEdge{kMarginTolerance, 0.2, 12};
inline constexpr EdgeSearch kSpeedEdge{0.1, 0.1, 6};
// An edge's first guess is at least this fraction of the way to its limit.
inline constexpr double kSmallestEdge = 1e-4;

// The last x from x0 toward `guess` (a predicted edge), at most `limit`, for which `pots` holds
// and the first beyond it that misses (both `limit` where it still pots there): the guess's own
// bracket (`how.bracket` of it either side) where the edge lies in it, else found by
// bisection until the two are within `how.resolution` of the inside's distance from x0 (or are
// neighbouring numbers).
struct Bracket {
  double in, out;
};
Bracket Edge(const std::function<bool(double)>& pots, double x0, double guess, double limit,
             const EdgeSearch& how);

// The heading margin [rad] from a bracket of its edge about `centre`: the one of which
// 1 - kMarginTolerance is the inside, a heading played (near a jaw the window may have holes:
// what is between the aim and the inside is not all known to pot), its 1 + kMarginTolerance
// beyond the outside; or the inside where the bracket is wider than that (an edge at the aim
// itself).
double Margin(const Bracket& b, double centre);

// Margin(), its far side played: where the heading 1 + kMarginTolerance of it out still pots
// (K drops again past a hole in the window at the outside), the margin is the one whose
// 1 + kMarginTolerance is the outside, a heading played that misses.
double PlayedMargin(const std::function<bool(double)>& pots, const Bracket& b, double centre);

// The cue's turns [rad] either way (left: counterclockwise) from the truth's aim `centre` that
// still pot on the truth, played to rest with `shape`; each edge's first guess is `window`'s
// (K's departures, the truth's) mapped through the aim's d departure / d heading.
struct HeadingMargin {
  double left = 0.0, right = 0.0;
};
HeadingMargin HeadingMargins(SearchContext& search, const StrokeShape& shape, const Aimed& centre,
                             const Drop& window);

// The cue speeds [m/s] between which the search's stroke (`shape` at `heading`) pots, each
// played until K's fate is decided: the slowest from the pace's fit, the fastest often the cue's
// top speed.
struct SpeedWindow {
  double lo = 0.0, hi = 0.0;
};
SpeedWindow SpeedWindowAt(SearchContext& search, const StrokeShape& shape, double heading);

}  // namespace billiard::pot
