#include "bench/peer_comparison.h"

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "sim/physics/ball_dynamics.h"
#include "sim/physics/rodas4.h"
#include "sim/physics/simulator.h"
#include "sim/physics/stage_matrix.h"
#include "sim/physics/trajectory.h"

namespace billiard::bench {

namespace {

// The converged endpoints (as the speed-against-error benchmark's approx reference).
constexpr double kConvergedTolerance = 1e-10;
// A peer gives up on a tolerance after this many attempted steps (the sweep's loosest tolerances
// are allowed to fail).
constexpr long kPeerMaxSteps = 1'000'000;
// The per-step arithmetic (the floor's and a whole RODAS4 step's): states sampled along the
// figure's trajectory, so that it is not timed on one state the branch predictor has learned
// (held in the timed object itself, not on the heap: where the heap puts them moved the time by
// up to 2x from run to run); a 1 ms step, whose value does not change the cost.
constexpr int kArithmeticStates = 64;
constexpr double kArithmeticStep = 1e-3;  // [s]
constexpr int kRodas4Solves = 6;          // one per stage, Hairer & Wanner 1996

double Distance(const physics::BallState& a, const physics::BallState& b) {
  return (a.head<2>() - b.head<2>()).norm();
}

physics::SimulationOptions OurOptions(double tolerance, bool rest_switch) {
  physics::SimulationOptions o;
  o.tolerance = tolerance;
  o.rest_switch = rest_switch;
  return o;
}

// The per-step arithmetic over states along a trajectory: one call of either pass is one pass
// over them.
class StepArithmetic {
 public:
  StepArithmetic(const physics::ModelParameters& p, const physics::Trajectory& trajectory,
                 double t_end)
      : dynamics_(p, physics::ApproximateFrictionModel{p.contact}) {
    for (int i = 0; i < kArithmeticStates; ++i) {
      states_[i] = trajectory.At(t_end * i / (kArithmeticStates - 1));
    }
  }

  // The floor's: one right-hand side with its Jacobian, the stage matrix inverted and six
  // solves, each feeding the next as the stages do, by RODAS4's own code (stage_matrix.h).
  void Floor() {
    for (const physics::BallState& s : states_) {
      physics::BallState f;
      physics::StateJacobian jac;
      dynamics_.DerivativeAndJacobian(s, &f, &jac);
      physics::StageMatrix<physics::IsTranslationInvariant<Dynamics>::value> m;
      m.Invert(jac, 1.0 / (Stepper::kGamma * kArithmeticStep));
      physics::BallState g = f;
      for (int k = 0; k < kRodas4Solves; ++k) g = m.Solve(g);
      sink_ = sink_ + g.sum();
    }
  }

  // A whole RODAS4 step attempt (sim/physics/rodas4.h): the floor's arithmetic, the five further
  // right-hand sides and the stage sums; no error control, dense output or event search.
  void Rodas4() {
    Stepper stepper(dynamics_);
    physics::StepAttempt attempt;
    physics::IntegrationStats stats;
    for (const physics::BallState& s : states_) {
      stepper.Attempt(s, kArithmeticStep, &attempt, &stats);
      stepper.Accept();
      sink_ = sink_ + attempt.x_new.sum();
    }
  }

