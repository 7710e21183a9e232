#include "tools/billiard/node_status_command.h"

#include <algorithm>
#include <iostream>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <utility>

#include "lcmtypes/billiard/node_status_t.hpp"
#include "lcmtypes/message_checks.h"
#include "lcmtypes/names.h"
#include "lcmtypes/node/node_health.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

namespace {

struct NodeStatusArgs {
  std::string log;
};

// One node process: its name and when it started, which its statuses all give (utime - uptime)
// to within the scheduling jitter of one status.
struct Process {
  std::string node;
  std::int64_t started_ms;
  bool operator<(const Process& o) const {
    return std::tie(started_ms, node) < std::tie(o.started_ms, o.node);
  }
};

struct Reports {
  long statuses = 0;
  node_status_t last;
  int max_queue_depth = 0;
  double max_latency_p99_us = 0.0, max_latency_us = 0.0;
};

void Run(const NodeStatusArgs& args) {
  lcm::LogFile log(args.log, "r");
  if (!log.good()) throw UsageError("cannot read LCM log '" + args.log + "'");
  std::map<Process, Reports> processes;
  long malformed = 0;
  while (const lcm::LogEvent* e = log.readNextEvent()) {
    if (e->channel != messages::kNodeStatusChannel) continue;
    node_status_t s;
    if (!messages::DecodeChecked(e->data, static_cast<std::size_t>(e->datalen), s).empty()) {
      ++malformed;
      continue;
    }
    // Statuses a second apart: a start time rounded to 100 ms names the process.
    const std::int64_t started_ms = (s.utime - s.uptime_us) / 100000 * 100;
    Reports& r = processes[{s.node, started_ms}];
    ++r.statuses;
    r.max_queue_depth = std::max(r.max_queue_depth, static_cast<int>(s.queue_depth));
    r.max_latency_p99_us = std::max(r.max_latency_p99_us, s.latency_p99_us);
    r.max_latency_us = std::max(r.max_latency_us, s.latency_max_us);
    r.last = std::move(s);
  }
  nlohmann::json out = {{"processes", nlohmann::json::array()}, {"malformed", malformed}};
  for (const auto& [process, r] : processes) {
    nlohmann::json counters = nlohmann::json::object();
    for (int i = 0; i < r.last.num_counters; ++i) {
      counters[r.last.counter_names[i]] = r.last.counter_values[i];
    }
    out["processes"].push_back({{"node", process.node},
                                {"started_utime", r.last.utime - r.last.uptime_us},
                                {"uptime_s", 1e-6 * r.last.uptime_us},
                                {"params", r.last.params},
                                {"params_hash", r.last.params_hash},
                                {"version", r.last.version},
                                {"statuses", r.statuses},
                                {"received", r.last.received},
                                {"dropped", r.last.dropped},
                                {"published", r.last.published},
                                {"last_error", r.last.last_error},
                                {"counters", counters},
                                {"max_queue_depth", r.max_queue_depth},
                                {"max_latency_p99_us", r.max_latency_p99_us},
                                {"max_latency_us", r.max_latency_us}});
  }
  std::cout << out.dump() << std::endl;
}

}  // namespace

void AddNodeStatusCommand(CLI::App& app) {
  auto args = std::make_shared<NodeStatusArgs>();
  CLI::App* cmd = app.add_subcommand(
      "node-status", "Summarise the NODE_STATUS messages of an LCM log per node process (JSON)");
  cmd->add_option("LOG", args->log, "LCM log (lcm-logger, run_loop.sh --log)")->required();
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
