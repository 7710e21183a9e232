#include "sim/physics/simulator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "sim/physics/ball_dynamics.h"
#include "sim/physics/closed_form.h"
#include "sim/physics/dopri5.h"
#include "sim/physics/rest.h"
#include "sim/physics/rodas4.h"

namespace billiard::physics {

std::string ModelName(Model m) {
  switch (m) {
    case Model::kApproximate:
      return "approx";
    case Model::kIntegral:
      return "integral";
    case Model::kClosedForm:
      return "closed-form";
  }
  return "?";
}

std::optional<Model> ParseModel(const std::string& name) {
  for (Model m : {Model::kApproximate, Model::kIntegral, Model::kClosedForm}) {
    if (ModelName(m) == name) return m;
  }
  return std::nullopt;
}

std::string IntegratorName(Integrator i) { return i == Integrator::kDopri5 ? "dopri5" : "rodas4"; }

std::optional<Integrator> ParseIntegrator(const std::string& name) {
  for (Integrator i : {Integrator::kRodas4, Integrator::kDopri5}) {
    if (IntegratorName(i) == name) return i;
  }
  return std::nullopt;
}

IntegratorOptions IntegratorOptionsFor(const ModelParameters& params, double tolerance) {
  IntegratorOptions o;
  // The friction law is linear in the slip only within eps a of zero (eps_r a for the rolling
  // direction near a stop). A step whose velocity error exceeds that zone overshoots it, and the
  // slip chatters across zero at the Coulomb switch: with eps = 1e-9 and tolerance 1e-7, millions
  // of steps for one shot. Resolving the zone lets the L-stable method settle into it. The cap
  // is 10 eps a, about 3e-4 m/s with the built-in sets: above any tolerance they are run at.
  //
  // The spins are held to the same slip as the velocity, in the units eq. 17 compares slips in
  // (per patch radius): wx, wy move the patch's linear slip by r w, and wz is itself the angular
  // slip ws, the counterpart of vs / a. So wz's tolerance is velocity_tol / a, not / r: a bound
  // r / a (about 7-10) times tighter than any other component's bought no accuracy (issue 16:
  // 212 scenes at 1e-6, 4 % fewer step attempts, the same endpoint errors).
  const ContactParameters& c = params.contact;
  const double velocity_tol =
      std::min(tolerance, 10.0 * std::min(c.eps_t, c.eps_r) * c.patch_radius);
  const double spin_tol = velocity_tol / params.ball.radius;
  const double side_spin_tol = velocity_tol / c.patch_radius;
  o.abs_tol << tolerance, tolerance, velocity_tol, velocity_tol, spin_tol, spin_tol, side_spin_tol;
  return o;
}

namespace {

// Runs `system` with the chosen integrator.
template <class System, class Stop = NeverStop>
IntegrationResult Run(Integrator integrator, const System& system, const BallState& x0, double t0,
                      double t_end, const IntegratorOptions& options, IntegrationStats* stats,
                      DenseTrajectory* dense, const Stop& stop = Stop()) {
  if (integrator == Integrator::kDopri5) {
    return IntegrateWith<Dopri5Stepper>(system, x0, t0, t_end, options, stats, dense, stop);
  }
  return IntegrateWith<Rodas4Stepper>(system, x0, t0, t_end, options, stats, dense, stop);
}

// The stop of a 5-DOF ball as an event on the dense output: the first time ClassifyRest calls the
// ball stopped, searched inside every step that comes near the rest speed, not only at the ends
// of steps. Near its stop a pivoting ball's force rings about the balanced value (period a few
// ms) while its speed hovers about the rest speed, so the criterion holds in windows shorter than
// a step, and which window the step ends happened to land in decided where the ball rested: up
// to 15 um apart between tolerances (issue 16). Sampled inside the step, the first window is
// found whatever the step size, and bisection locates its start.
//
// A balanced pivot is then followed for a few more time constants of that ringing before the
// averaged dynamics takes over. Which window comes first is still a threshold on an oscillating
// force: where a minimum of the ringing grazes 1 % of mu g, a trajectory a tolerance apart
// catches the window a ringing period (about 13 ms) earlier or later (200 seeded shots with the
// paper's parameters: one at 1e-6 caught t = 1.0308 s, not 1.0437 s). And while the ring lasts
// (|v| swings between 2e-4 and 7e-4 m/s about its balanced 1.3e-4) the centre of curvature that
// BallAtRest averages to is the ring's, not the precession's: it moved by tens of um within a
// period, and the two windows' centres were 2.8 um apart. The ring is the fast oscillatory mode
// of the (v, wx, wy) Jacobian (about -80 +- 500i /s there; the precession is the slow pair, about
// -10 +- 35i); after kSettleTimeConstants of its decay times the centre moves only with the slow
// precession, so the rest point no longer depends on which window the criterion caught first.
//
// Used as IntegrateAdaptive's stop predicate; `dense` must be the integration's dense output
// (each accepted step is appended before the predicate sees its end state).
template <class Dynamics>
class RestEvent {
 public:
  RestEvent(const Dynamics& dynamics, const DenseTrajectory* dense)
      : dynamics_(dynamics), dense_(dense) {
    near_rest_speed_ = kNearRestFactor * RestSpeed(dynamics.parameters().contact);
  }

