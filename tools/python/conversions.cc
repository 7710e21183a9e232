#include "tools/python/conversions.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "planner/game/game_json.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/robots.h"
#include "sim/params/table_specs.h"

namespace billiard::python {

py::object& RefusedType() {
  static py::object type;
  return type;
}

[[noreturn]] void Refuse(const std::string& reason) {
  PyErr_SetString(RefusedType().ptr(), reason.c_str());
  throw py::error_already_set();
}

std::vector<double> Numbers(const Array& a, std::size_t n, const std::string& what) {
  if (static_cast<std::size_t>(a.size()) != n || a.ndim() != 1) {
    throw py::value_error(what + " must be " + std::to_string(n) + " numbers");
  }
  std::vector<double> v(a.data(), a.data() + n);
  for (double x : v) {
    if (!std::isfinite(x)) throw py::value_error(what + " has a number that is not finite");
  }
  return v;
}

physics::ModelParameters Params(const std::string& name_or_path) {
  try {
    return params::LoadParameters(name_or_path);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
}

table::TableGeometry Table(const std::string& name_or_path) {
  try {
    return table::BuildTable(params::LoadTableSpec(name_or_path));
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
}

cue::Robot Robot(const std::string& name_or_path) {
  try {
    return params::LoadRobot(name_or_path);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(std::string("robot: ") + e.what());
  }
}

Array StateArray(const physics::BallState& s) {
  Array out(7);
  std::copy(s.data(), s.data() + 7, out.mutable_data());
  return out;
}

// The balls of an N x 7 array of states, ids 0..N-1 unless given.
std::vector<table::SceneBall> SceneBalls(const Array& states, const std::optional<std::vector<int>>& ids) {
  if (states.ndim() != 2 || states.shape(1) != 7) {
    throw py::value_error("states must be an N x 7 array of [X, Y, vx, vy, wx, wy, wz]");
  }
  const std::size_t n = states.shape(0);
  if (ids && ids->size() != n) throw py::value_error("ids must name every ball (N of them)");
  std::vector<table::SceneBall> balls;
  auto a = states.unchecked<2>();
  for (std::size_t i = 0; i < n; ++i) {
    table::SceneBall b;
    b.id = ids ? (*ids)[i] : static_cast<int>(i);
    for (int j = 0; j < 7; ++j) b.state[j] = a(i, j);
    balls.push_back(b);
  }
  return balls;
}

py::object ToPython(const nlohmann::json& json) {
  switch (json.type()) {
    case nlohmann::json::value_t::null:
      return py::none();
    case nlohmann::json::value_t::boolean:
      return py::bool_(json.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(json.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(json.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float:
      return py::float_(json.get<double>());
    case nlohmann::json::value_t::string:
      return py::str(json.get<std::string>());
    case nlohmann::json::value_t::array: {
      py::list list;
      for (const nlohmann::json& item : json) list.append(ToPython(item));
      return list;
    }
    case nlohmann::json::value_t::object: {
      py::dict dict;
      for (const auto& [key, value] : json.items()) dict[py::str(key)] = ToPython(value);
      return dict;
    }
    default:
      throw py::value_error("JSON holds a value Python has no type for");
  }
}

py::dict CueJson(const physics::CueStroke& stroke,
                 const std::optional<cue::CueClearance>& clearance) {
  nlohmann::json cue = game::CueStrokeJson(stroke);
  if (clearance) cue["clearance"] = game::ClearanceJson(*clearance);
  return ToPython(cue);
}

}  // namespace billiard::python
