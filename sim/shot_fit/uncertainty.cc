#include "sim/shot_fit/uncertainty.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/shot_fit/correlation_time.h"

namespace billiard::shot_fit {

namespace {

// How near a bound of its Range a fitted constant sits at it (AtRangeBound).
constexpr double kAtBound = 1e-6, kAtBoundSds = 3.0;

// The shots' LaggedProducts summed, in shot order.
std::vector<double> PooledLaggedProducts(const std::vector<ShotBlocks>& blocks) {
  std::vector<double> lagged(kMaxLag + 1, 0.0);
  for (const ShotBlocks& b : blocks)
    for (std::size_t k = 0; k < b.lagged.size(); ++k) lagged[k] += b.lagged[k];
  return lagged;
}

}  // namespace

bool AtRangeBound(double value, double sd, bool pinned, double lo, double hi) {
  const double margin = pinned ? kAtBoundSds * sd : 0.0;
  return value <= std::max(lo * (1.0 + kAtBound), lo + margin) ||
         value >= std::min(hi * (1.0 - kAtBound), hi - margin);
}

Eigen::MatrixXd ConstantsCovariance(const std::vector<ShotBlocks>& blocks, std::size_t k,
                                    double* correlation_time) {
  const Reduced reduced = Reduce(blocks, k, 0.0);
  double squares = 0.0;
  int dof = -static_cast<int>(k);
  for (const ShotBlocks& b : blocks) {
    squares += b.squares;
    dof += b.residuals - static_cast<int>(b.ss.rows());
  }
  *correlation_time = CorrelationTime(PooledLaggedProducts(blocks));
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

void JudgeIdentifiable(double value, double variance, double max_relative_sd, ConstantFit* fit) {
  fit->value = value;
  fit->sd = std::sqrt(variance);
  // A fit that ran to the edge of its range found no minimum there: what the shots say lies
  // beyond what any table is, and its curvature is no uncertainty.
  const Range range = ConstantRange(fit->constant);
  const bool pinned = fit->sd <= max_relative_sd * std::abs(fit->value);
  fit->at_bound = AtRangeBound(fit->value, fit->sd, pinned, range.lo, range.hi);
  fit->identifiable = !fit->at_bound && pinned;
  if (!fit->identifiable) fit->value = fit->prior;
}

std::vector<std::pair<std::string, double>> SetUncertainty(const std::vector<ConstantFit>& constants,
                                                           const physics::ModelParameters& fitted) {
  std::vector<std::pair<std::string, double>> sd;
  for (const ConstantFit& c : constants) {
    if (!c.identifiable || !std::isfinite(c.sd)) continue;
    switch (c.constant) {
      case Constant::kMu: sd.emplace_back("contact.mu", c.sd); break;
      case Constant::kSpin: sd.emplace_back("contact.patch_radius", c.sd); break;
      case Constant::kRolling:
        sd.emplace_back("contact.d", c.sd * 5 * fitted.ball.radius / fitted.contact.patch_radius);
        break;
      case Constant::kCushion: sd.emplace_back("collision.cushion_restitution", c.sd); break;
      case Constant::kCushionFriction: sd.emplace_back("collision.cushion_friction", c.sd); break;
      case Constant::kBallBall: sd.emplace_back("collision.ball_restitution", c.sd); break;
    }
  }
  return sd;
}

}  // namespace billiard::shot_fit
