// The balls of a scene as every step of the choice reads them: one found by its id, where it
// lies, and the cue ball placed (ball in hand).
//
// Module: billiard::choice.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "sim/table/scene.h"

namespace billiard::choice {

// The ball `id` of `balls`, nullptr when it is not on the table.
const table::SceneBall* FindBall(const std::vector<table::SceneBall>& balls, int id);

// Where `b` lies on the table.
Eigen::Vector2d Position(const table::SceneBall& b);

// `balls` with the cue ball (id 0) lifted, if there, and placed at `place`, first.
std::vector<table::SceneBall> WithCueBallAt(std::vector<table::SceneBall> balls,
                                            const Eigen::Vector2d& place);

}  // namespace billiard::choice
