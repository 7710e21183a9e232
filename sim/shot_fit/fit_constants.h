// The shared constants a shot fit may identify (shot_fit.h's FitShots): the cloth's sliding
// friction and rolling resistance, the pivot friction's lever, the cushions' restitution and
// friction and the balls' restitution. Each has a name (the command line's), a range the fits
// search, and a place in the parameter set (sim/physics/parameters.h) it is read from and written
// into.
//
// Module: billiard::shot_fit.
#pragma once

#include <string>
#include <vector>

#include "sim/physics/parameters.h"

namespace billiard::shot_fit {

// The shared constants a fit may identify:
//   kMu               "mu": the cloth's sliding friction mu (contact.mu);
//   kRolling          "rolling": the rolling resistance mu_r = a d / (5 r) (d follows, a kept;
//                     where d would pass 1, d = 1 and a = 5 r mu_r);
//   kSpin             "spin": the contact patch radius a, the lever of the pivot friction that
//                     stops side spin (ClothParameters::spin_decel; mu_r kept, d follows);
//   kCushion          "cushion": the ball-cushion restitution e_e;
//   kCushionFriction  "cushion_friction": the ball-cushion friction mu_w;
//   kBallBall         "ball_ball": the ball-ball restitution e_b.
enum class Constant { kMu, kRolling, kSpin, kCushion, kCushionFriction, kBallBall };

const char* ConstantName(Constant constant);
// Reads "mu,rolling,..." (the names above, comma-separated, no repeats); throws
// std::invalid_argument naming an unknown or repeated name.
std::vector<Constant> ParseConstants(const std::string& list);
double ConstantValue(const physics::ModelParameters& p, Constant constant);
// `p` with the constants set to `values` (in the order of `constants`; spin before rolling).
physics::ModelParameters WithConstants(const physics::ModelParameters& p,
                                       const std::vector<Constant>& constants,
                                       const std::vector<double>& values);

// The range the fit searches for each constant (far beyond any cloth, cushion or ball).
struct Range {
  double lo, hi;
};
Range ConstantRange(Constant c);

}  // namespace billiard::shot_fit
