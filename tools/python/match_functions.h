// A match in the `billiard` Python module, rack by rack, so that racks can be played apart (on
// Dask's workers: tools/python/billiard_dask.py) and summed to what `billiard match --json`
// prints: `play_rack` plays rack r of a match (seeded SampleSeed(seed, r), broken by player
// r % 2: planner/game/match.h) and returns its record, a dict of plain numbers, strings and
// lists that pickles; `match_summary` sums such records with the library's own
// game::AddRack and game::MatchJson (planner/game/match_summary.h), the code the CLI sums with.
#pragma once

#include <pybind11/pybind11.h>

namespace billiard::python {

// Adds play_rack and match_summary to the module `m`.
void AddMatchFunctions(pybind11::module_& m);

}  // namespace billiard::python
