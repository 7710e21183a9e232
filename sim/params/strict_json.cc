#include "sim/params/strict_json.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace billiard::params::internal {

namespace {

std::string KeyPath(const std::string& section, const std::string& key) {
  return section.empty() ? key : section + "." + key;
}

}  // namespace

std::string TypeName(const nlohmann::json& j) { return j.is_null() ? "null" : j.type_name(); }

void ReadSection(const nlohmann::json& section, const std::string& name,
                 const std::vector<Field>& fields, const std::string& origin,
                 const std::vector<std::string>& other_keys) {
  if (!section.is_object()) {
    throw std::invalid_argument(origin + ": \"" + name + "\" must be an object, not " +
                                TypeName(section));
  }
  for (const auto& [key, value] : section.items()) {
    const bool known = std::any_of(fields.begin(), fields.end(),
                                   [&key = key](const Field& f) { return key == f.key; }) ||
                       std::find(other_keys.begin(), other_keys.end(), key) != other_keys.end();
    if (!known) throw std::invalid_argument(origin + ": unknown key " + KeyPath(name, key));
  }
  for (const Field& f : fields) {
    if (!section.contains(f.key)) {
      throw std::invalid_argument(origin + ": missing number " + KeyPath(name, f.key));
    }
    const nlohmann::json& value = section.at(f.key);
    if (!value.is_number()) {
      throw std::invalid_argument(origin + ": " + KeyPath(name, f.key) + " must be a number, not " +
                                  TypeName(value));
    }
    *f.value = value.get<double>();
  }
}

std::string ReadText(const nlohmann::json& j, const char* key, const std::string& fallback,
                     const std::string& origin) {
  if (!j.contains(key)) return fallback;
  if (!j.at(key).is_string()) {
    throw std::invalid_argument(origin + ": " + key + " must be a string, not " +
                                TypeName(j.at(key)));
  }
  return j.at(key).get<std::string>();
}

nlohmann::json ParseObject(const std::string& json_text, const std::string& origin,
                           const std::string& what) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(json_text);
  } catch (const nlohmann::json::exception& e) {
    // parse_error, and out_of_range for a number beyond double range (1e400): bad input both.
    throw std::invalid_argument(origin + ": not valid JSON (" + e.what() + ")");
  }
  if (!j.is_object()) throw std::invalid_argument(origin + ": " + what + " is a JSON object");
  return j;
}

bool ReadFile(const std::string& path, std::string* text) {
  std::ifstream file(path);
  if (!file) return false;
  std::stringstream contents;
  contents << file.rdbuf();
  *text = contents.str();
  return true;
}

std::string BuiltinOrFileText(const std::vector<std::pair<std::string, std::string>>& builtin,
                              const std::string& name_or_path, const std::string& what,
                              const std::string& short_what, bool* from_file) {
  if (from_file) *from_file = false;
  for (const auto& [name, json] : builtin) {
    if (name == name_or_path) return json;
  }
  std::string text;
  if (!ReadFile(name_or_path, &text)) {
    std::string known;
    for (const auto& [name, json] : builtin) known += (known.empty() ? "" : ", ") + name;
    throw std::invalid_argument("unknown " + what + " '" + name_or_path + "' (not a built-in " +
                                short_what + ": " + known + "; not a readable file)");
  }
  if (from_file) *from_file = true;
  return text;
}

}  // namespace billiard::params::internal
