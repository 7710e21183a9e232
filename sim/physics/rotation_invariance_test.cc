// The 5-DOF model is isotropic in the table plane (Kudra et al. 2016, eqs. 14-23: every term is
// built from vectors in the plane and from wz), so turning a ball's start about the vertical must
// turn its derivative and its whole trajectory by the same angle. The rolling resistance is the
// one term whose direction comes from the state alone (v_hat, eq. 2), and the one that decides
// where a rolling ball stops, so it is also checked against the moment of the normal force at the
// shifted pressure centre (eqs. 1-4).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "sim/params/parameter_sets.h"
#include "sim/physics/ball_dynamics.h"
#include "sim/physics/ball_state.h"
#include "sim/physics/integral_friction.h"
#include "sim/physics/simulator.h"
#include "sim/physics/testing/test_support.h"

namespace billiard::physics {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Turns (X, Y), (vx, vy) and (wx, wy) by phi about the vertical; wz is a component along the axis.
BallState Rotate(const BallState& s, double phi) {
  const Eigen::Rotation2Dd turn(phi);
  BallState out = s;
  out.segment<2>(kX) = turn * s.segment<2>(kX);
  out.segment<2>(kVx) = turn * s.segment<2>(kVx);
  out.segment<2>(kWx) = turn * s.segment<2>(kWx);
  return out;
}

struct NamedState {
  std::string kind;
  BallState state;
};

// States of every contact regime the model has: full sliding, rolling (zero slip, with and
// without side spin), pivoting (v near zero, large wz), and speed and slip at the regularization
// scales eps_r a and eps_t a, where the friction law is steepest.
std::vector<NamedState> RandomStates(const ModelParameters& p, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), position(0.2, 1.0);
  const double r = p.ball.radius, a = p.contact.patch_radius;
  const double v_eps = p.contact.eps_r * a, slip_eps = p.contact.eps_t * a;
  // Spin about the horizontal that gives slip u on top of rolling at v.
  const auto spin_for = [r](const Eigen::Vector2d& v, const Eigen::Vector2d& u) {
    return Eigen::Vector2d(-(v.y() - u.y()) / r, (v.x() - u.x()) / r);
  };
  std::vector<NamedState> states;
  for (int i = 0; i < 40; ++i) {
    const Eigen::Vector2d x(position(rng), position(rng));
    const Eigen::Vector2d v(2.0 * unit(rng), 2.0 * unit(rng));
    const auto make = [&](const Eigen::Vector2d& vel, const Eigen::Vector2d& w, double wz) {
      return MakeBallState(x.x(), x.y(), vel.x(), vel.y(), w.x(), w.y(), wz);
    };
    states.push_back(
        {"sliding", make(v, {150.0 * unit(rng), 150.0 * unit(rng)}, 150.0 * unit(rng))});
    states.push_back({"rolling", make(v, spin_for(v, Eigen::Vector2d::Zero()), 0.0)});
    states.push_back({"rolling with side spin",
                      make(v, spin_for(v, Eigen::Vector2d::Zero()), 150.0 * unit(rng))});
    const Eigen::Vector2d creep(3.0 * v_eps * unit(rng), 3.0 * v_eps * unit(rng));
    states.push_back(
        {"pivoting", make(creep, {0.05 * unit(rng), 0.05 * unit(rng)}, 150.0 * unit(rng))});
    const Eigen::Vector2d slip(3.0 * slip_eps * unit(rng), 3.0 * slip_eps * unit(rng));
    states.push_back(
        {"at the regularization scale", make(creep, spin_for(creep, slip), 3.0 * unit(rng))});
    states.push_back({"slipping at eps_t a", make(v, spin_for(v, slip), 0.1 * unit(rng))});
  }
  return states;
}

