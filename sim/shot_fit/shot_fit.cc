#include "sim/shot_fit/shot_fit.h"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "sim/table/table_simulation.h"

namespace billiard::shot_fit {

namespace {

using physics::ModelParameters;

// The tip's reach in the fit, per axis, as a fraction of r: about a miscue's limit (the cue
// set's max_tip_offset is 0.5) with room for the side and height together to stay below r.
constexpr double kTipLimit = 0.6;
constexpr double kMaxElevation = 0.6;  // [rad], a masse is no three-cushion shot
constexpr double kMaxCueSpeed = 12.0;  // [m/s], beyond any player's break
// A scene that needs more events is no shot the fit should follow (a numerical pathology).
constexpr std::int64_t kMaxEvents = 20000;
// The horizons of the continuation [s]; the last stage is always the whole shot.
constexpr double kHorizons[] = {2.0, 4.0, 8.0};
// The first stage's grid around the launch the samples show, and how many of its best points
// go on to the refinement.
constexpr double kSpeedFactors[] = {0.9, 1.0, 1.12};
constexpr double kTipGrid[] = {-0.4, 0.0, 0.4};
constexpr int kStarts = 4;
// How many samples after the first one give the launch velocity (50 Hz: 0.06 s).
constexpr int kLaunchSamples = 3;

const char* const kConstantNames[] = {"mu",      "rolling",          "spin",
                                      "cushion", "cushion_friction", "ball_ball"};

// The range the fit searches for each constant (far beyond any cloth, cushion or ball).
struct Range {
  double lo, hi;
};
Range ConstantRange(Constant c) {
  switch (c) {
    case Constant::kMu: return {0.02, 0.6};
    case Constant::kRolling: return {2e-4, 0.05};
    case Constant::kSpin: return {2e-4, 0.02};
    case Constant::kCushion: return {0.3, 0.99};
    case Constant::kCushionFriction: return {0.0, 0.4};
    case Constant::kBallBall: return {0.5, 1.0};
  }
  return {0.0, 0.0};
}

// The strike as the optimiser sees it: speed, heading, tip side and height as fractions of r,
// the impact time and, when fitted, the elevation.
std::vector<double> ToVector(const Strike& s, bool elevation, double r) {
  std::vector<double> x = {s.stroke.speed, s.stroke.heading, s.stroke.tip_side / r,
                           s.stroke.tip_height / r, s.time};
  if (elevation) x.push_back(s.stroke.elevation);
  return x;
}

Strike FromVector(const double* x, bool elevation, double r) {
  Strike s;
  s.stroke.speed = x[0];
  s.stroke.heading = x[1];
  s.stroke.tip_side = x[2] * r;
  s.stroke.tip_height = x[3] * r;
  s.time = x[4];
  s.stroke.elevation = elevation ? x[5] : 0.0;
  return s;
}

std::vector<Eigen::Vector2d> StartPositions(const table::TableGeometry& table, double r,
                                            const TrackedShot& shot) {
  std::vector<Eigen::Vector2d> p;
  for (const TrackedBall& b : shot.balls) {
    const Eigen::Vector2d first = b.position.front();
    p.emplace_back(std::clamp(first.x(), r, table.length - r),
                   std::clamp(first.y(), r, table.width - r));
  }
  // Balls the tracking put into each other (touching balls, millimetre rounding): apart along
  // their line, by half the overlap each, plus a micrometre.
  constexpr double kClearance = 1e-6;
  for (int pass = 0; pass < 3; ++pass) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      for (std::size_t j = i + 1; j < p.size(); ++j) {
        Eigen::Vector2d d = p[j] - p[i];
        const double gap = d.norm() - 2.0 * r;
        if (gap >= kClearance) continue;
        d = d.norm() > 0.0 ? Eigen::Vector2d(d.normalized()) : Eigen::Vector2d::UnitX();
        const Eigen::Vector2d push = 0.5 * (kClearance - gap) * d;
        p[i] -= push;
        p[j] += push;
      }
    }
  }
  return p;
}

