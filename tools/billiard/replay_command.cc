#include "tools/billiard/replay_command.h"

#include <iostream>
#include <lcm/lcm-cpp.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "estimator/node/estimator_node.h"
#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "lcmtypes/names.h"
#include "lcmtypes/node/node_loop.h"
#include "planner/node/planner_node.h"
#include "sim/camera/camera_model.h"
#include "sim/params/parameter_sets.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

namespace {

struct ReplayArgs {
  std::string log;
  std::string params = params::kDefaultParameterSet;
  std::string camera;
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

// Collects what the fresh nodes publish.
struct Outputs {
  std::vector<Bytes> states, commands;
  void OnState(const lcm::ReceiveBuffer* rbuf, const std::string&) {
    const auto* p = static_cast<const std::uint8_t*>(rbuf->data);
    states.emplace_back(p, p + rbuf->data_size);
  }
  void OnCommand(const lcm::ReceiveBuffer* rbuf, const std::string&) {
    commands.push_back(WithoutWallTime(rbuf->data, static_cast<int>(rbuf->data_size)));
  }
};

// Where two sequences of messages first differ (-1: identical), and how many match in order.
struct Comparison {
  long recorded = 0, replayed = 0, identical = 0, first_difference = -1;
};

Comparison Compare(const std::vector<Bytes>& recorded, const std::vector<Bytes>& replayed) {
  Comparison c{static_cast<long>(recorded.size()), static_cast<long>(replayed.size())};
  for (std::size_t i = 0; i < std::max(recorded.size(), replayed.size()); ++i) {
    if (i < recorded.size() && i < replayed.size() && recorded[i] == replayed[i]) {
      ++c.identical;
    } else if (c.first_difference < 0) {
      c.first_difference = static_cast<long>(i);
    }
  }
  return c;
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
  estimator_node::EstimatorNode estimator(lcm, camera, params, {}, {}, quiet);
  planner_node::PlannerNode planner(lcm, params, {}, quiet);
  Outputs out;
  lcm.subscribe(messages::kTableStateChannel, &Outputs::OnState, &out);
  lcm.subscribe(messages::kCueCommandChannel, &Outputs::OnCommand, &out);

  std::vector<Bytes> recorded_states, recorded_commands;
  long inputs = 0;
  while (const lcm::LogEvent* e = log.readNextEvent()) {
    const auto* p = static_cast<const std::uint8_t*>(e->data);
    if (e->channel == messages::kCameraImageChannel ||
        e->channel == messages::kShotRequestChannel) {
      ++inputs;
      lcm.publish(e->channel, e->data, e->datalen);
      nodes::HandleUntilIdle(lcm, [&planner] { return planner.Work(); });
    } else if (e->channel == messages::kTableStateChannel) {
      recorded_states.emplace_back(p, p + e->datalen);
    } else if (e->channel == messages::kCueCommandChannel) {
      recorded_commands.push_back(WithoutWallTime(e->data, e->datalen));
    }
  }
  const Comparison states = Compare(recorded_states, out.states);
  const Comparison commands = Compare(recorded_commands, out.commands);
  const bool same = states.first_difference < 0 && commands.first_difference < 0 &&
                    commands.recorded > 0;
  const auto describe = [](const Comparison& c) {
    return nlohmann::json{{"recorded", c.recorded},
                          {"replayed", c.replayed},
                          {"identical", c.identical},
                          {"first_difference", c.first_difference}};
  };
  if (args.json) {
    std::cout << nlohmann::json{{"inputs", inputs},
                                {"table_states", describe(states)},
                                {"cue_commands", describe(commands)},
                                {"identical", same}}
                     .dump()
              << std::endl;
  }
  std::cerr << "replay: " << inputs << " inputs; TABLE_STATE " << states.identical << " of "
            << states.recorded << " identical, CUE_COMMAND " << commands.identical << " of "
            << commands.recorded << " identical (all fields but solve_us)" << std::endl;
  if (!same) throw Refused("the replay differs from the recording");
}

}  // namespace

void AddReplayCommand(CLI::App& app) {
  auto args = std::make_shared<ReplayArgs>();
  CLI::App* cmd = app.add_subcommand(
      "replay",
      "Feed a recorded loop's CAMERA_IMAGE and SHOT_REQUEST to fresh estimator and planner nodes "
      "and compare their TABLE_STATE and CUE_COMMAND with the recorded ones (exit 3 if any "
      "differs)");
  cmd->add_option("LOG", args->log, "LCM log (run_loop.sh --log FILE)")->required();
  cmd->add_option("--params", args->params, "As the loop's nodes had (default pool)")
      ->capture_default_str();
  cmd->add_option("--camera", args->camera, "Camera model JSON, as the estimator had");
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
