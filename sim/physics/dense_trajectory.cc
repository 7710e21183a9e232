#include "sim/physics/dense_trajectory.h"

#include <algorithm>
#include <stdexcept>

namespace billiard::physics {

void DenseTrajectory::Append(double t0, double t1, const BallState& x0, const BallState& x1,
                             const BallState& c3, const BallState& c4) {
  // Default-initialized: a block is written step by step, never read before.
  if (size_ % kBlockSteps == 0) blocks_.emplace_back(new Block);
  step(size_++) = {t0, t1, x0, x1, c3, c4};
}

double DenseTrajectory::start_time() const { return size_ == 0 ? 0.0 : step(0).t0; }
double DenseTrajectory::end_time() const { return size_ == 0 ? 0.0 : step(size_ - 1).t1; }
double DenseTrajectory::last_step_start() const { return size_ == 0 ? 0.0 : step(size_ - 1).t0; }

BallState DenseTrajectory::At(double t) const {
  if (size_ == 0) throw std::logic_error("dense trajectory has no steps");
  t = std::clamp(t, start_time(), end_time());
  // The first step that ends at or after t (the last one if none does); the last step first,
  // where events are searched.
  std::size_t lo = t >= step(size_ - 1).t0 ? size_ - 1 : 0, hi = size_ - 1;
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (step(mid).t1 < t) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  const Step& s = step(lo);
  if (s.t1 <= s.t0) return s.x0;
  return Interpolate(s.x0, s.x1, s.c3, s.c4, (t - s.t0) / (s.t1 - s.t0));
}

void DenseTrajectory::TruncateLastStepAt(double t) {
  if (size_ == 0) throw std::logic_error("dense trajectory has no steps");
  Step& step = this->step(size_ - 1);
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
