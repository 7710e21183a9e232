// The classes of balls the detector tells apart (ball_identity.h), as table_state_t carries them.
#pragma once

#include <cstdint>
#include <string>

namespace billiard::estimator {

// The ball sets (which classes a frame may hold).
enum class BallSet { kPool, kSnooker, kCarom };

// The set a parameter set's balls belong to: "snooker" and "carom" by name, pool otherwise.
BallSet BallSetOf(const std::string& parameter_set_name);

// A ball's class, with the values table_state_t carries (ball_state_t's CLASS_ constants): kUnknown
// (zero, so that a message filled with zeros claims nothing), pool's numbers 1-15 (1-7 solids, 8
// the black, 9-15 stripes), the cue ball, or one of the named colours of snooker and carom.
enum class BallClass : std::int8_t {
  kUnknown = 0,
  kCue = 16,
  kRed = 20,  // snooker's reds, carom's red
  kYellow = 21,
  kGreen = 22,
  kBrown = 23,
  kBlue = 24,
  kPink = 25,
  kBlack = 26,  // snooker's black
};

// The class of pool ball `number` (1-15).
BallClass PoolBall(int number);

// "cue", "1".."15", "red", "yellow", ... or "unknown".
std::string BallClassName(BallClass ball_class);

}  // namespace billiard::estimator
