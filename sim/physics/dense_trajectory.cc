#include "sim/physics/dense_trajectory.h"

#include <algorithm>
#include <stdexcept>

namespace billiard::physics {

void DenseTrajectory::Append(double t0, double t1, const BallState& x0, const BallState& x1,
                             const BallState& c3, const BallState& c4) {
  steps_.push_back({t0, t1, x0, x1, c3, c4});
}

double DenseTrajectory::start_time() const { return steps_.empty() ? 0.0 : steps_.front().t0; }
double DenseTrajectory::end_time() const { return steps_.empty() ? 0.0 : steps_.back().t1; }
double DenseTrajectory::last_step_start() const { return steps_.empty() ? 0.0 : steps_.back().t0; }

BallState DenseTrajectory::At(double t) const {
  if (steps_.empty()) throw std::logic_error("dense trajectory has no steps");
  t = std::clamp(t, start_time(), end_time());
  const auto it = std::lower_bound(steps_.begin(), steps_.end(), t,
                                   [](const Step& step, double time) { return step.t1 < time; });
  const Step& step = it == steps_.end() ? steps_.back() : *it;
  if (step.t1 <= step.t0) return step.x0;
  return Interpolate(step.x0, step.x1, step.c3, step.c4, (t - step.t0) / (step.t1 - step.t0));
}

void DenseTrajectory::TruncateLastStepAt(double t) {
  if (steps_.empty()) throw std::logic_error("dense trajectory has no steps");
  Step& step = steps_.back();
  if (!(t >= step.t0 && t <= step.t1)) throw std::logic_error("truncation outside the last step");
  if (step.t1 <= step.t0) return;
  // The interpolant as x0 + B s + C s^2 + D s^3, rescaled to s' = s / lambda over [t0, t].
  const double lambda = (t - step.t0) / (step.t1 - step.t0);
  const BallState b = lambda * (step.x1 - step.x0 + step.c3);
  const BallState c = lambda * lambda * (step.c4 - step.c3);
  const BallState d = -lambda * lambda * lambda * step.c4;
  step.t1 = t;
  step.x1 = step.x0 + b + c + d;
  step.c4 = -d;
  step.c3 = -c - d;
}

BallState DenseTrajectory::Interpolate(const BallState& x0, const BallState& x1,
                                       const BallState& c3, const BallState& c4, double s) {
  return (1.0 - s) * x0 + s * (x1 + (1.0 - s) * (c3 + s * c4));
}

}  // namespace billiard::physics
