#include "bench/cross_validation.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <optional>
#include <stdexcept>
#include <utility>

#include "bench/format.h"
#include "bench/one_thread.h"
#include "estimator/ball_identity.h"

namespace billiard::bench {

namespace {

using estimator::BallClass;
using estimator::BallSet;
using estimator::KnownBall;
using estimator::PoolGroup;

// The class a label names in `set` (KnownBall's class and group): a class's own name, carom's
// "white" for the cue ball, "eight" (and pool's "black") for the black, or a pool ball's group;
// none for a name the set has no ball of, or no name.
std::optional<std::pair<BallClass, PoolGroup>> KnownClass(const std::string& label, BallSet set) {
  const bool pool = set == BallSet::kPool;
  if (pool && label == "solid") return std::pair{BallClass::kUnknown, PoolGroup::kSolid};
  if (pool && label == "stripe") return std::pair{BallClass::kUnknown, PoolGroup::kStripe};
  if (label == "white") return std::pair{BallClass::kCue, PoolGroup::kNone};
  if (label == "eight" || (pool && label == "black")) {
    return std::pair{pool ? estimator::PoolBall(8) : BallClass::kBlack, PoolGroup::kNone};
  }
  for (const BallClass c : estimator::ClassesIn(set)) {
    if (!label.empty() && estimator::BallClassName(c) == label) {
      return std::pair{c, PoolGroup::kNone};
    }
  }
  return std::nullopt;
}

// A frame's detections scored once per min_score: labels, found and false, for the F1.
struct Counts {
  int labels = 0, found = 0, false_detections = 0;
};

double F1(const Counts& c) {
  const int denominator = c.labels + c.found + c.false_detections;
  return denominator > 0 ? 2.0 * c.found / denominator : 0.0;
}

FrameRuns RunFrame(const LabelledFrame& frame, const cv::Mat& image,
                   const std::vector<double>& min_scores) {
  FrameRuns runs;
  runs.size = image.size();
  for (const double min_score : min_scores) {
    estimator::DetectorOptions options;
    options.ball_set = BallSetFor(frame);
    options.min_score = min_score;
    estimator::BallDetector detector(options);
    runs.balls.push_back(detector.Detect(image));
    runs.looks.push_back(
        estimator::LookAtBalls(detector.SearchedFrame(image), runs.balls.back(), options.ball_set));
    runs.failure = detector.failure();
    runs.table_view =
        detector.knows_table() ? estimator::TableViewName(detector.table()->view) : "";
  }
  return runs;
}

// Every frame of the sets run at every min_score, in order, each reported when done.
std::vector<FrameRuns> RunEveryFrame(const std::vector<LabelledSet>& sets,
                                     const CrossValidationOptions& options) {
  std::size_t total = 0, done = 0;
  for (const LabelledSet& set : sets) total += set.frames.size();
  std::vector<FrameRuns> runs;
  for (const LabelledSet& set : sets) {
    for (const LabelledFrame& frame : set.frames) {
      const auto start = std::chrono::steady_clock::now();
      const cv::Mat image =
          frame.image.empty() ? options.read_image(set.directory + "/" + frame.file) : frame.image;
      runs.push_back(RunFrame(frame, image, options.min_scores));
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      options.progress("frame " + std::to_string(++done) + " of " + std::to_string(total) + ", " +
                       frame.file + ": detected at " + std::to_string(options.min_scores.size()) +
                       " min_scores (" + Fixed(seconds, 1) + " s)");
    }
  }
  return runs;
}

int IndexOf(const std::vector<double>& min_scores, double min_score) {
  const auto at = std::find(min_scores.begin(), min_scores.end(), min_score);
  if (at == min_scores.end()) {
    throw std::invalid_argument("min_score " + Fixed(min_score, 2) + " is not among those tried");
  }
  return static_cast<int>(at - min_scores.begin());
}

std::vector<std::string> SourcesOf(const std::vector<Fold>& folds) {
  std::vector<std::string> sources;
  for (const Fold& fold : folds) sources.push_back(fold.source);
  return sources;
}

std::vector<FrameScore> ScoreAll(const std::vector<LabelledFrame>& frames,
                                 const std::vector<FrameRuns>& runs,
                                 const std::vector<double>& min_scores,
                                 const std::vector<int>& indices, const FittedConstants& fitted) {
  std::vector<FrameScore> scores;
  for (const int i : indices) {
    scores.push_back(
        ScoreWith(frames, runs, min_scores, i, fitted.identity.parameters, fitted.min_score));
  }
  return scores;
}

std::string Described(const FittedConstants& c) {
  const auto& p = c.identity.parameters;
  return "min_score " + Fixed(c.min_score, 2) + ", cue_white " + Fixed(p.cue_white, 2) +
         ", cue_colour " + Fixed(p.cue_colour, 2) + ", black_share " + Fixed(p.black_share, 2) +
         ", stripe_plain " + Fixed(p.stripe_plain, 2) + ", colours of " +
         std::to_string(c.identity.classes_fitted) + " classes fitted";
}

}  // namespace

std::string SourceRepository(const std::string& source) {
  return source.substr(0, source.find(' '));
}

std::vector<Fold> LeaveOneSourceOut(const std::vector<LabelledFrame>& frames) {
  std::map<std::string, Fold> by_source;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const std::string source = SourceRepository(frames[i].source);
    if (source.empty()) throw std::invalid_argument("'" + frames[i].file + "' has no source");
    by_source[source].source = source;
    by_source[source].held_out.push_back(static_cast<int>(i));
  }
  if (by_source.size() < 2) {
    throw std::invalid_argument("the frames hold " + std::to_string(by_source.size()) +
                                " source: leaving it out leaves nothing to fit on");
  }
  std::vector<Fold> folds;
  for (auto& [source, fold] : by_source) {
    for (std::size_t i = 0; i < frames.size(); ++i) {
      if (SourceRepository(frames[i].source) != source)
        fold.training.push_back(static_cast<int>(i));
    }
    folds.push_back(std::move(fold));
  }
  return folds;
}

