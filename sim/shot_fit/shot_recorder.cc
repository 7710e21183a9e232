#include "sim/shot_fit/shot_recorder.h"

#include <algorithm>
#include <string>

namespace billiard::shot_fit {

namespace {

constexpr double kMicro = 1e-6;  // [s/us]

}  // namespace

void ShotRecorder::State(std::int64_t utime, const std::vector<TrackSample>& tracks) {
  if (latest_ && utime <= latest_->first) return;
  latest_ = {utime, tracks};
  if (!open_ || utime <= open_->strike_utime) return;
  if (kMicro * static_cast<double>(utime - open_->strike_utime) > longest_shot_) {
    Finish();
    return;
  }
  const double t = kMicro * static_cast<double>(utime - open_->start_utime);
  for (const TrackSample& s : tracks) {
    const auto k = std::find(open_->tracks.begin(), open_->tracks.end(), s.track);
    if (k == open_->tracks.end()) continue;
    const auto i = static_cast<std::size_t>(k - open_->tracks.begin());
    TrackedBall& ball = open_->shot.balls[i];
    if ((s.position - ball.position.back()).norm() < thinning_) {
      open_->unkept[i] = {t, s.position};
      continue;
    }
    ball.t.push_back(t);
    ball.position.push_back(s.position);
    open_->unkept[i].reset();
  }
}

void ShotRecorder::Strike(std::int64_t utime, std::int32_t track) {
  if (last_strike_ == utime) return;
  last_strike_ = utime;
  Finish();
  const auto has_track = [track](const TrackSample& s) { return s.track == track; };
  if (!latest_ || latest_->first > utime ||
      std::none_of(latest_->second.begin(), latest_->second.end(), has_track)) {
    ++skipped_;
    return;
  }
  Open open;
  open.strike_utime = utime;
  open.start_utime = latest_->first;
  for (const TrackSample& s : latest_->second) {
    if (s.track == track) open.shot.cue = open.shot.balls.size();
    open.tracks.push_back(s.track);
    open.shot.balls.push_back({"track " + std::to_string(s.track), {0.0}, {s.position}});
  }
  open.unkept.resize(open.tracks.size());
  open_ = std::move(open);
}

void ShotRecorder::Finish() {
  if (!open_) return;
  Open open = std::move(*open_);
  open_.reset();
  for (std::size_t i = 0; i < open.unkept.size(); ++i) {
    if (!open.unkept[i]) continue;
    open.shot.balls[i].t.push_back(open.unkept[i]->first);
    open.shot.balls[i].position.push_back(open.unkept[i]->second);
  }
  if (open.shot.balls[open.shot.cue].t.size() < 2) {
    ++skipped_;
    return;
  }
  open.shot.id = std::to_string(shots_.size() + 1);
  shots_.push_back(std::move(open.shot));
  strike_utimes_.push_back(open.strike_utime);
}

}  // namespace billiard::shot_fit
