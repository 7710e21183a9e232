// The robot's execution noise measured on its own strokes: each commanded stroke held against
// the launch the tracks show (launch_fit.h), and over many shots the spreads of its speed,
// heading and tip offsets, with their uncertainty. What the shot choice should assume
// (sim/params/execution_noise.h) once the robot has played enough, instead of a guess in a file.
// Archibald and Nieves-Rivera (2019, "Bayesian execution skill estimation", AAAI workshop)
// estimate a computational billiards agent's noise from its executions the same way: what was
// intended against what was done.
//
// Per shot, the residual r = (log(|v| / |v_c|), angle(v) - angle(v_c), the same of the velocity
// it rolls on, v1 against v1_c): the measured launch v against the launch v_c the commanded
// stroke gives (cue_strike.h, squirt included), and after the slide (launch_spin.h). The stroke
// played is the commanded one with errors e = (speed fraction, heading, tip side, tip height),
// zero-mean normal and independent, so to first order
//
//     r = mu + J e + m,    Cov(r) = C = J diag(s_v^2, s_h^2, s_t^2, s_t^2) J^T + M + F,
//
// J the launch's derivatives with respect to e at the commanded stroke (central differences
// through StrikeBall), M the tracking's covariance of the residual (the launch fit's, mapped,
// with the tracks' error per coordinate pooled over every shot's fit: a few frames cannot
// estimate it alone, and a guess of it would be subtracted from the spreads as it stands),
// F what is held known (an absolute speed spread, the prior's), mu a constant bias per spin
// style (StyleOf: a robot's calibration, the tracking's lag, what the closed form leaves out of
// a long slide: not noise, reported apart). The variances theta =
// (s_v^2, s_h^2, s_t^2) are the maximum of the restricted (REML) Gaussian likelihood over the
// shots (Patterson and Thompson 1971), found by Fisher scoring on variance components (Searle,
// Casella and McCulloch 1992, "Variance Components", ch. 6; mu by generalised least squares at
// each step): the likelihood of the residuals' contrasts free of mu, so that the biases' degrees
// of freedom are not taken from the variances (the likelihood's own maximum leaves them in:
// with the loop's four styles about 3 % off each spread, with many styles of few shots far
// more), so the tracking's error is
// subtracted in variance and each shot weighs by how well it was seen. Their standard errors are
// the inverse Fisher information's; the intervals, 95 % on the log of the spread (positive,
// asymmetric), or [0, ...] for a spread at zero. Shots beyond the 99.9 % point of chi-square
// with 4 degrees of freedom at the estimate (a collision the cut missed, a lost track) are left
// out and the fit repeated. A coordinate the frames did not see (a slide shorter than two
// frames hides the launch, frames that end in the slide hide v1) weighs nothing.
//
// What the launch can tell:
//   - the heading: the launch's direction, to the tracking's fraction of a milliradian;
//   - the speed: the launch's speed, whose ratio to the cue's is TP A.30's (a centre hit's
//     does not depend on the tip offsets to first order);
//   - the tip offsets only through what they change of the launch: the side one squirts it
//     (TP A.31, about 0.12 rad per ball radius of offset: 0.8 mm turns it 0.2 degree, as much as
//     the heading's spread), the height one changes its speed where the stroke is off centre
//     (1 mm at 0.3 r above changes it by about 3 %). The squirt is the same for every shot, so
//     it cannot be told from the heading by the direction alone; the height's effect grows with
//     the commanded offset, so shots with spin tell the tip's spread from the speed's; above
//     all it changes the spin, which the velocity the ball rolls on shows (launch_spin.h: about
//     3 % of it for 0.8 mm, which no speed error changes), where strokes of different heights
//     are tracked past their slide (the loop's --spins). The squirt turns the rolling
//     direction by 5/7 of the launch's after a natural roll, by 5/3 of it after a draw, the
//     heading both alike: with the rolling direction the heading is told from the squirt. The one
//     tip spread (the noise model's, side and height alike) is therefore identified only where
//     the strokes' offsets vary enough: where its relative standard error exceeds
//     kIdentifiableRelativeSd it is held at the prior (NoiseFitOptions::tip_prior), reported so,
//     and the others fitted again with it known. The side spin a tip error gives shows only
//     after a cushion, which is not used here.
//   - the elevation's spread: not at all from a level stroke's launch (held known, F).
//
// Module: billiard::shot_fit.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <map>
#include <vector>

