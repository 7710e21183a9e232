#include "planner/testing/request_suite.h"

namespace billiard::planner::testing {

planner::ShotRequest RequestSuite::Next(int i) {
  constexpr double kMargin = 0.1, kMinDistance = 0.2;
  std::uniform_real_distribution<double> x(kMargin, table_.length - kMargin);
  std::uniform_real_distribution<double> y(kMargin, table_.width - kMargin);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  planner::ShotRequest q;
  do {
    q.from = {x(rng_), y(rng_)};
    q.to = {x(rng_), y(rng_)};
  } while ((q.to - q.from).norm() < kMinDistance);
  q.final_speed = i % 2 ? 0.0 : 0.6 * u(rng_);
  if (i % 5 == 4) {
    q.slide_length = 0.5 * (q.to - q.from).norm() * u(rng_);
  } else {
    q.style = static_cast<planner::SpinStyle>(i % 4);
  }
  if (i % 3 == 0) q.side_spin = 40.0 * (u(rng_) - 0.5);
  return q;
}

}  // namespace billiard::planner::testing
