#include "sim/shot_fit/joint_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/shot_fit/correlation_time.h"
#include "sim/shot_fit/shot_model.h"

namespace billiard::shot_fit {

namespace {

// Cauchy's loss of each shot's RMSE (SolveJoint), c^2 the median mean squared error of the
// shots where the solve starts.
class CauchyLoss {
 public:
  CauchyLoss(const JointProblem& problem, const JointProblem::Evaluations& start) {
    std::vector<double> mse;
    for (std::size_t j = 0; j < start.size(); ++j) {
      samples_.push_back(problem.Samples(j));
      mse.push_back(start[j].first / samples_[j]);
    }
    c2_ = std::max(Median(mse), 1e-12);
  }

  // The robust cost of the shots' sums of squares `e`: sum_j n_j c^2 log(1 + e_j / c^2).
  double operator()(const JointProblem::Evaluations& e) const {
    double sum = 0.0;
    for (std::size_t j = 0; j < e.size(); ++j)
      sum += samples_[j] * c2_ * std::log1p(e[j].first / samples_[j] / c2_);
    return sum;
  }

  // Shot j's blocks weighted as the iteratively reweighted loss weighs them at its sum of
  // squares `squares`.
  void Weigh(std::size_t j, double squares, ShotBlocks* blocks) const {
    const double w = 1.0 / (1.0 + squares / samples_[j] / c2_);
    for (Eigen::MatrixXd* m : {&blocks->ss, &blocks->sc, &blocks->cc}) *m *= w;
    blocks->gs *= w;
    blocks->gc *= w;
  }

