// Our RODAS4 against the off-the-shelf solvers and against the floor, on the same equations
// (issue 16): the approximate 5-DOF model on the paper's Figs. 6-10, 8 s, endpoints within 1e-6 m.
//
// Ours: physics::Simulate with its default options (tolerance 1e-6, rest switch on), what
// `billiard simulate --json` reports as wall_us.
//
// The peers (peer_solvers.h: Boost.Odeint's rosenbrock4, SUNDIALS CVODE's BDF, both with our
// analytic Jacobian and our error weights) integrate the regularized equations to 8 s without a
// rest switch, at the loosest tolerance of a sweep (1e-3 .. 1e-10 by factors of about 3) whose
// endpoint is within 1e-6 m of the converged endpoint of those equations (our RODAS4 at 1e-10,
// rest switch off). Loosest means the first one that is, even when a tighter one is not: the peer
// gets the benefit of the doubt. On Figs. 9 and 10 the ball stops while pivoting, and the peers
// pay for the precession that our rest switch replaces by its average: that is the point of the
// comparison there.
//
// The floor: what an order-4 L-stable method cannot do without, per step times steps.
//   per step: one right-hand side with its Jacobian (one DerivativeAndJacobian pass), the
//     inversion of the stage matrix I/(gamma h) - J and the six solves of a RODAS4 step
//     (Hairer & Wanner 1996), by the same code as RODAS4 (sim/physics/stage_matrix.h),
//     timed in a tight loop over states along the figure's trajectory; RODAS4's five further
//     right-hand sides per step are left out, as the issue defines it;
//   steps: the fewest accepted steps our RODAS4 (rest switch on) takes at any tolerance of the
//     sweep whose endpoint is within 1e-6 m of our converged endpoint (tolerance 1e-10, rest
//     switch on). Rejected steps are not counted.
//
// Beside it, a whole RODAS4 step attempt timed the same way, on the same states, gives what ours
// over the floor would be if each of our accepted steps cost that arithmetic and nothing else (no
// rejected step, error control, dense output or event search): OursOverFloorFromArithmetic. It
// is the per-step factor (the five further right-hand sides and the stage sums) times the step
// factor (the default tolerance's steps over the fewest of any tolerance). Where it is above the
// target, no saving outside the stepper's arithmetic reaches the target at the default tolerance.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/peer_solvers.h"
#include "bench/scene_suite.h"
#include "bench/timing.h"
#include "sim/physics/integrator.h"
#include "sim/physics/parameters.h"

namespace billiard::bench {

// The endpoint accuracy every solver is held to [m].
inline constexpr double kPeerEndpointAccuracy = 1e-6;
// Issue 16's acceptance targets: our time over Odeint's, and over the floor, at most these.
inline constexpr double kTargetOursOverOdeint = 0.5;
inline constexpr double kTargetOursOverFloor = 3.0;

// Every timed run gets 50 ms in 15 batches: tens of repeats of a 50 us run, one or two per batch
// of a 2 ms one; the median of fifteen discards the batches an interruption landed in. (A machine
// busy with other work for the whole 50 ms slows every batch alike: time on a quiet one.)
inline constexpr TimingBudget kPeerTiming{50000.0, 15};

// The tolerances tried, loosest first: 1e-3, 3e-4, 1e-4, ..., 3e-10, 1e-10.
std::vector<double> PeerToleranceSweep();

// Our RODAS4 at its default options on one figure.
struct OursOnFigure {
  double tolerance = 0.0;
  double wall_us = 0.0;
  physics::IntegrationStats stats;
  double error_m = 0.0;  // endpoint from ours converged (rest switch on)
};

// One peer on one figure, at the loosest tolerance of the sweep that reaches the accuracy.
struct PeerOnFigure {
  std::string peer;    // "odeint-rosenbrock4", "cvode-bdf"
  bool found = false;  // false: no tolerance of the sweep reached it (nothing else is set)
  double tolerance = 0.0;
  double wall_us = 0.0;
  PeerRun run;
  double error_m = 0.0;  // endpoint from the regularized equations converged (no rest switch)
};

struct FloorOnFigure {
  long steps = 0;               // fewest accepted steps, see the header comment
  double tolerance = 0.0;       // the sweep's tolerance where RODAS4 took them
  double step_us = 0.0;         // the per-step arithmetic
  double wall_us = 0.0;         // steps * step_us
  double rodas4_step_us = 0.0;  // a whole RODAS4 step attempt on the same states
};

struct FigureComparison {
  std::string scene;  // "fig6", ...
  // The distance between the two converged endpoints, with and without the rest switch [m]:
  // where the rest switch puts a stopped ball against where the regularized equations leave it.
  double rest_switch_shift_m = 0.0;
  OursOnFigure ours;
  PeerOnFigure odeint, cvode;
  FloorOnFigure floor;
};

struct PeerComparison {
  std::vector<FigureComparison> figures;
};

// Runs the comparison on `figures` (the "figure" group of SceneSuite). On each figure ours, the
// floor's arithmetic and the two peers are timed on the calling thread, interleaved
// (MedianWallUsInterleaved, timing.h: a busy stretch of the machine slows all four alike).
// Throws std::runtime_error when a converged reference fails.
PeerComparison ComparePeers(const physics::ModelParameters& p, const std::vector<Scene>& figures,
                            const std::function<void(const std::string&)>& progress);

// The floor's step count on one scene: the fewest accepted steps of our RODAS4 (rest switch on)
// over PeerToleranceSweep whose endpoint is within kPeerEndpointAccuracy of `converged` (ours at
// the sweep's tightest tolerance, rest switch on), and the tolerance where it took them. The
// sweep holds the default tolerance, so where the default reaches the accuracy the floor takes at
// most its steps.
struct FloorSteps {
  long steps = 0;
  double tolerance = 0.0;
};
FloorSteps FewestAcceptedSteps(const physics::ModelParameters& p, const Scene& scene,
                               const physics::BallState& converged);

// Ours over a peer's or the floor's time; 0 when the other was not found.
double Ratio(double ours_us, double other_us);

// Ours over the floor with each of our accepted steps at floor.rodas4_step_us and nothing else
// (see the file comment).
double OursOverFloorFromArithmetic(const FigureComparison& f);

// The comparison as JSON: per figure, the four times, the steps, the errors, the ratios and the
// targets met.
nlohmann::json PeerComparisonJson(const PeerComparison& comparison);

}  // namespace billiard::bench
