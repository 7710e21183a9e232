// Seeded pot layouts for the tests and `billiard bench-pot`: balls at rest scattered over a table
// and a pot to ask of them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "planner/pot/pot_planner.h"
#include "sim/physics/parameters.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::pot::testing {

struct PotLayout {
  std::uint64_t seed = 0;
  std::vector<table::SceneBall> balls;  // id 0 the cue ball, then 1, 2, ...
  PotRequest request;                   // a random object ball and pocket, any kind
};

// `min_balls` to `max_balls` balls (the cue ball among them) placed uniformly on the playing
// surface, each at least a ball's width clear of the others and of the cushions (so that every
// pot starts from a clean lie; touching balls and balls on a rail are the table's own tests), and
// a random object ball and pocket. The same seed gives the same layout on every machine.
PotLayout SeededPotLayout(const table::TableGeometry& table, double radius, std::uint64_t seed,
                          int min_balls = 2, int max_balls = 16);

// Whether the straight ghost-ball shot is clear: no ball within a ball's width of the cue ball's
// line to the ghost ball or of K's line to the pocket's mouth, that line clear of the pocket's
// own jaws (its rounded noses), and a cut below `max_cut_deg`.
// The cut beyond which bench-pot's coverage does not count a line as clear: past it the object
// ball takes a sliver of the cue ball's speed, and a pot is a matter of throw and luck.
inline constexpr double kClearCutDeg = 80.0;

bool StraightLineClear(const table::TableGeometry& table, double radius,
                       const std::vector<table::SceneBall>& balls, int object,
                       const std::string& pocket, double max_cut_deg);

}  // namespace billiard::pot::testing
