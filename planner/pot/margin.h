// Step 6 of a pot, the margin: how far the cue may turn either way, and between which cue speeds
// it may play, and K still drop legally.
//
// The heading margin is true throughout: each side's is the largest turn from the aim within
// which every heading on a grid of kMarginGrid (a hundredth of a degree) pots legally on the
// truth, played to rest: K in P, the cue ball's first contact K, no scratch. It is walked
// outward from the aim one grid step at a time until the first heading that does not, so that a
// hole in the window (the cue ball scratching off a jaw K rattled in from, K dropping again past
// a rail's nose) ends the margin where it begins; bracketing the edge and playing a heading on
// either side of it (0.9 and 1.1 of the margin, as the margin was found until issue 47) leaves
// such holes inside. A plan's walk costs one simulation per grid step of its margins, and most
// margins are a few hundredths of a degree. The speed window is the search's, to 10 %, at the
// search's aim.
#pragma once

#include <cmath>
#include <functional>

#include "planner/pot/search_context.h"

namespace billiard::pot {

// The grid the heading margin is walked on [rad]: issue 47's acceptance asks every heading a
// hundredth of a degree apart inside the margin to pot, and that is ten times finer than the
// robot's heading noise (0.1 degree, README "The cue"), so a heading the robot can be off by
// falls between two headings played no more than 0.005 degree from one. A margin below one step
// is 0: the aim alone is known to pot (the truth plays it), and such a pot is as fragile as
// today's of a few thousandths of a degree; the plan is kept and ranks last on its margin.
inline constexpr double kMarginGrid = 0.01 * kDegree;
// The farthest a heading margin is walked either way [rad]: a quarter turn, which ends the walk
// whatever the table does (bench-pot's widest margins are a few degrees).
inline constexpr double kMarginLimit = 0.5 * M_PI;

// The largest turn n * step [rad] from `centre` toward `side` (+1: left, counterclockwise; -1:
// right) for which `pots` holds at centre + side * j * step for each j = 1 .. n, walked outward
// until the first heading for which it does not, no farther than `limit`.
// With a `stride` above 1 only every stride-th heading is played on the way out, and the edge
// between the last that pots and the first that does not is found by bisection on the grid: the
// same n unless a hole narrower than a stride lies inside the window (it is stepped over), for
// about n / stride + log2(stride) plays instead of n + 1.
double WalkedMargin(const std::function<bool(double)>& pots, double centre, double side,
                    double step = kMarginGrid, double limit = kMarginLimit, int stride = 1);

// The cue's turns [rad] either way (left: counterclockwise) from the truth's aim `centre` within
// which every heading of the grid pots legally on the truth, played to rest with `shape`; walked
// as the search's options ask (PotOptions::margin_cap, margin_stride; in full by default).
struct HeadingMargin {
  double left = 0.0, right = 0.0;
};
HeadingMargin HeadingMargins(SearchContext& search, const StrokeShape& shape, double centre);

// The last x from x0 toward `guess` (a predicted edge), at most `limit`, for which `pots` holds
// and the first beyond it that misses (both `limit` where it still pots there): the guess's own
// bracket (`how.bracket` of it either side) where the edge lies in it, else found by bisection
// until the two are within `how.resolution` of the inside's distance from x0, or within
// 2^-how.halvings of the bracket (an edge at x0 itself), or are neighbouring numbers. The speed
// window's edges.
struct EdgeSearch {
  double bracket, resolution;
  int halvings;
};
// A speed edge is told to 10 % (it is what the robot's speed may be off by, not what it aims
// with), one at the plan's own speed (a fragile pot) to 1/64 of its bracket.
inline constexpr EdgeSearch kSpeedEdge{0.1, 0.1, 6};
// An edge's first guess is at least this fraction of the way to its limit.
inline constexpr double kSmallestEdge = 1e-4;
struct Bracket {
  double in, out;
};
Bracket Edge(const std::function<bool(double)>& pots, double x0, double guess, double limit,
             const EdgeSearch& how);

// The cue speeds [m/s] between which the search's stroke (`shape` at `heading`) pots, each
// played until K's fate is decided: the slowest from the pace's fit, the fastest often the cue's
// top speed.
struct SpeedWindow {
  double lo = 0.0, hi = 0.0;
};
SpeedWindow SpeedWindowAt(SearchContext& search, const StrokeShape& shape, double heading);

}  // namespace billiard::pot
