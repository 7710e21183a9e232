// Golden-section search (Kiefer 1953, "Sequential minimax search for a maximum"): the least of
// a unimodal function on an interval. Each step keeps the part of the bracket that holds the
// least, shrinking it by the golden ratio 0.618 with one new evaluation: the fewest evaluations
// for a bracket of a given width among searches that compare values alone (no derivative).
//
// Module: billiard::physics. The standard library alone.
#pragma once

#include <cmath>

namespace billiard::physics {

// The middle of the bracket on the least of `f` (unimodal on [lo, hi]) once `narrow(lo, hi)`
// holds for it.
template <typename Function, typename Narrow>
double GoldenSectionMinimum(const Function& f, double lo, double hi, const Narrow& narrow) {
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = hi - golden * (hi - lo), b = lo + golden * (hi - lo);
  double fa = f(a), fb = f(b);
  while (!narrow(lo, hi)) {
    if (fa < fb) {
      hi = b, b = a, fb = fa;
      a = hi - golden * (hi - lo), fa = f(a);
    } else {
      lo = a, a = b, fa = fb;
      b = lo + golden * (hi - lo), fb = f(b);
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace billiard::physics
