#include "bench/peer_solvers.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <stdexcept>
#include <string>
#include <utility>

#include "sim/physics/ball_dynamics.h"
#include "sim/physics/simulator.h"

namespace billiard::bench {

namespace {

using Dynamics = physics::BallDynamics<physics::ApproximateFrictionModel>;

Dynamics MakeDynamics(const physics::ModelParameters& p) {
  return Dynamics(p, physics::ApproximateFrictionModel{p.contact});
}

// Our first step, 10 us: far below the stiff slip's time constant, so no peer starts by a failure.
constexpr double kInitialStep = 1e-5;  // [s]
// What is left of [0, t_end] when a peer is called done: a picometre at the paper's 1 m/s.
constexpr double kTimeResolution = 1e-12;  // [s]

namespace odeint = boost::numeric::odeint;
using OdeintVector = boost::numeric::ublas::vector<double>;
using OdeintMatrix = boost::numeric::ublas::matrix<double>;

// Odeint's controller takes one absolute tolerance for every component; ours weighs each
// component by its own (IntegratorOptionsFor). So the peer integrates y = S x, S = diag(tol /
// abs_tol_i): an error of tol in y_i is one of abs_tol_i in x_i, the same weights as ours, on the
// same equations (y' = S f(S^-1 y), dy'/dy = S J S^-1).
struct ScaledSystem {
  const Dynamics* dynamics;
  physics::BallState scale;  // S
  PeerRun* run;              // counts the evaluations

  physics::BallState Unscaled(const OdeintVector& y) const {
    physics::BallState x;
    for (int i = 0; i < 7; ++i) x[i] = y[i] / scale[i];
    return x;
  }
};

struct OdeintRhs {
  ScaledSystem s;
  void operator()(const OdeintVector& y, OdeintVector& dydt, double /*t*/) const {
    const physics::BallState f = s.dynamics->Derivative(s.Unscaled(y));
    ++s.run->rhs_evals;
    for (int i = 0; i < 7; ++i) dydt[i] = s.scale[i] * f[i];
  }
};

struct OdeintJacobian {
  ScaledSystem s;
  void operator()(const OdeintVector& y, OdeintMatrix& jac, double /*t*/,
                  OdeintVector& dfdt) const {
    physics::BallState f;
    physics::StateJacobian j;
    s.dynamics->DerivativeAndJacobian(s.Unscaled(y), &f, &j);
    ++s.run->rhs_evals;
    ++s.run->jacobian_evals;
    for (int r = 0; r < 7; ++r) {
      for (int c = 0; c < 7; ++c) jac(r, c) = s.scale[r] * j(r, c) / s.scale[c];
      dfdt[r] = 0.0;  // the ball's equations are autonomous
    }
  }
};

}  // namespace

PeerRun OdeintRosenbrock4(const physics::ModelParameters& p, const physics::BallState& initial,
                          double t_end, double tolerance, long max_steps) {
  const Dynamics dynamics = MakeDynamics(p);
  PeerRun run;
  const physics::BallState abs_tol = physics::IntegratorOptionsFor(p, tolerance).abs_tol;
  const ScaledSystem scaled{&dynamics,
                            physics::BallState::Constant(tolerance).cwiseQuotient(abs_tol), &run};
  const auto system = std::make_pair(OdeintRhs{scaled}, OdeintJacobian{scaled});
  // Absolute error only, as ours (IntegratorOptions::rel_tol = 0).
  odeint::rosenbrock4_controller<odeint::rosenbrock4<double>> stepper(tolerance, 0.0);
  OdeintVector y(7);
  for (int i = 0; i < 7; ++i) y[i] = scaled.scale[i] * initial[i];
  double t = 0.0, dt = kInitialStep;
  while (t_end - t > kTimeResolution) {
    if (run.steps + run.rejected_steps >= max_steps) {
      throw std::runtime_error("odeint rosenbrock4: more than " + std::to_string(max_steps) +
                               " steps before t = " + std::to_string(t_end));
    }
    dt = std::min(dt, t_end - t);
    if (stepper.try_step(system, y, t, dt) == odeint::success) {
      ++run.steps;
    } else {
      ++run.rejected_steps;
    }
  }
  run.final_state = scaled.Unscaled(y);
  return run;
}

// The CVODE objects of one solver, and the dynamics its callbacks evaluate.
struct CvodeBdf::Solver {
  explicit Solver(const physics::ModelParameters& p) : dynamics(MakeDynamics(p)) {}

  Dynamics dynamics;
  SUNContext context = nullptr;
  void* memory = nullptr;
  N_Vector y = nullptr, abs_tol = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver linear_solver = nullptr;

  static physics::BallState StateOf(N_Vector v) {
    return Eigen::Map<const physics::BallState>(N_VGetArrayPointer(v));
  }

