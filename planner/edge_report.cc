#include "planner/edge_report.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include "planner/shot_planner.h"
#include "sim/params/parameter_sets.h"
#include "sim/physics/closed_form.h"
#include "sim/physics/simulator.h"

namespace billiard::planner {

namespace {

struct EdgeSet {
  std::string name;
  double mu, d, eps_t, eps_r;
};

physics::ModelParameters WithContact(const EdgeSet& set) {
  physics::ModelParameters p = params::LoadParameters("paper");
  p.name = set.name;
  p.contact.mu = set.mu;
  p.contact.d = set.d;
  p.contact.eps_t = set.eps_t;
  p.contact.eps_r = set.eps_r;
  return p;
}

nlohmann::json Array(const physics::BallState& s) {
  return std::vector<double>(s.data(), s.data() + 7);
}

double Energy(const physics::BallState& s, const physics::ModelParameters& p) {
  return physics::KineticEnergy(s, p.ball.mass, p.ball.radius);
}

nlohmann::json Simulation(const physics::ModelParameters& p, const std::string& scene,
                          const physics::BallState& initial) {
  constexpr double kEnd = 8.0;
  nlohmann::json j = {{"scene", scene}, {"initial", Array(initial)}, {"t_end", kEnd}};
  try {
    const auto start = std::chrono::steady_clock::now();
    const physics::SimulationResult r = physics::Simulate(p, initial, kEnd);
    j["wall_us"] =
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    j["steps"] = r.stats.steps;
    j["rejected_steps"] = r.stats.rejected_steps;
    j["rhs_evals"] = r.stats.rhs_evals;
    j["final"] = Array(r.final_state);
    j["rest_time"] = r.rest_time < 0.0 ? nlohmann::json() : nlohmann::json(r.rest_time);
    j["energy_start_J"] = Energy(initial, p);
    j["energy_end_J"] = Energy(r.final_state, p);
    double rise = 0.0, previous = Energy(initial, p);
    for (int i = 1; i <= 4000; ++i) {
      const double e = Energy(r.trajectory->At(kEnd * i / 4000), p);
      rise = std::max(rise, e - previous);
      previous = e;
    }
    j["max_energy_rise_J"] = rise;
    // The closed form has no pivot friction, and no end of sliding without friction.
    if (initial[physics::kWz] == 0.0 && p.contact.mu > 0.0) {
      const Eigen::Vector2d exact =
          physics::ClosedFormTrajectory(physics::ClosedFormParameters::From(p), initial)
              .At(kEnd)
              .head<2>();
      j["closed_form_final"] = {exact.x(), exact.y()};
      j["closed_form_gap_m"] = (exact - r.final_state.head<2>()).norm();
    }
  } catch (const std::exception& e) {
    j["error"] = e.what();
  }
  return j;
}

struct Request {
  std::string name;
  ShotRequest shot;
};

std::vector<Request> Requests() {
  const auto shot = [](double v2, SpinStyle style, double side_spin) {
    ShotRequest q;
    q.from = {0.4, 0.4};
    q.to = {1.6, 0.8};
    q.final_speed = v2;
    q.style = style;
    q.side_spin = side_spin;
    return q;
  };
  return {{"natural, stop", shot(0.0, SpinStyle::kNatural, 0.0)},
          {"stun, stop", shot(0.0, SpinStyle::kStun, 0.0)},
          {"draw, wz 20, stop", shot(0.0, SpinStyle::kDraw, 20.0)},
          {"natural, 0.3 m/s", shot(0.3, SpinStyle::kNatural, 0.0)},
          {"stun, 0.3 m/s", shot(0.3, SpinStyle::kStun, 0.0)},
          {"follow, wz -15, 0.3 m/s", shot(0.3, SpinStyle::kFollow, -15.0)},
          {"draw, 1.5 m/s", shot(1.5, SpinStyle::kDraw, 0.0)},
          {"draw, wz 10, 1.5 m/s", shot(1.5, SpinStyle::kDraw, 10.0)}};
}

nlohmann::json Plan(const physics::ModelParameters& p, const Request& r,
                    const PlannerOptions& options = {}) {
  const ShotPlan plan = PlanShot(r.shot, p, options);
  nlohmann::json j = {{"request", r.name},
                      {"status", PlanStatusName(plan.status)},
                      {"reason", plan.reason},
                      {"iterations", plan.iterations},
                      {"simulations", plan.simulations},
                      {"solve_us", plan.solve_us},
                      {"launch_speed", plan.v0.norm()},
                      {"refined_miss_m", plan.refined_miss_m}};
  if (plan.status == PlanStatus::kOk) {
    const physics::BallState launch =
        physics::MakeBallState(r.shot.from.x(), r.shot.from.y(), plan.v0.x(), plan.v0.y(),
                               plan.w0.x(), plan.w0.y(), plan.w0.z());
    const physics::Arrival a = physics::SimulateArrival(p, launch, r.shot.final_speed, 60.0);
    j["resimulated_miss_m"] = (a.state.head<2>() - r.shot.to).norm();
  }
  return j;
}

}  // namespace

nlohmann::json EdgeParameterReport() {
  const EdgeSet sets[] = {
      {"paper", 0.2, 1.0, 0.01, 0.01},
      {"mu = 0, d = 0", 0.0, 0.0, 0.01, 0.01},
      {"d = 0", 0.2, 0.0, 0.01, 0.01},
      {"eps_t = eps_r = 1e-9", 0.2, 1.0, 1e-9, 1e-9},
      {"eps_t = 1e-9", 0.2, 1.0, 1e-9, 0.01},
      {"eps_r = 1e-9", 0.2, 1.0, 0.01, 1e-9},
      {"d = 0, eps_t = eps_r = 1e-9", 0.2, 0.0, 1e-9, 1e-9},
      {"mu = 0, d = 0, eps_t = eps_r = 1e-9", 0.0, 0.0, 1e-9, 1e-9},
      {"mu = 0, d = 1 (refused)", 0.0, 1.0, 0.01, 0.01},
      {"eps_t = eps_r = 0 (refused)", 0.2, 1.0, 0.0, 0.0},
  };
  const std::pair<const char*, physics::BallState> scenes[] = {
      {"Fig. 6: rolling", physics::MakeBallState(0, 0, 0, 1, -50, 0, 0)},
      {"stun", physics::MakeBallState(0, 0, 0, 1, 0, 0, 0)},
      {"Fig. 8: back spin", physics::MakeBallState(0, 0, 0, 1, 150, 5, 0)},
      {"Fig. 9: side spin", physics::MakeBallState(0, 0, 0, 1, -50, -3.5, -150)},
      {"Fig. 10: back and side spin", physics::MakeBallState(0, 0, 0, 1, 150, 0, -150)},
  };
  const std::vector<Request> requests = Requests();

  nlohmann::json report = {{"sets", nlohmann::json::array()}};
  for (const EdgeSet& set : sets) {
    const physics::ModelParameters p = WithContact(set);
    nlohmann::json j = {{"name", set.name},   {"mu", set.mu},       {"d", set.d},
                        {"eps_t", set.eps_t}, {"eps_r", set.eps_r}, {"valid", true}};
    try {
      physics::ValidateParameters(p);
    } catch (const std::invalid_argument& e) {
      j["valid"] = false;
      j["reason"] = e.what();
    }
    j["simulations"] = nlohmann::json::array();
    if (j["valid"]) {
      for (const auto& [scene, initial] : scenes) {
        j["simulations"].push_back(Simulation(p, scene, initial));
      }
    }
    j["plans"] = nlohmann::json::array();
    for (const Request& r : requests) j["plans"].push_back(Plan(p, r));
    report["sets"].push_back(j);
  }

  // Budgets too small for a spin-heavy shot: the planner must refuse, never answer ok.
  const physics::ModelParameters paper = params::LoadParameters("paper");
  const physics::ModelParameters tiny_eps =
      WithContact({"eps_t = eps_r = 1e-9", 0.2, 1.0, 1e-9, 1e-9});
  const Request draw{"draw, wz 20, stop", requests[2].shot};
  struct Budget {
    std::string name;
    const physics::ModelParameters& params;
    int max_iterations;
    long max_steps;
  };
  const long steps = physics::SimulationOptions().max_steps;
  const Budget budgets[] = {{"paper, no iteration", paper, 0, steps},
                            {"paper, one iteration", paper, 1, steps},
                            {"eps = 1e-9, one iteration", tiny_eps, 1, steps},
                            {"paper, 10 steps a simulation", paper, 25, 10}};
  report["non_convergence"] = nlohmann::json::array();
  for (const Budget& b : budgets) {
    PlannerOptions options;
    options.max_iterations = b.max_iterations;
    options.acceptable_miss = 1e-7;
    options.simulation.max_steps = b.max_steps;
    nlohmann::json j = Plan(b.params, draw, options);
    j["case"] = b.name + " (acceptable miss 1e-7 m)";
    report["non_convergence"].push_back(j);
  }
  return report;
}

}  // namespace billiard::planner
