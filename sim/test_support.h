// Shared fixtures of the physics tests: the paper's parameters and initial states.
#pragma once

#include <array>

#include "ball_state.h"
#include "parameters.h"

namespace billiard::testing {

inline ModelParameters PaperParameters() { return LoadParameters("paper"); }

// X = Y = 0, vx = 0, vy = 1 m/s and the spins of Figs. 6-10 of seed 000.
inline std::array<BallState, 5> PaperFigureStates() {
  return {MakeBallState(0, 0, 0, 1, -50, 0, 0), MakeBallState(0, 0, 0, 1, -50, 5, 0),
          MakeBallState(0, 0, 0, 1, 150, 5, 0), MakeBallState(0, 0, 0, 1, -50, -3.5, -150),
          MakeBallState(0, 0, 0, 1, 150, 0, -150)};
}

}  // namespace billiard::testing
