// node_status_t: strings and a counted array of strings, the layout with the most to walk.
#include "fuzz/support.h"

namespace billiard::fuzz {

std::vector<Bytes> Seeds() {
  node_status_t planner{};
  planner.utime = 1700000000000000;
  planner.node = "planner_node";
  planner.uptime_us = 3000000;
  planner.params = "pool";
  planner.params_hash = "0123456789abcdef";
  planner.version = "0.1.0";
  planner.received = 40;
  planner.dropped = 2;
  planner.published = 38;
  planner.last_error = "unknown spin value 9 (0-4, see shot_request_t)";
  planner.last_error_utime = 1699999999000000;
  planner.latency_count = 12;
  planner.latency_p50_us = 900.0;
  planner.latency_p99_us = 2500.0;
  planner.latency_max_us = 3100.0;
  planner.counter_names = {"duplicate", "stale_state", "busy"};
  planner.counter_values = {1, 0, 1};
  planner.num_counters = 3;

  node_status_t estimator{};
  estimator.utime = 1700000000000000;
  estimator.node = "estimator_node";
  return {Encode(planner), Encode(estimator)};
}

}  // namespace billiard::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  billiard::node_status_t m;
  billiard::fuzz::DecodeAndCheck(data, size, m);
  return 0;
}
