// A table scene as data: the JSON of `billiard simulate --scene` and `billiard rack`.
//
//   {"table": "pool-9ft", "params": "pool",
//    "balls": [{"id": 0, "state": [X, Y, vx, vy, wx, wy, wz]}, ...]}
//
// A ball may be struck instead of launched: {"id": 0, "state": [X, Y, 0, 0, 0, 0, 0],
// "cue": {"speed", "heading", "tip_side", "tip_height", "elevation"}} (the stroke of
// physics::CueStroke, as `billiard plan` prints it; the three offsets default to 0), its launch
// given by the cue strike model with squirt (sim/physics/cue_strike.h) from rest at (X, Y); an
// elevated cue hops it off the cloth (sim/physics/hop.h).
//
// "table" names a table specification (sim/params/table_specs.h), "params" a parameter set
// (parameter_sets.h), each built in or a file; the states are in table coordinates (README.md,
// "Table coordinates"), id 0 is the cue ball.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/table/scene.h"

namespace billiard::params {

struct SceneFile {
  std::string table;
  std::string params;
  std::vector<table::SceneBall> balls;
  std::map<int, physics::CueStroke> cues;  // ball id -> the stroke that launches it from rest
};

// The balls as they start: each struck ball in `scene.cues` at rest at its place, launched by its
// stroke (table::Struck: its launch and its hop). Throws std::invalid_argument, naming the ball, for a stroke of
// a ball that is not there or not at rest, or that no cue gives.
std::vector<table::SceneBall> LaunchedBalls(const SceneFile& scene,
                                            const physics::ModelParameters& p);

// Parses a scene; an unknown key, a missing one, a value of the wrong type or a state that is
// not seven numbers is refused with a one-line reason naming it and `origin`. Whether the balls
// fit the table is the simulation's check (table::ValidateScene).
SceneFile ParseScene(const std::string& json_text, const std::string& origin);

// Reads the scene file at `path` (std::invalid_argument if unreadable or invalid).
SceneFile LoadScene(const std::string& path);

// The scene as JSON text, every number to full precision, the format ParseScene reads.
std::string SceneJson(const SceneFile& scene);

}  // namespace billiard::params
