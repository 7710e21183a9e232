// Seeded breaks for the tests and the benchmark: a rack, and the cue ball struck into it.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/physics/parameters.h"
#include "sim/table/rack.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::table::testing {

struct BreakOptions {
  RackKind rack = RackKind::kEightBall;
  double speed = 7.0;           // the cue ball's launch speed [m/s] (a firm break: 7-9 m/s)
  double max_aim_error = 0.01;  // heading jitter about the line to the apex ball [rad]
  double max_tip_offset = 0.3;  // tip offsets drawn within this fraction of the radius
};

// The rack of `seed`, its cue ball launched by a cue stroke (Alciatore TP A.30) aimed at the
// rack's apex ball with a seeded aim error and tip offset, level cue.
std::vector<SceneBall> SeededBreak(const TableGeometry& table, const physics::ModelParameters& p,
                                   std::uint64_t seed, const BreakOptions& options = {});

}  // namespace billiard::table::testing
