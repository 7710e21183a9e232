// `billiard fit-shots` as a user runs it: its JSON, the set it writes, its refusals.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

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

}  // namespace
}  // namespace billiard::testing
