// A table scene as data: the JSON of `billiard simulate --scene` and `billiard rack`.
//
//   {"table": "pool-9ft", "params": "pool",
//    "balls": [{"id": 0, "state": [X, Y, vx, vy, wx, wy, wz]}, ...]}
//
// "table" names a table specification (sim/params/table_specs.h), "params" a parameter set
// (parameter_sets.h), each built in or a file; the states are in table coordinates (README.md,
// "Table coordinates"), id 0 is the cue ball.
#pragma once

#include <string>
#include <vector>

#include "sim/table/scene.h"

namespace billiard::params {

struct SceneFile {
  std::string table;
  std::string params;
  std::vector<table::SceneBall> balls;
};

// Parses a scene; an unknown key, a missing one, a value of the wrong type or a state that is
// not seven numbers is refused with a one-line reason naming it and `origin`. Whether the balls
// fit the table is the simulation's check (table::ValidateScene).
SceneFile ParseScene(const std::string& json_text, const std::string& origin);

// Reads the scene file at `path` (std::invalid_argument if unreadable or invalid).
SceneFile LoadScene(const std::string& path);

// The scene as JSON text, every number to full precision, the format ParseScene reads.
std::string SceneJson(const SceneFile& scene);

}  // namespace billiard::params
