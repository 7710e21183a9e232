#include "tools/billiard/replay_command.h"

#include <cstdint>
#include <filesystem>
#include <iostream>
#include <lcm/lcm-cpp.hpp>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "estimator/node/estimator_node.h"
#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/image_t.hpp"
#include "lcmtypes/billiard/node_status_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "lcmtypes/message_checks.h"
#include "lcmtypes/names.h"
#include "lcmtypes/node/node_loop.h"
#include "planner/node/planner_node.h"
#include "sim/camera/camera_model.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/robots.h"
#include "tools/billiard/command_line.h"
#include "tools/billiard/message_difference.h"

namespace billiard::cli {

namespace {

struct ReplayArgs {
  std::string log;
  std::string params = params::kDefaultParameterSet;
  std::string camera;
  std::string robot = params::kDefaultRobot;
  bool json = false;
};

using Bytes = std::vector<std::uint8_t>;

// A cue command without its planning wall time, the one field that is not a function of the
// messages (cue_command_t.solve_us).
Bytes WithoutWallTime(const void* data, int size) {
  cue_command_t c;
  if (c.decode(data, 0, size) != size) return {};
  c.solve_us = 0.0;
  Bytes bytes(c.getEncodedSize());
  c.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

// A compared message as the comparison needs it: its bytes (a cue command's without solve_us)
// and, when recorded, where it is in the log.
struct Compared {
  Bytes bytes;
  long event = std::numeric_limits<long>::max();  // replayed messages come after every recorded
};

Compared RecordedMessage(const lcm::LogEvent& e, long event) {
  const auto* p = static_cast<const std::uint8_t*>(e.data);
  if (e.channel == messages::kCueCommandChannel) return {WithoutWallTime(e.data, e.datalen), event};
  return {Bytes(p, p + e.datalen), event};
}

// A frame's utime; nothing when it does not decode (the estimator drops it too).
std::optional<std::int64_t> FrameUtime(const lcm::LogEvent& e) {
  image_t frame;
  if (!messages::Decode(e.data, static_cast<std::size_t>(e.datalen), frame).empty()) {
    return std::nullopt;
  }
  return frame.utime;
}

// Collects what the fresh nodes publish.
struct Outputs {
  std::vector<Compared> states, commands;
  void OnState(const lcm::ReceiveBuffer* rbuf, const std::string&) {
    const auto* p = static_cast<const std::uint8_t*>(rbuf->data);
    states.push_back({Bytes(p, p + rbuf->data_size)});
  }
  void OnCommand(const lcm::ReceiveBuffer* rbuf, const std::string&) {
    commands.push_back({WithoutWallTime(rbuf->data, static_cast<int>(rbuf->data_size))});
  }
};

// The first message of a channel that differs: its index among the channel's messages, the
// recorded (else the replayed) one's utime, and its first field that differs, or why there is
// no field to name (one side has no message at that index, or one that does not decode).
struct MessageDifference {
  std::string channel;
  long index = 0;
  std::int64_t utime = 0;
  long event = 0;  // of the recorded message in the log (past its end when none is recorded)
  std::optional<FieldDifference> field;
  std::string reason;
};

// How the sequences of one channel's messages compare.
struct Comparison {
  long recorded = 0, replayed = 0, identical = 0;
  std::optional<MessageDifference> first_difference;
};

// Decodes both messages at a differing index and finds the field.
template <class Message>
MessageDifference Locate(const std::string& channel, long index, const Compared* recorded,
                         const Compared* replayed) {
  const auto decode = [](const Compared* m, Message& out) {
    return m && messages::Decode(m->bytes.data(), m->bytes.size(), out).empty();
  };
  Message a, b;
  const bool have_a = decode(recorded, a), have_b = decode(replayed, b);
  MessageDifference d;
  d.channel = channel;
  d.index = index;
  d.utime = have_a ? a.utime : have_b ? b.utime : 0;
  d.event = recorded ? recorded->event : replayed->event;
  if (have_a && have_b) {
    d.field = FirstFieldDifference(a, b);
  } else if (!recorded || !replayed) {
    d.reason = recorded ? "recorded, not replayed" : "replayed, not recorded";
  } else {
    d.reason = std::string(have_a ? "the replayed" : "the recorded") + " message does not decode";
  }
  return d;
}

template <class Message>
Comparison Compare(const std::string& channel, const std::vector<Compared>& recorded,
                   const std::vector<Compared>& replayed) {
  Comparison c;
  c.recorded = static_cast<long>(recorded.size());
  c.replayed = static_cast<long>(replayed.size());
  for (std::size_t i = 0; i < std::max(recorded.size(), replayed.size()); ++i) {
    const Compared* a = i < recorded.size() ? &recorded[i] : nullptr;
    const Compared* b = i < replayed.size() ? &replayed[i] : nullptr;
    if (a && b && a->bytes == b->bytes) {
      ++c.identical;
    } else if (!c.first_difference) {
      c.first_difference = Locate<Message>(channel, static_cast<long>(i), a, b);
    }
  }
  return c;
}

nlohmann::json ToJson(const std::optional<MessageDifference>& d) {
  if (!d) return nullptr;
  nlohmann::json j = {{"channel", d->channel}, {"index", d->index}, {"utime", d->utime}};
  if (d->field) {
    j["field"] = d->field->field;
    j["recorded"] = d->field->recorded;
    j["replayed"] = d->field->replayed;
  } else {
    j["reason"] = d->reason;
  }
  return j;
}

// "TABLE_STATE 12 (utime 400000): balls[0].position[1]: recorded 0.6351 replayed 0.635"
std::string Describe(const MessageDifference& d) {
  const std::string message =
      d.channel + " " + std::to_string(d.index) + " (utime " + std::to_string(d.utime) + "): ";
  if (!d.field) return message + d.reason;
  return message + d.field->field + ": recorded " + d.field->recorded.dump() + " replayed " +
         d.field->replayed.dump();
}

// How the recorded session was clocked, as table_sim_node said on NODE_STATUS; empty while the
// log has not said (a log recorded before the simulator said it).
std::string ClockOf(const lcm::LogEvent& e) {
  node_status_t s;
  if (e.channel != messages::kNodeStatusChannel ||
      !messages::DecodeChecked(e.data, static_cast<std::size_t>(e.datalen), s).empty()) {
    return "";
  }
  for (int i = 0; i < s.num_counters; ++i) {
    if (s.counter_names[i] == messages::kRealtimeClockSetting) {
      return s.counter_values[i] ? "realtime" : "lockstep";
    }
  }
  return "";
}

// A log the replay cannot use: said in one line (and as JSON with --json), exit 3.
[[noreturn]] void RefuseReplay(const ReplayArgs& args, const std::string& clock,
                               const std::string& reason) {
  if (args.json) {
    std::cout << nlohmann::json{{"identical", false},
                                {"replayable", false},
                                {"clock", clock},
                                {"reason", reason}}
                     .dump()
              << std::endl;
  }
  throw Refused(reason);
}

// A file that holds no event is not a log to replay: an empty file or something else.
[[noreturn]] void RejectEmptyLog(const std::string& path) {
  std::error_code error;
  if (std::filesystem::file_size(path, error) == 0 && !error) {
    throw UsageError("'" + path + "' is empty: no LCM log to replay");
  }
  throw UsageError("'" + path + "' is not an LCM log (no event in it)");
}

camera::CameraModel ReplayCamera(const ReplayArgs& args, const physics::ModelParameters& params) {
  try {
    return args.camera.empty() ? camera::CameraModel::Overhead(params.table, 1280, 720)
                               : camera::LoadCameraModel(args.camera);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--camera: ") + e.what());
  }
}

// A recorded TABLE_STATE: the estimator answered a CAMERA_IMAGE of its utime.
struct AnsweredFrame {
  std::int64_t utime = 0;
  long frames_before = 0;  // CAMERA_IMAGE events in the log before the state
  long event = 0;
};

// What the log held and what the fresh nodes made of it.
struct ReplayedLog {
  std::vector<Compared> recorded_states, recorded_commands;
  Outputs replayed;
  std::vector<AnsweredFrame> answered;
  std::unordered_map<std::int64_t, long> frame_events;  // a frame's utime: its first event
  long events = 0, inputs = 0, frames = 0;
  std::string clock = "unknown";
};

// Reads the log once, feeding its frames and requests to fresh nodes as it goes.
ReplayedLog ReplayLog(const ReplayArgs& args, lcm::LogFile& log) {
  const physics::ModelParameters params = LoadParametersOption(args.params);
  const camera::CameraModel camera = ReplayCamera(args, params);
  // The nodes in this process, on an in-memory LCM: each input is handled to the end before the
  // next, which is the order the lockstep run had.
  lcm::LCM lcm("memq://");
  const auto quiet = [](const std::string&) {};
  // A camera file is the rig's calibration, whose table the node used (estimator_node --camera).
  estimator::EstimatorOptions options;
  options.table_from_camera = !args.camera.empty();
  estimator_node::EstimatorNode estimator(lcm, camera, params, options, {}, quiet);
  planner_node::PlannerNodeOptions planning;
  planning.pot.robot = LoadRobotOption(args.robot);
  planner_node::PlannerNode planner(lcm, params, planning, quiet);
  ReplayedLog r;
  lcm.subscribe(messages::kTableStateChannel, &Outputs::OnState, &r.replayed);
  lcm.subscribe(messages::kCueCommandChannel, &Outputs::OnCommand, &r.replayed);

  for (const lcm::LogEvent* e; (e = log.readNextEvent()); ++r.events) {
    if (const std::string said = ClockOf(*e); !said.empty()) r.clock = said;
    if (r.clock == "realtime") {
      RefuseReplay(args, r.clock,
                   "'" + args.log +
                       "' was recorded with --realtime: its nodes answered as the "
                       "wall clock let them, so it is not replayable bit for bit");
    }
    if (e->channel == messages::kCameraImageChannel ||
        e->channel == messages::kShotRequestChannel) {
      ++r.inputs;
      if (e->channel == messages::kCameraImageChannel) {
        ++r.frames;
        if (const auto utime = FrameUtime(*e)) r.frame_events.emplace(*utime, r.events);
      }
      lcm.publish(e->channel, e->data, e->datalen);
      nodes::HandleUntilIdle(lcm, [&planner] { return planner.Work(); });
    } else if (e->channel == messages::kTableStateChannel) {
      r.recorded_states.push_back(RecordedMessage(*e, r.events));
      if (table_state_t s;
          messages::Decode(e->data, static_cast<std::size_t>(e->datalen), s).empty()) {
        r.answered.push_back({s.utime, r.frames, r.events});
      }
    } else if (e->channel == messages::kCueCommandChannel) {
      r.recorded_commands.push_back(RecordedMessage(*e, r.events));
    }
  }
  return r;
}

// Messages a node had that the log does not hold: lost by lcm-logger, the one receiver a lockstep
// run does not wait for (UDP multicast promises no delivery). The log is at fault, not the nodes,
// and the first is said as such, before the messages it puts out of step.
struct LostMessages {
  long count = 0;
  std::optional<MessageDifference> first;

  void Add(const std::string& channel, long index, std::int64_t utime, long event,
           const std::string& reason) {
    if (count++ > 0) return;
    first = MessageDifference{channel, index, utime, event, std::nullopt, reason};
  }
};

// The frames the estimator answered (their TABLE_STATE is recorded) that the log does not hold.
// The replay's estimator never sees them, so its states are a frame out of step from the first.
LostMessages FindLostFrames(const ReplayedLog& r) {
  LostMessages lost;
  for (const AnsweredFrame& a : r.answered) {
    if (r.frame_events.count(a.utime)) continue;
    lost.Add(messages::kCameraImageChannel, a.frames_before, a.utime, a.event,
             "not in the log, though a recorded TABLE_STATE answers it: lcm-logger lost it");
  }
  return lost;
}

// The estimator's states of frames the log holds, which the replay's estimator published and the
// log does not hold: the recorded states are a state out of step with the replayed from the first.
LostMessages FindLostStates(const ReplayedLog& r) {
  std::unordered_set<std::int64_t> recorded;
  for (const AnsweredFrame& a : r.answered) recorded.insert(a.utime);
  LostMessages lost;
  for (std::size_t i = 0; i < r.replayed.states.size(); ++i) {
    const Bytes& bytes = r.replayed.states[i].bytes;
    table_state_t state;
    if (!messages::Decode(bytes.data(), bytes.size(), state).empty()) continue;
    const auto frame = r.frame_events.find(state.utime);
    if (recorded.count(state.utime) || frame == r.frame_events.end()) continue;
    lost.Add(messages::kTableStateChannel, static_cast<long>(i), state.utime, frame->second,
             "not in the log, though its frame is and the estimator answers it: lcm-logger "
             "lost it");
  }
  return lost;
}

// The earlier in the log of two differences.
std::optional<MessageDifference> Earlier(const std::optional<MessageDifference>& a,
                                         const std::optional<MessageDifference>& b) {
  return !a || (b && b->event < a->event) ? b : a;
}

nlohmann::json ToJson(const Comparison& c) {
  return nlohmann::json{{"recorded", c.recorded},
                        {"replayed", c.replayed},
                        {"identical", c.identical},
                        {"first_difference", ToJson(c.first_difference)}};
}

void Run(const ReplayArgs& args) {
  lcm::LogFile log(args.log, "r");
  if (!log.good()) throw UsageError("cannot read LCM log '" + args.log + "'");
  const ReplayedLog r = ReplayLog(args, log);
  if (r.events == 0) RejectEmptyLog(args.log);
  if (r.frames == 0) {
    RefuseReplay(args, r.clock,
                 "'" + args.log +
                     "' has no CAMERA_IMAGE frames (run_loop.sh --log-frames "
                     "none): nothing to replay through the estimator");
  }

  const Comparison states =
      Compare<table_state_t>(messages::kTableStateChannel, r.recorded_states, r.replayed.states);
  const Comparison commands = Compare<cue_command_t>(messages::kCueCommandChannel,
                                                     r.recorded_commands, r.replayed.commands);
  const LostMessages lost_frames = FindLostFrames(r), lost_states = FindLostStates(r);
  // The first difference in the log's order: a message missing from the recording comes last.
  const std::optional<MessageDifference> first =
      Earlier(Earlier(Earlier(lost_frames.first, lost_states.first), states.first_difference),
              commands.first_difference);
  const bool same = !first && commands.recorded > 0;
  if (args.json) {
    std::cout << nlohmann::json{{"inputs", r.inputs},
                                {"clock", r.clock},
                                {"table_states", ToJson(states)},
                                {"cue_commands", ToJson(commands)},
                                {"lost_frames", lost_frames.count},
                                {"lost_states", lost_states.count},
                                {"first_difference", ToJson(first)},
                                {"identical", same}}
                     .dump()
              << std::endl;
  }
  std::cerr << "replay: " << r.inputs << " inputs; TABLE_STATE " << states.identical << " of "
            << states.recorded << " identical, CUE_COMMAND " << commands.identical << " of "
            << commands.recorded << " identical (all fields but solve_us)" << std::endl;
  if (lost_frames.count + lost_states.count > 0) {
    std::cerr << "replay: the log lacks " << lost_frames.count << " frame(s) and "
              << lost_states.count
              << " state(s) the estimator had, lost by lcm-logger: the replay cannot match from "
                 "the first on"
              << std::endl;
  }
  if (first) std::cerr << "replay: first difference: " << Describe(*first) << std::endl;
  if (!same) {
    throw Refused(first ? "the replay differs from the recording"
                        : "the recording has no CUE_COMMAND to compare");
  }
}

}  // namespace

void AddReplayCommand(CLI::App& app) {
  auto args = std::make_shared<ReplayArgs>();
  CLI::App* cmd = app.add_subcommand(
      "replay",
      "Feed a recorded loop's CAMERA_IMAGE and SHOT_REQUEST to fresh estimator and planner nodes "
      "and compare their TABLE_STATE and CUE_COMMAND with the recorded ones (exit 3 if any "
      "differs, naming the first message and field that do, or if the log was recorded with "
      "--realtime or without frames; exit 2 if LOG is no LCM log)");
  cmd->add_option("LOG", args->log, "LCM log (run_loop.sh --log FILE)")->required();
  cmd->add_option("--params", args->params, "As the loop's nodes had (default pool)")
      ->capture_default_str();
  cmd->add_option("--camera", args->camera, "Camera model JSON, as the estimator had");
  cmd->add_option("--robot", args->robot, "As the planner had (default gantry)")
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