 private:
  using Dynamics = physics::BallDynamics<physics::ApproximateFrictionModel>;
  using Stepper = physics::Rodas4Stepper<Dynamics>;
  const Dynamics dynamics_;
  std::array<physics::BallState, kArithmeticStates> states_;
  volatile double sink_ = 0.0;  // every result feeds it, so that nothing is optimised away
};

// The loosest tolerance at which the peer ends within the accuracy of `converged` (untimed), and
// in *timed_run the run at that tolerance, to be timed. make(tol) returns the run at a tolerance,
// a callable returning PeerRun: what make sets up is not timed.
template <class MakeRun>
PeerOnFigure Peer(const std::string& name, const physics::BallState& converged, MakeRun make,
                  std::function<PeerRun()>* timed_run) {
  PeerOnFigure peer;
  peer.peer = name;
  for (double tol : PeerToleranceSweep()) {
    std::function<PeerRun()> run = make(tol);
    try {
      peer.run = run();
    } catch (const std::runtime_error&) {
      continue;  // a step budget exceeded at a loose tolerance: not accurate there
    }
    peer.error_m = Distance(peer.run.final_state, converged);
    if (peer.error_m > kPeerEndpointAccuracy) continue;
    peer.found = true;
    peer.tolerance = tol;
    *timed_run = run;
    return peer;
  }
  peer = PeerOnFigure();
  peer.peer = name;
  return peer;
}

// One figure: the references, the sweeps, then ours, the floor's arithmetic and the peers timed
// interleaved (MedianWallUsInterleaved), so that their ratios hold on a busy machine.
FigureComparison CompareOnFigure(const physics::ModelParameters& p, const Scene& scene) {
  FigureComparison fig;
  fig.scene = scene.name;
  const physics::SimulationResult ours_converged =
      physics::Simulate(p, scene.initial, scene.t_end, OurOptions(kConvergedTolerance, true));
  const physics::BallState regularized_converged =
      physics::Simulate(p, scene.initial, scene.t_end, OurOptions(kConvergedTolerance, false))
          .final_state;
  fig.rest_switch_shift_m = Distance(ours_converged.final_state, regularized_converged);

  const FloorSteps fewest = FewestAcceptedSteps(p, scene, ours_converged.final_state);
  fig.floor.steps = fewest.steps;
  fig.floor.tolerance = fewest.tolerance;
  StepArithmetic arithmetic(p, *ours_converged.trajectory, scene.t_end);

  std::function<PeerRun()> odeint_run, cvode_run;
  fig.odeint = Peer(
      "odeint-rosenbrock4", regularized_converged,
      [&](double tol) {
        return [&p, &scene, tol] {
          return OdeintRosenbrock4(p, scene.initial, scene.t_end, tol, kPeerMaxSteps);
        };
      },
      &odeint_run);
  fig.cvode = Peer(
      "cvode-bdf", regularized_converged,
      [&](double tol) {
        // The solver is made once per tolerance; each run re-initialises it (CvodeBdf).
        auto solver = std::make_shared<CvodeBdf>(p, tol, kPeerMaxSteps);
        return [&scene, solver] { return solver->Run(scene.initial, scene.t_end); };
      },
      &cvode_run);

  const physics::SimulationOptions defaults;  // ours, as `billiard simulate` runs
  fig.ours.tolerance = defaults.tolerance;
  physics::SimulationResult ours;
  std::vector<std::function<void()>> timed = {
      [&] { ours = physics::Simulate(p, scene.initial, scene.t_end, defaults); },
      [&] { arithmetic.Floor(); }, [&] { arithmetic.Rodas4(); }};
  if (fig.odeint.found) timed.push_back([&] { fig.odeint.run = odeint_run(); });
  if (fig.cvode.found) timed.push_back([&] { fig.cvode.run = cvode_run(); });
  const std::vector<double> wall_us = MedianWallUsInterleaved(timed, kPeerTiming);

  fig.ours.wall_us = wall_us[0];
  fig.ours.stats = ours.stats;
  fig.ours.error_m = Distance(ours.final_state, ours_converged.final_state);
  fig.floor.step_us = wall_us[1] / kArithmeticStates;
  fig.floor.wall_us = fig.floor.steps * fig.floor.step_us;
  fig.floor.rodas4_step_us = wall_us[2] / kArithmeticStates;
  std::size_t next = 3;
  if (fig.odeint.found) fig.odeint.wall_us = wall_us[next++];
  if (fig.cvode.found) fig.cvode.wall_us = wall_us[next++];
  return fig;
}

}  // namespace

// From 3e-4 up only the position weight loosens: IntegratorOptionsFor caps the velocity and spin
// weights at 10 eps a (3e-4 m/s with the paper's set), so a peer that reaches the accuracy at
// the loosest tolerance gains little from looser ones.
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

double OursOverFloorFromArithmetic(const FigureComparison& f) {
  return Ratio(f.ours.stats.steps * f.floor.rodas4_step_us, f.floor.wall_us);
}

PeerComparison ComparePeers(const physics::ModelParameters& p, const std::vector<Scene>& figures,
                            const std::function<void(const std::string&)>& progress) {
  PeerComparison comparison;
  for (const Scene& scene : figures) {
    progress("peers: " + scene.name);
    comparison.figures.push_back(CompareOnFigure(p, scene));
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
           {"wall_us", f.floor.wall_us},
           {"rodas4_step_us", f.floor.rodas4_step_us}}},
         {"ours_over_odeint", over_odeint},
         {"ours_over_cvode", Ratio(f.ours.wall_us, f.cvode.wall_us)},
         {"ours_over_floor", over_floor},
         {"ours_over_floor_from_arithmetic", OursOverFloorFromArithmetic(f)},
         {"odeint_target_met", f.odeint.found && over_odeint <= kTargetOursOverOdeint},
         {"floor_target_met", over_floor <= kTargetOursOverFloor}});
  }
  return {{"endpoint_accuracy_m", kPeerEndpointAccuracy},
          {"target_ours_over_odeint", kTargetOursOverOdeint},
          {"target_ours_over_floor", kTargetOursOverFloor},
          {"figures", figures}};
}

}  // namespace billiard::bench
