// What the calibration benchmarks (bench-game's choices, bench-constants' banks and kicks) share:
// the seeded scenes they choose on, and a predicted probability judged against what happened by
// decile of the prediction (a reliability diagram, Murphy and Winkler 1977). A decile holding at least kJudgedCount executions is judged
// within kCalibrationTolerance (issue 47's acceptance: within 5 points where a decile has 30).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

#include "plot/reliability.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::bench {

inline constexpr int kDeciles = 10;
inline constexpr int kJudgedCount = 30;
inline constexpr double kCalibrationTolerance = 0.05;

// A prediction and its executions.
struct CalibrationPoint {
  double predicted = 0.0;  // the chosen shot's reported probability
  double selection = 0.0;  // the finalists' estimate that chose it (biased up)
  int executions = 0, potted = 0;
};

// `balls` with a cue ball (id 0) at a free place drawn from `seed`: on the surface, 3 radii from
// the rails and 4 from every ball (a choice without ball in hand).
std::vector<table::SceneBall> WithSeededCueBall(const table::TableGeometry& table, double radius,
                                                std::vector<table::SceneBall> balls,
                                                std::uint64_t seed);

// The decile a prediction falls in.
int DecileOf(double predicted);

// The executions of `points` by the decile of their prediction: the mean prediction and the
// measured rate of each.
std::vector<plot::ReliabilityBin> Deciles(const std::vector<CalibrationPoint>& points);

// The deciles as JSON (lo, hi, count, choices, predicted, measured and its binomial standard
// error, judged, within_5_points); `calibrated` says whether every judged decile is within.
nlohmann::json DecilesJson(const std::vector<CalibrationPoint>& points, bool* calibrated);

}  // namespace billiard::bench