// One shot with one parameter set: the start scene, and what a strike makes of it.
class ShotModel {
 public:
  ShotModel(const table::TableGeometry& table, const ModelParameters& params,
            const TrackedShot& shot)
      : table_(table),
        params_(params),
        shot_(shot),
        start_(StartPositions(table, params.ball.radius, shot)) {}

  const TrackedShot& shot() const { return shot_; }
  const ModelParameters& params() const { return params_; }
  const std::vector<Eigen::Vector2d>& start() const { return start_; }

  // 2 per sample of each ball up to `horizon`.
  int ResidualCount(double horizon) const {
    int n = 0;
    for (const TrackedBall& b : shot_.balls)
      for (double t : b.t) n += t <= horizon ? 2 : 0;
    return n;
  }

  // Simulated minus tracked, ball by ball, sample by sample, up to `horizon`; false where the
  // strike is none a cue gives or the simulation refuses the scene.
  bool Residuals(const Strike& strike, double horizon, double* out) const {
    try {
      const table::TableSimulation sim = Run(strike, std::min(horizon, shot_.Duration()));
      int k = 0;
      for (std::size_t i = 0; i < shot_.balls.size(); ++i) {
        const TrackedBall& b = shot_.balls[i];
        for (std::size_t s = 0; s < b.t.size(); ++s) {
          if (b.t[s] > horizon) continue;
          const double tau = std::clamp(b.t[s] - strike.time, 0.0, sim.time());
          const physics::BallState state = sim.StateAt(i, tau);
          out[k++] = state[physics::kX] - b.position[s].x();
          out[k++] = state[physics::kY] - b.position[s].y();
        }
      }
      return true;
    } catch (const std::exception&) {
      return false;
    }
  }

  std::vector<double> Residuals(const Strike& strike, double horizon) const {
    std::vector<double> r(ResidualCount(horizon));
    if (!Residuals(strike, horizon, r.data())) return {};
    return r;
  }

  // Half the sum of squares (Ceres' cost), infinite where Residuals fails.
  double Cost(const Strike& strike, double horizon) const {
    const std::vector<double> r = Residuals(strike, horizon);
    if (r.empty() && ResidualCount(horizon) > 0) return std::numeric_limits<double>::infinity();
    double c = 0.0;
    for (double v : r) c += v * v;
    return 0.5 * c;
  }

  table::TableSimulation Run(const Strike& strike, double until) const {
    std::vector<table::SceneBall> balls;
    for (std::size_t i = 0; i < start_.size(); ++i) {
      table::SceneBall b;
      b.id = static_cast<int>(i);
      b.state.segment<2>(physics::kX) = start_[i];
      if (i == shot_.cue && strike.stroke.speed > 0.0)
        b.state = physics::StrikeBall(strike.stroke, start_[i], params_);
      balls.push_back(b);
    }
    table::TableSimulationOptions options;
    options.max_events = kMaxEvents;
    table::TableSimulation sim(table_, params_, balls, options);
    sim.Run(std::max(0.0, until - strike.time));
    return sim;
  }

 private:
  const table::TableGeometry& table_;
  const ModelParameters& params_;
  const TrackedShot& shot_;
  std::vector<Eigen::Vector2d> start_;
};

ShotErrors ErrorsOf(const ShotModel& model, const Strike& strike) {
  const TrackedShot& shot = model.shot();
  const std::vector<double> r = model.Residuals(strike, std::numeric_limits<double>::infinity());
  if (r.empty()) throw std::invalid_argument("shot " + shot.id + ": the strike cannot be simulated");
  ShotErrors e;
  std::size_t k = 0;
  double all = 0.0;
  for (const TrackedBall& b : shot.balls) {
    double sum = 0.0;
    for (std::size_t s = 0; s < b.t.size(); ++s, k += 2) sum += r[k] * r[k] + r[k + 1] * r[k + 1];
    all += sum;
    e.rmse.push_back(std::sqrt(sum / static_cast<double>(b.t.size())));
  }
  e.rmse_all = std::sqrt(all / static_cast<double>(shot.SampleCount()));
  return e;
}

