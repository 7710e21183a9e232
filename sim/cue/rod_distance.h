// How far the placed cue's rod (placed_cue.h: the balls of radius r(s) on its axis, s in
// [0, L] from the tip, r(s) = r0 + k s) stays from a ball and from a box: > 0 the distance
// between their surfaces, < 0 they overlap (by about that much).
//
// A ball (centre C, radius R). The rod's distance to C is the least over s of
// g(s) = |A(s) - C| - r(s), A(s) the axis point. With C at s_c along the axis and rho across
// it, |A(s) - C| = sqrt((s - s_c)^2 + rho^2), and g'(s) = (s - s_c) / sqrt(...) - k vanishes at
//
//     s* = s_c + k rho / sqrt(1 - k^2),      g(s*) = rho sqrt(1 - k^2) - r0 - k s_c,
//
// where the ball touches the rod's side: the line from C to A(s*) is normal to it, tilted k
// off the perpendicular to the axis because the rod widens. g is convex (a distance to a line
// minus a linear function), so on [0, L] its least value is at s* clamped to the segment, where
// an end's rounded cap is nearest. The rod and the ball are apart by g(s*) - R. (Tested against
// sampling the axis.)
//
// A box (an axis-aligned box, a side infinite where its bound is): f(s) = d(A(s)) - r(s), d the
// signed distance to the box (the distance outside it, minus the distance to its nearest face
// inside), is convex too (d is convex for a convex set and r is linear), so its least value on
// [0, L] is found by golden-section search (Kiefer 1953) to a tenth of a nanometre of s: f
// changes by at most 1 + k per metre of s, so the value found is that close to the least.
//
// Module: billiard::cue.
#pragma once

#include <Eigen/Core>

#include "sim/cue/placed_cue.h"

namespace billiard::cue {

// lower <= upper on each axis; a bound may be infinite (a rail's box reaches down without end).
struct Box {
  Eigen::Vector3d lower, upper;
};

// The signed distance from `p` to `box`: the distance to it outside, minus the distance to its
// nearest face inside.
double SignedDistance(const Eigen::Vector3d& p, const Box& box);

// The distance between the rod's surface and the ball of `radius` at `centre` (< 0: overlap);
// with `along`, where on the axis the rod comes nearest it [m from the tip]: s* clamped.
double DistanceToBall(const PlacedCue& cue, const Eigen::Vector3d& centre, double radius,
                      double* along = nullptr);

// The distance between the rod's surface and `box` (< 0: overlap); with `along`, where on the axis
// the rod comes nearest it [m from the tip].
double DistanceToBox(const PlacedCue& cue, const Box& box, double* along = nullptr);

}  // namespace billiard::cue
