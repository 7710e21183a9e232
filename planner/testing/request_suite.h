// Seeded random shot requests over a table: what the planner's acceptance test and benchmark
// plan. Deterministic for a seed, so both see the same requests. A testing library
// (planner_testing): it includes the planner and the physics; no production code includes it.
#pragma once

#include <cstdint>
#include <random>

#include "planner/closed_form_inverse.h"
#include "sim/physics/parameters.h"

namespace billiard::planner::testing {

class RequestSuite {
 public:
  RequestSuite(const physics::TableParameters& table, std::uint32_t seed)
      : table_(table), rng_(seed) {}

  // Request number i (counted by the caller) cycles through the kinds: odd ones stop at the
  // target, even ones pass it at up to 0.6 m/s; every fifth sets a slide length (up to half the
  // distance), the others a spin style in turn; every third has side spin within +-20 rad/s.
  // Start and target lie 10 cm or more inside the cushions and 20 cm or more apart.
  planner::ShotRequest Next(int i);

 private:
  physics::TableParameters table_;
  std::mt19937 rng_;
};

}  // namespace billiard::planner::testing