#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/shot_fit/launch_fit.h"

namespace billiard::shot_fit {

// One shot's residual, as the fit takes it.
struct LaunchResidual {
  // log speed ratio, direction [rad], log rolling-speed ratio, rolling direction [rad].
  Eigen::Vector4d residual = Eigen::Vector4d::Zero();
  // d residual / d (speed fraction, heading [rad], tip side [m], tip height [m]).
  Eigen::Matrix4d jacobian = Eigen::Matrix4d::Zero();
  // The tracking's covariance of the residual per unit variance of a tracked coordinate, and
  // the launch fit's residual sum of squares and degrees of freedom.
  Eigen::Matrix4d measurement = Eigen::Matrix4d::Zero();
  double squares = 0.0, dof = 0.0;
  double cue_speed = 0.0;                                 // commanded [m/s]
  int style = 0;  // StyleOf the commanded stroke: the strokes of one style share a bias
};

// The spin style of a stroke: its spin ratio (launch_spin.h) in steps of 1/kStylesPerUnitSpin
// (the loop's natural 2, follow 1, stun 0, draw -2). The closed form the launches are held
// against leaves out what the table's full model does during a long slide (its rolling
// resistance already at work: a stunned or drawn ball rolls on 3 to 5 % slower than the closed
// form says, a naturally rolled one 1 %), the same for every stroke of a style: a bias per style,
// not noise.
inline constexpr double kStylesPerUnitSpin = 2.0;
int StyleOf(const physics::CueStroke& commanded, const physics::ModelParameters& p);

// The residual of `launch` against `commanded`, struck at `start` with `p`'s cue model.
LaunchResidual ResidualOf(const physics::CueStroke& commanded, const Eigen::Vector2d& start,
                          const MeasuredLaunch& launch, const physics::ModelParameters& p);

// A spread and its uncertainty, in the residuals' units (a fraction, radians, metres).
struct Spread {
  double value = 0.0;
  double sd = 0.0;  // standard error
  double lower = 0.0, upper = 0.0;  // 95 % interval
  bool identified = false;  // false: held at the prior (value), sd 0
};

// A tip spread whose relative standard error exceeds this is held at its prior.
inline constexpr double kIdentifiableRelativeSd = 0.5;

struct NoiseFitOptions {
  double tip_prior = 0.5e-3;          // [m], held where not identified
  // The tracks' error per coordinate is pooled over the shots' launch fits (their residual sums
  // of squares over their degrees of freedom), at least this [m].
  double position_sd_floor = 1e-5;
  bool fit_tip = true;                // false: the tip's spread held at tip_prior, not fitted
  double speed_absolute = 0.0;        // a known absolute cue-speed spread [m/s]
  double outlier_chi2 = 18.47;        // chi-square(4) at 99.9 %
  int max_iterations = 200;
  double tolerance = 1e-10;           // on the variances' change, relative
  // Starting spreads (the prior's): the likelihood has one maximum in practice, but a start in
  // the right decade saves iterations.
  double speed_start = 0.01, heading_start = 1.7e-3;
};

struct NoiseFit {
  Spread speed;    // fraction of the cue speed
  Spread heading;  // [rad]
  Spread tip;      // each tip offset [m]
  std::map<int, Eigen::Vector4d> bias;  // mu by StyleOf, in the residual's coordinates
  std::vector<std::size_t> used;                   // indices of the residuals fitted
  std::size_t rejected = 0;                        // left out as outliers
  double position_sd = 0.0;  // the tracks' error per coordinate, pooled over the shots [m]
  int iterations = 0;
};

// The spreads of `shots` (at least 3; throws std::invalid_argument with fewer).
NoiseFit FitExecutionNoise(const std::vector<LaunchResidual>& shots,
                           const NoiseFitOptions& options = {});

}  // namespace billiard::shot_fit