// The launch the first samples show: the cue ball's direction and speed just after the impact,
// and the impact's time (the line through those samples back to where the ball stood), turned
// into the level centre-ball stroke of TP A.30 that gives it, the heading off by the squirt of
// `side` (a fraction of r).
Strike LaunchGuess(const ModelParameters& p, const TrackedBall& cue, double side) {
  Strike s;
  if (cue.t.size() < 3) return s;  // the cue ball never moves: no strike
  const int last = std::min<int>(kLaunchSamples, static_cast<int>(cue.t.size()) - 1);
  const Eigen::Vector2d v = (cue.position[last] - cue.position[1]) / (cue.t[last] - cue.t[1]);
  const double speed = v.norm();
  if (!(speed > 0.0)) return s;
  const double travelled = (cue.position[1] - cue.position[0]).norm();
  s.time = std::clamp(cue.t[1] - travelled / speed, cue.t[0], cue.t[1]);
  const double m = p.ball.mass, big_m = p.cue.mass, e = p.cue.tip_restitution;
  s.stroke.speed = speed * (m + big_m) / ((1.0 + e) * big_m);
  s.stroke.tip_side = side * p.ball.radius;
  s.stroke.heading = std::atan2(v.y(), v.x()) - physics::SquirtAngle(s.stroke.tip_side, p);
  return s;
}

struct StrikeResidual {
  const ShotModel* model;
  double horizon;
  bool elevation;
  bool operator()(double const* const* x, double* residuals) const {
    return model->Residuals(FromVector(x[0], elevation, model->params().ball.radius), horizon,
                            residuals);
  }
};

ceres::Solver::Options SolverOptions(int max_iterations) {
  ceres::Solver::Options o;
  o.linear_solver_type = ceres::DENSE_QR;
  o.num_threads = 1;
  o.max_num_iterations = max_iterations;
  o.function_tolerance = 1e-10;
  o.parameter_tolerance = 1e-10;
  o.logging_type = ceres::SILENT;
  return o;
}

// Refines x over `horizon`; returns the cost there (infinite where the start cannot be simulated).
double RefineStrike(const ShotModel& model, double horizon, const FitOptions& options,
                    double impact_lo, double impact_hi, std::vector<double>* x) {
  const int residuals = model.ResidualCount(horizon);
  const double r = model.params().ball.radius;
  if (residuals == 0) return 0.0;
  if (!std::isfinite(model.Cost(FromVector(x->data(), options.fit_elevation, r), horizon)))
    return std::numeric_limits<double>::infinity();
  ceres::NumericDiffOptions diff;
  diff.relative_step_size = 1e-5;
  auto* cost = new ceres::DynamicNumericDiffCostFunction<StrikeResidual, ceres::CENTRAL>(
      new StrikeResidual{&model, horizon, options.fit_elevation}, ceres::TAKE_OWNERSHIP, diff);
  cost->AddParameterBlock(static_cast<int>(x->size()));
  cost->SetNumResiduals(residuals);
  ceres::Problem problem;
  problem.AddResidualBlock(cost, nullptr, x->data());
  double* b = x->data();
  problem.SetParameterLowerBound(b, 0, 0.01);
  problem.SetParameterUpperBound(b, 0, kMaxCueSpeed);
  for (int k : {2, 3}) {
    problem.SetParameterLowerBound(b, k, -kTipLimit);
    problem.SetParameterUpperBound(b, k, kTipLimit);
  }
  problem.SetParameterLowerBound(b, 4, impact_lo);
  problem.SetParameterUpperBound(b, 4, impact_hi);
  if (options.fit_elevation) {
    problem.SetParameterLowerBound(b, 5, 0.0);
    problem.SetParameterUpperBound(b, 5, kMaxElevation);
  }
  ceres::Solver::Summary summary;
  ceres::Solve(SolverOptions(options.max_iterations), &problem, &summary);
  return model.Cost(FromVector(x->data(), options.fit_elevation, r), horizon);
}

double Median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

