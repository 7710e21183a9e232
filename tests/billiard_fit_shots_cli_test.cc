// `billiard fit-shots`, `billiard identify` and `billiard identify-noise` as a user runs them:
// their JSON, the set and the shots they write, their refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <lcm/lcm-cpp.hpp>
#include <string>
#include <vector>

#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "lcmtypes/names.h"

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/shot_fit/shot_fit.h"
#include "tests/support/billiard_command.h"

namespace billiard::testing {
namespace {

// Two shots simulated with the carom set and tracked as the real recordings are.
std::string SyntheticShotsFile() {
  const table::TableGeometry table = table::BuildTable(params::LoadTableSpec("carom-10ft"));
  shot_fit::TrackedShots shots;
  shots.source = "simulated with the carom set";
  shots.shots = shot_fit::SyntheticShots(table, params::LoadParameters("carom"), 2, 11);
  const std::string path = ::testing::TempDir() + "/fit_shots_synthetic.json";
  std::ofstream(path) << shot_fit::TrackedShotsJson(shots);
  return path;
}

TEST(BilliardFitShots, FitsEachStrikeToTheTrackingsNoise) {
  const std::string shots = SyntheticShotsFile();
  const std::string args = "fit-shots --shots " + shots + " --params carom --json";
  const CommandResult r = Billiard(args);
  ASSERT_EQ(r.status, 0);
  const nlohmann::json j = OneObject(r, args);
  ASSERT_EQ(j["shots"].size(), 2u);
  for (const auto& s : j["shots"]) {
    EXPECT_LT(s["rmse_m"]["cue"].get<double>(), 0.005) << s["id"];  // 1 mm of noise per axis
    for (const char* key : {"speed_m_s", "heading_rad", "tip_side_m", "tip_height_m", "time_s"})
      EXPECT_TRUE(s["strike"].contains(key)) << key;
  }
  EXPECT_LT(j["median_cue_rmse_m"].get<double>(), 0.005);
  EXPECT_EQ(j["params"]["name"], "carom");
  EXPECT_TRUE(j["constants"].empty());
}

TEST(BilliardFitShots, WritesASetItReadsBack) {
  const std::string shots = SyntheticShotsFile();
  const std::string out = ::testing::TempDir() + "/fitted_set.json";
  const CommandResult fit =
      Billiard("fit-shots --shots " + shots + " --params carom --fit-physics mu --out-params " +
               out + " --json");
  ASSERT_EQ(fit.status, 0);
  const nlohmann::json j = OneObject(fit, "fit-shots --fit-physics mu");
  EXPECT_TRUE(j["constants"]["mu"]["identifiable"].get<bool>());
  EXPECT_NEAR(j["constants"]["mu"]["value"].get<double>(), 0.2, 0.2 * 0.03);
  const physics::ModelParameters set = params::LoadParameters(out);
  EXPECT_EQ(set.name, "carom-fitted");
  EXPECT_EQ(set.contact.mu, j["constants"]["mu"]["value"].get<double>());
  const CommandResult again = Billiard("fit-shots --shots " + shots + " --params " + out + " --json");
  EXPECT_EQ(again.status, 0);
}

TEST(BilliardFitShots, RefusesBadInputInOneLine) {
  for (const std::string& args :
       {std::string("fit-shots --shots /nonexistent.json"),
        "fit-shots --shots " + SyntheticShotsFile() + " --fit-physics mu,friction",
        "fit-shots --shots " + SyntheticShotsFile() + " --hold-out-every 1",
        "fit-shots --shots " + SyntheticShotsFile() + " --table no-such-table"}) {
    const CommandResult r = Billiard(args, true);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(r.out.find('\n'), r.out.size() - 1) << args << ": " << r.out;
  }
}

template <typename Message>
void Write(lcm::LogFile& log, const std::string& channel, std::int64_t utime, const Message& m) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(m.getEncodedSize()));
  m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  lcm::LogEvent e{};
  e.timestamp = utime;
  e.channel = channel;
  e.datalen = static_cast<std::int32_t>(bytes.size());
  e.data = bytes.data();
  log.writeEvent(&e);
}

table_state_t State(std::int64_t utime, std::int32_t id, double x, double y) {
  table_state_t state{};
  state.utime = utime;
  ball_state_t b{};
  b.utime = utime;
  b.ball_id = id;
  b.position[0] = x;
  b.position[1] = y;
  state.balls = {b};
  state.num_balls = 1;
  return state;
}

