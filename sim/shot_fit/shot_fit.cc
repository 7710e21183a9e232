#include "sim/shot_fit/shot_fit.h"

#include <Eigen/Core>
#include <algorithm>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "sim/shot_fit/joint_fit.h"

namespace billiard::shot_fit {

namespace {

constexpr double kWholeShot = std::numeric_limits<double>::infinity();

// One FitShots run: the shots, and what is fitted of them so far.
class ShotsFitter {
 public:
  ShotsFitter(const table::TableGeometry& table, const physics::ModelParameters& params,
              const std::vector<TrackedShot>& shots, const FitOptions& options,
              batch::ThreadPool& pool, const std::vector<bool>& held_out,
              const FitProgress& progress)
      : table_(table),
        shots_(shots),
        options_(options),
        pool_(pool),
        held_out_(held_out),
        progress_(progress),
        phase_options_(options),
        constants_(options.constants),
        problem_{table, params, shots, {}, constants_, phase_options_, pool} {
    out_.params = params;
    out_.shots.resize(shots.size());
    // While the constants are fitted the cue ball stays where it was first seen (its offset
    // along its line is nearly the impact's time, and the joint steps would trade one against
    // the other); the strikes reported are fitted with the options as given.
    if (!options.constants.empty()) phase_options_.fit_cue_start = false;
    for (std::size_t i = 0; i < shots.size(); ++i) {
      all_.push_back(i);
      if (!IsHeldOut(i)) fitted_.push_back(i);
    }
    for (Constant c : options.constants) {
      ConstantFit f;
      f.constant = c;
      f.prior = f.value = ConstantValue(params, c);
      out_.constants.push_back(f);
    }
  }

  // Without constants to fit: every shot's strike, once.
  void FitStrikesAlone() { FitStrikes(all_, false, "strikes", kWholeShot); }

  // The constants and the strikes of the shots not held out, then the strikes of all.
  void FitConstants() {
    Continuation();
    DropTheUnidentifiable();
    out_.constant_shots = static_cast<int>(problem_.included.size());
    FitTheFinalStrikes();
  }

  // What was fitted, with the median cue-ball RMSEs.
  ShotsFit Result() {
    std::vector<double> cue, cue_held;
    for (const ShotFit& f : out_.shots) {
      if (!f.ok()) continue;
      (f.held_out ? cue_held : cue).push_back(f.rmse_cue);
    }
    out_.median_cue_rmse = Median(cue);
    out_.held_out_median_cue_rmse = Median(cue_held);
    return out_;
  }

 private:
  bool IsHeldOut(std::size_t i) const { return !held_out_.empty() && held_out_[i]; }

  // Fits the strikes of the shots `which` with out_.params over `horizon`, from their previous
  // strikes when `refine`; a shot that fails carries the reason.
  void FitStrikes(const std::vector<std::size_t>& which, bool refine, const std::string& stage,
                  double horizon) {
    auto results = pool_.Map(
        which.size(),
        [&](std::size_t job) {
          const std::size_t i = which[job];
          std::optional<Strike> previous;
          if (refine && out_.shots[i].ok()) previous = out_.shots[i].strike;
          return FitStrikeUpTo(table_, out_.params, shots_[i], phase_options_, previous, horizon);
        },
        progress_ ? batch::Progress(
                        [&](std::size_t done, std::size_t total) { progress_(stage, done, total); })
                  : batch::Progress());
    for (std::size_t job = 0; job < which.size(); ++job) {
      const std::size_t i = which[job];
      if (results[job].ok()) {
        out_.shots[i] = *results[job].value;
      } else {
        out_.shots[i] = ShotFit{};
        out_.shots[i].id = shots_[i].id;
        out_.shots[i].error = results[job].error;
      }
      out_.shots[i].held_out = IsHeldOut(i);
    }
  }

  Layout LayoutOf(std::size_t i) const {
    return Layout(phase_options_, problem_.base.ball.radius, shots_[i]);
  }

  // The strike vectors of the shots the constants are fitted on.
  std::vector<std::vector<double>> StrikesOf() const {
    std::vector<std::vector<double>> x;
    for (std::size_t i : problem_.included)
      x.push_back(ToVector(out_.shots[i].strike, LayoutOf(i)));
    return x;
  }

  std::vector<double> ValuesOf() const {
    std::vector<double> v;
    for (Constant c : constants_) v.push_back(ConstantValue(out_.params, c));
    return v;
  }

  // The shots the constants are fitted on: those not held out whose fit over the horizon is no
  // outlier.
  void ChooseShots() {
    problem_.included.clear();
    for (std::size_t i : fitted_)
      if (out_.shots[i].ok()) problem_.included.push_back(i);
    problem_.included = Inliers(problem_, StrikesOf(), ValuesOf(), options_.outlier_factor);
  }

