// The balls `billiard detect --calib` found, as a scene (sim/params/scene_file.h) that `simulate
// --scene`, `plan-pot --scene` and `choose-shot --scene` read: every ball at rest where it was
// found, its id its class where known (pool: 0 the cue ball, 1-15 its number), else the next id
// from 16 not taken (snooker's and carom's colours, a ball not named, a second ball of a class
// the set has one of).
//
// A position measured in a frame is good to a few millimetres (the calibration, the cushions'
// height, the ball's outline), so a ball found up to kSnapM off the playing surface (frozen to a
// cushion) is put on it, and two balls found up to kSnapM into each other (touching) are moved
// apart along their line to touching. A ball further off (in a pocket's jaws, on a rail) is left
// out, said in the notes; balls further into each other make no scene (table::ValidateScene's
// reason).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "estimator/ball_class.h"
#include "sim/params/scene_file.h"
#include "sim/table/table_geometry.h"

namespace billiard::cli {

// How far off the surface, or into another ball, a measured position is taken for a ball's
// there [m].
inline constexpr double kSnapM = 0.005;

struct DetectedBall {
  Eigen::Vector2d xy;  // on the table [m]
  estimator::BallClass ball_class = estimator::BallClass::kUnknown;
};

// The scene of `balls` on `table` (named `table_name`) with parameter set `params_name` and balls
// of `radius` [m]; `notes` gets one line per ball left out. Throws
// std::invalid_argument (table::ValidateScene's reason) when the balls make no scene.
params::SceneFile DetectedScene(const std::vector<DetectedBall>& balls,
                                const table::TableGeometry& table, const std::string& table_name,
                                const std::string& params_name, double radius,
                                std::vector<std::string>* notes);

}  // namespace billiard::cli
