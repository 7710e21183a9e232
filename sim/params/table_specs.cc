#include "sim/params/table_specs.h"

#include <stdexcept>

#include "sim/params/strict_json.h"

namespace billiard::params {

namespace internal {
const std::vector<std::pair<std::string, std::string>>& BuiltinTableJson();
}

using table::TableSpec;

std::vector<std::string> TableNames() {
  std::vector<std::string> names;
  for (const auto& [name, json] : internal::BuiltinTableJson()) names.push_back(name);
  return names;
}

namespace {

// A pocket object ("corner" or "side"), if there.
std::optional<TableSpec::PocketSpec> ReadPocket(const nlohmann::json& j, const char* key,
                                                const std::string& origin) {
  if (!j.contains(key)) return std::nullopt;
  TableSpec::PocketSpec p;
  internal::ReadSection(j.at(key), key,
                        {{"mouth", &p.mouth},
                         {"jaw_angle", &p.jaw_angle},
                         {"jaw_radius", &p.jaw_radius},
                         {"capture_depth", &p.capture_depth}},
                        origin);
  return p;
}

// The rail object, if there.
std::optional<TableSpec::RailSpec> ReadRail(const nlohmann::json& j, const std::string& origin) {
  if (!j.contains("rail")) return std::nullopt;
  TableSpec::RailSpec rail;
  internal::ReadSection(j.at("rail"), "rail", {{"height", &rail.height}, {"width", &rail.width}},
                        origin);
  return rail;
}

}  // namespace

TableSpec ParseTableSpec(const std::string& json_text, const std::string& origin) {
  const nlohmann::json j = internal::ParseObject(json_text, origin, "a table specification");
  TableSpec spec;
  internal::ReadSection(
      j, "",
      {{"length", &spec.length}, {"width", &spec.width}, {"cushion_height", &spec.cushion_height}},
      origin, {"name", "source", "corner", "side", "rail"});
  spec.name = internal::ReadText(j, "name", origin, origin);
  spec.source = internal::ReadText(j, "source", "", origin);
  spec.corner = ReadPocket(j, "corner", origin);
  spec.side = ReadPocket(j, "side", origin);
  spec.rail = ReadRail(j, origin);
  try {
    table::BuildTable(spec);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(origin + ": " + e.what());
  }
  return spec;
}

TableSpec LoadTableSpec(const std::string& name_or_path) {
  return ParseTableSpec(
      internal::BuiltinOrFileText(internal::BuiltinTableJson(), name_or_path, "table", "table"),
      name_or_path);
}

}  // namespace billiard::params
