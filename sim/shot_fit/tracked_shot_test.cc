#include "sim/shot_fit/tracked_shot.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/shot_fit/synthetic_shots.h"

namespace billiard::shot_fit {
namespace {

std::string RefusalOf(const std::string& json) {
  try {
    ParseTrackedShots(json, "s.json");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(TrackedShots, RefusesBadInputInOneLineNamingTheShot) {
  EXPECT_EQ(RefusalOf("{"), RefusalOf("{")) << "deterministic";
  EXPECT_NE(RefusalOf("{").find("s.json: invalid JSON"), std::string::npos);
  EXPECT_NE(RefusalOf("{}").find("array \"shots\""), std::string::npos);
  const std::string ball = R"("1": {"t": [0, 0.02], "x": [1, 1.1], "y": [0.5, 0.5]})";
  EXPECT_NE(RefusalOf(R"({"shots": [{"id": 7, "cue_ball": "2", "balls": {)" + ball + "}}]}")
                .find("s.json: shot 7: has no ball \"2\""),
            std::string::npos);
  EXPECT_NE(RefusalOf(R"({"shots": [{"id": 7, "cue_ball": "1", "balls": {"1": {"t": [0.1, 0],
            "x": [1, 1], "y": [1, 1]}}}]})")
                .find("shot 7, ball 1: times decrease"),
            std::string::npos);
  EXPECT_NE(RefusalOf(R"({"shots": [{"id": 7, "cue_ball": "1", "balls": {"1": {"t": [0],
            "x": [1, 2], "y": [1]}}}]})")
                .find("differ in length"),
            std::string::npos);
  for (const std::string& message : {RefusalOf("{"), RefusalOf("{}")})
    EXPECT_EQ(message.find('\n'), std::string::npos);
}

TEST(TrackedShots, ReadBackWhatTheyWrite) {
  const table::TableGeometry table = table::BuildTable(params::LoadTableSpec("carom-10ft"));
  const physics::ModelParameters p = params::LoadParameters("carom");
  TrackedShots shots;
  shots.source = "simulated";
  shots.shots = SyntheticShots(table, p, 2, 3);
  const TrackedShots back = ParseTrackedShots(TrackedShotsJson(shots), "x");
  ASSERT_EQ(back.shots.size(), 2u);
  EXPECT_EQ(back.source, "simulated");
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(back.shots[i].id, shots.shots[i].id);
    EXPECT_EQ(back.shots[i].cue, shots.shots[i].cue);
    ASSERT_EQ(back.shots[i].balls.size(), shots.shots[i].balls.size());
    for (std::size_t b = 0; b < back.shots[i].balls.size(); ++b) {
      EXPECT_EQ(back.shots[i].balls[b].t, shots.shots[i].balls[b].t);
      EXPECT_EQ(back.shots[i].balls[b].position, shots.shots[i].balls[b].position);
    }
  }
}

}  // namespace
}  // namespace billiard::shot_fit
