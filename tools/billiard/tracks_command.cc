#include "tools/billiard/tracks_command.h"

#include <cstdint>
#include <iostream>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "estimator/ball_class.h"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "lcmtypes/message_checks.h"
#include "lcmtypes/names.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

namespace {

struct TracksArgs {
  std::string log;
};

// One track of the estimator's, over the states that carry it: its first and its latest.
struct Track {
  long states = 0;
  ball_state_t first, last;
};

// The states of the log: how many, over what time, and each track.
struct Tracks {
  long states = 0, malformed = 0;
  std::int64_t first_utime = 0, last_utime = 0;
  int balls_at_end = 0;
  std::map<int, Track> tracks;

  void Add(const table_state_t& state) {
    if (states++ == 0) first_utime = state.utime;
    last_utime = state.utime;
    balls_at_end = state.num_balls;
    for (const ball_state_t& b : state.balls) {
      Track& track = tracks[b.ball_id];
      if (track.states++ == 0) track.first = b;
      track.last = b;
    }
  }
};

nlohmann::json TrackJson(int id, const Track& t, std::int64_t start_utime) {
  const auto seconds = [start_utime](std::int64_t utime) { return 1e-6 * (utime - start_utime); };
  return {{"id", id},
          {"states", t.states},
          {"class", estimator::BallClassName(static_cast<estimator::BallClass>(t.last.ball_class))},
          {"class_confidence", t.last.class_confidence},
          {"first_s", seconds(t.first.utime)},
          {"last_s", seconds(t.last.utime)},
          {"first", {t.first.position[0], t.first.position[1]}},
          {"last", {t.last.position[0], t.last.position[1]}},
          {"last_velocity", {t.last.velocity[0], t.last.velocity[1]}}};
}

void Run(const TracksArgs& args) {
  lcm::LogFile log(args.log, "r");
  if (!log.good()) throw UsageError("cannot read LCM log '" + args.log + "'");
  Tracks tracks;
  while (const lcm::LogEvent* e = log.readNextEvent()) {
    if (e->channel != messages::kTableStateChannel) continue;
    table_state_t state;
    if (!messages::DecodeChecked(e->data, static_cast<std::size_t>(e->datalen), state).empty()) {
      ++tracks.malformed;
      continue;
    }
    tracks.Add(state);
  }
  nlohmann::json out = {{"states", tracks.states},
                        {"seconds", 1e-6 * (tracks.last_utime - tracks.first_utime)},
                        {"balls_at_end", tracks.balls_at_end},
                        {"tracks", nlohmann::json::array()},
                        {"malformed", tracks.malformed}};
  for (const auto& [id, track] : tracks.tracks) {
    out["tracks"].push_back(TrackJson(id, track, tracks.first_utime));
  }
  std::cout << out.dump() << std::endl;
}

}  // namespace

void AddTracksCommand(CLI::App& app) {
  auto args = std::make_shared<TracksArgs>();
  CLI::App* cmd = app.add_subcommand(
      "tracks",
      "Summarise the estimator's TABLE_STATE messages of an LCM log track by track (JSON)");
  cmd->add_option("LOG", args->log, "LCM log (lcm-logger, run_loop.sh --log)")->required();
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
