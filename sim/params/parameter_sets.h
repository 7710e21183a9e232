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

// The set every node and command uses unless told otherwise: the regulation pool ball, the ball
// users have. (`billiard bench` alone defaults to "paper": its scenes are the paper's figures.)
inline constexpr char kDefaultParameterSet[] = "pool";

// The names of the built-in parameter sets ("carom", "carom-fitted", "paper", "pool", "snooker").
std::vector<std::string> BuiltinParameterSetNames();

// A built-in set by name, or a JSON file by path (then `file` holds the path). Throws
// std::invalid_argument with a one-line reason on an unknown name, an unreadable file, a missing
// field or a value out of range.
physics::ModelParameters LoadParameters(const std::string& name_or_path);

// Parses a parameter set from JSON text (the format of sim/params/*.json): the objects "ball",
// "contact", "cue", "collision" and "table" with every number of physics::ModelParameters, and
// optional strings "name" (default: `origin`) and "source". An unknown key, a missing number or
// a value of the wrong type is refused, naming the key ("t.json: unknown key contact.muu").
// An optional object "fit" (the report of the fit that identified the set: how, on what data,
// with what uncertainties) is documentation; the physics does not read it. An optional object
// "uncertainty" gives standard deviations of named constants ("collision.cushion_restitution":
// 0.03) and a "source" string: the set's ConstantsUncertainty, which the shot choice samples
// (constants_uncertainty.h); a key the sampler does not draw or an sd that is negative or not
// a number is refused, naming the key ("t.json: uncertainty.contact.mu must be a standard
// deviation, a number >= 0, not -0.1").
physics::ModelParameters ParseParameters(const std::string& json_text, const std::string& origin);

// The number of `p` a file names `key` ("contact.mu", "table.length"), or nullptr.
double* ParameterByKey(physics::ModelParameters& p, const std::string& key);

// The set as JSON text that ParseParameters reads back to the same numbers and uncertainty
// (every one at full precision), with `fit_json`, when not empty, a JSON object, as its "fit".
std::string ParametersJson(const physics::ModelParameters& p, const std::string& fit_json = "");

// The set's name, and the file it came from when not built in: "pool", "mine (my/set.json)".
std::string ParameterSetLabel(const physics::ModelParameters& p);

// A hash of the set's numbers (physics::ParameterValues, FNV-1a over their bits), 16 hex digits:
// two sets give the same hash exactly when they are the same physics, whatever their names or
// files. The nodes announce it in NODE_STATUS.
std::string ParameterHash(const physics::ModelParameters& p);

}  // namespace billiard::params
