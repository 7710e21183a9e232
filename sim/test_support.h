// Shared fixtures of the physics tests: the paper's parameters and initial states.
#pragma once

#include <gtest/gtest.h>

#include <array>

#include "ball_state.h"
#include "parameters.h"
#include "trajectory.h"

namespace billiard::testing {

inline ModelParameters PaperParameters() { return LoadParameters("paper"); }

// X = Y = 0, vx = 0, vy = 1 m/s and the spins of Figs. 6-10 of seed 000.
inline std::array<BallState, 5> PaperFigureStates() {
  return {MakeBallState(0, 0, 0, 1, -50, 0, 0), MakeBallState(0, 0, 0, 1, -50, 5, 0),
          MakeBallState(0, 0, 0, 1, 150, 5, 0), MakeBallState(0, 0, 0, 1, -50, -3.5, -150),
          MakeBallState(0, 0, 0, 1, 150, 0, -150)};
}

// Samples the trajectory at `samples` equal intervals of (0, t_end] and expects every state to be
// finite and the kinetic energy never to rise by more than previous * rel_slack + abs_slack.
inline void ExpectEnergyNeverRises(const Trajectory& trajectory, const ModelParameters& p,
                                   double t_end, int samples, double abs_slack,
                                   double rel_slack = 0.0) {
  double previous = KineticEnergy(trajectory.At(0.0), p.ball.mass, p.ball.radius);
  for (int i = 1; i <= samples; ++i) {
    const double t = t_end * i / samples;
    const BallState s = trajectory.At(t);
    ASSERT_TRUE(s.allFinite()) << "t = " << t;
    const double e = KineticEnergy(s, p.ball.mass, p.ball.radius);
    EXPECT_LE(e, previous * (1 + rel_slack) + abs_slack) << "t = " << t;
    previous = e;
  }
}

}  // namespace billiard::testing
