// Whether the detector's constants fitted from data transfer to a camera they were not fitted on:
// leave-one-source-out cross-validation on labelled sets (issue 45, `billiard bench-detect
// --cross-validate`).
//
// A source is the repository a frame came from (its label's `source`, "owner/repo path@commit").
// Each fold holds one source's frames out; the constants that are fitted from data are fitted by
// code on the other sources' labelled frames, and the detector with them is scored on the frames
// held out. The folds' scores together are the headline figures; beside them the same frames
// scored with the constants fitted on every source (what the fit gives when it has seen the
// camera) and with the constants set by hand. Fitted:
//   - DetectorOptions::min_score: of `min_scores`, the one whose detections on the training
//     frames have the highest F1 of recall and precision (pooled over the frames; the middle of
//     those that tie). The detector is run at each value on every frame once, so the fit and the
//     scores held out are the detector's own at that value;
//   - the identity's colours and shares (estimator/identity_fit.h), from the training frames'
//     detections at the fitted min_score that match a label with a class, each source a camera.
// The identity of a held-out frame is its detections' looks (at the fold's min_score) named under
// the fold's parameters, which is what the detector names with them (BallDetector::SearchedFrame).
// Every other constant set from data is fixed, and the figures do not cover it
// (docs/vision.md's table of the estimator's constants).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bench/detection_benchmark.h"
#include "estimator/identity_fit.h"

namespace billiard::bench {

// The repository of a label's `source`: its first word ("owner/repo").
std::string SourceRepository(const std::string& source);

// One fold: the source held out, and the indices of the frames it trains on and scores.
struct Fold {
  std::string source;
  std::vector<int> training, held_out;
};

// A fold per source (in the order of their names), every frame held out by its source's fold
// alone. Throws std::invalid_argument when a frame has no source, or the frames hold fewer than
// two sources (leaving one out would leave nothing to fit on).
std::vector<Fold> LeaveOneSourceOut(const std::vector<LabelledFrame>& frames);

// The constants fitted on a set of frames.
struct FittedConstants {
  double min_score = 0;
  estimator::IdentityFit identity;
};

// The detector on one frame at every min_score tried: its balls (named with the hand-set
// identity) and their looks, the frame's view and why no table was found.
struct FrameRuns {
  std::vector<std::vector<estimator::BallDetection>> balls;  // per min_score tried
  std::vector<std::vector<estimator::BallLook>> looks;
  std::string table_view, failure;
  cv::Size size;
};

// The min_score of `min_scores` with the highest F1 over `training` (indices of `frames`,
// `runs` parallel to them); the middle of those that tie (the higher of two).
double ChooseMinScore(const std::vector<LabelledFrame>& frames, const std::vector<FrameRuns>& runs,
                      const std::vector<double>& min_scores, const std::vector<int>& training);

// The known balls of `training`'s frames at min_scores[at]: the detections that match a label
// with a class (estimator/identity_fit.h), each frame's source its index in `sources`.
std::vector<estimator::KnownBall> KnownBalls(const std::vector<LabelledFrame>& frames,
                                             const std::vector<FrameRuns>& runs,
                                             const std::vector<int>& training, int at,
                                             const std::vector<std::string>& sources);

// Fits the constants on `training`.
FittedConstants FitConstants(const std::vector<LabelledFrame>& frames,
                             const std::vector<FrameRuns>& runs,
                             const std::vector<double>& min_scores,
                             const std::vector<int>& training,
                             const std::vector<std::string>& sources);

// Frame `index` scored with `constants`: its detections at their min_score, named under their
// identity parameters.
FrameScore ScoreWith(const std::vector<LabelledFrame>& frames, const std::vector<FrameRuns>& runs,
                     const std::vector<double>& min_scores, int index,
                     const estimator::IdentityParameters& identity, double min_score);

struct CrossValidationOptions {
  // The min_scores tried; the hand-set one (DetectorOptions' default) among them.
  std::vector<double> min_scores = {0.30, 0.35, 0.40, 0.45, 0.50, 0.55,
                                    0.60, 0.65, 0.70, 0.75, 0.80};
  // Reads an image file (BGR); throws std::invalid_argument with the reason when it cannot.
  std::function<cv::Mat(const std::string&)> read_image;
  std::function<void(const std::string&)> progress = [](const std::string&) {};
  // The identity classifier every protocol names the balls with (`--identity model`): fitted on
  // rendered balls alone, it is the same in every fold, and only the rules' parameters it
  // replaces are fitted; none, the rules' colours and shares.
  std::shared_ptr<const estimator::IdentityClassifier> classifier;
};

// A labelled set: its directory (its frames' files are relative to it) and its frames.
struct LabelledSet {
  std::string directory;
  std::vector<LabelledFrame> frames;
};

struct FoldResult {
  Fold fold;
  FittedConstants fitted;
  // The held-out frames scored with the fold's constants, with those fitted on every source, and
  // with those set by hand.
  std::vector<FrameScore> held_out, fitted_on_all, by_hand;
};

struct CrossValidationResult {
  std::vector<std::string> sets;
  std::vector<double> min_scores;
  FittedConstants fitted_on_all;
  std::vector<FoldResult> folds;
  double wall_s = 0;
};

// The protocol on the frames of `sets`, with OpenCV on one thread (deterministic). Throws
// std::invalid_argument as LeaveOneSourceOut does, or when the hand-set min_score is not tried.
CrossValidationResult RunCrossValidation(const std::vector<LabelledSet>& sets,
                                         const CrossValidationOptions& options);

}  // namespace billiard::bench
