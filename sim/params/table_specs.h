// Tables as data: the built-in table specifications (sim/params/tables/*.json, compiled into the
// library like the parameter sets) and files of the same format read at run time.
//
// The format: a JSON object with the strings "name" (default: the built-in name or the path)
// and "source" (where every number comes from), the numbers "length", "width" and
// "cushion_height" [m], and the optional objects "corner" and "side", each with the numbers
// "mouth" [m], "jaw_angle" [deg], "jaw_radius" [m] and "capture_depth" [m]
// (table::TableSpec). A table without pockets (carom) has neither object. The optional object
// "rail" has the numbers "height" and "width" [m] (TableSpec::RailSpec): every built-in table
// has one; a file without one (written before rails were data) still loads.
//
// Module: billiard::params. Includes the physics and the table (sim/table/).
#pragma once

#include <string>
#include <vector>

#include "sim/table/table_geometry.h"

namespace billiard::params {

// The table a command, a node or a binding plays on unless told another: the built-in 9-ft pool
// table (WPA's tournament size).
inline constexpr char kDefaultTable[] = "pool-9ft";

// The names of the built-in tables: "carom-10ft", "pool-7ft", "pool-8ft", "pool-9ft",
// "snooker-12ft".
std::vector<std::string> TableNames();

// A built-in table by name, or a JSON file by path. Throws std::invalid_argument with a one-line
// reason on an unknown name, an unreadable file, invalid JSON, an unknown key, a missing number
// or a value of the wrong type (naming the key: "t.json: unknown key corner.mouthh"), or a
// specification that does not make a table (table::BuildTable's checks).
table::TableSpec LoadTableSpec(const std::string& name_or_path);

// Parses a table specification from JSON text; `origin` names it in the refusals.
table::TableSpec ParseTableSpec(const std::string& json_text, const std::string& origin);

}  // namespace billiard::params