// A loop's log: one ball at rest at (1, 0.7), struck at 0.1 s by the cue, rolling along x at
// 30 frames a second; the simulator's truth as ball 0, the estimator's track 7 seen 2 mm off in y.
std::string LoopLog() {
  const std::string path = ::testing::TempDir() + "/identify_loop.lcm";
  lcm::LogFile log(path, "w");
  constexpr double kDt = 1.0 / 30.0, kSpeed = 1.0, kDeceleration = 0.07;
  cue_command_t strike{};
  strike.status = cue_command_t::STATUS_OK;
  strike.cue_speed = 1.5;
  strike.ball_id = 7;
  strike.utime = 100000;
  for (int k = 0; k < 60; ++k) {
    const auto utime = static_cast<std::int64_t>(std::llround(1e6 * k * kDt));
    const double t = std::clamp(k * kDt - 0.1, 0.0, kSpeed / kDeceleration);
    const double x = 1.0 + kSpeed * t - 0.5 * kDeceleration * t * t;
    Write(log, messages::kTableTruthChannel, utime, State(utime, 0, x, 0.7));
    Write(log, messages::kTableStateChannel, utime, State(utime, 7, x, 0.702));
    if (k == 3) Write(log, messages::kCueCommandChannel, strike.utime, strike);
  }
  return path;
}

// The same shot cut from the estimator's tracks or from the truth: --shots-out writes what the
// fit takes, the struck ball the true one nearest the struck track.
TEST(BilliardIdentify, CutsTheShotsFromTheTracksOrTheTruth) {
  const std::string log = LoopLog();
  for (const std::string tracks : {"estimator", "truth"}) {
    SCOPED_TRACE(tracks);
    const std::string shots = ::testing::TempDir() + "/identify_" + tracks + ".json";
    const CommandResult r = Billiard("identify " + log + " --tracks " + tracks +
                                     " --fit-physics rolling --shots-out " + shots + " --json");
    ASSERT_EQ(r.status, 0) << r.out;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["log"]["tracks"], tracks);
    EXPECT_EQ(j["shots"].size(), 1u);
    EXPECT_TRUE(j.contains("residual_correlation_samples"));
    EXPECT_TRUE(j["constants"]["rolling"].contains("at_bound"));
    const shot_fit::TrackedShots cut = shot_fit::ReadTrackedShots(shots);
    ASSERT_EQ(cut.shots.size(), 1u);
    const shot_fit::TrackedBall& ball = cut.shots[0].balls.at(cut.shots[0].cue);
    EXPECT_EQ(ball.name, tracks == "truth" ? "track 0" : "track 7");
    EXPECT_DOUBLE_EQ(ball.position.front().x(), 1.0);  // at rest, the state before the strike
    EXPECT_DOUBLE_EQ(ball.position.back().y(), tracks == "truth" ? 0.7 : 0.702);
    EXPECT_GT(ball.position.back().x(), 1.5);
  }
  const CommandResult bad = Billiard("identify " + log + " --tracks camera", true);
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("--tracks must be estimator or truth"), std::string::npos) << bad.out;
  EXPECT_EQ(bad.out.find('\n'), bad.out.size() - 1) << bad.out;
}

// identify-noise measures the one shot's launch, and refuses (exit 2, one line) to learn a noise
// from fewer than ten, an unknown prior, or tracks it does not know.
TEST(BilliardIdentifyNoise, RefusesWhatItCannotLearnFrom) {
  const std::string log = LoopLog();
  const CommandResult few = Billiard("identify-noise " + log + " --json", true);
  EXPECT_EQ(few.status, 2);
  EXPECT_NE(few.out.find("1 launches measured of 1 shots, 10 needed"), std::string::npos)
      << few.out;
  EXPECT_EQ(few.out.find('\n'), few.out.size() - 1) << few.out;
  const CommandResult prior = Billiard("identify-noise " + log + " --prior no-such-noise", true);
  EXPECT_EQ(prior.status, 2);
  EXPECT_NE(prior.out.find("--prior"), std::string::npos) << prior.out;
  const CommandResult tracks = Billiard("identify-noise " + log + " --tracks camera", true);
  EXPECT_EQ(tracks.status, 2);
}

}  // namespace
}  // namespace billiard::testing
