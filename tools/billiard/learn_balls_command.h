#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

// `billiard learn-balls IMAGE --balls FILE --out MODEL.json`: this rig's look of its balls
// (estimator/ball_model.h) from a frame whose balls FILE names: a JSON list of
// {"id": "cue" | "1".."15" | "red" | ..., "u": px, "v": px}, or {"id", "x": m, "y": m} on the table
// with --calib. A FILE that is not such a list, a ball listed twice or beyond the set's count, and
// two listed on one ball are usage errors (2); a frame without a table, or in which no listed ball
// is found, is refused (3, nothing written); a listed ball not found is said on stderr and left
// out (its class keeps the hand-set colours).
void AddLearnBallsCommand(CLI::App& app);

}  // namespace billiard::cli
