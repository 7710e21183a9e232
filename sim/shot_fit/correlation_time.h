// How many independent residuals a fit's residuals are worth: their integrated correlation time
// in samples, tau = 1 + 2 sum_k rho_k, the lag-k autocorrelations of each ball's residuals pooled
// over the shots and summed up to the first that is not positive (the simplest of Geyer 1992's
// initial sequence estimators, "Practical Markov chain Monte Carlo", Statistical Science 7).
// n correlated residuals say what n / tau independent ones would.
//
// Why: the estimator's tracks are filtered, so neighbouring frames share their errors (tau 7-8
// frames in the loop), and a model's own error on real shots lasts for seconds; independent
// noise gives 1. The constants' uncertainty (uncertainty.h) is inflated by it.
//
// Module: billiard::shot_fit.
#pragma once

#include <vector>

#include "sim/shot_fit/tracked_shot.h"

namespace billiard::shot_fit {

// The lags the residuals' correlation is summed over [samples]: at 30-50 Hz, 2-3 s, beyond the
// estimator's filtered tracks' memory.
inline constexpr int kMaxLag = 100;

// The residuals' sums of products at lags 0..kMaxLag, per ball and coordinate over its samples
// up to `horizon` (ShotModel::Residuals' order: ball by ball, x then y per sample). Index k: the
// sum over each ball's coordinates of r_i r_{i+k}, i and i + k samples of that ball k apart
// (k = 0: the squares): the residuals' autocovariance, unnormalised.
std::vector<double> LaggedProducts(const TrackedShot& shot, double horizon,
                                   const std::vector<double>& r);

// The integrated correlation time of residuals whose LaggedProducts, summed over the shots, are
// `lagged` (index 0: the squares). Never below 1; 1 when they are all zero.
double CorrelationTime(const std::vector<double>& lagged);

}  // namespace billiard::shot_fit