  // One stage: every strike over the horizon (from the last when `refine`), then the strikes
  // and the constants together.
  void Stage(double horizon, bool refine, const std::string& name) {
    problem_.horizon = horizon;
    FitStrikes(fitted_, refine, "strikes, " + name, horizon);
    ChooseShots();
    if (progress_) progress_("joint fit, " + name, 0, 1);
    std::vector<std::vector<double>> x = StrikesOf();
    std::vector<double> v = ValuesOf();
    SolveJoint(problem_, options_, &x, &v);
    out_.params = WithConstants(out_.params, constants_, v);
    for (std::size_t j = 0; j < problem_.included.size(); ++j)
      out_.shots[problem_.included[j]].strike =
          FromVector(x[j].data(), LayoutOf(problem_.included[j]));
  }

  // A continuation over the horizon, as for one shot: the constants the first seconds show
  // (the slide, the roll, the first cushions) before the later collisions, whose timing they
  // set, can mislead them. Then the rounds over whole shots, and the strikes over them.
  void Continuation() {
    bool refine = false;
    for (double h : kHorizons) {
      Stage(h, refine, "first " + std::to_string(static_cast<int>(h)) + " s");
      refine = true;
    }
    for (int r_index = 0; r_index < options_.rounds; ++r_index)
      Stage(kWholeShot, true, "whole shots, round " + std::to_string(r_index + 1));
    FitStrikes(fitted_, true, "strikes, whole shots", kWholeShot);
  }

  // Identifiability: constants the shots do not pin down go back to their priors, and the
  // others are fitted once more without them.
  void DropTheUnidentifiable() {
    while (!constants_.empty()) {
      ChooseShots();
      const Eigen::MatrixXd cov =
          ConstantsCovariance(problem_.LinearizeAll(StrikesOf(), ValuesOf()), constants_.size(),
                              &out_.correlation_time);
      std::vector<Constant> kept;
      for (std::size_t c = 0; c < constants_.size(); ++c) {
        ConstantFit& fit =
            *std::find_if(out_.constants.begin(), out_.constants.end(),
                          [&](const ConstantFit& f) { return f.constant == constants_[c]; });
        JudgeIdentifiable(ConstantValue(out_.params, constants_[c]), cov(c, c),
                          options_.max_relative_sd, &fit);
        if (fit.identifiable) {
          kept.push_back(constants_[c]);
        } else {
          out_.params = WithConstants(out_.params, {fit.constant}, {fit.prior});
        }
      }
      if (kept.size() == constants_.size()) break;
      constants_ = kept;
      if (!constants_.empty()) {
        Stage(kWholeShot, true, "whole shots, without the unidentifiable");
        FitStrikes(fitted_, true, "strikes, whole shots", kWholeShot);
      }
    }
  }

  // The strikes reported: with the final constants and the options as given (the cue ball's
  // start fitted too), then those of the held-out shots.
  void FitTheFinalStrikes() {
    std::vector<std::size_t> rest;
    for (std::size_t i : all_)
      if (IsHeldOut(i)) rest.push_back(i);
    phase_options_ = options_;
    FitStrikes(fitted_, true, "strikes, the final constants", kWholeShot);
    FitStrikes(rest, false, "held-out strikes", kWholeShot);
  }

  const table::TableGeometry& table_;
  const std::vector<TrackedShot>& shots_;
  const FitOptions& options_;
  batch::ThreadPool& pool_;
  const std::vector<bool>& held_out_;
  const FitProgress& progress_;
  ShotsFit out_;
  FitOptions phase_options_;               // the options of the strikes' fits in the current phase
  std::vector<Constant> constants_;        // those still fitted
  std::vector<std::size_t> all_, fitted_;  // every shot; those not held out
  JointProblem problem_;                   // over constants_ with phase_options_
};

}  // namespace

ShotsFit FitShots(const table::TableGeometry& table, const physics::ModelParameters& params,
                  const std::vector<TrackedShot>& shots, const FitOptions& options,
                  batch::ThreadPool& pool, const std::vector<bool>& held_out,
                  const FitProgress& progress) {
  if (!held_out.empty() && held_out.size() != shots.size())
    throw std::invalid_argument("FitShots: held_out needs one flag per shot");
  ShotsFitter fitter(table, params, shots, options, pool, held_out, progress);
  if (options.constants.empty()) {
    fitter.FitStrikesAlone();
  } else {
    fitter.FitConstants();
  }
  return fitter.Result();
}

}  // namespace billiard::shot_fit
