#include "sim/params/parameter_sets.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace billiard::params {

namespace internal {
const std::vector<std::pair<std::string, std::string>>& BuiltinParameterJson();
}

using physics::ContactParameters;
using physics::ModelParameters;

std::vector<std::string> BuiltinParameterSetNames() {
  std::vector<std::string> names;
  for (const auto& [name, json] : internal::BuiltinParameterJson()) names.push_back(name);
  return names;
}

namespace {

double Number(const nlohmann::json& object, const char* section, const char* key,
              const std::string& origin) {
  const auto& s = object.at(section);
  if (!s.contains(key) || !s.at(key).is_number()) {
    throw std::invalid_argument(origin + ": missing number " + section + "." + key);
  }
  return s.at(key).get<double>();
}

}  // namespace

physics::ModelParameters ParseParameters(const std::string& json_text, const std::string& origin) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(json_text);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::invalid_argument(origin + ": not valid JSON (" + e.what() + ")");
  }
  for (const char* section : {"ball", "contact", "cue", "table"}) {
    if (!j.is_object() || !j.contains(section) || !j.at(section).is_object()) {
      throw std::invalid_argument(origin + ": missing object \"" + section + "\"");
    }
  }
  physics::ModelParameters p;
  p.name = j.value("name", origin);
  p.source = j.value("source", "");
  p.ball.radius = Number(j, "ball", "radius", origin);
  p.ball.mass = Number(j, "ball", "mass", origin);
  p.ball.gravity = Number(j, "ball", "gravity", origin);
  physics::ContactParameters& c = p.contact;
  c.patch_radius = Number(j, "contact", "patch_radius", origin);
  c.mu = Number(j, "contact", "mu", origin);
  c.d = Number(j, "contact", "d", origin);
  c.eps_t = Number(j, "contact", "eps_t", origin);
  c.eps_r = Number(j, "contact", "eps_r", origin);
  c.b_t = Number(j, "contact", "b_t", origin);
  c.m_t = Number(j, "contact", "m_t", origin);
  c.b_m = Number(j, "contact", "b_m", origin);
  c.m_m = Number(j, "contact", "m_m", origin);
  p.cue.mass = Number(j, "cue", "mass", origin);
  p.cue.tip_restitution = Number(j, "cue", "tip_restitution", origin);
  p.cue.max_tip_offset = Number(j, "cue", "max_tip_offset", origin);
  p.cue.max_speed = Number(j, "cue", "max_speed", origin);
  p.table.length = Number(j, "table", "length", origin);
  p.table.width = Number(j, "table", "width", origin);
  physics::ValidateParameters(p);
  return p;
}

physics::ModelParameters LoadParameters(const std::string& name_or_path) {
  for (const auto& [name, json] : internal::BuiltinParameterJson()) {
    if (name == name_or_path) return ParseParameters(json, name);
  }
  std::ifstream file(name_or_path);
  if (!file) {
    std::string known;
    for (const auto& name : BuiltinParameterSetNames()) known += (known.empty() ? "" : ", ") + name;
    throw std::invalid_argument("unknown parameter set '" + name_or_path +
                                "' (not a built-in set: " + known + "; not a readable file)");
  }
  std::stringstream text;
  text << file.rdbuf();
  return ParseParameters(text.str(), name_or_path);
}

}  // namespace billiard::params
