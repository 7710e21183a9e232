// What the `billiard` Python module's functions share: NumPy arrays to and from the library's
// types, the parameter sets and tables by name, and the two ways a call fails: bad input raises
// ValueError (the CLI's exit 2), an answer that is no raises billiard.Refused (the CLI's exit 3)
// with the CLI's reason.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "sim/cue/clearance.h"
#include "sim/cue/robot.h"
#include "sim/physics/ball_state.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::python {

namespace py = pybind11;

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The module's exception type billiard.Refused, set once by the module's init.
py::object& RefusedType();

// Raises billiard.Refused with `reason`.
[[noreturn]] void Refuse(const std::string& reason);

// Exactly `n` finite numbers of a 1-D array; ValueError naming `what` otherwise.
std::vector<double> Numbers(const Array& a, std::size_t n, const std::string& what);

// A parameter set and a table by name or file; ValueError with the reason.
physics::ModelParameters Params(const std::string& name_or_path);
table::TableGeometry Table(const std::string& name_or_path);
// The robot of a `robot` argument (params::LoadRobot: gantry, player or a file), as the CLI's
// --robot; ValueError when it does not load.
cue::Robot Robot(const std::string& name_or_path);

// A ball's state as a 7-array [X, Y, vx, vy, wx, wy, wz].
Array StateArray(const physics::BallState& s);

// The balls of an N x 7 array of states, ids 0..N-1 unless given.
std::vector<table::SceneBall> SceneBalls(const Array& states, const std::optional<std::vector<int>>& ids);

// JSON as Python: objects as dicts, arrays as lists, null as None; the CLI's own JSON writers
// (planner/game/game_json.h) give the module's answers where they are the same.
py::object ToPython(const nlohmann::json& json);

// A stroke as the CLI's JSON has it (game::CueStrokeJson), with "clearance"
// (game::ClearanceJson) where the robot's cue was checked.
py::dict CueJson(const physics::CueStroke& stroke, const std::optional<cue::CueClearance>& clearance = std::nullopt);

}  // namespace billiard::python