ShotFit FitOne(const table::TableGeometry& table, const ModelParameters& params,
               const TrackedShot& shot, const FitOptions& options,
               const std::optional<Strike>& previous) {
  const ShotModel model(table, params, shot);
  const double r = params.ball.radius;
  const TrackedBall& cue = shot.balls.at(shot.cue);
  const double full = std::numeric_limits<double>::infinity();
  ShotFit fit;
  fit.id = shot.id;
  if (cue.t.size() < 3) {  // a cue ball that never moves: the strike is none
    fit.errors = ErrorsOf(model, fit.strike);
    fit.rmse_cue = fit.errors.rmse[shot.cue];
    return fit;
  }
  // The impact lies between the first sample (the ball still) and the second (moving); a
  // frame's worth of slack before, for a clock that started late.
  const double impact_lo = cue.t[0] - (cue.t[1] - cue.t[0]), impact_hi = cue.t[1];
  const double first_horizon = std::min(kHorizons[0], shot.Duration());

  std::vector<std::pair<double, std::vector<double>>> scored;
  for (double side : kTipGrid) {
    for (double height : kTipGrid) {
      for (double factor : kSpeedFactors) {
        Strike s = LaunchGuess(params, cue, side);
        s.stroke.speed *= factor;
        s.stroke.tip_height = height * r;
        const std::vector<double> x = ToVector(s, options.fit_elevation, r);
        scored.emplace_back(model.Cost(s, first_horizon), x);
      }
    }
  }
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  scored.resize(std::min<std::size_t>(kStarts, scored.size()));

  double best_cost = full;
  std::vector<double> best;
  auto consider = [&](std::vector<double> x, bool continuation) {
    if (continuation) {
      for (double h : kHorizons) {
        if (h >= shot.Duration()) break;
        RefineStrike(model, h, options, impact_lo, impact_hi, &x);
      }
    }
    const double c = RefineStrike(model, full, options, impact_lo, impact_hi, &x);
    if (c < best_cost) {
      best_cost = c;
      best = x;
    }
  };
  for (const auto& start : scored) consider(start.second, true);
  if (previous) {
    std::vector<double> x = ToVector(*previous, options.fit_elevation, r);
    x[4] = std::clamp(x[4], impact_lo, impact_hi);
    consider(x, false);
  }
  if (best.empty()) throw std::invalid_argument("shot " + shot.id + ": no strike simulates");
  fit.strike = FromVector(best.data(), options.fit_elevation, r);
  fit.errors = ErrorsOf(model, fit.strike);
  fit.rmse_cue = fit.errors.rmse[shot.cue];
  return fit;
}

// The residuals of the shots `included` with their strikes fixed, for the constants `values`;
// each shot one job on the pool. Empty where a shot cannot be simulated.
struct ConstantsProblem {
  const table::TableGeometry& table;
  const ModelParameters& base;
  const std::vector<TrackedShot>& shots;
  const std::vector<std::size_t>& included;
  const std::vector<Strike>& strikes;  // per shot of `shots`
  const std::vector<Constant>& constants;
  batch::ThreadPool& pool;

  // Residuals of every included shot for each constants vector of `points`, one job per
  // (point, shot).
  std::vector<std::vector<double>> Evaluate(const std::vector<std::vector<double>>& points) const {
    const std::size_t n = included.size();
    std::vector<ModelParameters> sets;
    for (const std::vector<double>& v : points) sets.push_back(WithConstants(base, constants, v));
    auto results = pool.Map(points.size() * n, [&](std::size_t job) {
      const std::size_t point = job / n, s = included[job % n];
      const ShotModel model(table, sets[point], shots[s]);
      return model.Residuals(strikes[s], std::numeric_limits<double>::infinity());
    });
    std::vector<std::vector<double>> out(points.size());
    for (std::size_t point = 0; point < points.size(); ++point) {
      for (std::size_t k = 0; k < n; ++k) {
        const auto& r = results[point * n + k];
        if (!r.ok() || r.value->empty()) {
          out[point].clear();
          break;
        }
        out[point].insert(out[point].end(), r.value->begin(), r.value->end());
      }
    }
    return out;
  }

  int ResidualCount() const {
    int m = 0;
    for (std::size_t s : included) m += 2 * static_cast<int>(shots[s].SampleCount());
    return m;
  }
};

