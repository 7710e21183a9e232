// The robot's execution noise as data: how far a stroke actually played strays from the stroke
// asked for. The built-in models are the JSON files of noise/ (compiled into the library, like
// the parameter sets); a file of the same format is read at run time.
//
//   {"name": "robot", "source": "...", "speed_fraction": 0.01, "speed_mps": 0,
//    "heading_deg": 0.1, "tip_mm": 0.5, "elevation_deg": 0}
//
// Each number is the standard deviation of an independent zero-mean normal error: the cue speed
// relative to itself (speed_fraction) and absolute (speed_mps), the heading, each of the two tip
// offsets (side and height), and the cue's elevation.
//
// "robot" (kDefaultNoise) is the noise the table simulator executes with (table_sim_node
// --noise on) and the one the shot choice (planner/choice/) plans for: one definition, read by
// both. "computational-pool" is the noise of the computational pool tournaments, cited in its
// file.
//
// Module: billiard::params.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"

namespace billiard::params {

// The noise the table simulator executes with and the shot choice assumes by default.
inline constexpr char kDefaultNoise[] = "robot";

// Standard deviations, in SI units (the files are in degrees and millimetres).
struct ExecutionNoise {
  std::string name;
  std::string source;
  double speed = 0.0;           // relative to the cue speed
  double speed_absolute = 0.0;  // [m/s]
  double heading = 0.0;         // [rad]
  double tip_offset = 0.0;      // of each tip offset [m]
  double elevation = 0.0;       // [rad]
};

// "computational-pool", "robot".
std::vector<std::string> BuiltinNoiseNames();

// A built-in model by name or a JSON file by path. Throws std::invalid_argument with a one-line
// reason on an unknown name, an unreadable file, an unknown or missing key, or a spread that is
// negative or not finite.
ExecutionNoise LoadNoise(const std::string& name_or_path);
ExecutionNoise ParseNoise(const std::string& json_text, const std::string& origin);

// `stroke` as the robot plays it: each spread times a standard normal number from
// `unit_normal`, drawn in a fixed order (speed, heading, tip side, tip height, then the
// elevation and the absolute speed only where their spread is not zero, so that a model without
// them draws what the table simulator always drew). The tip is kept on the ball (within 0.95
// of its radius: past the edge the cue would miss it) and the elevation folded at the
// horizontal (the cue cannot strike from below the ball).
physics::CueStroke Perturbed(physics::CueStroke stroke, const ExecutionNoise& noise,
                             double ball_radius, const std::function<double()>& unit_normal);

}  // namespace billiard::params