  static int Rhs(realtype /*t*/, N_Vector y, N_Vector ydot, void* data) {
    const Solver* self = static_cast<const Solver*>(data);
    Eigen::Map<physics::BallState>(N_VGetArrayPointer(ydot)) =
        self->dynamics.Derivative(StateOf(y));
    return 0;
  }

  static int Jacobian(realtype /*t*/, N_Vector y, N_Vector /*fy*/, SUNMatrix jac, void* data,
                      N_Vector, N_Vector, N_Vector) {
    const Solver* self = static_cast<const Solver*>(data);
    physics::BallState f;
    physics::StateJacobian j;
    self->dynamics.DerivativeAndJacobian(StateOf(y), &f, &j);
    // SUNDIALS' dense matrix is column-major, as Eigen's default.
    Eigen::Map<physics::StateJacobian>(SUNDenseMatrix_Data(jac)) = j;
    return 0;
  }
};

namespace {

void Check(int flag, const char* call) {
  if (flag < 0) {
    throw std::runtime_error(std::string("cvode: ") + call +
                             " failed: " + CVodeGetReturnFlagName(flag));
  }
}

template <class T>
T* Made(T* object, const char* call) {
  if (!object) throw std::runtime_error(std::string("cvode: ") + call + " failed");
  return object;
}

}  // namespace

CvodeBdf::CvodeBdf(const physics::ModelParameters& p, double tolerance, long max_steps)
    : solver_(std::make_unique<Solver>(p)) {
  Solver& s = *solver_;
  Check(SUNContext_Create(nullptr, &s.context), "SUNContext_Create");
  s.y = Made(N_VNew_Serial(7, s.context), "N_VNew_Serial");
  s.abs_tol = Made(N_VNew_Serial(7, s.context), "N_VNew_Serial");
  N_VConst(0.0, s.y);
  Eigen::Map<physics::BallState>(N_VGetArrayPointer(s.abs_tol)) =
      physics::IntegratorOptionsFor(p, tolerance).abs_tol;
  s.memory = Made(CVodeCreate(CV_BDF, s.context), "CVodeCreate");
  Check(CVodeInit(s.memory, &Solver::Rhs, 0.0, s.y), "CVodeInit");
  // Absolute error only, as ours (IntegratorOptions::rel_tol = 0).
  Check(CVodeSVtolerances(s.memory, 0.0, s.abs_tol), "CVodeSVtolerances");
  Check(CVodeSetUserData(s.memory, &s), "CVodeSetUserData");
  Check(CVodeSetMaxNumSteps(s.memory, max_steps), "CVodeSetMaxNumSteps");
  Check(CVodeSetInitStep(s.memory, kInitialStep), "CVodeSetInitStep");
  s.matrix = Made(SUNDenseMatrix(7, 7, s.context), "SUNDenseMatrix");
  s.linear_solver = Made(SUNLinSol_Dense(s.y, s.matrix, s.context), "SUNLinSol_Dense");
  Check(CVodeSetLinearSolver(s.memory, s.linear_solver, s.matrix), "CVodeSetLinearSolver");
  Check(CVodeSetJacFn(s.memory, &Solver::Jacobian), "CVodeSetJacFn");
}

CvodeBdf::~CvodeBdf() {
  Solver& s = *solver_;
  CVodeFree(&s.memory);
  SUNLinSolFree(s.linear_solver);
  SUNMatDestroy(s.matrix);
  N_VDestroy(s.abs_tol);
  N_VDestroy(s.y);
  SUNContext_Free(&s.context);
}

PeerRun CvodeBdf::Run(const physics::BallState& initial, double t_end) {
  Solver& s = *solver_;
  Eigen::Map<physics::BallState>(N_VGetArrayPointer(s.y)) = initial;
  Check(CVodeReInit(s.memory, 0.0, s.y), "CVodeReInit");
  Check(CVodeSetStopTime(s.memory, t_end), "CVodeSetStopTime");
  realtype t = 0.0;
  Check(CVode(s.memory, t_end, s.y, &t, CV_NORMAL), "CVode");
  PeerRun run;
  run.final_state = Solver::StateOf(s.y);
  long steps = 0, error_failures = 0, newton_failures = 0, rhs = 0, jacobians = 0;
  Check(CVodeGetNumSteps(s.memory, &steps), "CVodeGetNumSteps");
  Check(CVodeGetNumErrTestFails(s.memory, &error_failures), "CVodeGetNumErrTestFails");
  Check(CVodeGetNumNonlinSolvConvFails(s.memory, &newton_failures),
        "CVodeGetNumNonlinSolvConvFails");
  Check(CVodeGetNumRhsEvals(s.memory, &rhs), "CVodeGetNumRhsEvals");
  Check(CVodeGetNumJacEvals(s.memory, &jacobians), "CVodeGetNumJacEvals");
  run.steps = steps;
  run.rejected_steps = error_failures + newton_failures;
  run.rhs_evals = rhs + jacobians;  // each Jacobian pass evaluates the right-hand side too
  run.jacobian_evals = jacobians;
  return run;
}

}  // namespace billiard::bench
