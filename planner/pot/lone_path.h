// Step 1 of a pot, the headings found on a ball's own path, alone on the table: where the rail's
// rebound and the massé's bend are the models' (Mathavan et al. 2010's cushion impact, Kudra et
// al. 2016's sliding parabola), not a mirror's or a straight line's.
//  - A kick's and a curve's first heading: the secant method on the side of the ghost ball the
//    cue ball's path passes (after the rail, for a kick).
//  - A curve too thin to search: the cut read off the path where it passes the ghost ball.
//  - A bank's line: the direction in which K, leaving the contact, passes the pocket's mouth
//    after its rail.
// Each path is the search's (search_context.h), run a stretch at a time until it has passed the
// point or the ball rests.
#pragma once

#include <Eigen/Core>
#include <limits>
#include <optional>

#include "planner/pot/routes.h"
#include "planner/pot/search_context.h"
#include "sim/physics/ball_state.h"
#include "sim/physics/cue_strike.h"

namespace billiard::pot {

// How the path of `ball` (its state and flight) alone on the table passes a point: the signed
// distance [m] at its closest approach (left of its travel > 0; infinite where it never does,
// after its rail if asked) and the ball's velocity there.
struct Passing {
  double side = std::numeric_limits<double>::infinity();
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
};
Passing Pass(SearchContext& search, const table::SceneBall& ball, const Eigen::Vector2d& point,
             bool after_rail);

// The signed distance [m] by which the cue ball's path alone on the table, struck with
// `stroke`, passes `point` (left of its travel > 0), at its closest approach.
double PassingSide(SearchContext& search, const physics::CueStroke& stroke, const Eigen::Vector2d& point,
                   bool after_rail);

// The same for a ball that starts in `state` on the cloth, alone on the table.
double PassingSide(SearchContext& search, const physics::BallState& state, const Eigen::Vector2d& point,
                   bool after_rail);

// The launch heading that sends the cue ball along its route to the ghost ball, squirt
// included (the launch leaves the cue's heading by the squirt angle).
// A kick's and a curve's heading is found on the cue ball's own path, alone on the table (the
// rail's rebound, the slide's bend): the secant method on the side of the ghost ball its path
// passes, after the rail for a kick.
double FirstHeading(SearchContext& search, const Route& route, const StrokeShape& shape,
                    const Eigen::Vector2d& ghost);

// A curve's cut read off the cue ball's path alone where it passes its ghost ball: one that
// leaves the cut beyond the cue's limit by more than the aim can change it (10 degrees) is
// refused before the aim is searched (every heading tried there is a simulation). Where the path
// does not pass the ghost ball, the aim's own scan decides.
std::optional<Refusal> CurveTooThin(SearchContext& search, const StrokeShape& shape, double heading,
                                    const Eigen::Vector2d& ghost, const Eigen::Vector2d& departure);

// The direction near `mirror` in which K, leaving the contact at the reach speed alone on the
// table, passes the pocket's mouth after its rail (or `mirror` where that is not found).
double BankLine(SearchContext& search, const Contact& c, double mirror);

}  // namespace billiard::pot
