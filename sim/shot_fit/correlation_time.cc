#include "sim/shot_fit/correlation_time.h"

#include <algorithm>
#include <cstddef>

namespace billiard::shot_fit {

std::vector<double> LaggedProducts(const TrackedShot& shot, double horizon,
                                   const std::vector<double>& r) {
  std::vector<double> lagged(kMaxLag + 1, 0.0);
  std::size_t first = 0;  // the ball's first residual
  for (const TrackedBall& b : shot.balls) {
    const auto n = static_cast<std::size_t>(
        std::count_if(b.t.begin(), b.t.end(), [&](double t) { return t <= horizon; }));
    for (std::size_t axis = 0; axis < 2; ++axis) {
      for (std::size_t i = 0; i < n; ++i) {
        const double ri = r[first + 2 * i + axis];
        for (std::size_t k = 0; k <= kMaxLag && i + k < n; ++k)
          lagged[k] += ri * r[first + 2 * (i + k) + axis];
      }
    }
    first += 2 * n;
  }
  return lagged;
}

double CorrelationTime(const std::vector<double>& lagged) {
  if (!(lagged[0] > 0.0)) return 1.0;
  double tau = 1.0;
  for (std::size_t k = 1; k < lagged.size(); ++k) {
    const double rho = lagged[k] / lagged[0];
    if (rho <= 0.0) break;
    tau += 2.0 * rho;
  }
  return tau;
}

}  // namespace billiard::shot_fit
