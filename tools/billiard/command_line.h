// Helpers shared by the billiard subcommands: strict number parsing and one-line errors.
#pragma once

#include <functional>
#include <optional>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "planner/game/game_json.h"
#include "sim/cue/clearance.h"
#include "sim/cue/robot.h"
#include "sim/physics/ball_state.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"

namespace billiard::cli {

// A user error: printed as one line, exit status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Not a failure of the tool: the command ran and its answer is no (a refused plan), already
// printed. what() is the one-line reason for stderr; exit status 3.
struct Refused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The command has already said why it failed (on stderr); the tool exits with `status`.
struct ExitStatus : std::runtime_error {
  explicit ExitStatus(int status)
      : std::runtime_error("exit status " + std::to_string(status)), status(status) {}
  int status;
};

// Parses exactly `count` comma-separated finite numbers; `what` names them in the error.
std::vector<double> ParseNumberList(const std::string& text, std::size_t count,
                                    const std::string& what);

// Throws UsageError unless value is finite.
void RequireFinite(double value, const std::string& what);

// The name of `names` nearest `word` by edit distance (insertions, deletions and substitutions
// of one character each; Levenshtein 1966), the first of equals; "" when none is within
// `max_edits`. For "did you mean" after a mistyped name, and no guess at an unrelated one.
std::string NearestName(const std::string& word, const std::vector<std::string>& names,
                        std::size_t max_edits);

// "params": the set's name, and "params_file": the file it came from (when not built in).
void DescribeParameters(const physics::ModelParameters& p, nlohmann::json* j);

// A cue stroke as `plan`, `plan-pot` and `play` print it (the object a scene's "cue" reads), and
// its clearance (sim/cue/clearance.h) beside it: one writer with the Python module's.
using game::ClearanceJson;
using game::CueStrokeJson;

// `value` rounded to `decimals` places as text, and "0" where it rounds to zero: a player reads
// "0 mm", not "-1.73472e-18 m" or "-0.000".
std::string Fixed(double value, int decimals);

// A stroke in the units a player reads: "speed 1.234 m/s, heading 45.00 deg, tip 3.0 mm right
// and 12.0 mm below centre, elevation 0 deg" (the heading from +x counterclockwise, in
// (-180, 180]; the tip offsets as the player sees the cue ball from behind the cue).
std::string StrokeInWords(const physics::CueStroke& stroke);

// Makes the directory `dir` of an option (as the report writers would) and checks that files can
// be made in it; UsageError naming `option` if not. Called before a run of minutes, so that a
// mistyped path is said at once instead of after the work.
void RequireWritableDirectory(const std::string& dir, const std::string& option);

// The parameter set of a --params option (a built-in name or a JSON file); UsageError if it
// does not load.
physics::ModelParameters LoadParametersOption(const std::string& name_or_path);

// The robot of a --robot option (a built-in name, params::RobotNames(), or a JSON file);
// UsageError if it does not load.
cue::Robot LoadRobotOption(const std::string& name_or_path);

// The benchmarks' --robot: a robot as LoadRobotOption loads it, or none for "none" (the level
// cue, unchecked: the figures before robots, to compare with).
std::optional<cue::Robot> LoadRobotOrNone(const std::string& name_or_path);

// The help of every planning command's --robot option.
inline constexpr char kRobotHelp[] =
    "The robot whose cue plays the strokes: gantry | player | FILE (sim/params/robots/): every "
    "stroke is planned at the elevation its cue needs to clear the balls, the rails and its body";

// The most rows a trajectory file gets: a sample every 10 us of a 10 s shot, far finer than the
// integrator's steps (about a hundred a shot), and at 130 to 180 bytes a row about 150 MB. A
// --sample-dt of 1e-9 would otherwise write gigabytes.
inline constexpr double kMaxTrajectoryRows = 1e6;

// Samples at 0, dt, 2 dt, ... and at t_end itself; a double, as a tiny dt overflows any integer.
double TrajectorySamples(double t_end, double dt);

// Refuses (UsageError), before any file is made, a trajectory of `balls` rows per sample that
// would hold more than kMaxTrajectoryRows rows.
void RequireTrajectoryWithinLimit(double t_end, double dt, int balls = 1);

// Writes the trajectory CSV "t,[id,]X,Y,vx,vy,wx,wy,wz": at t = 0, dt, ..., t_end a row of each
// of `balls` balls, `state(t, k)` for ball k (and its `id(k)`, a column only when given). Refuses
// (UsageError) too many rows or a file it cannot make.
void WriteTrajectoryCsv(const std::string& path, double t_end, double dt, int balls,
                        const std::function<physics::BallState(double t, int k)>& state,
                        const std::function<int(int k)>& id = nullptr);

}  // namespace billiard::cli
