#include "sim/shot_fit/shot_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace billiard::shot_fit {

namespace {

// A scene that needs more events is no shot the fit should follow (a numerical pathology).
constexpr std::int64_t kMaxEvents = 20000;

std::vector<Eigen::Vector2d> FirstSeen(const TrackedShot& shot) {
  std::vector<Eigen::Vector2d> p;
  for (const TrackedBall& b : shot.balls) p.push_back(b.position.front());
  return p;
}

}  // namespace

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

ShotModel::ShotModel(const table::TableGeometry& table, const physics::ModelParameters& params,
                     const TrackedShot& shot)
    : table_(table), params_(params), shot_(shot), start_(FirstSeen(shot)) {}

int ShotModel::ResidualCount(double horizon) const {
  int n = 0;
  for (const TrackedBall& b : shot_.balls)
    for (double t : b.t) n += t <= horizon ? 2 : 0;
  return n;
}

bool ShotModel::Residuals(const Strike& strike, double horizon, double* out,
                          std::uint64_t* impacts) const {
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

std::vector<double> ShotModel::Residuals(const Strike& strike, double horizon,
                                         std::uint64_t* impacts) const {
  std::vector<double> r(ResidualCount(horizon));
  if (!Residuals(strike, horizon, r.data(), impacts)) return {};
  return r;
}

double ShotModel::Cost(const Strike& strike, double horizon) const {
  const std::vector<double> r = Residuals(strike, horizon);
  if (r.empty() && ResidualCount(horizon) > 0) return std::numeric_limits<double>::infinity();
  double c = 0.0;
  for (double v : r) c += v * v;
  return 0.5 * c;
}

table::TableSimulation ShotModel::Run(const Strike& strike, double until) const {
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
      b = table::Struck(b.id, strike.stroke, where[i], params_);
    balls.push_back(b);
  }
  table::TableSimulationOptions options;
  options.max_events = kMaxEvents;
  options.cushion_model = kCushionModel;
  table::TableSimulation sim(table_, params_, balls, options);
  sim.Run(std::max(0.0, until - strike.time));
  return sim;
}

ShotErrors ErrorsOf(const ShotModel& model, const Strike& strike) {
  const TrackedShot& shot = model.shot();
  const std::vector<double> r = model.Residuals(strike, std::numeric_limits<double>::infinity());
  if (r.empty())
    throw std::invalid_argument("shot " + shot.id + ": the strike cannot be simulated");
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

ShotErrors Errors(const table::TableGeometry& table, const physics::ModelParameters& params,
                  const TrackedShot& shot, const Strike& strike) {
  return ErrorsOf(ShotModel(table, params, shot), strike);
}

table::TableSimulation SimulateShot(const table::TableGeometry& table,
                                    const physics::ModelParameters& params, const TrackedShot& shot,
                                    const Strike& strike) {
  return ShotModel(table, params, shot).Run(strike, shot.Duration());
}

}  // namespace billiard::shot_fit
