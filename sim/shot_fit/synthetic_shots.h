// Shots whose truth is known: scenes simulated (shot_model.h) and tracked as a camera would track
// them, sampled at a frame rate with Gaussian noise and thinned as the real recordings are
// (shared/data/real-shots/). The fits' tests and `billiard bench-shot-fit` recover the strikes
// and the constants they were made with.
//
// Module: billiard::shot_fit.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sim/physics/parameters.h"
#include "sim/shot_fit/shot_model.h"
#include "sim/shot_fit/tracked_shot.h"
#include "sim/table/table_geometry.h"

namespace billiard::shot_fit {

// A shot as a camera would track it from the simulation: the balls at `starts` (index `cue`
// struck by `strike`), each sampled every `period` from 0 to `duration` with Gaussian noise of
// standard deviation `noise` [m] per coordinate (seeded by `seed`), thinned as the real
// recordings are: a sample is kept where the ball moved at least `thinning` [m] from the last
// kept one, and the first and the last are always kept.
TrackedShot SimulateTrackedShot(const table::TableGeometry& table,
                                const physics::ModelParameters& params,
                                const std::vector<Eigen::Vector2d>& starts, std::size_t cue,
                                const Strike& strike, double duration, double period, double noise,
                                double thinning, std::uint64_t seed);

// The frame period of the synthetic shots: the real recordings' 50 Hz [s].
inline constexpr double kSyntheticPeriod = 0.02;

// A synthetic shot before it is tracked: where its balls start, and how ball 0 is struck.
struct SyntheticScene {
  std::vector<Eigen::Vector2d> starts;
  Strike strike;
};

// `count` random strikes (cue speed 2-4 m/s, any heading, tip offsets within 0.4 r, the impact
// within the first frame period) of one of three balls placed at random, clear of each other
// and of the cushions (seeded by `seed`).
std::vector<SyntheticScene> SyntheticScenes(const table::TableGeometry& table, double ball_radius,
                                            int count, std::uint64_t seed);

// `count` strokes as the loop's shots to a point are (table_sim_node --spins): one ball at
// rest, placed at random a third of the table clear of the cushions, cue speeds 0.25-0.6 m/s,
// any heading, no side, the tip heights of the spin styles in turn (natural, stun, follow, draw:
// 0.4, 0, 0.2 and -0.4 r; the planner's SpinRatio over 5/2), the impact within the first frame
// period (seeded by `seed`). With `natural_only`, every stroke at the natural roll's height.
std::vector<SyntheticScene> LoopScenes(const table::TableGeometry& table, double ball_radius,
                                       int count, std::uint64_t seed, bool natural_only = false);

// The `count` SyntheticScenes simulated with `params` for 8 s and tracked by
// SimulateTrackedShot as the real recordings are: 50 Hz, 1 mm of noise, thinned where a ball
// moved less than 2 mm. Ball 0 is struck.
std::vector<TrackedShot> SyntheticShots(const table::TableGeometry& table,
                                        const physics::ModelParameters& params, int count,
                                        std::uint64_t seed);

}  // namespace billiard::shot_fit