double ChooseMinScore(const std::vector<LabelledFrame>& frames, const std::vector<FrameRuns>& runs,
                      const std::vector<double>& min_scores, const std::vector<int>& training) {
  std::vector<double> f1;
  for (std::size_t k = 0; k < min_scores.size(); ++k) {
    Counts total;
    for (const int i : training) {
      const FrameScore score = ScoreFrame(frames[i], runs[i].balls[k]);
      total.labels += score.labels;
      total.found += score.found;
      total.false_detections += score.false_detections;
    }
    f1.push_back(F1(total));
  }
  const double best = *std::max_element(f1.begin(), f1.end());
  std::vector<double> tied;
  for (std::size_t k = 0; k < f1.size(); ++k) {
    if (f1[k] == best) tied.push_back(min_scores[k]);
  }
  return tied[tied.size() / 2];
}

std::vector<KnownBall> KnownBalls(const std::vector<LabelledFrame>& frames,
                                  const std::vector<FrameRuns>& runs,
                                  const std::vector<int>& training, int at,
                                  const std::vector<std::string>& sources) {
  std::vector<KnownBall> known;
  for (const int i : training) {
    const LabelledFrame& frame = frames[i];
    const BallSet set = BallSetFor(frame);
    const int source =
        static_cast<int>(std::find(sources.begin(), sources.end(), SourceRepository(frame.source)) -
                         sources.begin());
    const FrameScore score = ScoreFrame(frame, runs[i].balls[at]);
    for (std::size_t d = 0; d < score.detection_label.size(); ++d) {
      const int label = score.detection_label[d];
      if (label < 0 || static_cast<std::size_t>(label) >= frame.classes.size()) continue;
      const auto known_class = KnownClass(frame.classes[label], set);
      if (!known_class) continue;
      known.push_back({runs[i].looks[at][d], set, known_class->first, known_class->second, source});
    }
  }
  return known;
}

FittedConstants FitConstants(const std::vector<LabelledFrame>& frames,
                             const std::vector<FrameRuns>& runs,
                             const std::vector<double>& min_scores,
                             const std::vector<int>& training,
                             const std::vector<std::string>& sources) {
  FittedConstants fitted;
  fitted.min_score = ChooseMinScore(frames, runs, min_scores, training);
  const int at = IndexOf(min_scores, fitted.min_score);
  fitted.identity = estimator::FitIdentity(KnownBalls(frames, runs, training, at, sources),
                                           estimator::HandSetIdentity());
  return fitted;
}

FrameScore ScoreWith(const std::vector<LabelledFrame>& frames, const std::vector<FrameRuns>& runs,
                     const std::vector<double>& min_scores, int index,
                     const estimator::IdentityParameters& identity, double min_score) {
  const LabelledFrame& frame = frames[index];
  const FrameRuns& run = runs[index];
  const int at = IndexOf(min_scores, min_score);
  std::vector<estimator::BallDetection> balls = run.balls[at];
  const auto named = estimator::NameBalls(run.looks[at], balls, BallSetFor(frame), identity);
  for (std::size_t i = 0; i < balls.size(); ++i) {
    balls[i].ball_class = named[i].ball_class;
    balls[i].class_confidence = named[i].confidence;
  }
  FrameScore score = ScoreFrame(frame, balls);
  score.size = run.size;
  score.failure = run.failure;
  score.table_view = run.table_view;
  score.view = !frame.view.empty() ? frame.view : run.table_view;
  return score;
}

CrossValidationResult RunCrossValidation(const std::vector<LabelledSet>& sets,
                                         const CrossValidationOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const OneThread one_thread;
  CrossValidationResult result;
  result.min_scores = options.min_scores;
  FittedConstants by_hand;
  by_hand.min_score = estimator::DetectorOptions().min_score;
  by_hand.identity.parameters = estimator::HandSetIdentity();
  by_hand.identity.parameters.classifier = options.classifier;
  IndexOf(options.min_scores, by_hand.min_score);
  std::vector<LabelledFrame> frames;
  for (const LabelledSet& set : sets) {
    result.sets.push_back(set.directory);
    frames.insert(frames.end(), set.frames.begin(), set.frames.end());
  }
  const std::vector<Fold> folds = LeaveOneSourceOut(frames);
  const std::vector<std::string> sources = SourcesOf(folds);
  const std::vector<FrameRuns> runs = RunEveryFrame(sets, options);
  std::vector<int> every(frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i) every[i] = static_cast<int>(i);
  result.fitted_on_all = FitConstants(frames, runs, options.min_scores, every, sources);
  result.fitted_on_all.identity.parameters.classifier = options.classifier;
  options.progress("fitted on every source: " + Described(result.fitted_on_all));
  for (const Fold& fold : folds) {
    FoldResult r;
    r.fold = fold;
    r.fitted = FitConstants(frames, runs, options.min_scores, fold.training, sources);
    r.fitted.identity.parameters.classifier = options.classifier;
    r.held_out = ScoreAll(frames, runs, options.min_scores, fold.held_out, r.fitted);
    r.fitted_on_all =
        ScoreAll(frames, runs, options.min_scores, fold.held_out, result.fitted_on_all);
    r.by_hand = ScoreAll(frames, runs, options.min_scores, fold.held_out, by_hand);
    options.progress(fold.source + " held out: " + Described(r.fitted));
    result.folds.push_back(std::move(r));
  }
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace billiard::bench
