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

namespace billiard::shot_fit {

namespace {

using physics::ModelParameters;

// The tip's reach in the fit, per axis, as a fraction of r: about a miscue's limit (the cue
// set's max_tip_offset is 0.5) with room for the side and height together to stay below r.
constexpr double kTipLimit = 0.6;
constexpr double kMaxElevation = 0.6;  // [rad], a masse is no three-cushion shot
// Where a fitted elevation starts [rad]: off the bound, where its differences are two-sided.
constexpr double kStartElevation = 0.05;
constexpr double kMaxCueSpeed = 12.0;  // [m/s], beyond any player's break
// How far the fit may move a ball from where it was first seen [m]: the recordings round to a
// millimetre, and a ball's centre is found to about as much again.
constexpr double kStartSlack = 0.004;
// A scene that needs more events is no shot the fit should follow (a numerical pathology).
constexpr std::int64_t kMaxEvents = 20000;
// The horizons of the continuation [s]; the last stage is always the whole shot.
constexpr double kHorizons[] = {2.0, 4.0, 8.0};
// The first stage's grid around the launch the samples show, and how many of its best points
// go on to the refinement. Wide in heading and speed: where the cue ball meets a ball within the
// first frames, the samples show it after that collision.
constexpr double kSpeedFactors[] = {0.8, 1.0, 1.25, 1.6};
constexpr double kHeadingOffsets[] = {0.0, -0.04, 0.04, -0.12, 0.12, -0.3, 0.3};  // [rad]
constexpr double kTipGrid[] = {-0.4, -0.2, 0.0, 0.2, 0.4};
constexpr int kStarts = 6;
// How many samples after the first one give the launch velocity (50 Hz: 0.06 s).
constexpr int kLaunchSamples = 3;

const char* const kConstantNames[] = {"mu",      "rolling",          "spin",
                                      "cushion", "cushion_friction", "ball_ball"};

// How near a bound of its Range a fitted constant sits at it (AtRangeBound).
constexpr double kAtBound = 1e-6, kAtBoundSds = 3.0;

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
// the impact time, the elevation when fitted, and the start offsets of the balls whose starts
// are fitted (FitOptions::fit_start, fit_cue_start).
struct Layout {
  bool elevation = false;
  double radius = 0.0;
  std::vector<std::size_t> offset_balls;