// The constants' cost over the included shots: one Ceres residual block, its Jacobian by
// central differences whose evaluations share the pool (deterministic, unlike a parallel sum).
class ConstantsCost : public ceres::CostFunction {
 public:
  explicit ConstantsCost(const ConstantsProblem& problem) : problem_(problem) {
    set_num_residuals(problem.ResidualCount());
    mutable_parameter_block_sizes()->push_back(static_cast<int>(problem.constants.size()));
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const std::size_t k = problem_.constants.size();
    const std::vector<double> x(parameters[0], parameters[0] + k);
    std::vector<std::vector<double>> points = {x};
    std::vector<double> steps(k);
    const bool jacobian = jacobians != nullptr && jacobians[0] != nullptr;
    if (jacobian) {
      for (std::size_t c = 0; c < k; ++c) {
        steps[c] = kRelativeStep * std::max(std::abs(x[c]), 1e-3);
        for (double sign : {1.0, -1.0}) {
          std::vector<double> y = x;
          y[c] += sign * steps[c];
          points.push_back(y);
        }
      }
    }
    const std::vector<std::vector<double>> r = problem_.Evaluate(points);
    for (const auto& v : r)
      if (v.empty()) return false;
    const int m = num_residuals();
    std::copy(r[0].begin(), r[0].end(), residuals);
    if (jacobian) {
      for (int i = 0; i < m; ++i)
        for (std::size_t c = 0; c < k; ++c)
          jacobians[0][i * k + c] = (r[1 + 2 * c][i] - r[2 + 2 * c][i]) / (2.0 * steps[c]);
    }
    return true;
  }

 private:
  static constexpr double kRelativeStep = 1e-4;
  const ConstantsProblem& problem_;
};

std::vector<double> SolveConstants(const ConstantsProblem& problem, std::vector<double> x,
                                   int max_iterations) {
  ceres::Problem ceres_problem;
  ceres_problem.AddResidualBlock(new ConstantsCost(problem), nullptr, x.data());
  for (std::size_t c = 0; c < x.size(); ++c) {
    const Range range = ConstantRange(problem.constants[c]);
    ceres_problem.SetParameterLowerBound(x.data(), static_cast<int>(c), range.lo);
    ceres_problem.SetParameterUpperBound(x.data(), static_cast<int>(c), range.hi);
  }
  ceres::Solver::Summary summary;
  ceres::Solve(SolverOptions(max_iterations), &ceres_problem, &summary);
  return x;
}

