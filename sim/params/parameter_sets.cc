#include "sim/params/parameter_sets.h"

#include "sim/params/constants_uncertainty.h"
#include "sim/params/strict_json.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
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

using internal::Field;

namespace {

// The numbers of `p` by section and key, as the files spell them.
std::vector<std::pair<std::string, std::vector<Field>>> Sections(ModelParameters& p) {
  ContactParameters& c = p.contact;
  return {{"ball", {{"radius", &p.ball.radius}, {"mass", &p.ball.mass}, {"gravity", &p.ball.gravity}}},
          {"contact",
           {{"patch_radius", &c.patch_radius},
            {"mu", &c.mu},
            {"d", &c.d},
            {"eps_t", &c.eps_t},
            {"eps_r", &c.eps_r},
            {"b_t", &c.b_t},
            {"m_t", &c.m_t},
            {"b_m", &c.b_m},
            {"m_m", &c.m_m}}},
          {"cue",
           {{"mass", &p.cue.mass},
            {"tip_restitution", &p.cue.tip_restitution},
            {"max_tip_offset", &p.cue.max_tip_offset},
            {"max_speed", &p.cue.max_speed},
            {"end_mass", &p.cue.end_mass}}},
          {"collision",
           {{"ball_restitution", &p.collision.ball_restitution},
            {"ball_friction_a", &p.collision.ball_friction_a},
            {"ball_friction_b", &p.collision.ball_friction_b},
            {"ball_friction_c", &p.collision.ball_friction_c},
            {"cushion_restitution", &p.collision.cushion_restitution},
            {"cushion_friction", &p.collision.cushion_friction}}},
          {"table", {{"length", &p.table.length}, {"width", &p.table.width}}}};
}

// The optional "uncertainty": {"source": "...", "<section>.<key>": sd, ...}, each key one the
// sampler draws (ConstantByKey) and each sd a finite number >= 0.
physics::ConstantsUncertainty ReadUncertainty(const nlohmann::json& j, const std::string& origin) {
  physics::ConstantsUncertainty u;
  if (!j.is_object()) {
    throw std::invalid_argument(origin + ": \"uncertainty\" must be an object, not " +
                                internal::TypeName(j));
  }
  u.source = internal::ReadText(j, "source", "", origin);
  ModelParameters probe;
  for (const auto& [key, value] : j.items()) {
    if (key == "source") continue;
    const std::string path = "uncertainty." + key;
    if (ConstantByKey(probe, key) == nullptr) {
      throw std::invalid_argument(origin + ": unknown key " + path +
                                  " (a constant of contact, collision or cue mass, "
                                  "tip_restitution, end_mass)");
    }
    if (!value.is_number() || !std::isfinite(value.get<double>()) || value.get<double>() < 0) {
      throw std::invalid_argument(origin + ": " + path +
                                  " must be a standard deviation, a number >= 0, not " + value.dump());
    }
    u.sd.emplace_back(key, value.get<double>());
  }
  return u;
}

}  // namespace

double* ParameterByKey(ModelParameters& p, const std::string& key) {
  const std::size_t dot = key.find('.');
  if (dot == std::string::npos) return nullptr;
  for (const auto& [section, fields] : Sections(p)) {
    if (section != key.substr(0, dot)) continue;
    for (const Field& f : fields) {
      if (f.key == key.substr(dot + 1)) return f.value;
    }
  }
  return nullptr;
}

ModelParameters ParseParameters(const std::string& json_text, const std::string& origin) {
  const nlohmann::json j = internal::ParseObject(json_text, origin, "a parameter set");
  ModelParameters p;
  const auto sections = Sections(p);
  for (const auto& [key, value] : j.items()) {
    const bool known = key == "name" || key == "source" || key == "uncertainty" ||
                       (key == "fit" && value.is_object()) ||
                       std::any_of(sections.begin(), sections.end(),
                                   [&key = key](const auto& s) { return s.first == key; });
    if (!known) throw std::invalid_argument(origin + ": unknown key " + key);
  }
  for (const auto& [name, fields] : sections) {
    if (!j.contains(name))
      throw std::invalid_argument(origin + ": missing object \"" + name + "\"");
    internal::ReadSection(j.at(name), name, fields, origin);
  }
  p.name = internal::ReadText(j, "name", origin, origin);
  p.source = internal::ReadText(j, "source", "", origin);
  if (j.contains("uncertainty")) p.uncertainty = ReadUncertainty(j.at("uncertainty"), origin);
  physics::ValidateParameters(p);
  return p;
}

ModelParameters LoadParameters(const std::string& name_or_path) {
  bool from_file = false;
  const std::string text = internal::BuiltinOrFileText(
      internal::BuiltinParameterJson(), name_or_path, "parameter set", "set", &from_file);
  ModelParameters p = ParseParameters(text, name_or_path);
  if (from_file) p.file = name_or_path;
  return p;
}

std::string ParametersJson(const ModelParameters& p, const std::string& fit_json) {
  const ContactParameters& c = p.contact;
  const physics::CollisionParameters& k = p.collision;
  nlohmann::ordered_json j;
  j["name"] = p.name;
  j["source"] = p.source;
  j["ball"] = {{"radius", p.ball.radius}, {"mass", p.ball.mass}, {"gravity", p.ball.gravity}};
  j["contact"] = {{"patch_radius", c.patch_radius}, {"mu", c.mu},   {"d", c.d},
                  {"eps_t", c.eps_t},               {"eps_r", c.eps_r}, {"b_t", c.b_t},
                  {"m_t", c.m_t},                   {"b_m", c.b_m}, {"m_m", c.m_m}};
  j["cue"] = {{"mass", p.cue.mass},
              {"tip_restitution", p.cue.tip_restitution},
              {"max_tip_offset", p.cue.max_tip_offset},
              {"max_speed", p.cue.max_speed},
              {"end_mass", p.cue.end_mass}};
  j["collision"] = {{"ball_restitution", k.ball_restitution},
                    {"ball_friction_a", k.ball_friction_a},
                    {"ball_friction_b", k.ball_friction_b},
                    {"ball_friction_c", k.ball_friction_c},
                    {"cushion_restitution", k.cushion_restitution},
                    {"cushion_friction", k.cushion_friction}};
  j["table"] = {{"length", p.table.length}, {"width", p.table.width}};
  if (!p.uncertainty.sd.empty()) {
    nlohmann::ordered_json u;
    if (!p.uncertainty.source.empty()) u["source"] = p.uncertainty.source;
    for (const auto& [key, sd] : p.uncertainty.sd) u[key] = sd;
    j["uncertainty"] = u;
  }
  if (!fit_json.empty()) j["fit"] = nlohmann::ordered_json::parse(fit_json);
  return j.dump(2) + "\n";
}

std::string ParameterSetLabel(const ModelParameters& p) {
  return p.file.empty() ? p.name : p.name + " (" + p.file + ")";
}

std::string ParameterHash(const ModelParameters& p) {
  constexpr std::uint64_t kFnvOffsetBasis = 14695981039346656037ull;
  constexpr std::uint64_t kFnvPrime = 1099511628211ull;
  std::uint64_t hash = kFnvOffsetBasis;
  for (double value : physics::ParameterValues(p)) {
    unsigned char bytes[sizeof value];
    std::memcpy(bytes, &value, sizeof value);
    for (unsigned char byte : bytes) hash = (hash ^ byte) * kFnvPrime;
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

}  // namespace billiard::params
