// Step 3b of PlanShot (shot_planner.h): Levenberg-Marquardt (Levenberg 1944, Marquardt 1963, as
// Ceres Solver implements it) on (speed, heading) within the speed bounds, where Newton's method
// on the speed (newton_aim.h) does not converge: a Newton step leaves the bounds, a simulation
// fails, or kAimSteps corrections are not enough. With JacobianMethod::kSensitivities its
// Jacobian comes from the forward sensitivities of one simulation a point; with
// kCentralDifferences, from five simulations a point (Ceres alone, kept to measure the
// difference).
#pragma once

#include "planner/shot.h"

namespace billiard::planner {

// Refines `launch` (speed, heading) for at most `iterations` (none: nothing is simulated), until
// the miss is below the options' miss_tolerance; returns the iterations.
int Polish(Shot& shot, double launch[2], int iterations);

}  // namespace billiard::planner
