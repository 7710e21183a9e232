// Parameter sets as data: the built-in sets (the JSON files beside this header, compiled into the
// library so that the binaries need no data directory) and sets read from JSON files of the same
// format.
//
// Module: billiard::params. Includes the physics (sim/physics/) and nothing else of the project.
#pragma once

#include <string>
#include <vector>

#include "sim/physics/parameters.h"

namespace billiard::params {

// The names of the built-in parameter sets ("paper", "pool").
std::vector<std::string> BuiltinParameterSetNames();

// A built-in set by name, or a JSON file by path. Throws std::invalid_argument with a one-line
// reason on an unknown name, an unreadable file, a missing field or a value out of range.
physics::ModelParameters LoadParameters(const std::string& name_or_path);

// Parses a parameter set from JSON text (the format of sim/params/*.json).
physics::ModelParameters ParseParameters(const std::string& json_text, const std::string& origin);

}  // namespace billiard::params
