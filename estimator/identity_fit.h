// Identity's parameters (identity_parameters.h) fitted by code from balls whose classes are known,
// instead of set by looking at frames: `billiard bench-detect --cross-validate` fits them on some
// cameras' labelled balls and measures them on another camera's (issue 45).
//
//   - Each share threshold is the decision stump between the balls that should be at least it
//     and those that should be below it (the fewest on the wrong side, at the middle of the widest
//     gap among the thresholds that tie): `cue_white` between the cue balls' white share and every
//     other ball's but a stripe's (whose caps are white); `cue_colour` between the cue balls'
//     coloured share and the coloured balls'; `black_share` between the black balls' black share
//     and the coloured balls'; `stripe_plain` between the pool stripes' plain share and the
//     solids'. A threshold with fewer than kMinBallsPerSide balls on a side keeps the prior's.
//   - A class's colours are its sources' (cameras') median colours, one per source that showed
//     it, the nearest counting as the hand-set table's several colours do (a TV set's pink 4 and
//     another's purple one stay apart, where one median of both would be neither). The colour of
//     a ball is the one it is judged by under the fitted thresholds (JudgedColour: a stripe seen
//     cap on by its band). A class no training ball shows keeps the prior's colours.
#pragma once

#include <optional>
#include <vector>

#include "estimator/ball_class.h"
#include "estimator/ball_identity.h"
#include "estimator/identity_parameters.h"

namespace billiard::estimator {

// What a label may say of a pool ball whose number cannot be read: its group.
enum class PoolGroup { kNone, kSolid, kStripe };

// A ball whose class is known, as a frame showed it.
struct KnownBall {
  BallLook look;
  BallSet set = BallSet::kPool;
  // Its class, or kUnknown with its `group` where only that is known.
  BallClass ball_class = BallClass::kUnknown;
  PoolGroup group = PoolGroup::kNone;
  int source = 0;  // the camera, or the source of frames, it was seen by
};

inline constexpr int kMinBallsPerSide = 3;

struct IdentityFit {
  IdentityParameters parameters;
  // Which thresholds were fitted (the others are the prior's).
  bool cue_white = false, cue_colour = false, black_share = false, stripe_plain = false;
  // The colour classes given their sources' colours, and those that kept the prior's.
  int classes_fitted = 0, classes_kept = 0;
};

IdentityFit FitIdentity(const std::vector<KnownBall>& balls, const IdentityParameters& prior);

// The threshold with the fewest of `above` below it and of `below` at or above it, at the middle
// of the widest gap between neighbouring values among those that tie (the lowest of equal gaps);
// none when either side is empty.
std::optional<double> SplitShares(const std::vector<double>& above,
                                  const std::vector<double>& below);

}  // namespace billiard::estimator
