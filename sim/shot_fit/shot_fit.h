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
// The pieces, each a header of its own: the constants (fit_constants.h), one shot simulated
// (shot_model.h), one shot's strike (strike_fit.h), the joint fit (joint_fit.h), the residuals'
// correlation time (correlation_time.h), the uncertainty and identifiability (uncertainty.h),
// synthetic shots (synthetic_shots.h). This header includes those a caller uses.
//
// Module: billiard::shot_fit. Includes the physics, the table and the batch (sim/physics,
// sim/table, sim/batch); its implementation uses Ceres' solver.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "sim/batch/thread_pool.h"
#include "sim/physics/parameters.h"
#include "sim/shot_fit/fit_constants.h"
#include "sim/shot_fit/shot_model.h"
#include "sim/shot_fit/strike_fit.h"
#include "sim/shot_fit/synthetic_shots.h"
#include "sim/shot_fit/tracked_shot.h"
#include "sim/shot_fit/uncertainty.h"
#include "sim/table/table_geometry.h"

namespace billiard::shot_fit {

struct ShotsFit {
  std::vector<ShotFit> shots;
  physics::ModelParameters params;  // the given set with the fitted constants
  std::vector<ConstantFit> constants;
  int constant_shots = 0;  // shots the constants were fitted on (outliers left out)
  // The residuals' integrated correlation time at the constants' solution [samples]: n
  // residuals tell what n / correlation_time independent ones would (1: independent).
  double correlation_time = 1.0;
  double median_cue_rmse = 0.0;           // over the fitted shots [m]
  double held_out_median_cue_rmse = 0.0;  // over the held-out shots, 0 when none [m]
};

// Told of each stage's progress: its name ("strikes", "constants", ...), the jobs done, of total.
using FitProgress =
    std::function<void(const std::string& stage, std::size_t done, std::size_t total)>;

// Fits the strike of every shot and, with options.constants, the shared constants over the shots
// not held out (held_out[i]: shot i; empty: none). A shot that fails carries the reason; the
// others complete. Deterministic whatever the pool's thread count.
ShotsFit FitShots(const table::TableGeometry& table, const physics::ModelParameters& params,
                  const std::vector<TrackedShot>& shots, const FitOptions& options,
                  batch::ThreadPool& pool, const std::vector<bool>& held_out = {},
                  const FitProgress& progress = nullptr);

}  // namespace billiard::shot_fit