  bool operator()(const BallState& end) {
    if (dense_->size() == 0) {  // the initial state
      kind_ = ClassifyRest(end, dynamics_);
      if (kind_ == RestKind::kMoving) return false;
      time_ = dense_->end_time();
      state_ = end;
      return true;
    }
    const double t0 = dense_->last_step_start(), t1 = dense_->end_time();
    if (settle_until_ < 0.0 && !FindStop(end, t0, t1)) return false;
    // A stop was found in this step or an earlier one: take over where the ring has settled.
    if (t1 < settle_until_) return false;
    time_ = settle_until_;
    state_ = time_ == t1 ? end : dense_->At(time_);
    const RestKind now = ClassifyRest(state_, dynamics_);
    if (now != RestKind::kMoving) kind_ = now;
    return true;
  }

  // Where the averaged dynamics takes over, once the predicate has held (time() < 0 before), its
  // state there and how the ball rests.
  double time() const { return time_; }
  const BallState& state() const { return state_; }
  RestKind kind() const { return kind_; }

 private:
  // A step is searched when the ball is slower than this many rest speeds at one of its ends.
  static constexpr double kNearRestFactor = 2.0;
  // The windows measured last about half a millisecond; steps near the stop are a few ms long.
  static constexpr int kSamplesPerStep = 8;
  // A nanosecond: at the stop's speed (10 eps_r a, a few mm/s at most) a fraction of a picometre.
  static constexpr double kRestTimeResolution = 1e-9;  // [s]
  // Decay times of the ring a balanced pivot is followed for: its linear amplitude falls to e^-4,
  // 2 %. The worst of the 200 paper shots at 1e-6 after 2, 3, 4 and 6 of them: 1.41, 1.07, 0.43
  // and 0.33 um from its 1e-9 rest point. Figs. 9 and 10: 110 and 180 ms, 52 and 48 more steps.
  static constexpr double kSettleTimeConstants = 4.0;

  // Searches the step [t0, t1] (its end state `end`) for the first time the ball is called
  // stopped; if found, sets kind_ and settle_until_ (that time, plus the settling of a pivot).
  bool FindStop(const BallState& end, double t0, double t1) {
    const double start_speed =
        dense_->size() == 1 ? dense_->At(t0).segment<2>(kVx).norm() : previous_end_speed_;
    previous_end_speed_ = end.segment<2>(kVx).norm();
    if (std::min(start_speed, previous_end_speed_) >= near_rest_speed_) {
      return false;  // a ball this fast at both ends of a step does not stop inside it
    }
    double moving = t0;
    for (int k = 1; k <= kSamplesPerStep; ++k) {
      const double t = k == kSamplesPerStep ? t1 : t0 + (t1 - t0) * k / kSamplesPerStep;
      BallState stop = k == kSamplesPerStep ? end : dense_->At(t);
      if (!Stopped(stop)) {
        moving = t;
        continue;
      }
      double lo = moving, hi = t;
      while (hi - lo > kRestTimeResolution) {
        const double mid = 0.5 * (lo + hi);
        const BallState s = dense_->At(mid);
        if (Stopped(s)) {
          hi = mid;
          stop = s;
        } else {
          lo = mid;
        }
      }
      kind_ = ClassifyRest(stop, dynamics_);
      settle_until_ = hi + (kind_ == RestKind::kBalancedPivot ? SettlingTime(stop) : 0.0);
      return true;
    }
    return false;
  }

