// The cue strike of one tracked shot: the stroke, the moment of the impact and where the balls
// really stood, whose simulation (shot_model.h) best reproduces the tracked balls.
//
// The cost is piecewise smooth: a small change of the strike makes or misses a collision, and a
// ball that catches up with another before it stops, or stops just short, is another shot. So
// the fit (FitStrike):
//   1. starts from the launch the samples show: the cue ball's direction and speed over its
//      first frames and the moment the line through them leaves its start; the cue speed from
//      TP A.30 (Alciatore 2004) for a centre hit, the heading corrected by the squirt of the side
//      offset tried;
//   2. scores a grid around it over the first 2 s: tip side and height in 0.2 r steps, the speed
//      0.8-1.6 times, the heading turned by up to 0.3 rad (where the cue ball meets a ball in the
//      first frames, its samples show it after that collision);
//   3. refines the best six with Ceres' Levenberg-Marquardt (central differences, bounds) over a
//      growing horizon, 2, 4 and 8 s and the whole shot (kHorizons): a continuation, since the
//      early path fixes the launch before the later cushions and collisions, whose timing the
//      launch sets, can mislead it. The best at the whole shot wins.
// The balls' starts are fitted too, within 4 mm of their first samples: the recordings round to
// a millimetre, and a millimetre of an object ball's position turns a cut by a degree, which no
// strike can make up for.
//
// The strike as the optimiser sees it (Layout, ToVector, FromVector), its bounds and difference
// steps are here too: the joint fit of the constants (joint_fit.h) steps the same vectors.
//
// Module: billiard::shot_fit; its implementation uses Ceres' solver.
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sim/physics/parameters.h"
#include "sim/shot_fit/fit_constants.h"
#include "sim/shot_fit/shot_model.h"
#include "sim/shot_fit/tracked_shot.h"
#include "sim/table/table_geometry.h"

namespace billiard::shot_fit {

struct FitOptions {
  bool fit_elevation = false;  // else the cue is level
  bool fit_start = true;       // each object ball's start within a few mm of its first sample
  // The cue ball's too, in the strikes reported; while constants are fitted it stays where it
  // was first seen (along its line its offset is nearly the impact's time).
  bool fit_cue_start = true;
  std::vector<Constant> constants;  // fitted jointly over the shots (FitShots)
  int rounds = 1;                   // joint fits over whole shots, after the continuation
  double max_relative_sd = 0.2;     // beyond it a constant is not identifiable
  // Shots whose fit leaves an RMSE (all balls, over the horizon) above this multiple of the
  // median are left out of the constants' fit: a shot the model cannot follow (a kiss the
  // tracking lost, a double hit) would pull every constant.
  double outlier_factor = 3.0;
  int max_iterations = 40;  // of each Ceres solve and of each joint solve
};

struct ShotFit {
  std::string id;
  bool held_out = false;  // not used to fit the constants
  Strike strike;
  ShotErrors errors;
  double rmse_cue = 0.0;  // errors.rmse of the cue ball
  std::string error;      // why the shot has no fit, when it has none (then ok() is false)
  bool ok() const { return error.empty(); }
};

// The strike that best reproduces `shot` with `params`; `previous`, when given, is refined as
// one more start. Throws std::invalid_argument on a shot that cannot be simulated.
ShotFit FitStrike(const table::TableGeometry& table, const physics::ModelParameters& params,
                  const TrackedShot& shot, const FitOptions& options,
                  const std::optional<Strike>& previous = std::nullopt);

// FitStrike over the samples up to `horizon` (the errors reported over the whole shot).
ShotFit FitStrikeUpTo(const table::TableGeometry& table, const physics::ModelParameters& params,
                      const TrackedShot& shot, const FitOptions& options,
                      const std::optional<Strike>& previous,
                      double horizon = std::numeric_limits<double>::infinity());

// The horizons of the continuation [s]; the last stage is always the whole shot.
inline constexpr double kHorizons[] = {2.0, 4.0, 8.0};

// The strike as the optimiser sees it: speed, heading, tip side and height as fractions of r,
// the impact time, the elevation when fitted, and the start offsets of the balls whose starts
// are fitted (FitOptions::fit_start, fit_cue_start).
struct Layout {
  bool elevation = false;
  double radius = 0.0;
  std::vector<std::size_t> offset_balls;

  Layout(const FitOptions& options, double r, const TrackedShot& shot);
  std::size_t first_offset() const { return elevation ? 6 : 5; }
  std::size_t size() const { return first_offset() + 2 * offset_balls.size(); }
};

std::vector<double> ToVector(const Strike& s, const Layout& layout);
// The inverse of ToVector (a negative elevation read as the level cue, its bound).
Strike FromVector(const double* x, const Layout& layout);

// The steps of the central differences in a strike vector x (ToVector's order): small against
// what a camera resolves, large against the rounding of the simulation.
std::vector<double> DifferenceSteps(const Layout& layout, const std::vector<double>& x);

// The bounds of a strike vector (ToVector's order) for a shot whose impact lies in [lo, hi].
struct StrikeBounds {
  std::vector<double> lo, hi;
};
StrikeBounds BoundsOf(const Layout& layout, double impact_lo, double impact_hi);

// The impact lies between the cue ball's first sample (still) and its second (moving); a
// frame's worth of slack before, for a clock that started late.
std::pair<double, double> ImpactRange(const TrackedShot& shot);

}  // namespace billiard::shot_fit
