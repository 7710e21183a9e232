// The robot's execution noise learned from its own strokes as it plays (planner_node
// --learn-noise, `billiard identify-noise`): each commanded stroke paired with the shot the
// estimator tracked after it (sim/shot_fit/shot_recorder.h cuts them, by the strike's utime),
// the launch measured from the first frames (sim/shot_fit/launch_fit.h) and held against the
// stroke, and the spreads fitted over all the shots so far (sim/shot_fit/execution_noise_fit.h:
// the tracking's error subtracted, each spread with its 95 % interval). The choice then plans
// for the noise learned: the prior (what it was told) with the spreads the shots identify.
//
// Only strokes from where the ball lay are learned from: a stroke after a placement in hand
// starts from where the robot put the ball, which the tracks before it do not show.
//
// Module: billiard::planner_node.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lcmtypes/billiard/cue_command_t.hpp"
#include "sim/params/execution_noise.h"
#include "sim/physics/parameters.h"
#include "sim/shot_fit/execution_noise_fit.h"
#include "sim/shot_fit/tracked_shot.h"

namespace billiard::planner_node {

// The choice's noise is replaced by a learned one from this many measured launches on.
inline constexpr std::size_t kMinNoiseShots = 10;

class NoiseLearner {
 public:
  explicit NoiseLearner(params::ExecutionNoise prior);

  // An answer the node sent: an ok stroke not from a placement is remembered by its utime.
  void Commanded(const cue_command_t& command);

  // The shots closed so far (`shots`, each struck at strike_utimes[i]): those not seen before
  // are measured; with kMinNoiseShots launches or more, the noise is fitted again. Returns
  // whether it was.
  bool Learn(const std::vector<shot_fit::TrackedShot>& shots,
             const std::vector<std::int64_t>& strike_utimes, const physics::ModelParameters& p);

  // The noise to plan for: the prior until enough launches, then the learned one.
  const params::ExecutionNoise& noise() const { return noise_; }
  const std::optional<shot_fit::NoiseFit>& fit() const { return fit_; }
  // Shots looked at, and those whose launch could not be measured (why, counted by reason).
  std::size_t shots_seen() const { return seen_; }
  const std::map<std::string, int>& unmeasured() const { return unmeasured_; }
  std::size_t launches() const { return residuals_.size(); }
  // The index, among the shots given to Learn, of the shot each launch was measured on: the
  // fit's `used` are indices of launches.
  const std::vector<std::size_t>& launch_shots() const { return launch_shots_; }

  // The latest fit in one line: each spread, its interval, the shots used.
  std::string Describe() const;

 private:
  params::ExecutionNoise prior_, noise_;
  std::map<std::int64_t, physics::CueStroke> strokes_;  // by the command's utime
  std::vector<shot_fit::LaunchResidual> residuals_;
  std::vector<std::size_t> launch_shots_;
  std::optional<shot_fit::NoiseFit> fit_;
  std::size_t seen_ = 0;
  std::map<std::string, int> unmeasured_;
};

}  // namespace billiard::planner_node
