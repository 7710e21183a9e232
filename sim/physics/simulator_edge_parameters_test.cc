// Contact parameters at the edge of their range: no friction (mu = 0), no rolling resistance
// (d = 0), a regularization a million times below the paper's (eps = 1e-9), and the combinations.
// Each is checked against what the physics says without the simulator: Newton's laws for the
// frictionless ball, the closed form for eps -> 0, the energy balance of the contact.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>

#include "sim/physics/ball_dynamics.h"
#include "sim/physics/closed_form.h"
#include "sim/physics/simulator.h"
#include "sim/physics/testing/test_support.h"

namespace billiard::physics {
namespace {

ModelParameters Edge(double mu, double d, double eps_t, double eps_r) {
  ModelParameters p = testing::PaperParameters();
  p.contact.mu = mu;
  p.contact.d = d;
  p.contact.eps_t = eps_t;
  p.contact.eps_r = eps_r;
  return p;
}

double Energy(const BallState& s, const ModelParameters& p) {
  return KineticEnergy(s, p.ball.mass, p.ball.radius);
}

// dE/dt of the 5-DOF approximate model at s.
double Power(const ModelParameters& p, const BallState& s) {
  const BallDynamics<ApproximateFrictionModel> dynamics(p, ApproximateFrictionModel{p.contact});
  const BallState f = dynamics.Derivative(s);
  const double m = p.ball.mass, r = p.ball.radius;
  return m * s.segment<2>(kVx).dot(f.segment<2>(kVx)) +
         0.4 * m * r * r * s.segment<3>(kWx).dot(f.segment<3>(kWx));
}

// The simulator's defaults with a step budget, so that a regression to chattering fails in
// milliseconds instead of running to the default 5,000,000 steps.
SimulationOptions Budget(long max_steps, double tolerance = SimulationOptions().tolerance) {
  SimulationOptions o;
  o.max_steps = max_steps;
  o.tolerance = tolerance;
  return o;
}

std::string Name(const ModelParameters& p, const BallState& s0) {
  char name[64];
  std::snprintf(name, sizeof name, "eps_t %g, eps_r %g, ", p.contact.eps_t, p.contact.eps_r);
  return name + FormatState(s0);
}

std::string ThrownBy(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(EdgeParameters, ValidationAcceptsTheLimitsAndRefusesAContactThatCreatesEnergy) {
  EXPECT_NO_THROW(ValidateParameters(Edge(0.0, 0.0, 0.01, 0.01)));
  EXPECT_NO_THROW(ValidateParameters(Edge(0.2, 0.0, 0.01, 0.01)));
  EXPECT_NO_THROW(ValidateParameters(Edge(0.2, 1.0, 1e-9, 1e-9)));
  EXPECT_NO_THROW(ValidateParameters(Edge(0.0, 0.0, 1e-9, 1e-9)));
  ModelParameters at_threshold = Edge(0.0, 1.0, 0.01, 0.01);
  at_threshold.contact.mu = at_threshold.RollingResistance();  // 0.03
  EXPECT_NO_THROW(ValidateParameters(at_threshold));

  const std::string no_friction = ThrownBy([] { ValidateParameters(Edge(0.0, 1.0, 0.01, 0.01)); });
  EXPECT_NE(no_friction.find("below the rolling resistance"), std::string::npos) << no_friction;
  EXPECT_NE(no_friction.find("d = 0"), std::string::npos) << no_friction;
  EXPECT_NE(ThrownBy([] { ValidateParameters(Edge(0.2, 1.0, 0.0, 0.01)); }).find("positive"),
            std::string::npos);
  EXPECT_NE(ThrownBy([] { ValidateParameters(Edge(-0.1, 0.0, 0.01, 0.01)); }).find(">= 0"),
            std::string::npos);
  EXPECT_NE(ThrownBy([] { ValidateParameters(Edge(0.2, 1.0, NAN, 0.01)); }).find("finite"),
            std::string::npos);

  // The simulator refuses such a set too, with the same reason, instead of integrating it.
  const BallState roll = testing::PaperFigureStates()[0];
  EXPECT_EQ(ThrownBy([&] { Simulate(Edge(0.0, 1.0, 0.01, 0.01), roll, 1.0); }), no_friction);
  EXPECT_NE(ThrownBy([&] { SimulateArrival(Edge(0.2, 1.0, 0.0, 0.0), roll, 0.0, 1.0); }), "");
}

TEST(EdgeParameters, TheRefusedRangeIsWhereTheContactCreatesEnergy) {
  // The rolling-resistance moment does work m g mu_r (u . v_hat - |v|) (u the contact slip):
  // without friction to take more than that away, a ball with back spin gains energy.
  const ModelParameters frictionless = Edge(0.0, 1.0, 0.01, 0.01);
  const BallState back_spin = MakeBallState(0, 0, 0, 1, 100, 0, 0);  // u = 3 m/s along v
  const double m = frictionless.ball.mass, g = frictionless.ball.gravity;
  const double regularized_v = std::hypot(1.0, 0.01 * frictionless.contact.patch_radius);
  EXPECT_NEAR(Power(frictionless, back_spin),
              m * g * frictionless.RollingResistance() * (3.0 - 1.0) / regularized_v, 1e-12);
  EXPECT_GT(Power(frictionless, back_spin), 0.0);

  // At mu = mu_r, the smallest mu accepted, no state of any scale gains energy.
  ModelParameters threshold = Edge(0.0, 1.0, 0.01, 0.01);
  threshold.contact.mu = threshold.RollingResistance();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double eps : {0.01, 1e-9}) {
    threshold.contact.eps_t = threshold.contact.eps_r = eps;
    for (int i = 0; i < 20000; ++i) {
      const double scale = std::pow(10.0, -6.0 + 3.5 * (u(rng) + 1.0));  // 1 um/s .. 10 m/s
      const double w = scale / threshold.ball.radius;
      const BallState s = MakeBallState(0, 0, scale * u(rng), scale * u(rng), w * u(rng),
                                        w * u(rng), i % 2 ? w * u(rng) : 0.0);
      ASSERT_LE(Power(threshold, s), 1e-12 * Energy(s, threshold)) << FormatState(s);
    }
  }
}

TEST(EdgeParameters, FrictionlessBallKeepsItsVelocityAndSpin) {
  // mu = 0 (so d = 0): no force and no moment act, so every state moves uniformly for ever.
  for (double eps : {0.01, 1e-9}) {
    const ModelParameters p = Edge(0.0, 0.0, eps, eps);
    for (const BallState& s0 : testing::PaperFigureStates()) {
      const SimulationResult r = Simulate(p, s0, 8.0);
      EXPECT_EQ(r.final_state.tail<5>(), s0.tail<5>()) << FormatState(s0);
      EXPECT_NEAR(r.final_state[kX], 8.0 * s0[kVx], 1e-12);
      EXPECT_NEAR(r.final_state[kY], 8.0 * s0[kVy], 1e-12);
      EXPECT_EQ(r.rest_time, -1.0);
      EXPECT_LT(r.stats.steps + r.stats.rejected_steps, 20);
      EXPECT_EQ(Energy(r.final_state, p), Energy(s0, p));
    }
  }
  // The integral friction model has no friction to integrate either.
  SimulationOptions integral;
  integral.model = Model::kIntegral;
  const BallState s0 = testing::PaperFigureStates()[3];
  EXPECT_EQ(Simulate(Edge(0.0, 0.0, 0.01, 0.01), s0, 8.0, integral).final_state.tail<5>(),
            s0.tail<5>());
  // The closed form's sliding phase never ends without friction: it says so.
  SimulationOptions closed;
  closed.model = Model::kClosedForm;
  EXPECT_NE(ThrownBy([&] { Simulate(Edge(0.0, 0.0, 0.01, 0.01), s0, 8.0, closed); }).find("mu_s"),
            std::string::npos);
}

TEST(EdgeParameters, WithoutRollingResistanceABallRollsOnUntilTheTimeLimit) {
  const ModelParameters p = Edge(0.2, 0.0, 0.01, 0.01);
  // A natural roll meets no force at all.
  const SimulationResult roll = Simulate(p, testing::PaperFigureStates()[0], 8.0);
  EXPECT_NEAR(roll.final_state[kY], 8.0, 1e-12);
  EXPECT_EQ(roll.final_state.tail<5>(), testing::PaperFigureStates()[0].tail<5>());

  // A stun shot slides until t1 = 2 v0 / (7 mu g), then rolls at 5/7 v0 for ever.
  const BallState stun = MakeBallState(0, 0, 0, 1, 0, 0, 0);
  const SimulationResult r = Simulate(p, stun, 8.0);
  EXPECT_NEAR(r.final_state[kVy], 5.0 / 7.0, 1e-9);
  EXPECT_NEAR(r.final_state[kWx], -5.0 / 7.0 / p.ball.radius, 1e-7);
  EXPECT_EQ(r.rest_time, -1.0);
  testing::ExpectEnergyNeverRises(*r.trajectory, p, 8.0, 4000, 1e-12);
  EXPECT_NEAR(Energy(r.final_state, p), 5.0 / 7.0 * Energy(stun, p), 1e-9);  // 2/7 lost sliding

  // Asked where it stops, it runs to the time limit and says it did not arrive; a horizon of
  // three hours costs no more steps than 8 s, as the step grows while it rolls.
  const auto start = std::chrono::steady_clock::now();
  const Arrival a = SimulateArrival(p, stun, 0.0, 1e4);
  const double wall_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  EXPECT_FALSE(a.reached);
  EXPECT_EQ(a.time, 1e4);
  ASSERT_TRUE(a.state.allFinite());
  EXPECT_NEAR(a.state[kVy], 5.0 / 7.0, 1e-9);
  const ClosedFormTrajectory exact(ClosedFormParameters::From(p), stun);
  EXPECT_NEAR(a.state[kY], exact.At(1e4)[kY], 1e-5);
  EXPECT_LT(a.stats.steps + a.stats.rejected_steps, 200);
  std::fprintf(stderr, "d = 0 stun to t = 1e4 s: %ld steps (%ld rejected), %.2f ms, Y = %.9f m\n",
               a.stats.steps, a.stats.rejected_steps, wall_ms, a.state[kY]);
}

// The limit of the physics notes: with wz = 0 and the same d, the 5-DOF model becomes the
// closed form as eps_t, eps_r -> 0 (rolling resistance while sliding aside, hence d = 0 or a
// ball rolling from the start).
struct ClosedFormLimit {
  const char* name;
  double d;
  BallState initial;
};

TEST(EdgeParameters, TinyRegularizationReachesTheClosedFormInBoundedSteps) {
  const ClosedFormLimit cases[] = {
      {"stun, d = 0", 0.0, MakeBallState(0, 0, 0, 1, 0, 0, 0)},
      {"Fig. 7 spins, d = 0", 0.0, MakeBallState(0, 0, 0, 1, -50, 5, 0)},
      {"Fig. 8 spins, d = 0", 0.0, MakeBallState(0, 0, 0, 1, 150, 5, 0)},
      {"oblique, d = 0", 0.0, MakeBallState(0, 0, 0.4, 1.0, 30, -10, 0)},
      {"Fig. 6 roll, d = 1", 1.0, MakeBallState(0, 0, 0, 1, -50, 0, 0)},
  };
  for (const ClosedFormLimit& c : cases) {
    const ModelParameters p = Edge(0.2, c.d, 1e-9, 1e-9);
    const auto start = std::chrono::steady_clock::now();
    const SimulationResult r = Simulate(p, c.initial, 8.0, Budget(10000));
    const double wall_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const ClosedFormTrajectory exact(ClosedFormParameters::From(p), c.initial);
    ASSERT_TRUE(r.final_state.allFinite()) << c.name;
    for (double t : {0.05, 0.5, 2.0, 8.0}) {
      const BallState s = r.trajectory->At(t), e = exact.At(t);
      EXPECT_LT((s.head<2>() - e.head<2>()).norm(), 2e-6) << c.name << " t = " << t;
      EXPECT_LT((s.segment<2>(kVx) - e.segment<2>(kVx)).norm(), 1e-6) << c.name << " t = " << t;
    }
    testing::ExpectEnergyNeverRises(*r.trajectory, p, 8.0, 4000, 1e-9);
    std::fprintf(stderr,
                 "eps = 1e-9, %s: %ld steps (%ld rejected), %.2f ms, X, Y = %.9f, %.9f "
                 "(closed form %.9f, %.9f)\n",
                 c.name, r.stats.steps, r.stats.rejected_steps, wall_ms, r.final_state[kX],
                 r.final_state[kY], exact.At(8.0)[kX], exact.At(8.0)[kY]);
  }
}

TEST(EdgeParameters, TinyRegularizationOnThePaperFiguresIsFiniteConvergedAndDissipative) {
  // Side spin and rolling resistance while sliding have no closed form: the truth is the same
  // model at a 100x tighter tolerance. eps_t and eps_r tiny together and each alone.
  const ModelParameters sets[] = {Edge(0.2, 1.0, 1e-9, 1e-9), Edge(0.2, 1.0, 1e-9, 0.01),
                                  Edge(0.2, 1.0, 0.01, 1e-9)};
  for (const ModelParameters& p : sets) {
    for (const BallState& s0 : testing::PaperFigureStates()) {
      const std::string name = Name(p, s0);
      const auto start = std::chrono::steady_clock::now();
      const SimulationResult a = Simulate(p, s0, 8.0, Budget(40000));
      const double wall_ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count();
      const SimulationResult b = Simulate(p, s0, 8.0, Budget(100000, 1e-9));
      ASSERT_TRUE(a.final_state.allFinite()) << name;
      EXPECT_LT((a.final_state.head<2>() - b.final_state.head<2>()).norm(), 1e-6) << name;
      testing::ExpectEnergyNeverRises(*a.trajectory, p, 8.0, 2000, 1e-9);
      std::fprintf(stderr, "%s: %ld steps (%ld rejected), %.2f ms, X, Y = %.9f, %.9f\n",
                   name.c_str(), a.stats.steps, a.stats.rejected_steps, wall_ms, a.final_state[kX],
                   a.final_state[kY]);
    }
  }
}

TEST(EdgeParameters, PlannerToleranceDoesNotMakeTheSlipChatter) {
  // At the planner's tolerance (1e-6) and eps = 1e-6, a stun shot's slip used to chatter across
  // zero at the end of sliding: more than 300,000 steps where 100 do.
  for (double eps : {1e-6, 1e-9}) {
    const Arrival a = SimulateArrival(Edge(0.2, 1.0, eps, eps), MakeBallState(0, 0, 0, 1, 0, 0, 0),
                                      0.0, 10.0, Budget(5000, 1e-6), true);
    EXPECT_TRUE(a.reached);
    EXPECT_TRUE(a.sensitivity->allFinite());
    std::fprintf(stderr,
                 "stun, eps = %g, tolerance 1e-6, with sensitivities: %ld steps "
                 "(%ld rejected), stops at Y = %.9f m\n",
                 eps, a.stats.steps, a.stats.rejected_steps, a.state[kY]);
  }
}

}  // namespace
}  // namespace billiard::physics
