// `billiard tracks LOG` as a user runs it: the estimator's states of a written log, track by
// track (a ball rolling, a ball at rest, a track that came and went), the other channels and a
// damaged state passed over; a log that cannot be read is a usage error.
#include <gtest/gtest.h>

#include <lcm/lcm-cpp.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lcmtypes/billiard/table_state_t.hpp"
#include "lcmtypes/names.h"
#include "tests/support/billiard_command.h"

namespace {

using billiard::ball_state_t;
using billiard::table_state_t;
using billiard::testing::Billiard;
using billiard::testing::CommandResult;
using billiard::testing::OneObject;

void WriteEvent(lcm::LogFile& log, const std::string& channel, std::vector<std::uint8_t> bytes) {
  lcm::LogEvent e{};
  e.channel = channel;
  e.datalen = static_cast<std::int32_t>(bytes.size());
  e.data = bytes.data();
  ASSERT_EQ(log.writeEvent(&e), 0);
}

std::vector<std::uint8_t> Encoded(const table_state_t& state) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(state.getEncodedSize()));
  state.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

ball_state_t Ball(int id, std::int8_t ball_class, double x, double y, double vx) {
  ball_state_t b{};
  b.ball_id = id;
  b.ball_class = ball_class;
  b.class_confidence = 0.9f;
  b.position[0] = x;
  b.position[1] = y;
  b.velocity[0] = vx;
  return b;
}

// Ten states 0.1 s apart: track 4 (the cue ball) rolling along x at 0.5 m/s from (1, 0.5),
// track 7 (the 3) at rest at (2, 1), track 9 seen in states 2 to 4 only.
std::string WrittenLog() {
  const std::string path = ::testing::TempDir() + "/billiard_tracks.lcm";
  lcm::LogFile log(path, "w");
  for (int k = 0; k < 10; ++k) {
    table_state_t state{};
    state.utime = 5'000'000 + 100'000 * k;
    state.balls = {Ball(4, ball_state_t::CLASS_CUE, 1.0 + 0.05 * k, 0.5, 0.5),
                   Ball(7, 3, 2.0, 1.0, 0.0)};
    if (k >= 2 && k <= 4) state.balls.push_back(Ball(9, ball_state_t::CLASS_UNKNOWN, 0.3, 0.3, 0));
    for (ball_state_t& b : state.balls) b.utime = state.utime;
    state.num_balls = static_cast<std::int32_t>(state.balls.size());
    WriteEvent(log, billiard::messages::kTableStateChannel, Encoded(state));
    WriteEvent(log, billiard::messages::kTableTruthChannel, Encoded(state));  // not the estimator's
  }
  WriteEvent(log, billiard::messages::kTableStateChannel, {1, 2, 3});  // damaged
  return path;
}

TEST(BilliardTracks, SummarisesEachTrackOfTheEstimatorsStates) {
  const std::string log = WrittenLog();
  const CommandResult r = Billiard("tracks " + log);
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json j = OneObject(r, "tracks");
  EXPECT_EQ(j["states"], 10);
  EXPECT_EQ(j["malformed"], 1);
  EXPECT_NEAR(j["seconds"].get<double>(), 0.9, 1e-9);
  EXPECT_EQ(j["balls_at_end"], 2);
  ASSERT_EQ(j["tracks"].size(), 3u);
  const nlohmann::json& cue = j["tracks"][0];
  EXPECT_EQ(cue["id"], 4);
  EXPECT_EQ(cue["class"], "cue");
  EXPECT_EQ(cue["states"], 10);
  EXPECT_NEAR(cue["class_confidence"].get<double>(), 0.9, 1e-6);
  EXPECT_EQ(cue["first"], (std::vector<double>{1.0, 0.5}));
  EXPECT_NEAR(cue["last"][0].get<double>(), 1.45, 1e-12);
  EXPECT_EQ(cue["last_velocity"], (std::vector<double>{0.5, 0.0}));
  EXPECT_EQ(j["tracks"][1]["class"], "3");
  const nlohmann::json& brief = j["tracks"][2];
  EXPECT_EQ(brief["id"], 9);
  EXPECT_EQ(brief["class"], "unknown");
  EXPECT_EQ(brief["states"], 3);
  EXPECT_NEAR(brief["first_s"].get<double>(), 0.2, 1e-9);
  EXPECT_NEAR(brief["last_s"].get<double>(), 0.4, 1e-9);
}

TEST(BilliardTracks, ALogThatCannotBeReadIsAUsageError) {
  const CommandResult r = Billiard("tracks /no/such.lcm", true);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "billiard: cannot read LCM log '/no/such.lcm'\n");
}

}  // namespace
