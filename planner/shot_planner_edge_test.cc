// The planner with contact parameters at the edge of their range (mu = 0, d = 0, eps = 1e-9 and
// their combinations): every plan it calls ok is simulated again, independently, at the
// simulator's default (10x tighter) tolerance and must land on the target; every refusal must
// say why; parameter sets the model cannot take are refused as invalid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "planner/edge_report.h"
#include "planner/shot_planner.h"
#include "sim/params/parameter_sets.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/physics/simulator.h"

namespace billiard::planner {
namespace {

physics::ModelParameters Edge(double mu, double d, double eps) {
  physics::ModelParameters p = params::LoadParameters("paper");
  p.contact.mu = mu;
  p.contact.d = d;
  p.contact.eps_t = p.contact.eps_r = eps;
  return p;
}

ShotRequest Shot(double final_speed, SpinStyle style, double side_spin = 0.0) {
  ShotRequest q;
  q.from = {0.4, 0.4};
  q.to = {1.6, 0.8};
  q.final_speed = final_speed;
  q.style = style;
  q.side_spin = side_spin;
  return q;
}

// Stops, slow and fast arrivals with every style, with and without side spin, and a slide length.
std::vector<ShotRequest> Requests() {
  std::vector<ShotRequest> requests;
  for (double v2 : {0.0, 0.3, 1.1, 1.5}) {
    for (SpinStyle style :
         {SpinStyle::kNatural, SpinStyle::kStun, SpinStyle::kFollow, SpinStyle::kDraw}) {
      requests.push_back(Shot(v2, style));
    }
    requests.push_back(Shot(v2, SpinStyle::kDraw, 10.0));
  }
  ShotRequest slide = Shot(0.3, SpinStyle::kNatural);
  slide.slide_length = 0.5;
  requests.push_back(slide);
  return requests;
}

physics::BallState LaunchOf(const ShotPlan& plan, const ShotRequest& q) {
  return physics::MakeBallState(q.from.x(), q.from.y(), plan.v0.x(), plan.v0.y(), plan.w0.x(),
                                plan.w0.y(), plan.w0.z());
}

// An ok plan must really arrive at the target, simulated at the simulator's default tolerance,
// and its stroke must give its launch; a refusal must have a reason.
void ExpectNoWrongOk(const physics::ModelParameters& p, const ShotRequest& q, const ShotPlan& plan,
                     const std::string& what) {
  if (plan.status != PlanStatus::kOk) {
    EXPECT_FALSE(plan.reason.empty()) << what;
    return;
  }
  const physics::Arrival a = physics::SimulateArrival(p, LaunchOf(plan, q), q.final_speed, 60.0);
  EXPECT_TRUE(a.reached) << what;
  EXPECT_LT((a.state.head<2>() - q.to).norm(), 1e-5) << what;
  EXPECT_LT((physics::StrikeBall(plan.stroke, q.from, p) - LaunchOf(plan, q)).norm(), 1e-9) << what;
}

struct EdgeSet {
  const char* name;
  physics::ModelParameters params;
};

TEST(EdgeParameterPlans, EveryOkLandsOnTheTargetAndEveryRefusalSaysWhy) {
  const EdgeSet sets[] = {
      {"mu = 0, d = 0", Edge(0.0, 0.0, 0.01)},
      {"d = 0", Edge(0.2, 0.0, 0.01)},
      {"eps = 1e-9", Edge(0.2, 1.0, 1e-9)},
      {"d = 0, eps = 1e-9", Edge(0.2, 0.0, 1e-9)},
      {"mu = 0, d = 0, eps = 1e-9", Edge(0.0, 0.0, 1e-9)},
  };
  const physics::ModelParameters paper = params::LoadParameters("paper");
  const std::vector<ShotRequest> requests = Requests();
  for (const EdgeSet& set : sets) {
    int ok = 0;
    double worst_us = 0.0;
    for (std::size_t i = 0; i < requests.size(); ++i) {
      const ShotRequest& q = requests[i];
      const ShotPlan plan = PlanShot(q, set.params);
      const std::string what = std::string(set.name) + ", request " + std::to_string(i) + ": " +
                               PlanStatusName(plan.status) + " " + plan.reason;
      ExpectNoWrongOk(set.params, q, plan, what);
      ok += plan.status == PlanStatus::kOk;
      worst_us = std::max(worst_us, plan.solve_us);
      // The model's physics decides, not the numerics: without friction nothing ever slows
      // down, without rolling resistance nothing stops, and eps only sets the slip scale.
      if (set.params.contact.mu == 0.0) {
        EXPECT_EQ(plan.status, PlanStatus::kUnreachable) << what;
        EXPECT_NE(plan.reason.find("never changes"), std::string::npos) << what;
      } else if (set.params.contact.d == 0.0 && q.final_speed == 0.0) {
        EXPECT_EQ(plan.status, PlanStatus::kUnreachable) << what;
        EXPECT_NE(plan.reason.find("never stops"), std::string::npos) << what;
      } else if (set.params.contact.d != 0.0) {
        EXPECT_EQ(plan.status, PlanShot(q, paper).status) << what;
      }
      if (plan.status != PlanStatus::kOk) {
        EXPECT_NE(plan.status, PlanStatus::kNotConverged) << what;
      }
    }
    std::fprintf(stderr, "%s: %d of %zu requests planned, slowest %.1f ms\n", set.name, ok,
                 requests.size(), worst_us / 1e3);
  }
}

TEST(EdgeParameterPlans, WithoutRollingResistanceTheBallArrivesStillSliding) {
  // d = 0: the speed falls only while the ball slides, by mu g along the line (Coulomb), so a
  // ball that arrives at v2 was launched at sqrt(v2^2 + 2 mu g D). With eps = 1e-9 the 5-DOF
  // ball is that Coulomb ball, and the closed-form launch needs no refinement.
  const physics::ModelParameters p = Edge(0.2, 0.0, 1e-9);
  for (double v2 : {1.1, 1.5}) {
    const ShotRequest q = Shot(v2, SpinStyle::kDraw);
    const ShotPlan plan = PlanShot(q, p);
    ASSERT_EQ(plan.status, PlanStatus::kOk) << plan.reason;
    const double distance = (q.to - q.from).norm();
    EXPECT_NEAR(plan.v0.norm(), std::sqrt(v2 * v2 + 2 * 0.2 * p.ball.gravity * distance), 1e-9);
    EXPECT_EQ(plan.iterations, 0);
    EXPECT_DOUBLE_EQ(plan.slide_length, distance);
    ExpectNoWrongOk(p, q, plan, "v2 = " + std::to_string(v2));
  }
  // Stun keeps 5/7 of its speed when it starts rolling, more than 1.1 m/s here: it never slows
  // to that speed, and the planner says so before simulating.
  const ShotPlan stun = PlanShot(Shot(1.1, SpinStyle::kStun), p);
  EXPECT_EQ(stun.status, PlanStatus::kUnreachable);
  EXPECT_NE(stun.reason.find("rolls on at"), std::string::npos) << stun.reason;
  EXPECT_EQ(stun.simulations, 0);
}

TEST(EdgeParameterPlans, ParameterSetsTheModelCannotTakeAreInvalid) {
  physics::ModelParameters nan_mu = params::LoadParameters("paper");
  nan_mu.contact.mu = NAN;
  const std::pair<physics::ModelParameters, const char*> sets[] = {
      {Edge(0.0, 1.0, 0.01), "below the rolling resistance"},  // creates energy
      {Edge(0.2, 1.0, 0.0), "eps_t and eps_r must be positive"},
      {Edge(0.2, 1.0, -1e-9), "eps_t and eps_r must be positive"},
      {nan_mu, "finite"},
  };
  for (const auto& [params, words] : sets) {
    const ShotPlan plan = PlanShot(Shot(0.0, SpinStyle::kNatural), params);
    EXPECT_EQ(plan.status, PlanStatus::kInvalid) << plan.reason;
    EXPECT_NE(plan.reason.find("invalid parameters"), std::string::npos) << plan.reason;
    EXPECT_NE(plan.reason.find(words), std::string::npos) << plan.reason;
    EXPECT_EQ(plan.simulations, 0);
  }
}

TEST(EdgeParameterPlans, ReportCoversEverySetAndFindsNoWrongOk) {
  const nlohmann::json report = EdgeParameterReport();
  ASSERT_EQ(report["sets"].size(), 10u);
  for (const auto& set : report["sets"]) {
    const std::string name = set["name"];
    EXPECT_EQ(set["valid"].get<bool>(), name.find("refused") == std::string::npos) << name;
    if (!set["valid"].get<bool>()) {
      EXPECT_FALSE(set["reason"].get<std::string>().empty()) << name;
      EXPECT_TRUE(set["simulations"].empty()) << name;
    } else {
      EXPECT_EQ(set["simulations"].size(), 5u) << name;
    }
    for (const auto& s : set["simulations"]) {
      EXPECT_FALSE(s.contains("error")) << name << ", " << s["scene"] << ": " << s["error"];
      EXPECT_LE(s["max_energy_rise_J"].get<double>(), 1e-9) << name << ", " << s["scene"];
    }
    ASSERT_EQ(set["plans"].size(), 8u) << name << ": every request of the report";
    for (const auto& plan : set["plans"]) {
      const std::string what = name + ", " + plan["request"].get<std::string>();
      if (plan["status"] == "ok") {
        EXPECT_LT(plan["resimulated_miss_m"].get<double>(), 1e-5) << what;
      } else {
        EXPECT_FALSE(plan["reason"].get<std::string>().empty()) << what;
      }
    }
  }
  ASSERT_EQ(report["non_convergence"].size(), 4u);
  for (const auto& plan : report["non_convergence"]) {
    EXPECT_EQ(plan["status"], "not_converged") << plan["case"] << ": " << plan["reason"];
  }
}

}  // namespace
}  // namespace billiard::planner
