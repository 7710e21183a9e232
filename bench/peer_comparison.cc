#include "bench/peer_comparison.h"

#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "sim/physics/ball_dynamics.h"
#include "sim/physics/simulator.h"

namespace billiard::bench {

namespace {

// The converged endpoints (as the speed-against-error benchmark's approx reference).
constexpr double kConvergedTolerance = 1e-10;
// A peer gives up on a tolerance after this many attempted steps (the sweep's loosest tolerances
// are allowed to fail).
constexpr long kPeerMaxSteps = 1'000'000;
// The floor's per-step arithmetic: states sampled along the figure's trajectory, so that it is
// not timed on one state the branch predictor has learned; gamma and a step size for the matrix
// I/(gamma h) - J (their values do not change the cost).
constexpr int kArithmeticStates = 64;
constexpr double kRodas4Gamma = 0.25;
constexpr double kNominalStep = 1e-3;  // [s]
constexpr int kRodas4Solves = 6;       // one per stage, Hairer & Wanner 1996

double Distance(const physics::BallState& a, const physics::BallState& b) {
  return (a.head<2>() - b.head<2>()).norm();
}

physics::SimulationOptions OurOptions(double tolerance, bool rest_switch) {
  physics::SimulationOptions o;
  o.tolerance = tolerance;
  o.rest_switch = rest_switch;
  return o;
}

// Time of the floor's per-step arithmetic [us], averaged over `states`.
double StepArithmeticUs(const physics::ModelParameters& p,
                        const std::vector<physics::BallState>& states) {
  using Matrix = physics::StateJacobian;
  const physics::BallDynamics<physics::ApproximateFrictionModel> dynamics(
      p, physics::ApproximateFrictionModel{p.contact});
  const Matrix shift = Matrix::Identity() / (kRodas4Gamma * kNominalStep);
  double sink = 0.0;  // every result feeds it, so that nothing is optimised away
  const auto pass = [&] {
    for (const physics::BallState& s : states) {
      physics::BallState f;
      Matrix jac;
      dynamics.DerivativeAndJacobian(s, &f, &jac);
      // The LU RODAS4 uses (sim/physics/rodas4.h); each solve feeds the next, as the stages do.
      const Eigen::PartialPivLU<Matrix> lu(shift - jac);
      physics::BallState g = f;
      for (int k = 0; k < kRodas4Solves; ++k) g = lu.solve(g);
      sink += g.sum();
    }
  };
  const double us = MedianWallUs(pass, kPeerTiming) / states.size();
  volatile double keep = sink;
  (void)keep;
  return us;
}

OursOnFigure TimeOurs(const physics::ModelParameters& p, const Scene& scene,
                      const physics::BallState& converged) {
  OursOnFigure ours;
  const physics::SimulationOptions options;  // the defaults, as `billiard simulate` runs
  ours.tolerance = options.tolerance;
  physics::SimulationResult result;
  ours.wall_us = MedianWallUs(
      [&] { result = physics::Simulate(p, scene.initial, scene.t_end, options); }, kPeerTiming);
  ours.stats = result.stats;
  ours.error_m = Distance(result.final_state, converged);
  return ours;
}

// The floor on one figure: the fewest steps, and the arithmetic per step along the converged
// trajectory.
FloorOnFigure Floor(const physics::ModelParameters& p, const Scene& scene,
                    const physics::SimulationResult& converged) {
  FloorOnFigure floor;
  const FloorSteps fewest = FewestAcceptedSteps(p, scene, converged.final_state);
  floor.steps = fewest.steps;
  floor.tolerance = fewest.tolerance;
  std::vector<physics::BallState> states;
  for (int i = 0; i < kArithmeticStates; ++i) {
    states.push_back(converged.trajectory->At(scene.t_end * i / (kArithmeticStates - 1)));
  }
  floor.step_us = StepArithmeticUs(p, states);
  floor.wall_us = floor.steps * floor.step_us;
  return floor;
}

// The loosest tolerance at which the peer ends within the accuracy of `converged`, timed there.
// make(tol) returns the run at that tolerance, a callable returning PeerRun: what it sets up is
// not timed.
template <class MakeRun>
PeerOnFigure Peer(const std::string& name, const physics::BallState& converged, MakeRun make) {
  PeerOnFigure peer;
  peer.peer = name;
  for (double tol : PeerToleranceSweep()) {
    auto run = make(tol);
    PeerRun result;
    try {
      result = run();
    } catch (const std::runtime_error&) {
      continue;  // a step budget exceeded at a loose tolerance: not accurate there
    }
    const double error = Distance(result.final_state, converged);
    if (error > kPeerEndpointAccuracy) continue;
    peer.found = true;
    peer.tolerance = tol;
    peer.error_m = error;
    peer.wall_us = MedianWallUs([&] { peer.run = run(); }, kPeerTiming);
    break;
  }
  return peer;
}

}  // namespace

std::vector<double> PeerToleranceSweep() {
  constexpr int kLoosestDecade = 3, kTightestDecade = 10;  // 1e-3 .. 1e-10 = kConvergedTolerance
  std::vector<double> sweep;
  for (int decade = kLoosestDecade; decade <= kTightestDecade; ++decade) {
    sweep.push_back(std::pow(10.0, -decade));
    if (decade < kTightestDecade) sweep.push_back(3.0 * std::pow(10.0, -decade - 1));
  }
  return sweep;
}

FloorSteps FewestAcceptedSteps(const physics::ModelParameters& p, const Scene& scene,
                               const physics::BallState& converged) {
  FloorSteps fewest{std::numeric_limits<long>::max(), 0.0};
  for (double tol : PeerToleranceSweep()) {
    const physics::SimulationResult r =
        physics::Simulate(p, scene.initial, scene.t_end, OurOptions(tol, true));
    if (Distance(r.final_state, converged) <= kPeerEndpointAccuracy &&
        r.stats.steps < fewest.steps) {
      fewest = {r.stats.steps, tol};
    }
  }
  // The sweep's tightest tolerance is the converged one, which reaches the accuracy.
  return fewest;
}

double Ratio(double ours_us, double other_us) { return other_us > 0.0 ? ours_us / other_us : 0.0; }

PeerComparison ComparePeers(const physics::ModelParameters& p, const std::vector<Scene>& figures,
                            const std::function<void(const std::string&)>& progress) {
  PeerComparison comparison;
  for (const Scene& scene : figures) {
    progress("peers: " + scene.name);
    FigureComparison fig;
    fig.scene = scene.name;
    const physics::SimulationResult ours_converged =
        physics::Simulate(p, scene.initial, scene.t_end, OurOptions(kConvergedTolerance, true));
    const physics::BallState regularized_converged =
        physics::Simulate(p, scene.initial, scene.t_end, OurOptions(kConvergedTolerance, false))
            .final_state;
    fig.rest_switch_shift_m = Distance(ours_converged.final_state, regularized_converged);
    fig.ours = TimeOurs(p, scene, ours_converged.final_state);
    fig.floor = Floor(p, scene, ours_converged);
    fig.odeint = Peer("odeint-rosenbrock4", regularized_converged, [&](double tol) {
      return
          [&, tol] { return OdeintRosenbrock4(p, scene.initial, scene.t_end, tol, kPeerMaxSteps); };
    });
    fig.cvode = Peer("cvode-bdf", regularized_converged, [&](double tol) {
      // The solver is made once per tolerance; each run re-initialises it (CvodeBdf).
      auto solver = std::make_shared<CvodeBdf>(p, tol, kPeerMaxSteps);
      return [&, solver] { return solver->Run(scene.initial, scene.t_end); };
    });
    comparison.figures.push_back(fig);
  }
  return comparison;
}

nlohmann::json PeerComparisonJson(const PeerComparison& comparison) {
  const auto peer_json = [](const PeerOnFigure& peer) -> nlohmann::json {
    if (!peer.found) return {{"found", false}};
    return {{"found", true},
            {"tolerance", peer.tolerance},
            {"wall_us", peer.wall_us},
            {"steps", peer.run.steps},
            {"rejected_steps", peer.run.rejected_steps},
            {"rhs_evals", peer.run.rhs_evals},
            {"jacobian_evals", peer.run.jacobian_evals},
            {"error_m", peer.error_m}};
  };
  nlohmann::json figures = nlohmann::json::array();
  for (const FigureComparison& f : comparison.figures) {
    const double over_odeint = Ratio(f.ours.wall_us, f.odeint.wall_us);
    const double over_floor = Ratio(f.ours.wall_us, f.floor.wall_us);
    figures.push_back(
        {{"scene", f.scene},
         {"rest_switch_shift_m", f.rest_switch_shift_m},
         {"ours",
          {{"tolerance", f.ours.tolerance},
           {"wall_us", f.ours.wall_us},
           {"steps", f.ours.stats.steps},
           {"rejected_steps", f.ours.stats.rejected_steps},
           {"rhs_evals", f.ours.stats.rhs_evals},
           {"error_m", f.ours.error_m}}},
         {"odeint", peer_json(f.odeint)},
         {"cvode", peer_json(f.cvode)},
         {"floor",
          {{"steps", f.floor.steps},
           {"tolerance", f.floor.tolerance},
           {"step_us", f.floor.step_us},
           {"wall_us", f.floor.wall_us}}},
         {"ours_over_odeint", over_odeint},
         {"ours_over_cvode", Ratio(f.ours.wall_us, f.cvode.wall_us)},
         {"ours_over_floor", over_floor},
         {"odeint_target_met", f.odeint.found && over_odeint <= kTargetOursOverOdeint},
         {"floor_target_met", over_floor <= kTargetOursOverFloor}});
  }
  return {{"endpoint_accuracy_m", kPeerEndpointAccuracy},
          {"target_ours_over_odeint", kTargetOursOverOdeint},
          {"target_ours_over_floor", kTargetOursOverFloor},
          {"figures", figures}};
}

}  // namespace billiard::bench
