// Step 2 of a pot, the aim: the cue heading at which the cue ball's first contact is K and K
// leaves along a target direction, the first contact simulated.
//
// The ball-ball impact model the table uses (Alciatore, "The Illustrated Principles of Pool and
// Billiards", 2004, TP A.14: cut- and spin-induced throw) gives the contact normal that sends K
// along the target with the cue ball's state at contact; the heading moves the contact there
// (the normal turns with the heading as the departure does, less the throw's change), then the
// secant method on simulated departures brings K's direction to the target within kAimTolerance.
// Where a first guess misses K, headings kContactStep apart are tried out to kContactScan.
// Aiming through the ghost ball alone (the line of centres on the target, the throw not
// corrected) is what aiming without the impact model would do: GhostBallHeading's.
#pragma once

#include <optional>
#include <string>

#include "planner/pot/search_context.h"
#include "sim/physics/parameters.h"

namespace billiard::pot {

// The aim is refined until K leaves along the window's middle to this [rad]: 10 um at a metre, a
// thousandth of a pocket's window seen from a metre (its edges are known to 1e-3 rad). An aim left
// further off than kAimAccepted is none.
inline constexpr double kAimTolerance = 1e-5;
inline constexpr double kAimAccepted = 1e-4;
inline constexpr int kMaxAimIterations = 12;
// The first difference of the aim's residual is taken over this heading step [rad].
inline constexpr double kAimProbe = 1e-4;
// Where the first guess misses K, headings this far apart are tried out to kContactScan [rad].
inline constexpr double kContactStep = 0.1 * kDegree;
inline constexpr double kContactScan = 1.5 * kDegree;

struct Aimed {
  double heading = 0.0;
  Contact contact;
  double slope = 0.0;  // d departure / d heading
};

// The contact normal [rad] that sends K along `target` when the cue ball arrives as in `c`:
// the ball-ball impact model the simulation resolves (Alciatore TP A.14), so that the cut- and
// spin-induced throw is aimed for.
double ThrowCorrectedNormal(const physics::ModelParameters& params, const Contact& c, double target);

// The heading at which the cue ball's first contact is K and K leaves along `target` (the
// throw corrected) or, with `throw_corrected` false, the line of centres points along it
// (the ghost ball alone), from `heading`. `slope` is d departure / d heading if known (0:
// measured). std::nullopt where no heading near `heading` meets K or the aim does not converge.
std::optional<Aimed> AimAt(SearchContext& search, const StrokeShape& shape, double heading, double target,
                           bool truth, double slope, bool throw_corrected = true);

// Why no aim along a route meets K, for the search's shape and first heading: the ball the cue
// ball meets first, or none.
std::string BlockedReason(SearchContext& search, const StrokeShape& shape, double heading);

}  // namespace billiard::pot
