#include "lcmtypes/node/node_health.h"

#include "lcmtypes/names.h"
#include "lcmtypes/version.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace billiard::nodes {

namespace {

std::int64_t WallUtime() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// The q-quantile of `values` by the nearest-rank rule (sorts them).
double Quantile(std::vector<double>& values, double q) {
  if (values.empty()) return 0.0;
  const auto rank = static_cast<std::size_t>(std::ceil(q * values.size()));
  const std::size_t k = std::min(values.size() - 1, rank == 0 ? 0 : rank - 1);
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[k];
}

}  // namespace

NodeHealth::NodeHealth(std::string node, Log log, Clock::duration period)
    : node_(std::move(node)), log_(std::move(log)), period_(period) {}

void NodeHealth::Dropped(const std::string& why) {
  ++dropped_;
  Record("dropped: ", why);
}

void NodeHealth::Refused(const std::string& counter, const std::string& why) {
  Count(counter);
  Record("refused: ", why);
}

void NodeHealth::Record(const char* what, const std::string& why) {
  last_error_ = why;
  last_error_utime_ = WallUtime();
  const Clock::time_point now = Clock::now();
  if (now - log_second_ >= std::chrono::seconds(1)) {
    log_second_ = now;
    log_lines_ = 0;
  }
  if (log_lines_ >= kLogLinesPerSecond) {
    ++not_logged_;
    return;
  }
  ++log_lines_;
  std::string line = what + why;
  if (not_logged_ > 0) {
    line += " (" + std::to_string(not_logged_) + " earlier refusals not logged)";
    not_logged_ = 0;
  }
  try {
    log_(line);
  } catch (...) {  // a log that fails must not take the node with it
  }
}

void NodeHealth::Latency(Clock::duration latency) {
  const double us = std::chrono::duration<double, std::micro>(latency).count();
  ++latency_count_;
  latency_max_us_ = std::max(latency_max_us_, us);
  if (latencies_us_.size() < kMaxLatencySamples) latencies_us_.push_back(us);
}

std::int64_t NodeHealth::counter(const std::string& name) const {
  const auto it = counters_.find(name);
  return it == counters_.end() ? 0 : it->second;
}

node_status_t NodeHealth::TakeStatus() {
  node_status_t s{};
  s.utime = WallUtime();
  s.node = node_;
  s.params = params_;
  s.params_hash = params_hash_;
  s.version = kVersion;
  s.uptime_us =
      std::chrono::duration_cast<std::chrono::microseconds>(Clock::now() - start_).count();
  s.received = received_;
  s.dropped = dropped_;
  s.published = published_;
  s.last_error = last_error_;
  s.last_error_utime = last_error_utime_;
  s.latency_count = static_cast<std::int32_t>(std::min<std::int64_t>(latency_count_, INT32_MAX));
  s.latency_p50_us = Quantile(latencies_us_, 0.5);
  s.latency_p99_us = Quantile(latencies_us_, 0.99);
  s.latency_max_us = latency_max_us_;
  s.queue_depth = queue_depth_;
  for (const auto& [name, value] : counters_) {
    s.counter_names.push_back(name);
    s.counter_values.push_back(value);
  }
  s.num_counters = static_cast<std::int32_t>(counters_.size());
  latencies_us_.clear();
  latency_count_ = 0;
  latency_max_us_ = 0.0;
  return s;
}

void NodeHealth::Publish(lcm::LCM& lcm) {
  announced_ = true;
  last_status_ = Clock::now();
  const node_status_t status = TakeStatus();
  lcm.publish(messages::kNodeStatusChannel, &status);
}

void NodeHealth::PublishIfDue(lcm::LCM& lcm) {
  // The first status goes out at once: it tells the others the node is there, and with which
  // physics.
  if (!announced_ || Clock::now() - last_status_ >= period_) Publish(lcm);
}

}  // namespace billiard::nodes
