// Scenes at the degenerate edges of the table simulation, for its property tests and its fuzz
// target: balls frozen to a cushion and to each other, a cue ball rolling or sliding along a
// cushion it touches (square to it, or closing or parting at up to 1e-3 rad), into chains of
// touching balls, grazing a ball, with every spin a cue gives; and the invariants that any run of
// any scene must keep.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sim/physics/parameters.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"
#include "sim/table/table_simulation.h"

namespace billiard::table::testing {

// A source of numbers in [0, 1): a seeded generator for the tests, the fuzzer's bytes for the
// fuzz target.
using Uniform = std::function<double()>;

// A valid scene of 2-8 balls drawn from `uniform` (every ball on the surface, none overlapping):
// each ball frozen to a cushion, frozen to a ball placed before it, or anywhere; the cue ball
// (id 0) at 0.3-8 m/s along the cushion it touches, at the centre or the edge of a ball, or
// anywhere, with side spin up to 60 rad/s and top or back spin from draw to over-follow.
std::vector<SceneBall> DegenerateScene(const TableGeometry& table, double radius,
                                       const Uniform& uniform);

// The motion between events as `billiard simulate --scene --model` names it, with the 5-DOF
// model's default method: "closed-form" (every ball), "auto" (FiveDofWhereNeeded) or "approx"
// (the 5-DOF model for every moving ball). Throws std::invalid_argument for another name.
TableSimulationOptions MotionOptions(const std::string& model, const physics::ModelParameters& p);

// The same from a seed.
std::vector<SceneBall> SeededDegenerateScene(const TableGeometry& table, double radius,
                                             std::uint64_t seed);

// What a run kept, sampled every `dt` and at its end: the deepest overlap of two balls on the
// table, the farthest a ball not yet pocketed was out of the table's boundary, and the largest
// relative rise of the kinetic energy from one sample to the next.
struct SceneInvariants {
  double overlap = 0.0;     // [m]
  double off_surface = 0.0;  // [m]
  double energy_rise = 0.0;  // relative
};

SceneInvariants MeasureInvariants(const TableSimulation& sim, const TableGeometry& table,
                                  const physics::ModelParameters& p, double dt);

}  // namespace billiard::table::testing
