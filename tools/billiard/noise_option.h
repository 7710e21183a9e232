// The commands' noise options (--noise, --plant-noise, --prior): a built-in name
// (params::BuiltinNoiseNames()) or a JSON file of sim/params/noise/'s form.
#pragma once

#include <string>

#include "sim/params/execution_noise.h"

namespace billiard::cli {

// The noise `name_or_path` names; UsageError (exit 2) naming `flag` if it does not load.
params::ExecutionNoise LoadNoiseOption(const std::string& name_or_path, const std::string& flag);

}  // namespace billiard::cli
