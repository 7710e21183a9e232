#include "sim/batch/wilson.h"

#include <algorithm>
#include <cmath>

namespace billiard::batch {

Interval WilsonInterval(int successes, int trials, double z) {
  if (trials <= 0) return {};
  const double n = trials;
  const double p = successes / n;
  const double z2 = z * z;
  const double centre = (p + z2 / (2 * n)) / (1 + z2 / n);
  const double half = z / (1 + z2 / n) * std::sqrt(p * (1 - p) / n + z2 / (4 * n * n));
  // At k = 0 and k = n the bound is exactly 0 or 1 (centre and half agree); said so, rather than
  // left to the rounding of their difference.
  return {successes == 0 ? 0.0 : std::max(0.0, centre - half),
          successes == trials ? 1.0 : std::min(1.0, centre + half)};
}

}  // namespace billiard::batch
