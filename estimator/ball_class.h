// The classes of balls the detector tells apart (ball_identity.h), as table_state_t carries them.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace billiard::estimator {

// The ball sets (which classes a frame may hold): pool (the cue ball and 1-15), snooker (the cue
// ball, 15 reds and six colours), carom (the white, the yellow and the red) and English pool,
// "blackball" (the cue ball, seven reds, seven yellows and the black).
enum class BallSet { kPool, kSnooker, kCarom, kBlackball };

// The set a parameter set's balls belong to: "snooker" and "carom" by name, pool otherwise.
BallSet BallSetOf(const std::string& parameter_set_name);

// The set of a name ("pool", "snooker", "carom", "blackball"), or none.
std::optional<BallSet> BallSetNamed(const std::string& name);
inline constexpr const char* kBallSetNames = "pool, snooker, carom, blackball";

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

// The classes of a set's balls, each once, the cue ball first: what ball_identity.h may call a
// ball of the set.
std::vector<BallClass> ClassesIn(BallSet set);

// How many balls of `ball_class` a set holds: snooker's 15 reds, carom's 2 (four-ball games have
// two), English pool's 7 reds and 7 yellows; 1 for every other class of the set, 0 for a class
// not in it.
int CountIn(BallSet set, BallClass ball_class);

// "cue", "1".."15", "red", "yellow", ... or "unknown".
std::string BallClassName(BallClass ball_class);

// The class of `set` whose BallClassName is `name`, or none.
std::optional<BallClass> BallClassNamed(const std::string& name, BallSet set);

// "pool", "snooker", "carom" or "blackball": the name BallSetNamed reads.
std::string BallSetName(BallSet set);

}  // namespace billiard::estimator
