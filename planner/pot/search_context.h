// The scene a pot is searched on, and the two motions its strokes are simulated with: the shared
// context of the named steps (pot_planner.h, README "A pot in named steps").
//
// The search runs the closed form (Jaroukh 2019) between events, among the balls near the route
// being planned (routes.h, NearRoute: the truth has them all), and meets the jaws with Han 2005's
// single impulse where no rail is on the route (20 times cheaper than Mathavan et al. 2010's
// integrated impact) or, where rails are, with Mathavan et al. 2010's impact integrated with 50
// steps per approach momentum, not the truth's 250. The truth is the motion `billiard simulate
// --scene` runs by default (sim/model_choice/), with every ball and the set's own cushion model.
// Every simulation of either counts toward the plan's.
//
// Also the small vocabulary the steps share: a stroke's free parts (StrokeShape), the cue ball's
// first contact (Contact), a stroke played (Played), a refusal on the way (Refusal), the pace's
// last fit (PaceFit), and angles in the plane.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planner/pot/pot_planner.h"
#include "sim/physics/ball_state.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"
#include "sim/table/table_simulation.h"

namespace billiard::pot {

inline constexpr double kDegree = M_PI / 180.0;

// An angle [rad] wrapped into [-pi, pi].
inline double Wrap(double a) { return std::remainder(a, 2.0 * M_PI); }
// The unit vector at `angle` [rad], and the angle of a vector.
inline Eigen::Vector2d Unit(double angle) { return {std::cos(angle), std::sin(angle)}; }
inline double Angle(const Eigen::Vector2d& v) { return std::atan2(v.y(), v.x()); }

// The state turned by `angle` about the vertical: velocity and horizontal spin.
physics::BallState Rotated(physics::BallState s, double angle);

// The state of ball i just before time t (the segment in force before an event at t).
physics::BallState StateBefore(const table::TableSimulation& sim, std::size_t i, double t);

// The index of ball `id` in `sim` (std::logic_error where it has none).
std::size_t IndexOf(const table::TableSimulation& sim, int id);

// An angle in words: "1.23 deg".
std::string Degrees(double radians);

// A speed in words: "0.3 m/s", "1.23 m/s".
std::string MetresPerSecond(double speed);

// A stroke's free parts, the heading left to the aim.
struct StrokeShape {
  double speed = 0.0, tip_side = 0.0, tip_height = 0.0, elevation = 0.0;
  physics::CueStroke At(double heading) const { return {speed, heading, tip_side, tip_height, elevation}; }
};

// Where the cue ball first touched a ball, and the two balls there.
struct Contact {
  int ball = -1;  // the id it touched first; -1: none (it stopped or dropped first)
  double time = 0.0;
  Eigen::Vector2d cue_at = Eigen::Vector2d::Zero(), object_at = Eigen::Vector2d::Zero();
  physics::BallState cue_before = physics::BallState::Zero(), object_before = physics::BallState::Zero();
  physics::BallState object_after = physics::BallState::Zero();
  double departure = 0.0;  // direction of K's velocity after the impact [rad]
  double normal = 0.0;     // direction of the line of centres, cue ball to K [rad]
  std::vector<table::SceneBall> others;  // every other ball then (neither the cue ball nor K)
};

// A full run: what became of K and of the cue ball.
struct Played {
  PotOutcome outcome;
  std::unique_ptr<table::TableSimulation> sim;
  // K's speed as it crossed a capture line or, stopped early, met the rail that turned it away.
  std::optional<double> arrival_speed;
};

// A refusal on the way, the most telling kept.
struct Refusal {
  PotStatus status;
  std::string reason;
  // K does not drop along its own route, whatever the cue ball does: a curve, which changes only
  // the cue ball's path, cannot mend it.
  bool object_route_closed = false;
  // cue_blocked at the final stroke: the elevation [rad] that clears there, to plan again at.
  std::optional<double> elevation_needed = std::nullopt;
};

// The pace's last fit (pace.h): d (arrival speed^2) / d (cue speed^2), and the arrival speed at
// the pace.
struct PaceFit {
  double slope = 0.0, arrival = 0.0;
};

class SearchContext {
 public:
  // The pot of ball `object` into `pocket` from `balls` (id 0 the cue ball, struck from where it
  // is, at rest), with a cue-ball target for position play.
  SearchContext(const table::TableGeometry& table, const physics::ModelParameters& params,
                const std::vector<table::SceneBall>& balls, int object, const table::Pocket& pocket,
                const PotOptions& options, std::optional<CueTarget> target = std::nullopt);

