#include "sim/shot_fit/strike_fit.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

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
// The first stage's grid around the launch the samples show, and how many of its best points
// go on to the refinement. Wide in heading and speed: where the cue ball meets a ball within the
// first frames, the samples show it after that collision.
constexpr double kSpeedFactors[] = {0.8, 1.0, 1.25, 1.6};
constexpr double kHeadingOffsets[] = {0.0, -0.04, 0.04, -0.12, 0.12, -0.3, 0.3};  // [rad]
constexpr double kTipGrid[] = {-0.4, -0.2, 0.0, 0.2, 0.4};
constexpr int kStarts = 6;
// How many samples after the first one give the launch velocity (50 Hz: 0.06 s).
constexpr int kLaunchSamples = 3;

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

// Step 2: the grid around the launch the samples show (LaunchGuess), scored over `horizon`; its
// kStarts best points, best first (ties in the grid's order).
std::vector<std::vector<double>> GridStarts(const ShotModel& model, const FitOptions& options,
                                            const Layout& layout, double horizon) {
  const ModelParameters& params = model.params();
  const double r = params.ball.radius;
  const TrackedBall& cue = model.shot().balls.at(model.shot().cue);
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
          scored.emplace_back(model.Cost(s, horizon), x);
        }
      }
    }
  }
  std::stable_sort(scored.begin(), scored.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  scored.resize(std::min<std::size_t>(kStarts, scored.size()));
  std::vector<std::vector<double>> starts;
  for (auto& start : scored) starts.push_back(std::move(start.second));
  return starts;
}

// Step 3: the best of the starts refined, each through the continuation's horizons up to
// `horizon` when `continuation`, then over `horizon` itself.
class BestStrike {
 public:
  BestStrike(const ShotModel& model, const FitOptions& options, double horizon)
      : model_(model), options_(options), horizon_(horizon) {
    std::tie(impact_lo_, impact_hi_) = ImpactRange(model.shot());
  }

  void Consider(std::vector<double> x, bool continuation) {
    if (continuation) {
      for (double h : kHorizons) {
        if (h >= std::min(horizon_, model_.shot().Duration())) break;
        RefineStrike(model_, h, options_, impact_lo_, impact_hi_, &x);
      }
    }
    const double c = RefineStrike(model_, horizon_, options_, impact_lo_, impact_hi_, &x);
    if (c < best_cost_) {
      best_cost_ = c;
      best_ = x;
    }
  }

  // The previous strike, its impact moved into the shot's range.
  void ConsiderPrevious(const Strike& previous, const Layout& layout) {
    std::vector<double> x = ToVector(previous, layout);
    x[4] = std::clamp(x[4], impact_lo_, impact_hi_);
    Consider(x, false);
  }

  const std::vector<double>& best() const { return best_; }

 private:
  const ShotModel& model_;
  const FitOptions& options_;
  double horizon_;
  double impact_lo_ = 0.0, impact_hi_ = 0.0;
  double best_cost_ = std::numeric_limits<double>::infinity();
  std::vector<double> best_;
};

// `fit` with `strike` and its errors over the whole shot.
void SetStrike(const ShotModel& model, const Strike& strike, ShotFit* fit) {
  fit->strike = strike;
  fit->errors = ErrorsOf(model, fit->strike);
  fit->rmse_cue = fit->errors.rmse[model.shot().cue];
}

}  // namespace

Layout::Layout(const FitOptions& options, double r, const TrackedShot& shot)
    : elevation(options.fit_elevation), radius(r) {
  for (std::size_t i = 0; i < shot.balls.size(); ++i)
    if (i == shot.cue ? options.fit_cue_start : options.fit_start) offset_balls.push_back(i);
}

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

std::vector<double> DifferenceSteps(const Layout& layout, const std::vector<double>& x) {
  std::vector<double> h = {1e-4 * x[0], 1e-5, 1e-4, 1e-4, 1e-5};  // [m/s], rad, -, -, s
  if (layout.elevation) h.push_back(1e-4);                        // [rad]
  h.resize(layout.size(), 1e-5);                                  // start offsets [m]
  return h;
}

StrikeBounds BoundsOf(const Layout& layout, double impact_lo, double impact_hi) {
  StrikeBounds b{
      {0.01, -std::numeric_limits<double>::infinity(), -kTipLimit, -kTipLimit, impact_lo},
      {kMaxCueSpeed, std::numeric_limits<double>::infinity(), kTipLimit, kTipLimit, impact_hi}};
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

std::pair<double, double> ImpactRange(const TrackedShot& shot) {
  const TrackedBall& cue = shot.balls.at(shot.cue);
  if (cue.t.size() < 2) return {0.0, 0.0};
  return {cue.t[0] - (cue.t[1] - cue.t[0]), cue.t[1]};
}

ShotFit FitStrikeUpTo(const table::TableGeometry& table, const ModelParameters& params,
                      const TrackedShot& shot, const FitOptions& options,
                      const std::optional<Strike>& previous, double horizon) {
  const ShotModel model(table, params, shot);
  const Layout layout(options, params.ball.radius, shot);
  ShotFit fit;
  fit.id = shot.id;
  if (shot.balls.at(shot.cue).t.size() < 3) {  // a cue ball that never moves: the strike is none
    SetStrike(model, Strike{}, &fit);
    return fit;
  }
  const double first_horizon = std::min({kHorizons[0], horizon, shot.Duration()});
  BestStrike best(model, options, horizon);
  for (std::vector<double>& start : GridStarts(model, options, layout, first_horizon))
    best.Consider(std::move(start), true);
  if (previous) best.ConsiderPrevious(*previous, layout);
  if (best.best().empty()) throw std::invalid_argument("shot " + shot.id + ": no strike simulates");
  SetStrike(model, FromVector(best.best().data(), layout), &fit);
  return fit;
}

ShotFit FitStrike(const table::TableGeometry& table, const ModelParameters& params,
                  const TrackedShot& shot, const FitOptions& options,
                  const std::optional<Strike>& previous) {
  return FitStrikeUpTo(table, params, shot, options, previous);
}

}  // namespace billiard::shot_fit
