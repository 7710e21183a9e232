// Where a replayed message first differs from the recorded one, field by field, so that a replay
// that differs says what changed and not only that something did.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"

namespace billiard::cli {

// A field named as in its .lcm file, with indices ("balls[0].position[1]", "heading"), and its
// two values.
struct FieldDifference {
  std::string field;
  nlohmann::json recorded, replayed;
};

// The first field, in the order of the message's definition, whose values differ. Numbers are
// compared bit for bit, as the encoded bytes are: -0.0 is not 0.0. Nothing when all are the same.
std::optional<FieldDifference> FirstFieldDifference(const table_state_t& recorded,
                                                    const table_state_t& replayed);

// Every field but solve_us, the planning wall time, which no replay reproduces.
std::optional<FieldDifference> FirstFieldDifference(const cue_command_t& recorded,
                                                    const cue_command_t& replayed);

}  // namespace billiard::cli
