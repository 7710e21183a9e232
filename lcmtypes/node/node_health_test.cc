#include "lcmtypes/node/node_health.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "lcmtypes/message_checks.h"
#include "lcmtypes/names.h"
#include "lcmtypes/version.h"

namespace billiard::nodes {
namespace {

using std::chrono::microseconds;
using std::chrono::milliseconds;

TEST(NodeHealth, CountsAndReportsWhatHappened) {
  std::vector<std::string> log;
  NodeHealth health("test_node", [&log](const std::string& line) { log.push_back(line); });
  for (int i = 0; i < 5; ++i) health.Received();
  health.Published();
  health.Dropped("first reason");
  // The time of the last error is wall-clock time (what a status reader compares with its own).
  const auto wall_utime = [] {
    return std::chrono::duration_cast<microseconds>(
               std::chrono::system_clock::now().time_since_epoch())
        .count();
  };
  const std::int64_t before_error = wall_utime();
  health.Dropped("second reason");
  const std::int64_t after_error = wall_utime();
  health.Count("duplicate");
  health.Count("duplicate", 2);
  health.SetQueueDepth(3);
  // Latencies 1..100 us: nearest-rank median 50, 99th percentile 99.
  for (int us = 100; us >= 1; --us) health.Latency(microseconds(us));

  const node_status_t s = health.TakeStatus();
  EXPECT_EQ(messages::Check(s), "");
  EXPECT_EQ(s.node, "test_node");
  EXPECT_EQ(s.received, 5);
  EXPECT_EQ(s.published, 1);
  EXPECT_EQ(s.dropped, 2);
  EXPECT_EQ(s.last_error, "second reason");
  EXPECT_GE(s.last_error_utime, before_error);
  EXPECT_LE(s.last_error_utime, after_error);
  EXPECT_EQ(s.queue_depth, 3);
  EXPECT_EQ(s.latency_count, 100);
  EXPECT_DOUBLE_EQ(s.latency_p50_us, 50.0);
  EXPECT_DOUBLE_EQ(s.latency_p99_us, 99.0);
  EXPECT_DOUBLE_EQ(s.latency_max_us, 100.0);
  ASSERT_EQ(s.num_counters, 1);
  EXPECT_EQ(s.counter_names[0], "duplicate");
  EXPECT_EQ(s.counter_values[0], 3);
  EXPECT_EQ(log, (std::vector<std::string>{"dropped: first reason", "dropped: second reason"}));

  // Latency is per period; counts are totals.
  const node_status_t next = health.TakeStatus();
  EXPECT_EQ(next.latency_count, 0);
  EXPECT_EQ(next.latency_max_us, 0.0);
  EXPECT_EQ(next.received, 5);
  EXPECT_EQ(next.dropped, 2);
}

TEST(NodeHealth, ARefusalIsCountedUnderItsNameAndIsTheLastErrorButNotADrop) {
  std::vector<std::string> log;
  NodeHealth health("table_sim_node", [&log](const std::string& line) { log.push_back(line); });
  health.Refused("cue_blocked", "CUE_COMMAND 3: the gantry's cue meets ball 4");
  health.Refused("cue_blocked", "CUE_COMMAND 5: the gantry's cue meets the lower rail");
  EXPECT_EQ(health.counter("cue_blocked"), 2);
  EXPECT_EQ(health.dropped(), 0);
  EXPECT_EQ(health.last_error(), "CUE_COMMAND 5: the gantry's cue meets the lower rail");
  ASSERT_EQ(log.size(), 2u);
  EXPECT_EQ(log[0], "refused: CUE_COMMAND 3: the gantry's cue meets ball 4");
}

TEST(NodeHealth, AFloodOfRefusalsIsCountedButNotAllLogged) {
  std::vector<std::string> log;
  NodeHealth health("test_node", [&log](const std::string& line) { log.push_back(line); });
  for (int i = 0; i < 10000; ++i) health.Dropped("bad " + std::to_string(i));
  EXPECT_EQ(health.dropped(), 10000);
  EXPECT_EQ(health.last_error(), "bad 9999");
  ASSERT_EQ(log.size(), static_cast<std::size_t>(NodeHealth::kLogLinesPerSecond));

  // The first line of the next second says how many went unlogged.
  std::this_thread::sleep_for(milliseconds(1100));
  health.Dropped("later");
  ASSERT_EQ(log.size(), NodeHealth::kLogLinesPerSecond + 1u);
  const int not_logged = 10000 - NodeHealth::kLogLinesPerSecond;
  EXPECT_EQ(log.back(),
            "dropped: later (" + std::to_string(not_logged) + " earlier refusals not logged)");
}

TEST(NodeHealth, ALogThatThrowsDoesNotTakeTheNodeWithIt) {
  NodeHealth health("test_node", [](const std::string&) { throw std::runtime_error("disk full"); });
  EXPECT_NO_THROW(health.Dropped("anything"));
  EXPECT_EQ(health.dropped(), 1);
}

// Collects the statuses published on NODE_STATUS.
struct StatusSink {
  std::vector<node_status_t>* seen;
  void On(const lcm::ReceiveBuffer* rbuf, const std::string&) {
    node_status_t s;
    EXPECT_EQ(messages::DecodeChecked(rbuf->data, rbuf->data_size, s), "");
    seen->push_back(s);
  }
};

TEST(NodeHealth, AnnouncesItselfAtOnceThenPublishesOncePerPeriod) {
  lcm::LCM lcm("memq://");
  std::vector<node_status_t> seen;
  StatusSink sink{&seen};
  lcm.subscribe(messages::kNodeStatusChannel, &StatusSink::On, &sink);
  NodeHealth health(
      "test_node", [](const std::string&) {}, milliseconds(50));
  health.SetParameters("pool", "0123456789abcdef");
  health.PublishIfDue(lcm);  // the first call announces the node
  health.PublishIfDue(lcm);  // not yet due
  std::this_thread::sleep_for(milliseconds(60));
  health.Received();
  health.PublishIfDue(lcm);
  health.PublishIfDue(lcm);  // due again only a period later
  while (lcm.handleTimeout(0) > 0) {
  }
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen[0].received, 0);
  EXPECT_EQ(seen[1].received, 1);
  EXPECT_GE(seen[1].uptime_us, 50000);
  for (const node_status_t& s : seen) {
    EXPECT_EQ(s.params, "pool");
    EXPECT_EQ(s.params_hash, "0123456789abcdef");
    EXPECT_EQ(s.version, kVersion);
  }
}

TEST(NodeHealth, PublishesASettingAmongTheCountersAtOnceWhenAsked) {
  lcm::LCM lcm("memq://");
  std::vector<node_status_t> seen;
  StatusSink sink{&seen};
  lcm.subscribe(messages::kNodeStatusChannel, &StatusSink::On, &sink);
  NodeHealth health("test_node", [](const std::string&) {});
  health.Set(messages::kRealtimeClockSetting, 0);  // a setting of 0 is reported too
  health.Publish(lcm);
  health.PublishIfDue(lcm);  // the period starts again with the status published
  while (lcm.handleTimeout(0) > 0) {
  }
  ASSERT_EQ(seen.size(), 1u);
  ASSERT_EQ(seen[0].num_counters, 1);
  EXPECT_EQ(seen[0].counter_names[0], messages::kRealtimeClockSetting);
  EXPECT_EQ(seen[0].counter_values[0], 0);
}

}  // namespace
}  // namespace billiard::nodes
