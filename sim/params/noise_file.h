// A noise model written in the form sim/params/noise/'s files have (execution_noise.h), which
// LoadNoise reads back: how a noise learned on the robot (planner/node/noise_learning.h) is
// handed to whatever plans for a noise (`billiard identify-noise --noise-out`, then `--noise` of
// choose-shot, play or bench-game).
//
// Module: billiard::params.
#pragma once

#include <string>

#include "sim/params/execution_noise.h"

namespace billiard::params {

// `noise` as a file's JSON text, in the files' units (degrees, millimetres), every key present.
std::string FormatNoise(const ExecutionNoise& noise);

}  // namespace billiard::params
