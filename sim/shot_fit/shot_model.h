// One tracked shot simulated with one parameter set: the balls at rest where they were first
// seen, the cue ball struck at `Strike::time` (between its first two samples: a 50 Hz camera
// sees the ball still, then moving) by the stroke of sim/physics/cue_strike.h (Alciatore 2004,
// TP A.30-A.31), and the whole table run in closed form (sim/table/table_simulation.h). The
// residuals are the simulated centre minus the tracked one at every tracked time of every ball;
// the fits (strike_fit.h, joint_fit.h) take their costs from them.
//
// The cost they make is piecewise smooth: a small change of the strike makes or misses a
// collision. ImpactSequence names the piece a run lies on.
//
// Module: billiard::shot_fit.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/shot_fit/tracked_shot.h"
#include "sim/table/cushion_impact.h"
#include "sim/table/table_geometry.h"
#include "sim/table/table_simulation.h"

namespace billiard::shot_fit {

// The cushion model of every simulation here: Han 2005's closed form (the three-cushion paper),
// smooth in the strike and the constants. Mathavan 2010's explicit steps chatter where a contact
// grips: its rebound moves by about 1e-5 of itself between neighbouring inputs, and the slide
// after it ends microseconds apart, noise that defeats the differences a fit takes.
inline constexpr table::CushionModel kCushionModel = table::CushionModel::kHan2005;

// A shot's strike, and where its balls really stood: the tracking sees them a millimetre or two
// off, and a cut's angle turns by a degree a millimetre.
struct Strike {
  physics::CueStroke stroke;
  double time = 0.0;  // of the impact, on the shot's clock [s]
  // Per ball of the shot, its start relative to where it was first seen [m]; empty: as seen.
  std::vector<Eigen::Vector2d> start_offsets;
};

struct ShotErrors {
  std::vector<double> rmse;  // per ball of the shot [m]
  double rmse_all = 0.0;     // over every sample of every ball [m]
};

// The scene at the start of `shot` (each ball where it was first seen, moved onto the playing
// surface and off the others where the tracking put it a millimetre wrong), the cue struck by
// `strike`, simulated for the whole tracked time; the errors against the tracking. Throws
// std::invalid_argument on a stroke no cue gives.
ShotErrors Errors(const table::TableGeometry& table, const physics::ModelParameters& params,
                  const TrackedShot& shot, const Strike& strike);

// The simulation Errors compares: ball i of the scene is shot.balls[i], its clock starting at
// the impact (table time t is shot time t + strike.time), run to the shot's end.
table::TableSimulation SimulateShot(const table::TableGeometry& table,
                                    const physics::ModelParameters& params, const TrackedShot& shot,
                                    const Strike& strike);

// The balls moved onto the playing surface and off each other where the tracking (or a fitted
// offset) put them a millimetre wrong (touching balls, millimetre rounding): apart along their
// line, by half the overlap each, plus a micrometre.
std::vector<Eigen::Vector2d> Placed(const table::TableGeometry& table, double r,
                                    std::vector<Eigen::Vector2d> p);

// The run's impacts in order (kind, balls, cushion), hashed (FNV-1a): two runs with the same
// sequence lie on one smooth piece of the cost. Between pieces it jumps: a ball that catches up
// with another before it stops, or stops just short, is a different shot.
std::uint64_t ImpactSequence(const table::TableSimulation& sim);

// One shot with one parameter set: the start scene, and what a strike makes of it. Holds
// references to its arguments, which must outlive it.
class ShotModel {
 public:
  ShotModel(const table::TableGeometry& table, const physics::ModelParameters& params,
            const TrackedShot& shot);

  const TrackedShot& shot() const { return shot_; }
  const physics::ModelParameters& params() const { return params_; }

  // 2 per sample of each ball up to `horizon`.
  int ResidualCount(double horizon) const;

  // Simulated minus tracked, ball by ball, sample by sample, up to `horizon`; false where the
  // strike is none a cue gives or the simulation refuses the scene.
  // `impacts`, when given, receives the run's ImpactSequence.
  bool Residuals(const Strike& strike, double horizon, double* out,
                 std::uint64_t* impacts = nullptr) const;
  // The same as a vector, empty where they fail.
  std::vector<double> Residuals(const Strike& strike, double horizon,
                                std::uint64_t* impacts = nullptr) const;

  // Half the sum of squares (Ceres' cost), infinite where Residuals fails.
  double Cost(const Strike& strike, double horizon) const;

  // The table struck by `strike`, run until shot time `until`.
  table::TableSimulation Run(const Strike& strike, double until) const;

 private:
  const table::TableGeometry& table_;
  const physics::ModelParameters& params_;
  const TrackedShot& shot_;
  std::vector<Eigen::Vector2d> start_;  // where each ball was first seen
};

// The errors of `strike` over the whole shot (Errors); throws std::invalid_argument naming the
// shot where it cannot be simulated.
ShotErrors ErrorsOf(const ShotModel& model, const Strike& strike);

}  // namespace billiard::shot_fit
