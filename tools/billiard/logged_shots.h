// The shots of a recorded loop (an LCM log of run_loop.sh --log), cut by
// shot_fit::ShotRecorder: each commanded strike (CUE_COMMAND, status ok) the start of one, the
// estimator's TABLE_STATE tracks its samples. `billiard identify` fits the physics to them,
// `billiard identify-noise` the robot's execution noise (with the commands kept).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lcmtypes/billiard/cue_command_t.hpp"
#include "sim/shot_fit/tracked_shot.h"

namespace billiard::cli {

// With `truth`, the samples are the table simulator's TABLE_TRUTH instead, the struck ball the
// true one nearest the struck track: the same shots without the estimator, which tells what
// the tracking adds to the fits' error.
struct LoggedShots {
  std::vector<shot_fit::TrackedShot> shots;
  std::vector<std::int64_t> strike_utimes;  // per shot, of the command that struck it
  std::vector<cue_command_t> commands;      // every ok command, in the log's order
  long events = 0, states = 0, strikes = 0, refused = 0, undecodable = 0;
  int skipped = 0;  // strikes that started no shot (ShotRecorder::skipped)
};

// Throws UsageError (command_line.h) for a log that cannot be read, is empty, or holds no shot.
LoggedShots ReadLoggedShots(const std::string& path, bool truth);

}  // namespace billiard::cli
