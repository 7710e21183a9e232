// How well the shots pin the shared constants down, and which of them they identify at all.
//
// The uncertainty of the constants is their marginal covariance with the strikes eliminated
// (joint_fit.h's reduced system, undamped):
//   tau sigma^2 (sum_s J_c^T J_c - J_c^T J_s (J_s^T J_s)^-1 J_s^T J_c)^-1,
// sigma^2 the residuals' sum of squares over their degrees of freedom and tau their correlation
// time in samples (correlation_time.h): n residuals of a filtered track say what n / tau
// independent ones would. It is the statistical uncertainty given the model, the start positions
// and the tracking: on real shots the model's own error dominates, on synthetic ones the start
// positions' noise biases the constants by a few tenths of a per cent, beyond it, and a scale
// error of the tracked positions is a change of the rolling resistance that no residual shows.
//
// A constant whose relative standard uncertainty exceeds FitOptions::max_relative_sd (or whose
// reduced matrix is singular: no shot excites it), or whose fit ran to the edge of its range
// (AtRangeBound: no minimum inside what any table is, so its curvature is no uncertainty), is
// not identifiable: FitShots keeps it at its prior and fits the others again without it.
//
// Module: billiard::shot_fit.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "sim/shot_fit/fit_constants.h"
#include "sim/shot_fit/joint_fit.h"

namespace billiard::shot_fit {

struct ConstantFit {
  Constant constant = Constant::kMu;
  double prior = 0.0;  // the value of the given parameter set
  double value = 0.0;  // fitted, or the prior when not identifiable
  // Standard uncertainty: the marginal covariance inflated by the residuals' correlation time
  // (ShotsFit::correlation_time); infinite when the shots do not excite the constant.
  double sd = 0.0;
  bool at_bound = false;  // the fit ran to the edge of the constant's range (AtRangeBound)
  bool identifiable = false;
};

// Whether a constant fitted to `value` +- `sd` sits at a bound of the range [lo, hi] its fit
// searched (far beyond any table's, so that what the shots say lies beyond it): within 1e-6 of a
// bound (relative), or, when the sd would call it known (`pinned`), within 3 sd of one: a fit
// that stopped a hair inside the edge has no minimum there either, and its curvature is no
// uncertainty (the adaptive loop's truth fitted mu 0.5995 +- 0.0003 against 0.6 from shots that
// never slide). Such a constant is not identifiable.
bool AtRangeBound(double value, double sd, bool pinned, double lo, double hi);

// The marginal covariance of the k constants at the solution whose blocks (undamped, unweighted)
// are `blocks`: tau sigma^2 S^-1 with the reduced matrix S, sigma^2 the sum of squares over the
// residuals less the strikes' and the constants' parameters, and the residuals' correlation time
// tau (into *correlation_time). A constant no shot excites (its row of S zero) has an infinite
// variance, the others those of the rest of S; all are infinite where that rest is singular.
Eigen::MatrixXd ConstantsCovariance(const std::vector<ShotBlocks>& blocks, std::size_t k,
                                    double* correlation_time);

// Judges `fit` at `value` with variance `variance` (its diagonal element of
// ConstantsCovariance): sets its value, sd, at_bound and identifiable, identifiable where its
// relative sd is at most `max_relative_sd` and it is not at a bound of ConstantRange; a
// constant not identifiable goes back to its prior value.
void JudgeIdentifiable(double value, double variance, double max_relative_sd, ConstantFit* fit);

// The identifiable constants' sds as a parameter set carries them (its "uncertainty", drawn by
// the shot choice: sim/params/constants_uncertainty.h), each under the set's key: mu as
// contact.mu, spin as contact.patch_radius, cushion as collision.cushion_restitution,
// cushion_friction as collision.cushion_friction, ball_ball as collision.ball_restitution, and
// rolling as contact.d, mu_r's sd times 5 r / a (d = 5 r mu_r / a with `fitted`'s a held).
std::vector<std::pair<std::string, double>> SetUncertainty(const std::vector<ConstantFit>& constants,
                                                           const physics::ModelParameters& fitted);

}  // namespace billiard::shot_fit
