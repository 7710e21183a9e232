// Tracked shots cut from a running loop: the strikes it commanded and the states its estimator
// published, as they come (over LCM, or read back from a log), turned into the TrackedShot the
// fits take (shot_fit.h).
//
// A shot starts at a strike (the utime of the commanded cue strike and the track it struck) and
// ends at the next strike or at Finish(). Its balls are the tracks of the latest state before
// the strike, each seen there at rest, which is the shot's first sample (time 0 on the shot's
// clock); then every later state's position of each of those tracks. A track that appears
// during the shot (a ball the estimator lost and found again under another id) is not followed:
// a fit would start it at rest where it first appeared. A strike of a track the latest state does
// not have, or one that comes before any state, starts no shot (counted in skipped()). A strike
// at the same utime as the latest is the same strike commanded again (a resent request's answer)
// and changes nothing, even after Finish().
//
// Plain data in, plain data out: no LCM here, so that the `billiard identify` command (a log)
// and a node (live messages) cut shots the same way.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "sim/shot_fit/tracked_shot.h"

namespace billiard::shot_fit {

// One track of a state: its id and where its centre is [m].
struct TrackSample {
  std::int32_t track = 0;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
};

class ShotRecorder {
 public:
  // A shot ends `longest_shot` after its strike at the latest [s]: a loop left standing would
  // otherwise make one shot of hours at rest. With `thinning` > 0, a ball's sample is kept only
  // where it moved at least that far [m] from the last kept one (the last always kept), as the
  // real recordings are thinned: a ball at rest then costs the fits two samples, not hundreds.
  explicit ShotRecorder(double longest_shot = 60.0, double thinning = 0.0)
      : longest_shot_(longest_shot), thinning_(thinning) {}

  // The estimator's state at `utime` [us]: every track it knows of. A state older than the
  // latest is ignored (a late message).
  void State(std::int64_t utime, const std::vector<TrackSample>& tracks);
  // The cue struck track `track` at `utime` [us].
  void Strike(std::int64_t utime, std::int32_t track);
  // Closes the open shot, if any: at the end of a log, or once the balls are at rest (a node
  // that identifies between shots).
  void Finish();

  // The shots closed so far, in the order of their strikes; ids "1", "2", ... in that order.
  const std::vector<TrackedShot>& shots() const { return shots_; }
  // Per shot, the utime of the strike that started it [us]: the commanded stroke it played
  // (execution_noise_fit.h pairs them).
  const std::vector<std::int64_t>& strike_utimes() const { return strike_utimes_; }
  // Strikes that started no shot, and shots dropped for having no sample after the strike.
  int skipped() const { return skipped_; }

 private:
  struct Open {
    std::int64_t strike_utime = 0;
    std::int64_t start_utime = 0;  // of the shot's first sample
    std::vector<std::int32_t> tracks;  // of shot.balls, in order
    TrackedShot shot;
    // Per ball, its latest sample when thinning left it out: the shot's last is always kept.
    std::vector<std::optional<std::pair<double, Eigen::Vector2d>>> unkept;
  };

  double longest_shot_;
  double thinning_;
  std::optional<std::pair<std::int64_t, std::vector<TrackSample>>> latest_;
  std::optional<Open> open_;
  std::optional<std::int64_t> last_strike_;
  std::vector<TrackedShot> shots_;
  std::vector<std::int64_t> strike_utimes_;
  int skipped_ = 0;
};

}  // namespace billiard::shot_fit