// |R f(s) - f(R s)| over the states and random angles, relative to the acceleration scale of the
// state (the full friction mu g, or the derivative itself if larger), is below rel_tol; the
// worst state is reported.
template <class Friction>
void ExpectDerivativeTurnsWithTheState(const ModelParameters& p, Friction friction, double rel_tol,
                                       const std::string& model) {
  const BallDynamics<Friction> dynamics(p, friction);
  const double mu_g = p.contact.mu * p.ball.gravity;
  // Spin accelerations are compared as r dw/dt, in the units of the linear ones.
  const auto in_linear_units = [&p](BallState f) {
    f.tail<3>() *= p.ball.radius;
    return f;
  };
  std::mt19937 rng(2016);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  const std::vector<NamedState> states = RandomStates(p, 7);
  double worst = 0.0;
  std::string worst_case = "none";
  for (const NamedState& s : states) {
    const BallState f = dynamics.Derivative(s.state);
    const double scale = std::max(mu_g, in_linear_units(f).template tail<5>().norm());
    for (int k = 0; k < 3; ++k) {
      const double phi = angle(rng);
      const BallState difference =
          in_linear_units(Rotate(f, phi) - dynamics.Derivative(Rotate(s.state, phi)));
      if (difference.norm() / scale > worst) {
        worst = difference.norm() / scale;
        std::ostringstream what;
        what << s.kind << " state " << FormatState(s.state) << " turned by " << phi
             << ": R f(s) - f(R s) = " << difference.transpose();
        worst_case = what.str();
      }
    }
  }
  EXPECT_EQ(states.size(), 240u);
  EXPECT_LT(worst, rel_tol) << model << ", worst: " << worst_case;
  std::fprintf(stderr, "%s: worst relative |R f(s) - f(R s)| %.2e\n", model.c_str(), worst);
}

TEST(RotationInvariance, ApproximateModelDerivativeTurnsWithTheState) {
  for (const char* set : {"paper", "pool"}) {
    const ModelParameters p = params::LoadParameters(set);
    // Rounding only: the rotated inputs differ in their last bits (1e-16 m/s at 1 m/s), which the
    // slope of the friction law at a slip of eps_t a amplifies by up to |v| / (eps_t a) ~ 1e5.
    ExpectDerivativeTurnsWithTheState(p, ApproximateFrictionModel{p.contact}, 1e-9,
                                      std::string("approx, ") + set);
  }
}

TEST(RotationInvariance, IntegralModelDerivativeTurnsWithTheState) {
  const ModelParameters p = testing::PaperParameters();
  // The quadrature's nodes are fixed to the patch, not to the state, so a turned state is
  // integrated on other nodes: agreement to the calibrated quadrature error (on T, times 5/2 on
  // r dw/dt), not to rounding.
  constexpr double kQuadratureTolerance = 1e-8;
  const CalibratedQuadrature q =
      CalibrateQuadrature(p.contact.eps_t, p.contact.d, kQuadratureTolerance);
  ExpectDerivativeTurnsWithTheState(
      p, IntegralFrictionModel{IntegralFriction(q.order), p.contact.eps_t},
      10 * kQuadratureTolerance, "integral");
}

// A rolling ball (no slip, no side spin) meets no friction, only the normal force m g acting at
// the pressure centre S, shifted from the patch centre by a f with f = (d/5) v_hat (eqs. 1-4,
// regularized by eps_r as in eq. 14). About the ball's centre that force's moment is
// a m g (f x e_z), which turns w at 5/2 g a / r^2 (f x e_z) against the rolling: for any heading.
TEST(RotationInvariance, RollingResistanceOpposesTheRollingAtEveryHeading) {
  const ModelParameters p = testing::PaperParameters();
  const BallDynamics<ApproximateFrictionModel> approx(p, {p.contact});
  const BallDynamics<IntegralFrictionModel> integral(p, {IntegralFriction(), p.contact.eps_t});
  const double g = p.ball.gravity, r = p.ball.radius, a = p.contact.patch_radius;
  const double d = p.contact.d, eps_r = p.contact.eps_r;
  for (double speed : {1.0, 0.05, 3.0 * eps_r * a}) {
    for (int k = 0; k < 24; ++k) {
      const double heading = 2.0 * kPi * (k + 0.37) / 24;
      const Eigen::Vector2d v = speed * Eigen::Vector2d(std::cos(heading), std::sin(heading));
      const BallState s = MakeBallState(0.5, 0.5, v.x(), v.y(), -v.y() / r, v.x() / r, 0.0);
      const double regularized = speed / std::hypot(speed, eps_r * a);  // |v| / sqrt(|v|^2 + ..)
      const Eigen::Vector2d f = d / 5.0 * regularized * v / speed;
      const Eigen::Vector2d moment(f.y(), -f.x());  // f x e_z
      const Eigen::Vector2d expected = 2.5 * g * a / (r * r) * moment;
      for (const BallState& ds : {approx.Derivative(s), integral.Derivative(s)}) {
        // Rounding leaves a slip of 1e-16 m/s, next to nothing against eps_t a.
        EXPECT_LT(ds.segment<2>(kVx).norm(), 1e-9) << "no friction without slip";
        EXPECT_LT((ds.segment<2>(kWx) - expected).norm(), 1e-9 * expected.norm())
            << "heading " << heading << ", speed " << speed
            << ": dw/dt = " << ds.segment<2>(kWx).transpose() << ", expected "
            << expected.transpose();
        // Against the rolling: the spin's kinetic energy falls.
        EXPECT_LT(ds.segment<2>(kWx).dot(s.segment<2>(kWx)), 0.0) << heading;
        EXPECT_LT(std::abs(ds[kWz]), 1e-6) << "no pivot moment without spin";
      }
    }
  }
}