// The marginal covariance of the constants, the strikes eliminated (see the header), at the
// fitted strikes and constants. Per shot one job: central differences of its residuals in its
// strike's parameters and in the constants.
Eigen::MatrixXd ConstantsCovariance(const ConstantsProblem& problem, const std::vector<double>& x,
                                    bool elevation) {
  const std::size_t k = x.size();
  const ModelParameters p = WithConstants(problem.base, problem.constants, x);
  const double r = p.ball.radius;
  struct Blocks {
    Eigen::MatrixXd info;  // the shot's Schur complement
    double squares = 0.0;
    int residuals = 0, strike_parameters = 0;
  };
  auto blocks = problem.pool.Map(problem.included.size(), [&](std::size_t job) {
    const std::size_t s = problem.included[job];
    const ShotModel model(problem.table, p, problem.shots[s]);
    const double full = std::numeric_limits<double>::infinity();
    const std::vector<double> r0 = model.Residuals(problem.strikes[s], full);
    if (r0.empty()) throw std::runtime_error("shot does not simulate");
    const int m = static_cast<int>(r0.size());
    const std::vector<double> xs = ToVector(problem.strikes[s], elevation, r);
    const double strike_steps[] = {1e-4 * xs[0], 1e-5, 1e-4, 1e-4, 1e-5, 1e-4};
    Eigen::MatrixXd js(m, xs.size()), jc(m, k);
    for (std::size_t j = 0; j < xs.size(); ++j) {
      std::vector<double> plus = xs, minus = xs;
      plus[j] += strike_steps[j];
      minus[j] -= strike_steps[j];
      const auto rp = model.Residuals(FromVector(plus.data(), elevation, r), full);
      const auto rm = model.Residuals(FromVector(minus.data(), elevation, r), full);
      if (rp.empty() || rm.empty()) throw std::runtime_error("strike step does not simulate");
      for (int i = 0; i < m; ++i) js(i, j) = (rp[i] - rm[i]) / (2.0 * strike_steps[j]);
    }
    for (std::size_t c = 0; c < k; ++c) {
      const double h = 1e-4 * std::max(std::abs(x[c]), 1e-3);
      std::vector<double> plus = x, minus = x;
      plus[c] += h;
      minus[c] -= h;
      const ModelParameters pp = WithConstants(problem.base, problem.constants, plus);
      const ModelParameters pm = WithConstants(problem.base, problem.constants, minus);
      const auto rp = ShotModel(problem.table, pp, problem.shots[s]).Residuals(problem.strikes[s], full);
      const auto rm = ShotModel(problem.table, pm, problem.shots[s]).Residuals(problem.strikes[s], full);
      if (rp.empty() || rm.empty()) throw std::runtime_error("constant step does not simulate");
      for (int i = 0; i < m; ++i) jc(i, c) = (rp[i] - rm[i]) / (2.0 * h);
    }
    const Eigen::MatrixXd ss = js.transpose() * js;
    const Eigen::MatrixXd sc = js.transpose() * jc;
    Blocks b;
    b.info = jc.transpose() * jc - sc.transpose() * ss.completeOrthogonalDecomposition().solve(sc);
    for (double v : r0) b.squares += v * v;
    b.residuals = m;
    b.strike_parameters = static_cast<int>(xs.size());
    return b;
  });
  Eigen::MatrixXd info = Eigen::MatrixXd::Zero(k, k);
  double squares = 0.0;
  int dof = -static_cast<int>(k);
  for (const auto& b : blocks) {
    if (!b.ok()) continue;
    info += b.value->info;
    squares += b.value->squares;
    dof += b.value->residuals - b.value->strike_parameters;
  }
  const double sigma2 = squares / std::max(dof, 1);
  // A constant no shot excites has a zero row: its variance is infinite, not the pseudo-
  // inverse's zero.
  Eigen::MatrixXd cov = Eigen::MatrixXd::Constant(k, k, std::numeric_limits<double>::infinity());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(info);
  const double largest = eig.eigenvalues().cwiseAbs().maxCoeff();
  if (largest > 0.0 && eig.eigenvalues().minCoeff() > 1e-12 * largest)
    cov = sigma2 * info.inverse();
  return cov;
}

}  // namespace

const char* ConstantName(Constant constant) { return kConstantNames[static_cast<int>(constant)]; }

std::vector<Constant> ParseConstants(const std::string& list) {
  std::vector<Constant> out;
  std::stringstream in(list);
  std::string name;
  while (std::getline(in, name, ',')) {
    if (name.empty()) continue;
    const auto* end = std::end(kConstantNames);
    const auto* found = std::find(std::begin(kConstantNames), end, name);
    if (found == end) {
      throw std::invalid_argument(
          "unknown constant \"" + name +
          "\" (known: mu, rolling, spin, cushion, cushion_friction, ball_ball)");
    }
    const auto c = static_cast<Constant>(found - std::begin(kConstantNames));
    if (std::find(out.begin(), out.end(), c) != out.end())
      throw std::invalid_argument("constant \"" + name + "\" named twice");
    out.push_back(c);
  }
  return out;
}

double ConstantValue(const ModelParameters& p, Constant constant) {
  switch (constant) {
    case Constant::kMu: return p.contact.mu;
    case Constant::kRolling: return p.RollingResistance();
    case Constant::kSpin: return p.contact.patch_radius;
    case Constant::kCushion: return p.collision.cushion_restitution;
    case Constant::kCushionFriction: return p.collision.cushion_friction;
    case Constant::kBallBall: return p.collision.ball_restitution;
  }
  return 0.0;
}