  const table::TableGeometry& table() const { return table_; }
  const physics::ModelParameters& params() const { return params_; }
  const PotOptions& options() const { return options_; }
  const table::Pocket& pocket() const { return pocket_; }
  const std::optional<CueTarget>& target() const { return target_; }
  double radius() const { return r_; }
  // The scene, the cue ball at rest where it was given.
  const std::vector<table::SceneBall>& balls() const { return balls_; }
  const table::SceneBall& cue_ball() const { return balls_[cue_]; }
  const table::SceneBall& object_ball() const { return balls_[object_]; }
  const Eigen::Vector2d& cue_position() const { return cue_position_; }
  int object_id() const { return object_id_; }
  // Table simulations run so far, search and truth.
  int simulations() const { return simulations_; }

  // The search's scene for the route being planned: the balls it simulates (`near`; empty: every
  // ball), and whether it meets the rails with the set's cushion model (a bank's and a kick's
  // route is the rail's rebound; where the cue ball stops turns on every rail it meets) rather
  // than Han 2005's impulse.
  void SearchAmong(std::vector<table::SceneBall> near, bool rails_matter);

  // The pace's last fit. It is the search's, not a route's: a pace that meets its arrival speed at
  // the first speed tried fits nothing and leaves the one before.
  PaceFit& pace_fit() { return pace_fit_; }

  // A simulation of `balls`: the truth, or the search.
  std::unique_ptr<table::TableSimulation> Simulation(const std::vector<table::SceneBall>& balls, bool truth);

  // The scene with the cue ball struck: the balls near the routes, or the whole scene in its own
  // order (so that its ties break as `simulate --scene`'s do) for a shot played to rest.
  std::unique_ptr<table::TableSimulation> Launch(const physics::CueStroke& stroke, bool truth, bool whole = false);

  // The cue ball's first contact with a ball for `stroke`.
  Contact FirstContact(const physics::CueStroke& stroke, bool truth);

  // Plays a stroke to rest, or with `to_rest` false until K drops (what the pace and the speed
  // window ask: the cue ball's later travel, its cushions above all, is most of a shot's cost):
  // K's fate and the cue ball's.
  Played Play(const physics::CueStroke& stroke, bool truth, bool to_rest = true);

  // The event that decides K in `sim`: its drop, or a rail after which it heads away from P's
  // mouth (it cannot drop in P on its route then; what follows would only cost cushion impacts).
  // A rail that turns K toward P (a bank's, or one K runs along into the jaws) decides nothing.
  std::function<bool(const table::TableEvent&)> KsFate(const table::TableSimulation& sim) const;

 private:
  const table::TableGeometry& table_;
  const physics::ModelParameters& params_;
  std::vector<table::SceneBall> balls_;
  int object_id_;
  const table::Pocket& pocket_;
  PotOptions options_;
  std::optional<CueTarget> target_;
  double r_;
  decltype(table::TableSimulationOptions::five_dof) truth_motion_;
  std::size_t cue_ = 0, object_ = 0;
  Eigen::Vector2d cue_position_ = Eigen::Vector2d::Zero();
  int simulations_ = 0;
  PaceFit pace_fit_;
  std::vector<table::SceneBall> near_;  // the search's scene of a direct route; empty: the whole
  bool rails_matter_ = false;           // the search's cushions are the truth's (else kSearchCushion)
};

}  // namespace billiard::pot
