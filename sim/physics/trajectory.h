// A computed motion of one ball that can be sampled at any time.
#pragma once

#include "sim/physics/ball_state.h"

namespace billiard::physics {

class Trajectory {
 public:
  virtual ~Trajectory() = default;
  // The state at time t; t is clamped to [start_time(), end_time()].
  virtual BallState At(double t) const = 0;
  virtual double start_time() const = 0;
  virtual double end_time() const = 0;
};

}  // namespace billiard::physics
