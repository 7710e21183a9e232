#include "tools/billiard/logged_shots.h"

#include <algorithm>
#include <lcm/lcm-cpp.hpp>

#include "lcmtypes/billiard/table_state_t.hpp"
#include "lcmtypes/message_checks.h"
#include "lcmtypes/names.h"
#include "sim/shot_fit/shot_recorder.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

namespace {

std::vector<shot_fit::TrackSample> Samples(const table_state_t& state) {
  std::vector<shot_fit::TrackSample> tracks;
  for (const ball_state_t& b : state.balls)
    tracks.push_back({b.ball_id, {b.position[0], b.position[1]}});
  return tracks;
}

// The ball of `to` nearest track `track` of `from`; `track` itself when `from` has no such track
// or `to` no ball.
std::int32_t NearestBall(const std::vector<shot_fit::TrackSample>& from, std::int32_t track,
                         const std::vector<shot_fit::TrackSample>& to) {
  const auto struck = std::find_if(from.begin(), from.end(),
                                   [&](const shot_fit::TrackSample& s) { return s.track == track; });
  if (struck == from.end() || to.empty()) return track;
  const auto nearest = std::min_element(
      to.begin(), to.end(), [&](const shot_fit::TrackSample& a, const shot_fit::TrackSample& b) {
        return (a.position - struck->position).squaredNorm() <
               (b.position - struck->position).squaredNorm();
      });
  return nearest->track;
}

}  // namespace

LoggedShots ReadLoggedShots(const std::string& path, bool truth) {
  lcm::LogFile log(path, "r");
  if (!log.good()) throw UsageError("cannot read LCM log '" + path + "'");
  shot_fit::ShotRecorder recorder;
  LoggedShots out;
  std::vector<shot_fit::TrackSample> estimated, true_balls;  // the latest of each
  const std::string samples_channel =
      truth ? messages::kTableTruthChannel : messages::kTableStateChannel;
  for (const lcm::LogEvent* e; (e = log.readNextEvent()); ++out.events) {
    const auto size = static_cast<std::size_t>(e->datalen);
    if (e->channel == messages::kTableStateChannel || e->channel == messages::kTableTruthChannel) {
      table_state_t state;
      if (!messages::DecodeChecked(e->data, size, state).empty()) {
        ++out.undecodable;
        continue;
      }
      (e->channel == messages::kTableStateChannel ? estimated : true_balls) = Samples(state);
      if (e->channel != samples_channel) continue;
      ++out.states;
      recorder.State(state.utime, truth ? true_balls : estimated);
    } else if (e->channel == messages::kCueCommandChannel) {
      cue_command_t command;
      if (!messages::DecodeChecked(e->data, size, command).empty()) {
        ++out.undecodable;
      } else if (command.status != cue_command_t::STATUS_OK) {
        ++out.refused;
      } else {
        ++out.strikes;
        out.commands.push_back(command);
        recorder.Strike(command.utime, truth ? NearestBall(estimated, command.ball_id, true_balls)
                                             : command.ball_id);
      }
    }
  }
  recorder.Finish();
  if (out.events == 0) throw UsageError("'" + path + "' is empty or not an LCM log");
  out.shots = recorder.shots();
  out.strike_utimes = recorder.strike_utimes();
  out.skipped = recorder.skipped();
  if (out.shots.empty()) {
    throw UsageError("'" + path + "' holds no commanded strike followed by " +
                     (truth ? "the simulator's truth" : "the estimator's tracks") + " (" + std::to_string(out.strikes) + " strikes, " +
                     std::to_string(out.states) + " table states): nothing to identify from");
  }
  return out;
}

}  // namespace billiard::cli
