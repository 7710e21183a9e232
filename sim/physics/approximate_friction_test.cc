// The approximate friction model (eq. 17) against the integral model where they must agree
// (eq. 11) and the symmetries they share (eq. 9).
#include "sim/physics/approximate_friction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sim/physics/integral_friction.h"

namespace billiard::physics {
namespace {

constexpr double kPi = 3.14159265358979323846;

ContactParameters Fitted(double b_t, double m_t, double b_m, double m_m) {
  ContactParameters c;  // eps_t = 0: the exact (unregularized) models
  c.b_t = b_t;
  c.m_t = m_t;
  c.b_m = b_m;
  c.m_m = m_m;
  return c;
}

class ApproximateFrictionEq11 : public ::testing::TestWithParam<ContactParameters> {};

TEST_P(ApproximateFrictionEq11, EqualsIntegralModelWithoutSpin) {
  const IntegralFriction integral;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(-kPi, kPi), unit(0.0, 1.0);
  for (int i = 0; i < 50; ++i) {
    const double phi = angle(rng), gamma = angle(rng), d = unit(rng), vs = 0.1 + 5 * unit(rng);
    const ContactKinematics<double> k{vs * std::cos(phi), vs * std::sin(phi), 0.0,
                                      d * std::cos(gamma), d * std::sin(gamma)};
    const auto a = ApproximateFriction(k, GetParam());
    const auto b = integral.Evaluate(k, 0.0);
    EXPECT_NEAR(a.tsx, b.tsx, 1e-9);
    EXPECT_NEAR(a.tsy, b.tsy, 1e-9);
    EXPECT_NEAR(a.ms, b.ms, 1e-9);
  }
}

TEST_P(ApproximateFrictionEq11, EqualsIntegralModelWithoutLinearSlip) {
  const IntegralFriction integral;
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> angle(-kPi, kPi), unit(0.0, 1.0);
  for (int i = 0; i < 50; ++i) {
    const double gamma = angle(rng), d = unit(rng), ws = 10 * (unit(rng) - 0.5);
    const ContactKinematics<double> k{0.0, 0.0, ws, d * std::cos(gamma), d * std::sin(gamma)};
    const auto a = ApproximateFriction(k, GetParam());
    const auto b = integral.Evaluate(k, 0.0);
    EXPECT_NEAR(a.tsx, b.tsx, 1e-9);
    EXPECT_NEAR(a.tsy, b.tsy, 1e-9);
    EXPECT_NEAR(a.ms, b.ms, 1e-9);
  }
}

// The paper's two fitted parameter sets (section 2.3).
INSTANTIATE_TEST_SUITE_P(PaperFits, ApproximateFrictionEq11,
                         ::testing::Values(Fitted(0.68102, 2.0, 0.480909, 2.0),
                                           Fitted(0.771, 2.655, 0.419, 3.073)));

TEST(ApproximateFriction, SatisfiesTheSymmetriesOfEquationNine) {
  const ContactParameters c = Fitted(0.771, 2.655, 0.419, 3.073);
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> angle(-kPi, kPi), unit(0.0, 1.0);
  const auto slip = [](double theta, double phi, double gamma, double d) {
    return ContactKinematics<double>{std::cos(theta) * std::cos(phi),
                                     std::cos(theta) * std::sin(phi), std::sin(theta),
                                     d * std::cos(gamma), d * std::sin(gamma)};
  };
  for (int i = 0; i < 100; ++i) {
    const double theta = angle(rng), phi = angle(rng), gamma = angle(rng), d = unit(rng);
    const auto f = ApproximateFriction(slip(theta, phi, gamma, d), c);
    const auto a = ApproximateFriction(slip(theta + kPi, phi, gamma, d), c);
    const auto b = ApproximateFriction(slip(-theta, phi + kPi, gamma, d), c);
    const auto g = ApproximateFriction(slip(-theta, phi, gamma + kPi, d), c);
    EXPECT_NEAR(f.tsx, -a.tsx, 1e-12);
    EXPECT_NEAR(f.ms, -a.ms, 1e-12);
    EXPECT_NEAR(f.tsy, -b.tsy, 1e-12);
    EXPECT_NEAR(f.ms, -b.ms, 1e-12);
    EXPECT_NEAR(f.tsx, g.tsx, 1e-12);
    EXPECT_NEAR(f.tsy, g.tsy, 1e-12);
    EXPECT_NEAR(f.ms, -g.ms, 1e-12);
  }
}

TEST(ApproximateFriction, RegularizationRemovesTheSingularityAtZeroSlip) {
  ContactParameters c = Fitted(0.68102, 2.0, 0.480909, 2.0);
  c.eps_t = 0.01;
  const auto f = ApproximateFriction(ContactKinematics<double>{0, 0, 0, 0.5, 0.5}, c);
  EXPECT_EQ(f.tsx, 0.0);
  EXPECT_EQ(f.tsy, 0.0);
  EXPECT_EQ(f.ms, 0.0);
  // Near zero slip the force is linear in the slip with slope 1 / eps_t.
  const auto g = ApproximateFriction(ContactKinematics<double>{1e-6, 0, 0, 0, 0}, c);
  EXPECT_NEAR(g.tsx, 1e-4, 1e-12);
}

}  // namespace
}  // namespace billiard::physics