  // kSettleTimeConstants decay times of the fastest oscillatory mode of the (vx, vy, wx, wy)
  // block of the Jacobian at `s`: the ring of a pivot about its balance. Zero without one.
  double SettlingTime(const BallState& s) const {
    BallState f;
    StateJacobian jac;
    dynamics_.DerivativeAndJacobian(s, &f, &jac);
    const Eigen::Matrix4d block = jac.template block<4, 4>(kVx, kVx);
    const Eigen::Vector4cd modes = Eigen::EigenSolver<Eigen::Matrix4d>(block, false).eigenvalues();
    int fastest = 0;
    for (int i = 1; i < 4; ++i) {
      if (std::abs(modes[i].imag()) > std::abs(modes[fastest].imag())) fastest = i;
    }
    const double decay = -modes[fastest].real();
    if (modes[fastest].imag() == 0.0 || !(decay > 0.0)) return 0.0;
    return kSettleTimeConstants / decay;
  }

  bool Stopped(const BallState& s) const { return ClassifyRest(s, dynamics_) != RestKind::kMoving; }

  const Dynamics& dynamics_;
  const DenseTrajectory* dense_;
  double near_rest_speed_ = 0.0;
  double previous_end_speed_ = 0.0;  // the speed where the last step began
  double settle_until_ = -1.0;       // where the averaged dynamics takes over, once a stop is found
  double time_ = -1.0;
  BallState state_ = BallState::Zero();
  RestKind kind_ = RestKind::kMoving;
};

// Ends the integration `run` at the stop `rest` found in the last step of `dense`.
template <class Dynamics>
void EndAtRest(const RestEvent<Dynamics>& rest, DenseTrajectory* dense, IntegrationResult* run) {
  if (dense->size() > 0) dense->TruncateLastStepAt(rest.time());
  run->t = rest.time();
  run->state = rest.state();
}

template <class Friction>
SimulationResult Integrate(const ModelParameters& params, Friction friction,
                           const BallState& initial, double t_end,
                           const SimulationOptions& options) {
  const BallDynamics<Friction> dynamics(params, std::move(friction));
  IntegratorOptions integrator = IntegratorOptionsFor(params, options.tolerance);
  integrator.max_steps = options.max_steps;
  auto dense = std::make_shared<DenseTrajectory>();
  SimulationResult result;
  IntegrationResult run;
  RestEvent<BallDynamics<Friction>> rest_event(dynamics, dense.get());
  if (options.rest_switch) {
    run = Run(options.integrator, dynamics, initial, 0.0, t_end, integrator, &result.stats,
              dense.get(), [&rest_event](const BallState& s) { return rest_event(s); });
  } else {
    run = Run(options.integrator, dynamics, initial, 0.0, t_end, integrator, &result.stats,
              dense.get());
  }
  if (run.stopped) {
    // Where the ball stopped inside the last step, not where the step happened to end: so the
    // rest point converges with the tolerance instead of moving with the steps.
    EndAtRest(rest_event, dense.get(), &run);
    const BallAtRest<BallDynamics<Friction>> rest(dynamics, run.state, rest_event.kind());
    result.rest_time = run.t;
    // Only wz moves now, at the contact's moment (constant while the spin is well above the
    // regularization, scaled with wz for a balanced pivot), which a step of RODAS4 follows
    // exactly or nearly: the first step tries the whole remaining time and the controller
    // shortens it where the spin runs out. From the 10 us start the steps grew by at most 6x each,
    // about eight of them to cover seconds of a ball that no longer moves (212 scenes at the
    // default: 7.6 % fewer steps in all, the same endpoints).
    IntegratorOptions rest_integrator = integrator;
    rest_integrator.initial_step = t_end - run.t;
    run = Run(options.integrator, rest, rest.start(), run.t, t_end, rest_integrator, &result.stats,
              dense.get());
  }
  result.final_state = run.state;
  if (dense->size() == 0) {  // t_end = 0: the trajectory is the initial state
    dense->Append(0.0, 0.0, initial, initial, BallState::Zero(), BallState::Zero());
  }
  result.trajectory = std::move(dense);
  return result;
}

// The first time in the last step of `dense` at which the speed falls to `speed` (bisection on
// the dense output: the step began faster than `speed` and ended at or below it).
double SpeedCrossing(const DenseTrajectory& dense, double speed) {
  double lo = dense.last_step_start(), hi = dense.end_time();
  for (int i = 0; i < 60 && hi - lo > 1e-13 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (dense.At(mid).segment<2>(kVx).norm() > speed ? lo : hi) = mid;
  }
  return hi;
}

template <class Friction>
Arrival IntegrateToArrival(const ModelParameters& params, Friction friction,
                           const BallState& initial, double speed, double t_max,
                           const SimulationOptions& options, bool with_sensitivity) {
  const BallDynamics<Friction> dynamics(params, std::move(friction));
  IntegratorOptions integrator = IntegratorOptionsFor(params, options.tolerance);
  integrator.max_steps = options.max_steps;
  auto dense = std::make_shared<DenseTrajectory>();
  RestEvent<BallDynamics<Friction>> rest_event(dynamics, dense.get());
  const auto arrived = [&rest_event, speed](const BallState& s) {
    return rest_event(s) || s.segment<2>(kVx).norm() <= speed;
  };
  Arrival a;
  IntegrationResult run;
  std::optional<Rodas4SensitivityStepper<BallDynamics<Friction>>> stepper;
  if (with_sensitivity) {
    stepper.emplace(dynamics);
    run = IntegrateAdaptive(*stepper, initial, 0.0, t_max, integrator, &a.stats, dense.get(),
                            arrived);
  } else {
    run = Run(options.integrator, dynamics, initial, 0.0, t_max, integrator, &a.stats, dense.get(),
              arrived);
  }
  a.reached = run.stopped;
  a.time = run.t;
  a.state = run.state;
  if (dense->size() == 0) {  // arrived at t = 0
    dense->Append(0.0, 0.0, initial, initial, BallState::Zero(), BallState::Zero());
  }
  if (stepper) a.sensitivity = stepper->sensitivity();
  const bool at_rest = rest_event.time() >= 0.0;
  if (run.stopped && run.t > 0.0 && !at_rest) {
    // The speed fell to `speed` within the last step: locate it, and take S there.
    a.time = SpeedCrossing(*dense, speed);
    a.state = dense->At(a.time);
    if (stepper) {
      const double step = dense->end_time() - dense->last_step_start();
      Sensitivity& s = *a.sensitivity;
      s = stepper->SensitivityWithinLastStep((a.time - dense->last_step_start()) / step);
      // The arrival time moves with the initial state:
      // dt/dx0 = -(v_hat . dv/dx0) / (v_hat . dv/dt).
      const BallState f = dynamics.Derivative(a.state);
      const Eigen::Vector2d v_hat = a.state.segment<2>(kVx).normalized();
      const double rate = v_hat.dot(f.segment<2>(kVx));
      if (rate < 0.0) s += f * (-(v_hat.transpose() * s.middleRows<2>(kVx)) / rate);
    }
  } else if (run.stopped && at_rest) {
    // Where it stopped inside the last step, as Simulate locates it.
    const double step_start = dense->last_step_start(), step = dense->end_time() - step_start;
    EndAtRest(rest_event, dense.get(), &run);
    a.time = run.t;
    if (stepper && step > 0.0) {
      a.sensitivity = stepper->SensitivityWithinLastStep((run.t - step_start) / step);
    }
    a.state = BallAtRest<BallDynamics<Friction>>(dynamics, run.state, rest_event.kind()).start();
  }
  a.trajectory = std::move(dense);
  return a;
}

void ValidateInput(const ModelParameters& params, const BallState& initial, double t_end,
                   const SimulationOptions& options) {
  if (!initial.allFinite()) throw std::invalid_argument("initial state has a non-finite number");
  if (!std::isfinite(t_end) || t_end < 0.0) {
    throw std::invalid_argument("end time must be a finite number >= 0");
  }
  if (options.model != Model::kClosedForm) {
    // A zero eps makes 0/0 at rest; mu below the rolling resistance creates energy. The closed
    // form checks the few numbers it reads itself.
    ValidateParameters(params);
    if (!(options.tolerance > 0.0)) throw std::invalid_argument("tolerance must be positive");
  }
}

// Calls integrate(friction) with the friction model of the 5-DOF `options.model`, and stores the
// integral model's calibrated quadrature in *quadrature.
template <class Integrate>
auto WithFrictionModel(const ModelParameters& params, const SimulationOptions& options,
                       std::optional<CalibratedQuadrature>* quadrature, Integrate&& integrate) {
  if (options.model == Model::kIntegral) {
    const CalibratedQuadrature q =
        CalibrateQuadrature(params.contact.eps_t, params.contact.d, options.quadrature_tolerance);
    *quadrature = q;
    return integrate(IntegralFrictionModel{IntegralFriction(q.order), params.contact.eps_t});
  }
  return integrate(ApproximateFrictionModel{params.contact});
}

}  // namespace

SimulationResult Simulate(const ModelParameters& params, const BallState& initial, double t_end,
                          const SimulationOptions& options) {
  ValidateInput(params, initial, t_end, options);
  if (options.model == Model::kClosedForm) {
    auto trajectory =
        std::make_shared<ClosedFormTrajectory>(ClosedFormParameters::From(params), initial);
    SimulationResult r;
    r.final_state = trajectory->At(t_end);
    r.trajectory = std::move(trajectory);
    return r;
  }
  std::optional<CalibratedQuadrature> quadrature;
  SimulationResult r = WithFrictionModel(params, options, &quadrature, [&](auto friction) {
    return Integrate(params, std::move(friction), initial, t_end, options);
  });
  r.quadrature = quadrature;
  return r;
}

Arrival SimulateArrival(const ModelParameters& params, const BallState& initial, double speed,
                        double t_max, const SimulationOptions& options, bool with_sensitivity) {
  ValidateInput(params, initial, t_max, options);
  if (!std::isfinite(speed) || speed < 0.0) {
    throw std::invalid_argument("arrival speed must be a finite number >= 0");
  }
  if (with_sensitivity &&
      (options.model == Model::kClosedForm || options.integrator != Integrator::kRodas4)) {
    throw std::invalid_argument("sensitivities need a 5-DOF model integrated with RODAS4");
  }
  if (options.model == Model::kClosedForm) {
    auto trajectory =
        std::make_shared<ClosedFormTrajectory>(ClosedFormParameters::From(params), initial);
    Arrival a;
    const double t = trajectory->TimeAtSpeed(speed);
    a.reached = t <= t_max;
    a.time = std::min(t, t_max);
    a.state = trajectory->At(a.time);
    a.trajectory = std::move(trajectory);
    return a;
  }
  std::optional<CalibratedQuadrature> quadrature;
  return WithFrictionModel(params, options, &quadrature, [&](auto friction) {
    return IntegrateToArrival(params, std::move(friction), initial, speed, t_max, options,
                              with_sensitivity);
  });
}

}  // namespace billiard::physics