 private:
  std::vector<double> samples_;  // per included shot
  double c2_ = 0.0;
};

// The bounds of each included shot's strike vector.
std::vector<StrikeBounds> IncludedBounds(const JointProblem& problem) {
  std::vector<StrikeBounds> bounds;
  for (std::size_t s : problem.included) {
    const auto [lo, hi] = ImpactRange(problem.shots[s]);
    bounds.push_back(
        BoundsOf(Layout(problem.options, problem.base.ball.radius, problem.shots[s]), lo, hi));
  }
  return bounds;
}

// A point of the joint problem: each included shot's strike vector, and the constants' values.
struct JointPoint {
  std::vector<std::vector<double>> strikes;
  std::vector<double> values;
};

// The Levenberg-Marquardt step from `from` at damping `lambda`: the reduced system solved for
// the constants, each strike's step back-substituted, each clamped to its range.
JointPoint Step(const JointProblem& problem, const std::vector<ShotBlocks>& blocks, double lambda,
                const std::vector<StrikeBounds>& bounds, const JointPoint& from) {
  const std::size_t k = from.values.size();
  const Reduced reduced = Reduce(blocks, k, lambda);
  const Eigen::VectorXd dc = -reduced.s.ldlt().solve(reduced.g);
  JointPoint to = from;
  for (std::size_t c = 0; c < k; ++c) {
    const Range range = ConstantRange(problem.constants[c]);
    to.values[c] = std::clamp(to.values[c] + dc[c], range.lo, range.hi);
  }
  for (std::size_t j = 0; j < blocks.size(); ++j) {
    const Eigen::VectorXd ds = -reduced.a_inv[j] * (blocks[j].gs + blocks[j].sc * dc);
    for (std::size_t c = 0; c < to.strikes[j].size(); ++c)
      to.strikes[j][c] = std::clamp(to.strikes[j][c] + ds[c], bounds[j].lo[c], bounds[j].hi[c]);
  }
  return to;
}

}  // namespace

ShotBlocks BlocksOf(const Eigen::MatrixXd& j, std::size_t n, const std::vector<double>& residuals) {
  const int m = static_cast<int>(residuals.size());
  const std::size_t k = static_cast<std::size_t>(j.cols()) - n;
  const Eigen::Map<const Eigen::VectorXd> r(residuals.data(), m);
  const auto js = j.leftCols(n), jc = j.rightCols(k);
  ShotBlocks b;
  b.ss = js.transpose() * js;
  b.sc = js.transpose() * jc;
  b.cc = jc.transpose() * jc;
  b.gs = js.transpose() * r;
  b.gc = jc.transpose() * r;
  b.squares = r.squaredNorm();
  b.residuals = m;
  return b;
}

double JointProblem::Evaluation::Squares() const {
  if (r.empty()) return std::numeric_limits<double>::infinity();
  double sum = 0.0;
  for (double v : r) sum += v * v;
  return sum;
}

JointProblem::Evaluation JointProblem::Evaluate(std::size_t s, const std::vector<double>& strike,
                                                const std::vector<double>& values) const {
  const physics::ModelParameters p = WithConstants(base, constants, values);
  Evaluation e;
  e.r = ShotModel(table, p, shots[s])
            .Residuals(FromVector(strike.data(), Layout(options, p.ball.radius, shots[s])), horizon,
                       &e.impacts);
  return e;
}

Eigen::MatrixXd JointProblem::Jacobian(std::size_t s, const std::vector<double>& strike,
                                       const std::vector<double>& values,
                                       const Evaluation& e0) const {
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
  return j;
}

ShotBlocks JointProblem::Linearize(std::size_t s, const std::vector<double>& strike,
                                   const std::vector<double>& values) const {
  const Evaluation e0 = Evaluate(s, strike, values);
  if (e0.r.empty()) throw std::runtime_error("shot " + shots[s].id + " does not simulate");
  ShotBlocks b = BlocksOf(Jacobian(s, strike, values, e0), strike.size(), e0.r);
  b.lagged = LaggedProducts(shots[s], horizon, e0.r);
  return b;
}

std::vector<ShotBlocks> JointProblem::LinearizeAll(const std::vector<std::vector<double>>& strikes,
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

JointProblem::Evaluations JointProblem::EvaluateAll(const std::vector<std::vector<double>>& strikes,
                                                    const std::vector<double>& values) const {
  auto results = pool.Map(included.size(), [&](std::size_t job) {
    const Evaluation e = Evaluate(included[job], strikes[job], values);
    return std::make_pair(e.Squares(), e.impacts);
  });
  Evaluations out;
  for (const auto& result : results)
    out.push_back(result.ok()
                      ? *result.value
                      : std::make_pair(std::numeric_limits<double>::infinity(), std::uint64_t{0}));
  return out;
}

int JointProblem::Samples(std::size_t j) const {
  return std::max(1, ShotModel(table, base, shots[included[j]]).ResidualCount(horizon) / 2);
}

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

void SolveJoint(const JointProblem& problem, const FitOptions& options,
                std::vector<std::vector<double>>* strikes, std::vector<double>* values) {
  const std::vector<StrikeBounds> bounds = IncludedBounds(problem);
  JointProblem::Evaluations current = problem.EvaluateAll(*strikes, *values);
  const CauchyLoss loss(problem, current);
  double lambda = 1e-3;
  constexpr double kMaxLambda = 1e8;
  constexpr double kRelativeDecrease = 1e-7;
  for (int iteration = 0; iteration < options.max_iterations && lambda < kMaxLambda; ++iteration) {
    std::vector<ShotBlocks> blocks = problem.LinearizeAll(*strikes, *values);
    for (std::size_t j = 0; j < blocks.size(); ++j) loss.Weigh(j, current[j].first, &blocks[j]);
    bool accepted = false;
    while (!accepted && lambda < kMaxLambda) {
      JointPoint next = Step(problem, blocks, lambda, bounds, {*strikes, *values});
      const JointProblem::Evaluations trial = problem.EvaluateAll(next.strikes, next.values);
      // A step is judged on every shot: one that jumps to another piece of the cost (a
      // collision made or missed) counts with the rest, else the fit could walk a shot into a
      // worse shot step by step. (Where a shot does not simulate, the sum is infinite.)
      const double before = loss(current), after = loss(trial);
      if (after < before) {
        accepted = true;
        const bool converged = before - after < kRelativeDecrease * before;
        current = trial;
        *strikes = std::move(next.strikes);
        *values = std::move(next.values);
        lambda = std::max(lambda / 3.0, 1e-9);
        if (converged) return;
      } else {
        lambda *= 4.0;
      }
    }
  }
}

std::vector<std::size_t> Inliers(const JointProblem& problem,
                                 const std::vector<std::vector<double>>& strikes,
                                 const std::vector<double>& values, double outlier_factor) {
  const JointProblem::Evaluations evaluations = problem.EvaluateAll(strikes, values);
  std::vector<double> rmse;
  for (std::size_t j = 0; j < evaluations.size(); ++j)
    rmse.push_back(std::sqrt(evaluations[j].first / problem.Samples(j)));
  const double limit = outlier_factor * Median(rmse);
  std::vector<std::size_t> kept;
  for (std::size_t j = 0; j < rmse.size(); ++j)
    if (rmse[j] <= limit) kept.push_back(problem.included[j]);
  return kept;
}

double Median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace billiard::shot_fit
