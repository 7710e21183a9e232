// The cue ball's launch as an overhead camera's tracks show it: its velocity right after the
// strike, from the frames of a tracked shot before the ball meets anything, with the
// covariance the tracking leaves on it. What the robot's stroke actually did, to hold against
// what it was commanded to do (execution_noise_fit.h).
//
// Model: the closed-form slide and roll of Jaroukh 2019 (sim/physics/closed_form.h). Struck at
// an unknown time t_s between the last frame that shows the ball at rest and the first that
// shows it moving, the ball slides with a constant acceleration a (mu_s g along its slip) for
// the slide time T, then rolls, slowed by 5/7 mu_r g along its path:
//
//     p(t) = p0 + v tau + a tau^2 / 2                                      tau = t - t_s <= T
//     p(t) = p0 + v T + a T^2 / 2 + (v + a T)(tau - T) - 5/7 mu_r g (tau - T)^2 d / 2   tau > T
//
// p0 is the ball's position at rest (fitted too, the samples before the strike its data: one
// sample's error turns the launch's line about it), T and the rolling direction d at first the
// commanded stroke's (cue_strike.h, then closed_form.h); v and a are free, so that the launch
// velocity is the tracks' and the spin actually given shows in a T = v_roll - v (the speed the ball
// rolls on). Given t_s the model is linear in (v, a): least squares; t_s is the golden-section
// least of the residual sum of squares. Where frames run past the slide, the stroke played, not the
// commanded one, sets T and d: T is the duration for which the fitted slide decelerates at mu_s g
// (a golden-section search within 1.25 times the commanded one), d the fitted rolling
// velocity's direction, both taken again until d settles. The robot's error moves them little, but
// the rolling frames weigh: over a long roll the resistance along a line off by the heading's error
// bends the path by that error times the distance the ball slows (0.3 degree over a 5 s roll: 4
// mm), and the rolling frames extrapolated to a slide's end placed wrong bend a draw's launch. When
// the slide is shorter than two frames, a is the commanded stroke's (mu_s g along its slip), since
// frames that straddle one slide sample or none cannot tell it from v: the launch is not seen, only
// the rolling velocity. When the frames end inside the slide, the rolling velocity is not seen: the
// slide's acceleration is mu_s g whatever the spin, which sets only how long it lasts.
//
// Samples are used from the strike for as long as the model holds: while the ball is clear of every
// other ball's start (2 r + clearance) and of the cushions (r + clearance from the playing
// surface's edges), and so is the commanded stroke's path 15 % faster up to the sample's time (a
// ball that met a cushion between two frames can be back inside at the second), and it has not come
// near rest (the commanded stroke's stop time): a collision, a cushion or a stop would break the
// model. The whole of that stretch: a lone ball's roll of seconds fixes its line and speed far
// better than its first tenths (the loop's noise identified over twelve seeds: the tip's and the
// speed's errors halved against the first 0.3 s, docs/identification.md, "The whole roll"). Frames
// near the slide's end are left out unless three frames follow 1.25 times the commanded slide (the
// played one ends within that). The launch's covariance is the Gauss-Newton one over (t_s, v, a),
// s^2 (J^T J)^-1, with s the residuals' RMS or `position_sd`, whichever is larger: the tracks'
// error per coordinate, which a fit of a few frames cannot estimate alone. Filtered tracks (the
// estimator's) share their error between neighbouring frames, which this covariance does not know;
// docs/identification.md says what that does to the noise measured.
//
// Module: billiard::shot_fit.
#pragma once

#include <Eigen/Core>
#include <string>

#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/shot_fit/tracked_shot.h"

namespace billiard::shot_fit {

struct LaunchFitOptions {
  double position_sd = 5e-4;  // the tracks' error per coordinate, at least [m]
  double clearance = 3e-3;    // from other balls and the cushions' lines [m]
  int min_samples = 3;        // moving samples needed (two equations each; seven unknowns)
};

struct MeasuredLaunch {
  bool ok = false;
  std::string reason;  // why not, when !ok
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();      // right after the strike [m/s]
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();    // of velocity [m^2/s^2]
  Eigen::Vector2d rolling = Eigen::Vector2d::Zero();       // v + a T: the velocity it rolls on
  // Whether the frames saw the launch (the slide lasts more than two frames, a fitted: otherwise
  // velocity is the rolling one less the commanded slide's change) and the velocity it rolls
  // on (frames past the slide's end: otherwise rolling says nothing of the spin the stroke
  // gave, the slide's acceleration being mu_s g whatever the spin).
  bool launch_seen = false, rolling_seen = false;
  Eigen::Matrix4d joint_covariance = Eigen::Matrix4d::Zero();  // of (velocity, rolling)
  double strike_time = 0.0;  // t_s on the shot's clock [s]
  int samples = 0;           // moving samples fitted
  double rms = 0.0;          // of the fit's residuals [m]
  // The fit's residual sum of squares [m^2] and its degrees of freedom, and the variance per
  // coordinate the covariances assumed: a fit over many shots pools the first two into the
  // tracks' error (execution_noise_fit.h).
  double squares = 0.0, dof = 0.0, variance = 0.0;
};

// The launch of `shot`'s struck ball (shot.cue), which `commanded` was meant to give, on a table
// of `p`'s size and physics. Not ok, with the reason, when fewer than min_samples samples are
// left before the first collision, cushion or stop, or the ball never moves.
MeasuredLaunch FitLaunch(const TrackedShot& shot, const physics::CueStroke& commanded,
                         const physics::ModelParameters& p, const LaunchFitOptions& options = {});

}  // namespace billiard::shot_fit
