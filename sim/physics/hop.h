// A ball off the cloth: the hop an elevated cue gives it, its flight and its landings.
//
// An elevated cue drives the ball down into the bed (cue_strike.h: along the cue's axis the
// impulse has a part tan(elevation) of its horizontal part pointing down, v_down for a launch v
// along the heading). The bed gives back e_b of it: the ball leaves the cloth at e_b v_down and
// flies. In the air its centre moves straight at constant velocity and its spin keeps (no
// cloth; air drag neglected: with a drag coefficient of 0.5 it takes 0.1 % of a 2 m/s ball's
// speed over a 0.1 s hop); its height is a parabola under g. It lands at the speed it left with
// (from the bed), v_z, and the bed's normal impulse m (1 + e_b) v_z sends it off again at e_b v_z,
// with Coulomb friction mu against the contact point's slip u = v + r z x w during the impact:
// an impulse F = min(mu m (1 + e_b) v_z, 2/7 m |u|) along -u, which changes u by 7/2 F / m and so
// never more than stops it (a solid ball, I = 2/5 m r^2; the cloth's sliding friction, as the
// table's in the cushion impact of Mathavan et al. 2010). Heights fall by e_b^2 a bounce:
// below kSettledHop the ball is taken as on the cloth (what is left of the bounces, e_b / (1 -
// e_b) of that hop's flight, 9 ms at 0.1 mm, lasts less than a tenth of the slide of a 0.3 m/s
// ball).
//
// The bed's restitution e_b, a slate under a cloth, is an assumption of about a half (the cloth
// takes much of a ball's downward speed; not measured here). Strike and bed: the strike's own
// impact with the bed is taken as frictionless (cue_strike.h), the landings' are not.
//
// Module: billiard::physics.
#pragma once

#include "sim/physics/ball_state.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"

namespace billiard::physics {

// e_b, the slate bed's restitution under the cloth (an assumption, see above).
inline constexpr double kBedRestitution = 0.5;
// A bounce lower than this [m] is the ball on the cloth.
inline constexpr double kSettledHop = 1e-4;

// The centre's height above its place on the cloth [m] and its vertical speed (up > 0) [m/s].
struct Flight {
  double height = 0.0;
  double vertical_speed = 0.0;
};

// Whether `flight` rises (or is) more than kSettledHop above the cloth at its apex: a lower one
// is the ball on the cloth.
bool Airborne(const Flight& flight, double gravity);
// The highest the centre rises above the cloth in `flight` [m].
double Apex(const Flight& flight, double gravity);
// How long until `flight` meets the cloth again [s] (0 for a ball on it).
double TimeToLand(const Flight& flight, double gravity);
// `flight` t seconds later (t within TimeToLand).
Flight FlightAfter(const Flight& flight, double t, double gravity);

// The ball's state and its flight right after landing on the cloth at `landing_speed` (down,
// > 0) in state `s`: the bed's friction impulse applied, the rebound a flight from the cloth
// (none, Flight{}, where it is below kSettledHop).
struct Landing {
  BallState state;
  Flight rebound;
};
Landing LandOnBed(const BallState& s, double landing_speed, const ModelParameters& p);

// The speed [m/s] `launch` (StrikeBall's state after `stroke`) leaves the cloth upward at: e_b
// times the speed the elevated cue drove it down with; 0 for a level cue.
double LaunchUpSpeed(const CueStroke& stroke, const BallState& launch);

}  // namespace billiard::physics
