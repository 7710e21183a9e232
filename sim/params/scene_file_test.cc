// Scene files: the round trip to the bit, and every malformed scene refused naming what is wrong.
#include "sim/params/scene_file.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace billiard::params {
namespace {

std::string Refusal(const std::string& json) {
  try {
    ParseScene(json, "s.json");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(SceneFile, RoundTripsEveryNumberToTheBit) {
  SceneFile scene{"pool-9ft", "pool", {}, {}};
  scene.balls.push_back({0, physics::MakeBallState(0.1 + 1e-17, 1.0 / 3.0, -2.5e-300, 7, 0, 0,
                                                   -123.456789012345678)});
  scene.balls.push_back({9, physics::MakeBallState(2.2, 0.6, 0, 0, 0, 0, 0)});
  const SceneFile back = ParseScene(SceneJson(scene), "t");
  EXPECT_EQ(back.table, "pool-9ft");
  EXPECT_EQ(back.params, "pool");
  ASSERT_EQ(back.balls.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(back.balls[k].id, scene.balls[k].id);
    EXPECT_EQ(back.balls[k].state, scene.balls[k].state);
  }
}

TEST(SceneFile, ReadsAStrokeAndWritesItBack) {
  const SceneFile scene = ParseScene(
      R"({"table":"pool-9ft","params":"pool","balls":[{"id":0,"state":[1,0.5,0,0,0,0,0],)"
      R"("cue":{"speed":2.5,"heading":0.25,"tip_height":-0.01}}]})",
      "c.json");
  ASSERT_EQ(scene.cues.count(0), 1u);
  EXPECT_EQ(scene.cues.at(0).speed, 2.5);
  EXPECT_EQ(scene.cues.at(0).heading, 0.25);
  EXPECT_EQ(scene.cues.at(0).tip_height, -0.01);
  EXPECT_EQ(scene.cues.at(0).tip_side, 0.0);  // the offsets default to 0
  const SceneFile back = ParseScene(SceneJson(scene), "t");
  EXPECT_EQ(back.cues.at(0).tip_height, -0.01);
  EXPECT_NE(Refusal(R"({"table":"t","params":"pool","balls":[{"id":0,"state":[1,1,0,0,0,0,0],)"
                    R"("cue":{"speed":1}}]})")
                .find("missing number cue.heading"),
            std::string::npos);
}

TEST(SceneFile, RefusesMalformedScenesNamingTheFault) {
  const std::string ball = R"({"id":0,"state":[1,0.5,0,0,0,0,0]})";
  EXPECT_EQ(Refusal(R"({"table":"pool-9ft","params":"pool","balls":[)" + ball + "]}"), "");
  EXPECT_NE(Refusal("[1, 2]").find("a scene is a JSON object"), std::string::npos);
  EXPECT_NE(Refusal("{").find("not valid JSON"), std::string::npos);
  // Beyond double range: nlohmann says out_of_range, not parse_error; still bad input.
  EXPECT_NE(Refusal(R"({"table":"t","params":"pool","balls":[{"id":0,"state":[1e400,1,0,0,0,0,0]}]})")
                .find("not valid JSON"),
            std::string::npos);
  EXPECT_NE(Refusal(R"({"params":"pool","balls":[]})").find("missing table"), std::string::npos);
  EXPECT_NE(Refusal(R"({"table":"pool-9ft","params":"pool","balls":[],"bals":1})")
                .find("unknown key bals"),
            std::string::npos);
  EXPECT_NE(Refusal(R"({"table":7,"params":"pool","balls":[]})").find("table must be a string"),
            std::string::npos);
  EXPECT_NE(Refusal(R"({"table":"t","params":"pool","balls":[{"id":0.5,"state":[1,1,0,0,0,0,0]}]})")
                .find("balls[0]: id must be an integer"),
            std::string::npos);
  EXPECT_NE(Refusal(R"({"table":"t","params":"pool","balls":[{"id":0,"state":[1,1,0]}]})")
                .find("balls[0]: state must be 7 numbers"),
            std::string::npos);
  EXPECT_NE(Refusal(R"({"table":"t","params":"pool","balls":[{"id":0,"state":[1,"x",0,0,0,0,0]}]})")
                .find("state[1] must be a number"),
            std::string::npos);
  EXPECT_NE(Refusal(R"({"table":"t","params":"pool","balls":[{"id":0,"spin":1}]})")
                .find("unknown key spin"),
            std::string::npos);
}

// `simulate --scene --json` prints the balls with a scene's keys beside its own: refused, still
// strict, pointing to the scene `simulate --scene-out` writes.
TEST(SceneFile, ASimulationsResultIsToldApartFromAScene) {
  const std::string result = R"({"table":"pool-9ft","params":"pool","model":"auto","accuracy_m":0.005,
      "balls":[{"id":0,"state":[1,0.5,0,0,0,0,0],"pocketed":null}],"events":[],"at_rest":true})";
  const std::string why = Refusal(result);
  EXPECT_NE(why.find("not a scene"), std::string::npos) << why;
  EXPECT_NE(why.find("--scene-out"), std::string::npos) << why;
}

TEST(SceneFile, AMissingFileIsRefusedWithItsPath) {
  try {
    LoadScene("/nonexistent/scene.json");
    FAIL() << "no refusal";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scene.json"), std::string::npos);
  }
}

}  // namespace
}  // namespace billiard::params
