// Robots as data: the built-in robots (sim/params/robots/*.json, compiled into the library like
// the tables) and files of the same format read at run time, as cue::Robot (sim/cue/robot.h
// says what each number means and how the body is checked).
//
//   {"name": "gantry", "source": "...",
//    "cue": {"length": 0.5, "tip_radius": 0.0065, "butt_radius": 0.0094},
//    "bridge": 0.15,
//    "elevation_deg": {"min": 0, "max": 60},
//    "max_tip_offset": 0.5,
//    "speed_mps": {"min": 0, "max": 8},
//    "gantry": {"overhang": 0.6, "clearance": 0.008},
//    "noise": "robot"}
//
// Lengths in metres, the elevation in degrees, speeds in m/s, max_tip_offset a fraction of the
// ball's radius. The body is the optional object "gantry" (the numbers "overhang" and
// "clearance") or "arm" (the numbers "base_x", "base_y", "base_z" in the table frame and
// "reach"); a player has neither. "name" defaults to the built-in name or the path; "source"
// says where every number comes from.
//
// The noise is named, not embedded: "noise" is a built-in noise model's name (noise/*.json) or
// a noise file's path, relative to the robot file's folder when relative. One noise model so
// stays one definition, read by the table simulator (--noise) and by the robot alike, and a
// noise measured on a robot is a file of its own beside it. LoadRobot checks that it loads and
// gives it as a path params::LoadNoise reads from anywhere.
//
// "gantry" (kDefaultRobot) is the table simulator's robot, whose limits and noise are the ones
// the planner and the table simulator used before robots were data; "player" is a person with a
// standard cue, what computational pool assumes.
//
// Module: billiard::params.
#pragma once

#include <string>
#include <vector>

#include "sim/cue/robot.h"

namespace billiard::params {

inline constexpr char kDefaultRobot[] = "gantry";

// The names of the built-in robots: "gantry", "player".
std::vector<std::string> RobotNames();

// A built-in robot by name, or a JSON file by path. Throws std::invalid_argument with a one-line
// reason naming the file and the key on an unknown name, an unreadable file, invalid JSON, an
// unknown key, a missing number, a value of the wrong type ("r.json: unknown key cue.lenght"),
// a robot cue::ValidateRobot refuses ("r.json: bridge must be in [0, cue.length]"), or a noise
// that does not load ("r.json: noise: unknown noise model 'x' (...)").
cue::Robot LoadRobot(const std::string& name_or_path);

// Parses a robot from JSON text; `origin` names it in the refusals, `folder` is where a relative
// noise path is found ("" for the working directory).
cue::Robot ParseRobot(const std::string& json_text, const std::string& origin,
                      const std::string& folder = "");

}  // namespace billiard::params
