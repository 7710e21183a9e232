// The integral friction model against the exact values and symmetries of Kudra et al. 2016.
#include "sim/physics/integral_friction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace billiard::physics {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Slip in the angular variables of eqs. 6-7, rolling direction of eq. 2.
ContactKinematics<double> Slip(double theta, double phi, double gamma, double d) {
  return {std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi), std::sin(theta),
          d * std::cos(gamma), d * std::sin(gamma)};
}

TEST(IntegralFriction, PureSlidingGivesUnitForceAlongTheSlip) {
  const IntegralFriction model;
  for (double phi : {0.0, 0.4, 2.0, -2.9}) {
    for (double d : {0.0, 0.6, 1.0}) {
      const auto f = model.Evaluate(Slip(0.0, phi, 1.3, d), 0.0);
      EXPECT_NEAR(std::hypot(f.tsx, f.tsy), 1.0, 1e-12);
      EXPECT_NEAR(std::atan2(f.tsy, f.tsx), phi, 1e-12);
    }
  }
}

TEST(IntegralFriction, PureSpinGivesThreePiOverSixteen) {
  const IntegralFriction model;
  for (double ws : {0.01, 1.0, -7.0}) {
    const auto f = model.Evaluate(ContactKinematics<double>{0.0, 0.0, ws, 0.0, 0.0}, 0.0);
    EXPECT_NEAR(f.ms, std::copysign(3.0 * kPi / 16.0, ws), 1e-10);
    EXPECT_NEAR(f.tsx, 0.0, 1e-12);
    EXPECT_NEAR(f.tsy, 0.0, 1e-12);
  }
}

TEST(IntegralFriction, PureSpinWithRollingResistanceMatchesMomentsOfPressure) {
  // With vs = 0 the slip direction is tangential about the centre, so eq. 5 reduces to the
  // pressure moments of eq. 12: Tsx = -c_{0,1,1}, Tsy = c_{1,0,1}, Ms = c_{0,0,-1}.
  const IntegralFriction model;
  const double d = 0.8, gamma = 0.9;
  const auto f = model.Evaluate(Slip(kPi / 2, 0.0, gamma, d), 0.0);
  EXPECT_NEAR(f.tsx, -3.0 / 32.0 * kPi * d * std::sin(gamma), 1e-10);
  EXPECT_NEAR(f.tsy, 3.0 / 32.0 * kPi * d * std::cos(gamma), 1e-10);
  EXPECT_NEAR(f.ms, 3.0 / 16.0 * kPi, 1e-10);
}

TEST(IntegralFriction, SatisfiesTheSymmetriesOfEquationNine) {
  const IntegralFriction model;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> angle(-kPi, kPi), unit(0.0, 1.0);
  for (int i = 0; i < 40; ++i) {
    const double theta = angle(rng), phi = angle(rng), gamma = angle(rng), d = unit(rng);
    const auto f = model.Evaluate(Slip(theta, phi, gamma, d), 0.0);
    const auto a = model.Evaluate(Slip(theta + kPi, phi, gamma, d), 0.0);
    const auto b = model.Evaluate(Slip(-theta, phi + kPi, gamma, d), 0.0);
    const auto c = model.Evaluate(Slip(-theta, phi, gamma + kPi, d), 0.0);
    constexpr double tol = 1e-7;
    EXPECT_NEAR(f.tsx, -a.tsx, tol);
    EXPECT_NEAR(f.tsy, -a.tsy, tol);
    EXPECT_NEAR(f.ms, -a.ms, tol);
    EXPECT_NEAR(f.tsx, -b.tsx, tol);
    EXPECT_NEAR(f.tsy, -b.tsy, tol);
    EXPECT_NEAR(f.ms, -b.ms, tol);
    EXPECT_NEAR(f.tsx, c.tsx, tol);
    EXPECT_NEAR(f.tsy, c.tsy, tol);
    EXPECT_NEAR(f.ms, -c.ms, tol);
  }
}

TEST(IntegralFriction, CalibratedOrderMeetsItsToleranceAgainstAFineReference) {
  const IntegralFriction reference(QuadratureOrder{1024, 512});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(-kPi, kPi), unit(0.0, 1.0);
  for (double eps_t : {0.0, 0.01}) {
    const CalibratedQuadrature q = CalibrateQuadrature(eps_t, 1.0, 1e-6);
    EXPECT_LE(q.error_estimate, 1e-6);
    const IntegralFriction model(q.order);
    double worst = 0.0;
    for (int i = 0; i < 200; ++i) {
      const auto k = Slip(angle(rng), angle(rng), angle(rng), unit(rng));
      const auto a = model.Evaluate(k, eps_t), b = reference.Evaluate(k, eps_t);
      worst = std::max(
          {worst, std::abs(a.tsx - b.tsx), std::abs(a.tsy - b.tsy), std::abs(a.ms - b.ms)});
    }
    EXPECT_LT(worst, 1e-6) << "eps_t = " << eps_t;
  }
}

TEST(IntegralFriction, ErrorFallsAsTheOrderDoubles) {
  // ICR inside the patch near its rim: the hardest case for the quadrature.
  const ContactKinematics<double> k{0.97 * 0.6, 0.97 * 0.8, 1.0, 0.3, -0.5};
  const auto exact = IntegralFriction({2048, 1024}).Evaluate(k, 0.0);
  double previous = 1.0;
  for (int n : {16, 32, 64, 128}) {
    const auto f = IntegralFriction({n, n / 2}).Evaluate(k, 0.0);
    const double error =
        std::abs(f.tsx - exact.tsx) + std::abs(f.tsy - exact.tsy) + std::abs(f.ms - exact.ms);
    EXPECT_LT(error, previous) << n;
    previous = error;
  }
  EXPECT_LT(previous, 1e-5);
}

TEST(IntegralFriction, RegularizedModelTendsToTheExactOne) {
  const IntegralFriction model;
  const auto k = Slip(0.8, 0.3, 2.0, 0.7);
  const auto exact = model.Evaluate(k, 0.0);
  double previous = 1.0;
  for (double eps_t : {1e-1, 1e-2, 1e-3, 1e-4}) {
    const auto f = model.Evaluate(k, eps_t);
    const double error =
        std::abs(f.tsx - exact.tsx) + std::abs(f.tsy - exact.tsy) + std::abs(f.ms - exact.ms);
    EXPECT_LT(error, previous);
    previous = error;
  }
  EXPECT_LT(previous, 1e-5);
}

}  // namespace
}  // namespace billiard::physics
