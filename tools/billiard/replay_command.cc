#include "tools/billiard/replay_command.h"

#include <cstdint>
#include <filesystem>
#include <iostream>
#include <lcm/lcm-cpp.hpp>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "estimator/node/estimator_node.h"
#include "lcmtypes/billiard/cue_command_t.hpp"
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

void Run(const ReplayArgs& args) {
  lcm::LogFile log(args.log, "r");
  if (!log.good()) throw UsageError("cannot read LCM log '" + args.log + "'");
  const physics::ModelParameters params = LoadParametersOption(args.params);
  camera::CameraModel camera;
  try {
    camera = args.camera.empty() ? camera::CameraModel::Overhead(params.table, 1280, 720)
                                 : camera::LoadCameraModel(args.camera);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--camera: ") + e.what());
  }

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
  Outputs out;
  lcm.subscribe(messages::kTableStateChannel, &Outputs::OnState, &out);
  lcm.subscribe(messages::kCueCommandChannel, &Outputs::OnCommand, &out);

  std::vector<Compared> recorded_states, recorded_commands;
  long events = 0, inputs = 0, frames = 0;
  std::string clock = "unknown";
  for (const lcm::LogEvent* e; (e = log.readNextEvent()); ++events) {
    if (const std::string said = ClockOf(*e); !said.empty()) clock = said;
    if (clock == "realtime") {
      RefuseReplay(args, clock,
                   "'" + args.log +
                       "' was recorded with --realtime: its nodes answered as the "
                       "wall clock let them, so it is not replayable bit for bit");
    }
    if (e->channel == messages::kCameraImageChannel ||
        e->channel == messages::kShotRequestChannel) {
      ++inputs;
      frames += e->channel == messages::kCameraImageChannel;
      lcm.publish(e->channel, e->data, e->datalen);
      nodes::HandleUntilIdle(lcm, [&planner] { return planner.Work(); });
    } else if (e->channel == messages::kTableStateChannel) {
      recorded_states.push_back(RecordedMessage(*e, events));
    } else if (e->channel == messages::kCueCommandChannel) {
      recorded_commands.push_back(RecordedMessage(*e, events));
    }
  }
  if (events == 0) RejectEmptyLog(args.log);
  if (frames == 0) {
    RefuseReplay(args, clock,
                 "'" + args.log +
                     "' has no CAMERA_IMAGE frames (run_loop.sh --log-frames "
                     "none): nothing to replay through the estimator");
  }

  const Comparison states =
      Compare<table_state_t>(messages::kTableStateChannel, recorded_states, out.states);
  const Comparison commands =
      Compare<cue_command_t>(messages::kCueCommandChannel, recorded_commands, out.commands);
  // The first difference in the log's order: a message missing from the recording comes last.
  std::optional<MessageDifference> first = states.first_difference;
  if (!first || (commands.first_difference && commands.first_difference->event < first->event)) {
    first = commands.first_difference;
  }
  const bool same = !first && commands.recorded > 0;
  const auto describe = [](const Comparison& c) {
    return nlohmann::json{{"recorded", c.recorded},
                          {"replayed", c.replayed},
                          {"identical", c.identical},
                          {"first_difference", ToJson(c.first_difference)}};
  };
  if (args.json) {
    std::cout << nlohmann::json{{"inputs", inputs},
                                {"clock", clock},
                                {"table_states", describe(states)},
                                {"cue_commands", describe(commands)},
                                {"first_difference", ToJson(first)},
                                {"identical", same}}
                     .dump()
              << std::endl;
  }
  std::cerr << "replay: " << inputs << " inputs; TABLE_STATE " << states.identical << " of "
            << states.recorded << " identical, CUE_COMMAND " << commands.identical << " of "
            << commands.recorded << " identical (all fields but solve_us)" << std::endl;
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
  cmd->add_option("--robot", args->robot, "As the planner had (default gantry)")->capture_default_str();
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
