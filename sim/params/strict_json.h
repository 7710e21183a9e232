// The strict reading shared by the parameter sets and the table specifications: every key
// known, every number there, every value of its type; a refusal names the key.
//
// Internal to sim/params (its .cc files alone include it).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace billiard::params::internal {

// A number of an object: its key, and where it goes.
struct Field {
  const char* key;
  double* value;
};

// The JSON type of `j` in words, for the refusals.
std::string TypeName(const nlohmann::json& j);

// Reads the numbers `fields` of the object `section` (called `name`, "" at the top level):
// every key must be a field or one of `other_keys` (read by the caller), every field there and
// a number. Throws std::invalid_argument ("origin: unknown key contact.muu").
void ReadSection(const nlohmann::json& section, const std::string& name,
                 const std::vector<Field>& fields, const std::string& origin,
                 const std::vector<std::string>& other_keys = {});

// An optional string at the top level of `j`, or `fallback`.
std::string ReadText(const nlohmann::json& j, const char* key, const std::string& fallback,
                     const std::string& origin);

// Parses `json_text` as a JSON object; refuses invalid JSON and non-objects, naming `what`.
nlohmann::json ParseObject(const std::string& json_text, const std::string& origin,
                           const std::string& what);

// Reads the file at `path` into `text`; false when it cannot be opened.
bool ReadFile(const std::string& path, std::string* text);

// The JSON text of the built-in entry named `name_or_path`, else of the file at that path
// (*from_file, when given, says which). Throws std::invalid_argument when it is neither:
// "unknown `what` 'x' (not a built-in `short_what`: a, b; not a readable file)".
std::string BuiltinOrFileText(const std::vector<std::pair<std::string, std::string>>& builtin,
                              const std::string& name_or_path, const std::string& what,
                              const std::string& short_what, bool* from_file = nullptr);

}  // namespace billiard::params::internal
