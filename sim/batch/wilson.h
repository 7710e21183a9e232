// The Wilson score interval of a binomial proportion (Wilson 1927, "Probable inference, the law
// of succession, and statistical inference", JASA 22: 209-212): the proportions p whose normal
// test at z does not reject the k successes seen in n trials,
//   (k/n + z^2/2n  -/+  z sqrt(k/n (1 - k/n) / n + z^2/4n^2)) / (1 + z^2/n).
// Unlike the normal (Wald) interval it stays inside [0, 1] and keeps its coverage near 0 and 1
// and for small n (Brown, Cai and DasGupta 2001), which a match of a few racks is.
//
// Module: billiard::batch.
#pragma once

namespace billiard::batch {

// The normal quantile of a two-sided 95 % interval.
inline constexpr double kZ95 = 1.959963984540054;

struct Interval {
  double lo = 0.0;
  double hi = 1.0;
};

// The Wilson interval of `successes` in `trials` at `z`; [0, 1] when there are no trials.
Interval WilsonInterval(int successes, int trials, double z = kZ95);

}  // namespace billiard::batch
