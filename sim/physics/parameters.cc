#include "sim/physics/parameters.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace billiard::physics {

namespace {

// `what` is a C string so that a passing check allocates nothing: every 5-DOF simulation
// validates its parameters (650 ns with std::string, 60 ns without).
void Require(bool ok, const std::string& name, const char* what) {
  if (!ok) throw std::invalid_argument(name + ": " + what);
}

}  // namespace

std::array<double, kParameterCount> ParameterValues(const ModelParameters& p) {
  const ContactParameters& c = p.contact;
  return {p.ball.radius,
          p.ball.mass,
          p.ball.gravity,
          c.patch_radius,
          c.mu,
          c.d,
          c.eps_t,
          c.eps_r,
          c.b_t,
          c.m_t,
          c.b_m,
          c.m_m,
          p.cue.mass,
          p.cue.tip_restitution,
          p.cue.max_tip_offset,
          p.cue.max_speed,
          p.cue.end_mass,
          p.collision.ball_restitution,
          p.collision.ball_friction_a,
          p.collision.ball_friction_b,
          p.collision.ball_friction_c,
          p.collision.cushion_restitution,
          p.collision.cushion_friction,
          p.table.length,
          p.table.width};
}

void ValidateParameters(const ModelParameters& p) {
  const std::string& n = p.name;
  const ContactParameters& c = p.contact;
  for (double v : ParameterValues(p)) {
    Require(std::isfinite(v), n, "every parameter must be a finite number");
  }
  Require(p.ball.radius > 0.0 && p.ball.mass > 0.0 && p.ball.gravity > 0.0, n,
          "ball radius, mass and gravity must be positive");
  Require(c.patch_radius > 0.0 && c.patch_radius < p.ball.radius, n,
          "contact patch radius must be positive and smaller than the ball");
  Require(c.mu >= 0.0, n, "mu must be >= 0");
  Require(c.d >= 0.0 && c.d <= 1.0, n, "d must lie in [0, 1] (the pressure must stay positive)");
  // The rolling-resistance moment adds m g mu_r (u . v_hat - |v|) to dE/dt and friction takes
  // mu m g |u| away (u the slip): below mu_r, a ball with back spin gains energy.
  if (c.mu < p.RollingResistance()) {
    std::ostringstream what;
    what << "mu = " << c.mu
         << " is below the rolling resistance a d / (5 r) = " << p.RollingResistance()
         << ", where the contact model creates energy (a frictionless contact needs d = 0)";
    throw std::invalid_argument(n + ": " + what.str());
  }
  Require(c.eps_t > 0.0 && c.eps_r > 0.0, n, "eps_t and eps_r must be positive");
  Require(c.b_t > 0.0 && c.b_m > 0.0, n, "b_T and b_M must be positive");
  Require(c.m_t >= 1.0 && c.m_m >= 1.0, n, "m_T and m_M must be >= 1");
  Require(p.cue.mass > 0.0 && p.cue.max_speed > 0.0, n, "cue mass and top speed must be positive");
  Require(p.cue.end_mass > 0.0, n, "cue end_mass must be positive");
  Require(p.cue.tip_restitution >= 0.0 && p.cue.tip_restitution <= 1.0, n,
          "cue tip restitution must lie in [0, 1]");
  Require(p.cue.max_tip_offset > 0.0 && p.cue.max_tip_offset < 1.0, n,
          "cue max_tip_offset is a fraction of the radius in (0, 1)");
  const CollisionParameters& k = p.collision;
  Require(k.ball_restitution >= 0.0 && k.ball_restitution <= 1.0 && k.cushion_restitution >= 0.0 &&
              k.cushion_restitution <= 1.0,
          n, "ball and cushion restitution must lie in [0, 1]");
  Require(k.ball_friction_a >= 0.0 && k.ball_friction_b >= 0.0 && k.ball_friction_c >= 0.0 &&
              k.cushion_friction >= 0.0,
          n, "ball-ball and cushion friction must be >= 0");
  Require(p.table.length > 2.0 * p.ball.radius && p.table.width > 2.0 * p.ball.radius, n,
          "the table must be larger than the ball");
}

}  // namespace billiard::physics