ModelParameters WithConstants(const ModelParameters& p, const std::vector<Constant>& constants,
                              const std::vector<double>& values) {
  if (constants.size() != values.size())
    throw std::invalid_argument("WithConstants: one value per constant");
  ModelParameters out = p;
  const double r = p.ball.radius;
  double rolling = p.RollingResistance();
  for (std::size_t i = 0; i < constants.size(); ++i) {
    switch (constants[i]) {
      case Constant::kMu: out.contact.mu = values[i]; break;
      case Constant::kRolling: rolling = values[i]; break;
      case Constant::kSpin: out.contact.patch_radius = values[i]; break;
      case Constant::kCushion: out.collision.cushion_restitution = values[i]; break;
      case Constant::kCushionFriction: out.collision.cushion_friction = values[i]; break;
      case Constant::kBallBall: out.collision.ball_restitution = values[i]; break;
    }
  }
  // mu_r = a d / (5 r) kept (or set) after a possibly new a.
  out.contact.d = 5.0 * r * rolling / out.contact.patch_radius;
  if (out.contact.d > 1.0) {
    out.contact.d = 1.0;
    out.contact.patch_radius = 5.0 * r * rolling;
  }
  return out;
}

ShotErrors Errors(const table::TableGeometry& table, const ModelParameters& params,
                  const TrackedShot& shot, const Strike& strike) {
  return ErrorsOf(ShotModel(table, params, shot), strike);
}

ShotFit FitStrike(const table::TableGeometry& table, const ModelParameters& params,
                  const TrackedShot& shot, const FitOptions& options,
                  const std::optional<Strike>& previous) {
  return FitOne(table, params, shot, options, previous);
}

ShotsFit FitShots(const table::TableGeometry& table, const ModelParameters& params,
                  const std::vector<TrackedShot>& shots, const FitOptions& options,
                  batch::ThreadPool& pool, const std::vector<bool>& held_out,
                  const FitProgress& progress) {
  if (!held_out.empty() && held_out.size() != shots.size())
    throw std::invalid_argument("FitShots: held_out needs one flag per shot");
  auto is_held_out = [&](std::size_t i) { return !held_out.empty() && held_out[i]; };
  ShotsFit out;
  out.params = params;
  out.shots.resize(shots.size());

  // Fits the strikes of the shots `which` with out.params, from their previous strikes when
  // `refine`.
  auto fit_strikes = [&](const std::vector<std::size_t>& which, bool refine, const char* stage) {
    auto results = pool.Map(
        which.size(),
        [&](std::size_t job) {
          const std::size_t i = which[job];
          std::optional<Strike> previous;
          if (refine && out.shots[i].ok()) previous = out.shots[i].strike;
          return FitOne(table, out.params, shots[i], options, previous);
        },
        progress ? batch::Progress([&](std::size_t done, std::size_t total) {
          progress(stage, done, total);
        })
                 : batch::Progress());
    for (std::size_t job = 0; job < which.size(); ++job) {
      const std::size_t i = which[job];
      if (results[job].ok()) {
        out.shots[i] = *results[job].value;
      } else {
        out.shots[i] = ShotFit{};
        out.shots[i].id = shots[i].id;
        out.shots[i].error = results[job].error;
      }
      out.shots[i].held_out = is_held_out(i);
    }
  };

  std::vector<std::size_t> all(shots.size()), fitted;
  for (std::size_t i = 0; i < shots.size(); ++i) {
    all[i] = i;
    if (!is_held_out(i)) fitted.push_back(i);
  }
  std::vector<Constant> constants = options.constants;
  const bool with_constants = !constants.empty();
  fit_strikes(with_constants ? fitted : all, false, "strikes");

  for (Constant c : options.constants) {
    ConstantFit f;
    f.constant = c;
    f.prior = f.value = ConstantValue(params, c);
    out.constants.push_back(f);
  }
  if (with_constants) {
    std::vector<Strike> strikes(shots.size());
    std::vector<std::size_t> included;
    auto choose_shots = [&] {
      std::vector<double> rmse;
      for (std::size_t i : fitted)
        if (out.shots[i].ok()) rmse.push_back(out.shots[i].errors.rmse_all);
      const double limit = options.outlier_factor * Median(rmse);
      included.clear();
      for (std::size_t i : fitted) {
        strikes[i] = out.shots[i].strike;
        if (out.shots[i].ok() && out.shots[i].errors.rmse_all <= limit) included.push_back(i);
      }
    };
    auto values_of = [&] {
      std::vector<double> v;
      for (Constant c : constants) v.push_back(ConstantValue(out.params, c));
      return v;
    };
    const ConstantsProblem problem{table, params, shots, included, strikes, constants, pool};
    auto round = [&](int r) {
      choose_shots();
      if (progress) progress("constants, round " + std::to_string(r + 1), 0, 1);
      const std::vector<double> v = SolveConstants(problem, values_of(), options.max_iterations);
      out.params = WithConstants(out.params, constants, v);
      fit_strikes(fitted, true, ("strikes, round " + std::to_string(r + 1)).c_str());
    };
    for (int r = 0; r < options.rounds && !constants.empty(); ++r) round(r);

    // Identifiability: constants the shots do not pin down go back to their priors, and the
    // others are fitted once more without them.
    for (int pass = 0; pass < 2 && !constants.empty(); ++pass) {
      choose_shots();
      const Eigen::MatrixXd cov = ConstantsCovariance(problem, values_of(), options.fit_elevation);
      std::vector<Constant> kept;
      for (std::size_t c = 0; c < constants.size(); ++c) {
        auto it = std::find_if(out.constants.begin(), out.constants.end(),
                               [&](const ConstantFit& f) { return f.constant == constants[c]; });
        it->value = ConstantValue(out.params, constants[c]);
        it->sd = std::sqrt(cov(c, c));
        it->identifiable = it->sd <= options.max_relative_sd * std::abs(it->value);
        if (it->identifiable) {
          kept.push_back(constants[c]);
        } else {
          it->value = it->prior;
        }
      }
      if (kept.size() == constants.size()) break;
      for (const ConstantFit& f : out.constants)
        if (!f.identifiable) out.params = WithConstants(out.params, {f.constant}, {f.prior});
      constants = kept;
      if (!constants.empty()) round(options.rounds);
    }
    out.constant_shots = static_cast<int>(included.size());
    std::vector<std::size_t> rest;
    for (std::size_t i : all)
      if (is_held_out(i)) rest.push_back(i);
    fit_strikes(rest, false, "held-out strikes");
  }

  std::vector<double> cue, cue_held;
  for (const ShotFit& f : out.shots) {
    if (!f.ok()) continue;
    (f.held_out ? cue_held : cue).push_back(f.rmse_cue);
  }
  out.median_cue_rmse = Median(cue);
  out.held_out_median_cue_rmse = Median(cue_held);
  return out;
}

