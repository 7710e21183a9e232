// The real roots of a polynomial of degree at most four on an interval, for the event times of
// the table: two balls on parabolic paths touch where |d(t)|^2 - (2R)^2, a quartic in t, reaches
// zero; a ball meets a straight cushion at the root of a quadratic and a circular jaw at the
// root of a quartic. A missed root lets two balls pass through each other, so the finder must
// not miss one: not at a grazing (tangent) contact, where the root is double; not when the
// leading coefficients vanish (equal accelerations make the quartic a quadratic); not when the
// coefficients span many orders of magnitude; not at the ends of the interval.
//
// Method: the derivative isolation of Yuksel 2022 ("High-Performance Polynomial Root Finding
// for Graphics", Proc. ACM Comput. Graph. Interact. Tech. 5(3), article 7, HPG 2022). The
// critical points of p (the roots of p' in the interval, found by the same method one degree
// lower, down to the linear case) cut [lo, hi] into pieces on which p is monotone; a piece whose
// ends have opposite signs holds exactly one root, found by Newton's iteration kept inside the
// piece's bracket (a bisection step whenever Newton would leave it or stops halving its step,
// as rtsafe does in Press et al. 2007, Numerical Recipes, 3rd ed., section 9.4) to full double
// precision. A piece whose ends have the same sign holds no root, so no root is missed however
// close the roots are; a double root is a critical point, where p is examined directly.
//
// Why not the quartic solver of Orellana and De Michele 2020 (ACM TOMS 46(2), article 20,
// "Algorithm 1010: Boosting efficiency in solving quartic equations with no compromise in
// accuracy"), which pooltool uses: it returns all four complex roots of a true quartic, so a
// collision finder built on it must still decide when a root's imaginary part is small enough
// to call it real (at a grazing contact the double root splits, in rounding, into a complex pair
// or two close real roots), must dispatch a vanishing leading coefficient to another solver, and
// must then select the roots in the interval. Only the real roots in [lo, hi] matter here;
// derivative isolation finds exactly those, for every degree up to four alike, and decides the
// tangent case by the value of p at the critical point instead of by an imaginary part.
//
// "Within rounding of 0" means |p(t)| <= 16 u sum_k |c_k| |t|^k (u = 2^-53): twice the bound
// 2n u of Horner's evaluation for n = 4 (Higham 2002, Accuracy and Stability of Numerical
// Algorithms, 2nd ed., section 5.1), the factor two for coefficients that carry a few rounding
// errors of their own. The coefficients are otherwise taken as exact: a caller whose c[0] comes
// from a cancellation (|d0|^2 - (2R)^2 for balls in contact) must compute it accurately.
#pragma once

#include <array>
#include <optional>

namespace billiard::table {

// p(t) = c[0] + c[1] t + c[2] t^2 + c[3] t^3 + c[4] t^4, lowest order first.
using Quartic = std::array<double, 5>;

// p(t) by Horner's rule.
double Evaluate(const Quartic& p, double t);

// The real roots of p in [lo, hi], ascending, a multiple root once; returns how many (<= 4).
// A root of even multiplicity (p touches zero without crossing) counts when |p| there is within
// rounding of 0; so does an end of the interval where |p| is within rounding of 0. Where p stays
// within rounding of 0 across a stretch, the stretch counts once, at its start.
// Throws std::invalid_argument for a coefficient or bound that is not finite, lo > hi, or p = 0.
int RootsInInterval(const Quartic& p, double lo, double hi, std::array<double, 4>* roots);

// The first t in [lo, hi] with p(t) <= 0, for p(lo) > 0: the first root where p crosses or
// touches zero (touching within rounding of 0, as above); std::nullopt if p stays positive on
// [lo, hi]. A start within rounding of zero from which p rises (a pair just separated from
// contact) is not a root; for p(lo) <= 0 the answer is lo itself.
// Throws std::invalid_argument as RootsInInterval does.
std::optional<double> FirstNonPositive(const Quartic& p, double lo, double hi);

}  // namespace billiard::table
