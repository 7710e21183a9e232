// Step 3 of a pot, the pace: the cue speed at which K crosses the capture line at the arrival
// speed (PotOptions::arrival_speed, 0.6 m/s: firm enough to drop through a slightly-off jaw,
// slow enough not to drag the cue ball into a scratch).
//
// K's kinetic energy at the pocket is the cue ball's less what friction takes by the metre, so
// the square of the arrival speed is nearly linear in the square of the cue speed: the secant
// method on the squares, the stroke re-aimed at each speed (the throw changes with it, a kick's
// rebound and a curve's bend too). Each stroke is the search's, played until K's fate is decided.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "planner/pot/aim.h"
#include "planner/pot/routes.h"
#include "planner/pot/search_context.h"

namespace billiard::pot {

// The slowest cue stroke tried [m/s].
inline constexpr double kSlowestCue = 0.05;
// The first cue speed tried on a plain pot [m/s], and the arrival speed it is matched to within.
inline constexpr double kFirstCueSpeed = 1.5;
inline constexpr double kArrivalTolerance = 0.05;

// The plain pot's pace for `route` (its ghost ball `ghost`): `shape`'s speed and `aimed` moved
// to it, K sent along `direction`; the search's pace fit updated. A refusal where K does not
// reach P at the cue's top speed or the cue ball no longer meets K first. A curve keeps the
// pace it is given, the fastest whose hop the table's motion covers (its bend grows with the pace):
// a refusal where K does not reach P at it.
std::optional<Refusal> Pace(SearchContext& search, const Route& route, const Eigen::Vector2d& ghost,
                            StrokeShape* shape, Aimed* aimed, double direction);

// The slowest cue speed that pots by `fit` (the fit made at `speed`): where it brings K to the
// capture line at no speed; 0.8 of `speed` where there is no fit.
double SlowestPottingSpeed(const PaceFit& fit, double speed);

}  // namespace billiard::pot
