// Identifying the physics from tracked shots: for each shot, the cue strike whose whole-table
// simulation (sim/table/table_simulation.h) best reproduces the tracked balls; over many shots,
// the shared constants of the cloth, the cushions and the balls, with their uncertainties.
//
// One shot. The balls start at rest where they were first seen (their starts fitted within a
// few millimetres); the cue ball is struck at `Strike::time` (between its first two samples: a
// 50 Hz camera sees the ball still, then moving) by the stroke of sim/physics/cue_strike.h, and
// the table runs in closed form. The residuals are the simulated centre minus the tracked one
// at every tracked time of every ball, for the whole tracked time; a ball's RMSE is over its
// samples. The cost is piecewise smooth: a small change of the strike makes or misses a
// collision. So the fit (FitStrike) starts from the launch the first samples show (its
// direction, its speed, the moment of the impact), scores a grid of tip offsets, speeds and
// headings around it over the first seconds, and refines the best few with Ceres'
// Levenberg-Marquardt (central differences) over a horizon that grows to the whole shot (a
// continuation: the early path fixes the launch before the later cushions and collisions, whose
// timing the launch sets, can mislead it).
//
// Many shots (FitShots). The strikes, one problem per shot, are fitted in parallel on a
// batch::ThreadPool (each job its own shot: the results do not depend on the thread count).
// With constants to fit, the strikes and the constants are solved jointly by a
// Levenberg-Marquardt over the reduced system (each shot's Gauss-Newton blocks from central
// differences on the pool, the strikes eliminated by the Schur complement, the sums in shot
// order), robust (Cauchy's loss of each shot's RMSE) and over the same growing horizon. The
// uncertainty of the constants is their marginal covariance, the strikes eliminated:
// tau sigma^2 (sum_s J_c^T J_c - J_c^T J_s (J_s^T J_s)^-1 J_s^T J_c)^-1, sigma^2 from the
// residuals and tau their correlation time in samples (a filtered track's neighbouring frames
// share their errors: n of them say what n / tau independent ones would). A constant whose
// relative standard uncertainty exceeds FitOptions::max_relative_sd (the shots do not excite
// it), or whose fit ran to the edge of its range, is reported as not identifiable, kept at its
// prior value, and the others fitted again. The design and its measurements: sim/shot_fit/README.md.
//
// Module: billiard::shot_fit. Includes the physics, the table and the batch (sim/physics,
// sim/table, sim/batch); its implementation uses Ceres' solver.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sim/batch/thread_pool.h"
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

// The shared constants a fit may identify:
//   kMu               "mu": the cloth's sliding friction mu (contact.mu);
//   kRolling          "rolling": the rolling resistance mu_r = a d / (5 r) (d follows, a kept;
//                     where d would pass 1, d = 1 and a = 5 r mu_r);
//   kSpin             "spin": the contact patch radius a, the lever of the pivot friction that
//                     stops side spin (ClothParameters::spin_decel; mu_r kept, d follows);
//   kCushion          "cushion": the ball-cushion restitution e_e;
//   kCushionFriction  "cushion_friction": the ball-cushion friction mu_w;
//   kBallBall         "ball_ball": the ball-ball restitution e_b.
enum class Constant { kMu, kRolling, kSpin, kCushion, kCushionFriction, kBallBall };

const char* ConstantName(Constant constant);
// Reads "mu,rolling,..." (the names above, comma-separated, no repeats); throws
// std::invalid_argument naming an unknown or repeated name.
std::vector<Constant> ParseConstants(const std::string& list);
double ConstantValue(const physics::ModelParameters& p, Constant constant);
// `p` with the constants set to `values` (in the order of `constants`; spin before rolling).
physics::ModelParameters WithConstants(const physics::ModelParameters& p,
                                       const std::vector<Constant>& constants,
                                       const std::vector<double>& values);

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
                                    const physics::ModelParameters& params,
                                    const TrackedShot& shot, const Strike& strike);

struct FitOptions {
  bool fit_elevation = false;     // else the cue is level
  bool fit_start = true;          // each object ball's start within a few mm of its first sample
  // The cue ball's too, in the strikes reported; while constants are fitted it stays where it
  // was first seen (along its line its offset is nearly the impact's time).
  bool fit_cue_start = true;
  std::vector<Constant> constants;  // fitted jointly over the shots (FitShots)
  int rounds = 1;                 // joint fits over whole shots, after the continuation
  double max_relative_sd = 0.2;   // beyond it a constant is not identifiable
  // Shots whose fit leaves an RMSE (all balls, over the horizon) above this multiple of the median are
  // left out of the constants' fit: a shot the model cannot follow (a kiss the tracking lost,
  // a double hit) would pull every constant.
  double outlier_factor = 3.0;
  int max_iterations = 40;        // of each Ceres solve and of each joint solve
};

