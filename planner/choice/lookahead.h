// The lookahead's closed-form estimate of how easy a pot looks, for the value of the table a
// shot leaves, the ball-in-hand screening and the easiest-looking baseline: no planning inside
// a sample.
//
// Module: billiard::choice.
#pragma once

#include <vector>

#include "sim/params/execution_noise.h"
#include "sim/rules/rules.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::choice {

// The probability that a straight ghost-ball pot of `ball` in `pocket` from the cue ball drops
// under `noise`'s heading error: 0 when a ball lies across either line or the cut is past
// max_cut_deg; else erf(d / (sqrt 2 sigma)), d the heading tolerance. The object ball may leave
// its line by the pocket's half-width less a radius (foreshortened by the angle it enters at)
// over its distance to the pocket, and a heading error e of the cue ball, a distance D from
// the ghost ball, turns the object ball by e D / (2 r cos cut) (the line of centres moves
// sideways by e D on a ball of reach 2 r cos cut). It ignores throw, squirt and speed: a ranking,
// not the truth.
double EasyPotEstimate(double radius, const std::vector<table::SceneBall>& balls, int ball,
                       const table::Pocket& pocket, const params::ExecutionNoise& noise,
                       double max_cut_deg = 80.0);

// The best EasyPotEstimate over the legal targets and pockets of `balls` (1 when the rack is
// over: no object ball left, or under nine-ball the 9 gone; rules::Ruleset::RackOver).
double BestNextShotValue(const table::TableGeometry& table, double radius,
                         const std::vector<table::SceneBall>& balls, rules::Rules rules,
                         const params::ExecutionNoise& noise);

}  // namespace billiard::choice
