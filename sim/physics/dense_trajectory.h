// The dense output of a Rosenbrock integration: one cubic-in-time interpolant per accepted step
// (Hairer and Wanner's RODAS continuous extension, third order).
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "sim/physics/trajectory.h"

namespace billiard::physics {

class DenseTrajectory : public Trajectory {
 public:
  // A step from (t0, x0) to (t1, x1) with the interpolation coefficients c3, c4:
  // x(s) = (1 - s) x0 + s (x1 + (1 - s) (c3 + s c4)),  s = (t - t0) / (t1 - t0).
  void Append(double t0, double t1, const BallState& x0, const BallState& x1, const BallState& c3,
              const BallState& c4);

  BallState At(double t) const override;
  // The interpolant of one step at s = (t - t0) / (t1 - t0) in [0, 1].
  static BallState Interpolate(const BallState& x0, const BallState& x1, const BallState& c3,
                               const BallState& c4, double s);
  double start_time() const override;
  double end_time() const override;
  std::size_t size() const { return size_; }
  // Where the last step began (an event found after it lies within that step).
  double last_step_start() const;
  // Ends the trajectory at t inside its last step (an event located there): the step's cubic
  // restricted to [t0, t], the same curve to rounding.
  void TruncateLastStepAt(double t);

 private:
  struct Step {
    double t0, t1;
    BallState x0, x1, c3, c4;
  };
  // Steps are kept in blocks that never move once written, not in one growing vector: a
  // trajectory then grows without copying its steps, and in pieces small enough for the allocator
  // to hand back the same memory to the next simulation. (A growing vector of them spent about a
  // third of a simulation in copies and page faults: its doubling blocks crossed malloc's mmap and
  // trim thresholds.)
  static constexpr std::size_t kBlockSteps = 32;
  using Block = std::array<Step, kBlockSteps>;
  Step& step(std::size_t i) { return (*blocks_[i / kBlockSteps])[i % kBlockSteps]; }
  const Step& step(std::size_t i) const { return (*blocks_[i / kBlockSteps])[i % kBlockSteps]; }
  std::vector<std::unique_ptr<Block>> blocks_;
  std::size_t size_ = 0;
};

}  // namespace billiard::physics
