// The table's own uncertainty: a parameter set's constants drawn within their standard
// deviations (physics::ConstantsUncertainty, the set's "uncertainty"), one draw per Monte Carlo
// sample, as the robot's execution noise is drawn per sample (execution_noise.h).
//
// Why: a plan that pots only inside a window of a few hundredths of a degree lives on one
// cushion model's exact rebound. Issue 47 measured against an independent engine (pooltool 0.6)
// that of 99 plans the planner called ok, all 39 direct pots dropped but only 16 of 21 banks and
// 30 of 37 kicks: the constants a bank depends on (the cushion's restitution and friction) are
// known only to within a spread, and a probability that ignores it is overconfident.
//
// The draw is a truncated normal: each named constant is its value plus its sd times a standard
// normal number, all drawn together and drawn again whenever the set leaves its physical range
// (physics::ValidateParameters: a restitution within [0, 1], a friction >= 0, mu above the
// rolling resistance ...). Deterministic: the numbers come from the caller's `unit_normal`, so a
// sample's own seed stream gives the same constants on any thread.
//
// Module: billiard::params.
#pragma once

#include <functional>
#include <string>

#include "sim/physics/parameters.h"

namespace billiard::params {

// The number of `p` that an uncertainty may name `key`, or nullptr: the cloth's contact
// ("contact.*"), the impacts ("collision.*") and the cue's "cue.mass", "cue.tip_restitution" and
// "cue.end_mass". The ball, the table's size and the robot's limits are not drawn: they are
// measured (the geometry the planner plans on) or set (what the robot may do).
double* ConstantByKey(physics::ModelParameters& p, const std::string& key);

// How many times a draw outside the physical range is drawn again before the set is kept as it
// is: with sds a fraction of the values, a redraw is rare and 64 in a row never happens.
inline constexpr int kMaxConstantDraws = 64;

// `p` with every constant its uncertainty names drawn as above, one `unit_normal()` per named
// constant per draw in the uncertainty's order; `p` itself when it has no uncertainty (or when
// kMaxConstantDraws draws all left the physical range). The result keeps `p`'s name and
// uncertainty.
physics::ModelParameters SampledConstants(const physics::ModelParameters& p,
                                          const std::function<double()>& unit_normal);

}  // namespace billiard::params