TrackedShot SimulateTrackedShot(const table::TableGeometry& table, const ModelParameters& params,
                                const std::vector<Eigen::Vector2d>& starts, std::size_t cue,
                                const Strike& strike, double duration, double period, double noise,
                                double thinning, std::uint64_t seed) {
  if (cue >= starts.size()) throw std::invalid_argument("SimulateTrackedShot: no such cue ball");
  TrackedShot shot;
  shot.cue = cue;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    TrackedBall b;
    b.name = std::to_string(i + 1);
    b.t = {0.0};
    b.position = {starts[i]};
    shot.balls.push_back(b);
  }
  const ShotModel model(table, params, shot);
  const table::TableSimulation sim = model.Run(strike, duration);
  std::mt19937_64 random(seed);
  std::normal_distribution<double> gauss(0.0, noise);
  const int samples = static_cast<int>(std::floor(duration / period + 1e-9)) + 1;
  for (std::size_t i = 0; i < starts.size(); ++i) {
    TrackedBall& b = shot.balls[i];
    b.t.clear();
    b.position.clear();
    Eigen::Vector2d last_true = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
    for (int k = 0; k < samples; ++k) {
      const double t = k * period;
      const double tau = std::clamp(t - strike.time, 0.0, sim.time());
      const Eigen::Vector2d p = sim.StateAt(i, tau).segment<2>(physics::kX);
      const Eigen::Vector2d seen = p + Eigen::Vector2d(gauss(random), gauss(random));
      const bool keep = k == 0 || k == samples - 1 || (p - last_true).norm() >= thinning;
      if (!keep) continue;
      b.t.push_back(t);
      b.position.push_back(seen);
      last_true = p;
    }
  }
  return shot;
}

}  // namespace billiard::shot_fit
