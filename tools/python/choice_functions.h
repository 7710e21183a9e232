// The shot choice in the `billiard` Python module: `choose_shot` (billiard choose-shot: the pot
// most likely to drop under the robot's execution noise, with a one-shot lookahead) and `play`
// (billiard play: a rack in simulation, shot by shot). The same library calls as the CLI's, so
// the same seed gives the same answer to the bit (tools/python/billiard_test.py checks it).
#pragma once

#include <pybind11/pybind11.h>

namespace billiard::python {

// Adds choose_shot and play to the module `m`.
void AddChoiceFunctions(pybind11::module_& m);

}  // namespace billiard::python
