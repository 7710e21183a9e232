// Physical and contact parameters of a ball on a cloth, as named data sets.
//
// The contact parameters follow Kudra et al. 2016: the patch radius a (the paper's \hat a), the
// Coulomb coefficient mu, the rolling-resistance parameter d (shift of the pressure centre,
// eq. 1), the regularization parameters eps_t and eps_r (eqs. 14-17) and the approximation's
// fitted constants b_T, m_T, b_M, m_M (eq. 17). The closed-form model (Jaroukh 2019) reads the
// same set: mu_s = mu and mu_r = a d / (5 r) (shared/docs/physics-notes.md, section 2).
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace billiard::physics {

struct BallParameters {
  double radius = 0.0;   // r [m]
  double mass = 0.0;     // m [kg]
  double gravity = 0.0;  // g [m/s^2]
};

struct ContactParameters {
  double patch_radius = 0.0;  // a [m]
  double mu = 0.0;            // Coulomb friction coefficient, >= a d / (5 r)
  double d = 0.0;             // rolling resistance parameter, 0 <= d <= 1
  double eps_t = 0.0;         // friction regularization (dimensionless)
  double eps_r = 0.0;         // rolling-resistance regularization (dimensionless)
  double b_t = 0.0, m_t = 2.0;
  double b_m = 0.0, m_m = 2.0;
};

// The robot's cue (Alciatore, The Illustrated Principles of Pool and Billiards, TP A.30).
struct CueParameters {
  double mass = 0.0;             // M [kg]
  double tip_restitution = 0.0;  // e, 0..1
  double max_tip_offset = 0.0;   // largest tip offset from the ball centre, as a fraction of r
  double max_speed = 0.0;        // fastest cue stroke the robot gives [m/s]
  // m_e [kg]: the mass of the shaft's tip end that moves sideways with the ball during the impact
  // (Alciatore, TP A.31; Shepard 2001), which sets the squirt: about 5-7 g for a low-deflection
  // shaft, 10-12 g for a standard one.
  double end_mass = 0.0;
};

// Impacts between two balls and of a ball with a cushion (sim/table/).
struct CollisionParameters {
  double ball_restitution = 0.0;  // e_b, normal restitution between two balls, 0..1
  // Ball-ball sliding friction against the relative speed v of the contact points,
  // mu_b = a + b exp(-c v): Alciatore's fit (TP A.14) to the throw measurements of Marlow 1995.
  double ball_friction_a = 0.0;      // [-]
  double ball_friction_b = 0.0;      // [-]
  double ball_friction_c = 0.0;      // [s/m]
  double cushion_restitution = 0.0;  // e_e, ball-cushion, 0..1
  double cushion_friction = 0.0;     // mu_w, ball-cushion sliding friction
};

// The playing surface: origin at a corner, x along the long side [m].
struct TableParameters {
  double length = 0.0;
  double width = 0.0;
};

// How well a set's constants are known: standard deviations of named constants, each named by
// its key in the set's files ("collision.cushion_restitution"), and where they come from. The
// physics does not read them; the shot choice draws the table's constants from them
// (sim/params/constants_uncertainty.h) as it draws the robot's noise.
struct ConstantsUncertainty {
  std::string source;
  std::vector<std::pair<std::string, double>> sd;  // key, standard deviation (>= 0)
};

struct ModelParameters {
  std::string name;
  std::string source;  // where the numbers come from
  std::string file;    // the file the set was read from; empty for a built-in set
  BallParameters ball;
  ContactParameters contact;
  CueParameters cue;
  CollisionParameters collision;
  TableParameters table;
  ConstantsUncertainty uncertainty;  // empty: the constants taken as exact

  // Rolling-resistance coefficient of the closed-form model that matches this contact.
  double RollingResistance() const {
    return contact.patch_radius * contact.d / (5.0 * ball.radius);
  }
};

// Throws std::invalid_argument, with a one-line reason, if a value is non-finite or outside its
// physical range, or if mu is below the rolling resistance a d / (5 r) (the contact would create
// energy). mu = 0 with d = 0, d = 0, and eps_t, eps_r as small as 1e-9 are valid.
void ValidateParameters(const ModelParameters& p);

// Every number of a set, in a fixed order (ball, contact, cue, collision, table): what
// makes two sets the same physics whatever their names.
inline constexpr std::size_t kParameterCount = 25;
std::array<double, kParameterCount> ParameterValues(const ModelParameters& p);

}  // namespace billiard::physics
