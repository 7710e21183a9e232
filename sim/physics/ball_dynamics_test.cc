// The 5-DOF equations of motion: their Jacobian, their invariants, and their limit.
#include "sim/physics/ball_dynamics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "sim/physics/closed_form.h"
#include "sim/physics/simulator.h"
#include "sim/physics/testing/test_support.h"

namespace billiard::physics {
namespace {

TEST(BallDynamics, JacobianMatchesCentralDifferences) {
  const ModelParameters p = testing::PaperParameters();
  const BallDynamics<ApproximateFrictionModel> approx(p, {p.contact});
  const BallDynamics<IntegralFrictionModel> integral(p, {IntegralFriction(), p.contact.eps_t});
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> v(-1.0, 1.0), w(-100.0, 100.0);
  for (int i = 0; i < 20; ++i) {
    const BallState s = MakeBallState(0.1, 0.2, v(rng), v(rng), w(rng), w(rng), w(rng));
    for (int model = 0; model < 2; ++model) {
      BallState f;
      StateJacobian jac;
      model == 0 ? approx.DerivativeAndJacobian(s, &f, &jac)
                 : integral.DerivativeAndJacobian(s, &f, &jac);
      const auto rhs = [&](const BallState& x) {
        return model == 0 ? approx.Derivative(x) : integral.Derivative(x);
      };
      EXPECT_LT((f - rhs(s)).norm(), 1e-9 * (1 + f.norm()));
      for (int j = 0; j < 7; ++j) {
        const double h = 1e-6 * std::max(1.0, std::abs(s[j]));
        BallState plus = s, minus = s;
        plus[j] += h;
        minus[j] -= h;
        const BallState column = (rhs(plus) - rhs(minus)) / (2 * h);
        EXPECT_LT((jac.col(j) - column).norm(), 1e-5 * (1 + column.norm()))
            << "model " << model << " column " << j;
      }
    }
  }
}

// The approximate model's parameter sets: the paper's and the pool set, each with its m_T = m_M = 2
// fit and with the free fit of Kudra et al. 2016, section 2.3 (b_T 0.771, m_T 2.655, b_M 0.419,
// m_M 3.073).
std::vector<std::pair<std::string, ModelParameters>> ApproximateModelSets() {
  std::vector<std::pair<std::string, ModelParameters>> sets;
  for (const char* name : {"paper", "pool"}) {
    ModelParameters p = params::LoadParameters(name);
    sets.emplace_back(std::string(name) + ", m = 2", p);
    p.contact.b_t = 0.771;
    p.contact.m_t = 2.655;
    p.contact.b_m = 0.419;
    p.contact.m_m = 3.073;
    sets.emplace_back(std::string(name) + ", free fit", p);
  }
  return sets;
}

// States of one regime of the motion, drawn from `rng` for the parameters `p`.
struct Regime {
  const char* name;
  std::function<BallState(std::mt19937&, const ModelParameters&)> draw;
};

// A state moving at v with the contact point slipping at u (m/s) and spin wz.
BallState WithSlip(const Eigen::Vector2d& v, const Eigen::Vector2d& u, double wz, double r) {
  return MakeBallState(0.1, 0.2, v.x(), v.y(), (u.y() - v.y()) / r, (v.x() - u.x()) / r, wz);
}

Eigen::Vector2d RandomDirection(std::mt19937& rng) {
  const double angle = std::uniform_real_distribution<double>(-M_PI, M_PI)(rng);
  return {std::cos(angle), std::sin(angle)};
}

// 10^x for x uniform in [lo, hi].
double LogUniform(std::mt19937& rng, double lo, double hi) {
  return std::pow(10.0, std::uniform_real_distribution<double>(lo, hi)(rng));
}

std::vector<Regime> MotionRegimes() {
  using U = std::uniform_real_distribution<double>;
  return {
      {"sliding",
       [](std::mt19937& rng, const ModelParameters&) {
         U v(-3, 3), w(-200, 200);
         return MakeBallState(0.1, 0.2, v(rng), v(rng), w(rng), w(rng), w(rng));
       }},
      // Slip from 100 times below to 10 times above the regularization scale eps_t a.
      {"rolling",
       [](std::mt19937& rng, const ModelParameters& p) {
         const double slip = p.contact.eps_t * p.contact.patch_radius * LogUniform(rng, -2, 1);
         return WithSlip(U(0.05, 3)(rng) * RandomDirection(rng), slip * RandomDirection(rng),
                         U(-50, 50)(rng), p.ball.radius);
       }},
      // Half of them exactly still, where the linear slip vanishes and only the norm's spin part
      // remains.
      {"pure spin",
       [](std::mt19937& rng, const ModelParameters&) {
         const double wz = U(-200, 200)(rng);
         if (U(0, 1)(rng) < 0.5) return MakeBallState(0.1, 0.2, 0, 0, 0, 0, wz);
         const Eigen::Vector2d v = 1e-6 * RandomDirection(rng);
         return MakeBallState(0.1, 0.2, v.x(), v.y(), U(-1, 1)(rng), U(-1, 1)(rng), wz);
       }},
      // Speeds from 100 times below to 10 times above the rolling regularization eps_r a.
      {"near rest",
       [](std::mt19937& rng, const ModelParameters& p) {
         const double scale = p.contact.eps_r * p.contact.patch_radius;
         const double speed = scale * LogUniform(rng, -2, 1);
         const double slip = scale * LogUniform(rng, -2, 1);
         return WithSlip(speed * RandomDirection(rng), slip * RandomDirection(rng), U(-1, 1)(rng),
                         p.ball.radius);
       }},
      {"large spins",
       [](std::mt19937& rng, const ModelParameters&) {
         U v(-5, 5), w(-1000, 1000);
         return MakeBallState(0.1, 0.2, v(rng), v(rng), w(rng), w(rng), w(rng));
       }},
  };
}

// max |a - b| / max |b| over the entries.
template <class Derived>
double RelativeDifference(const Eigen::MatrixBase<Derived>& a,
                          const Eigen::MatrixBase<Derived>& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

TEST(BallDynamics, AnalyticJacobianEqualsAutomaticDifferentiation) {
  static_assert(HasAnalyticJacobian<ApproximateFrictionModel>::value);
  static_assert(!HasAnalyticJacobian<IntegralFrictionModel>::value);
  constexpr int kStatesPerRegime = 500;  // 5 regimes x 4 parameter sets: 10,000 states
  std::mt19937 rng(16);
  for (const auto& [set, p] : ApproximateModelSets()) {
    const BallDynamics<ApproximateFrictionModel> dynamics(p, {p.contact});
    for (const Regime& regime : MotionRegimes()) {
      double worst = 0.0, worst_derivative = 0.0;
      for (int i = 0; i < kStatesPerRegime; ++i) {
        const BallState s = regime.draw(rng, p);
        BallState f, f_ad;
        StateJacobian jac, jac_ad;
        dynamics.DerivativeAndJacobian(s, &f, &jac);
        dynamics.DerivativeAndJacobianByAutoDiff(s, &f_ad, &jac_ad);
        ASSERT_TRUE(jac_ad.allFinite()) << set << ", " << regime.name << ": " << s.transpose();
        // The derivative is the same computation on doubles as Derivative, hence the same bits;
        // automatic differentiation divides by multiplying with the reciprocal (ceres::Jet), so
        // it may differ in the last bit.
        ASSERT_TRUE(f == dynamics.Derivative(s)) << set << ", " << regime.name;
        worst_derivative = std::max(worst_derivative, RelativeDifference(f, f_ad));
        worst = std::max(worst, RelativeDifference(jac, jac_ad));
      }
      EXPECT_LT(worst, 1e-12) << set << ", " << regime.name;
      EXPECT_LT(worst_derivative, 1e-15) << set << ", " << regime.name;
    }
  }
}

// X, vx, wy, wz -> -X, -vx, -wy, -wz maps trajectories onto their mirror images.
BallState Mirror(BallState s) {
  for (int i : {kX, kVx, kWy, kWz}) s[i] = -s[i];
  return s;
}

TEST(BallDynamics, MirroredStartGivesTheMirroredTrajectory) {
  const ModelParameters p = testing::PaperParameters();
  for (const BallState& s0 : testing::PaperFigureStates()) {
    const SimulationResult a = Simulate(p, s0, 8.0);
    const SimulationResult b = Simulate(p, Mirror(s0), 8.0);
    for (double t = 0.0; t <= 8.0; t += 0.25) {
      EXPECT_LT((Mirror(a.trajectory->At(t)) - b.trajectory->At(t)).norm(), 1e-12) << t;
    }
  }
}

TEST(BallDynamics, KineticEnergyNeverIncreasesOnThePaperFigures) {
  const ModelParameters p = testing::PaperParameters();
  for (const BallState& s0 : testing::PaperFigureStates()) {
    // Dense output is third order: allow its interpolation error, nothing more.
    testing::ExpectEnergyNeverRises(*Simulate(p, s0, 8.0).trajectory, p, 8.0, 8000, 1e-9);
  }
}

TEST(BallDynamics, RollingBallOfFigureSixStopsAfterTheNotesDistance) {
  const SimulationResult r =
      Simulate(testing::PaperParameters(), testing::PaperFigureStates()[0], 8.0);
  EXPECT_NEAR(r.final_state[kY], 2.3785, 1e-4);
  EXPECT_EQ(r.final_state[kX], 0.0);
}

TEST(BallDynamics, ConvergesToTheClosedFormAsRegularizationVanishes) {
  // wz = 0 and d = 0: no pivot friction and no rolling resistance, so the only difference from
  // the Coulomb point-contact model of Jaroukh 2019 is the regularization eps_t.
  ModelParameters p = testing::PaperParameters();
  p.contact.d = 0.0;
  const BallState s0 = MakeBallState(0, 0, 0.4, 1.0, 30.0, -10.0, 0.0);
  const ClosedFormTrajectory exact(ClosedFormParameters::From(p), s0);
  const double t_end = 1.0;  // well past the end of sliding (0.16 s)
  double previous = 1.0;
  for (double eps : {1e-1, 1e-2, 1e-3, 1e-4}) {
    p.contact.eps_t = p.contact.eps_r = eps;
    SimulationOptions options;
    options.tolerance = 1e-10;
    const BallState s = Simulate(p, s0, t_end, options).final_state;
    const double error = (s.head<4>() - exact.At(t_end).head<4>()).norm();
    EXPECT_LT(error, 0.5 * previous) << "eps = " << eps;
    previous = error;
  }
  EXPECT_LT(previous, 1e-5);
}

}  // namespace
}  // namespace billiard::physics
