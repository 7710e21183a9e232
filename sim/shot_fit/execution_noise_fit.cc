#include "sim/shot_fit/execution_noise_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "sim/physics/closed_form.h"
#include "sim/shot_fit/launch_spin.h"

namespace billiard::shot_fit {

namespace {

// Central-difference steps of the stroke's errors: a millionth of the speed, a microradian, a
// micrometre; the launch is smooth in each far beyond them.
constexpr double kFractionStep = 1e-6, kHeadingStep = 1e-6, kTipStep = 1e-6;
constexpr double kZ95 = 1.959963984540054;
constexpr double kPi = 3.14159265358979323846;
constexpr int kMaxRejectionRounds = 10;

// A spin the frames did not see weighs nothing: its variance is this per unit variance of a
// tracked coordinate [1/m^2] (at the floor of 1e-5 m, still 1e4 of log speed squared).
constexpr double kUnseen = 1e14;

double Wrapped(double angle) { return std::remainder(angle, 2.0 * kPi); }

// The residual's coordinates of a launch velocity and the velocity it rolls on: log speed,
// direction, log rolling speed, rolling direction.
Eigen::Vector4d Coordinates(const Eigen::Vector2d& v, const Eigen::Vector2d& rolling) {
  return {std::log(v.norm()), std::atan2(v.y(), v.x()), std::log(rolling.norm()),
          std::atan2(rolling.y(), rolling.x())};
}

// The directions' differences, wrapped.
Eigen::Vector4d WrappedDirections(Eigen::Vector4d d) {
  d[1] = Wrapped(d[1]);
  d[3] = Wrapped(d[3]);
  return d;
}

Eigen::Vector4d LaunchOf(const physics::CueStroke& stroke, const Eigen::Vector2d& start,
                         const physics::ModelParameters& p) {
  const physics::BallState launch = physics::StrikeBall(stroke, start, p);
  const physics::ClosedFormTrajectory path(physics::ClosedFormParameters::From(p), launch);
  return Coordinates(launch.segment<2>(physics::kVx),
                     path.slide_end_state().segment<2>(physics::kVx));
}

// The variance components of one shot: what each free spread's variance multiplies, and what is
// known.
struct Components {
  Eigen::Matrix4d g[3];  // speed fraction, heading, tip (side and height)
  Eigen::Matrix4d fixed;
  Eigen::Vector4d r;
  int style = 0;
};

Components ComponentsOf(const LaunchResidual& s, double position_variance,
                        const NoiseFitOptions& o) {
  Components c;
  const auto outer = [&](int k) { return s.jacobian.col(k) * s.jacobian.col(k).transpose(); };
  c.g[0] = outer(0);
  c.g[1] = outer(1);
  c.g[2] = outer(2) + outer(3);
  const double absolute = o.speed_absolute / s.cue_speed;
  c.fixed = position_variance * s.measurement + absolute * absolute * c.g[0];
  c.r = s.residual;
  c.style = s.style;
  return c;
}

// Fisher scoring for the variances theta of `free` components (the others held at theta's
// values), the biases by generalised least squares at each step.
struct Scoring {
  Eigen::Vector3d theta;
  std::map<int, Eigen::Vector4d> bias;  // by spin style
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
  int iterations = 0;
};

Eigen::Matrix4d CovarianceOf(const Components& c, const Eigen::Vector3d& theta) {
  return c.fixed + theta[0] * c.g[0] + theta[1] * c.g[1] + theta[2] * c.g[2];
}

// The bias of each spin style: the weighted mean of its residuals.
std::map<int, Eigen::Vector4d> Bias(const std::vector<Components>& shots,
                                    const Eigen::Vector3d& theta) {
  std::map<int, Eigen::Matrix4d> weight;
  std::map<int, Eigen::Vector4d> weighted;
  for (const Components& c : shots) {
    const Eigen::Matrix4d w = CovarianceOf(c, theta).inverse();
    weight.try_emplace(c.style, Eigen::Matrix4d::Zero()).first->second += w;
    weighted.try_emplace(c.style, Eigen::Vector4d::Zero()).first->second += w * c.r;
  }
  std::map<int, Eigen::Vector4d> bias;
  for (const auto& [style, w] : weight) bias[style] = w.ldlt().solve(weighted[style]);
  return bias;
}

// The sums over one spin style's shots that the restricted likelihood's correction needs: W =
// Sum V^-1, B_j = Sum V^-1 G_j V^-1 and D_jk = Sum V^-1 G_j V^-1 G_k V^-1.
struct StyleSums {
  Eigen::Matrix4d w = Eigen::Matrix4d::Zero();
  Eigen::Matrix4d b[3] = {Eigen::Matrix4d::Zero(), Eigen::Matrix4d::Zero(),
                          Eigen::Matrix4d::Zero()};
  Eigen::Matrix4d d[3][3];
  StyleSums() {
    for (auto& row : d) {
      for (Eigen::Matrix4d& m : row) m.setZero();
    }
  }
};

// (Sum V^-1)^-1 of a style, scaled to a unit diagonal before it is inverted: a coordinate no shot
// of the style saw weighs 1e-14 of the others, beyond what an unscaled inverse keeps.
Eigen::Matrix4d InverseOfWeight(const Eigen::Matrix4d& w) {
  const Eigen::Vector4d scale = w.diagonal().cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
  const Eigen::Matrix4d unit = scale.asDiagonal() * w * scale.asDiagonal();
  return scale.asDiagonal() * unit.ldlt().solve(Eigen::Matrix4d::Identity()) * scale.asDiagonal();
}

// The restricted likelihood's score and expected information (Patterson and Thompson 1971;
// Searle, Casella and McCulloch 1992, sec. 6.6): the Gaussian likelihood's with P = V^-1 -
// V^-1 X (X^T V^-1 X)^-1 X^T V^-1 in place of V^-1, X the per-style biases' design. The
// likelihood's own maximum takes the biases as known and so leaves their degrees of freedom in
// the variances, which come out low: with four styles of fifteen shots by about 7 % (3 % of a
// spread). Per style, with C = W^-1:
//   score_j       = 1/2 (e^T G_j e - Sum tr(V^-1 G_j) + tr(C B_j))
//   information_jk = 1/2 (Sum tr(V^-1 G_j V^-1 G_k) - tr(C D_jk) - tr(C D_kj) + tr(C B_j C B_k))
// e = V^-1 (r - mu), the generalised least squares residual, as in the likelihood's.
void Score(const std::vector<Components>& shots, int free, Scoring& s, Eigen::Vector3d* score) {
  score->setZero();
  s.information.setZero();
  std::map<int, StyleSums> sums;
  for (const Components& c : shots) {
    const Eigen::Matrix4d w = CovarianceOf(c, s.theta).inverse();
    const Eigen::Vector4d e = w * (c.r - s.bias.at(c.style));
    StyleSums& style = sums[c.style];
    style.w += w;
    for (int j = 0; j < free; ++j) {
      const Eigen::Matrix4d wg = w * c.g[j];
      (*score)[j] += 0.5 * (e.dot(c.g[j] * e) - wg.trace());
      style.b[j] += wg * w;
      for (int k = 0; k < free; ++k) {
        s.information(j, k) += 0.5 * (wg * w * c.g[k]).trace();
        style.d[j][k] += wg * w * c.g[k] * w;
      }
    }
  }
  for (const auto& [style, sum] : sums) {
    const Eigen::Matrix4d c = InverseOfWeight(sum.w);
    for (int j = 0; j < free; ++j) {
      (*score)[j] += 0.5 * (c * sum.b[j]).trace();
      for (int k = 0; k < free; ++k) {
        s.information(j, k) += 0.5 * ((c * sum.b[j] * c * sum.b[k]).trace() -
                                      (c * sum.d[j][k]).trace() - (c * sum.d[k][j]).trace());
      }
    }
  }
}

Scoring FisherScoring(const std::vector<Components>& shots, Eigen::Vector3d theta, int free,
                      const NoiseFitOptions& o) {
  Scoring s;
  s.theta = theta;
  for (; s.iterations < o.max_iterations; ++s.iterations) {
    s.bias = Bias(shots, s.theta);
    Eigen::Vector3d score;
    Score(shots, free, s, &score);
    const Eigen::VectorXd step =
        s.information.topLeftCorner(free, free).ldlt().solve(score.head(free));
    double change = 0.0;
    for (int j = 0; j < free; ++j) {
      const double next = std::max(0.0, s.theta[j] + step[j]);
      change = std::max(change, std::abs(next - s.theta[j]) / std::max(next, 1e-300));
      s.theta[j] = next;
    }
    if (change < o.tolerance) break;
  }
  s.bias = Bias(shots, s.theta);
  Eigen::Vector3d score;
  Score(shots, free, s, &score);
  return s;
}

// The spread of variance `theta` with standard error `sd_theta`.
Spread SpreadOf(double theta, double sd_theta) {
  Spread s;
  s.identified = true;
  s.value = std::sqrt(theta);
  if (theta > 0.0) {
    s.sd = sd_theta / (2.0 * s.value);
    const double factor = std::exp(kZ95 * s.sd / s.value);
    s.lower = s.value / factor;
    s.upper = s.value * factor;
  } else {
    s.sd = std::sqrt(sd_theta);
    s.upper = std::sqrt(kZ95 * sd_theta);
  }
  return s;
}

// The fit on `used`: the tip free, then held at its prior where it is not identified.
NoiseFit FitOn(const std::vector<Components>& all, const std::vector<std::size_t>& used,
               const NoiseFitOptions& o) {
  std::vector<Components> shots;
  for (std::size_t i : used) shots.push_back(all[i]);
  const Eigen::Vector3d start(o.speed_start * o.speed_start, o.heading_start * o.heading_start,
                              o.tip_prior * o.tip_prior);
  Scoring s = FisherScoring(shots, start, 3, o);
  Eigen::Matrix3d covariance = s.information.inverse();
  const double tip_relative_sd = std::sqrt(covariance(2, 2)) / (2.0 * s.theta[2]);
  const bool tip_identified = o.fit_tip && covariance.allFinite() && s.theta[2] > 0.0 &&
                              tip_relative_sd <= kIdentifiableRelativeSd;
  if (!tip_identified) {
    Eigen::Vector3d held = s.theta;
    held[2] = start[2];
    s = FisherScoring(shots, held, 2, o);
    covariance.setZero();
    covariance.topLeftCorner(2, 2) = s.information.topLeftCorner(2, 2).inverse();
  }
  NoiseFit fit;
  fit.speed = SpreadOf(s.theta[0], std::sqrt(covariance(0, 0)));
  fit.heading = SpreadOf(s.theta[1], std::sqrt(covariance(1, 1)));
  fit.tip = tip_identified ? SpreadOf(s.theta[2], std::sqrt(covariance(2, 2))) : Spread{};
  if (!tip_identified) fit.tip.value = fit.tip.lower = fit.tip.upper = o.tip_prior;
  fit.bias = s.bias;
  fit.used = used;
  fit.iterations = s.iterations;
  return fit;
}

}  // namespace

int StyleOf(const physics::CueStroke& commanded, const physics::ModelParameters& p) {
  return static_cast<int>(std::lround(kStylesPerUnitSpin * SpinRatioOf(commanded, p)));
}

LaunchResidual ResidualOf(const physics::CueStroke& commanded, const Eigen::Vector2d& start,
                          const MeasuredLaunch& launch, const physics::ModelParameters& p) {
  LaunchResidual out;
  out.cue_speed = commanded.speed;
  out.style = StyleOf(commanded, p);
  out.residual = WrappedDirections(Coordinates(launch.velocity, launch.rolling) -
                                   LaunchOf(commanded, start, p));
  const auto difference = [&](int k, double step) {
    physics::CueStroke up = commanded, down = commanded;
    double* up_field[] = {&up.speed, &up.heading, &up.tip_side, &up.tip_height};
    double* down_field[] = {&down.speed, &down.heading, &down.tip_side, &down.tip_height};
    const double h = k == 0 ? step * commanded.speed : step;  // a fraction of the speed
    *up_field[k] += h;
    *down_field[k] -= h;
    return Eigen::Vector4d(WrappedDirections(LaunchOf(up, start, p) - LaunchOf(down, start, p)) /
                    (2.0 * step));
  };
  const double steps[] = {kFractionStep, kHeadingStep, kTipStep, kTipStep};
  for (int k = 0; k < 4; ++k) out.jacobian.col(k) = difference(k, steps[k]);
  // The coordinates' derivatives with respect to (v, rolling).
  const Eigen::Vector2d v = launch.velocity, u = launch.rolling;
  Eigen::Matrix4d g = Eigen::Matrix4d::Zero();
  g.block<1, 2>(0, 0) = v.transpose() / v.squaredNorm();
  g.block<1, 2>(1, 0) = Eigen::Vector2d(-v.y(), v.x()).transpose() / v.squaredNorm();
  g.block<1, 2>(2, 2) = u.transpose() / u.squaredNorm();
  g.block<1, 2>(3, 2) = Eigen::Vector2d(-u.y(), u.x()).transpose() / u.squaredNorm();
  out.measurement = g * launch.joint_covariance * g.transpose() / launch.variance;
  out.squares = launch.squares;
  out.dof = launch.dof;
  const auto unseen = [&](int k) {
    out.measurement.row(k).setZero();
    out.measurement.col(k).setZero();
    out.measurement(k, k) = kUnseen;
  };
  // An unseen launch is the rolling velocity less the commanded slide's change: its
  // coordinates repeat the rolling ones and are left to them.
  if (!launch.launch_seen) {
    unseen(0);
    unseen(1);
  }
  if (!launch.rolling_seen) {
    unseen(2);
    unseen(3);
  }
  return out;
}

NoiseFit FitExecutionNoise(const std::vector<LaunchResidual>& shots, const NoiseFitOptions& o) {
  if (shots.size() < 3) {
    throw std::invalid_argument("the noise needs at least 3 shots, not " +
                                std::to_string(shots.size()));
  }
  double squares = 0.0, dof = 0.0;
  for (const LaunchResidual& s : shots) {
    squares += s.squares;
    dof += s.dof;
  }
  const double floor = o.position_sd_floor * o.position_sd_floor;
  const double variance = std::max(floor, dof > 0.0 ? squares / dof : floor);
  std::vector<Components> all;
  for (const LaunchResidual& s : shots) all.push_back(ComponentsOf(s, variance, o));
  std::vector<std::size_t> used(all.size());
  for (std::size_t i = 0; i < used.size(); ++i) used[i] = i;
  NoiseFit fit = FitOn(all, used, o);
  for (int round = 0; round < kMaxRejectionRounds; ++round) {
    const Eigen::Vector3d theta(fit.speed.value * fit.speed.value,
                                fit.heading.value * fit.heading.value,
                                fit.tip.value * fit.tip.value);
    std::vector<std::size_t> inliers;
    for (std::size_t i = 0; i < all.size(); ++i) {
      const Eigen::Vector4d e = all[i].r - fit.bias.at(all[i].style);
      if (e.dot(CovarianceOf(all[i], theta).ldlt().solve(e)) <= o.outlier_chi2) {
        inliers.push_back(i);
      }
    }
    if (inliers == fit.used || inliers.size() < 3) break;
    fit = FitOn(all, inliers, o);
  }
  fit.rejected = all.size() - fit.used.size();
  fit.position_sd = std::sqrt(variance);
  return fit;
}

}  // namespace billiard::shot_fit
