#include "sim/params/scene_file.h"

#include "sim/params/strict_json.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace billiard::params {

namespace {

using internal::TypeName;

// Refuses any key of `object` that is not in `known`, naming it.
void RequireKnownKeys(const nlohmann::json& object, const std::vector<std::string>& known,
                      const std::string& where) {
  internal::ReadSection(object, "", {}, where, known);
}

const nlohmann::json& Required(const nlohmann::json& object, const char* key,
                               const std::string& where) {
  if (!object.contains(key)) throw std::invalid_argument(where + ": missing " + key);
  return object.at(key);
}

std::string RequiredText(const nlohmann::json& object, const char* key, const std::string& where) {
  const nlohmann::json& value = Required(object, key, where);
  if (!value.is_string()) {
    throw std::invalid_argument(where + ": " + key + " must be a string, not " + TypeName(value));
  }
  return value.get<std::string>();
}

physics::CueStroke ParseCue(const nlohmann::json& j, const std::string& where) {
  physics::CueStroke stroke;
  internal::ReadSection(j, "cue", {{"speed", &stroke.speed}, {"heading", &stroke.heading}}, where,
                        {"tip_side", "tip_height", "elevation"});
  for (const internal::Field& f : {internal::Field{"tip_side", &stroke.tip_side},
                                   internal::Field{"tip_height", &stroke.tip_height},
                                   internal::Field{"elevation", &stroke.elevation}}) {
    if (!j.contains(f.key)) continue;
    if (!j.at(f.key).is_number()) {
      throw std::invalid_argument(where + ": cue." + f.key + " must be a number, not " +
                                  TypeName(j.at(f.key)));
    }
    *f.value = j.at(f.key).get<double>();
  }
  return stroke;
}

table::SceneBall ParseBall(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object()) throw std::invalid_argument(where + " must be an object, not " + TypeName(j));
  RequireKnownKeys(j, {"id", "state", "cue"}, where);
  const nlohmann::json& id = Required(j, "id", where);
  if (!id.is_number_integer()) {
    throw std::invalid_argument(where + ": id must be an integer, not " + TypeName(id));
  }
  const nlohmann::json& state = Required(j, "state", where);
  if (!state.is_array() || state.size() != 7) {
    throw std::invalid_argument(where + ": state must be 7 numbers [X, Y, vx, vy, wx, wy, wz]");
  }
  table::SceneBall ball;
  ball.id = id.get<int>();
  for (int k = 0; k < 7; ++k) {
    if (!state[k].is_number()) {
      throw std::invalid_argument(where + ": state[" + std::to_string(k) +
                                  "] must be a number, not " + TypeName(state[k]));
    }
    ball.state[k] = state[k].get<double>();
  }
  return ball;
}

}  // namespace

SceneFile ParseScene(const std::string& json_text, const std::string& origin) {
  const nlohmann::json j = internal::ParseObject(json_text, origin, "a scene");
  // The scene reader stays strict (a mistyped key is never ignored); a simulation's result is
  // told apart by what only it holds, and pointed to the scene the simulation can write.
  if (j.contains("events") && j.contains("at_rest")) {
    throw std::invalid_argument(origin + ": a simulation's result (simulate --json), not a scene; "
                                "simulate --scene-out writes the table at the end as a scene");
  }
  RequireKnownKeys(j, {"table", "params", "balls"}, origin);
  SceneFile scene;
  scene.table = RequiredText(j, "table", origin);
  scene.params = RequiredText(j, "params", origin);
  const nlohmann::json& balls = Required(j, "balls", origin);
  if (!balls.is_array()) {
    throw std::invalid_argument(origin + ": balls must be an array, not " + TypeName(balls));
  }
  for (std::size_t k = 0; k < balls.size(); ++k) {
    const std::string where = origin + ": balls[" + std::to_string(k) + "]";
    scene.balls.push_back(ParseBall(balls[k], where));
    if (balls[k].contains("cue")) {
      scene.cues[scene.balls.back().id] = ParseCue(balls[k].at("cue"), where);
    }
  }
  return scene;
}

SceneFile LoadScene(const std::string& path) {
  std::string text;
  if (!internal::ReadFile(path, &text)) {
    throw std::invalid_argument("cannot read scene file '" + path + "'");
  }
  return ParseScene(text, path);
}

std::string SceneJson(const SceneFile& scene) {
  nlohmann::json j;
  j["table"] = scene.table;
  j["params"] = scene.params;
  j["balls"] = nlohmann::json::array();
  for (const table::SceneBall& b : scene.balls) {
    nlohmann::json ball = {{"id", b.id},
                           {"state", std::vector<double>(b.state.data(), b.state.data() + 7)}};
    const auto cue = scene.cues.find(b.id);
    if (cue != scene.cues.end()) {
      const physics::CueStroke& c = cue->second;
      ball["cue"] = {{"speed", c.speed},
                     {"heading", c.heading},
                     {"tip_side", c.tip_side},
                     {"tip_height", c.tip_height},
                     {"elevation", c.elevation}};
    }
    j["balls"].push_back(ball);
  }
  return j.dump();
}

std::vector<table::SceneBall> LaunchedBalls(const SceneFile& scene,
                                            const physics::ModelParameters& p) {
  std::vector<table::SceneBall> balls = scene.balls;
  for (const auto& [id, stroke] : scene.cues) {
    const std::string name = "ball " + std::to_string(id);
    const auto ball = std::find_if(balls.begin(), balls.end(),
                                   [id = id](const table::SceneBall& b) { return b.id == id; });
    if (ball == balls.end()) throw std::invalid_argument(name + " is struck but not on the table");
    if (!ball->state.tail<5>().isZero()) {
      throw std::invalid_argument(name + ": a struck ball starts at rest (velocity and spin 0)");
    }
    try {
      *ball = table::Struck(id, stroke, ball->state.head<2>(), p);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(name + ": " + e.what());
    }
  }
  return balls;
}

}  // namespace billiard::params