  Layout(const FitOptions& options, double r, const TrackedShot& shot)
      : elevation(options.fit_elevation), radius(r) {
    for (std::size_t i = 0; i < shot.balls.size(); ++i)
      if (i == shot.cue ? options.fit_cue_start : options.fit_start) offset_balls.push_back(i);
  }
  std::size_t first_offset() const { return elevation ? 6 : 5; }
  std::size_t size() const { return first_offset() + 2 * offset_balls.size(); }
};

std::vector<double> ToVector(const Strike& s, const Layout& layout) {
  std::vector<double> x = {s.stroke.speed, s.stroke.heading, s.stroke.tip_side / layout.radius,
                           s.stroke.tip_height / layout.radius, s.time};
  if (layout.elevation) x.push_back(s.stroke.elevation);
  for (std::size_t i : layout.offset_balls) {
    const Eigen::Vector2d d =
        i < s.start_offsets.size() ? s.start_offsets[i] : Eigen::Vector2d::Zero();
    x.push_back(d.x());
    x.push_back(d.y());
  }
  return x;
}

Strike FromVector(const double* x, const Layout& layout) {
  Strike s;
  s.stroke.speed = x[0];
  s.stroke.heading = x[1];
  s.stroke.tip_side = x[2] * layout.radius;
  s.stroke.tip_height = x[3] * layout.radius;
  s.time = x[4];
  // The differences step below a level cue's 0 (the bound); the stroke there is the level one.
  s.stroke.elevation = layout.elevation ? std::max(x[5], 0.0) : 0.0;
  if (layout.offset_balls.empty()) return s;
  s.start_offsets.assign(layout.offset_balls.back() + 1, Eigen::Vector2d::Zero());
  const double* offset = x + layout.first_offset();
  for (std::size_t i : layout.offset_balls) {
    s.start_offsets[i] = Eigen::Vector2d(offset[0], offset[1]);
    offset += 2;
  }
  return s;
}

// The balls moved onto the playing surface and off each other where the tracking (or a fitted
// offset) put them a millimetre wrong (touching balls, millimetre rounding): apart along their
// line, by half the overlap each, plus a micrometre.
std::vector<Eigen::Vector2d> Placed(const table::TableGeometry& table, double r,
                                    std::vector<Eigen::Vector2d> p) {
  for (Eigen::Vector2d& q : p) {
    q = Eigen::Vector2d(std::clamp(q.x(), r, table.length - r),
                        std::clamp(q.y(), r, table.width - r));
  }
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

std::vector<Eigen::Vector2d> FirstSeen(const TrackedShot& shot) {
  std::vector<Eigen::Vector2d> p;
  for (const TrackedBall& b : shot.balls) p.push_back(b.position.front());
  return p;
}

// The run's impacts in order (kind, balls, cushion), hashed (FNV-1a): two runs with the same
// sequence lie on one smooth piece of the cost. Between pieces it jumps: a ball that catches up
// with another before it stops, or stops just short, is a different shot.
std::uint64_t ImpactSequence(const table::TableSimulation& sim) {
  constexpr std::uint64_t kFnvOffsetBasis = 14695981039346656037ull;
  constexpr std::uint64_t kFnvPrime = 1099511628211ull;
  std::uint64_t hash = kFnvOffsetBasis;
  for (const table::TableEvent& e : sim.events()) {
    if (e.type == table::EventType::kTransition) continue;
    for (int v : {static_cast<int>(e.type), e.ball, e.other, e.cushion})
      hash = (hash ^ static_cast<std::uint64_t>(v + 1)) * kFnvPrime;
  }
  return hash;
}

// One shot with one parameter set: the start scene, and what a strike makes of it.
class ShotModel {
 public:
  ShotModel(const table::TableGeometry& table, const ModelParameters& params,
            const TrackedShot& shot)
      : table_(table),
        params_(params),
        shot_(shot),
        start_(FirstSeen(shot)) {}

  const TrackedShot& shot() const { return shot_; }
  const ModelParameters& params() const { return params_; }

  // 2 per sample of each ball up to `horizon`.
  int ResidualCount(double horizon) const {
    int n = 0;
    for (const TrackedBall& b : shot_.balls)
      for (double t : b.t) n += t <= horizon ? 2 : 0;
    return n;
  }

  // Simulated minus tracked, ball by ball, sample by sample, up to `horizon`; false where the
  // strike is none a cue gives or the simulation refuses the scene.
  // `impacts`, when given, receives the run's ImpactSequence.
  bool Residuals(const Strike& strike, double horizon, double* out,
                 std::uint64_t* impacts = nullptr) const {
    try {
      const table::TableSimulation sim = Run(strike, std::min(horizon, shot_.Duration()));
      if (impacts != nullptr) *impacts = ImpactSequence(sim);
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

  std::vector<double> Residuals(const Strike& strike, double horizon,
                                std::uint64_t* impacts = nullptr) const {
    std::vector<double> r(ResidualCount(horizon));
    if (!Residuals(strike, horizon, r.data(), impacts)) return {};
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
    std::vector<Eigen::Vector2d> where = start_;
    for (std::size_t i = 0; i < std::min(where.size(), strike.start_offsets.size()); ++i)
      where[i] += strike.start_offsets[i];
    where = Placed(table_, params_.ball.radius, where);
    std::vector<table::SceneBall> balls;
    for (std::size_t i = 0; i < where.size(); ++i) {
      table::SceneBall b;
      b.id = static_cast<int>(i);
      b.state.segment<2>(physics::kX) = where[i];
      if (i == shot_.cue && strike.stroke.speed > 0.0)
        b.state = physics::StrikeBall(strike.stroke, where[i], params_);
      balls.push_back(b);
    }
    table::TableSimulationOptions options;
    options.max_events = kMaxEvents;
    options.cushion_model = kCushionModel;
    table::TableSimulation sim(table_, params_, balls, options);
    sim.Run(std::max(0.0, until - strike.time));
    return sim;
  }

 private:
  const table::TableGeometry& table_;
  const ModelParameters& params_;
  const TrackedShot& shot_;
  std::vector<Eigen::Vector2d> start_;  // where each ball was first seen
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
  Layout layout;
  bool operator()(double const* const* x, double* residuals) const {
    return model->Residuals(FromVector(x[0], layout), horizon, residuals);
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

// The steps of the central differences in a strike vector x (ToVector's order): small against
// what a camera resolves, large against the rounding of the simulation.
std::vector<double> DifferenceSteps(const Layout& layout, const std::vector<double>& x) {
  std::vector<double> h = {1e-4 * x[0], 1e-5, 1e-4, 1e-4, 1e-5};  // [m/s], rad, -, -, s
  if (layout.elevation) h.push_back(1e-4);                        // [rad]
  h.resize(layout.size(), 1e-5);                                  // start offsets [m]
  return h;
}

// The bounds of a strike vector (ToVector's order) for a shot whose impact lies in [lo, hi].
struct StrikeBounds {
  std::vector<double> lo, hi;
};
StrikeBounds BoundsOf(const Layout& layout, double impact_lo, double impact_hi) {
  StrikeBounds b{{0.01, -std::numeric_limits<double>::infinity(), -kTipLimit, -kTipLimit, impact_lo},
                 {kMaxCueSpeed, std::numeric_limits<double>::infinity(), kTipLimit, kTipLimit,
                  impact_hi}};
  if (layout.elevation) {
    b.lo.push_back(0.0);
    b.hi.push_back(kMaxElevation);
  }
  for (std::size_t i = b.lo.size(); i < layout.size(); ++i) {
    b.lo.push_back(-kStartSlack);
    b.hi.push_back(kStartSlack);
  }
  return b;
}

// The impact lies between the cue ball's first sample (still) and its second (moving); a
// frame's worth of slack before, for a clock that started late.
std::pair<double, double> ImpactRange(const TrackedShot& shot) {
  const TrackedBall& cue = shot.balls.at(shot.cue);
  if (cue.t.size() < 2) return {0.0, 0.0};
  return {cue.t[0] - (cue.t[1] - cue.t[0]), cue.t[1]};
}

// Refines x over `horizon`; returns the cost there (infinite where the start cannot be simulated).
double RefineStrike(const ShotModel& model, double horizon, const FitOptions& options,
                    double impact_lo, double impact_hi, std::vector<double>* x) {
  const int residuals = model.ResidualCount(horizon);
  const Layout layout(options, model.params().ball.radius, model.shot());
  if (residuals == 0) return 0.0;
  if (!std::isfinite(model.Cost(FromVector(x->data(), layout), horizon)))
    return std::numeric_limits<double>::infinity();
  ceres::NumericDiffOptions diff;
  diff.relative_step_size = 1e-5;
  auto* cost = new ceres::DynamicNumericDiffCostFunction<StrikeResidual, ceres::CENTRAL>(
      new StrikeResidual{&model, horizon, layout}, ceres::TAKE_OWNERSHIP, diff);
  cost->AddParameterBlock(static_cast<int>(x->size()));
  cost->SetNumResiduals(residuals);
  ceres::Problem problem;
  problem.AddResidualBlock(cost, nullptr, x->data());
  const StrikeBounds bounds = BoundsOf(layout, impact_lo, impact_hi);
  for (std::size_t k = 0; k < x->size(); ++k) {
    if (std::isfinite(bounds.lo[k])) problem.SetParameterLowerBound(x->data(), k, bounds.lo[k]);
    if (std::isfinite(bounds.hi[k])) problem.SetParameterUpperBound(x->data(), k, bounds.hi[k]);
  }
  ceres::Solver::Summary summary;
  ceres::Solve(SolverOptions(options.max_iterations), &problem, &summary);
  return model.Cost(FromVector(x->data(), layout), horizon);
}

double Median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The fit over the samples up to `horizon` (the errors reported over the whole shot).
ShotFit FitOne(const table::TableGeometry& table, const ModelParameters& params,
               const TrackedShot& shot, const FitOptions& options,
               const std::optional<Strike>& previous,
               double horizon = std::numeric_limits<double>::infinity()) {
  const ShotModel model(table, params, shot);
  const double r = params.ball.radius;
  const Layout layout(options, r, shot);
  const TrackedBall& cue = shot.balls.at(shot.cue);
  ShotFit fit;
  fit.id = shot.id;
  if (cue.t.size() < 3) {  // a cue ball that never moves: the strike is none
    fit.errors = ErrorsOf(model, fit.strike);
    fit.rmse_cue = fit.errors.rmse[shot.cue];
    return fit;
  }
  const auto [impact_lo, impact_hi] = ImpactRange(shot);
  const double first_horizon = std::min({kHorizons[0], horizon, shot.Duration()});

  std::vector<std::pair<double, std::vector<double>>> scored;
  for (double side : kTipGrid) {
    for (double height : kTipGrid) {
      for (double factor : kSpeedFactors) {
        for (double turn : kHeadingOffsets) {
          Strike s = LaunchGuess(params, cue, side);
          s.stroke.speed *= factor;
          s.stroke.heading += turn;
          s.stroke.tip_height = height * r;
          if (options.fit_elevation) s.stroke.elevation = kStartElevation;
          const std::vector<double> x = ToVector(s, layout);
          scored.emplace_back(model.Cost(s, first_horizon), x);
        }
      }
    }
  }
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  scored.resize(std::min<std::size_t>(kStarts, scored.size()));

  double best_cost = std::numeric_limits<double>::infinity();
  std::vector<double> best;
  auto consider = [&](std::vector<double> x, bool continuation) {
    if (continuation) {
      for (double h : kHorizons) {
        if (h >= std::min(horizon, shot.Duration())) break;
        RefineStrike(model, h, options, impact_lo, impact_hi, &x);
      }
    }
    const double c = RefineStrike(model, horizon, options, impact_lo, impact_hi, &x);
    if (c < best_cost) {
      best_cost = c;
      best = x;
    }
  };
  for (const auto& start : scored) consider(start.second, true);
  if (previous) {
    std::vector<double> x = ToVector(*previous, layout);
    x[4] = std::clamp(x[4], impact_lo, impact_hi);
    consider(x, false);
  }
  if (best.empty()) throw std::invalid_argument("shot " + shot.id + ": no strike simulates");
  fit.strike = FromVector(best.data(), layout);
  fit.errors = ErrorsOf(model, fit.strike);
  fit.rmse_cue = fit.errors.rmse[shot.cue];
  return fit;
}

// The joint problem of the strikes of several shots and the shared constants, linearized at one
// point: for each shot its Gauss-Newton blocks, from central differences of its residuals.
struct ShotBlocks {
  Eigen::MatrixXd ss, sc, cc;  // J_s^T J_s, J_s^T J_c, J_c^T J_c
  Eigen::VectorXd gs, gc;      // J_s^T r, J_c^T r
  double squares = 0.0;
  int residuals = 0;
  // Index k: the sum over each ball's coordinates of r_i r_{i+k}, i and i + k samples of that
  // ball k apart (k = 0: the squares): the residuals' autocovariance, unnormalised.
  std::vector<double> lagged;
};

// The lags the residuals' correlation is summed over [samples]: at 30-50 Hz, 2-3 s, beyond the
// estimator's filtered tracks' memory.
constexpr int kMaxLag = 100;

// The residuals' sums of products at lags 0..kMaxLag (ShotBlocks::lagged), per ball and
// coordinate over its samples up to `horizon` (ShotModel::Residuals' order: ball by ball,
// x then y per sample).
std::vector<double> LaggedProducts(const TrackedShot& shot, double horizon,
                                   const std::vector<double>& r) {
  std::vector<double> lagged(kMaxLag + 1, 0.0);
  std::size_t first = 0;  // the ball's first residual
  for (const TrackedBall& b : shot.balls) {
    const auto n = static_cast<std::size_t>(
        std::count_if(b.t.begin(), b.t.end(), [&](double t) { return t <= horizon; }));
    for (std::size_t axis = 0; axis < 2; ++axis) {
      for (std::size_t i = 0; i < n; ++i) {
        const double ri = r[first + 2 * i + axis];
        for (std::size_t k = 0; k <= kMaxLag && i + k < n; ++k)
          lagged[k] += ri * r[first + 2 * (i + k) + axis];
      }
    }
    first += 2 * n;
  }
  return lagged;
}

// The residuals' integrated correlation time in samples, tau = 1 + 2 sum_k rho_k, the lag-k
// autocorrelations pooled over the shots, summed up to the first that is not positive (the
// simplest of Geyer 1992's initial sequence estimators): n correlated residuals say what
// n / tau independent ones would. The
// estimator's tracks are filtered, so neighbouring frames share their errors; a model's own
// error on real shots lasts for seconds. Never below 1.
double CorrelationTime(const std::vector<ShotBlocks>& blocks) {
  std::vector<double> lagged(kMaxLag + 1, 0.0);
  for (const ShotBlocks& b : blocks)
    for (std::size_t k = 0; k < b.lagged.size(); ++k) lagged[k] += b.lagged[k];
  if (!(lagged[0] > 0.0)) return 1.0;
  double tau = 1.0;
  for (std::size_t k = 1; k <= kMaxLag; ++k) {
    const double rho = lagged[k] / lagged[0];
    if (rho <= 0.0) break;
    tau += 2.0 * rho;
  }
  return tau;
}

struct JointProblem {
  const table::TableGeometry& table;
  const ModelParameters& base;  // the constants not fitted
  const std::vector<TrackedShot>& shots;
  std::vector<std::size_t> included;
  const std::vector<Constant>& constants;
  const FitOptions& options;
  batch::ThreadPool& pool;
  double horizon = std::numeric_limits<double>::infinity();  // the samples up to it count

  struct Evaluation {
    std::vector<double> r;  // empty where the shot does not simulate
    std::uint64_t impacts = 0;
    double Squares() const {
      if (r.empty()) return std::numeric_limits<double>::infinity();
      double sum = 0.0;
      for (double v : r) sum += v * v;
      return sum;
    }
  };

  Evaluation Evaluate(std::size_t s, const std::vector<double>& strike,
                      const std::vector<double>& values) const {
    const ModelParameters p = WithConstants(base, constants, values);
    Evaluation e;
    e.r = ShotModel(table, p, shots[s])
              .Residuals(FromVector(strike.data(), Layout(options, p.ball.radius, shots[s])),
                         horizon, &e.impacts);
    return e;
  }

  // Central differences within the piece of the cost the point lies on: a step that changes
  // the impacts gives way to the one-sided difference of the other, and where both do, the
  // shot says nothing of that parameter here (its column is zero).
  ShotBlocks Linearize(std::size_t s, const std::vector<double>& strike,
                       const std::vector<double>& values) const {
    const Evaluation e0 = Evaluate(s, strike, values);
    if (e0.r.empty()) throw std::runtime_error("shot " + shots[s].id + " does not simulate");
    const int m = static_cast<int>(e0.r.size());
    const std::size_t n = strike.size(), k = values.size();
    const std::vector<double> strike_steps =
        DifferenceSteps(Layout(options, base.ball.radius, shots[s]), strike);

    Eigen::MatrixXd j = Eigen::MatrixXd::Zero(m, n + k);
    for (std::size_t c = 0; c < n + k; ++c) {
      std::vector<double> xp = strike, xm = strike, vp = values, vm = values;
      double h;
      if (c < n) {
        h = strike_steps[c];
        xp[c] += h;
        xm[c] -= h;
      } else {
        h = 1e-4 * std::max(std::abs(values[c - n]), 1e-3);
        vp[c - n] += h;
        vm[c - n] -= h;
      }
      const Evaluation ep = Evaluate(s, xp, vp), em = Evaluate(s, xm, vm);
      const bool plus = !ep.r.empty() && ep.impacts == e0.impacts;
      const bool minus = !em.r.empty() && em.impacts == e0.impacts;
      for (int i = 0; i < m; ++i) {
        if (plus && minus) {
          j(i, c) = (ep.r[i] - em.r[i]) / (2.0 * h);
        } else if (plus) {
          j(i, c) = (ep.r[i] - e0.r[i]) / h;
        } else if (minus) {
          j(i, c) = (e0.r[i] - em.r[i]) / h;
        }
      }
    }
    const Eigen::Map<const Eigen::VectorXd> r(e0.r.data(), m);
    const auto js = j.leftCols(n), jc = j.rightCols(k);
    ShotBlocks b;
    b.ss = js.transpose() * js;
    b.sc = js.transpose() * jc;
    b.cc = jc.transpose() * jc;
    b.gs = js.transpose() * r;
    b.gc = jc.transpose() * r;
    b.squares = r.squaredNorm();
    b.residuals = m;
    b.lagged = LaggedProducts(shots[s], horizon, e0.r);
    return b;
  }

  std::vector<ShotBlocks> LinearizeAll(const std::vector<std::vector<double>>& strikes,
                                       const std::vector<double>& values) const {
    auto results = pool.Map(included.size(), [&](std::size_t job) {
      return Linearize(included[job], strikes[job], values);
    });
    std::vector<ShotBlocks> out;
    for (auto& result : results) {
      if (!result.ok()) throw std::runtime_error(result.error);
      out.push_back(std::move(*result.value));
    }
    return out;
  }

  // Each included shot's sum of squares and impacts.
  std::vector<std::pair<double, std::uint64_t>> EvaluateAll(
      const std::vector<std::vector<double>>& strikes, const std::vector<double>& values) const {
    auto results = pool.Map(included.size(), [&](std::size_t job) {
      const Evaluation e = Evaluate(included[job], strikes[job], values);
      return std::make_pair(e.Squares(), e.impacts);
    });
    std::vector<std::pair<double, std::uint64_t>> out;
    for (const auto& result : results)
      out.push_back(result.ok() ? *result.value
                                : std::make_pair(std::numeric_limits<double>::infinity(),
                                                 std::uint64_t{0}));
    return out;
  }
};

// The reduced system of the constants, the strikes eliminated: with each shot's strike block
// damped as A_s = J_s^T J_s + lambda diag(J_s^T J_s),
//   S = sum_s J_c^T J_c + lambda diag(sum_s J_c^T J_c) - sum_s J_c^T J_s A_s^-1 J_s^T J_c,
//   g = sum_s J_c^T r - J_c^T J_s A_s^-1 J_s^T r.
struct Reduced {
  Eigen::MatrixXd s;
  Eigen::VectorXd g;
  std::vector<Eigen::MatrixXd> a_inv;  // per shot
};
Reduced Reduce(const std::vector<ShotBlocks>& blocks, std::size_t k, double lambda) {
  Reduced out;
  out.s = Eigen::MatrixXd::Zero(k, k);
  out.g = Eigen::VectorXd::Zero(k);
  Eigen::MatrixXd cc = Eigen::MatrixXd::Zero(k, k);
  for (const ShotBlocks& b : blocks) {
    // A tiny floor keeps a strike parameter no sample sees (a tip offset with no cushion to
    // show its spin) from making A singular.
    Eigen::MatrixXd a = b.ss;
    a.diagonal() += lambda * b.ss.diagonal() +
                    Eigen::VectorXd::Constant(a.rows(), 1e-12 * (1.0 + b.ss.diagonal().maxCoeff()));
    const Eigen::MatrixXd a_inv = a.ldlt().solve(Eigen::MatrixXd::Identity(a.rows(), a.cols()));
    cc += b.cc;
    out.s -= b.sc.transpose() * a_inv * b.sc;
    out.g += b.gc - b.sc.transpose() * a_inv * b.gs;
    out.a_inv.push_back(a_inv);
  }
  out.s += cc;
  out.s.diagonal() += lambda * cc.diagonal();
  return out;
}

// Levenberg-Marquardt over the strikes of the included shots and the constants together, by the
// reduced system (each iteration one linearization of every shot on the pool, summed in shot
// order: the same steps on any thread count), within the bounds (a step is clamped to them).
// Robust: shot j of n_j samples and mean squared error e_j costs n_j c^2 log(1 + e_j / c^2)
// (Cauchy's loss of the shot's RMSE, c the median RMSE when the solve starts), so that the
// constants follow the typical shot rather than the few the model cannot follow; iteratively
// reweighted, each shot's blocks weighted by 1 / (1 + e_j / c^2) at each linearization.
void SolveJoint(const JointProblem& problem, const FitOptions& options,
                std::vector<std::vector<double>>* strikes, std::vector<double>* values) {
  const std::size_t k = values->size();
  std::vector<StrikeBounds> bounds;
  for (std::size_t s : problem.included) {
    const auto [lo, hi] = ImpactRange(problem.shots[s]);
    bounds.push_back(BoundsOf(Layout(problem.options, problem.base.ball.radius, problem.shots[s]), lo, hi));
  }
  std::vector<std::pair<double, std::uint64_t>> current = problem.EvaluateAll(*strikes, *values);
  std::vector<double> samples, mse;
  for (std::size_t j = 0; j < current.size(); ++j) {
    samples.push_back(std::max(1, ShotModel(problem.table, problem.base,
                                            problem.shots[problem.included[j]])
                                          .ResidualCount(problem.horizon) / 2));
    mse.push_back(current[j].first / samples[j]);
  }
  const double c2 = std::max(Median(mse), 1e-12);
  auto robust = [&](const std::vector<std::pair<double, std::uint64_t>>& e) {
    double sum = 0.0;
    for (std::size_t j = 0; j < e.size(); ++j)
      sum += samples[j] * c2 * std::log1p(e[j].first / samples[j] / c2);
    return sum;
  };
  double lambda = 1e-3;
  constexpr double kMaxLambda = 1e8;
  constexpr double kRelativeDecrease = 1e-7;
  for (int iteration = 0; iteration < options.max_iterations && lambda < kMaxLambda; ++iteration) {
    std::vector<ShotBlocks> blocks = problem.LinearizeAll(*strikes, *values);
    for (std::size_t j = 0; j < blocks.size(); ++j) {
      const double w = 1.0 / (1.0 + current[j].first / samples[j] / c2);
      for (Eigen::MatrixXd* m : {&blocks[j].ss, &blocks[j].sc, &blocks[j].cc}) *m *= w;
      blocks[j].gs *= w;
      blocks[j].gc *= w;
    }
    bool accepted = false;
    while (!accepted && lambda < kMaxLambda) {
      const Reduced reduced = Reduce(blocks, k, lambda);
      const Eigen::VectorXd dc = -reduced.s.ldlt().solve(reduced.g);
      std::vector<double> new_values = *values;
      for (std::size_t c = 0; c < k; ++c) {
        const Range range = ConstantRange(problem.constants[c]);
        new_values[c] = std::clamp(new_values[c] + dc[c], range.lo, range.hi);
      }
      std::vector<std::vector<double>> new_strikes = *strikes;
      for (std::size_t j = 0; j < blocks.size(); ++j) {
        const Eigen::VectorXd ds = -reduced.a_inv[j] * (blocks[j].gs + blocks[j].sc * dc);
        for (std::size_t c = 0; c < new_strikes[j].size(); ++c)
          new_strikes[j][c] = std::clamp(new_strikes[j][c] + ds[c], bounds[j].lo[c], bounds[j].hi[c]);
      }
      const std::vector<std::pair<double, std::uint64_t>> trial =
          problem.EvaluateAll(new_strikes, new_values);
      // A step is judged on every shot: one that jumps to another piece of the cost (a
      // collision made or missed) counts with the rest, else the fit could walk a shot into a
      // worse shot step by step. (Where a shot does not simulate, the sum is infinite.)
      const double before = robust(current), after = robust(trial);
      if (after < before) {
        accepted = true;
        const bool converged = before - after < kRelativeDecrease * before;
        current = trial;
        *strikes = std::move(new_strikes);
        *values = std::move(new_values);
        lambda = std::max(lambda / 3.0, 1e-9);
        if (converged) return;
      } else {
        lambda *= 4.0;
      }
    }
  }
}

// The marginal covariance of the constants at the solution (see the header): tau sigma^2 S^-1
// with the undamped reduced matrix S and the residuals' correlation time tau
// (CorrelationTime, into *correlation_time); infinite where S is singular (a constant no shot
// excites).
Eigen::MatrixXd ConstantsCovariance(const JointProblem& problem,
                                    const std::vector<std::vector<double>>& strikes,
                                    const std::vector<double>& values, double* correlation_time) {
  const std::size_t k = values.size();
  const std::vector<ShotBlocks> blocks = problem.LinearizeAll(strikes, values);
  const Reduced reduced = Reduce(blocks, k, 0.0);
  double squares = 0.0;
  int dof = -static_cast<int>(k);
  for (std::size_t j = 0; j < blocks.size(); ++j) {
    squares += blocks[j].squares;
    dof += blocks[j].residuals - static_cast<int>(strikes[j].size());
  }
  *correlation_time = CorrelationTime(blocks);
  const double sigma2 = *correlation_time * squares / std::max(dof, 1);
  // A constant no shot excites has a zero row: its variance is infinite, and the others' are
  // those of the rest of the matrix.
  Eigen::MatrixXd cov = Eigen::MatrixXd::Constant(k, k, std::numeric_limits<double>::infinity());
  const double largest = reduced.s.diagonal().cwiseAbs().maxCoeff();
  std::vector<int> excited;
  for (std::size_t c = 0; c < k; ++c)
    if (reduced.s(c, c) > 1e-12 * largest) excited.push_back(static_cast<int>(c));
  if (excited.empty()) return cov;
  const Eigen::MatrixXd s = reduced.s(excited, excited);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(s);
  if (eig.eigenvalues().minCoeff() <= 1e-12 * eig.eigenvalues().cwiseAbs().maxCoeff()) return cov;
  const Eigen::MatrixXd inverse = sigma2 * s.inverse();
  for (std::size_t a = 0; a < excited.size(); ++a)
    for (std::size_t b = 0; b < excited.size(); ++b) cov(excited[a], excited[b]) = inverse(a, b);
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

table::TableSimulation SimulateShot(const table::TableGeometry& table,
                                    const ModelParameters& params, const TrackedShot& shot,
                                    const Strike& strike) {
  return ShotModel(table, params, shot).Run(strike, shot.Duration());
}

ShotFit FitStrike(const table::TableGeometry& table, const ModelParameters& params,
                  const TrackedShot& shot, const FitOptions& options,
                  const std::optional<Strike>& previous) {
  return FitOne(table, params, shot, options, previous);
}

bool AtRangeBound(double value, double sd, bool pinned, double lo, double hi) {
  const double margin = pinned ? kAtBoundSds * sd : 0.0;
  return value <= std::max(lo * (1.0 + kAtBound), lo + margin) ||
         value >= std::min(hi * (1.0 - kAtBound), hi - margin);
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
  // While the constants are fitted the cue ball stays where it was first seen (its offset
  // along its line is nearly the impact's time, and the joint steps would trade one against
  // the other); the strikes reported are fitted with the options as given.
  FitOptions phase_options = options;
  if (!options.constants.empty()) phase_options.fit_cue_start = false;
  auto fit_strikes = [&](const std::vector<std::size_t>& which, bool refine,
                         const std::string& stage, double horizon) {
    auto results = pool.Map(
        which.size(),
        [&](std::size_t job) {
          const std::size_t i = which[job];
          std::optional<Strike> previous;
          if (refine && out.shots[i].ok()) previous = out.shots[i].strike;
          return FitOne(table, out.params, shots[i], phase_options, previous, horizon);
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
  const double full = std::numeric_limits<double>::infinity();
  if (!with_constants) fit_strikes(all, false, "strikes", full);

  for (Constant c : options.constants) {
    ConstantFit f;
    f.constant = c;
    f.prior = f.value = ConstantValue(params, c);
    out.constants.push_back(f);
  }
  if (with_constants) {
    JointProblem problem{table, params, shots, {}, constants, phase_options, pool};
    const double r = params.ball.radius;
    // The shots the constants are fitted on: those not held out whose strike fit is no outlier.
    auto strikes_of = [&] {
      std::vector<std::vector<double>> x;
      for (std::size_t i : problem.included)
        x.push_back(ToVector(out.shots[i].strike, Layout(phase_options, r, shots[i])));
      return x;
    };
    auto values_of = [&] {
      std::vector<double> v;
      for (Constant c : constants) v.push_back(ConstantValue(out.params, c));
      return v;
    };
    // The shots the constants are fitted on: those not held out whose fit over the horizon is
    // no outlier.
    auto choose_shots = [&] {
      problem.included.clear();
      for (std::size_t i : fitted)
        if (out.shots[i].ok()) problem.included.push_back(i);
      const auto evaluations = problem.EvaluateAll(strikes_of(), values_of());
      std::vector<double> rmse;
      for (std::size_t j = 0; j < evaluations.size(); ++j) {
        const ShotModel model(table, out.params, shots[problem.included[j]]);
        rmse.push_back(std::sqrt(evaluations[j].first /
                                 std::max(1, model.ResidualCount(problem.horizon) / 2)));
      }
      const double limit = options.outlier_factor * Median(rmse);
      std::vector<std::size_t> kept;
      for (std::size_t j = 0; j < rmse.size(); ++j)
        if (rmse[j] <= limit) kept.push_back(problem.included[j]);
      problem.included = kept;
    };
    // One stage: every strike over the horizon (from the last when `refine`), then the strikes
    // and the constants together.
    auto stage = [&](double horizon, bool refine, const std::string& name) {
      problem.horizon = horizon;
      fit_strikes(fitted, refine, "strikes, " + name, horizon);
      choose_shots();
      if (progress) progress("joint fit, " + name, 0, 1);
      std::vector<std::vector<double>> x = strikes_of();
      std::vector<double> v = values_of();
      SolveJoint(problem, options, &x, &v);
      out.params = WithConstants(out.params, constants, v);
      for (std::size_t j = 0; j < problem.included.size(); ++j)
        out.shots[problem.included[j]].strike =
            FromVector(x[j].data(), Layout(phase_options, r, shots[problem.included[j]]));
    };
    // A continuation over the horizon, as for one shot: the constants the first seconds show
    // (the slide, the roll, the first cushions) before the later collisions, whose timing they
    // set, can mislead them.
    bool refine = false;
    for (double h : kHorizons) {
      stage(h, refine, "first " + std::to_string(static_cast<int>(h)) + " s");
      refine = true;
    }
    for (int r_index = 0; r_index < options.rounds; ++r_index)
      stage(full, true, "whole shots, round " + std::to_string(r_index + 1));
    auto final_strikes = [&] { fit_strikes(fitted, true, "strikes, whole shots", full); };
    final_strikes();

    // Identifiability: constants the shots do not pin down go back to their priors, and the
    // others are fitted once more without them.
    while (!constants.empty()) {
      choose_shots();
      const Eigen::MatrixXd cov =
          ConstantsCovariance(problem, strikes_of(), values_of(), &out.correlation_time);
      std::vector<Constant> kept;
      for (std::size_t c = 0; c < constants.size(); ++c) {
        auto it = std::find_if(out.constants.begin(), out.constants.end(),
                               [&](const ConstantFit& f) { return f.constant == constants[c]; });
        it->value = ConstantValue(out.params, constants[c]);
        it->sd = std::sqrt(cov(c, c));
        // A fit that ran to the edge of its range found no minimum there: what the shots say
        // lies beyond what any table is, and its curvature is no uncertainty.
        const Range range = ConstantRange(constants[c]);
        const bool pinned = it->sd <= options.max_relative_sd * std::abs(it->value);
        it->at_bound = AtRangeBound(it->value, it->sd, pinned, range.lo, range.hi);
        it->identifiable = !it->at_bound && pinned;
        if (it->identifiable) {
          kept.push_back(constants[c]);
        } else {
          it->value = it->prior;
          out.params = WithConstants(out.params, {it->constant}, {it->prior});
        }
      }
      if (kept.size() == constants.size()) break;
      constants = kept;
      if (!constants.empty()) {
        stage(full, true, "whole shots, without the unidentifiable");
        final_strikes();
      }
    }
    out.constant_shots = static_cast<int>(problem.included.size());
    std::vector<std::size_t> rest;
    for (std::size_t i : all)
      if (is_held_out(i)) rest.push_back(i);
    phase_options = options;
    fit_strikes(fitted, true, "strikes, the final constants", full);
    fit_strikes(rest, false, "held-out strikes", full);
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

std::vector<SyntheticScene> SyntheticScenes(const table::TableGeometry& table, double ball_radius,
                                            int count, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double r = ball_radius;
  std::vector<SyntheticScene> scenes;
  while (static_cast<int>(scenes.size()) < count) {
    SyntheticScene scene;
    while (scene.starts.size() < 3) {
      const Eigen::Vector2d q(2 * r + unit(random) * (table.length - 4 * r),
                              2 * r + unit(random) * (table.width - 4 * r));
      bool clear = true;
      for (const Eigen::Vector2d& o : scene.starts) clear = clear && (q - o).norm() > 3 * r;
      if (clear) scene.starts.push_back(q);
    }
    Strike& s = scene.strike;
    s.stroke.speed = 2.0 + 2.0 * unit(random);
    s.stroke.heading = 2 * M_PI * unit(random);
    s.stroke.tip_side = (unit(random) - 0.5) * 0.8 * r;
    s.stroke.tip_height = (unit(random) - 0.5) * 0.8 * r;
    s.time = kSyntheticPeriod * unit(random);
    scenes.push_back(std::move(scene));
  }
  return scenes;
}

std::vector<TrackedShot> SyntheticShots(const table::TableGeometry& table,
                                        const ModelParameters& params, int count,
                                        std::uint64_t seed) {
  constexpr double kDuration = 8.0, kNoise = 0.001, kThinning = 0.002;
  std::vector<TrackedShot> shots;
  for (const SyntheticScene& scene : SyntheticScenes(table, params.ball.radius, count, seed)) {
    shots.push_back(SimulateTrackedShot(table, params, scene.starts, 0, scene.strike, kDuration,
                                        kSyntheticPeriod, kNoise, kThinning,
                                        seed + shots.size()));
    shots.back().id = std::to_string(shots.size());
  }
  return shots;
}

}  // namespace billiard::shot_fit