struct ShotFit {
  std::string id;
  bool held_out = false;  // not used to fit the constants
  Strike strike;
  ShotErrors errors;
  double rmse_cue = 0.0;  // errors.rmse of the cue ball
  std::string error;      // why the shot has no fit, when it has none (then ok() is false)
  bool ok() const { return error.empty(); }
};

// The strike that best reproduces `shot` with `params`; `previous`, when given, is refined as
// one more start. Throws std::invalid_argument on a shot that cannot be simulated.
ShotFit FitStrike(const table::TableGeometry& table, const physics::ModelParameters& params,
                  const TrackedShot& shot, const FitOptions& options,
                  const std::optional<Strike>& previous = std::nullopt);

struct ConstantFit {
  Constant constant = Constant::kMu;
  double prior = 0.0;       // the value of the given parameter set
  double value = 0.0;       // fitted, or the prior when not identifiable
  // Standard uncertainty: the marginal covariance inflated by the residuals' correlation time
  // (ShotsFit::correlation_time); infinite when the shots do not excite the constant.
  double sd = 0.0;
  bool at_bound = false;    // the fit ran to the edge of the constant's range (AtRangeBound)
  bool identifiable = false;
};

struct ShotsFit {
  std::vector<ShotFit> shots;
  physics::ModelParameters params;  // the given set with the fitted constants
  std::vector<ConstantFit> constants;
  int constant_shots = 0;           // shots the constants were fitted on (outliers left out)
  // The residuals' integrated correlation time at the constants' solution [samples]: n
  // residuals tell what n / correlation_time independent ones would (1: independent).
  double correlation_time = 1.0;
  double median_cue_rmse = 0.0;           // over the fitted shots [m]
  double held_out_median_cue_rmse = 0.0;  // over the held-out shots, 0 when none [m]
};

// Told of each stage's progress: its name ("strikes", "constants", ...), the jobs done, of total.
using FitProgress = std::function<void(const std::string& stage, std::size_t done, std::size_t total)>;

// Fits the strike of every shot and, with options.constants, the shared constants over the shots
// not held out (held_out[i]: shot i; empty: none). A shot that fails carries the reason; the
// others complete. Deterministic whatever the pool's thread count.
// Whether a constant fitted to `value` +- `sd` sits at a bound of the range [lo, hi] its fit
// searched (far beyond any table's, so that what the shots say lies beyond it): within 1e-6 of a
// bound (relative), or, when the sd would call it known (`pinned`), within 3 sd of one: a fit
// that stopped a hair inside the edge has no minimum there either, and its curvature is no
// uncertainty (the adaptive loop's truth fitted mu 0.5995 +- 0.0003 against 0.6 from shots that
// never slide). Such a constant is not identifiable.
bool AtRangeBound(double value, double sd, bool pinned, double lo, double hi);

ShotsFit FitShots(const table::TableGeometry& table, const physics::ModelParameters& params,
                  const std::vector<TrackedShot>& shots, const FitOptions& options,
                  batch::ThreadPool& pool, const std::vector<bool>& held_out = {},
                  const FitProgress& progress = nullptr);

// A shot as a camera would track it from the simulation: the balls at `starts` (index `cue`
// struck by `strike`), each sampled every `period` from 0 to `duration` with Gaussian noise of
// standard deviation `noise` [m] per coordinate (seeded by `seed`), thinned as the real
// recordings are: a sample is kept where the ball moved at least `thinning` [m] from the last
// kept one, and the first and the last are always kept.
TrackedShot SimulateTrackedShot(const table::TableGeometry& table,
                                const physics::ModelParameters& params,
                                const std::vector<Eigen::Vector2d>& starts, std::size_t cue,
                                const Strike& strike, double duration, double period, double noise,
                                double thinning, std::uint64_t seed);

// The frame period of the synthetic shots: the real recordings' 50 Hz [s].
inline constexpr double kSyntheticPeriod = 0.02;

// A synthetic shot before it is tracked: where its balls start, and how ball 0 is struck.
struct SyntheticScene {
  std::vector<Eigen::Vector2d> starts;
  Strike strike;
};

// `count` random strikes (cue speed 2-4 m/s, any heading, tip offsets within 0.4 r, the impact
// within the first frame period) of one of three balls placed at random, clear of each other
// and of the cushions (seeded by `seed`).
std::vector<SyntheticScene> SyntheticScenes(const table::TableGeometry& table, double ball_radius,
                                            int count, std::uint64_t seed);

// The `count` SyntheticScenes simulated with `params` for 8 s and tracked by
// SimulateTrackedShot as the real recordings are: 50 Hz, 1 mm of noise, thinned where a ball
// moved less than 2 mm. Ball 0 is struck.
std::vector<TrackedShot> SyntheticShots(const table::TableGeometry& table,
                                        const physics::ModelParameters& params, int count,
                                        std::uint64_t seed);

}  // namespace billiard::shot_fit
