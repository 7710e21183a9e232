#include "planner/node/noise_learning.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "sim/shot_fit/launch_fit.h"

namespace billiard::planner_node {

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

// The reason a launch was not measured, without its counts: "only 2 samples ..." and "only 1
// sample ..." are one reason.
std::string ReasonKind(const std::string& reason) {
  const std::size_t only = reason.find("only ");
  if (only != 0) return reason;
  const std::size_t space = reason.find(' ', 5);
  return "only N" + reason.substr(space);
}

}  // namespace

NoiseLearner::NoiseLearner(params::ExecutionNoise prior)
    : prior_(std::move(prior)), noise_(prior_) {}

void NoiseLearner::Commanded(const cue_command_t& command) {
  if (command.status != cue_command_t::STATUS_OK || command.has_cue_placement) return;
  strokes_[command.utime] = {command.cue_speed, command.heading, command.tip_side,
                             command.tip_height, command.elevation};
}

bool NoiseLearner::Learn(const std::vector<shot_fit::TrackedShot>& shots,
                         const std::vector<std::int64_t>& strike_utimes,
                         const physics::ModelParameters& p) {
  const std::size_t before = residuals_.size();
  for (; seen_ < shots.size() && seen_ < strike_utimes.size(); ++seen_) {
    const auto stroke = strokes_.find(strike_utimes[seen_]);
    if (stroke == strokes_.end()) continue;  // a placement, or a stroke of another node
    const shot_fit::TrackedShot& shot = shots[seen_];
    const shot_fit::MeasuredLaunch launch = shot_fit::FitLaunch(shot, stroke->second, p);
    if (!launch.ok) {
      ++unmeasured_[ReasonKind(launch.reason)];
      continue;
    }
    residuals_.push_back(
        shot_fit::ResidualOf(stroke->second, shot.balls[shot.cue].position[0], launch, p));
    launch_shots_.push_back(seen_);
  }
  if (residuals_.size() == before || residuals_.size() < kMinNoiseShots) return false;
  shot_fit::NoiseFitOptions options;
  options.tip_prior = prior_.tip_offset;
  options.speed_absolute = prior_.speed_absolute;
  options.speed_start = std::max(prior_.speed, 1e-3);
  options.heading_start = std::max(prior_.heading, 1e-4);
  fit_ = shot_fit::FitExecutionNoise(residuals_, options);
  noise_ = prior_;
  noise_.name = prior_.name + "-learned";
  noise_.source = "learned from " + std::to_string(fit_->used.size()) +
                  " of the robot's strokes, from the prior " + prior_.name;
  noise_.speed = fit_->speed.value;
  noise_.heading = fit_->heading.value;
  noise_.tip_offset = fit_->tip.value;
  return true;
}

std::string NoiseLearner::Describe() const {
  std::ostringstream line;
  if (!fit_) {
    line << "no noise learned yet (" << residuals_.size() << " launches measured, "
         << kMinNoiseShots << " needed)";
    return line.str();
  }
  const shot_fit::NoiseFit& f = *fit_;
  line << "learned noise from " << f.used.size() << " launches (" << f.rejected
       << " left out) of " << seen_ << " shots: heading " << f.heading.value / kDegree
       << " deg [" << f.heading.lower / kDegree << ", " << f.heading.upper / kDegree
       << "], speed " << 100 * f.speed.value << " % [" << 100 * f.speed.lower << ", "
       << 100 * f.speed.upper << "], tip " << 1e3 * f.tip.value << " mm";
  if (f.tip.identified) {
    line << " [" << 1e3 * f.tip.lower << ", " << 1e3 * f.tip.upper << "]";
  } else {
    line << " (held at the prior: not identified)";
  }
  return line.str();
}

}  // namespace billiard::planner_node