// Whole shots: the paper's figures (sliding, rolling, side spin, pivoting to a stop) and a
// stun shot with side spin, turned by angles that are no multiple of a right angle.
TEST(RotationInvariance, TurnedShotFollowsTheTurnedTrajectory) {
  const ModelParameters p = testing::PaperParameters();
  const auto figures = testing::PaperFigureStates();
  std::vector<BallState> shots(figures.begin(), figures.end());
  shots.push_back(MakeBallState(0.3, 0.2, 0.8, 0.5, 0.0, 0.0, 40.0));
  constexpr double kTEnd = 8.0;
  // While the ball moves: the integrator's error norm is the RMS over components with equal x
  // and y tolerances, so the turned shot takes the same steps, and the two agree to rounding:
  // 1e-13 measured while sliding and rolling, up to 1.1e-9 in the last tenth of a second before a
  // stop, where the regularized rolling direction (eps_r a) sharpens and amplifies it (2e-10
  // before wz's tolerance was loosened to the patch's slip, issue 16: longer steps there).
  constexpr double kWhileMoving = 3e-9;
  for (const Model model : {Model::kApproximate, Model::kIntegral}) {
    SimulationOptions options;
    options.model = model;
    // Once stopped: the rest switch takes over at the end of the first step below 10 eps_r a,
    // which rounding can move within that creep (1e-8 m measured); the simulation promises its
    // endpoint to its tolerance.
    const double at_rest = options.tolerance;
    for (std::size_t i = 0; i < shots.size(); ++i) {
      // The integral model costs a second a shot: the side-spin figure and the stun shot.
      if (model == Model::kIntegral && i != 3 && i != 5) continue;
      const SimulationResult base = Simulate(p, shots[i], kTEnd, options);
      EXPECT_GT(base.rest_time, 0.0) << "shot " << i << " stops within " << kTEnd << " s";
      const double moving_until = base.rest_time > 0.0 ? base.rest_time : kTEnd;
      // Not a coincidence of a ball that never moved: every shot travels centimetres at least.
      EXPECT_GT((base.final_state - shots[i]).head<2>().norm(), 0.05) << "shot " << i;
      for (double phi : {0.7, -2.3}) {
        const SimulationResult turned = Simulate(p, Rotate(shots[i], phi), kTEnd, options);
        const std::string what =
            ModelName(model) + ", shot " + std::to_string(i) + " by " + std::to_string(phi);
        // Positions, velocities and r w: one worst difference per shot, with its time.
        double worst = 0.0, worst_t = 0.0;
        for (double t = 0.05; t < moving_until - 0.01; t += 0.05) {
          BallState difference = Rotate(base.trajectory->At(t), phi) - turned.trajectory->At(t);
          difference.tail<3>() *= p.ball.radius;
          if (difference.lpNorm<Eigen::Infinity>() > worst) {
            worst = difference.lpNorm<Eigen::Infinity>();
            worst_t = t;
          }
        }
        EXPECT_LT(worst, kWhileMoving) << what << ", at t = " << worst_t;
        const BallState expected = Rotate(base.final_state, phi);
        EXPECT_LT((expected.head<2>() - turned.final_state.head<2>()).norm(), at_rest) << what;
        EXPECT_LT(p.ball.radius * std::abs(expected[kWz] - turned.final_state[kWz]), at_rest)
            << what;
      }
    }
  }
}

}  // namespace
}  // namespace billiard::physics
