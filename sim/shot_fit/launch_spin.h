// The topspin or draw a stroke gave the cue ball, read from its track: what the tip's height
// did, held against what the commanded height should have done. The noise fit
// (execution_noise_fit.h) identifies the tip's spread from it; this is the relation it rests on,
// said once and checked against the slide's closed form.
//
// A ball struck on its line slides until its contact point stops slipping. The friction acts at
// the contact point, so the angular momentum about that point is kept through the slide
// (Coriolis 1835; Alciatore 2004, "the 5/7 rule" of a stun shot; Jaroukh 2019's closed form,
// sim/physics/closed_form.h). With I = 2/5 m R^2 that gives the velocity it rolls on,
//
//     v1 = 5/7 v0 + 2/7 s0,    s0 = R (wy, -wx),
//
// s0 the spin's velocity at the launch (s0 = v0 rolling, 0 stunned, against v0 drawn). So the
// launch v0 and the rolling velocity v1 that the launch fit measures (launch_fit.h) give the
// spin, s0 = (7 v1 - 5 v0) / 2, and its ratio to the launch along the line,
//
//     q = s0 . v0 / |v0|^2 = 7/2 (v1 . v0) / |v0|^2 - 5/2,
//
// 1 for a rolling ball, 0 stunned, negative drawn: the planner's SpinRatio (R w / v). A tip
// height error of dh turns q by about 5/2 dh / R (cue_strike.h), 0.09 for a millimetre, while a
// speed error leaves q as it is: the spin tells the tip's height from the stroke's speed.
//
// Module: billiard::shot_fit.
#pragma once

#include <Eigen/Core>

#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/shot_fit/launch_fit.h"

namespace billiard::shot_fit {

struct LaunchSpin {
  bool seen = false;  // both the launch and the velocity it rolls on were seen
  Eigen::Vector2d spin_velocity = Eigen::Vector2d::Zero();  // s0 = R (wy, -wx) [m/s]
  double ratio = 0.0;     // q = s0 . v0 / |v0|^2
  double ratio_sd = 0.0;  // its standard error, from the launch fit's covariance
};

// The velocity the ball rolls on after sliding from launch velocity `v0` with spin velocity
// `s0`: 5/7 v0 + 2/7 s0.
Eigen::Vector2d RollingVelocity(const Eigen::Vector2d& v0, const Eigen::Vector2d& s0);

// The spin `launch` shows; not seen (and zero) unless the frames saw both its launch and the
// velocity it rolls on.
LaunchSpin SpinOf(const MeasuredLaunch& launch);

// The spin ratio q the stroke `stroke` gives (StrikeBall, squirt included), at `p`'s cue model.
double SpinRatioOf(const physics::CueStroke& stroke, const physics::ModelParameters& p);

}  // namespace billiard::shot_fit
